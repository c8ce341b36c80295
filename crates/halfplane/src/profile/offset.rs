//! The slope integrals of a contact `[c - a, c + a]` centred anywhere, which the normal problem
//! under a moment needs (docs/theory.md, "Normal contact under a moment"): with
//! `xi = c + a cos(phi)`,
//!
//! `I_j(c, a) = integral_0^pi g'(xi) cos(j phi) dphi`, j = 0, 1, 2,
//!
//! and their partial derivatives in c and a. Then `A P = a I_1`, `A M = c A P + a^2 I_2 / 2` and
//! the rotation is `-I_0 / pi`. Piecewise-polynomial slopes are integrated exactly by the moments
//! `integral cos^j phi dphi` (as `pieces` does for the stick-zone integrals); the power law by its
//! Gauss-Jacobi rule.

use super::pieces::{angle_between, Pieces};
use super::power::PowerSlope;
use super::{Profile, Slope};
use crate::error::Result;

/// `I_j(c, a)` (j = 0, 1, 2) and their partial derivatives in the centre c and half-width a.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub(crate) struct ContactIntegrals {
    /// `I_0, I_1, I_2`.
    pub i: [f64; 3],
    /// `dI_j/dc`.
    pub i_c: [f64; 3],
    /// `dI_j/da`.
    pub i_a: [f64; 3],
}

impl Profile {
    /// `I_j(c, a)` and derivatives for the contact `[c - a, c + a]`, `a > 0`. Errors where the
    /// contact leaves a tabulated profile.
    pub(crate) fn contact_integrals(&self, c: f64, a: f64) -> Result<ContactIntegrals> {
        match &self.slope {
            Slope::Pieces(p) => p.contact_integrals(c, a),
            Slope::Power(p) => Ok(p.contact_integrals(c, a)),
        }
    }
}

/// `sum_k poly[k] m[k + shift]`: the integral of `poly(cos phi) cos^shift phi` from the moments
/// `m[j] = integral cos^j phi dphi` over a piece.
fn against(poly: &[f64], m: &[f64; 5], shift: usize) -> f64 {
    poly.iter().enumerate().map(|(k, p)| p * m[k + shift]).sum()
}

impl Pieces {
    /// Exact `I_j` and derivatives: on a piece with `g' = q0 + q1 u + q2 u^2`, `u = xi - o`,
    /// g' is `G0 + G1 cos + G2 cos^2` and g'' is `H0 + H1 cos` in `cos(phi)`; with
    /// `cos(2 phi) = 2 cos^2 - 1` every integrand is a polynomial of degree <= 4 in cos(phi),
    /// integrated by the moments `integral cos^j`. `dI_j/dc = integral g'' cos(j phi)` and
    /// `dI_j/da = integral g'' cos(phi) cos(j phi)`, plus the Leibniz terms of jumps of g' at
    /// angle phi_k: `jump cos(j phi_k) / (a sin phi_k)` (times `cos phi_k` for a).
    pub(super) fn contact_integrals(&self, c: f64, a: f64) -> Result<ContactIntegrals> {
        let (lo, hi) = (c - a, c + a);
        self.check_span("contact", lo, hi)?;
        // cos and sin of the angle of the point x, from the distances to the ends (accurate near
        // 0 and pi).
        let angle = |x: f64| {
            if x >= hi {
                return (1.0, 0.0);
            }
            if x <= lo {
                return (-1.0, 0.0);
            }
            let cos = ((x - c) / a).clamp(-1.0, 1.0);
            (cos, ((hi - x) * (x - lo)).sqrt() / a)
        };
        let mut out = ContactIntegrals::default();
        let first = self.pieces.partition_point(|p| p.end <= lo);
        let (mut cb, mut sb) = (-1.0, 0.0);
        for p in &self.pieces[first..] {
            if p.start >= hi {
                break;
            }
            let (ca, sa) = angle(p.end);
            let mut m = [0.0; 5];
            m[0] = angle_between(ca, sa, cb, sb);
            m[1] = sb - sa;
            m[2] = 0.5 * (cb * sb - ca * sa) + 0.5 * m[0];
            m[3] = (cb * cb * sb - ca * ca * sa) / 3.0 + 2.0 / 3.0 * m[1];
            m[4] = 0.25 * (cb * cb * cb * sb - ca * ca * ca * sa) + 0.75 * m[2];
            (cb, sb) = (ca, sa);
            let [q0, q1, q2] = p.coeffs;
            let u = c - p.origin;
            let g = [q0 + u * (q1 + u * q2), a * (q1 + 2.0 * u * q2), a * a * q2];
            let h = [q1 + 2.0 * u * q2, 2.0 * q2 * a];
            let i0 = against(&g, &m, 0);
            out.i[0] += i0;
            out.i[1] += against(&g, &m, 1);
            out.i[2] += 2.0 * against(&g, &m, 2) - i0;
            let (h0, h1) = (against(&h, &m, 0), against(&h, &m, 1));
            out.i_c[0] += h0;
            out.i_c[1] += h1;
            out.i_c[2] += 2.0 * against(&h, &m, 2) - h0;
            out.i_a[0] += h1;
            out.i_a[1] += against(&h, &m, 2);
            out.i_a[2] += 2.0 * against(&h, &m, 3) - h1;
        }
        for &(x, jump) in &self.jumps {
            if x > lo && x < hi {
                let (cos, sin) = angle(x);
                let k = jump / (a * sin);
                for (j, w) in [1.0, cos, 2.0 * cos * cos - 1.0].into_iter().enumerate() {
                    out.i_c[j] += k * w;
                    out.i_a[j] += k * w * cos;
                }
            }
        }
        Ok(out)
    }
}

impl PowerSlope {
    /// `I_j` by the Gauss-Jacobi rule ([`PowerSlope::weighted`]); `dI_j/dc` by the five-point
    /// central difference with step `1e-3 a` (truncation `h^4 I^(5)/30`, about 3e-14 relative,
    /// rounding about 1e-13), and `dI_j/da` from homogeneity: g' is homogeneous of degree `k - 1`,
    /// so `c dI/dc + a dI/da = (k - 1) I`.
    pub(super) fn contact_integrals(&self, c: f64, a: f64) -> ContactIntegrals {
        let i = self.weighted(a, c);
        let h = 1e-3 * a;
        let at = |t: f64| self.weighted(a, c + t * h);
        let (m2, m1, p1, p2) = (at(-2.0), at(-1.0), at(1.0), at(2.0));
        let mut out = ContactIntegrals {
            i,
            ..ContactIntegrals::default()
        };
        for j in 0..3 {
            out.i_c[j] = (m2[j] - 8.0 * m1[j] + 8.0 * p1[j] - p2[j]) / (12.0 * h);
            out.i_a[j] = ((self.exponent - 1.0) * i[j] - c * out.i_c[j]) / a;
        }
        out
    }
}
