//! Figures for halfplane, drawn from the same numbers the library computes: the paper's load-space,
//! slip-zone-map (Figure 5) and stick-zone-evolution (Figure 6) plots, the marching solver's
//! fields and zones, filled maps of the stresses and fatigue parameters below the contact with
//! the surface profiles of the cycle, a crack's stress intensity ranges against its length
//! ([`crack_figure`]), design maps of a sweep's rows ([`design_map_figure`]), and a wear run's
//! depth and pressure at its checkpoints with a checkpoint quantity against cycles
//! ([`wear_figure`]).
//! SVG or PNG by file name, rendered in pure Rust with a bundled font. Maps are filled contours
//! with a colour bar ([`ColorBar`]), numbers in plain notation ([`number`]).
//!
//! Each `*_figure` function returns a [`Figure`] (plain data: panels of named series) that
//! [`write()`] renders, so callers and tests can inspect exactly what is drawn. The science behind
//! the figures is the library's: this crate only draws. The slip-map sweep ([`SlipMap`]) and the
//! march recorders ([`MarchedCycle`], [`FieldRecorder`], [`StepFields`]) live in
//! [`halfplane::slip_map`] and [`halfplane::record`] and are re-exported here.

mod contour;
mod crack;
mod fields;
mod format;
mod map;
mod matching;
mod render;
mod shading;
mod wear;

pub use contour::{contour_segments, filled_contours, levels, FilledContours, GridMap};
pub use crack::{crack_figure, crack_growth_panel};
pub use fields::{fatigue_map_figure, stress_map_figure, surface_profiles_figure};
pub use format::{level_labels, number};
pub use map::{design_map_figure, DesignMap, MapColor};
pub use matching::match_figure;
pub use shading::{diverging, sequential};
pub use wear::{wear_figure, CheckpointQuantity, MAX_PROFILES};

pub use render::{
    palette, render_svg, write, ColorBar, Figure, Legend, LogAxes, Panel, Series, Style,
};

pub use halfplane::record::{FieldRecorder, MarchedCycle, StepFields};
pub use halfplane::slip_map::SlipMap;

use halfplane::asymptotic::{equivalent_shear, Edge};
use halfplane::evolution::Evolution;
use halfplane::march::MarchResult;
use halfplane::{Contact, Cycle, LoadPoint};
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
    let f = contact.friction().value();
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
                let a = contact.contact_at(&x)?.half_width();
                Ok((x.normal(), equivalent_shear(x.shear(), x.bulk(), a, edge)))
            })
            .collect::<Result<Vec<_>, halfplane::Error>>()?;
        ps.push(Series::new(name, Style::Line, color, points));
    }
    let mut panels = vec![
        Panel {
            legend: Legend::Auto,
            color_bar: None,
            equal_aspect: false,
            log_axes: LogAxes::Neither,
            title: "P–Q trajectory".into(),
            x_label: format!("normal load P ({force})"),
            y_label: format!("shear load Q ({force})"),
            series: pq,
        },
        Panel {
            legend: Legend::Auto,
            color_bar: None,
            equal_aspect: false,
            log_axes: LogAxes::Neither,
            title: "P–S trajectories of the edges".into(),
            x_label: format!("normal load P ({force})"),
            y_label: format!("equivalent shear S ({force})"),
            series: ps,
        },
    ];
    if p1.moment() != 0.0 || p2.moment() != 0.0 {
        panels.push(moment_panel(contact, p1, p2, units)?);
    }
    Ok(Figure {
        title: "Load space".into(),
        panels,
    })
}

/// The moment's panel of the load space: the pressure centroid M/P and the contact's ends along
/// the in-phase segment, against P, so that the contact's shift with the moment can be read.
fn moment_panel(
    contact: &Contact,
    p1: LoadPoint,
    p2: LoadPoint,
    units: &Units,
) -> Result<Panel, PlotError> {
    let samples = (0..=40)
        .map(|i| {
            let x = p1.lerp(&p2, i as f64 / 40.0);
            Ok((x, contact.contact_at(&x)?))
        })
        .collect::<Result<Vec<_>, halfplane::Error>>()?;
    let along = |f: &dyn Fn(&LoadPoint, &halfplane::NormalContact) -> f64| {
        samples
            .iter()
            .map(|(x, c)| (x.normal(), f(x, c)))
            .collect::<Vec<_>>()
    };
    Ok(Panel {
        legend: Legend::Auto,
        color_bar: None,
        equal_aspect: false,
        log_axes: LogAxes::Neither,
        title: "Moment: centroid and contact ends".into(),
        x_label: format!("normal load P ({})", units.force_per_length),
        y_label: format!("position x ({})", units.length),
        series: vec![
            Series::new("centroid M/P", Style::Line, 0, along(&|x, _| x.centroid())),
            Series::new(
                "contact ends b1, b2",
                Style::Dashed,
                3,
                along(&|_, c| c.end(Edge::Left)),
            ),
            Series::new("", Style::Dashed, 3, along(&|_, c| c.end(Edge::Right))),
            Series::new(
                "point 1",
                Style::Points,
                1,
                vec![(p1.normal(), p1.centroid())],
            ),
            Series::new(
                "point 2",
                Style::Points,
                2,
                vec![(p2.normal(), p2.centroid())],
            ),
        ],
    })
}

