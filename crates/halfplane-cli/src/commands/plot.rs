//! `halfplane plot FIGURE`: one figure, each with its own options, as SVG or PNG.

use crate::args::{Component, FigureArgs, MapParameter, PlotCommand};
use crate::case::{Case, FatigueSettings, WearSettings};
use crate::output::note;
use crate::report::wear::WearRow;
use crate::report::Cell;
use anyhow::{anyhow, bail, Result};
use halfplane::fatigue::{self, Parameter};
use halfplane::history::History;
use halfplane::march::{self, MarchOptions};
use halfplane::matching::Mode;
use halfplane::wear::Checkpoint;
use halfplane::written::Written;
use halfplane::{stress, Contact, Cycle};
use halfplane_plot::{CheckpointQuantity, FieldRecorder, GridMap, MarchedCycle, SlipMap, Units};
use std::path::PathBuf;

/// The most increments `march-fields` draws: each keeps four fields of every cell, and a figure
/// of more curves than this is unreadable anyway.
pub const MAX_STEPS: usize = 20;

/// What `plot` draws, and where.
#[derive(Debug, Clone)]
pub struct PlotConfig {
    /// The contact: profile, material and friction.
    pub contact: Contact,
    /// The axes' unit names, from the case's `[units]`.
    pub units: Units,
    /// The output file (its name ending says SVG or PNG; the plot crate checks it).
    pub output: PathBuf,
    /// Which figure, with its own settings.
    pub figure: FigureConfig,
}

/// The figure with what it alone needs.
#[derive(Debug, Clone)]
pub enum FigureConfig {
    /// The P-Q load space of the cycle, with the full-stick and sliding boundaries.
    LoadSpace {
        /// The cycle of `[cycle]`.
        cycle: Cycle,
    },
    /// The paper's Figure 5: slip-zone size against the shear range.
    SlipMap(SlipMap),
    /// The stick zone along the cycle (the paper's Figure 6), optionally with marching.
    Evolution {
        /// The cycle of `[cycle]`.
        cycle: Cycle,
        /// Points per half-cycle.
        points: usize,
        /// `--march`: the history to march and its solver settings.
        overlay: Option<(History, MarchOptions)>,
    },
    /// Pressure, traction and slip of chosen increments of a marched history.
    MarchFields {
        /// The load history of `[history]`.
        history: History,
        /// `[solver]` with `--cells` applied.
        options: MarchOptions,
        /// Increments to draw: 1 to the history's length, at most [`MAX_STEPS`].
        steps: Vec<usize>,
    },
    /// Stick intervals and contact edges of every increment of a marched history.
    MarchZones {
        /// The load history of `[history]`.
        history: History,
        /// `[solver]` with `--cells` applied.
        options: MarchOptions,
    },
    /// The load spaces of the prototype (the case) and its matched test.
    Match {
        /// The prototype's cycle of `[cycle]`.
        cycle: Cycle,
        /// The test contact.
        test: Contact,
        /// Asymptotic or exact.
        mode: Mode,
    },
    /// A stress component below the contact at an increment.
    StressMap {
        /// The load history of `[history]`.
        history: History,
        /// `[solver]` with `--cells` applied.
        options: MarchOptions,
        /// The increment, 1 to the history's length.
        step: usize,
        /// The component.
        component: Component,
    },
    /// A fatigue parameter over the grid of `[fatigue]`, or the surface profiles.
    Fatigue {
        /// The cyclic history of `[history]`.
        history: History,
        /// `[solver]` with `--cells` applied.
        options: MarchOptions,
        /// `[fatigue]`.
        settings: FatigueSettings,
        /// The parameter to map; `None`: the surface profiles.
        parameter: Option<Parameter>,
    },
    /// The crack: its ranges against length, and the stress map with the crack.
    Crack {
        /// The cyclic history of `[history]`.
        history: History,
        /// `[solver]` with `--cells` applied.
        options: MarchOptions,
        /// `[fatigue]`'s constants (the threshold's).
        constants: halfplane::fatigue::FatigueConstants,
        /// `[crack]`.
        crack: halfplane::crack::CrackOptions,
    },
    /// The wear run of `[wear]`: depth and pressure at the checkpoints, and a quantity of
    /// theirs against cycles.
    Wear {
        /// The case, whose `[history]` (one cycle, or sliding) the run repeats.
        case: Box<Case>,
        /// `[wear]`.
        settings: WearSettings,
        /// `--cells`.
        cells: Option<usize>,
        /// `--quantity`: a checkpoint column of the `wear` report.
        quantity: String,
    },
}

