//! Reports for `steady` and `evolve`: a readable table, JSON and CSV, built from library results.

use halfplane::asymptotic::AsymptoticSteady;
use halfplane::evolution::{Evolution, EvolutionWarning, PointState};
use halfplane::steady::{GivenPoint, Regime, SteadyState};
use halfplane::{Contact, Shape, StickZone};
use serde::Serialize;
use std::fmt::Write;

#[derive(Serialize)]
pub struct SteadyReport {
    regime: &'static str,
    profile: ProfileReport,
    compliance: f64,
    friction: f64,
    points: Pair<PointReport>,
    /// Which given point is point 1 of the analysis (the end of smaller Q).
    smaller_shear_point: &'static str,
    criteria: CriteriaReport,
    contact: ContactReport,
    stick_zone: Option<ZoneReport>,
    slip_zones: Option<Edges<Pair<f64>>>,
    asymptotic: Option<AsymptoticReport>,
}

#[derive(Serialize)]
struct ProfileReport {
    kind: &'static str,
    #[serde(skip_serializing_if = "Option::is_none")]
    radius: Option<f64>,
    #[serde(skip_serializing_if = "Option::is_none")]
    flat_half_width: Option<f64>,
    #[serde(skip_serializing_if = "Option::is_none")]
    coefficient: Option<f64>,
    #[serde(skip_serializing_if = "Option::is_none")]
    exponent: Option<f64>,
    #[serde(skip_serializing_if = "Option::is_none")]
    rows: Option<usize>,
    kinks: Vec<f64>,
}

#[derive(Serialize, Clone, Copy)]
struct Pair<T> {
    #[serde(rename = "at_point1")]
    first: T,
    #[serde(rename = "at_point2")]
    second: T,
}

#[derive(Serialize)]
struct Edges<T> {
    left: T,
    right: T,
}

#[derive(Serialize)]
struct PointReport {
    normal: f64,
    shear: f64,
    bulk: f64,
}

#[derive(Serialize)]
struct CriteriaReport {
    shear_ratio_1: f64,
    shear_ratio_2: f64,
    full_stick_ratio: Option<f64>,
    shear_range: f64,
    bulk_term: f64,
    friction: f64,
}

#[derive(Serialize)]
struct ContactReport {
    half_width_1: f64,
    half_width_2: f64,
    normal_intensity_1: f64,
    normal_intensity_2: f64,
}

#[derive(Serialize, Clone, Copy)]
struct ZoneReport {
    left: f64,
    right: f64,
    half_width: f64,
    eccentricity: f64,
}

impl From<StickZone> for ZoneReport {
    fn from(z: StickZone) -> Self {
        Self {
            left: z.left,
            right: z.right,
            half_width: z.half_width(),
            eccentricity: z.eccentricity(),
        }
    }
}

#[derive(Serialize)]
struct Compared {
    estimate: f64,
    exact: f64,
    relative_difference: f64,
}

impl Compared {
    fn new(estimate: f64, exact: f64) -> Self {
        Self {
            estimate,
            exact,
            relative_difference: (estimate - exact) / exact,
        }
    }
}

#[derive(Serialize)]
struct EdgeReport {
    shear_intensity_left: f64,
    shear_intensity_right: f64,
    equivalent_shear_left: f64,
    equivalent_shear_right: f64,
}

#[derive(Serialize)]
struct AsymptoticReport {
    stick_zone: AsymptoticZone,
    stick_load: Edges<f64>,
    edges: Pair<EdgeReport>,
    slip_zones: Edges<Pair<Compared>>,
}

#[derive(Serialize)]
struct AsymptoticZone {
    left: f64,
    right: f64,
    relative_difference_left: f64,
    relative_difference_right: f64,
}

/// One labelled row of a two-column (point1, point2) table.
fn row(o: &mut String, label: &str, a: f64, b: f64, note: &str) {
    let _ = writeln!(o, "{label:<15}{a:>14.6} {b:>14.6}{note}");
}

