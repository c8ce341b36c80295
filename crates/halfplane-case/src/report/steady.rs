//! The `steady` report: one nested record. The JSON is its serialization; the CSV is one row of
//! its numbers under dotted names ([`SteadyReport::COLUMNS`]); the table shows it in words.

use crate::units::{Quantity, Units};
use halfplane::asymptotic::AsymptoticSteady;
use halfplane::steady::{GivenPoint, Regime, SteadyState};
use halfplane::{Contact, Edge, NormalContact, Shape, StickZone};
use serde::Serialize;
use std::fmt::Write;

/// The `steady` report: one JSON object, one CSV row or the table.
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
    units: Units,
}

#[derive(Serialize)]
pub(crate) struct ProfileReport {
    /// The profile kind, as the case file names it.
    pub(crate) kind: &'static str,
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
    #[serde(skip_serializing_if = "Option::is_none")]
    left_radius: Option<f64>,
    #[serde(skip_serializing_if = "Option::is_none")]
    right_radius: Option<f64>,
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
    moment: f64,
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
    /// K_N, the same at both edges; null where the two edges' differ (a moment, or an
    /// asymmetric profile: see `normal_intensity_left_1` and the others).
    normal_intensity_1: Option<f64>,
    normal_intensity_2: Option<f64>,
    left_1: f64,
    right_1: f64,
    left_2: f64,
    right_2: f64,
    normal_intensity_left_1: f64,
    normal_intensity_right_1: f64,
    normal_intensity_left_2: f64,
    normal_intensity_right_2: f64,
    rotation_1: f64,
    rotation_2: f64,
    /// For a flat punch with rounded edges: whether that end lies on the flat (a regime change
    /// under a moment, not an error: the pressure there is then flat-punch-like).
    on_flat_left_1: bool,
    on_flat_right_1: bool,
    on_flat_left_2: bool,
    on_flat_right_2: bool,
}

impl ContactReport {
    fn new(steady: &SteadyState) -> Self {
        let [c1, c2] = [steady.contacts.first, steady.contacts.second];
        let single = |c: &NormalContact| {
            let k = c.normal_intensities();
            (c.is_centred() || k.left == k.right).then_some(k.left)
        };
        Self {
            half_width_1: c1.half_width(),
            half_width_2: c2.half_width(),
            normal_intensity_1: single(&c1),
            normal_intensity_2: single(&c2),
            left_1: c1.end(Edge::Left),
            right_1: c1.end(Edge::Right),
            left_2: c2.end(Edge::Left),
            right_2: c2.end(Edge::Right),
            normal_intensity_left_1: c1.normal_intensity(Edge::Left),
            normal_intensity_right_1: c1.normal_intensity(Edge::Right),
            normal_intensity_left_2: c2.normal_intensity(Edge::Left),
            normal_intensity_right_2: c2.normal_intensity(Edge::Right),
            rotation_1: c1.rotation(),
            rotation_2: c2.rotation(),
            on_flat_left_1: c1.end_on_flat().left,
            on_flat_right_1: c1.end_on_flat().right,
            on_flat_left_2: c2.end_on_flat().left,
            on_flat_right_2: c2.end_on_flat().right,
        }
    }