/// Points of the stress map along x and into the depth.
const MAP_POINTS: (usize, usize) = (121, 61);

impl PlotConfig {
    /// Reads the case and checks the figure's options against it.
    pub fn resolve(command: &PlotCommand) -> Result<Self> {
        let (common, case, figure) = match command {
            PlotCommand::LoadSpace(a) => {
                let case = load(a)?;
                let cycle = case.cycle()?;
                (a, case, FigureConfig::LoadSpace { cycle })
            }
            PlotCommand::SlipMap(a) => {
                let case = load(&a.figure)?;
                let p1 = a.normal.unwrap_or_else(|| {
                    case.cycle
                        .map_or(1000.0, |c| c.low().normal().min(c.high().normal()))
                });
                if !(p1.is_finite() && p1 > 0.0) {
                    bail!(
                        "invalid --normal = {}: must be a finite number > 0",
                        Written(p1)
                    );
                }
                let map = SlipMap {
                    normal: p1,
                    frictions: a.frictions.clone(),
                    ratios: a.ratios.clone(),
                    tensions: a.tensions.clone(),
                    samples: 60,
                };
                (&a.figure, case, FigureConfig::SlipMap(map))
            }
            PlotCommand::Evolution(a) => {
                let case = load(&a.figure)?;
                let cycle = case.cycle()?;
                let points = super::evolve::points(a.points)?;
                let overlay = match a.march {
                    true => Some(marching(&case, case.history()?, a.cells, &a.figure)?),
                    false => None,
                };
                let figure = FigureConfig::Evolution {
                    cycle,
                    points,
                    overlay,
                };
                (&a.figure, case, figure)
            }
            PlotCommand::MarchFields(a) => {
                let case = load(&a.figure)?;
                let (history, options) = marching(&case, case.history()?, a.cells, &a.figure)?;
                let steps = steps(&history, &a.steps)?;
                let figure = FigureConfig::MarchFields {
                    history,
                    options,
                    steps,
                };
                (&a.figure, case, figure)
            }
            PlotCommand::DesignMap(_) => {
                bail!("design-map draws a sweep's output, not a case: it is run by design_map::run")
            }
            PlotCommand::MarchZones(a) => {
                let case = load(&a.figure)?;
                let (history, options) = marching(&case, case.history()?, a.cells, &a.figure)?;
                (
                    &a.figure,
                    case,
                    FigureConfig::MarchZones { history, options },
                )
            }
            PlotCommand::Match(a) => {
                let case = load(&a.figure)?;
                let cycle = case.cycle()?;
                let options = a.test.options();
                let test = halfplane_case::matching::test_contact(&options, &case.contact)?;
                let mode = halfplane_case::matching::mode(&options);
                (&a.figure, case, FigureConfig::Match { cycle, test, mode })
            }
            PlotCommand::StressMap(a) => {
                let case = load(&a.figure)?;
                let (history, options) = marching(&case, case.history()?, a.cells, &a.figure)?;
                let last = history.loads().len();
                let step = a.step.unwrap_or(last);
                if step == 0 || step > last {
                    bail!("invalid --step {step}: the history has increments 1 to {last}");
                }
                let figure = FigureConfig::StressMap {
                    history,
                    options,
                    step,
                    component: a.component,
                };
                (&a.figure, case, figure)
            }
            PlotCommand::FatigueMap(a) => {
                let case = load(&a.figure)?;
                let settings = case.fatigue()?;
                let parameter = match a.parameter {
                    MapParameter::Swt => Parameter::Swt,
                    MapParameter::FatemiSocie => Parameter::FatemiSocie,
                    MapParameter::Findley => Parameter::Findley,
                    MapParameter::Crossland => Parameter::Crossland,
                    MapParameter::Mwcm => Parameter::Mwcm,
                    MapParameter::FatemiSocieMaxPlane => Parameter::FatemiSocieMaxPlane,
                    MapParameter::McDiarmid => Parameter::McDiarmid,
                };
                let missing = settings.constants.missing_for(parameter);
                if !missing.is_empty() {
                    bail!(
                        "--parameter {} needs {} in [fatigue]",
                        parameter.name(),
                        missing
                            .iter()
                            .map(|m| format!("fatigue.{m}"))
                            .collect::<Vec<_>>()
                            .join(" and ")
                    );
                }
                let (history, options) = marching(&case, cyclic(&case)?, a.cells, &a.figure)?;
                let figure = FigureConfig::Fatigue {
                    history,
                    options,
                    settings,
                    parameter: Some(parameter),
                };
                (&a.figure, case, figure)
            }
            PlotCommand::SurfaceProfiles(a) => {
                let case = load(&a.figure)?;
                let (history, options) = marching(&case, cyclic(&case)?, a.cells, &a.figure)?;
                let figure = FigureConfig::Fatigue {
                    history,
                    options,
                    settings: case.fatigue()?,
                    parameter: None,
                };
                (&a.figure, case, figure)
            }
            PlotCommand::Crack(a) => {
                let case = load(&a.figure)?;
                let crack = case.crack()?;
                let constants = case.fatigue()?.constants;
                let (history, options) = marching(&case, cyclic(&case)?, a.cells, &a.figure)?;
                let figure = FigureConfig::Crack {
                    history,
                    options,
                    constants,
                    crack,
                };
                (&a.figure, case, figure)
            }
            PlotCommand::Wear(a) => {
                let case = load(&a.figure)?;
                let settings = case.wear()?;
                if case.sliding.is_some() && a.quantity.starts_with("stick_") {
                    bail!(
                        "invalid --quantity {}: a sliding history ([history] kind = \"sliding\") has no stick zone; valid: {}",
                        a.quantity,
                        crate::args::wear_quantity_names()
                            .filter(|q| !q.starts_with("stick_"))
                            .collect::<Vec<_>>()
                            .join(", ")
                    );
                }
                let figure = FigureConfig::Wear {
                    case: Box::new(case.clone()),
                    settings,
                    cells: a.cells,
                    quantity: a.quantity.clone(),
                };
                (&a.figure, case, figure)
            }
        };
        Ok(Self {
            contact: case.contact,
            units: plot_units(&case.units),
            output: common.output.clone(),
            figure,
        })
    }
}

