//! The `halfplane` command: a thin layer that parses arguments, resolves the case file and prints
//! what the library computes.

mod case;
mod report;

use anyhow::Result;
use clap::{Parser, Subcommand};
use halfplane::{asymptotic, evolution, steady, SteadyOptions};
use std::path::PathBuf;
use std::process::ExitCode;

/// Frictional half-plane contact: steady-state stick zones, slip zones and their evolution.
#[derive(Parser)]
#[command(name = "halfplane", version)]
struct Cli {
    #[command(subcommand)]
    command: Command,
}

#[derive(Subcommand)]
enum Command {
    /// Steady state of an in-phase cycle: regime, permanent stick zone, slip zones, asymptotics.
    Steady {
        /// Case file (TOML) with [material], [friction], [profile] and [cycle].
        case: PathBuf,
        /// Print one JSON object instead of the table.
        #[arg(long)]
        json: bool,
    },
    /// Stick zone at evenly spaced points of each half-cycle (exact partial-path relation), with
    /// the asymptotic estimate beside it.
    Evolve {
        /// Case file (TOML) with [material], [friction], [profile] and [cycle].
        case: PathBuf,
        /// Points per half-cycle, ends included (>= 2).
        #[arg(long, default_value_t = 21)]
        points: usize,
        /// Print CSV (one row per point) instead of the table.
        #[arg(long, conflicts_with = "json")]
        csv: bool,
        /// Print one JSON object instead of the table.
        #[arg(long)]
        json: bool,
    },
}

fn run(cli: Cli) -> Result<()> {
    let options = SteadyOptions::default();
    match cli.command {
        Command::Steady { case, json } => {
            let case = case::load(&case)?;
            let cycle = case.cycle()?;
            let state = steady::analyse(&case.contact, &cycle, &options)?;
            let asym = match state.regime {
                halfplane::Regime::PartialSlip => Some(asymptotic::steady(&case.contact, &cycle)),
                _ => None,
            };
            let asym_ok = asym.as_ref().and_then(|a| a.as_ref().ok());
            let report = report::SteadyReport::new(&case.contact, &state, asym_ok)?;
            if json {
                println!("{}", serde_json::to_string_pretty(&report)?);
            } else {
                print!("{}", report.table(&state));
            }
            if let Some(Err(e)) = asym {
                eprintln!("note: no asymptotic estimate: {e}");
            }
        }
        Command::Evolve {
            case,
            points,
            csv,
            json,
        } => {
            let case = case::load(&case)?;
            let cycle = case.cycle()?;
            let ev = evolution::evolve(&case.contact, &cycle, points, &options)?;
            if csv {
                print!("{}", report::evolve_csv(&ev));
            } else if json {
                println!("{}", report::evolve_json(&ev)?);
            } else {
                print!("{}", report::evolve_table(&ev));
            }
            if !json {
                for w in report::warnings(&ev) {
                    eprintln!("{w}");
                }
            }
        }
    }
    Ok(())
}

fn main() -> ExitCode {
    match run(Cli::parse()) {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => {
            eprintln!("error: {e:#}");
            ExitCode::from(2)
        }
    }
}
