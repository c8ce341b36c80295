//! The `halfplane` command: a thin layer that parses arguments, resolves the case file and prints
//! what the library computes.

mod case;
mod report;

use anyhow::Result;
use clap::{Parser, Subcommand, ValueEnum};
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
    /// Draws a figure as SVG or PNG (by the output file name).
    Plot {
        /// Which figure.
        figure: FigureKind,
        /// Case file (TOML); the figure says which sections it needs.
        case: PathBuf,
        /// Output file, ending in .svg or .png.
        #[arg(long, short)]
        output: PathBuf,
        /// evolution: points per half-cycle.
        #[arg(long, default_value_t = 41)]
        points: usize,
        /// evolution: overlay the time-marching stick zone (needs [history] kind = "cycle").
        #[arg(long)]
        march: bool,
        /// march-fields: increments to draw, comma-separated (default: 1/4, 1/2, 3/4 and the end
        /// of the last cycle, or the last increment).
        #[arg(long, value_delimiter = ',')]
        steps: Vec<usize>,
        /// slip-map: friction coefficients, one panel each.
        #[arg(long, value_delimiter = ',', default_values_t = [0.3, 0.6])]
        frictions: Vec<f64>,
        /// slip-map: P2/P1 values.
        #[arg(long, value_delimiter = ',', default_values_t = [1.0, 1.2, 1.5])]
        ratios: Vec<f64>,
        /// slip-map: dsigma/P1 values (1/mm), dsigma = sigma1 - sigma2.
        #[arg(long, value_delimiter = ',', default_values_t = [0.0, 0.02, 0.05])]
        tensions: Vec<f64>,
        /// slip-map: P1 (N/mm); default the smaller P of [cycle], or 1000.
        #[arg(long)]
        normal: Option<f64>,
        /// march figures: cells (overrides [solver] cells).
        #[arg(long)]
        cells: Option<usize>,
    },
}

/// The figures `halfplane plot` draws.
#[derive(Clone, Copy, ValueEnum)]
enum FigureKind {
    /// P-Q trajectory with friction lines and the P-S trajectories of both edges (needs [cycle]).
    LoadSpace,
    /// Right-edge slip zone against dQ/(f P0), the paper's Figure 5 (uses [material], [profile]).
    SlipMap,
    /// Contact edges and stick boundaries over a cycle, the paper's Figure 6 (needs [cycle]).
    Evolution,
    /// Shear traction and slip along x at chosen increments (needs [history]).
    MarchFields,
    /// Stick intervals against increment number (needs [history]).
    MarchZones,
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
                options = options.with_cells(n)?;
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
                    report::march_table(&result, &history, options.shakedown_tolerance())
                );
            }
        }
        Command::Plot {
            figure,
            case,
            output,
            points,
            march: overlay,
            steps,
            frictions,
            ratios,
            tensions,
            normal,
            cells,
        } => {
            let case = case::load(&case)?;
            let march_options = |case: &case::Case| match cells {
                Some(n) => case.solver.with_cells(n),
                None => Ok(case.solver),
            };
            let fig = match figure {
                FigureKind::LoadSpace => {
                    halfplane_plot::load_space_figure(&case.contact, &case.cycle()?)?
                }
                FigureKind::SlipMap => {
                    let p1 = normal.unwrap_or_else(|| {
                        case.cycle
                            .map_or(1000.0, |c| c.low.normal.min(c.high.normal))
                    });
                    if !(p1.is_finite() && p1 > 0.0) {
                        anyhow::bail!("invalid --normal = {p1}: must be a finite number > 0");
                    }
                    let map = halfplane_plot::SlipMap {
                        normal: p1,
                        frictions,
                        ratios,
                        tensions,
                        samples: 60,
                    };
                    halfplane_plot::slip_map_figure(&case.contact, &map)?
                }
                FigureKind::Evolution => {
                    let cycle = case.cycle()?;
                    let ev = evolution::evolve(&case.contact, &cycle, points, &options)?;
                    let marched = if overlay {
                        let history = case.history()?;
                        let result = march::march(
                            &case.contact,
                            &history,
                            &march_options(&case)?,
                            |_, _| {},
                        )?;
                        Some(halfplane_plot::MarchedCycle::last_cycle(&result, &history)?)
                    } else {
                        None
                    };
                    halfplane_plot::evolution_figure(&ev, marched.as_ref())
                }
                FigureKind::MarchFields | FigureKind::MarchZones => {
                    let history = case.history()?;
                    let n = history.loads.len();
                    let wanted = if steps.is_empty() {
                        match history.cycles {
                            Some(c) => {
                                let last = c.first_step + (c.count - 1) * c.steps_per_cycle;
                                (1..=4).map(|q| last + q * c.steps_per_cycle / 4).collect()
                            }
                            None => vec![n],
                        }
                    } else {
                        steps
                    };
                    if let Some(bad) = wanted.iter().find(|&&k| k == 0 || k > n) {
                        anyhow::bail!(
                            "invalid --steps value {bad}: the history has increments 1 to {n}"
                        );
                    }
                    let mut recorder = halfplane_plot::FieldRecorder {
                        steps: wanted,
                        kept: Vec::new(),
                    };
                    let f = case.contact.friction.value();
                    let result = march::march(
                        &case.contact,
                        &history,
                        &march_options(&case)?,
                        |r, fields| recorder.observe(r.step, fields, f),
                    )?;
                    match figure {
                        FigureKind::MarchFields => {
                            halfplane_plot::march_fields_figure(&recorder.kept)
                        }
                        _ => halfplane_plot::march_zones_figure(&result),
                    }
                }
            };
            halfplane_plot::write(&fig, &output)?;
            eprintln!("wrote {}", output.display());
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
