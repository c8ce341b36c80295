//! `halfplane crack`: stress intensity factors of a surface-breaking crack over the steady
//! (last) cycle of the history, the short-crack threshold and the verdict (`docs/crack.md`).

use crate::args::{CrackArgs, Format};
use crate::output::emit;
use crate::report::crack::CrackReport;
use crate::units::Units;
use anyhow::Result;
use halfplane::crack::{self, CrackOptions};
use halfplane::fatigue::FatigueConstants;
use halfplane::history::History;
use halfplane::march::MarchOptions;
use halfplane::Contact;

/// What `crack` runs on.
#[derive(Debug, Clone)]
pub struct CrackConfig {
    /// The contact.
    pub contact: Contact,
    /// The (cyclic) history.
    pub history: History,
    /// `[solver]` with `--cells` applied.
    pub options: MarchOptions,
    /// `[fatigue]` constants (threshold and endurance_range are needed).
    pub constants: FatigueConstants,
    /// `[crack]`.
    pub crack: CrackOptions,
    /// Unit names.
    pub units: Units,
    /// Table, CSV or JSON.
    pub format: Format,
}

impl CrackConfig {
    /// Reads the case and resolves `[crack]` and `[fatigue]`.
    pub fn resolve(args: &CrackArgs) -> Result<Self> {
        let case = crate::case::load(&args.case)?;
        let crack = case.crack()?;
        let constants = case.fatigue()?.constants;
        let history = case.history()?;
        let options = case.solver_with_cells(args.cells)?;
        crate::limits::check_case_march(&history, &options, args.cells, args.no_size_limit)?;
        Ok(Self {
            history,
            options,
            contact: case.contact,
            constants,
            crack,
            units: case.units,
            format: args.format.format(),
        })
    }
}

/// Runs the analysis and prints the report.
pub fn run(config: &CrackConfig) -> Result<()> {
    let result = crate::progress::while_running("crack", || {
        crack::analyse(
            &config.contact,
            &config.history,
            &config.options,
            &config.constants,
            &config.crack,
        )
    })?;
    let report = CrackReport::new(&result, &config.units);
    emit(&match config.format {
        Format::Table => report.table(),
        Format::Csv => report.csv(),
        Format::Json => report.json()? + "\n",
    })
}
