//! Exact evolution of the stick zone along the steady in-phase cycle (beyond the paper).
//!
//! At a point X of a half-cycle, the stick-zone equations hold for the partial path from the last
//! reversal point to X, labelled by Q (docs/theory.md, "Slip zones along the cycle, exactly"): on the
//! half where Q rises, X replaces point 2; where Q falls, X replaces point 1. The relation is exact
//! while both slip zones grow monotonically from the reversal; [`evolve`] calls
//! [`steady::analyse`], which rejects partial-slip cycles where they do not
//! ([`Error::SlipReversesInHalf`], derivation in `docs/validity.md`), so for every cycle it
//! accepts both edges slip from just after each reversal and the stick boundaries only move
//! inwards.

use crate::asymptotic::{self, Edge, EdgeState};
use crate::error::{Error, Result};
use crate::labels::{display_as_str, Half, PerEdge, PerPoint};
use crate::load::{Cycle, LoadPoint};
use crate::normal::Contact;
use crate::normal_moment::NormalContact;
use crate::steady::{self, Regime, Segment, SteadyOptions, StickZone};

/// What the contact does at a point of the cycle.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum PointState {
    /// No slip anywhere (the stick zone is the whole current contact).
    FullStick,
    /// Slip at both edges: the exact partial-path result applies.
    PartialSlip,
    /// The two-edge relation puts only one edge in slip. The partial-path equations assume slip at
    /// both edges, so the slipping edge's boundary shown is approximate here (time marching gives
    /// the exact value). Cannot occur for a cycle that [`steady::analyse`] accepts (its stick
    /// boundaries stay inside `min(a_start, a_X)` along both halves); kept as a guard.
    OneEdgeSlip {
        /// The edge that slips.
        slipping: Edge,
    },
}

impl PointState {
    /// "full-stick", "partial-slip" or "one-edge-slip": the names the CLI prints.
    pub fn as_str(&self) -> &'static str {
        match self {
            PointState::FullStick => "full-stick",
            PointState::PartialSlip => "partial-slip",
            PointState::OneEdgeSlip { .. } => "one-edge-slip",
        }
    }
}

display_as_str!(PointState);

/// The state at one point of a half-cycle.
#[derive(Debug, Clone, Copy, PartialEq)]
#[non_exhaustive]
pub struct EvolutionPoint {
    /// The half: [`Half::First`] from the first point as given to the second, [`Half::Second`] back.
    pub half: Half,
    /// Fraction of the way along the half, 0 to 1.
    pub fraction: f64,
    /// The load at this point.
    pub load: LoadPoint,
    /// Contact half-width a_X.
    pub half_width: f64,
    /// The normal contact at this point (its ends `[b1, b2]`; `[-a_X, a_X]` without a moment on
    /// a symmetric profile).
    pub contact: NormalContact,
    /// What the contact does.
    pub state: PointState,
    /// Stick zone (the whole contact in full stick).
    pub stick_zone: StickZone,
    /// The asymptotic estimate, from the corrected slip-zone formulas.
    pub asymptotic_stick_zone: StickZone,
}

/// A condition that limits the exact result.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum EvolutionWarning {
    /// The stick boundary at `edge` moved outwards between two slipping points of a half: slip
    /// zones do not grow monotonically, so the partial-path relation (which assumes they do) is not
    /// exact there. Cannot occur for a cycle that [`steady::analyse`] accepts (it checks exactly
    /// this along both halves); kept as a guard against a failure between its sample points.
    NonMonotoneSlip {
        /// The half.
        half: Half,
        /// Edge.
        edge: Edge,
        /// Fraction where it happened.
        fraction: f64,
    },
    /// Some points have slip at one edge only (see [`PointState::OneEdgeSlip`]).
    OneEdgeSlip {
        /// The half.
        half: Half,
        /// Number of such points.
        count: usize,
    },
}

/// The stick zone along the cycle.
#[derive(Debug, Clone, PartialEq)]
#[non_exhaustive]
pub struct Evolution {
    /// The regime of the steady state.
    pub regime: Regime,
    /// Points of half 1 then half 2.
    pub points: Vec<EvolutionPoint>,
    /// Conditions that limit the result (empty when it is exact throughout).
    pub warnings: Vec<EvolutionWarning>,
}

/// The state at a point of the partial path from the partial-path zone `z`, the bounds `limit`
/// (the common part of the start's and the current contact, `[-min(a_s, a(t)), min(a_s, a(t))]`
/// without a moment) its boundaries must stay inside to slip, and the current contact `whole`:
/// an edge slips when the zone's boundary there is inside the bound; the stick zone reported
/// runs to the contact edge at an edge that does not slip.
fn classify(z: StickZone, limit: PerEdge<f64>, whole: StickZone) -> (PointState, StickZone) {
    let one_edge = |slipping| PointState::OneEdgeSlip { slipping };
    match (z.left > limit.left, z.right < limit.right) {
        (true, true) => (PointState::PartialSlip, z),
        (false, false) => (PointState::FullStick, whole),
        (true, false) => (
            one_edge(Edge::Left),
            StickZone {
                left: z.left,
                right: whole.right,
            },
        ),
        (false, true) => (
            one_edge(Edge::Right),
            StickZone {
                left: whole.left,
                right: z.right,
            },
        ),
    }
}