/// Slip-zone map in the style of the paper's Figure 5, drawn from [`SlipMap::sweep`]: the
/// right-edge slip zone at the smaller contact, `(min(a1, a2) - n)/a0` with `a0 = a(P0)`, against
/// `dQ/(f P0)`, one curve per (P2/P1, dsigma/P1), one panel per friction coefficient. The
/// definitions, and which points are left out (so curves may stop early), are those of
/// [`halfplane::slip_map`].
pub fn slip_map_figure(
    contact: &Contact,
    map: &SlipMap,
    units: &Units,
) -> Result<Figure, PlotError> {
    let panels = map
        .sweep(contact)?
        .into_iter()
        .map(|panel| Panel {
            legend: Legend::Auto,
            color_bar: None,
            equal_aspect: false,
            log_axes: LogAxes::Neither,
            title: format!("f = {}", panel.friction),
            x_label: "ΔQ/(f P0)".into(),
            y_label: "right slip zone (min(a1, a2) − n)/a0".into(),
            series: panel
                .curves
                .into_iter()
                .enumerate()
                .map(|(color, curve)| Series {
                    name: format!("P2/P1 = {}, Δσ/P1 = {}", curve.ratio, curve.tension),
                    style: if curve.ratio == 1.0 && curve.tension == 0.0 {
                        Style::Dashed
                    } else {
                        Style::Line
                    },
                    color,
                    pieces: curve.pieces,
                })
                .collect(),
        })
        .collect();
    Ok(Figure {
        title: format!(
            "Slip-zone map (P1 = {} {})",
            map.normal, units.force_per_length
        ),
        panels,
    })
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
    let t = |p: &halfplane::evolution::EvolutionPoint| (p.half.number() - 1) as f64 + p.fraction;
    let pts = &evolution.points;
    let line = |f: &dyn Fn(&halfplane::evolution::EvolutionPoint) -> f64| {
        pts.iter().map(|p| (t(p), f(p))).collect::<Vec<_>>()
    };
    let centred = pts.iter().all(|p| p.contact.is_centred());
    let panel = |right: bool| {
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
        let edge = if right { Edge::Right } else { Edge::Left };
        series.push(Series::new(
            "contact edge",
            Style::Line,
            3,
            line(&|p| p.contact.end(edge)),
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
            color_bar: None,
            equal_aspect: false,
            log_axes: LogAxes::Neither,
            title: match (right, centred) {
                (true, true) => "right edge: a and n".into(),
                (false, true) => "left edge: −a and −m".into(),
                (true, false) => "right edge: b2 and n".into(),
                (false, false) => "left edge: b1 and −m".into(),
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
                color_bar: None,
                equal_aspect: false,
                log_axes: LogAxes::Neither,
                title: "shear traction".into(),
                x_label: format!("position x ({})", units.length),
                y_label: format!("traction q ({})", units.stress),
                series: traction,
            },
            Panel {
                legend: Legend::Auto,
                color_bar: None,
                equal_aspect: false,
                log_axes: LogAxes::Neither,
                title: "accumulated slip".into(),
                x_label: format!("position x ({})", units.length),
                y_label: format!("slip ({})", units.length),
                series: slip,
            },
        ],
    }
}

/// The fill of stick zones: the palette's blue, lightened so the contact edges read over it.
const STICK: (u8, u8, u8) = (140, 185, 230);

/// Stick and slip zones against increment number: contact edges, and every stick interval as a
/// filled cell one increment wide centred on its increment (the rest of the contact slips).
pub fn march_zones_figure(result: &MarchResult, units: &Units) -> Figure {
    let edges = |edge: Edge| {
        result
            .steps
            .iter()
            .map(|s| (s.step as f64, s.ends[edge]))
            .collect::<Vec<_>>()
    };
    let bars: Vec<(f64, f64)> = result
        .steps
        .iter()
        .flat_map(|s| {
            s.stick_intervals.iter().flat_map(move |&[l, r]| {
                let k = s.step as f64;
                [(k - 0.5, l), (k + 0.5, r)]
            })
        })
        .collect();
    Figure {
        title: "Time marching: stick and slip zones".into(),
        panels: vec![Panel {
            legend: Legend::Auto,
            color_bar: None,
            equal_aspect: false,
            log_axes: LogAxes::Neither,
            title: "stick zones (filled); slip between them and the contact edges".into(),
            x_label: "increment".into(),
            y_label: format!("position x ({})", units.length),
            series: vec![
                Series {
                    name: if result.steps.iter().all(|s| s.ends.left == -s.ends.right) {
                        "contact edges ±a".into()
                    } else {
                        "contact edges b1, b2".into()
                    },
                    style: Style::Line,
                    color: 3,
                    pieces: vec![edges(Edge::Right), edges(Edge::Left)],
                },
                Series::new("stick", Style::Filled(STICK), 0, bars),
            ],
        }],
    }
}
