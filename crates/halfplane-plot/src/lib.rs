//! Figures for halfplane, drawn from the same numbers the library computes: the paper's load-space,
//! slip-zone-map (Figure 5) and stick-zone-evolution (Figure 6) plots, and the marching solver's
//! fields and zones. SVG or PNG by file name, rendered in pure Rust with a bundled font.
//!
//! Each `*_figure` function returns a [`Figure`] (plain data: panels of named series) that
//! [`write()`] renders, so callers and tests can inspect exactly what is drawn.

mod render;

pub use render::{palette, render_svg, write, Figure, Legend, Panel, Series, Style};

use halfplane::asymptotic::{equivalent_shear, Edge};
use halfplane::evolution::Evolution;
use halfplane::march::{Fields, MarchResult};
use halfplane::steady::{self, Regime, SteadyOptions};
use halfplane::{Contact, Cycle, Friction, LoadPoint};
use thiserror::Error;

/// What can go wrong when plotting.
#[derive(Debug, Error)]
pub enum PlotError {
    /// The output name does not say SVG or PNG.
    #[error("cannot tell the format of {path}: the output file name must end in .svg or .png")]
    Format {
        /// The path given.
        path: String,
    },
    /// The output file cannot be written.
    #[error("cannot write {path}: {message}")]
    Io {
        /// The path given.
        path: String,
        /// The system's reason.
        message: String,
    },
    /// The drawing library failed.
    #[error("drawing failed: {0}")]
    Draw(String),
    /// The analysis behind the figure failed.
    #[error(transparent)]
    Analysis(#[from] halfplane::Error),
    /// The request cannot be drawn (for example an increment the history does not have).
    #[error("{0}")]
    Request(String),
}

/// Names of the units the axis labels show. The numbers are drawn as given: these only label them,
/// so they must be the units the case was written in.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Units {
    /// Force per unit length (P, Q): "N/mm" by default.
    pub force_per_length: String,
    /// Length (x, a, slip): "mm" by default.
    pub length: String,
    /// Stress (sigma, traction): "MPa" by default.
    pub stress: String,
}

impl Default for Units {
    fn default() -> Self {
        Self {
            force_per_length: "N/mm".into(),
            length: "mm".into(),
            stress: "MPa".into(),
        }
    }
}

/// Load space (the paper's Figure 2 and the P-S figure): the trajectory in P-Q with the friction
/// lines Q = +/- f P and the end points marked, and the P-S trajectories of the two edges,
/// `S = Q +/- pi a sigma/4` (left +, right -), sampled along the in-phase segment.
pub fn load_space_figure(
    contact: &Contact,
    cycle: &Cycle,
    units: &Units,
) -> Result<Figure, PlotError> {
    let force = &units.force_per_length;
    let f = contact.friction.value();
    let (p1, p2) = cycle.as_given();
    let p_max = 1.15 * p1.normal().max(p2.normal());
    let friction_lines = |color| {
        vec![
            Series::new(
                "friction lines ±fP",
                Style::Dashed,
                color,
                vec![(0.0, 0.0), (p_max, f * p_max)],
            ),
            Series::new(
                "",
                Style::Dashed,
                color,
                vec![(0.0, 0.0), (p_max, -f * p_max)],
            ),
        ]
    };
    let ends = |a: LoadPoint, b: LoadPoint| vec![(a.normal(), a.shear()), (b.normal(), b.shear())];
    let mut pq = friction_lines(3);
    pq.push(Series::new("trajectory", Style::Line, 0, ends(p1, p2)));
    pq.push(Series::new(
        "point 1",
        Style::Points,
        1,
        vec![(p1.normal(), p1.shear())],
    ));
    pq.push(Series::new(
        "point 2",
        Style::Points,
        2,
        vec![(p2.normal(), p2.shear())],
    ));
    let mut ps = friction_lines(3);
    for (edge, name, color) in [
        (Edge::Left, "left edge S = Q + πaσ/4", 0),
        (Edge::Right, "right edge S = Q − πaσ/4", 1),
    ] {
        let points = (0..=40)
            .map(|i| {
                let x = p1.lerp(&p2, i as f64 / 40.0);
                Ok((
                    x.normal(),
                    equivalent_shear(x.shear(), x.bulk(), contact.half_width(x.normal())?, edge),
                ))
            })
            .collect::<Result<Vec<_>, halfplane::Error>>()?;
        ps.push(Series::new(name, Style::Line, color, points));
    }
    Ok(Figure {
        title: "Load space".into(),
        panels: vec![
            Panel {
                legend: Legend::Auto,
                title: "P–Q trajectory".into(),
                x_label: format!("normal load P ({force})"),
                y_label: format!("shear load Q ({force})"),
                series: pq,
            },
            Panel {
                legend: Legend::Auto,
                title: "P–S trajectories of the edges".into(),
                x_label: format!("normal load P ({force})"),
                y_label: format!("equivalent shear S ({force})"),
                series: ps,
            },
        ],
    })
}

