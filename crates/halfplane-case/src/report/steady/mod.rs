//! The `steady` report: one nested record. The JSON is its serialization; the CSV is one row of
//! its numbers under dotted names ([`SteadyReport::COLUMNS`]); the table shows it in words.

use crate::units::Units;
use halfplane::asymptotic::AsymptoticSteady;
use halfplane::steady::{Regime, SteadyState};
use halfplane::{Contact, Edge, NormalContact, Shape, StickZone};
use serde::Serialize;

mod columns;
mod table;

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
}

impl SteadyReport {
    /// One JSON object.
    pub fn json(&self) -> serde_json::Result<String> {
        serde_json::to_string_pretty(self)
    }
}
