//! Gauss-Jacobi quadrature for a surface-breaking crack (Hills et al. 1996; Erdogan, Gupta and Cook,
//! 1973). On `t` in [-1, 1], the mouth at `t = -1` and the tip at `t = 1`, a
//! dislocation density is written `B(t) = w(t) phi(t)` with `w(t) = sqrt((1 + t)/(1 - t))`:
//! square-root singular at the tip, bounded at the mouth, `phi` smooth. Integration points are
//! the zeros of the Jacobi polynomial `P_N^(-1/2, 1/2)`, `t_i = cos(pi (2i - 1)/(2N + 1))`, with
//! weights `W_i = 2 pi (1 + t_i)/(2N + 1)`; the Cauchy integral `integral w phi/(u - t) dt` is
//! exact as `sum W_i phi(t_i)/(u_k - t_i)` at the zeros of `P_N^(1/2, -1/2)`,
//! `u_k = cos(2 pi k/(2N + 1))`, for polynomial `phi` of degree below N: N equations for N
//! values per component, with no closure condition (the mouth may open).

use crate::error::Result;
use crate::quadrature::Rule as Gauss;

/// The rule for `n` points.
#[derive(Debug, Clone)]
pub(crate) struct Rule {
    /// Integration points `t_i`, descending (from the tip towards the mouth).
    pub nodes: Vec<f64>,
    /// Weights `W_i`.
    pub weights: Vec<f64>,
    /// Collocation points `u_k`, descending.
    pub collocation: Vec<f64>,
    /// Barycentric weights of the interpolant of `phi` through the nodes.
    bary: Vec<f64>,
    /// Gauss-Legendre on [0, 1] for the partial integrals.
    legendre: Gauss,
}

impl Rule {
    pub fn new(n: usize) -> Result<Self> {
        let m = (2 * n + 1) as f64;
        let pi = std::f64::consts::PI;
        let nodes: Vec<f64> = (1..=n)
            .map(|i| (pi * (2 * i - 1) as f64 / m).cos())
            .collect();
        let weights = nodes.iter().map(|t| 2.0 * pi * (1.0 + t) / m).collect();
        let collocation = (1..=n).map(|k| (2.0 * pi * k as f64 / m).cos()).collect();
        let bary = barycentric_weights(&nodes);
        Ok(Self {
            nodes,
            weights,
            collocation,
            bary,
            legendre: Gauss::jacobi(n + 20, 0.0)?,
        })
    }

    /// The Lagrange basis through the nodes at `x` (barycentric form, exact at a node).
    pub fn basis(&self, x: f64) -> Vec<f64> {
        lagrange_basis(&self.nodes, &self.bary, x)
    }

    /// `integral_u^1 w(t) L_i(t) dt` for every basis polynomial `L_i`. For `u >= 0`, with
    /// `t = 1 - v^2` the integrand is `2 sqrt(2 - v^2) L_i(1 - v^2)` on `0 <= v <= sqrt(1 - u)`;
    /// for `u < 0` the whole integral is `W_i` (the rule is exact for `L_i`) less the part from
    /// the mouth, where `t = -1 + v^2` gives `2 v^2 L_i(-1 + v^2)/sqrt(2 - v^2)` on
    /// `0 <= v <= sqrt(1 + u)`. Both integrands are polynomials times a function analytic
    /// within 0.41 of the interval, taken by Gauss-Legendre with N + 20 points (error of order
    /// 3.4^-40 beyond the polynomial part, which it integrates exactly).
    pub fn tail_integrals(&self, u: f64) -> Vec<f64> {
        let mut out = if u >= 0.0 {
            vec![0.0; self.nodes.len()]
        } else {
            self.weights.clone()
        };
        let (top, sign) = if u >= 0.0 {
            ((1.0 - u).sqrt(), 1.0)
        } else {
            ((1.0 + u).max(0.0).sqrt(), -1.0)
        };
        for (r, omega) in self.legendre.nodes.iter().zip(&self.legendre.weights) {
            let v = top * r;
            let (t, f) = if sign > 0.0 {
                (1.0 - v * v, 2.0 * (2.0 - v * v).sqrt())
            } else {
                (-1.0 + v * v, 2.0 * v * v / (2.0 - v * v).sqrt())
            };
            let scale = sign * omega * top * f;
            for (o, l) in out.iter_mut().zip(self.basis(t)) {
                *o += scale * l;
            }
        }
        out
    }
}

/// The barycentric weights `1/prod_{k != i}(x_i - x_k)` of Lagrange interpolation through
/// `nodes` (Berrut and Trefethen, *Barycentric Lagrange interpolation*, SIAM Review 46, 2004).
pub(super) fn barycentric_weights(nodes: &[f64]) -> Vec<f64> {
    (0..nodes.len())
        .map(|i| {
            let p: f64 = (0..nodes.len())
                .filter(|&k| k != i)
                .map(|k| nodes[i] - nodes[k])
                .product();
            1.0 / p
        })
        .collect()
}

/// Every Lagrange basis polynomial through `nodes` at `x` (the barycentric formula of the second
/// kind with the weights `bary`; exact at a node, and valid outside the nodes' span too).
pub(super) fn lagrange_basis(nodes: &[f64], bary: &[f64], x: f64) -> Vec<f64> {
    if let Some(i) = nodes.iter().position(|&t| t == x) {
        let mut e = vec![0.0; nodes.len()];
        e[i] = 1.0;
        return e;
    }
    let terms: Vec<f64> = nodes.iter().zip(bary).map(|(t, l)| l / (x - t)).collect();
    let sum: f64 = terms.iter().sum();
    terms.iter().map(|v| v / sum).collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_cauchy_rule_is_exact_for_polynomials() {
        // The weight's total is pi, and its Cauchy integral
        // integral_{-1}^{1} sqrt((1+t)/(1-t)) / (u - t) dt = -pi for |u| < 1 (Erdogan, Gupta and
        // Cook 1973): both exact at the collocation points.
        let rule = Rule::new(12).unwrap();
        let total: f64 = rule.weights.iter().sum();
        assert!((total - std::f64::consts::PI).abs() < 1e-13, "{total}");
        for &u in &rule.collocation {
            let s: f64 = rule
                .nodes
                .iter()
                .zip(&rule.weights)
                .map(|(t, w)| w / (u - t))
                .sum();
            assert!((s + std::f64::consts::PI).abs() < 1e-12, "{u} {s}");
        }
    }

    #[test]
    fn tail_integrals_of_the_weight() {
        // integral_u^1 sqrt((1+t)/(1-t)) dt = sqrt(1-u^2) + acos(u) (differentiate to check).
        let rule = Rule::new(10).unwrap();
        for u in [-0.99, -0.3, 0.0, 0.5, 0.97] {
            let s: f64 = rule.tail_integrals(u).iter().sum();
            let exact = (1.0 - u * u).sqrt() + u.acos();
            assert!((s - exact).abs() < 1e-12, "{u} {s} {exact}");
        }
    }
}
