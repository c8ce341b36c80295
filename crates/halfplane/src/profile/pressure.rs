//! The pressure kernel of piecewise-polynomial slopes in closed form, and the logarithmic term
//! `integral dt/(a cos t - x)` that every pressure route adds where it subtracts a continued slope.

use super::pieces::angle_between;
use super::{Profile, Slope};

/// The antiderivative `L(t) = integral dt/(a cos t - x) = ln|(k + u)/(k - u)|/sqrt(a^2 - x^2)` at
/// `u = tan(t/2)`, with `k = sqrt((a - x)/(a + x))` and `root = sqrt(a^2 - x^2)` for `|x| < a`
/// (the half-angle substitution `u = tan(t/2)` makes the integrand rational). Both pressure
/// routes multiply differences of it by the jump between a piece's continued slope formula and
/// g'(x). Callers pass `k` and `root` as they computed them, so each keeps its own rounding.
pub(crate) fn pressure_log_term(k: f64, u: f64, root: f64) -> f64 {
    ((k + u) / (k - u)).abs().ln() / root
}

impl Profile {
    /// For piecewise-polynomial slopes, the regular part of the pressure integral in closed form,
    /// for the contact `[centre - a, centre + a]` and `xi = centre + a cos t`:
    /// `integral_0^pi (g'(xi) - g'(x))/(xi - x) dt` (see [`crate::Contact::pressure`]; the
    /// symmetric contact has `centre = 0`, and the same kernel serves any centre, Johnson, Contact
    /// Mechanics, eq. 2.25a inverted for a pressure bounded at both ends).
    /// On a piece with `g' = q0 + q1 u + q2 u^2`, `u = xi - o`, the divided difference by the
    /// piece's own formula continued to x is `q1 + q2 (x + centre - 2 o) + q2 a cos t`, integrated
    /// by the moments `M0 = dt`, `M1 = d(sin t)`; the remainder `(c - g'(x))` multiplies
    /// `integral dt/(a cos t - s) = ln|(k + tan(t/2))/(k - tan(t/2))|/sqrt(a^2 - s^2)`,
    /// `k = sqrt((a - s)/(a + s))`, `s = x - centre`. `None` for the power law.
    pub(crate) fn pressure_integral(&self, centre: f64, a: f64, x: f64) -> Option<f64> {
        let Slope::Pieces(p) = &self.slope else {
            return None;
        };
        let gx = p.slope(x);
        let s = x - centre;
        let root = ((a - s) * (a + s)).sqrt();
        let k = ((a - s) / (a + s)).sqrt();
        let log_kernel = |c: f64, s: f64| {
            // tan(t/2) = s/(1 + c); at t = pi the kernel is 0.
            if c <= -1.0 {
                0.0
            } else {
                pressure_log_term(k, s / (1.0 + c), root)
            }
        };
        let angle = |xi: f64| {
            let t = xi - centre;
            let c = (t / a).clamp(-1.0, 1.0);
            (c, ((a - t).max(0.0) * (a + t).max(0.0)).sqrt() / a)
        };
        let (lo, hi) = (centre - a, centre + a);
        let first = p.pieces.partition_point(|q| q.end <= lo);
        let mut sum = 0.0;
        let (mut cb, mut sb) = (-1.0, 0.0);
        for q in &p.pieces[first..] {
            if q.start >= hi {
                break;
            }
            let (ca, sa) = if q.end >= hi {
                (1.0, 0.0)
            } else {
                angle(q.end)
            };
            let m0 = angle_between(ca, sa, cb, sb);
            let m1 = sb - sa;
            let [_, q1, q2] = q.coeffs;
            sum += (q1 + q2 * (x + centre - 2.0 * q.origin)) * m0 + q2 * a * m1;
            let continued = q.eval(x);
            if !(q.start <= x && x <= q.end) && continued != gx {
                // Within rounding of the piece's end, x's angle equals the end's and the log is
                // infinite: the term's limit there is 0 (g' continuous: (x - end) ln|x - end|),
                // or the pressure is singular anyway (a jump of g', where x on the kink itself
                // takes no such term either).
                let term = (continued - gx) * (log_kernel(cb, sb) - log_kernel(ca, sa));
                if term.is_finite() {
                    sum += term;
                }
            }
            (cb, sb) = (ca, sa);
        }
        Some(sum)
    }
}
