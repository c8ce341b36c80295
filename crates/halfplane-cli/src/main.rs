//! The `halfplane` command: a thin layer that parses arguments, resolves the case file and prints
//! what the library computes.

use anyhow::Result;
use clap::{Parser, Subcommand, ValueEnum};
use halfplane::{asymptotic, evolution, march, steady, SteadyOptions};
use halfplane_cli::{case, report};
use indicatif::{ProgressBar, ProgressStyle};
use std::io::{self, Write};
use std::path::PathBuf;
use std::process::ExitCode;

/// A failed write to stdout. Kept apart from other errors so that `main` can end quietly when
/// the reader has gone away (`halfplane march case.toml --csv | head`).
#[derive(Debug)]
struct StdoutError(io::Error);

impl std::fmt::Display for StdoutError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "cannot write to stdout: {}", self.0)
    }
}

impl std::error::Error for StdoutError {}

/// Writes `text` to stdout and flushes it. `print!` would panic on a closed pipe or a full disk;
/// this returns the error instead.
fn emit(text: &str) -> Result<()> {
    let mut out = io::stdout().lock();
    out.write_all(text.as_bytes())
        .and_then(|()| out.flush())
        .map_err(|e| StdoutError(e).into())
}

/// A line on stderr. `eprintln!` would panic when stderr cannot be written (a full disk): the
/// message is then lost, but the run's outcome and exit code stand.
fn note(text: &str) {
    let _ = writeln!(io::stderr().lock(), "{text}");
}

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
                emit(&(serde_json::to_string_pretty(&report)? + "\n"))?;
            } else {
                emit(&report.table(&state))?;
            }
            if let Some(Err(e)) = asym {
                note(&format!("note: no asymptotic estimate: {e}"));
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
            let ev = evolve(&case.contact, &cycle, points, &options)?;
            if csv {
                emit(&report::evolve_csv(&ev))?;
            } else if json {
                emit(&(report::evolve_json(&ev)? + "\n"))?;
            } else {
                emit(&report::evolve_table(&ev))?;
            }
            if !json {
                for w in report::warnings(&ev) {
                    note(&w);
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
            let options = case.solver_with_cells(cells)?;
            if let Some(dir) = &fields {
                std::fs::create_dir_all(dir).map_err(|e| {
                    anyhow::anyhow!(
                        "cannot create the --fields directory {}: {e}",
                        dir.display()
                    )
                })?;
            }
            let bar = ProgressBar::new(history.loads().len() as u64);
            bar.set_style(
                // The template is a constant that parses; a plain bar would do if it did not.
                ProgressStyle::with_template("{bar:40} {pos}/{len} increments {elapsed}")
                    .unwrap_or_else(|_| ProgressStyle::default_bar()),
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
                emit(&report::march_csv(&result))?;
            } else if json {
                emit(&(report::march_json(&result)? + "\n"))?;
            } else {
                emit(&report::march_table(
                    &result,
                    &history,
                    options.shakedown_tolerance(),
                ))?;
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
            let march_options = |case: &case::Case| case.solver_with_cells(cells);
            let units = halfplane_plot::Units::default();
            let fig = match figure {
                FigureKind::LoadSpace => {
                    halfplane_plot::load_space_figure(&case.contact, &case.cycle()?, &units)?
                }
                FigureKind::SlipMap => {
                    let p1 = normal.unwrap_or_else(|| {
                        case.cycle
                            .map_or(1000.0, |c| c.low().normal().min(c.high().normal()))
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
                    halfplane_plot::slip_map_figure(&case.contact, &map, &units)?
                }
                FigureKind::Evolution => {
                    let cycle = case.cycle()?;
                    let ev = evolve(&case.contact, &cycle, points, &options)?;
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
                    halfplane_plot::evolution_figure(&ev, marched.as_ref(), &units)
                }
                FigureKind::MarchFields | FigureKind::MarchZones => {
                    let history = case.history()?;
                    let n = history.loads().len();
                    let wanted = if steps.is_empty() {
                        match history.cycles() {
                            Some(c) => {
                                let last = c.first_step() + (c.count() - 1) * c.steps_per_cycle();
                                (1..=4)
                                    .map(|q| last + q * c.steps_per_cycle() / 4)
                                    .collect()
                            }
                            None => vec![n],
                        }
                    } else {
                        steps
                    };
                    // Each drawn step keeps four fields of every cell; a figure of more curves
                    // than this is unreadable anyway.
                    const MAX_STEPS: usize = 20;
                    if wanted.len() > MAX_STEPS {
                        anyhow::bail!(
                            "invalid --steps: {} values given, at most {MAX_STEPS} can be drawn",
                            wanted.len()
                        );
                    }
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
                            halfplane_plot::march_fields_figure(&recorder.kept, &units)
                        }
                        _ => halfplane_plot::march_zones_figure(&result, &units),
                    }
                }
            };
            halfplane_plot::write(&fig, &output)?;
            note(&format!("wrote {}", output.display()));
        }
    }
    Ok(())
}

/// [`evolution::evolve`], with the library's `points` named as the option that gave it.
fn evolve(
    contact: &halfplane::Contact,
    cycle: &halfplane::Cycle,
    points: usize,
    options: &SteadyOptions,
) -> Result<evolution::Evolution> {
    evolution::evolve(contact, cycle, points, options).map_err(|e| match e {
        halfplane::Error::InvalidCount {
            field,
            value,
            min,
            max,
        } if field == "points" => {
            anyhow::anyhow!("invalid --points = {value}: must be a whole number from {min} to {max} (points per half-cycle)")
        }
        other => other.into(),
    })
}

fn write_fields(path: &std::path::Path, f: &march::Fields) -> Result<()> {
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
    write().map_err(|e| anyhow::anyhow!("cannot write {}: {e}", path.display()))
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

/// What to do next when a load case is outside the steady-state analysis, chosen by the library's
/// error variant (never by its text).
fn hint(error: &anyhow::Error) -> Option<&'static str> {
    use halfplane::Error;
    match error.chain().find_map(|e| e.downcast_ref::<Error>())? {
        Error::SlipReversesInHalf { .. }
        | Error::StickZoneOutsideContact { .. }
        | Error::SlipReversal { .. } => Some(
            "this cycle is outside the steady-state analysis; `halfplane march` (numerical time \
             marching) has no such restriction: give the case a [history] section with \
             kind = \"cycle\"",
        ),
        _ => None,
    }
}

/// Exit 0 on success, 2 on any error. A closed stdout pipe is a success, quietly: the reader
/// stopped on purpose (`| head`), as it would for `cat`; a shell would otherwise report 141
/// (SIGPIPE), which Rust programs do not receive (the runtime ignores the signal).
fn main() -> ExitCode {
    let cli = match Cli::try_parse() {
        Ok(cli) => cli,
        // Usage errors go to stderr (exit 2); --help and --version go to stdout (exit 0), where
        // a full disk is an error like any other output (clap's own exit would ignore it).
        Err(e) => {
            let printed = e.print();
            return match printed {
                _ if e.use_stderr() => ExitCode::from(2),
                Err(io) if io.kind() != io::ErrorKind::BrokenPipe => {
                    note(&format!("error: {}", StdoutError(io)));
                    ExitCode::from(2)
                }
                _ => ExitCode::SUCCESS,
            };
        }
    };
    match run(cli) {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => match e.downcast_ref::<StdoutError>() {
            Some(StdoutError(io)) if io.kind() == io::ErrorKind::BrokenPipe => ExitCode::SUCCESS,
            _ => {
                note(&format!("error: {e:#}"));
                if let Some(h) = hint(&e) {
                    note(&format!("hint: {h}"));
                }
                ExitCode::from(2)
            }
        },
    }
}