fn regime_name(r: &Regime) -> &'static str {
    match r {
        Regime::GrossSliding { .. } => "gross-sliding",
        Regime::FullStick => "full-stick",
        Regime::PartialSlip => "partial-slip",
    }
}

fn profile_report(contact: &Contact) -> ProfileReport {
    let mut r = ProfileReport {
        kind: "",
        radius: None,
        flat_half_width: None,
        coefficient: None,
        exponent: None,
        rows: None,
        kinks: contact.profile.kinks(),
    };
    match contact.profile.shape() {
        Shape::Hertz { radius } => (r.kind, r.radius) = ("hertz", Some(*radius)),
        Shape::FlatRounded {
            flat_half_width,
            edge_radius,
        } => {
            (r.kind, r.radius, r.flat_half_width) =
                ("flat-rounded", Some(*edge_radius), Some(*flat_half_width))
        }
        Shape::PowerLaw {
            coefficient,
            exponent,
        } => {
            (r.kind, r.coefficient, r.exponent) = ("power-law", Some(*coefficient), Some(*exponent))
        }
        Shape::Tabulated { x, .. } => (r.kind, r.rows) = ("tabulated", Some(x.len())),
    }
    r
}

impl SteadyReport {
    pub fn new(
        contact: &Contact,
        steady: &SteadyState,
        asymptotic: Option<&AsymptoticSteady>,
    ) -> anyhow::Result<Self> {
        let (first, second) = steady.cycle.as_given();
        let point = |p: halfplane::LoadPoint| PointReport {
            normal: p.normal(),
            shear: p.shear(),
            bulk: p.bulk(),
        };
        let c = &steady.criteria;
        let asymptotic = match (asymptotic, steady.stick_zone, steady.slip_zones) {
            (Some(a), Some(zone), Some(slip)) if steady.regime == Regime::PartialSlip => {
                let edge = |e: &halfplane::asymptotic::EdgeState| EdgeReport {
                    shear_intensity_left: e.shear_intensity[0],
                    shear_intensity_right: e.shear_intensity[1],
                    equivalent_shear_left: e.equivalent_shear[0],
                    equivalent_shear_right: e.equivalent_shear[1],
                };
                Some(AsymptoticReport {
                    stick_zone: AsymptoticZone {
                        left: a.stick_zone.left,
                        right: a.stick_zone.right,
                        relative_difference_left: (a.stick_zone.left - zone.left) / zone.left,
                        relative_difference_right: (a.stick_zone.right - zone.right) / zone.right,
                    },
                    stick_load: Edges {
                        left: a.stick_load[0],
                        right: a.stick_load[1],
                    },
                    edges: Pair {
                        first: edge(&a.edges[0]),
                        second: edge(&a.edges[1]),
                    },
                    slip_zones: Edges {
                        left: Pair {
                            first: Compared::new(a.slip_zones[0][0], slip.left[0]),
                            second: Compared::new(a.slip_zones[1][0], slip.left[1]),
                        },
                        right: Pair {
                            first: Compared::new(a.slip_zones[0][1], slip.right[0]),
                            second: Compared::new(a.slip_zones[1][1], slip.right[1]),
                        },
                    },
                })
            }
            _ => None,
        };
        Ok(Self {
            regime: regime_name(&steady.regime),
            profile: profile_report(contact),
            compliance: contact.compliance().value(),
            friction: contact.friction.value(),
            points: Pair {
                first: point(first),
                second: point(second),
            },
            smaller_shear_point: if steady.cycle.swapped() {
                "point2"
            } else {
                "point1"
            },
            criteria: CriteriaReport {
                shear_ratio_1: c.shear_ratio[0],
                shear_ratio_2: c.shear_ratio[1],
                full_stick_ratio: c.full_stick_ratio.is_finite().then_some(c.full_stick_ratio),
                shear_range: steady.cycle.shear_range(),
                bulk_term: c.bulk_term,
                friction: c.friction,
            },
            contact: ContactReport {
                half_width_1: steady.half_width[0],
                half_width_2: steady.half_width[1],
                normal_intensity_1: contact.normal_intensity(steady.half_width[0])?,
                normal_intensity_2: contact.normal_intensity(steady.half_width[1])?,
            },
            stick_zone: steady.stick_zone.map(ZoneReport::from),
            slip_zones: steady.slip_zones.map(|s| Edges {
                left: Pair {
                    first: s.left[0],
                    second: s.left[1],
                },
                right: Pair {
                    first: s.right[0],
                    second: s.right[1],
                },
            }),
            asymptotic,
        })
    }