/// The unit names the figures' axis labels show.
fn plot_units(units: &crate::units::Units) -> halfplane_plot::Units {
    halfplane_plot::Units {
        force_per_length: units.force_per_length(),
        length: units.length.clone(),
        stress: units.stress.clone(),
    }
}

fn load(args: &FigureArgs) -> Result<Case> {
    crate::case::load(&args.case)
}

/// The solver settings of a figure that marches `history`, refused when the march is estimated
/// above the size limit (`crate::limits`) unless `--no-size-limit`.
fn marching(
    case: &Case,
    history: History,
    cells: Option<usize>,
    figure: &FigureArgs,
) -> Result<(History, MarchOptions)> {
    let options = case.solver_with_cells(cells)?;
    crate::limits::check_case_march(&history, &options, cells, figure.no_size_limit)?;
    Ok((history, options))
}

/// The history of `[history]`, which the fatigue figures need to have cycles.
fn cyclic(case: &Case) -> Result<History> {
    let history = case.history()?;
    if history.cycles().is_none() {
        bail!("the fatigue figures need a cyclic history: [history] kind = \"cycle\" or \"harmonic\" (a history from a file has no cycles)");
    }
    Ok(history)
}

/// The stress map: march to the increment, evaluate the component on a grid over
/// `+/-1.5 a` and down to `a` (`a` the half-width there) and draw it as a filled map.
fn stress_map(
    contact: &Contact,
    history: &History,
    options: &MarchOptions,
    step: usize,
    component: Component,
    units: &Units,
) -> Result<halfplane_plot::Figure> {
    let state = stress::marched(contact, history, options, &[step])?
        .into_iter()
        .next()
        .ok_or_else(|| anyhow!("the march did not reach step {step}"))?;
    let (x, z, field) = map_field(contact, &state)?;
    let (values, name) = match component {
        Component::Sxx => (field.sxx, "σxx"),
        Component::Szz => (field.szz, "σzz"),
        Component::Syy => (field.syy, "σyy"),
        Component::Sxz => (field.sxz, "σxz"),
    };
    let map = GridMap {
        x: &x,
        z: &z,
        values: &values,
    };
    Ok(halfplane_plot::stress_map_figure(
        &map,
        name,
        step,
        [state.ends.left, state.ends.right],
        units,
    )?)
}

