//! The `halfplane` command: a thin layer that parses arguments, resolves the case file and prints
//! what the library computes.

mod case;
mod report;

use anyhow::Result;
use clap::{Parser, Subcommand};
use halfplane::{asymptotic, evolution, march, steady, SteadyOptions};
use indicatif::{ProgressBar, ProgressStyle};
use std::io::Write;
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
    /// Numerical time marching through the load history in [history]: stick zones, tractions,
    /// slip and dissipated energy at every increment, slip amplitude per cycle.
    March {
        /// Case file (TOML) with [material], [friction], [profile], [history] and optionally
        /// [cycle] and [solver].
        case: PathBuf,
        /// Print CSV (one row per increment) instead of the summary.
        #[arg(long, conflicts_with = "json")]
        csv: bool,
        /// Print one JSON object instead of the summary.
        #[arg(long)]
        json: bool,
        /// Write the fields of every increment (x, pressure, traction, slip, slip_increment) as
        /// DIR/step_NNNNN.csv, and the slip amplitude of every cycle as DIR/slip_amplitude.csv.
        #[arg(long, value_name = "DIR")]
        fields: Option<PathBuf>,
        /// Cells across the largest contact (overrides [solver] cells; default 400).
        #[arg(long)]
        cells: Option<usize>,
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
        Command::March {
            case,
            csv,
            json,
            fields,
            cells,
        } => {
            let case = case::load(&case)?;
            let history = case.history()?;
            let mut options = case.solver;
            if let Some(n) = cells {
                options.cells = n;
            }
            if let Some(dir) = &fields {
                std::fs::create_dir_all(dir).map_err(|e| {
                    anyhow::anyhow!(
                        "cannot create the --fields directory {}: {e}",
                        dir.display()
                    )
                })?;
            }
            let bar = ProgressBar::new(history.loads.len() as u64);
            bar.set_style(
                ProgressStyle::with_template("{bar:40} {pos}/{len} increments {elapsed}")
                    .expect("valid template"),
            );
            let mut write_error = None;
            let result = march::march(&case.contact, &history, &options, |report, f| {
                bar.inc(1);
                if let (Some(dir), None) = (&fields, &write_error) {
                    if let Err(e) =
                        write_fields(&dir.join(format!("step_{:05}.csv", report.step)), f)
                    {
                        write_error = Some(e);
                    }
                }
            });
            bar.finish_and_clear();
            let result = result?;
            if let Some(e) = write_error {
                return Err(e);
            }
            if let (Some(dir), false) = (&fields, result.cycles.is_empty()) {
                write_amplitudes(&dir.join("slip_amplitude.csv"), &result)?;
            }
            if csv {
                print!("{}", report::march_csv(&result));
            } else if json {
                println!("{}", report::march_json(&result)?);
            } else {
                print!(
                    "{}",
                    report::march_table(&result, &history, options.shakedown_tolerance)
                );
            }
        }
    }
    Ok(())
}

fn write_fields(path: &std::path::Path, f: &march::Fields) -> Result<()> {
    let file = std::fs::File::create(path)
        .map_err(|e| anyhow::anyhow!("cannot write {}: {e}", path.display()))?;
    let mut out = std::io::BufWriter::new(file);
    writeln!(out, "x,pressure,traction,slip,slip_increment")?;
    for i in 0..f.x.len() {
        writeln!(
            out,
            "{},{},{},{},{}",
            f.x[i], f.pressure[i], f.traction[i], f.slip[i], f.slip_increment[i]
        )?;
    }
    out.flush()
        .map_err(|e| anyhow::anyhow!("cannot write {}: {e}", path.display()))
}

fn write_amplitudes(path: &std::path::Path, result: &march::MarchResult) -> Result<()> {
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
    std::fs::write(path, o).map_err(|e| anyhow::anyhow!("cannot write {}: {e}", path.display()))
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
