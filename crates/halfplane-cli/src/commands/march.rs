//! `halfplane march`: numerical time marching through the case's load history.

use crate::args::{Format, MarchArgs};
use crate::limits;
use crate::output::emit;
use crate::progress::Progress;
use crate::report::march::MarchReport;
use crate::units::Units;
use anyhow::{anyhow, Result};
use halfplane::history::{History, Steady};
use halfplane::march::{self, Fields, MarchOptions, MarchResult};
use halfplane::Contact;
use std::io::{self, Write};
use std::path::{Path, PathBuf};

/// What `march` runs on.
#[derive(Debug, Clone)]
pub struct MarchConfig {
    /// The contact: profile, material and friction.
    pub contact: Contact,
    /// The load history of `[history]` (its ramp and one cycle when marched until steady).
    pub history: History,
    /// `history.max_cycles` and `history.steady_tolerance`.
    pub steady: Steady,
    /// `history.cycles = "steady"`: march until the cycle repeats.
    pub until_steady: bool,
    /// `[solver]` with `--cells` applied.
    pub options: MarchOptions,
    /// `--fields DIR`: where to write the fields of every increment.
    pub fields: Option<PathBuf>,
    /// The unit names of `[units]`, for the table headers.
    pub units: Units,
    /// Table, CSV or JSON.
    pub format: Format,
}

impl MarchConfig {
    /// Reads the case (it must have a `[history]`), applies `--cells` and, unless
    /// `--no-size-limit`, refuses a march estimated to be too large (`crate::limits`).
    pub fn resolve(args: &MarchArgs) -> Result<Self> {
        let case = crate::case::load(&args.case)?;
        let (history, until) = case.march_history()?;
        let options = case.solver_with_cells(args.cells)?;
        if !args.no_size_limit {
            let field = limits::cells_field(args.cells, &options);
            let increments = limits::planned_increments(&history, until.as_ref());
            limits::check_march(increments, &options, &field)?;
            if args.fields.is_some() {
                limits::check_fields_files(increments, &options, &field)?;
            }
        }
        Ok(Self {
            history,
            steady: case.steady(),
            until_steady: until.is_some(),
            options,
            contact: case.contact,
            fields: args.fields.clone(),
            units: case.units,
            format: args.format.format(),
        })
    }
}

/// Marches through the history (with progress on stderr: a bar on a terminal, else a line every
/// few seconds), writes the `--fields` files
/// and prints the report.
pub fn run(config: &MarchConfig) -> Result<()> {
    let fields = config.fields.as_deref();
    if let Some(dir) = fields {
        std::fs::create_dir_all(dir).map_err(|e| {
            anyhow!(
                "cannot create the --fields directory {}: {e}",
                dir.display()
            )
        })?;
    }
    // Marched until steady, the count runs to max_cycles cycles (most marches end well before).
    let steady = config.until_steady.then_some(&config.steady);
    let planned = limits::planned_increments(&config.history, steady);
    let bar = Progress::new("march", "increments", planned as u64);
    let mut write_error = None;
    let observer = |r: &march::StepReport, f: &Fields| {
        bar.inc(1);
        if let (Some(dir), None) = (fields, &write_error) {
            if let Err(e) = write_fields(&dir.join(format!("step_{:05}.csv", r.step)), f) {
                write_error = Some(e);
            }
        }
    };
    let result = match config.until_steady {
        true => march::march_steady(
            &config.contact,
            &config.history,
            &config.steady,
            &config.options,
            observer,
        ),
        false => march::march(&config.contact, &config.history, &config.options, observer),
    };
    bar.finish();
    let result = result?;
    if let Some(e) = write_error {
        return Err(e);
    }
    if let (Some(dir), false) = (fields, result.cycles.is_empty()) {
        write_amplitudes(&dir.join("slip_amplitude.csv"), &result)?;
    }
    let report = MarchReport::new(&result, &config.units, &config.steady, config.until_steady);
    emit(&match config.format {
        Format::Table => report.table(
            &result,
            &config.history,
            config.options.shakedown_tolerance(),
        ),
        Format::Csv => report.csv(),
        Format::Json => report.json()? + "\n",
    })
}

/// `DIR/step_NNNNN.csv`: the fields along x at one increment.
fn write_fields(path: &Path, f: &Fields) -> Result<()> {
    let write = || -> io::Result<()> {
        let mut out = io::BufWriter::new(std::fs::File::create(path)?);
        writeln!(out, "x,pressure,traction,slip,slip_increment")?;
        for i in 0..f.x.len() {
            writeln!(
                out,
                "{},{},{},{},{}",
                f.x[i], f.pressure[i], f.traction[i], f.slip[i], f.slip_increment[i]
            )?;
        }
        // An explicit flush: dropping a BufWriter discards its error.
        out.flush()
    };
    write().map_err(|e| anyhow!("cannot write {}: {e}", path.display()))
}

/// `DIR/slip_amplitude.csv`: half the peak-to-peak slip of every cycle along x.
fn write_amplitudes(path: &Path, result: &MarchResult) -> Result<()> {
    let mut o = String::from("x");
    for c in &result.cycles {
        o.push_str(&format!(",cycle_{}", c.index));
    }
    o.push('\n');
    for (i, x) in result.x.iter().enumerate() {
        o.push_str(&x.to_string());
        for c in &result.cycles {
            o.push_str(&format!(",{}", 0.5 * c.slip_range[i]));
        }
        o.push('\n');
    }
    std::fs::write(path, o).map_err(|e| anyhow!("cannot write {}: {e}", path.display()))
}