    /// A readable table.
    pub fn table(&self, steady: &SteadyState) -> String {
        let mut o = String::new();
        let p = &self.points;
        let _ = writeln!(
            o,
            "profile      {}   A = {:.6e}   f = {}",
            self.profile.kind, self.compliance, self.friction
        );
        let _ = writeln!(o, "               {:>14} {:>14}", "point1", "point2");
        row(&mut o, "normal P", p.first.normal, p.second.normal, "");
        row(&mut o, "shear Q", p.first.shear, p.second.shear, "");
        row(&mut o, "bulk sigma", p.first.bulk, p.second.bulk, "");
        row(
            &mut o,
            "|Q|/P",
            self.criteria.shear_ratio_1,
            self.criteria.shear_ratio_2,
            &format!("   (gross sliding when >= f = {})", self.friction),
        );
        row(
            &mut o,
            "half-width a",
            self.contact.half_width_1,
            self.contact.half_width_2,
            "",
        );
        row(
            &mut o,
            "K_N",
            self.contact.normal_intensity_1,
            self.contact.normal_intensity_2,
            "",
        );
        let ratio = self
            .criteria
            .full_stick_ratio
            .map_or("infinite (dP = 0)".to_string(), |r| format!("{r:.6}"));
        let _ = writeln!(
            o,
            "eq. (1): (|dQ| + pi a_max |dsigma|/4)/|dP| = {ratio}   (full stick when <= f)"
        );
        let _ = writeln!(o);
        let regime = match steady.regime {
            Regime::GrossSliding { point } => format!(
                "gross sliding at {} (|Q| >= f P): no steady partial-slip state",
                if point == GivenPoint::First {
                    "point1"
                } else {
                    "point2"
                }
            ),
            Regime::FullStick => "full stick: no slip anywhere in the steady state".to_string(),
            Regime::PartialSlip => {
                "partial slip: permanent stick zone with slip at both edges".to_string()
            }
        };
        let _ = writeln!(o, "regime       {} — {regime}", self.regime);
        if let Some(z) = &self.stick_zone {
            let _ = writeln!(
                o,
                "stick zone   [-m, n] = [{:.6}, {:.6}]   d = {:.6}   e = {:.6}",
                z.left, z.right, z.half_width, z.eccentricity
            );
        }
        if let Some(s) = &self.slip_zones {
            let _ = writeln!(o, "slip zones     {:>14} {:>14}", "at point1", "at point2");
            row(&mut o, "  left", s.left.first, s.left.second, "");
            row(&mut o, "  right", s.right.first, s.right.second, "");
        }
        if let Some(a) = &self.asymptotic {
            let _ = writeln!(o);
            let _ = writeln!(o, "asymptotic (edge) description");
            row(
                &mut o,
                "  K_T left",
                a.edges.first.shear_intensity_left,
                a.edges.second.shear_intensity_left,
                "",
            );
            row(
                &mut o,
                "  K_T right",
                a.edges.first.shear_intensity_right,
                a.edges.second.shear_intensity_right,
                "",
            );
            row(
                &mut o,
                "  S left",
                a.edges.first.equivalent_shear_left,
                a.edges.second.equivalent_shear_left,
                "",
            );
            row(
                &mut o,
                "  S right",
                a.edges.first.equivalent_shear_right,
                a.edges.second.equivalent_shear_right,
                "",
            );
            let _ = writeln!(
                o,
                "  P_K          left {:.6}   right {:.6}",
                a.stick_load.left, a.stick_load.right
            );
            let _ = writeln!(
                o,
                "  stick zone   [{:.6}, {:.6}]   vs exact: {:+.3}% left, {:+.3}% right",
                a.stick_zone.left,
                a.stick_zone.right,
                100.0 * a.stick_zone.relative_difference_left,
                100.0 * a.stick_zone.relative_difference_right
            );
            for (name, e) in [("left", &a.slip_zones.left), ("right", &a.slip_zones.right)] {
                for (point, c) in [("point1", &e.first), ("point2", &e.second)] {
                    let _ = writeln!(
                        o,
                        "  slip {name:<5} at {point}: w = {:.6}   exact {:.6}   ({:+.3}%)",
                        c.estimate,
                        c.exact,
                        100.0 * c.relative_difference
                    );
                }
            }
        }
        o
    }
}

