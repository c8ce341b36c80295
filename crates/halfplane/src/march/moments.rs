//! Cell moments of the tractions the marcher knows in closed form: the pressure (so the slip
//! traction `f p`) and the square root of a stick-slip boundary.
//!
//! The marcher holds each cell's traction by its mean and its first-moment slope
//! (`docs/convergence.md`, "Sub-cell stick-slip boundaries"): a slipping cell carries `f p`,
//! whose cell mean differs from its centre value where `p` curves, and whose slope the
//! stick cells next to a stick-slip boundary feel strongly (taking the centre value alone left
//! errors of 4e-4 f p0 there at 400 cells). The pressure of every profile has the form
//! `p = sqrt(u) psi` with `u = (x - b1)(b2 - x)` and `psi` smooth (Johnson, *Contact Mechanics*,
//! section 5.7; the same form `dissipation.rs` integrates in time); `psi` is taken linear over a
//! cell (its centre value and a centred difference), and the moments are integrated with a
//! Gauss rule, in the variable `r = sqrt(distance to the edge)` within a few cells of a contact
//! edge, where `sqrt(u)` is not smooth in x.
//!
//! Owns these integrals, and the marcher's limit means and slopes built from them. Never
//! decides which cells slip.

use super::marcher::{Cell, Marcher};
use crate::error::Result;
use crate::labels::{Edge, PerEdge};
use crate::normal_moment::NormalContact;
use crate::quadrature::gauss_legendre;

impl Marcher {
    /// The limit traction `f p` of the current sub-step as cell means and slopes.
    pub(super) fn limits(&mut self, target: &NormalContact) {
        let (w, f) = (self.width, self.friction);
        self.shape = PressureShape::new(&self.x, &self.pressure, target.ends());
        for i in 0..self.x.len() {
            let xi = self.x[i];
            let [m0, m1] = if self.cells[i] == Cell::Out {
                [0.0; 2]
            } else {
                self.shape.moments(i, xi, w, xi - 0.5 * w, xi + 0.5 * w)
            };
            self.limit_mean[i] = f * m0 / w;
            self.limit_slope[i] = f * 12.0 * m1 / (w * w * w);
        }
    }

    /// The pressure of the current sub-step's contact at `x`.
    pub(super) fn pressure_at(&self, x: f64) -> Result<f64> {
        match &self.target {
            Some(t) if x > t.end(Edge::Left) && x < t.end(Edge::Right) => {
                self.contact.pressure_at(t, x)
            }
            _ => Ok(0.0),
        }
    }
}

/// The pressure over the cells in the form `sqrt(u) psi`, `psi` linear in each cell.
pub(super) struct PressureShape {
    ends: PerEdge<f64>,
    psi: Vec<f64>,
    dpsi: Vec<f64>,
}

impl PressureShape {
    /// From the centre pressures of the cells whose centre is inside the contact `ends`.
    pub(super) fn new(x: &[f64], pressure: &[f64], ends: PerEdge<f64>) -> Self {
        let n = x.len();
        let u = |x: f64| (x - ends.left) * (ends.right - x);
        let psi: Vec<f64> = (0..n)
            .map(|i| {
                let ui = u(x[i]);
                if ui > 0.0 {
                    pressure[i] / ui.sqrt()
                } else {
                    0.0
                }
            })
            .collect();
        let inside = |i: usize| u(x[i]) > 0.0;
        let dpsi = (0..n)
            .map(|i| {
                if !inside(i) {
                    return 0.0;
                }
                let left = i > 0 && inside(i - 1);
                let right = i + 1 < n && inside(i + 1);
                match (left, right) {
                    (true, true) => (psi[i + 1] - psi[i - 1]) / (x[i + 1] - x[i - 1]),
                    (true, false) => (psi[i] - psi[i - 1]) / (x[i] - x[i - 1]),
                    (false, true) => (psi[i + 1] - psi[i]) / (x[i + 1] - x[i]),
                    (false, false) => 0.0,
                }
            })
            .collect();
        Self { ends, psi, dpsi }
    }

    /// `[integral p, integral (x - centre) p]` over `[lo, hi]` within cell `i` (centre
    /// `centre`, width `width`), zero outside the contact.
    pub(super) fn moments(&self, i: usize, centre: f64, width: f64, lo: f64, hi: f64) -> [f64; 2] {
        let PerEdge {
            left: b1,
            right: b2,
        } = self.ends;
        let (lo, hi) = (lo.max(b1), hi.min(b2));
        if hi <= lo || self.psi[i] == 0.0 {
            return [0.0; 2];
        }
        let (psi, dpsi) = (self.psi[i], self.dpsi[i]);
        let f = |x: f64| {
            let p = ((x - b1) * (b2 - x)).max(0.0).sqrt() * (psi + dpsi * (x - centre));
            [p, p * (x - centre)]
        };
        // Within three cells of an edge, integrate in r = sqrt(distance to that edge), where the
        // integrand is smooth; elsewhere sqrt(u) is smooth over the cell.
        let near = 3.0 * width;
        if b2 - hi < near && b2 - hi <= lo - b1 {
            let (r1, r2) = ((b2 - hi).sqrt(), (b2 - lo).sqrt());
            gauss_legendre(r1, r2, |r| f(b2 - r * r).map(|v| 2.0 * r * v))
        } else if lo - b1 < near {
            let (r1, r2) = ((lo - b1).sqrt(), (hi - b1).sqrt());
            gauss_legendre(r1, r2, |r| f(b1 + r * r).map(|v| 2.0 * r * v))
        } else {
            gauss_legendre(lo, hi, f)
        }
    }
}