/// The stresses of a marched increment on the map's grid over `+/-1.5 a` about the contact's
/// centre and down to `a` (`a` the half-width then): the grid's x and z and the field row after
/// row (z outer).
fn map_field(
    contact: &Contact,
    state: &stress::MarchedTraction,
) -> Result<(Vec<f64>, Vec<f64>, stress::StressField)> {
    // Centred on the contact, which a moment moves off x = 0.
    let a = state.half_width;
    let centre = 0.5 * (state.ends.left + state.ends.right);
    grid_field(contact, state, centre, 1.5 * a, a)
}

/// The stresses of a marched increment on the map's grid: `x` from `centre - half` to
/// `centre + half`, `z` from 0 to `depth`; the grid's x and z and the field row after row.
fn grid_field(
    contact: &Contact,
    state: &stress::MarchedTraction,
    centre: f64,
    half: f64,
    depth: f64,
) -> Result<(Vec<f64>, Vec<f64>, stress::StressField)> {
    let (nx, nz) = MAP_POINTS;
    let x: Vec<f64> = (0..nx)
        .map(|i| centre + half * (-1.0 + 2.0 * i as f64 / (nx - 1) as f64))
        .collect();
    let z: Vec<f64> = (0..nz)
        .map(|j| depth * j as f64 / (nz - 1) as f64)
        .collect();
    let (px, pz): (Vec<f64>, Vec<f64>) = z
        .iter()
        .flat_map(|&z| x.iter().map(move |&x| (x, z)))
        .unzip();
    let field = stress::field(
        &state.traction,
        state.load.bulk(),
        &contact.material(),
        &px,
        &pz,
    )?;
    Ok((x, z, field))
}

/// The crack figure: the analysis of `halfplane crack`, and the `sxx` map at the increment where
/// the longest crack opens most (the first of the cycle when it never opens).
fn crack_figure(
    contact: &Contact,
    history: &History,
    options: &MarchOptions,
    constants: &halfplane::fatigue::FatigueConstants,
    crack: &halfplane::crack::CrackOptions,
    units: &Units,
) -> Result<halfplane_plot::Figure> {
    let result = halfplane::crack::analyse(contact, history, options, constants, crack)?;
    let longest = result
        .rows
        .last()
        .ok_or_else(|| anyhow!("the crack analysis gave no rows"))?;
    let peak = longest
        .increments
        .iter()
        .enumerate()
        .max_by(|a, b| a.1.k1.total_cmp(&b.1.k1))
        .map_or(0, |(i, _)| i);
    let step = result.steps[peak];
    let state = stress::marched(contact, history, options, &[step])?
        .into_iter()
        .next()
        .ok_or_else(|| anyhow!("the march did not reach step {step}"))?;
    // The map around the crack: 1.5 crack lengths to either side of the mouth and below it (at
    // least a fifth of the contact half-width), so that the stress the crack crosses shows.
    let span = 1.5 * longest.length.max(0.2 * state.half_width);
    let (x, z, field) = grid_field(contact, &state, result.mouth, span, span)?;
    let map = GridMap {
        x: &x,
        z: &z,
        values: &field.sxx,
    };
    Ok(halfplane_plot::crack_figure(
        &result,
        &map,
        step,
        [state.ends.left, state.ends.right],
        units,
    )?)
}

/// The increments `march-fields` draws: as given, or 1/4, 1/2, 3/4 and the end of the last cycle
/// (the last increment for a history from a file).
fn steps(history: &History, given: &[usize]) -> Result<Vec<usize>> {
    let n = history.loads().len();
    let wanted = if given.is_empty() {
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
        given.to_vec()
    };
    if wanted.len() > MAX_STEPS {
        bail!(
            "invalid --steps: {} values given, at most {MAX_STEPS} can be drawn",
            wanted.len()
        );
    }
    if let Some(bad) = wanted.iter().find(|&&k| k == 0 || k > n) {
        bail!("invalid --steps value {bad}: the history has increments 1 to {n}");
    }
    Ok(wanted)
}