/// Parameters of the slip-zone map (the paper's Figure 5).
#[derive(Debug, Clone, PartialEq)]
pub struct SlipMap {
    /// Normal load at point 1, P1 (force per length).
    pub normal: f64,
    /// Friction coefficients, one panel each (the paper: 0.3 and 0.6).
    pub frictions: Vec<f64>,
    /// P2/P1 values.
    pub ratios: Vec<f64>,
    /// dsigma/P1 values (1/length), with dsigma = sigma1 - sigma2.
    pub tensions: Vec<f64>,
    /// Points along dQ/(f P0) in (0, 1).
    pub samples: usize,
}

/// Slip-zone map in the style of the paper's Figure 5: the right-edge slip zone at the smaller
/// contact, `(min(a1, a2) - n)/a0` with `a0 = a(P0)`, against `dQ/(f P0)`, one curve per
/// (P2/P1, dsigma/P1), one panel per friction coefficient. (At the smaller contact the paper's
/// observation holds that a larger P2/P1 shortens the slip zone, and the curves meet zero
/// continuously at the full-stick limit when dsigma = 0.) Cycles are centred on Q = 0 and on
/// sigma = 0. Points where the analysis does not apply (slip zones that do not grow monotonically
/// through a half-cycle, stick zone outside the contact) are left out, so curves may stop early;
/// with tension they stop short of the full-stick limit, since monotone growth needs
/// `dQ - pi a_max |dsigma|/4 > f |dP|` (`docs/validity.md`).
pub fn slip_map_figure(
    contact: &Contact,
    map: &SlipMap,
    units: &Units,
) -> Result<Figure, PlotError> {
    let mut panels = Vec::new();
    for &f in &map.frictions {
        let friction = Friction::new(f)?;
        let c = Contact {
            friction,
            ..contact.clone()
        };
        let mut series = Vec::new();
        let mut color = 0;
        for &ratio in &map.ratios {
            for &tension in &map.tensions {
                let (p1, p2) = (map.normal, ratio * map.normal);
                let p0 = 0.5 * (p1 + p2);
                let a0 = c.half_width(p0)?;
                let d_sigma = tension * p1;
                let mut pieces = vec![Vec::new()];
                for i in 1..map.samples {
                    let x = i as f64 / map.samples as f64;
                    let dq = x * f * p0;
                    let low = LoadPoint::new("point1", p1, -0.5 * dq, 0.5 * d_sigma)?;
                    let high = LoadPoint::new("point2", p2, 0.5 * dq, -0.5 * d_sigma)?;
                    match steady::analyse(&c, &Cycle::new(low, high), &SteadyOptions::default()) {
                        Ok(s)
                            if s.regime == Regime::PartialSlip || s.regime == Regime::FullStick =>
                        {
                            let right = s.stick_zone.map_or(0.0, |z| z.right);
                            let a_min = s.half_width[0].min(s.half_width[1]);
                            let w = if s.regime == Regime::FullStick {
                                0.0
                            } else {
                                (a_min - right) / a0
                            };
                            // `pieces` starts with one piece and only grows, so there is a
                            // last one; a fresh one would do if there were not.
                            match pieces.last_mut() {
                                Some(last) => last.push((x, w)),
                                None => pieces.push(vec![(x, w)]),
                            }
                        }
                        _ => {
                            if pieces.last().is_some_and(|p| !p.is_empty()) {
                                pieces.push(Vec::new());
                            }
                        }
                    }
                }
                pieces.retain(|p| !p.is_empty());
                let name = format!("P2/P1 = {ratio}, Δσ/P1 = {tension}");
                series.push(Series {
                    name,
                    style: if ratio == 1.0 && tension == 0.0 {
                        Style::Dashed
                    } else {
                        Style::Line
                    },
                    color,
                    pieces,
                });
                color += 1;
            }
        }
        panels.push(Panel {
            legend: Legend::Auto,
            title: format!("f = {f}"),
            x_label: "ΔQ/(f P0)".into(),
            y_label: "right slip zone (min(a1, a2) − n)/a0".into(),
            series,
        });
    }
    Ok(Figure {
        title: format!(
            "Slip-zone map (P1 = {} {})",
            map.normal, units.force_per_length
        ),
        panels,
    })
}