/// The most points per half-cycle [`evolve`] takes: each point is a stick-zone solve (about 10 µs
/// for a small table) and about 120 bytes of result, so 100,000 take about 2 s and 60 MB in the
/// CLI; a finer sampling shows nothing more.
pub const MAX_POINTS_PER_HALF: usize = 100_000;

/// Evaluates the stick zone at `points_per_half` (2 to [`MAX_POINTS_PER_HALF`]) evenly spaced
/// points of each half-cycle, ends included. Needs the steady state to be partial slip or full
/// stick: the errors of [`steady::analyse`] (among them [`Error::SlipReversesInHalf`] when the
/// relation would not be exact) are passed on, and gross sliding is [`Error::GrossSliding`].
pub fn evolve(
    contact: &Contact,
    cycle: &Cycle,
    points_per_half: usize,
    options: &SteadyOptions,
) -> Result<Evolution> {
    if !(2..=MAX_POINTS_PER_HALF).contains(&points_per_half) {
        let (value, max) = (points_per_half as u64, MAX_POINTS_PER_HALF as u64);
        return Err(Error::InvalidCount {
            field: "points".into(),
            value,
            min: 2,
            max,
        });
    }
    let steady = steady::analyse(contact, cycle, options)?;
    let (first, second) = cycle.as_given();
    let given = PerPoint { first, second };
    if let Regime::GrossSliding { point } = steady.regime {
        let p = given[point];
        return Err(Error::GrossSliding {
            point,
            shear: p.shear().abs(),
            limit: contact.friction.value() * p.normal(),
        });
    }
    let f = contact.friction.value();
    let mut points = Vec::with_capacity(2 * points_per_half);
    let mut warnings = Vec::new();
    for half in Half::BOTH {
        let (start, end) = (given[half.start()], given[half.end()]);
        let start_contact = steady.contacts[half.start()];
        let start_edges = EdgeState::of(&start, start_contact)?;
        let rising = end.shear() >= start.shear();
        let mut guess = Some((start_contact.half_width(), start_contact.centre()));
        let mut near = start_contact;
        let mut previous: Option<StickZone> = None;
        let mut one_edge = 0;
        for j in 0..points_per_half {
            let fraction = j as f64 / (points_per_half - 1) as f64;
            let load = start.lerp(&end, fraction);
            near = contact_along(contact, &load, &near)?;
            let now = EdgeState::of(&load, near)?;
            let a_x = now.half_width;
            let whole = StickZone {
                left: near.end(Edge::Left),
                right: near.end(Edge::Right),
            };
            let (mut state, mut zone) = (PointState::FullStick, whole);
            if steady.regime == Regime::PartialSlip && j > 0 {
                let rotation = 0.5 * (start_contact.rotation() + near.rotation());
                let segment = if rising {
                    Segment::between(&start, &load, rotation)
                } else {
                    Segment::between(&load, &start, rotation)
                };
                let (z, _) = steady::stick_zone(contact, &segment, guess, options)?;
                guess = Some((z.half_width(), z.eccentricity()));
                let limit = PerEdge {
                    left: start_contact.end(Edge::Left).max(whole.left),
                    right: start_contact.end(Edge::Right).min(whole.right),
                };
                (state, zone) = classify(z, limit, whole);
                if matches!(state, PointState::OneEdgeSlip { .. }) {
                    one_edge += 1;
                }
            }
            if let (Some(p), PointState::PartialSlip) = (previous, state) {
                for (edge, moved_out) in [
                    (Edge::Left, zone.left < p.left - 1e-12 * a_x),
                    (Edge::Right, zone.right > p.right + 1e-12 * a_x),
                ] {
                    if moved_out {
                        warnings.push(EvolutionWarning::NonMonotoneSlip {
                            half,
                            edge,
                            fraction,
                        });
                    }
                }
            }
            if state != PointState::FullStick {
                previous = Some(zone);
            }
            let slip = PerEdge::from_fn(|e| asymptotic::slip_zone_size(&start_edges, &now, f, e));
            let asymptotic_stick_zone = if steady.regime == Regime::PartialSlip {
                asymptotic::stick_zone_within(&near, slip)
            } else {
                whole
            };
            points.push(EvolutionPoint {
                half,
                fraction,
                load,
                half_width: a_x,
                contact: near,
                state,
                stick_zone: zone,
                asymptotic_stick_zone,
            });
        }
        if one_edge > 0 {
            warnings.push(EvolutionWarning::OneEdgeSlip {
                half,
                count: one_edge,
            });
        }
    }
    Ok(Evolution {
        regime: steady.regime,
        points,
        warnings,
    })
}

/// The contact at `load`, started from `near`, the contact at the previous point of the half
/// (the ends of the half are the steady analysis's own contacts, so they agree exactly).
fn contact_along(
    contact: &Contact,
    load: &LoadPoint,
    near: &NormalContact,
) -> Result<NormalContact> {
    contact.contact_near(load.normal(), load.moment(), near)
}
