//! The asymptotic edge description (paper, section "Asymptotic representation"; Fleury et al.
//! 2017), with the slip-zone formulas as corrected in docs/theory.md.
//!
//! Sign convention: a full-stick shear traction behaves as `q ~ K_T/sqrt(s)` at distance s from
//! an edge, with q positive in the direction of positive Q at both edges. Bulk tension adds to
//! the shear at the left edge and subtracts at the right. Under a moment the contact `[b1, b2]`
//! is off centre and K_N differs at its two edges; K_T keeps its form with the contact's
//! half-width a (the full-stick traction of Q and sigma on `[b1, b2]` is the centred one moved
//! to the contact's centre), and each edge's slip zone moves with that edge.

use crate::error::{Error, Result};
pub use crate::labels::Edge;
use crate::labels::{GivenPoint, PerEdge, PerPoint};
use crate::load::{Cycle, LoadPoint};
use crate::normal::Contact;
use crate::normal_moment::NormalContact;
use crate::steady::{self, Segment, SteadyOptions, StickZone};
use std::f64::consts::PI;

/// Shear intensity in full stick: `K_T = Q/(pi sqrt(2a)) +/- (sigma/4) sqrt(a/2)`, + at the left
/// edge (docs/theory.md, "Asymptotic edge description").
pub fn shear_intensity(shear: f64, bulk: f64, half_width: f64, edge: Edge) -> f64 {
    shear / (PI * (2.0 * half_width).sqrt())
        + edge.bulk_sign() * 0.25 * bulk * (0.5 * half_width).sqrt()
}

/// Equivalent shear force `S = Q +/- pi a sigma/4` (paper eq. (33)), the shear
/// alone that gives the same K_T at that edge.
pub fn equivalent_shear(shear: f64, bulk: f64, half_width: f64, edge: Edge) -> f64 {
    shear + edge.bulk_sign() * PI * half_width * bulk / 4.0
}

/// The edge quantities at one load point.
#[derive(Debug, Clone, Copy, PartialEq)]
#[non_exhaustive]
pub struct EdgeState {
    /// Contact half-width a.
    pub half_width: f64,
    /// Normal intensity K_N: the same at both edges of a centred contact; under a moment the
    /// smaller of the two (each edge's is in `contact`).
    pub normal_intensity: f64,
    /// The normal contact: its ends, rotation and K_N at each edge.
    pub contact: NormalContact,
    /// K_T at each edge.
    pub shear_intensity: PerEdge<f64>,
    /// S at each edge.
    pub equivalent_shear: PerEdge<f64>,
}

impl EdgeState {
    /// Evaluates the edge quantities at `point`.
    ///
    /// Errors when `K_N` is not > 0 at both edges (a flat-rounded punch loaded so lightly that
    /// the contact does not pass its flat): slip-zone sizes divide by it.
    pub fn at(contact: &Contact, point: &LoadPoint) -> Result<Self> {
        Self::of(point, contact.contact_at(point)?)
    }

    /// The edge quantities at `point`, whose normal contact `state` is known.
    pub fn of(point: &LoadPoint, state: NormalContact) -> Result<Self> {
        let a = state.half_width();
        let k = state.normal_intensities();
        let normal_intensity = k.left.min(k.right);
        if normal_intensity.is_nan() || normal_intensity <= 0.0 {
            return Err(Error::InvalidInput {
                field: "normal load".into(),
                value: point.normal(),
                valid: "a load whose edge intensity K_N is > 0 at both edges (the asymptotic description divides by it)",
            });
        }
        Ok(Self {
            half_width: a,
            normal_intensity,
            contact: state,
            shear_intensity: PerEdge::from_fn(|e| {
                shear_intensity(point.shear(), point.bulk(), a, e)
            }),
            equivalent_shear: PerEdge::from_fn(|e| {
                equivalent_shear(point.shear(), point.bulk(), a, e)
            }),
        })
    }

    /// How far the contact edge `edge` lies outwards of where it lies in `other`: `a - a_other`
    /// for centred contacts, `b2 - b2_other` at the right edge and `b1_other - b1` at the left.
    fn edge_advance(&self, other: &EdgeState, edge: Edge) -> f64 {
        let (now, then) = (self.contact.end(edge), other.contact.end(edge));
        match edge {
            Edge::Left => then - now,
            Edge::Right => now - then,
        }
    }
}

/// Slip-zone size at `edge` when the load has moved from the reversal point `start` to `now`
/// (docs/theory.md, corrected form of the paper's eqs. (37) and (38)):
/// `w = |K_T(now) - K_T(start)|/(f K_N(now)) + (a_now - a_start)/2`, with, under a moment, that
/// edge's K_N and its own outward movement in place of `a_now - a_start` (the edge solution is
/// local to the edge). Not clamped: `w <= 0` means that edge still sticks.
pub fn slip_zone_size(start: &EdgeState, now: &EdgeState, friction: f64, edge: Edge) -> f64 {
    (now.shear_intensity[edge] - start.shear_intensity[edge]).abs()
        / (friction * now.contact.normal_intensity(edge))
        + 0.5 * now.edge_advance(start, edge)
}