/// A marched history's stick intervals in the time of the steady cycle: `(t, left, right)` with
/// t in [0, 2] over the last cycle (half 1 then half 2), for overlaying on the evolution.
#[derive(Debug, Clone, PartialEq)]
pub struct MarchedCycle {
    /// `(t, left, right)` for every increment of the last cycle (largest stick interval).
    pub points: Vec<(f64, f64, f64)>,
}

impl MarchedCycle {
    /// The last cycle of `result` (its history must have cycles).
    pub fn last_cycle(
        result: &MarchResult,
        history: &halfplane::history::History,
    ) -> Result<Self, PlotError> {
        let c = history.cycles().ok_or_else(|| {
            PlotError::Request(
                "the marching overlay needs a cyclic history ([history] kind = \"cycle\")".into(),
            )
        })?;
        let start = c.first_step() + (c.count() - 1) * c.steps_per_cycle();
        let points = (1..=c.steps_per_cycle())
            .filter_map(|k| {
                result
                    .steps
                    .get(start + k - 1)?
                    .largest_stick()
                    .map(|[l, r]| (2.0 * k as f64 / c.steps_per_cycle() as f64, l, r))
            })
            .collect();
        Ok(Self { points })
    }
}

/// Contact and stick-zone evolution over a cycle in the style of the paper's Figure 6: contact
/// edge, exact stick boundary (partial-path relation), asymptotic estimate and, when given, the
/// marching solver's stick interval, against the time t in cycles (half 1: 0-1, half 2: 1-2).
/// One panel per edge, so the slip zones (between the lines) are large enough to read.
pub fn evolution_figure(
    evolution: &Evolution,
    marched: Option<&MarchedCycle>,
    units: &Units,
) -> Figure {
    let t = |p: &halfplane::evolution::EvolutionPoint| (p.half - 1) as f64 + p.fraction;
    let pts = &evolution.points;
    let line = |f: &dyn Fn(&halfplane::evolution::EvolutionPoint) -> f64| {
        pts.iter().map(|p| (t(p), f(p))).collect::<Vec<_>>()
    };
    let panel = |right: bool| {
        let side = if right { 1.0 } else { -1.0 };
        let mut series = Vec::new();
        // Markers first, so the analytic lines are drawn over them.
        if let Some(m) = marched {
            let points = m
                .points
                .iter()
                .map(|&(t, l, r)| (t, if right { r } else { l }))
                .collect();
            series.push(Series::new(
                "stick boundary (time marching)",
                Style::Points,
                2,
                points,
            ));
        }
        series.push(Series::new(
            "contact edge",
            Style::Line,
            3,
            line(&|p| side * p.half_width),
        ));
        series.push(Series::new(
            "stick boundary (exact)",
            Style::Line,
            0,
            line(&|p| {
                if right {
                    p.stick_zone.right
                } else {
                    p.stick_zone.left
                }
            }),
        ));
        series.push(Series::new(
            "stick boundary (asymptotic)",
            Style::Dashed,
            1,
            line(&|p| {
                if right {
                    p.asymptotic_stick_zone.right
                } else {
                    p.asymptotic_stick_zone.left
                }
            }),
        ));
        Panel {
            legend: Legend::Auto,
            title: if right {
                "right edge: a and n".into()
            } else {
                "left edge: −a and −m".into()
            },
            x_label: "time t (cycles): point 1 → 2 → 1".into(),
            y_label: format!("position x ({})", units.length),
            series,
        }
    };
    Figure {
        title: "Contact and stick-zone evolution over a cycle".into(),
        panels: vec![panel(false), panel(true)],
    }
}

