//! `halfplane evolve`: the stick zone along both halves of the cycle.

use crate::args::{EvolveArgs, Format};
use crate::output::{emit, note};
use crate::report::evolve::EvolveReport;
use crate::units::Units;
use anyhow::{bail, Result};
use halfplane::evolution::{self, Evolution, MAX_POINTS_PER_HALF};
use halfplane::{Contact, Cycle, SteadyOptions};

/// What `evolve` runs on.
#[derive(Debug, Clone)]
pub struct EvolveConfig {
    /// The contact: profile, material and friction.
    pub contact: Contact,
    /// The cycle of `[cycle]`.
    pub cycle: Cycle,
    /// Points per half-cycle, ends included, 2 to [`MAX_POINTS_PER_HALF`].
    pub points: usize,
    /// The unit names of `[units]`, for the table headers.
    pub units: Units,
    /// Table, CSV or JSON.
    pub format: Format,
}

impl EvolveConfig {
    /// Reads the case (it must have a `[cycle]`) and checks `--points`.
    pub fn resolve(args: &EvolveArgs) -> Result<Self> {
        let case = crate::case::load(&args.case)?;
        Ok(Self {
            cycle: case.cycle()?,
            contact: case.contact,
            points: points(args.points)?,
            units: case.units,
            format: args.format.format(),
        })
    }
}

/// Checks a `--points` value (the library checks it again, naming its own parameter).
pub(crate) fn points(n: usize) -> Result<usize> {
    if !(2..=MAX_POINTS_PER_HALF).contains(&n) {
        bail!("invalid --points = {n}: must be a whole number from 2 to {MAX_POINTS_PER_HALF} (points per half-cycle)");
    }
    Ok(n)
}

/// The evolution at `points` points of each half.
pub(crate) fn evolve(contact: &Contact, cycle: &Cycle, points: usize) -> Result<Evolution> {
    Ok(evolution::evolve(
        contact,
        cycle,
        points,
        &SteadyOptions::default(),
    )?)
}

/// Computes the evolution and prints it; warnings go to stderr unless the JSON carries them.
pub fn run(config: &EvolveConfig) -> Result<()> {
    let ev = evolve(&config.contact, &config.cycle, config.points)?;
    let report = EvolveReport::new(&ev, &config.units);
    emit(&match config.format {
        Format::Table => report.table(),
        Format::Csv => report.csv(),
        Format::Json => report.json()? + "\n",
    })?;
    if config.format != Format::Json {
        for w in report.warnings() {
            note(w);
        }
    }
    Ok(())
}
