//! The power law `g = B|x|^k`: its slope integrals by Gauss-Jacobi quadrature with the weight
//! `|theta - theta0|^(k-1)` on each side of x = 0, which absorbs the algebraic singularity of g'
//! there, and its contact-law moment in closed form (the Wallis integral).

use super::StickIntegrals;
use crate::closed_form;
use crate::quadrature::{gauss_legendre, Rule};
use std::f64::consts::PI;

/// Power-law slope `g' = B k |x|^(k-1) sign(x)` with a Gauss-Jacobi rule for weight t^(k-1).
#[derive(Debug, Clone, PartialEq)]
pub(super) struct PowerSlope {
    pub(super) coefficient: f64,
    pub(super) exponent: f64,
    pub(super) rule: Rule,
}

impl PowerSlope {
    pub(super) fn slope(&self, x: f64) -> f64 {
        self.coefficient * self.exponent * x.abs().powf(self.exponent - 1.0) * x.signum()
    }

    /// J0 and J1 only (no derivatives).
    fn values(&self, d: f64, e: f64) -> (f64, f64) {
        let (b, k) = (self.coefficient, self.exponent);
        if e.abs() >= d {
            // x = 0 is outside the zone: the integrands are smooth.
            let [j0, j1] = gauss_legendre(0.0, PI, |t| {
                let xi = e + d * t.cos();
                let s = self.slope(xi);
                [s, xi * s]
            });
            return (j0, j1);
        }
        // theta0: where xi = e + d cos(theta0) = 0. On each side, with theta = theta0 -/+ L t,
        // |xi| = 2 d sin((theta + theta0)/2) sin(L t / 2) = L t R(t), R smooth and positive.
        let theta0 = ((d - e) * (d + e)).sqrt().atan2(-e);
        let mut j0 = 0.0;
        let mut j1 = 0.0;
        for (length, sign) in [(theta0, 1.0), (PI - theta0, -1.0)] {
            let mut s0 = 0.0;
            let mut s1 = 0.0;
            for (t, w) in self.rule.nodes.iter().zip(&self.rule.weights) {
                let theta = theta0 - sign * length * t;
                // |xi| = L t R(t); xi from one cosine loses at most ~1e-14 relative at the
                // node nearest theta0 (t ~ 0.01), whose weight is small.
                let r = (e + d * theta.cos()).abs() / (length * t);
                let rk1 = r.powf(k - 1.0);
                s0 += w * rk1;
                s1 += w * t * rk1 * r;
            }
            j0 += sign * b * k * length.powf(k) * s0;
            j1 += b * k * length.powf(k + 1.0) * s1;
        }
        (j0, j1)
    }

    /// `I_j = integral_0^pi g'(e + d cos t) [1, cos t, cos 2t] dt` (a contact centred at e, see
    /// `offset`), by the same split at x = 0 and Gauss-Jacobi rule as [`PowerSlope::values`],
    /// and from the same nodes their derivatives in the centre,
    /// `dI_j/dc = integral_0^pi g''(e + d cos t) [1, cos t, cos 2t] dt`, with
    /// `g'' = B k (k - 1) |x|^(k-2)` (even in x, integrable for k > 1). On each side of x = 0
    /// (see [`PowerSlope::values`]) the integrand is `B k (k-1) L^(k-1) t^(k-2) F(t)` with
    /// `F = R^(k-2) h(theta)` smooth, `R(0) = sqrt(d^2 - e^2)`; the singular part is integrated
    /// exactly, `integral_0^1 t^(k-2) F = integral_0^1 t^(k-1) (F - F(0))/t + F(0)/(k - 1)`, and
    /// the rest by the Gauss-Jacobi rule of the values (weight t^(k-1)), so one `powf` per node
    /// gives both. At k = 1 only `F(0)` remains: the Leibniz term `2B h(theta0)/(d sin theta0)`
    /// of the slope's jump 2B at x = 0. Outside (x = 0 not in the contact) `g'' = (k-1) g'/x`.
    pub(super) fn weighted(&self, d: f64, e: f64) -> ([f64; 3], [f64; 3]) {
        let (b, k) = (self.coefficient, self.exponent);
        let harmonics = |c: f64| [1.0, c, 2.0 * c * c - 1.0];
        if e.abs() >= d {
            let v = gauss_legendre(0.0, PI, |t| {
                let (c, xi) = (t.cos(), e + d * t.cos());
                let s = self.slope(xi);
                let h = harmonics(c);
                let s2 = (k - 1.0) * s / xi;
                [
                    s * h[0],
                    s * h[1],
                    s * h[2],
                    s2 * h[0],
                    s2 * h[1],
                    s2 * h[2],
                ]
            });
            return ([v[0], v[1], v[2]], [v[3], v[4], v[5]]);
        }
        let root = ((d - e) * (d + e)).sqrt();
        let theta0 = root.atan2(-e);
        // F(0) = R(0)^(k-2) h(theta0), the same on both sides.
        let f0 = harmonics(-e / d).map(|h| root.powf(k - 2.0) * h);
        let mut out = [0.0; 3];
        let mut out_c = [0.0; 3];
        for (length, sign) in [(theta0, 1.0), (PI - theta0, -1.0)] {
            let mut sum = [0.0; 3];
            let mut sum_c = [0.0; 3];
            for (t, w) in self.rule.nodes.iter().zip(&self.rule.weights) {
                let theta = theta0 - sign * length * t;
                let c = theta.cos();
                let r = (e + d * c).abs() / (length * t);
                let rk1 = r.powf(k - 1.0);
                let rk2 = rk1 / r;
                for (j, h) in harmonics(c).into_iter().enumerate() {
                    sum[j] += w * rk1 * h;
                    sum_c[j] += w * (rk2 * h - f0[j]) / t;
                }
            }
            let lk = length.powf(k);
            for j in 0..3 {
                out[j] += sign * b * k * lk * sum[j];
                out_c[j] += b * k * lk / length * ((k - 1.0) * sum_c[j] + f0[j]);
            }
        }
        (out, out_c)
    }

