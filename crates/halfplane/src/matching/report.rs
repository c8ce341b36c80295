//! The comparison of a matched pair: each side's steady state and edge description, every
//! matched or reported quantity side by side with its mismatch, and the warnings.

use super::{MatchConstraint, MatchSide, Mode};
use crate::asymptotic::EdgeState;
use crate::error::{Error, Result};
use crate::labels::{Edge, GivenPoint, PerEdge, PerPoint};
use crate::load::{Cycle, LoadPoint};
use crate::normal::Contact;
use crate::steady::{self, Regime, SlipZones, SteadyOptions, SteadyState};

/// [`MatchWarning::EdgeMotion`] is raised when half the difference between the test's and the
/// prototype's edge motion (the first-order change it makes to the asymptotic slip zones, eqs.
/// (35)-(38) as corrected in docs/theory.md) exceeds this fraction of the prototype's largest slip
/// zone.
pub const EDGE_MOTION_WARNING: f64 = 0.05;

/// [`MatchWarning::SlipZones`] is raised when an exact slip zone of the test differs from the
/// prototype's by more than this fraction of it.
pub const SLIP_ZONE_WARNING: f64 = 0.10;

/// One side of a match: the contact, its cycle (points as given), the steady state and the edge
/// description at both points.
#[derive(Debug, Clone, PartialEq)]
#[non_exhaustive]
pub struct Side {
    /// Profile, material and friction.
    pub contact: Contact,
    /// The cycle, points in the prototype's order.
    pub cycle: Cycle,
    /// [`steady::analyse`] of the cycle.
    pub steady: SteadyState,
    /// `K_N`, `K_T`, `S` and a at the first and second points as given.
    pub edges: PerPoint<EdgeState>,
    /// The edge whose state is matched: its `K_N` (the same at both edges of a centred
    /// contact) and its motion over the cycle.
    pub edge: Edge,
}

impl Side {
    /// Analyses `cycle` on `contact`: the steady state and the edge description at both points.
    /// Errors: [`Error::NoValidMatch`] on `side` when the cycle slides or is outside the
    /// steady-state analysis; any other error of the analysis as it is.
    pub(super) fn analyse(
        contact: &Contact,
        cycle: &Cycle,
        options: &SteadyOptions,
        side: MatchSide,
        edge: Option<Edge>,
    ) -> Result<Self> {
        let steady =
            steady::analyse(contact, cycle, options).map_err(|e| MatchConstraint::wrap(side, e))?;
        let (first, second) = cycle.as_given();
        if let Regime::GrossSliding { point } = steady.regime {
            let p = if point == GivenPoint::First {
                first
            } else {
                second
            };
            return Err(Error::NoValidMatch {
                side,
                constraint: MatchConstraint::GrossSliding,
                cause: Some(Box::new(Error::GrossSliding {
                    point,
                    shear: p.shear().abs(),
                    limit: contact.friction.value() * p.normal(),
                })),
            });
        }
        let edges = PerPoint {
            first: EdgeState::of(&first, steady.contacts.first)?,
            second: EdgeState::of(&second, steady.contacts.second)?,
        };
        // By default the edge whose K_T changes more over the cycle (the one that slips more).
        let range =
            |e: Edge| (edges.second.shear_intensity[e] - edges.first.shear_intensity[e]).abs();
        let edge = edge.unwrap_or(if range(Edge::Left) >= range(Edge::Right) {
            Edge::Left
        } else {
            Edge::Right
        });
        Ok(Self {
            contact: contact.clone(),
            cycle: *cycle,
            steady,
            edges,
            edge,
        })
    }

    /// `K_N` at the matched edge at `point`.
    pub fn normal_intensity(&self, point: GivenPoint) -> f64 {
        self.edges[point].contact.normal_intensity(self.edge)
    }

    /// The load at `point` as given.
    pub fn point(&self, point: GivenPoint) -> LoadPoint {
        let (first, second) = self.cycle.as_given();
        match point {
            GivenPoint::First => first,
            GivenPoint::Second => second,
        }
    }

    /// Exact slip zones per edge and point (zero in full stick).
    pub fn slip_zones(&self) -> SlipZones {
        self.steady.slip_zones.unwrap_or_default()
    }

    /// Contact-edge motion over the cycle, `a(second point) - a(first point)`: under a moment, the
    /// outward movement of the matched edge (`b2` rising, or `b1` falling) from the first point
    /// to the second.
    pub fn edge_motion(&self) -> f64 {
        let (first, second) = (self.steady.contacts.first, self.steady.contacts.second);
        let (then, now) = (first.end(self.edge), second.end(self.edge));
        if first.is_centred() && second.is_centred() {
            self.steady.half_width.second - self.steady.half_width.first
        } else if self.edge == Edge::Right {
            now - then
        } else {
            then - now
        }
    }
}

/// A quantity of the prototype beside the test's.
#[derive(Debug, Clone, Copy, PartialEq)]
#[non_exhaustive]
pub struct Compared {
    /// The prototype's value.
    pub prototype: f64,
    /// The test's value.
    pub test: f64,
    /// `(test - prototype)/|prototype|`; `None` when the prototype's value is zero.
    pub mismatch: Option<f64>,
}

impl Compared {
    /// The pair and its relative mismatch.
    pub fn new(prototype: f64, test: f64) -> Self {
        Self {
            prototype,
            test,
            mismatch: (prototype != 0.0).then(|| (test - prototype) / prototype.abs()),
        }
    }
}