/// Computes the figure, writes it and says where on stderr. The figures that march or integrate
/// say they are running every progress interval, like the commands that do (`fatigue`).
pub fn run(config: &PlotConfig) -> Result<()> {
    let fig = crate::progress::while_running("plot", || figure(config))?;
    halfplane_plot::write(&fig, &config.output)?;
    note(&format!("wrote {}", config.output.display()));
    Ok(())
}

/// The figure's data computed and laid out.
fn figure(config: &PlotConfig) -> Result<halfplane_plot::Figure> {
    let (contact, units) = (&config.contact, &config.units);
    Ok(match &config.figure {
        FigureConfig::LoadSpace { cycle } => {
            halfplane_plot::load_space_figure(contact, cycle, units)?
        }
        FigureConfig::SlipMap(map) => halfplane_plot::slip_map_figure(contact, map, units)?,
        FigureConfig::Evolution {
            cycle,
            points,
            overlay,
        } => {
            let ev = super::evolve::evolve(contact, cycle, *points)?;
            let marched = match overlay {
                Some((history, options)) => {
                    let result = march::march(contact, history, options, |_, _| {})?;
                    let marched = MarchedCycle::last_cycle(&result, history).ok_or_else(|| {
                        anyhow!(
                            "the marching overlay needs a cyclic history ([history] kind = \"cycle\")"
                        )
                    })?;
                    Some(marched)
                }
                None => None,
            };
            halfplane_plot::evolution_figure(&ev, marched.as_ref(), units)
        }
        FigureConfig::MarchFields {
            history,
            options,
            steps,
        } => {
            let mut recorder = FieldRecorder {
                steps: steps.clone(),
                kept: Vec::new(),
            };
            let f = contact.friction().value();
            march::march(contact, history, options, |r, fields| {
                recorder.observe(r.step, fields, f)
            })?;
            halfplane_plot::march_fields_figure(&recorder.kept, units)
        }
        FigureConfig::MarchZones { history, options } => {
            let result = march::march(contact, history, options, |_, _| {})?;
            halfplane_plot::march_zones_figure(&result, units)
        }
        FigureConfig::Match { cycle, test, mode } => {
            let report = halfplane::matching::match_cycle(contact, cycle, test, *mode)?;
            halfplane_plot::match_figure(&report, units)?
        }
        FigureConfig::StressMap {
            history,
            options,
            step,
            component,
        } => stress_map(contact, history, options, *step, *component, units)?,
        FigureConfig::Fatigue {
            history,
            options,
            settings,
            parameter,
        } => {
            let result = fatigue::analyse(
                contact,
                history,
                options,
                &settings.constants,
                &settings.grid,
            )?;
            match parameter {
                Some(p) => halfplane_plot::fatigue_map_figure(&result, *p, units)?,
                None => halfplane_plot::surface_profiles_figure(&result, units),
            }
        }
        FigureConfig::Crack {
            history,
            options,
            constants,
            crack,
        } => crack_figure(contact, history, options, constants, crack, units)?,
        FigureConfig::Wear {
            case,
            settings,
            cells,
            quantity,
        } => {
            let mut worn = case.worn_march(settings, *cells)?;
            let result = halfplane::wear::run(&mut worn, &settings.options, |_| {})?;
            let quantity = checkpoint_quantity(&result.checkpoints, quantity, &case.units)?;
            halfplane_plot::wear_figure(&result, &quantity, worn.loop_datum(), units)?
        }
    })
}

/// The column `name` of the `wear` report at every checkpoint, with its unit: the numbers its
/// CSV prints (`None` where it prints nothing).
fn checkpoint_quantity(
    checkpoints: &[Checkpoint],
    name: &str,
    units: &crate::units::Units,
) -> Result<CheckpointQuantity> {
    let column = WearRow::COLUMNS
        .iter()
        .find(|c| c.key == name)
        .ok_or_else(|| anyhow!("invalid --quantity {name}: not a column of the wear report"))?;
    let values = checkpoints
        .iter()
        .map(|c| match (column.get)(&WearRow::new(c)) {
            Cell::Num(v) => Some(v),
            _ => None,
        })
        .collect();
    Ok(CheckpointQuantity {
        name: name.to_string(),
        unit: units.of(column.quantity),
        values,
    })
}