    /// Whether the contacts are centred `[-a, a]` with one K_N: the table then shows what it
    /// always has, and a moment's rows otherwise.
    fn centred(&self) -> bool {
        self.normal_intensity_1.is_some()
            && self.normal_intensity_2.is_some()
            && self.left_1 == -self.right_1
            && self.left_2 == -self.right_2
    }
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

/// The profile as the reports show it.
pub(crate) fn profile_report(contact: &Contact) -> ProfileReport {
    let mut r = ProfileReport {
        kind: "",
        radius: None,
        left_radius: None,
        right_radius: None,
        flat_half_width: None,
        coefficient: None,
        exponent: None,
        rows: None,
        kinks: contact.profile().kinks(),
    };
    match contact.profile().shape() {
        Shape::Hertz { radius } => (r.kind, r.radius) = ("hertz", Some(*radius)),
        Shape::FlatRounded {
            flat_half_width, ..
        } => {
            // Equal radii keep `radius`; unequal ones give left_radius and right_radius only.
            let (left, right) = contact.profile().edge_radii().unwrap_or_default();
            (r.kind, r.flat_half_width) = ("flat-rounded", Some(*flat_half_width));
            if left == right {
                r.radius = Some(left);
            } else {
                (r.left_radius, r.right_radius) = (Some(left), Some(right));
            }
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
    /// The report of a steady analysis and its asymptotic estimate, with the unit names.
    pub fn new(
        contact: &Contact,
        steady: &SteadyState,
        asymptotic: Option<&AsymptoticSteady>,
        units: &Units,
    ) -> anyhow::Result<Self> {
        let (first, second) = steady.cycle.as_given();
        let point = |p: halfplane::LoadPoint| PointReport {
            normal: p.normal(),
            shear: p.shear(),
            bulk: p.bulk(),
            moment: p.moment(),
        };
        let c = &steady.criteria;
        let asymptotic = match (asymptotic, steady.stick_zone, steady.slip_zones) {
            (Some(a), Some(zone), Some(slip)) if steady.regime == Regime::PartialSlip => {
                let edge = |e: &halfplane::asymptotic::EdgeState| EdgeReport {
                    shear_intensity_left: e.shear_intensity.left,
                    shear_intensity_right: e.shear_intensity.right,
                    equivalent_shear_left: e.equivalent_shear.left,
                    equivalent_shear_right: e.equivalent_shear.right,
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
                            first: Compared::new(a.slip_zones.left.first, slip.left.first),
                            second: Compared::new(a.slip_zones.left.second, slip.left.second),
                        },
                        right: Pair {
                            first: Compared::new(a.slip_zones.right.first, slip.right.first),
                            second: Compared::new(a.slip_zones.right.second, slip.right.second),
                        },
                    },
                })
            }
            _ => None,
        };
        Ok(Self {
            regime: steady.regime.as_str(),
            profile: profile_report(contact),
            compliance: contact.compliance().value(),
            friction: contact.friction().value(),
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
                shear_ratio_1: c.shear_ratio.first,
                shear_ratio_2: c.shear_ratio.second,
                full_stick_ratio: c.full_stick_ratio.is_finite().then_some(c.full_stick_ratio),
                shear_range: steady.cycle.shear_range(),
                bulk_term: c.bulk_term,
                friction: c.friction,
            },
            contact: ContactReport::new(steady),
            stick_zone: steady.stick_zone.map(ZoneReport::from),
            slip_zones: steady.slip_zones.map(|s| Edges {
                left: Pair {
                    first: s.left.first,
                    second: s.left.second,
                },
                right: Pair {
                    first: s.right.first,
                    second: s.right.second,
                },
            }),
            asymptotic,
            units: units.clone(),
        })
    }

    /// A readable table.
    pub fn table(&self, steady: &SteadyState) -> String {
        let mut o = String::new();
        let p = &self.points;
        // The unit after a row's numbers, and inside a line.
        let tail = |q: Quantity| format!("   {}", self.units.of(q));
        let len = &self.units.length;
        let _ = writeln!(
            o,
            "profile      {}   A = {:.6e} 1/{}   f = {}",
            self.profile.kind, self.compliance, self.units.stress, self.friction
        );
        let _ = writeln!(o, "               {:>14} {:>14}", "point1", "point2");
        let force = tail(Quantity::ForcePerLength);
        row(&mut o, "normal P", p.first.normal, p.second.normal, &force);
        row(&mut o, "shear Q", p.first.shear, p.second.shear, &force);
        let stress = tail(Quantity::Stress);
        row(&mut o, "bulk sigma", p.first.bulk, p.second.bulk, &stress);
        let centred = self.contact.centred();
        if !centred {
            let moment = tail(Quantity::Moment);
            row(&mut o, "moment M", p.first.moment, p.second.moment, &moment);
        }
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
            &tail(Quantity::Length),
        );
        let k = &self.contact;
        let intensity = tail(Quantity::Intensity);
        if centred {
            let kn = |v: Option<f64>| v.unwrap_or(f64::NAN);
            row(
                &mut o,
                "K_N",
                kn(k.normal_intensity_1),
                kn(k.normal_intensity_2),
                &intensity,
            );
        } else {
            let length = tail(Quantity::Length);
            row(&mut o, "contact b1", k.left_1, k.left_2, &length);
            row(&mut o, "contact b2", k.right_1, k.right_2, &length);
            let yes = |on: bool| if on { "yes" } else { "no" };
            row(
                &mut o,
                "rotation",
                k.rotation_1,
                k.rotation_2,
                "   rad (the pad's tilt: + raises the right)",
            );
            row(
                &mut o,
                "K_N left",
                k.normal_intensity_left_1,
                k.normal_intensity_left_2,
                &intensity,
            );
            row(
                &mut o,
                "K_N right",
                k.normal_intensity_right_1,
                k.normal_intensity_right_2,
                &intensity,
            );
            for (edge, at_1, at_2) in [
                ("b1", k.on_flat_left_1, k.on_flat_left_2),
                ("b2", k.on_flat_right_1, k.on_flat_right_2),
            ] {
                if at_1 || at_2 {
                    let _ = writeln!(
                        o,
                        "  end {edge} on the flat: point1 {:<4} point2 {}   (flat-punch-like pressure there)",
                        yes(at_1),
                        yes(at_2)
                    );
                }
            }
        }
        let ratio = self
            .criteria
            .full_stick_ratio
            .map_or("infinite (dP = 0)".to_string(), |r| format!("{r:.6}"));
        if centred {
            let _ = writeln!(
                o,
                "eq. (1): (|dQ| + pi a_max |dsigma|/4)/|dP| = {ratio}   (full stick when <= f)"
            );
        } else {
            let _ = writeln!(
                o,
                "eq. (1) edge by edge: max |dS|/|dP_edge| along the cycle = {ratio}   (full stick when <= f)"
            );
        }
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
                "stick zone   [-m, n] = [{:.6}, {:.6}] {len}   d = {:.6} {len}   e = {:.6} {len}",
                z.left, z.right, z.half_width, z.eccentricity
            );
        }
        if let Some(s) = &self.slip_zones {
            let _ = writeln!(o, "slip zones     {:>14} {:>14}", "at point1", "at point2");
            let length = tail(Quantity::Length);
            row(&mut o, "  left", s.left.first, s.left.second, &length);
            row(&mut o, "  right", s.right.first, s.right.second, &length);
        }
        if let Some(a) = &self.asymptotic {
            let _ = writeln!(o);
            let _ = writeln!(o, "asymptotic (edge) description");
            row(
                &mut o,
                "  K_T left",
                a.edges.first.shear_intensity_left,
                a.edges.second.shear_intensity_left,
                &tail(Quantity::Intensity),
            );
            row(
                &mut o,
                "  K_T right",
                a.edges.first.shear_intensity_right,
                a.edges.second.shear_intensity_right,
                &tail(Quantity::Intensity),
            );
            row(
                &mut o,
                "  S left",
                a.edges.first.equivalent_shear_left,
                a.edges.second.equivalent_shear_left,
                &force,
            );
            row(
                &mut o,
                "  S right",
                a.edges.first.equivalent_shear_right,
                a.edges.second.equivalent_shear_right,
                &force,
            );
            let _ = writeln!(
                o,
                "  P_K          left {:.6}   right {:.6}{force}",
                a.stick_load.left, a.stick_load.right
            );
            let _ = writeln!(
                o,
                "  stick zone   [{:.6}, {:.6}] {len}   vs exact: {:+.3}% left, {:+.3}% right",
                a.stick_zone.left,
                a.stick_zone.right,
                100.0 * a.stick_zone.relative_difference_left,
                100.0 * a.stick_zone.relative_difference_right
            );
            for (name, e) in [("left", &a.slip_zones.left), ("right", &a.slip_zones.right)] {
                for (point, c) in [("point1", &e.first), ("point2", &e.second)] {
                    let _ = writeln!(
                        o,
                        "  slip {name:<5} at {point}: w = {:.6} {len}   exact {:.6} {len}   ({:+.3}%)",
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

impl SteadyReport {
    /// The one-row CSV's columns: every number and name of the JSON under its dotted path,
    /// always all of them and in this order, so rows of different cases
    /// line up; a value the case does not have (a profile parameter of another kind, the stick
    /// zone when sliding, the asymptotics outside partial slip) is an empty cell. `profile.kinks`
    /// lists the kinks space-separated.
    pub const COLUMNS: [&'static str; 82] = [
        "regime",
        "profile.kind",
        "profile.radius",
        "profile.flat_half_width",
        "profile.coefficient",
        "profile.exponent",
        "profile.rows",
        "profile.kinks",
        "compliance",
        "friction",
        "points.at_point1.normal",
        "points.at_point1.shear",
        "points.at_point1.bulk",
        "points.at_point2.normal",
        "points.at_point2.shear",
        "points.at_point2.bulk",
        "smaller_shear_point",
        "criteria.shear_ratio_1",
        "criteria.shear_ratio_2",
        "criteria.full_stick_ratio",
        "criteria.shear_range",
        "criteria.bulk_term",
        "criteria.friction",
        "contact.half_width_1",
        "contact.half_width_2",
        "contact.normal_intensity_1",
        "contact.normal_intensity_2",
        "stick_zone.left",
        "stick_zone.right",
        "stick_zone.half_width",
        "stick_zone.eccentricity",
        "slip_zones.left.at_point1",
        "slip_zones.left.at_point2",
        "slip_zones.right.at_point1",
        "slip_zones.right.at_point2",
        "asymptotic.stick_zone.left",
        "asymptotic.stick_zone.right",
        "asymptotic.stick_zone.relative_difference_left",
        "asymptotic.stick_zone.relative_difference_right",
        "asymptotic.stick_load.left",
        "asymptotic.stick_load.right",
        "asymptotic.edges.at_point1.shear_intensity_left",
        "asymptotic.edges.at_point1.shear_intensity_right",
        "asymptotic.edges.at_point1.equivalent_shear_left",
        "asymptotic.edges.at_point1.equivalent_shear_right",
        "asymptotic.edges.at_point2.shear_intensity_left",
        "asymptotic.edges.at_point2.shear_intensity_right",
        "asymptotic.edges.at_point2.equivalent_shear_left",
        "asymptotic.edges.at_point2.equivalent_shear_right",
        "asymptotic.slip_zones.left.at_point1.estimate",
        "asymptotic.slip_zones.left.at_point1.exact",
        "asymptotic.slip_zones.left.at_point1.relative_difference",
        "asymptotic.slip_zones.left.at_point2.estimate",
        "asymptotic.slip_zones.left.at_point2.exact",
        "asymptotic.slip_zones.left.at_point2.relative_difference",
        "asymptotic.slip_zones.right.at_point1.estimate",
        "asymptotic.slip_zones.right.at_point1.exact",
        "asymptotic.slip_zones.right.at_point1.relative_difference",
        "asymptotic.slip_zones.right.at_point2.estimate",
        "asymptotic.slip_zones.right.at_point2.exact",
        "asymptotic.slip_zones.right.at_point2.relative_difference",
        "units.force",
        "units.length",
        "units.stress",
        "profile.left_radius",
        "profile.right_radius",
        "points.at_point1.moment",
        "points.at_point2.moment",
        "contact.left_1",
        "contact.right_1",
        "contact.left_2",
        "contact.right_2",
        "contact.normal_intensity_left_1",
        "contact.normal_intensity_right_1",
        "contact.normal_intensity_left_2",
        "contact.normal_intensity_right_2",
        "contact.rotation_1",
        "contact.rotation_2",
        "contact.on_flat_left_1",
        "contact.on_flat_right_1",
        "contact.on_flat_left_2",
        "contact.on_flat_right_2",
    ];

    /// One JSON object.
    pub fn json(&self) -> serde_json::Result<String> {
        serde_json::to_string_pretty(self)
    }

    /// A header of [`Self::COLUMNS`] and one row: each the JSON value at that path, numbers as
    /// Rust writes them (as the other commands' CSV), empty when absent or null.
    pub fn csv(&self) -> serde_json::Result<String> {
        let v = serde_json::to_value(self)?;
        let cell = |path: &str| -> String {
            let found = path.split('.').try_fold(&v, |v, key| v.get(key));
            match found {
                Some(serde_json::Value::Number(n)) => match (n.as_u64(), n.as_f64()) {
                    (Some(i), _) => i.to_string(),
                    (None, Some(x)) => x.to_string(),
                    (None, None) => n.to_string(),
                },
                Some(serde_json::Value::String(s)) => s.clone(),
                Some(serde_json::Value::Bool(b)) => b.to_string(),
                Some(serde_json::Value::Array(a)) => a
                    .iter()
                    .map(|x| x.as_f64().map_or_else(String::new, |x| x.to_string()))
                    .collect::<Vec<_>>()
                    .join(" "),
                _ => String::new(),
            }
        };
        let row: Vec<String> = Self::COLUMNS.iter().map(|c| cell(c)).collect();
        Ok(format!("{}\n{}\n", Self::COLUMNS.join(","), row.join(",")))
    }
}