fn state_name(s: &PointState) -> &'static str {
    match s {
        PointState::FullStick => "full-stick",
        PointState::PartialSlip => "partial-slip",
        PointState::OneEdgeSlip { .. } => "one-edge-slip",
    }
}

/// Warnings in words, for stderr or the table.
pub fn warnings(ev: &Evolution) -> Vec<String> {
    ev.warnings
        .iter()
        .map(|w| match w {
            EvolutionWarning::NonMonotoneSlip { half, edge, fraction } => format!(
                "warning: half {half}: the {} stick boundary moves outwards at fraction {fraction:.4}; slip zones do not grow monotonically, so the exact partial-path result does not hold there (use `halfplane march`)",
                edge.name()
            ),
            EvolutionWarning::OneEdgeSlip { half, count } => format!(
                "warning: half {half}: {count} point(s) slip at one edge only; their slipping boundary is from the two-edge relation and only approximate (use `halfplane march` for exact values)"
            ),
        })
        .collect()
}

pub const EVOLVE_COLUMNS: &str = "half,fraction,normal,shear,bulk,half_width,stick_left,stick_right,asymptotic_stick_left,asymptotic_stick_right,state";

/// CSV, one row per point.
pub fn evolve_csv(ev: &Evolution) -> String {
    let mut o = String::from(EVOLVE_COLUMNS);
    o.push('\n');
    for p in &ev.points {
        let _ = writeln!(
            o,
            "{},{},{},{},{},{},{},{},{},{},{}",
            p.half,
            p.fraction,
            p.load.normal(),
            p.load.shear(),
            p.load.bulk(),
            p.half_width,
            p.stick_zone.left,
            p.stick_zone.right,
            p.asymptotic_stick_zone.left,
            p.asymptotic_stick_zone.right,
            state_name(&p.state)
        );
    }
    o
}

/// A readable table.
pub fn evolve_table(ev: &Evolution) -> String {
    let mut o = String::new();
    let _ = writeln!(o, "regime {}", regime_name(&ev.regime));
    let _ = writeln!(
        o,
        "{:>4} {:>8} {:>11} {:>11} {:>10} {:>10} {:>11} {:>11} {:>11} {:>11}  state",
        "half",
        "fraction",
        "normal",
        "shear",
        "bulk",
        "a",
        "stick_left",
        "stick_right",
        "asym_left",
        "asym_right"
    );
    for p in &ev.points {
        let _ = writeln!(
            o,
            "{:>4} {:>8.4} {:>11.4} {:>11.4} {:>10.4} {:>10.6} {:>11.6} {:>11.6} {:>11.6} {:>11.6}  {}",
            p.half,
            p.fraction,
            p.load.normal(),
            p.load.shear(),
            p.load.bulk(),
            p.half_width,
            p.stick_zone.left,
            p.stick_zone.right,
            p.asymptotic_stick_zone.left,
            p.asymptotic_stick_zone.right,
            state_name(&p.state)
        );
    }
    o
}

