//! `halfplane steady`: the steady state of an in-phase cycle.

use crate::args::{Format, SteadyArgs};
use crate::output::{emit, note};
use crate::report::steady::SteadyReport;
use crate::units::Units;
use anyhow::Result;
use halfplane::{asymptotic, steady, Contact, Cycle, Regime, SteadyOptions};

/// What `steady` runs on.
#[derive(Debug, Clone)]
pub struct SteadyConfig {
    /// The contact: profile, material and friction.
    pub contact: Contact,
    /// The cycle of `[cycle]`.
    pub cycle: Cycle,
    /// The unit names of `[units]`, for the table headers.
    pub units: Units,
    /// Table, CSV or JSON.
    pub format: Format,
}

impl SteadyConfig {
    /// Reads the case: it must have a `[cycle]`.
    pub fn resolve(args: &SteadyArgs) -> Result<Self> {
        let case = crate::case::load(&args.case)?;
        Ok(Self {
            cycle: case.cycle()?,
            contact: case.contact,
            units: case.units,
            format: args.format.format(),
        })
    }
}

/// Analyses the cycle and prints the report; a missing asymptotic estimate is a note on stderr.
pub fn run(config: &SteadyConfig) -> Result<()> {
    let state = steady::analyse(&config.contact, &config.cycle, &SteadyOptions::default())?;
    let asym = match state.regime {
        Regime::PartialSlip => Some(asymptotic::steady(&config.contact, &config.cycle)),
        _ => None,
    };
    let asym_ok = asym.as_ref().and_then(|a| a.as_ref().ok());
    let report = SteadyReport::new(&config.contact, &state, asym_ok, &config.units)?;
    emit(&match config.format {
        Format::Table => report.table(&state),
        Format::Csv => report.csv()?,
        Format::Json => report.json()? + "\n",
    })?;
    if let Some(Err(e)) = asym {
        note(&format!("note: no asymptotic estimate: {e}"));
    }
    Ok(())
}