/// Stick zone implied by the slip-zone sizes `w` at each edge in a contact of half-width a.
pub fn stick_zone_from_slip(half_width: f64, slip: PerEdge<f64>) -> StickZone {
    StickZone {
        left: -(half_width - slip.left.max(0.0)),
        right: half_width - slip.right.max(0.0),
    }
}

/// Stick zone implied by the slip-zone sizes `w` at each edge of the contact `state`:
/// `[b1 + w_left, b2 - w_right]`.
pub fn stick_zone_within(state: &NormalContact, slip: PerEdge<f64>) -> StickZone {
    StickZone {
        left: state.end(Edge::Left) + slip.left.max(0.0),
        right: state.end(Edge::Right) - slip.right.max(0.0),
    }
}

/// The asymptotic description of a steady in-phase cycle.
#[derive(Debug, Clone, Copy, PartialEq)]
#[non_exhaustive]
pub struct AsymptoticSteady {
    /// Edge quantities at the first and second points as given.
    pub edges: [EdgeState; 2],
    /// `P_K = P0 - dS/(2f)` at `[left, right]` edges (paper, section "Asymptotic representation").
    pub stick_load: [f64; 2],
    /// Permanent stick zone estimate `[-a(P_K left), a(P_K right)]`; under a moment, each end
    /// that end of the contact carrying `P_K` at that edge with the cycle's mean rotation.
    pub stick_zone: StickZone,
    /// Slip-zone sizes `w` per edge, then at the first and second points as given, from
    /// [`slip_zone_size`] over the half-cycle that ends there.
    pub slip_zones: PerEdge<PerPoint<f64>>,
}

/// Evaluates the asymptotic description of the cycle. Errors: [`Error::GrossSliding`] when an
/// end slides (there is no edge description), [`Error::AsymptoticBreakdown`] when `P_K <= 0`.
pub fn steady(contact: &Contact, cycle: &Cycle) -> Result<AsymptoticSteady> {
    let f = contact.friction.value();
    let (first, second) = cycle.as_given();
    // The edge description assumes partial slip: a sliding end has no stick zone to describe.
    for (point, p) in GivenPoint::BOTH.into_iter().zip([first, second]) {
        if p.shear().abs() >= f * p.normal() {
            return Err(Error::GrossSliding {
                point,
                shear: p.shear().abs(),
                limit: f * p.normal(),
            });
        }
    }
    let edges = [
        EdgeState::at(contact, &first)?,
        EdgeState::at(contact, &second)?,
    ];
    let centred = edges.iter().all(|e| e.contact.is_centred());
    let rotation = 0.5 * (edges[0].contact.rotation() + edges[1].contact.rotation());
    // Ranges from the end of smaller Q to the end of larger Q.
    let (lo, hi) = if cycle.swapped() {
        (edges[1], edges[0])
    } else {
        (edges[0], edges[1])
    };
    let p0 = cycle.mean_normal();
    let mut stick_load = [0.0; 2];
    let mut ends = [0.0; 2];
    for edge in [Edge::Left, Edge::Right] {
        let i = edge as usize;
        let p_k = p0 - (hi.equivalent_shear[edge] - lo.equivalent_shear[edge]) / (2.0 * f);
        if p_k.is_nan() || p_k <= 0.0 {
            return Err(Error::AsymptoticBreakdown {
                edge: edge.name(),
                p_k,
            });
        }
        stick_load[i] = p_k;
        ends[i] = if centred {
            contact.half_width(p_k)?
        } else {
            // The contact carrying P_K with the tilt `rotation`: the stick-zone equations with
            // no shear or tension range (docs/theory.md, "Moment").
            let carrying = Segment {
                normal_sum: 2.0 * p_k,
                shear_range: 0.0,
                bulk_range: 0.0,
                rotation,
            };
            let (zone, _) =
                steady::stick_zone(contact, &carrying, None, &SteadyOptions::default())?;
            match edge {
                Edge::Left => -zone.left,
                Edge::Right => zone.right,
            }
        };
    }
    // Over the half-cycle that ends at each point: half 2 ends at the first point, half 1 at the
    // second.
    let slip_at = |start: &EdgeState, now: &EdgeState, edge| slip_zone_size(start, now, f, edge);
    Ok(AsymptoticSteady {
        edges,
        stick_load,
        stick_zone: StickZone {
            left: -ends[0],
            right: ends[1],
        },
        slip_zones: PerEdge::from_fn(|e| PerPoint {
            first: slip_at(&edges[1], &edges[0], e),
            second: slip_at(&edges[0], &edges[1], e),
        }),
    })
}