#[derive(Serialize)]
struct EvolveRow {
    half: u8,
    fraction: f64,
    normal: f64,
    shear: f64,
    bulk: f64,
    half_width: f64,
    stick_left: f64,
    stick_right: f64,
    asymptotic_stick_left: f64,
    asymptotic_stick_right: f64,
    state: &'static str,
}

#[derive(Serialize)]
struct EvolveReport {
    regime: &'static str,
    points: Vec<EvolveRow>,
    warnings: Vec<String>,
}

/// One JSON object.
pub fn evolve_json(ev: &Evolution) -> serde_json::Result<String> {
    let report = EvolveReport {
        regime: regime_name(&ev.regime),
        points: ev
            .points
            .iter()
            .map(|p| EvolveRow {
                half: p.half,
                fraction: p.fraction,
                normal: p.load.normal(),
                shear: p.load.shear(),
                bulk: p.load.bulk(),
                half_width: p.half_width,
                stick_left: p.stick_zone.left,
                stick_right: p.stick_zone.right,
                asymptotic_stick_left: p.asymptotic_stick_zone.left,
                asymptotic_stick_right: p.asymptotic_stick_zone.right,
                state: state_name(&p.state),
            })
            .collect(),
        warnings: warnings(ev),
    };
    serde_json::to_string_pretty(&report)
}

pub const MARCH_COLUMNS: &str = "step,normal,shear,bulk,half_width,stick_left,stick_right,stick_intervals,energy_increment,energy,passes";

fn intervals_text(steps: &[[f64; 2]]) -> String {
    steps
        .iter()
        .map(|[l, r]| format!("{l}:{r}"))
        .collect::<Vec<_>>()
        .join(" ")
}

/// One CSV row per increment; the stick columns hold the largest stick interval (empty when
/// none) and `stick_intervals` every interval as `left:right`, space-separated.
pub fn march_csv(result: &halfplane::march::MarchResult) -> String {
    let mut o = String::from(MARCH_COLUMNS);
    o.push('\n');
    for s in &result.steps {
        let (l, r) = s
            .largest_stick()
            .map_or((String::new(), String::new()), |[l, r]| {
                (l.to_string(), r.to_string())
            });
        let _ = writeln!(
            o,
            "{},{},{},{},{},{l},{r},{},{},{},{}",
            s.step,
            s.load.normal(),
            s.load.shear(),
            s.load.bulk(),
            s.half_width,
            intervals_text(&s.stick_intervals),
            s.energy_increment,
            s.energy,
            s.passes
        );
    }
    o
}

#[derive(Serialize)]
struct MarchStepRow<'a> {
    step: usize,
    normal: f64,
    shear: f64,
    bulk: f64,
    half_width: f64,
    stick_intervals: &'a [[f64; 2]],
    largest_stick: Option<[f64; 2]>,
    energy_increment: f64,
    energy: f64,
}

#[derive(Serialize)]
struct MarchCycleRow {
    index: usize,
    energy: f64,
    max_slip_amplitude: f64,
}

#[derive(Serialize)]
struct MarchReport<'a> {
    cells: usize,
    cell_width: f64,
    steps: Vec<MarchStepRow<'a>>,
    cycles: Vec<MarchCycleRow>,
    shakedown_cycle: Option<usize>,
}