/// Fields of chosen increments, as kept by [`FieldRecorder`].
#[derive(Debug, Clone, PartialEq)]
pub struct StepFields {
    /// Increment number.
    pub step: usize,
    /// Cell centres.
    pub x: Vec<f64>,
    /// f p (the friction limit).
    pub limit: Vec<f64>,
    /// Shear traction.
    pub traction: Vec<f64>,
    /// Accumulated slip.
    pub slip: Vec<f64>,
}

/// Keeps copies of the fields at chosen increments (use it in the marching observer).
#[derive(Debug, Clone, PartialEq, Default)]
pub struct FieldRecorder {
    /// Increments to keep.
    pub steps: Vec<usize>,
    /// What was kept.
    pub kept: Vec<StepFields>,
}

impl FieldRecorder {
    /// Records `fields` if `step` is wanted.
    pub fn observe(&mut self, step: usize, fields: &Fields, friction: f64) {
        if self.steps.contains(&step) {
            self.kept.push(StepFields {
                step,
                x: fields.x.to_vec(),
                limit: fields.pressure.iter().map(|p| friction * p).collect(),
                traction: fields.traction.to_vec(),
                slip: fields.slip.to_vec(),
            });
        }
    }
}

/// Shear traction (with the friction limits f p dashed) and accumulated slip along x at the
/// recorded increments.
pub fn march_fields_figure(fields: &[StepFields], units: &Units) -> Figure {
    let mut traction = Vec::new();
    let mut slip = Vec::new();
    for (i, f) in fields.iter().enumerate() {
        let xy = |v: &[f64]| {
            f.x.iter()
                .copied()
                .zip(v.iter().copied())
                .collect::<Vec<_>>()
        };
        traction.push(Series::new(
            format!("q, step {}", f.step),
            Style::Line,
            i,
            xy(&f.traction),
        ));
        let neg: Vec<f64> = f.limit.iter().map(|v| -v).collect();
        traction.push(Series {
            name: format!("±f p, step {}", f.step),
            style: Style::Dashed,
            color: i,
            pieces: vec![xy(&f.limit), xy(&neg)],
        });
        slip.push(Series::new(
            format!("slip, step {}", f.step),
            Style::Line,
            i,
            xy(&f.slip),
        ));
    }
    Figure {
        title: "Time marching: fields along the contact".into(),
        panels: vec![
            Panel {
                legend: Legend::Auto,
                title: "shear traction".into(),
                x_label: format!("position x ({})", units.length),
                y_label: format!("traction q ({})", units.stress),
                series: traction,
            },
            Panel {
                legend: Legend::Auto,
                title: "accumulated slip".into(),
                x_label: format!("position x ({})", units.length),
                y_label: format!("slip ({})", units.length),
                series: slip,
            },
        ],
    }
}

/// Stick and slip zones against increment number: contact edges, and every stick interval as a
/// vertical bar at its increment (the rest of the contact slips).
pub fn march_zones_figure(result: &MarchResult, units: &Units) -> Figure {
    let edges = |sign: f64| {
        result
            .steps
            .iter()
            .map(|s| (s.step as f64, sign * s.half_width))
            .collect::<Vec<_>>()
    };
    let bars: Vec<(f64, f64)> = result
        .steps
        .iter()
        .flat_map(|s| {
            s.stick_intervals
                .iter()
                .flat_map(move |&[l, r]| [(s.step as f64, l), (s.step as f64, r)])
        })
        .collect();
    Figure {
        title: "Time marching: stick and slip zones".into(),
        panels: vec![Panel {
            legend: Legend::Auto,
            title: "stick intervals (bars); slip between them and the contact edges".into(),
            x_label: "increment".into(),
            y_label: format!("position x ({})", units.length),
            series: vec![
                Series {
                    name: "contact edges ±a".into(),
                    style: Style::Line,
                    color: 3,
                    pieces: vec![edges(1.0), edges(-1.0)],
                },
                Series::new("stick", Style::Segments, 0, bars),
            ],
        }],
    }
}
