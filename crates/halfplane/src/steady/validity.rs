//! Whether the steady-state analysis applies to a partial-slip cycle: both slip zones must grow
//! monotonically through each half-cycle (docs/validity.md, section 2). [`check_slip_grows`]
//! tests the start of each half exactly and follows the partial path along each half.
//!
//! Conventions: point 1 is the end with the smaller Q, `dQ = Q2 - Q1 >= 0`,
//! `dsigma = sigma1 - sigma2`, x positive in the direction of positive Q (the right stick
//! boundary is `n`, the left `-m`); half 1 runs from the first point as given to the second.

use super::{stick_zone, Segment, SteadyOptions, StickZone};
use crate::error::{Error, Result};
use crate::labels::{Edge, Half, PerEdge};
use crate::load::{Cycle, LoadPoint};
use crate::normal::Contact;
use crate::profile::Shape;
use std::f64::consts::PI;

/// Samples per half-cycle for the along-the-half check of [`check_slip_grows`].
const SAMPLES_PER_HALF: usize = 32;

/// The partial path of one half-cycle at fraction t: the stick zone, the contact half-width and
/// the outward speeds (`dm/dt` left, `dn/dt` right) of the stick boundaries and `da/dt` of the contact edge.
struct PathPoint {
    zone: StickZone,
    half_width: f64,
    boundary_rate: PerEdge<f64>,
    edge_rate: f64,
}

/// One half-cycle from the reversal point `start` towards `end`, with the cycle's `dQ >= 0` and
/// `dsigma = sigma1 - sigma2` (point 1 the end of smaller Q).
///
/// At fraction t the partial path from `start` is, labelled by Q as the stick-zone equations need
/// it, the segment with `P1 + P2 = 2 P_start + t (P_end - P_start)`, shear range `t dQ` and
/// tension range `t dsigma`, on either half (on the rising half the current point replaces point 2,
/// on the falling half point 1; both give these ranges).
struct HalfPath<'a> {
    contact: &'a Contact,
    start: LoadPoint,
    normal_change: f64,
    shear_range: f64,
    bulk_range: f64,
    options: &'a SteadyOptions,
}

impl HalfPath<'_> {
    fn segment(&self, t: f64) -> Segment {
        Segment {
            normal_sum: 2.0 * self.start.normal() + t * self.normal_change,
            shear_range: t * self.shear_range,
            bulk_range: t * self.bulk_range,
        }
    }

    /// The stick zone at fraction t > 0 and the boundary speeds from the implicit function
    /// theorem: with `R(d, e; t) = 0` the two stick-zone equations of [`super::stick_zone`] and `J` their
    /// exact Jacobian in (d, e), `(d', e') = -J^-1 dR/dt`, where
    /// `dR1/dt = pi A dsigma/(8f)` and `dR2/dt = pi e dsigma/4 - f (P_end - P_start) + dQ`;
    /// then `n' = d' + e'`, `m' = d' - e'` (docs/validity.md, "Along the half").
    fn at(&self, t: f64, guess: Option<(f64, f64)>) -> Result<PathPoint> {
        let f = self.contact.friction.value();
        let a_comp = self.contact.compliance().value();
        let (zone, _) = stick_zone(self.contact, &self.segment(t), guess, self.options)?;
        let (d, e) = (zone.half_width(), zone.eccentricity());
        let s = self.contact.profile.stick_integrals(d, e)?;
        let bulk = t * self.bulk_range;
        let jac = [
            [s.j0_d, s.j0_e],
            [
                2.0 * f / a_comp * s.j1_d,
                2.0 * f / a_comp * s.j1_e + PI * bulk / 4.0,
            ],
        ];
        let r_t = [
            PI * a_comp * self.bulk_range / (8.0 * f),
            PI * e * self.bulk_range / 4.0 - f * self.normal_change + self.shear_range,
        ];
        let det = jac[0][0] * jac[1][1] - jac[0][1] * jac[1][0];
        let d_t = -(jac[1][1] * r_t[0] - jac[0][1] * r_t[1]) / det;
        let e_t = -(-jac[1][0] * r_t[0] + jac[0][0] * r_t[1]) / det;
        let half_width = self
            .contact
            .half_width(self.start.normal() + t * self.normal_change)?;
        Ok(PathPoint {
            zone,
            half_width,
            boundary_rate: PerEdge {
                left: d_t - e_t,
                right: d_t + e_t,
            },
            edge_rate: self.normal_change / self.contact.load_rate(half_width)?,
        })
    }
}