    /// `J1(a, 0)` and `dJ1/da` in closed form: `integral_0^pi |cos t|^k dt = 2 W_k`, with `W_k`
    /// the Wallis integral ([`closed_form::wallis_integral`]).
    pub(super) fn symmetric_moment(&self, a: f64) -> (f64, f64) {
        let k = self.exponent;
        let wallis = closed_form::wallis_integral(k);
        let j1 = 2.0 * self.coefficient * k * wallis * a.powf(k);
        (j1, k * j1 / a)
    }

    /// Values and Jacobian. Because `xi g''(xi) = (k-1) g'(xi)` and the integrals are homogeneous
    /// (J0 of degree k-1, J1 of degree k in (d, e)), `dJ1/de = k J0`,
    /// `d dJ0/dd + e dJ0/de = (k-1) J0` and `d dJ1/dd + e dJ1/de = k J1`: only `dJ0/de` needs a
    /// (forward) difference, step 1e-7 d. Newton needs only an approximate Jacobian; the
    /// solution's accuracy is set by the values.
    pub(super) fn integrals(&self, d: f64, e: f64) -> StickIntegrals {
        let k = self.exponent;
        let h = 1e-7 * d;
        let (j0, j1) = self.values(d, e);
        let j0_e = (self.values(d, e + h).0 - j0) / h;
        let j1_e = k * j0;
        StickIntegrals {
            j0,
            j1,
            j0_d: ((k - 1.0) * j0 - e * j0_e) / d,
            j0_e,
            j1_d: (k * j1 - e * j1_e) / d,
            j1_e,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::super::{brute, Profile};

    #[test]
    fn power_law_integrals_match_brute_force() {
        // k = 2.5 has g' ~ |x|^1.5 at 0, so the brute-force panels next to x = 0 converge only
        // algebraically (~1e-12 with 64 panels); the Jacobi rule must agree to 1e-11.
        let profile = Profile::power_law(0.01, 2.5).unwrap();
        for (d, e) in [(0.8, 0.0), (0.8, 0.05), (0.7, -0.1)] {
            let s = profile.stick_integrals(d, e).unwrap();
            let (j0, j1) = brute(&profile, d, e);
            assert!((s.j0 - j0).abs() < 1e-11, "J0: {} vs {j0}", s.j0);
            assert!((s.j1 - j1).abs() < 1e-11, "J1: {} vs {j1}", s.j1);
        }
    }

    #[test]
    fn centre_derivatives_match_a_five_point_difference_of_the_values() {
        // dI_j/dc from g'' on the values' nodes against the five-point central difference of the
        // values with step h = 1e-4 a (truncation h^4 I^(5)/30 with I's scale of variation the
        // distance from x = 0 to the nearer end, 0.05 at the closest: about 1e-12; rounding
        // 1e-16/h): 1e-9 of the derivatives' scale (and 1e-12 where it is 0). Exponents from the
        // wedge (k = 1, the jump's Leibniz term alone) to a smooth even one; contacts across
        // x = 0 and beside it.
        for k in [1.0, 1.3, 2.0, 2.5, 4.0] {
            let slope = match Profile::power_law(0.01, k).unwrap().slope {
                super::super::Slope::Power(p) => p,
                _ => unreachable!(),
            };
            for (c, a) in [(0.0, 0.8), (0.1, 0.8), (-0.3, 0.5), (0.45, 0.5), (1.2, 0.4)] {
                let (_, got) = slope.weighted(a, c);
                let h = 1e-4 * a;
                let at = |t: f64| slope.weighted(a, c + t * h).0;
                let (m2, m1, p1, p2) = (at(-2.0), at(-1.0), at(1.0), at(2.0));
                let want: Vec<f64> = (0..3)
                    .map(|j| (m2[j] - 8.0 * m1[j] + 8.0 * p1[j] - p2[j]) / (12.0 * h))
                    .collect();
                let scale = want.iter().fold(0.0_f64, |m, w| m.max(w.abs()));
                for j in 0..3 {
                    assert!(
                        (got[j] - want[j]).abs() < 1e-9 * scale + 1e-12,
                        "k = {k}, (c, a) = ({c}, {a}): dI{j}/dc {} vs {}",
                        got[j],
                        want[j]
                    );
                }
            }
        }
    }
}
