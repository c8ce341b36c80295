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
        // The angle at the current piece's start, unknown after a skipped piece.
        let mut start = Some((-1.0, 0.0));
        for p in &self.pieces[first..] {
            if p.start >= hi {
                break;
            }
            if p.coeffs == [0.0; 3] {
                // g' = 0 here (a pad's flat): it adds nothing, and its angles are not needed.
                start = None;
                continue;
            }
            let (cb, sb) = start.unwrap_or_else(|| angle(p.start));
            let (ca, sa) = angle(p.end);
            let mut m = [0.0; 5];
            m[0] = angle_between(ca, sa, cb, sb);
            m[1] = sb - sa;
            m[2] = 0.5 * (cb * sb - ca * sa) + 0.5 * m[0];
            m[3] = (cb * cb * sb - ca * ca * sa) / 3.0 + 2.0 / 3.0 * m[1];
            m[4] = 0.25 * (cb * cb * cb * sb - ca * ca * ca * sa) + 0.75 * m[2];
            start = Some((ca, sa));
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
    /// `I_j` by the Gauss-Jacobi rule and `dI_j/dc` by the same nodes on g''
    /// ([`PowerSlope::weighted`]), and `dI_j/da` from homogeneity: g' is homogeneous of degree
    /// `k - 1`, so `c dI/dc + a dI/da = (k - 1) I`.
    pub(super) fn contact_integrals(&self, c: f64, a: f64) -> ContactIntegrals {
        let (i, i_c) = self.weighted(a, c);
        let mut out = ContactIntegrals {
            i,
            i_c,
            ..ContactIntegrals::default()
        };
        for j in 0..3 {
            out.i_a[j] = ((self.exponent - 1.0) * i[j] - c * i_c[j]) / a;
        }
        out
    }
}

#[cfg(test)]
mod tests {
    use super::super::Profile;
    use crate::quadrature::gauss_legendre;
    use std::f64::consts::PI;

    /// `I_j` by composite Gauss-Legendre on the pointwise slope, 64 panels between the angles of
    /// the kinks (smooth panels): independent of the moment route.
    fn brute(profile: &Profile, c: f64, a: f64, kinks: &[f64]) -> [f64; 3] {
        let mut cuts = vec![0.0, PI];
        cuts.extend(
            kinks
                .iter()
                .map(|k| (k - c) / a)
                .filter(|t| t.abs() < 1.0)
                .map(f64::acos),
        );
        cuts.sort_by(f64::total_cmp);
        let mut out = [0.0; 3];
        for w in cuts.windows(2) {
            for i in 0..64 {
                let h = (w[1] - w[0]) / 64.0;
                let v = gauss_legendre(w[0] + i as f64 * h, w[0] + (i + 1) as f64 * h, |t| {
                    let s = profile.slope(c + a * t.cos()).unwrap();
                    [s, s * t.cos(), s * (2.0 * t).cos()]
                });
                for j in 0..3 {
                    out[j] += v[j];
                }
            }
        }
        out
    }

    #[test]
    fn contact_integrals_match_quadrature_and_their_derivatives_finite_differences() {
        // Values: both routes exact to rounding on smooth panels, 1e-13 absolute (the integrals
        // are O(0.01-1)). Derivatives: central differences with h = 1e-6 (error ~h^2 I''' plus
        // rounding 1e-16/h), 1e-7 relative; the jump at the table's kink exercises the Leibniz
        // terms, the flat's edges the g'' jumps.
        let x: Vec<f64> = (0..=30).map(|i| -1.5 + 0.1 * i as f64).collect();
        let g = x
            .iter()
            .map(|&x| {
                if x < 0.0 {
                    x * x / 30.0
                } else {
                    0.05 * x + x * x / 20.0
                }
            })
            .collect();
        let profiles = [
            (
                Profile::flat_rounded_asymmetric(0.3, 20.0, 80.0).unwrap(),
                vec![-0.3, 0.3],
            ),
            (Profile::tabulated(x.clone(), g, vec![0.0]).unwrap(), x),
            (Profile::power_law(0.01, 2.5).unwrap(), vec![0.0]),
        ];
        for (profile, kinks) in &profiles {
            for (c, a) in [(0.1, 0.8), (-0.25, 0.6), (0.4, 0.5)] {
                let s = profile.contact_integrals(c, a).unwrap();
                let want = brute(profile, c, a, kinks);
                for (j, (got, want)) in s.i.iter().zip(want).enumerate() {
                    assert!(
                        (got - want).abs() < 1e-11,
                        "I{j}({c}, {a}): {got} vs {want}"
                    );
                }
                let h = 1e-6;
                let at = |c, a| profile.contact_integrals(c, a).unwrap().i;
                for j in 0..3 {
                    let dc = (at(c + h, a)[j] - at(c - h, a)[j]) / (2.0 * h);
                    let da = (at(c, a + h)[j] - at(c, a - h)[j]) / (2.0 * h);
                    assert!(
                        (s.i_c[j] - dc).abs() < 1e-7 * (1.0 + dc.abs()),
                        "dI{j}/dc: {} vs {dc}",
                        s.i_c[j]
                    );
                    assert!(
                        (s.i_a[j] - da).abs() < 1e-7 * (1.0 + da.abs()),
                        "dI{j}/da: {} vs {da}",
                        s.i_a[j]
                    );
                }
            }
        }
    }
}
