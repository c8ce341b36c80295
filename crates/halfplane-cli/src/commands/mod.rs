//! The commands, one module each: a validated configuration resolved from the raw arguments
//! (`Config::resolve`), and `run`, which computes and prints. `main` only parses and dispatches.

pub mod crack;
#[cfg(feature = "plot")]
pub mod design_map;
pub mod evolve;
pub mod fatigue;
pub mod march;
pub mod matching;
#[cfg(feature = "plot")]
pub mod plot;
pub mod steady;
pub mod stress;
pub mod sweep;
pub mod wear;

use crate::args::{Command, PlotCommand};
use anyhow::Result;

/// Why `plot` fails in a build without figures, and how to get them.
#[cfg(not(feature = "plot"))]
const NO_PLOT: &str = "this halfplane was built without figures (--no-default-features); build \
     it with --features plot (or without --no-default-features) to draw them";

/// Resolves the command's configuration and runs it.
pub fn run(command: &Command) -> Result<()> {
    match command {
        Command::Steady(a) => steady::run(&steady::SteadyConfig::resolve(a)?),
        Command::Evolve(a) => evolve::run(&evolve::EvolveConfig::resolve(a)?),
        Command::March(a) => march::run(&march::MarchConfig::resolve(a)?),
        Command::Match(a) => matching::run(&matching::resolve(a)?, a.json),
        Command::Stress(a) => stress::run(&stress::StressConfig::resolve(a)?),
        Command::Fatigue(a) => fatigue::run(&fatigue::FatigueConfig::resolve(a)?),
        Command::Crack(a) => crack::run(&crack::CrackConfig::resolve(a)?),
        #[cfg(feature = "plot")]
        Command::Plot(PlotCommand::DesignMap(a)) => {
            design_map::run(&design_map::DesignMapConfig::resolve(a)?)
        }
        #[cfg(feature = "plot")]
        Command::Plot(p) => plot::run(&plot::PlotConfig::resolve(p)?),
        #[cfg(not(feature = "plot"))]
        Command::Plot(_) => anyhow::bail!(NO_PLOT),
        Command::Sweep(a) => sweep::run(&sweep::SweepConfig::resolve(a)?),
        Command::Wear(a) => wear::run(wear::WearConfig::resolve(a)?),
    }
}

/// What to do next when a load case is outside the steady-state analysis or no test matches,
/// chosen by the library's [`halfplane::Error::alternative`] (never by its text) and, for
/// `match`, by the mode the command was run in (the hint offers the other one), or when a run is
/// refused as too large.
pub fn hint(error: &anyhow::Error, command: &Command) -> Option<&'static str> {
    use halfplane::error::Alternative;
    if error
        .chain()
        .any(|e| e.downcast_ref::<crate::limits::TooLarge>().is_some())
    {
        return Some(
            "make the run smaller (fewer cells, increments or rows, or --shard I/N for part of a \
             sweep), or add --no-size-limit to run it anyway",
        );
    }
    let exact = match command {
        Command::Match(a) => a.test.exact,
        Command::Plot(PlotCommand::Match(a)) => a.test.exact,
        _ => false,
    };
    let library = error
        .chain()
        .find_map(|e| e.downcast_ref::<halfplane::Error>())?;
    match library.alternative()? {
        Alternative::March => Some(
            "the steady-state analysis does not cover this cycle; `halfplane march` (numerical \
             time marching) has no such restriction: give the case a [history] section with \
             kind = \"cycle\"",
        ),
        Alternative::OtherTest if exact => Some(
            "choose another test geometry (for a Hertz test a different --radius gives another \
             contact size at the same K_N) or the asymptotic match (the same command without \
             --exact)",
        ),
        Alternative::OtherTest => Some(
            "choose another test geometry (for a Hertz test a different --radius gives another \
             contact size at the same K_N) or the exact match (--exact)",
        ),
    }
}
