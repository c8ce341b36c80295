//! `halfplane fatigue`: initiation parameters over the steady (last) cycle of the history, with
//! the material constants of `[fatigue]` (`docs/fatigue.md`).

use crate::args::{FatigueArgs, Format};
use crate::output::emit;
use crate::report::fatigue::FatigueReport;
use crate::units::Units;
use anyhow::Result;
use halfplane::fatigue::{self, FatigueConstants, FatigueGrid};
use halfplane::history::History;
use halfplane::march::MarchOptions;
use halfplane::Contact;

/// What `fatigue` runs on.
#[derive(Debug, Clone)]
pub struct FatigueConfig {
    /// The contact.
    pub contact: Contact,
    /// The (cyclic) history.
    pub history: History,
    /// `[solver]` with `--cells` applied.
    pub options: MarchOptions,
    /// `[fatigue]` constants.
    pub constants: FatigueConstants,
    /// `[fatigue]` grid.
    pub grid: FatigueGrid,
    /// Unit names.
    pub units: Units,
    /// Table, CSV or JSON.
    pub format: Format,
    /// The parameters `[fatigue]` leaves out, one line each, for stderr.
    pub skipped: Vec<String>,
}

impl FatigueConfig {
    /// Reads the case and resolves `[fatigue]`.
    pub fn resolve(args: &FatigueArgs) -> Result<Self> {
        let case = crate::case::load(&args.case)?;
        let settings = case.fatigue()?;
        let history = case.history()?;
        let options = case.solver_with_cells(args.cells)?;
        crate::limits::check_case_march(&history, &options, args.cells, args.no_size_limit)?;
        Ok(Self {
            history,
            options,
            contact: case.contact,
            constants: settings.constants,
            grid: settings.grid,
            units: case.units,
            format: args.format.format(),
            skipped: settings.skipped(),
        })
    }
}

/// Runs the analysis and prints the report; each parameter left out for want of its constants
/// is named on stderr with what it lacks.
pub fn run(config: &FatigueConfig) -> Result<()> {
    for line in &config.skipped {
        eprintln!("warning: {line}");
    }
    let result = crate::progress::while_running("fatigue", || {
        fatigue::analyse(
            &config.contact,
            &config.history,
            &config.options,
            &config.constants,
            &config.grid,
        )
    })?;
    let report = FatigueReport::new(&result, &config.units);
    emit(&match config.format {
        Format::Table => report.table(),
        Format::Csv => report.csv(),
        Format::Json => report.json()? + "\n",
    })
}
