//! The normal contacts along a cycle's load segment, for the edge tests that must hold all along
//! it: full stick (eq. (1) edge by edge) and the bounds on the rotation's rate that decide, for a
//! convex profile under a moment, whether slip keeps one direction through each half
//! (docs/validity.md, "Under a moment").
//!
//! Conventions: t runs from the cycle's point of smaller Q (`low`, t = 0) to the other (`high`);
//! `dsigma = sigma_low - sigma_high` (the paper's order); the equivalent-shear change at an edge
//! is `dS = dQ - pi a dsigma/4` at the left edge and `dQ + pi a dsigma/4` at the right.

use crate::error::Result;
use crate::labels::{Edge, PerEdge};
use crate::load::Cycle;
use crate::normal::Contact;
use crate::normal_moment::NormalContact;
use crate::profile::Shape;
use std::f64::consts::PI;

/// Intervals the segment is cut into when a moment (or an asymmetric profile) makes the contact
/// move otherwise than by the symmetric contact law: 5 contacts, the three inner ones each a
/// Newton step from a cubic prediction through the end contacts (`ends_predictor`). The bounds
/// they give are widened by the largest change between neighbours, so fewer samples are safe,
/// only more often inconclusive (then both halves are sampled, `validity.rs`).
const INTERVALS: usize = 4;

/// Normal contacts at fractions of the segment, with its load changes.
#[derive(Debug, Clone)]
pub(crate) struct SegmentPath {
    /// `(t, contact)` from t = 0 to t = 1.
    samples: Vec<(f64, NormalContact)>,
    d_normal: f64,
    d_moment: f64,
    d_shear: f64,
    d_bulk: f64,
    compliance: f64,
    /// The rotation is exactly `-M/(P R)`, its rate `-(dM P_low - M_low dP)/(P^2 R)` monotone in
    /// t, and a grows with P: the extreme values are at the ends (docs/validity.md).
    monotone: bool,
}

impl SegmentPath {
    /// The segment of `cycle` whose end contacts are `low` (smaller Q) and `high`. Centred
    /// contacts at both ends (a symmetric profile without a moment) need nothing in between: the
    /// edge changes are dP at both edges and a is monotone in P. Otherwise 3 contacts in between
    /// are solved.
    pub(crate) fn new(
        contact: &Contact,
        cycle: &Cycle,
        low: NormalContact,
        high: NormalContact,
    ) -> Result<Self> {
        let (from, to) = (cycle.low(), cycle.high());
        let centred = low.is_centred() && high.is_centred();
        let mut samples = vec![(0.0, low)];
        if !centred {
            let (d_normal, d_moment) = (to.normal() - from.normal(), to.moment() - from.moment());
            // Hertz's contacts are closed forms (contact_from ignores the start): no cubic.
            let cubic = !matches!(contact.profile().shape(), Shape::Hertz { .. });
            let predict = ends_predictor(&low, &high, d_normal, d_moment, cubic);
            for k in 1..INTERVALS {
                let t = k as f64 / INTERVALS as f64;
                let point = from.lerp(&to, t);
                // 1e-5 of the contact's size: three orders inside the widening of the bounds (the
                // change between neighbouring samples, of order 1e-2 of it). From the cubic
                // prediction one Newton step.
                let found =
                    contact.contact_from(point.normal(), point.moment(), predict(t), 1e-5)?;
                samples.push((t, found));
            }
        }
        samples.push((1.0, high));
        Ok(Self {
            samples,
            d_normal: to.normal() - from.normal(),
            d_moment: to.moment() - from.moment(),
            d_shear: cycle.shear_range(),
            d_bulk: cycle.bulk_range(),
            compliance: contact.compliance().value(),
            monotone: centred || matches!(contact.profile().shape(), Shape::Hertz { .. }),
        })
    }

    /// Whether both ends are centred contacts (no moment, symmetric profile).
    pub(crate) fn is_centred(&self) -> bool {
        self.samples.iter().all(|(_, c)| c.is_centred())
    }

    /// The change of the equivalent shear at `edge` over the cycle (low to high) with the
    /// contact half-width `a`.
    pub(crate) fn shear_change(&self, a: f64, edge: Edge) -> f64 {
        let sign = if edge == Edge::Left { -1.0 } else { 1.0 };
        self.d_shear + sign * PI * a * self.d_bulk / 4.0
    }

    /// Whether the whole contact sticks in the steady state, and the ratio that decided it: at
    /// every sampled contact and at both edges, `|dS| <= f |dP_edge|` (the traction's edge
    /// coefficient changes by less than f times the pressure's; eq. (1) of the paper is this with
    /// dP_edge = dP and the larger contact). The ratio is the largest `|dS|/|dP_edge|`, infinite
    /// where dP_edge = 0.
    pub(crate) fn sticks(&self, friction: f64) -> (bool, f64) {
        let mut sticks = true;
        let mut ratio: f64 = 0.0;
        for (_, c) in &self.samples {
            let d_edge = c.edge_load_changes(self.d_normal, self.d_moment);
            for edge in Edge::BOTH {
                let d_s = self.shear_change(c.half_width(), edge).abs();
                let d_p = d_edge[edge].abs();
                sticks &= d_s <= friction * d_p;
                ratio = ratio.max(if d_p > 0.0 { d_s / d_p } else { f64::INFINITY });
            }
        }
        (sticks, ratio)
    }