/// Checks that both slip zones grow monotonically through both halves of a partial-slip cycle,
/// the condition for the partial-path relation and so the permanent stick zone to be exact (see
/// [`super::analyse`], which calls it, and docs/validity.md). Half 1 runs from the first point as given
/// to the second. Returns [`Error::SlipReversesInHalf`] at the first failure. Conventions: point 1
/// is the end with the smaller Q, `dQ = Q2 - Q1 >= 0`, `dsigma = sigma1 - sigma2`, x positive in
/// the direction of positive Q (so the right edge is `n`, the left `-m`).
///
/// At the start of a half (t = 0, the stick zone is the whole contact `a_s`) the boundary speeds
/// are exact for any profile: `n' = (f dP - dS_right)/(2 f P'(a_s))`,
/// `m' = (f dP - dS_left)/(2 f P'(a_s))` and `a' = dP/P'(a_s)`, with `dP = P_end - P_start`,
/// `P'(a) = dP/da` and the equivalent-shear ranges `dS_left = dQ - pi a_s dsigma/4`,
/// `dS_right = dQ + pi a_s dsigma/4`; so `n' <= min(0, a')` exactly when `dS_right >= f |dP|`
/// (docs/validity.md, "Start of a half"). Along the half `m, n` must be non-increasing and stay
/// below `min(a_s, a(t))`; this is sampled for every profile but Hertz, for which the start-of-half
/// test implies it (docs/validity.md, "Along the half").
pub fn check_slip_grows(contact: &Contact, cycle: &Cycle, options: &SteadyOptions) -> Result<()> {
    let f = contact.friction.value();
    let (low, high) = (cycle.low(), cycle.high());
    let (d_q, d_sigma) = (cycle.shear_range(), cycle.bulk_range());
    // The half that starts from the larger contact first (where the weak edge binds; Q rising
    // first on a tie), so that the failure reported does not depend on the order the points
    // were given in; `half` numbers it as given.
    let (rising, falling) = if cycle.swapped() {
        (Half::Second, Half::First)
    } else {
        (Half::First, Half::Second)
    };
    let mut halves = [
        (rising, low, high, contact.half_width(low.normal())?),
        (falling, high, low, contact.half_width(high.normal())?),
    ];
    if halves[1].3 > halves[0].3 {
        halves.swap(0, 1);
    }
    // The start of each half first: exact, and where a failure is most often found.
    for (half, start, end, a_s) in halves {
        let d_p = end.normal() - start.normal();
        let load_rate = contact.load_rate(a_s)?;
        for edge in Edge::BOTH {
            let sign = if edge == Edge::Left { -1.0 } else { 1.0 };
            let equivalent_shear_range = d_q + sign * PI * a_s * d_sigma / 4.0;
            if equivalent_shear_range <= f * d_p.abs() {
                return Err(Error::SlipReversesInHalf {
                    half,
                    edge,
                    fraction: 0.0,
                    boundary_rate: (f * d_p - equivalent_shear_range) / (2.0 * f * load_rate),
                    limit_rate: (d_p / load_rate).min(0.0),
                });
            }
        }
    }
    // Hertz: the start-of-half test is sufficient along the whole half (docs/validity.md, "Along
    // the half": d(t) is the square root of a linear function and e is linear in t).
    if matches!(contact.profile.shape(), Shape::Hertz { .. }) {
        return Ok(());
    }
    for (half, start, end, a_s) in halves {
        let path = HalfPath {
            contact,
            start,
            normal_change: end.normal() - start.normal(),
            shear_range: d_q,
            bulk_range: d_sigma,
            options,
        };
        // Along the half: margins that must stay >= 0, per edge: -(boundary speed), and
        // (min(a_s, a(t)) - boundary)/t.
        let tolerance = 1e-9 * a_s;
        let margins = |p: &PathPoint, t: f64| -> [PerEdge<f64>; 2] {
            let limit = a_s.min(p.half_width);
            [
                p.boundary_rate.map(|rate| -rate),
                PerEdge {
                    left: (limit + p.zone.left) / t,
                    right: (limit - p.zone.right) / t,
                },
            ]
        };
        let mut guess = Some((a_s, 0.0));
        let mut previous_t = 0.0;
        for k in 1..=SAMPLES_PER_HALF {
            let t = k as f64 / SAMPLES_PER_HALF as f64;
            let p = path.at(t, guess)?;
            guess = Some((p.zone.half_width(), p.zone.eccentricity()));
            let failing = margins(&p, t);
            if !failing
                .iter()
                .flat_map(|m| m.to_array())
                .any(|v| v < -tolerance)
            {
                previous_t = t;
                continue;
            }
            // Bisect each failing margin on [previous_t, t] and report the earliest root.
            let mut first_failure: Option<(f64, Edge)> = None;
            for (kind, edge) in [0, 1].into_iter().flat_map(|k| Edge::BOTH.map(|e| (k, e))) {
                if failing[kind][edge] >= -tolerance {
                    continue;
                }
                let (mut lo, mut hi) = (previous_t, t);
                while hi - lo > 1e-10 {
                    let mid = 0.5 * (lo + hi);
                    let q = path.at(mid, guess)?;
                    if margins(&q, mid)[kind][edge] < -tolerance {
                        hi = mid;
                    } else {
                        lo = mid;
                    }
                }
                if first_failure.is_none_or(|(t0, _)| hi < t0) {
                    first_failure = Some((hi, edge));
                }
            }
            // At least one margin failed at t, so its bisection set first_failure.
            let Some((fraction, edge)) = first_failure else {
                continue;
            };
            let q = path.at(fraction, guess)?;
            return Err(Error::SlipReversesInHalf {
                half,
                edge,
                fraction,
                boundary_rate: q.boundary_rate[edge],
                limit_rate: q.edge_rate.min(0.0),
            });
        }
    }
    Ok(())
}