/// `[integral R, integral (x - centre) R]` over `[lo, hi]` of the tapered root
/// `R = sqrt(r) g(r/window)`, `r = side (at - x)` (`kernel::Shape::Root`, `g` its taper), which
/// must lie on its side within the window: in the variable `v = sqrt(r)` the integrands are
/// polynomials of degree at most 10, so the 20-point Gauss rule is exact.
pub(super) fn root_moments(
    at: f64,
    side: f64,
    window: f64,
    centre: f64,
    lo: f64,
    hi: f64,
) -> [f64; 2] {
    if hi <= lo {
        return [0.0; 2];
    }
    let (a, b) = ((side * (at - lo)).max(0.0), (side * (at - hi)).max(0.0));
    let (v1, v2) = (a.min(b).sqrt(), a.max(b).sqrt());
    gauss_legendre(v1, v2, |v| {
        let weight = 2.0 * v * v * super::kernel::root_taper(v * v / window);
        [weight, weight * (at - side * v * v - centre)]
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    /// `[integral g, integral (x - c) g]` of `g(x) = sqrt((x + a)(a - x))` over `[lo, hi]`:
    /// the half nearer each edge in the variable `sqrt(distance to that edge)`, 8 panels of
    /// Gauss-Legendre each (a different split from the code under test).
    fn ellipse(a: f64, c: f64, lo: f64, hi: f64) -> [f64; 2] {
        let mid = 0.0f64.clamp(lo, hi);
        let g = |x: f64| {
            let v = ((x + a) * (a - x)).max(0.0).sqrt();
            [v, v * (x - c)]
        };
        let mut sum = [0.0; 2];
        let mut add = |v: [f64; 2]| {
            sum[0] += v[0];
            sum[1] += v[1];
        };
        let panels = |r1: f64, r2: f64, map: &dyn Fn(f64) -> f64, add: &mut dyn FnMut([f64; 2])| {
            for k in 0..8 {
                let (p, q) = (
                    r1 + (r2 - r1) * k as f64 / 8.0,
                    r1 + (r2 - r1) * (k + 1) as f64 / 8.0,
                );
                add(gauss_legendre(p, q, |r| g(map(r)).map(|v| 2.0 * r * v)));
            }
        };
        if lo < mid {
            panels((lo + a).sqrt(), (mid + a).sqrt(), &|r| r * r - a, &mut add);
        }
        if mid < hi {
            panels((a - hi).sqrt(), (a - mid).sqrt(), &|r| a - r * r, &mut add);
        }
        sum
    }

    #[test]
    fn hertz_cell_moments_are_exact() {
        // Hertz: p = p0 sqrt(1 - x^2/a^2) = (p0/a) sqrt(u), psi constant, so the rule should be
        // exact up to rounding: 1e-13 of p0 w against a reference integrated in the root of the
        // distance to each edge, at the edge cells and inside.
        let (a, p0) = (0.76, 836.0);
        let n = 40;
        let w = 2.0 * a / n as f64;
        let x: Vec<f64> = (0..n).map(|i| -a + (i as f64 + 0.5) * w).collect();
        let pressure: Vec<f64> = x
            .iter()
            .map(|x| p0 * ((a - x) * (a + x)).sqrt() / a)
            .collect();
        let shape = PressureShape::new(&x, &pressure, PerEdge { left: -a, right: a });
        for i in [0, 1, 2, 5, 20, 38, 39] {
            let (lo, hi) = (x[i] - 0.5 * w, x[i] + 0.5 * w);
            let [m0, m1] = shape.moments(i, x[i], w, lo, hi);
            let [e0, e1] = ellipse(a, x[i], lo.max(-a), hi.min(a)).map(|v| v * p0 / a);
            assert!((m0 - e0).abs() < 1e-13 * p0 * w, "cell {i}: {m0} vs {e0}");
            assert!(
                (m1 - e1).abs() < 1e-13 * p0 * w * w,
                "cell {i}: {m1} vs {e1}"
            );
        }
    }

    #[test]
    fn root_moments_match_a_graded_rule() {
        // Against the tapered root integrated in x on panels graded towards the root's point.
        for (at, side, window, lo, hi) in [
            (1.0, 1.0, 0.5, 0.6, 0.95),
            (1.0, 1.0, 0.5, 0.9, 1.0),
            (-1.0, -1.0, 2.0, -1.0, -0.2),
        ] {
            let centre = 0.5 * (lo + hi) + 0.01;
            let f = |x: f64| {
                let r: f64 = side * (at - x);
                let v = r.max(0.0).sqrt() * super::super::kernel::root_taper(r / window);
                [v, v * (x - centre)]
            };
            let mut want = [0.0; 2];
            let (near, far) = if side > 0.0 { (hi, lo) } else { (lo, hi) };
            let mut outer = far;
            for _ in 0..44 {
                let inner = near + 0.5 * (outer - near);
                let (p, q) = if inner < outer {
                    (inner, outer)
                } else {
                    (outer, inner)
                };
                let v = gauss_legendre(p, q, f);
                want[0] += v[0];
                want[1] += v[1];
                outer = inner;
            }
            let got = root_moments(at, side, window, centre, lo, hi);
            for k in 0..2 {
                assert!(
                    (got[k] - want[k]).abs() < 1e-12,
                    "{at}: {got:?} vs {want:?}"
                );
            }
        }
    }
}