    /// Bounds `[lo, hi]` on `(pi/2) dtheta/dt` along the segment (low to high), where theta is
    /// the pad's rotation, and on the contact half-width: the sampled values, widened by the
    /// largest change between neighbouring samples unless the extremes are known to be at the
    /// ends.
    pub(crate) fn bounds(&self) -> RateBounds {
        let rates: Vec<f64> = self
            .samples
            .iter()
            .map(|(_, c)| {
                0.5 * PI * c.rotation_change(self.compliance, self.d_normal, self.d_moment)
            })
            .collect();
        let widths: Vec<f64> = self.samples.iter().map(|(_, c)| c.half_width()).collect();
        let spread = |v: &[f64]| -> (f64, f64, f64) {
            let lo = v.iter().copied().fold(f64::INFINITY, f64::min);
            let hi = v.iter().copied().fold(f64::NEG_INFINITY, f64::max);
            let step = v
                .windows(2)
                .map(|w| (w[1] - w[0]).abs())
                .fold(0.0, f64::max);
            (lo, hi, step)
        };
        let (lo, hi, step) = spread(&rates);
        let (_, a_max, a_step) = spread(&widths);
        let margin = if self.monotone { 0.0 } else { 1.0 };
        RateBounds {
            rate: [lo - margin * step, hi + margin * step],
            half_width: a_max + margin * a_step,
        }
    }
}

/// Bounds along a segment ([`SegmentPath::bounds`]).
#[derive(Debug, Clone, Copy)]
pub(crate) struct RateBounds {
    /// `[lo, hi]` of `(pi/2) dtheta/dt`, t from the low point to the high one.
    pub(crate) rate: [f64; 2],
    /// The largest contact half-width.
    pub(crate) half_width: f64,
}

impl RateBounds {
    /// The largest `|k + x|` for x in the rate bounds of the half that runs the other way when
    /// `reversed` (its rates are the negatives).
    pub(crate) fn largest_sum(&self, k: f64, reversed: bool) -> f64 {
        let [lo, hi] = if reversed {
            [-self.rate[1], -self.rate[0]]
        } else {
            self.rate
        };
        (k + lo).abs().max((k + hi).abs())
    }
}

/// A prediction `t -> (c, a)` of the contacts between `low` (t = 0) and `high` (t = 1) when P
/// and M change by `d_normal` and `d_moment` along the segment: the cubic Hermite interpolant of
/// each end through both contacts with the ends' slopes [`edge_speeds`] (error of order a
/// fourth derivative of the end over 384), or the straight line between them when `cubic` is
/// false or a speed is not finite (K_N = 0 at an end).
fn ends_predictor(
    low: &NormalContact,
    high: &NormalContact,
    d_normal: f64,
    d_moment: f64,
    cubic: bool,
) -> impl Fn(f64) -> (f64, f64) {
    // db/dt: the left end moves outwards towards -x.
    let slopes = |c: &NormalContact| {
        let s = edge_speeds(c, d_normal, d_moment);
        [-s.left, s.right]
    };
    let (m0, m1) = if cubic {
        (slopes(low), slopes(high))
    } else {
        ([f64::NAN; 2], [f64::NAN; 2])
    };
    let finite = m0.iter().chain(&m1).all(|m| m.is_finite());
    let (y0, y1) = (
        [low.end(Edge::Left), low.end(Edge::Right)],
        [high.end(Edge::Left), high.end(Edge::Right)],
    );
    move |t: f64| {
        let end = |i: usize| {
            if !finite {
                return y0[i] + t * (y1[i] - y0[i]);
            }
            let (t2, t3) = (t * t, t * t * t);
            (2.0 * t3 - 3.0 * t2 + 1.0) * y0[i]
                + (t3 - 2.0 * t2 + t) * m0[i]
                + (3.0 * t2 - 2.0 * t3) * y1[i]
                + (t3 - t2) * m1[i]
        };
        let (left, right) = (end(0), end(1));
        (0.5 * (left + right), 0.5 * (right - left))
    }
}

/// The edges' outward speeds of `c` (length per unit of the load change), when P and M change
/// by `d_normal` and `d_moment`: `2 dP_edge / (pi sqrt(2a) K_N)` (the pressure's edge
/// coefficient changes by `dP_edge/(pi sqrt(2a))`, and an edge moving out by `db` changes it by
/// `K_N db/2`).
pub(crate) fn edge_speeds(c: &NormalContact, d_normal: f64, d_moment: f64) -> PerEdge<f64> {
    let d_edge = c.edge_load_changes(d_normal, d_moment);
    let root = PI * (2.0 * c.half_width()).sqrt();
    PerEdge::from_fn(|e| 2.0 * d_edge[e] / (root * c.normal_intensity(e)))
}
