//! `halfplane wear`: fretting wear of the case's contact over `[wear] cycles` load cycles.

use crate::args::{Format, WearArgs};
use crate::output::{emit, note};
use crate::progress::Progress;
use crate::report::wear::{fields_csv, loop_csv, WearReport};
use crate::units::Units;
use anyhow::{anyhow, Result};
use halfplane::march::Worn;
use halfplane::wear::{self, WearOptions, WornCycle};
use halfplane_case::case::{Reached, WearFatigue};
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
    /// `--fatigue`.
    pub fatigue: Option<WearFatigue>,
}

impl WearConfig {
    /// Reads the case (with `[wear]` and a one-cycle or sliding `[history]`), applies `--cells`
    /// and marches the ramp.
    pub fn resolve(args: &WearArgs) -> Result<Self> {
        let case = crate::case::load(&args.case)?;
        let settings = case.wear()?;
        let fatigue = args
            .fatigue
            .then(|| case.wear_fatigue(&args.case.display().to_string()))
            .transpose()?;
        let mut worn = case.worn_march(&settings, args.cells)?;
        if fatigue.is_some() {
            worn.record_tractions();
        }
        Ok(Self {
            worn,
            options: settings.options,
            fields: args.fields.clone(),
            units: case.units,
            format: args.format.format(),
            fatigue,
        })
    }
}

/// Runs the wear loop (progress on stderr, one tick per checkpoint), writes each checkpoint's
/// fields as it is reached, evaluates the fatigue parameters of its cycle with `--fatigue`, and
/// prints the report. When the march fails part way, the report of the checkpoints reached is
/// printed before the error.
pub fn run(config: WearConfig) -> Result<()> {
    let WearConfig {
        mut worn,
        options,
        fields,
        units,
        format,
        fatigue,
    } = config;
    if let Some(f) = &fatigue {
        for line in &f.skipped {
            eprintln!("warning: {line}");
        }
    }
    let mut reached = Reached::new(fatigue, worn.unworn_contact());
    if let Some(dir) = &fields {
        std::fs::create_dir_all(dir).map_err(|e| {
            anyhow!(
                "cannot create the --fields directory {}: {e}",
                dir.display()
            )
        })?;
    }
    let bar = Progress::new("wear", "checkpoints", options.checkpoints().len() as u64);
    let mut write_error = None;
    let (approach, datum) = (worn.elastic_approach(), worn.loop_datum());
    let outcome = wear::run(&mut worn, &options, |c| {
        bar.inc(1);
        if let (Some(dir), None) = (&fields, &write_error) {
            for (name, text) in [("checkpoint", fields_csv(c)), ("loop", loop_csv(c))] {
                let path = dir.join(format!("{name}_{}.csv", c.cycle));
                if let Err(e) = std::fs::write(&path, text) {
                    write_error.get_or_insert(anyhow!("cannot write {}: {e}", path.display()));
                }
            }
        }
        reached.observe(c);
    });
    bar.finish();
    if let Some(e) = write_error {
        return Err(e);
    }
    if let Some(e) = reached.error.take() {
        return Err(e);
    }
    let (simulated, stopped) = match &outcome {
        Ok(r) => (Some(r.simulated_cycles), None),
        Err(e) => (None, Some(e.to_string())),
    };
    let checkpoints = &reached.checkpoints;
    let mut report = WearReport::new(
        checkpoints,
        simulated,
        approach,
        datum,
        &options,
        &units,
        stopped,
    );
    if reached.with_fatigue() {
        report = report.with_fatigue(&reached.parameters);
    }
    if outcome.is_err() && !checkpoints.is_empty() {
        note(&format!(
            "wear stopped after {} checkpoint(s); the report below holds them",
            checkpoints.len()
        ));
    }
    if outcome.is_ok() || !checkpoints.is_empty() {
        emit(&match format {
            Format::Table => report.table(),
            Format::Csv => report.csv(),
            Format::Json => report.json()? + "\n",
        })?;
    }
    outcome.map(|_| ())?;
    Ok(())
}
