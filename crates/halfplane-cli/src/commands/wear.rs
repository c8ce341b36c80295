//! `halfplane wear`: fretting wear of the case's contact over `[wear] cycles` load cycles.

use crate::args::{Format, WearArgs};
use crate::output::{emit, note};
use crate::progress::Progress;
use crate::report::wear::{fields_csv, WearReport};
use crate::units::Units;
use anyhow::{anyhow, Result};
use halfplane::march::Worn;
use halfplane::wear::{self, Checkpoint, WearOptions, WornCycle};
use std::path::PathBuf;

/// What `wear` runs on.
pub struct WearConfig {
    /// The march over the worn gap, its ramp done.
    pub worn: Worn,
    /// `[wear]`.
    pub options: WearOptions,
    /// `--fields DIR`: where to write each checkpoint's fields.
    pub fields: Option<PathBuf>,
    /// The unit names of `[units]`.
    pub units: Units,
    /// Table, CSV or JSON.
    pub format: Format,
}

impl WearConfig {
    /// Reads the case (with `[wear]` and a one-cycle or sliding `[history]`), applies `--cells`
    /// and marches the ramp.
    pub fn resolve(args: &WearArgs) -> Result<Self> {
        let case = crate::case::load(&args.case)?;
        let settings = case.wear()?;
        let worn = case.worn_march(settings.span, args.cells)?;
        Ok(Self {
            worn,
            options: settings.options,
            fields: args.fields.clone(),
            units: case.units,
            format: args.format.format(),
        })
    }
}

/// Runs the wear loop (progress on stderr, one tick per checkpoint), writes each checkpoint's
/// fields as it is reached, and prints the report. When the march fails part way, the report of
/// the checkpoints reached is printed before the error.
pub fn run(config: WearConfig) -> Result<()> {
    let WearConfig {
        mut worn,
        options,
        fields,
        units,
        format,
    } = config;
    if let Some(dir) = &fields {
        std::fs::create_dir_all(dir).map_err(|e| {
            anyhow!(
                "cannot create the --fields directory {}: {e}",
                dir.display()
            )
        })?;
    }
    let bar = Progress::new("wear", "checkpoints", options.checkpoints().len() as u64);
    let mut reached: Vec<Checkpoint> = Vec::new();
    let mut write_error = None;
    let approach = worn.elastic_approach();
    let outcome = wear::run(&mut worn, &options, |c| {
        bar.inc(1);
        if let (Some(dir), None) = (&fields, &write_error) {
            let path = dir.join(format!("checkpoint_{}.csv", c.cycle));
            if let Err(e) = std::fs::write(&path, fields_csv(c)) {
                write_error = Some(anyhow!("cannot write {}: {e}", path.display()));
            }
        }
        reached.push(c.clone());
    });
    bar.finish();
    if let Some(e) = write_error {
        return Err(e);
    }
    let (simulated, stopped) = match &outcome {
        Ok(r) => (Some(r.simulated_cycles), None),
        Err(e) => (None, Some(e.to_string())),
    };
    let report = WearReport::new(&reached, simulated, approach, &options, &units, stopped);
    if outcome.is_err() && !reached.is_empty() {
        note(&format!(
            "wear stopped after {} checkpoint(s); the report below holds them",
            reached.len()
        ));
    }
    if outcome.is_ok() || !reached.is_empty() {
        emit(&match format {
            Format::Table => report.table(),
            Format::Csv => report.csv(),
            Format::Json => report.json()? + "\n",
        })?;
    }
    outcome.map(|_| ())?;
    Ok(())
}
