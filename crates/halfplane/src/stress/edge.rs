//! Square-root edge elements: the first and last intervals of a contact's traction, where the
//! pressure (and the traction of a slip zone, `f p`) vanish like the square root of the distance to
//! the edge (`docs/stress.md`, "Edges"). Linear interpolation there would make the surface stress
//! at the edge wrong by O(sqrt(h)), 2% of `f p0` at 1600 cells, exactly where fretting cracks start.
//!
//! The traction holds such an interval as its linear interpolant (node form, `strip.rs`) plus the
//! correction `v [sqrt(t/h) - t/h]` (t the distance from the edge, h the interval, v the value at
//! its inner node), which vanishes at both ends. For a left edge at `s0`, with
//! `omega = (zeta - s0)/h`, its Cauchy integral `integral delta(xi)/(zeta - xi) dxi` is
//! `v [-1 + 2 omega g - omega (log omega - log(omega - 1))]` and its derivative in zeta
//! `(v/h)[g - log omega + log(omega - 1)]`, where `g = atanh(1/sqrt(omega))/sqrt(omega)
//! = integral_0^1 du/(omega - u^2)` (substitute t = h u^2). Principal logarithms and square root
//! of arguments with a non-negative imaginary part give the limit from the body on the surface. A
//! right edge is the mirror image: `F(zeta) = -conj(F~(-conj(zeta)))` with `F~` the left-edge form.

use num_complex::Complex64;

/// A square-root correction over `[edge, edge + length]`: the interval next to a contact edge,
/// or the intervals (one or several) on the stick side of a located stick-slip boundary
/// (`Traction::from_march_ends`).
#[derive(Debug, Clone, Copy, PartialEq)]
pub(super) struct SqrtEdge {
    /// Where the square root starts: a contact edge, where the tractions vanish, or a
    /// stick-slip boundary.
    pub edge: f64,
    /// The span's length, away from `edge` (positive: towards +x).
    pub length: f64,
    /// `[p, q]` of the square root at the span's far end: at a contact edge, the inner node's
    /// values; at a boundary, `amplitude sqrt(|length|)` in q.
    pub value: [f64; 2],
}

impl SqrtEdge {
    /// The correction `[p, q]` at `x` (zero outside the interval).
    pub fn at(&self, x: f64) -> [f64; 2] {
        let t = (x - self.edge) / self.length;
        if !(0.0..=1.0).contains(&t) {
            return [0.0; 2];
        }
        let shape = t.sqrt() - t;
        [self.value[0] * shape, self.value[1] * shape]
    }

    /// The correction's Cauchy integral `F` and (off the surface) its derivative `F'` at
    /// `(x, z)`, per unit value: multiply by `value[c]`.
    pub fn cauchy(&self, x: f64, z: f64) -> ([f64; 2], [f64; 2]) {
        let h = self.length.abs();
        // A point less than 1e-40 h deep takes the surface's limit: the correction's F and z F'
        // differ from it by O(sqrt(z/h)) (at the edge), below 1e-20 of the value, while `omega`'s
        // imaginary part z/h would be lost in its square root (z = 5e-324 gave NaN through
        // ln 0 at the inner node, found by the fuzz target `stress_points`).
        let (z, surface) = if z < 1e-40 * h {
            (0.0, true)
        } else {
            (z, z == 0.0)
        };
        if self.length > 0.0 {
            let (f, d) = left(Complex64::new((x - self.edge) / h, z / h), surface);
            ([f.re, f.im], [d.re / h, d.im / h])
        } else {
            // Mirror: F(zeta) = -conj(F~(-conj(zeta))), F'(zeta) = conj(F~'(-conj(zeta))).
            let (f, d) = left(Complex64::new((self.edge - x) / h, z / h), surface);
            ([-f.re, f.im], [d.re / h, -d.im / h])
        }
    }
}

/// `(F, h F')` of the left-edge correction with unit value at `omega` (see the module's formula).
fn left(omega: Complex64, surface: bool) -> (Complex64, Complex64) {
    let one = Complex64::new(1.0, 0.0);
    if surface && omega.re == 0.0 {
        return (Complex64::new(-1.0, 0.0), Complex64::new(0.0, 0.0));
    }
    if surface && omega.re == 1.0 {
        // The limits of the cancelling logarithms at the inner node: -1 + 2 ln 2.
        return (
            Complex64::new(-1.0 + 2.0 * std::f64::consts::LN_2, 0.0),
            Complex64::new(0.0, 0.0),
        );
    }
    let s = omega.sqrt();
    let g = ((s + one).ln() - (s - one).ln()).scale(0.5) / s;
    let logs = omega.ln() - (omega - one).ln();
    let f = Complex64::new(-1.0, 0.0) + (omega * g).scale(2.0) - omega * logs;
    let d = if surface {
        Complex64::new(0.0, 0.0)
    } else {
        g - logs
    };
    (f, d)
}
