//! `halfplane plot FIGURE`: one figure, each with its own options, as SVG or PNG.

use crate::args::{Component, FigureArgs, MapParameter, PlotCommand};
use crate::case::{Case, FatigueSettings, WearSettings};
use anyhow::{bail, Result};
use halfplane::fatigue::Parameter;
use halfplane::history::History;
use halfplane::march::MarchOptions;
use halfplane::matching::Mode;
use halfplane::written::Written;
use halfplane::{Contact, Cycle};
use halfplane_plot::{SlipMap, Units};
use std::path::PathBuf;

mod draw;
pub use draw::run;

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