/// Why a match may be poor. None of these makes the test invalid.
#[derive(Debug, Clone, Copy, PartialEq)]
#[non_exhaustive]
pub enum MatchWarning {
    /// The test's contact edge moves over the cycle by more than the prototype's, enough to
    /// change the slip zones noticeably: the single-term asymptote does not see it (paper,
    /// section "Asymptotic representation": poor when the edge moves significantly).
    EdgeMotion {
        /// The prototype's `a2 - a1`.
        prototype: f64,
        /// The test's `a2 - a1`.
        test: f64,
        /// `|test - prototype|/2` over the prototype's largest slip zone.
        relative_effect: f64,
    },
    /// An exact slip zone of the test differs from the prototype's by more than
    /// [`SLIP_ZONE_WARNING`] of it.
    SlipZones {
        /// The edge.
        edge: Edge,
        /// The point, as given.
        point: GivenPoint,
        /// `(test - prototype)/prototype`.
        mismatch: f64,
    },
    /// The test's regime is not the prototype's.
    Regime {
        /// The prototype's regime.
        prototype: Regime,
        /// The test's.
        test: Regime,
    },
}

impl std::fmt::Display for MatchWarning {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            MatchWarning::EdgeMotion {
                prototype,
                test,
                relative_effect,
            } => write!(
                f,
                "the test's contact edge moves by {test:.6} over the cycle, the prototype's by \
                 {prototype:.6}: half the difference is {:.1}% of the prototype's largest slip \
                 zone, which the asymptotic match does not account for",
                100.0 * relative_effect
            ),
            MatchWarning::SlipZones {
                edge,
                point,
                mismatch,
            } => write!(
                f,
                "the test's exact slip zone at the {edge} edge at the {point} point differs from \
                 the prototype's by {:+.1}%",
                100.0 * mismatch
            ),
            MatchWarning::Regime { prototype, test } => write!(
                f,
                "the test's steady state is {test}, the prototype's {prototype}"
            ),
        }
    }
}

/// The outcome of [`super::match_cycle`]: both sides and every quantity compared.
#[derive(Debug, Clone, PartialEq)]
#[non_exhaustive]
pub struct MatchReport {
    /// The mode the test was found in.
    pub mode: Mode,
    /// The prototype.
    pub prototype: Side,
    /// The test found.
    pub test: Side,
    /// `K_N` (eq. (31)) per point, at the matched edge ([`Side::edge`]).
    pub normal_intensity: PerPoint<Compared>,
    /// `K_T` (eq. (32)) per edge and point.
    pub shear_intensity: PerEdge<PerPoint<Compared>>,
    /// The mean of `K_T` over the two points, per edge.
    pub mean_shear_intensity: PerEdge<Compared>,
    /// `S` (eq. (33)) per edge and point.
    pub equivalent_shear: PerEdge<PerPoint<Compared>>,
    /// Contact-edge motion `a2 - a1` ([`Side::edge_motion`]).
    pub edge_motion: Compared,
    /// Exact slip zones ([`steady::analyse`]) per edge and point.
    pub slip_zones: PerEdge<PerPoint<Compared>>,
    /// Why the match may be poor.
    pub warnings: Vec<MatchWarning>,
}

impl MatchReport {
    /// Compares the two sides and collects the warnings.
    pub(super) fn compare(mode: Mode, prototype: Side, test: Side) -> Self {
        let per_point = |f: &dyn Fn(&EdgeState) -> f64| {
            PerPoint::from_fn(|p| Compared::new(f(&prototype.edges[p]), f(&test.edges[p])))
        };
        let normal_intensity = PerPoint::from_fn(|p| {
            Compared::new(prototype.normal_intensity(p), test.normal_intensity(p))
        });
        let mean = |s: &Side, e: Edge| {
            0.5 * (s.edges.first.shear_intensity[e] + s.edges.second.shear_intensity[e])
        };
        let (ps, ts) = (prototype.slip_zones(), test.slip_zones());
        let slip_zones =
            PerEdge::from_fn(|e| PerPoint::from_fn(|p| Compared::new(ps[e][p], ts[e][p])));
        let edge_motion = Compared::new(prototype.edge_motion(), test.edge_motion());
        let mut warnings = Vec::new();
        if prototype.steady.regime != test.steady.regime {
            warnings.push(MatchWarning::Regime {
                prototype: prototype.steady.regime,
                test: test.steady.regime,
            });
        }
        let largest = ps
            .into_iter()
            .flat_map(|e| e.into_iter())
            .fold(0.0, f64::max);
        let relative_effect = 0.5 * (edge_motion.test - edge_motion.prototype).abs() / largest;
        if largest > 0.0
            && edge_motion.test.abs() > edge_motion.prototype.abs()
            && relative_effect > EDGE_MOTION_WARNING
        {
            warnings.push(MatchWarning::EdgeMotion {
                prototype: edge_motion.prototype,
                test: edge_motion.test,
                relative_effect,
            });
        }
        for e in Edge::BOTH {
            for p in GivenPoint::BOTH {
                match slip_zones[e][p].mismatch {
                    Some(m) if m.abs() > SLIP_ZONE_WARNING => {
                        warnings.push(MatchWarning::SlipZones {
                            edge: e,
                            point: p,
                            mismatch: m,
                        })
                    }
                    _ => {}
                }
            }
        }
        Self {
            mode,
            normal_intensity,
            shear_intensity: PerEdge::from_fn(|e| per_point(&|s| s.shear_intensity[e])),
            mean_shear_intensity: PerEdge::from_fn(|e| {
                Compared::new(mean(&prototype, e), mean(&test, e))
            }),
            equivalent_shear: PerEdge::from_fn(|e| per_point(&|s| s.equivalent_shear[e])),
            edge_motion,
            slip_zones,
            warnings,
            prototype,
            test,
        }
    }
}