/// One JSON object.
pub fn march_json(result: &halfplane::march::MarchResult) -> serde_json::Result<String> {
    let report = MarchReport {
        cells: result.x.len(),
        // A march has at least 8 cells (the solver rejects fewer).
        cell_width: result.x[1] - result.x[0],
        steps: result
            .steps
            .iter()
            .map(|s| MarchStepRow {
                step: s.step,
                normal: s.load.normal(),
                shear: s.load.shear(),
                bulk: s.load.bulk(),
                half_width: s.half_width,
                stick_intervals: &s.stick_intervals,
                largest_stick: s.largest_stick(),
                energy_increment: s.energy_increment,
                energy: s.energy,
            })
            .collect(),
        cycles: result
            .cycles
            .iter()
            .map(|c| MarchCycleRow {
                index: c.index,
                energy: c.energy,
                max_slip_amplitude: c.max_slip_amplitude(),
            })
            .collect(),
        shakedown_cycle: result.shakedown_cycle,
    };
    serde_json::to_string_pretty(&report)
}

/// A readable summary.
pub fn march_table(
    result: &halfplane::march::MarchResult,
    history: &halfplane::history::History,
    tolerance: f64,
) -> String {
    let mut o = String::new();
    // A march has at least 8 cells (the solver rejects fewer), so these indices exist.
    let n = result.x.len();
    let w = result.x[1] - result.x[0];
    let span = result.x[n - 1] + 0.5 * w;
    let _ = writeln!(
        o,
        "grid         {n} cells over [-{span:.6}, {span:.6}], cell width {w:.6}"
    );
    match history.cycles() {
        Some(c) => {
            let _ = writeln!(
                o,
                "history      {} increments: {} of ramp, {} cycles of {}",
                history.loads().len(),
                c.first_step(),
                c.count(),
                c.steps_per_cycle()
            );
        }
        None => {
            let _ = writeln!(
                o,
                "history      {} increments from the file",
                history.loads().len()
            );
        }
    }
    if let Some(last) = result.steps.last() {
        let _ = writeln!(o, "energy       {:.6e} dissipated in all", last.energy);
    }
    if !result.cycles.is_empty() {
        let _ = writeln!(
            o,
            "\n{:>6} {:>14} {:>20}",
            "cycle", "energy", "max slip amplitude"
        );
        for c in &result.cycles {
            let _ = writeln!(
                o,
                "{:>6} {:>14.6e} {:>20.6e}",
                c.index,
                c.energy,
                c.max_slip_amplitude()
            );
        }
        let _ = match result.shakedown_cycle {
            Some(k) => writeln!(
                o,
                "steady cycle: from cycle {k} (cycle {} repeats it within {tolerance})",
                k + 1
            ),
            None => writeln!(
                o,
                "steady cycle: not reached (no two consecutive cycles agree within {tolerance})"
            ),
        };
    }
    let _ = writeln!(
        o,
        "\n{:>6} {:>11} {:>11} {:>10} {:>10} {:>11} {:>11} {:>5}",
        "step", "normal", "shear", "bulk", "a", "stick_left", "stick_right", "runs"
    );
    // With cycles, the ramp end and the end of every quarter of the last cycle (five steps, so
    // the search below is constant time); a file history lists every step. (Searching a list of
    // every step once per step made this quadratic: 1.1 s for 100,000 increments.)
    let ends: Option<Vec<usize>> = history.cycles().map(|c| {
        let last = c.first_step() + (c.count() - 1) * c.steps_per_cycle();
        let mut v = vec![c.first_step()];
        v.extend((1..=4).map(|q| last + q * c.steps_per_cycle() / 4));
        v
    });
    let listed = |step: usize| ends.as_ref().is_none_or(|e| e.contains(&step));
    for s in result.steps.iter().filter(|s| listed(s.step)) {
        let (l, r) = s
            .largest_stick()
            .map_or(("-".into(), "-".into()), |[l, r]| {
                (format!("{l:.6}"), format!("{r:.6}"))
            });
        let _ = writeln!(
            o,
            "{:>6} {:>11.4} {:>11.4} {:>10.4} {:>10.6} {:>11} {:>11} {:>5}",
            s.step,
            s.load.normal(),
            s.load.shear(),
            s.load.bulk(),
            s.half_width,
            l,
            r,
            s.stick_intervals.len()
        );
    }
    o
}
