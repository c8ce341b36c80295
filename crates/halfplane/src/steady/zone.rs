//! The permanent stick zone of one load segment: the two stick-zone equations solved by the
//! Hertz closed form or by Newton's method with a line search (the paper's eqs. (16) and (23),
//! with the segment's mean rotation under a moment).

use super::{Method, Segment, SteadyOptions, StickZone};
use crate::closed_form;
use crate::error::{Error, Result};
use crate::normal::Contact;
use crate::profile::Shape;
use std::f64::consts::PI;

/// The name the stick-zone Newton iteration gives its [`Error::NoConvergence`]: the one failure to
/// converge that the march may get past (`Error::alternative`).
pub(crate) const STICK_ZONE_EQUATIONS: &str = "stick-zone equations";

/// The error for a segment whose shear range leaves no stick zone: `dQ >= f (P1 + P2)` means the
/// contact slides (d^2 <= 0 in the Hertz closed form, P_K <= 0 in general).
fn no_stick_zone(contact: &Contact, segment: &Segment) -> Error {
    Error::NoStickZone {
        shear_range: segment.shear_range,
        limit: contact.friction.value() * segment.normal_sum,
    }
}

/// Solves the two stick-zone equations for a load segment (docs/theory.md, "Permanent stick zone";
/// paper eqs. (16) and (23), with `xi = e + d cos(theta)`), with the slope `g' + theta_m` where
/// `theta_m` is the segment's mean rotation (docs/theory.md, "Moment"; 0 without a moment on a
/// symmetric profile, which gives the paper's equations):
///
/// - `integral_0^pi g'(e + d cos t) dt + pi theta_m = -pi A dsigma/(8 f)`
/// - `f(P1 + P2) - dQ - pi e dsigma/4 = (2f/A) integral_0^pi xi (g'(xi) + theta_m) dt`
///
/// Hertz (with [`Method::Auto`]) uses the closed form ([`closed_form::hertz_stick_zone`]; the
/// rotation moves the zone by `-R theta_m`). Otherwise Newton's method with the exact Jacobian
/// and a backtracking line search, started from `guess` = (d, e), or else from the symmetric
/// solution `d = a(P_K)`, `P_K = (P1 + P2)/2 - dQ/(2f)`, `e = 0` (exact when dsigma = 0 and
/// there is no rotation), or, under a rotation or on an asymmetric profile, from the contact
/// carrying `P_K` with about the zone's tilt ([`zone_guess`]). Returns the zone and the
/// iterations used.
pub(crate) fn stick_zone(
    contact: &Contact,
    segment: &Segment,
    guess: Option<(f64, f64)>,
    options: &SteadyOptions,
) -> Result<(StickZone, usize)> {
    let f = contact.friction.value();
    let a_comp = contact.compliance().value();
    let Segment {
        normal_sum,
        shear_range,
        bulk_range,
        rotation,
    } = *segment;
    if let (Method::Auto, Shape::Hertz { radius }) = (options.method(), contact.profile.shape()) {
        let (d, e) =
            closed_form::hertz_stick_zone(a_comp, *radius, f, normal_sum, shear_range, bulk_range)
                .ok_or_else(|| no_stick_zone(contact, segment))?;
        return Ok((StickZone::from_half_width(d, e - radius * rotation), 0));
    }
    let residual = |d: f64, e: f64| -> Result<([f64; 2], [[f64; 2]; 2])> {
        let s = contact.profile.stick_integrals(d, e)?;
        let r = [
            s.j0 + PI * rotation + PI * a_comp * bulk_range / (8.0 * f),
            2.0 * f / a_comp * (s.j1 + PI * e * rotation) + PI * e * bulk_range / 4.0
                - f * normal_sum
                + shear_range,
        ];
        let jac = [
            [s.j0_d, s.j0_e],
            [
                2.0 * f / a_comp * s.j1_d,
                2.0 * f / a_comp * (s.j1_e + PI * rotation) + PI * bulk_range / 4.0,
            ],
        ];
        Ok((r, jac))
    };
    let (mut d, mut e) = match guess {
        Some(g) => g,
        None => {
            let p_k = 0.5 * normal_sum - shear_range / (2.0 * f);
            if p_k <= 0.0 {
                return Err(no_stick_zone(contact, segment));
            }
            if rotation == 0.0 && contact.profile.is_symmetric() {
                (contact.half_width(p_k)?, 0.0)
            } else {
                zone_guess(contact, p_k, rotation + a_comp * bulk_range / (8.0 * f))?
            }
        }
    };
    // Residual scales: the consistency equation is a slope integral (compare with pi g'(d)),
    // equilibrium a force (compare with f (P1 + P2)).
    let s1 = PI
        * contact
            .profile
            .slope(e + d)?
            .abs()
            .max(contact.profile.slope(e - d)?.abs())
            .max(f64::MIN_POSITIVE);
    let s2 = f * normal_sum;
    let norm = |r: [f64; 2]| ((r[0] / s1).powi(2) + (r[1] / s2).powi(2)).sqrt();
    let (mut r, mut jac) = residual(d, e)?;
    let (mut last_step, mut iterations) = (f64::INFINITY, 0);
    for iteration in 1..=options.max_iterations() {
        iterations = iteration;
        let det = jac[0][0] * jac[1][1] - jac[0][1] * jac[1][0];
        let step_d = -(jac[1][1] * r[0] - jac[0][1] * r[1]) / det;
        let step_e = -(-jac[1][0] * r[0] + jac[0][0] * r[1]) / det;
        if !(step_d.is_finite() && step_e.is_finite()) {
            break;
        }
        // Converged: the Newton step estimates the error, and its square is what remains. Tested
        // before the line search, which rounding would otherwise stall near the root.
        if step_d.abs().max(step_e.abs()) <= options.tolerance() * d {
            return Ok((
                StickZone::from_half_width(d + step_d, e + step_e),
                iteration,
            ));
        }
        let current = norm(r);
        let mut lambda = 1.0;
        let mut accepted = None;
        for _ in 0..40 {
            let (dn, en) = (d + lambda * step_d, e + lambda * step_e);
            if dn > 0.0 {
                if let Ok((rn, jn)) = residual(dn, en) {
                    if norm(rn) <= (1.0 - 1e-4 * lambda) * current || norm(rn) == 0.0 {
                        accepted = Some((dn, en, rn, jn));
                        break;
                    }
                }
            }
            lambda *= 0.5;
        }
        // Near the solution rounding can stop the residual decreasing: accept a tiny full step.
        let converging = step_d.abs().max(step_e.abs()) <= 1e3 * options.tolerance() * d;
        match accepted {
            Some((dn, en, rn, jn)) => {
                last_step = (dn - d).abs().max((en - e).abs()) / dn;
                d = dn;
                e = en;
                r = rn;
                jac = jn;
            }
            None if converging => {
                d += step_d;
                e += step_e;
                return Ok((StickZone::from_half_width(d, e), iteration));
            }
            None => break,
        }
    }
    Err(Error::NoConvergence {
        what: STICK_ZONE_EQUATIONS,
        iterations,
        last_step,
    })
}

/// A starting point `(d, e)` for the stick-zone Newton iteration under a rotation or on an
/// asymmetric profile. The zone solves the normal problem of the profile under the load `p_k`
/// with the prescribed rotation `tilt = theta_m + A dsigma/(8f)` (the first equation is the
/// consistency condition of that contact, the second its load, docs/theory.md, "Moment"); the
/// contact under `p_k` alone, moved by the moment that changes its rotation by the missing
/// tilt to first order (`dtheta = -2 A dM/(pi a^2)`, [`NormalContact::rotation_change`]), is
/// close to it.
fn zone_guess(contact: &Contact, p_k: f64, tilt: f64) -> Result<(f64, f64)> {
    let a_comp = contact.compliance().value();
    let plain = contact.contact_for(p_k, 0.0)?;
    let per_moment = plain.rotation_change(a_comp, 0.0, 1.0);
    let moment = (tilt - plain.rotation()) / per_moment;
    let moved = if moment.is_finite() {
        contact.contact_for(p_k, moment).unwrap_or(plain)
    } else {
        plain
    };
    Ok((moved.half_width(), moved.centre()))
}
