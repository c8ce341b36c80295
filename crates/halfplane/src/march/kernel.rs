//! The discretised log kernel: the cell matrix `G_ij = -integral_cell_j ln(|xi - x_i|/l) dxi`
//! of piecewise-constant tractions on equal cells collocated at their centres (docs/theory.md,
//! "Time marching": the kernel, scaled by `l = 4L` with L the half-span, is symmetric positive
//! definite Toeplitz on the cells), its first-moment companion for the slope of a cell's
//! traction, and the same integral over the few special elements of a sub-cell stick-slip
//! boundary (a constant on part of a cell, a linear piece, a one-sided square root).
//!
//! Owns every formula for the kernel (the antiderivatives `t ln(|t|/l) - t`,
//! `t^2 ln(|t|/l)/2 - t^2/4`, the square-root one below and the multipole series far from an
//! element); the marcher and every test build the kernel here, never from their own copy. Never
//! solves a system and never knows about stick, slip or loads.

use crate::quadrature::gauss_legendre;

/// `F(t) = t ln(|t|/l) - t`, the antiderivative of `ln(|t|/l)` (with `F(0) = 0`, its limit).
fn log_antiderivative(t: f64, scale: f64) -> f64 {
    if t == 0.0 {
        0.0
    } else {
        t * (t.abs() / scale).ln() - t
    }
}

/// `F1(t) = t^2 ln(|t|/l)/2 - t^2/4`, the antiderivative of `t ln(|t|/l)` (0 at t = 0).
fn moment_antiderivative(t: f64, scale: f64) -> f64 {
    if t == 0.0 {
        0.0
    } else {
        0.5 * t * t * (t.abs() / scale).ln() - 0.25 * t * t
    }
}

/// The first row of the cell matrix for `n` cells of width `width`, lengths in the logarithm
/// scaled by `scale` (`l`): `G_k = -(F((k + 1/2) w) - F((k - 1/2) w))`, the integral of
/// `-ln(|t|/l)` over the cell whose centre is k cells away. The matrix is `G_ij = G_|i-j|`.
pub(super) fn cell_row(n: usize, width: f64, scale: f64) -> Vec<f64> {
    (0..n)
        .map(|k| {
            let k = k as f64;
            -(log_antiderivative((k + 0.5) * width, scale)
                - log_antiderivative((k - 0.5) * width, scale))
        })
        .collect()
}

/// A lower bound on the smallest eigenvalue of the cell matrix of [`cell_row`]: `(4 C/pi) w`,
/// C Catalan's constant, about `1.16624 w`, at the cell-to-cell (zigzag) mode `(-1)^i`. That is
/// the cell-averaged log kernel's symbol at the frequency pi: `-ln|t|` transforms to `pi/|omega|`,
/// averaging over a cell multiplies by `sin(omega/2)/(omega/2)`, and sampling at the centres sums
/// over `omega = pi (2m + 1)`, giving `(2/pi) sum_m (-1)^m / ((2m + 1)|2m + 1|) = (4/pi) C`
/// (derived here); the part `w ln(l/w)` common to every entry only adds a multiple of the all-ones
/// matrix, positive semi-definite since l exceeds the grid. The eigenvalues approach it from above
/// as the cells grow (checked by Cholesky factorisations from 16 to 400 cells in the tests below).
/// Independent of `l`. Principal submatrices (any set of cells) have eigenvalues at least this.
pub(crate) fn smallest_eigenvalue_bound(width: f64) -> f64 {
    /// Catalan's constant, `sum_n (-1)^n / (2n + 1)^2`.
    const CATALAN: f64 = 0.915_965_594_177_219;
    4.0 * CATALAN / std::f64::consts::PI * width
}

/// The first column of the slope matrix: `g_k = -integral_{-w/2}^{w/2} t ln(|t - k w|/l) dt`,
/// the displacement kernel at a centre k cells to the right of a cell carrying the traction
/// `t = xi - x_j` (unit slope, zero mean). The matrix is `S_ij = g_(i-j)` with `g_(-k) = -g_k`
/// (odd), so `S` is Toeplitz and skew. `l` drops out (the traction has zero mean).
///
/// Beyond eight cells the antiderivatives cancel to `eps k^3`, so the series
/// `g_k = sum_(m odd) 2 h^(m+2) / (m (m+2) (k w)^m)`, `h = w/2` (from
/// `ln(k w - t) = ln(k w) - sum_m (t/(k w))^m/m`), is used there; its terms fall by `1/(4k)^2`.
pub(super) fn slope_column(n: usize, width: f64) -> Vec<f64> {
    let h = 0.5 * width;
    (0..n)
        .map(|k| {
            if k == 0 {
                return 0.0;
            }
            let d = k as f64 * width;
            if k < 8 {
                // -[F1(u) + d F(u)] over u = t - d from -h - d to h - d (scale 1: l drops out).
                let f = |u: f64| moment_antiderivative(u, 1.0) + d * log_antiderivative(u, 1.0);
                -(f(h - d) - f(-h - d))
            } else {
                let ratio = (h / d) * (h / d);
                let (mut term, mut sum, mut m) = (h * h * h / d, 0.0f64, 1.0);
                while term > 1e-18 * sum.max(f64::MIN_POSITIVE) {
                    sum += 2.0 * term / (m * (m + 2.0));
                    term *= ratio;
                    m += 2.0;
                }
                sum
            }
        })
        .collect()
}

/// `[-integral ln(|xi - y|/l), -integral (xi - x_c) ln(|xi - y|/l)]` over the cell of centre
/// `x_c` and half-width `h`, at `d = y - x_c`: the kernels of a cell's mean and slope at any
/// point. Antiderivatives within eight half-widths; beyond, where they cancel, the series
/// `-2h ln(|d|/l) + sum_(m even) 2 h^(m+1)/(m (m+1) d^m)` and
/// `sum_(m odd) 2 h^(m+2)/(m (m+2) d^m)` (from `ln|d - t| = ln|d| - sum_m (t/d)^m/m`).
pub(super) fn cell_kernels(d: f64, h: f64, scale: f64) -> [f64; 2] {
    if d.abs() < 8.0 * h {
        let g0 = -(log_antiderivative(h - d, scale) - log_antiderivative(-h - d, scale));
        let f = |u: f64| moment_antiderivative(u, 1.0) + d * log_antiderivative(u, 1.0);
        return [g0, -(f(h - d) - f(-h - d))];
    }
    let ratio = (h / d) * (h / d);
    let mut g0 = -2.0 * h * (d.abs() / scale).ln();
    let mut g1 = 0.0;
    // Even m for g0 (from 2), odd m for g1 (from 1): p = h^(m+1)/d^m.
    let mut p_odd = h * h / d;
    let mut p_even = h * h * h / (d * d);
    let mut m = 1.0;
    while m < 60.0 {
        let t1 = 2.0 * h * p_odd / (m * (m + 2.0));
        let t0 = 2.0 * p_even / ((m + 1.0) * (m + 2.0));
        g1 += t1;
        g0 += t0;
        if t1.abs() <= 1e-17 * g1.abs() && t0.abs() <= 1e-17 * g0.abs() {
            break;
        }
        p_odd *= ratio;
        p_even *= ratio;
        m += 2.0;
    }
    [g0, g1]
}

/// The full symmetric Toeplitz matrix of `row`, row-major N x N (for the dense solver).
pub(super) fn dense_matrix(row: &[f64]) -> Vec<f64> {
    let n = row.len();
    let mut m = vec![0.0; n * n];
    for i in 0..n {
        for j in 0..n {
            m[i * n + j] = row[i.abs_diff(j)];
        }
    }
    m
}

/// How a traction varies over an element.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(super) enum Shape {
    /// `value + slope (xi - centre)`.
    Affine { centre: f64, value: f64, slope: f64 },
    /// `sqrt(r) g(r/window)` with `r = side (at - xi)` and the taper [`root_taper`], zero where
    /// r < 0 or r > window: the square root of a stick-slip boundary at `at` whose stick side is
    /// to the left (`side = 1`) or to the right (`-1`), tapered to zero with zero slope at
    /// `window` from it.
    Root { at: f64, side: f64, window: f64 },
}

/// The square root's taper `g(t) = 1 - 3 t^2 + 2 t^3`: 1 at the boundary, zero with zero slope
/// at the window's end, and flat at the boundary, so that the tapered root has no `r^(3/2)` term
/// of its own. The traction's own `r^(3/2)` term at a boundary is small (for Cattaneo-Mindlin
/// `sqrt(c - x) sqrt(c + x)`, `-1/(4c)` relative); with the earlier taper `(1 - t)^2` the root
/// carried `-2/window` relative, with the window half the zone `-2/c`, which the boundary
/// element, a constant and a fixed ramp, cannot take out: its error grew as the stick zone
/// shrank (docs/convergence.md, "Sub-cell stick-slip boundaries").
pub(super) fn root_taper(t: f64) -> f64 {
    1.0 - t * t * (3.0 - 2.0 * t)
}

/// Multipole terms kept far from an element (its moments about the midpoint, orders 0..TERMS-1).
const TERMS: usize = 16;

/// A traction shape on `[lo, hi]` with its moments, for the kernel at any point.
#[derive(Debug, Clone, PartialEq)]
pub(super) struct Element {
    lo: f64,
    hi: f64,
    shape: Shape,
    /// `integral shape(xi) (xi - mid)^m dxi`, m = 0..TERMS-1.
    moments: [f64; TERMS],
}

impl Element {
    /// `shape` on `[lo, hi]` (`lo <= hi`; a `Root` element must lie on its nonzero side).
    pub(super) fn new(lo: f64, hi: f64, shape: Shape) -> Self {
        let mid = 0.5 * (lo + hi);
        let h = 0.5 * (hi - lo);
        let mut moments = [0.0; TERMS];
        // Moments of 1 about the midpoint: 2 h^(m+1)/(m+1) for even m.
        let plain = |m: usize| {
            if m.is_multiple_of(2) {
                2.0 * h.powi(m as i32 + 1) / (m as f64 + 1.0)
            } else {
                0.0
            }
        };
        match shape {
            Shape::Affine {
                centre,
                value,
                slope,
            } => {
                let at_mid = value + slope * (mid - centre);
                for (m, v) in moments.iter_mut().enumerate() {
                    *v = at_mid * plain(m) + slope * plain(m + 1);
                }
            }
            Shape::Root { at, side, window } => {
                // xi = at - side v^2, the root v g(v^2/window), dxi = 2 v dv (orientation
                // absorbed): the moments are polynomials of degree 2m + 8 in v, exact with 20
                // Gauss points (m <= 15).
                let (v1, v2) = root_range(lo, hi, at, side);
                moments = gauss_legendre(v1, v2, |v| {
                    let d = at - side * v * v - mid;
                    let mut out = [0.0; TERMS];
                    let mut p = 2.0 * v * v * root_taper(v * v / window);
                    for o in out.iter_mut() {
                        *o = p;
                        p *= d;
                    }
                    out
                });
            }
        }
        Self {
            lo,
            hi,
            shape,
            moments,
        }
    }

    /// Where the element is: `[lo, hi]`.
    pub(super) fn range(&self) -> [f64; 2] {
        [self.lo, self.hi]
    }

    /// The same shape on `[lo, hi]`, inside this element's range.
    pub(super) fn clipped(&self, lo: f64, hi: f64) -> Self {
        Self::new(lo, hi, self.shape)
    }

    /// `integral shape (xi - about)^k dxi` over the element, k = 0 or 1.
    pub(super) fn moment(&self, k: usize, about: f64) -> f64 {
        let mid = 0.5 * (self.lo + self.hi);
        match k {
            0 => self.moments[0],
            _ => self.moments[1] + (mid - about) * self.moments[0],
        }
    }

    /// The shape's value at `x` (zero outside the element).
    pub(super) fn value(&self, x: f64) -> f64 {
        if x < self.lo || x > self.hi {
            return 0.0;
        }
        match self.shape {
            Shape::Affine {
                centre,
                value,
                slope,
            } => value + slope * (x - centre),
            Shape::Root { at, side, window } => {
                let r = side * (at - x);
                if r < 0.0 || r > window {
                    0.0
                } else {
                    r.sqrt() * root_taper(r / window)
                }
            }
        }
    }

    /// `-integral_lo^hi shape(xi) ln(|xi - x|/l) dxi`: the displacement kernel at `x`.
    ///
    /// Closed forms near the element; from eight half-lengths away, where they cancel, the
    /// multipole series `-M_0 ln(|x - mid|/l) + sum_m M_m / (m (x - mid)^m)` (TERMS terms, each
    /// at most 1/8 of the one before).
    pub(super) fn kernel(&self, x: f64, scale: f64) -> f64 {
        let (lo, hi) = (self.lo, self.hi);
        if hi <= lo {
            return 0.0;
        }
        let mid = 0.5 * (lo + hi);
        let r = x - mid;
        if r.abs() > 8.0 * 0.5 * (hi - lo) {
            let mut sum = -self.moments[0] * (r.abs() / scale).ln();
            let mut p = r;
            for (m, mm) in self.moments.iter().enumerate().skip(1) {
                sum += mm / (m as f64 * p);
                p *= r;
            }
            return sum;
        }
        match self.shape {
            Shape::Affine {
                centre,
                value,
                slope,
            } => {
                // value + slope (xi - centre) = (value + slope (x - centre)) + slope u, u = xi - x.
                let at_x = value + slope * (x - centre);
                let f = |u: f64| {
                    at_x * log_antiderivative(u, scale) + slope * moment_antiderivative(u, scale)
                };
                -(f(hi - x) - f(lo - x))
            }
            Shape::Root { at, side, window } => {
                // sqrt(r) g(r/L) = r^(1/2) - 3 r^(5/2)/L^2 + 2 r^(7/2)/L^3.
                let (v1, v2) = root_range(lo, hi, at, side);
                let d = side * (at - x);
                let c = [1.0, 0.0, -3.0 / (window * window), 2.0 / window.powi(3)];
                -(0..4)
                    .filter(|&k| c[k] != 0.0)
                    .map(|k| {
                        c[k] * (root_antiderivative(v2, d, scale, k)
                            - root_antiderivative(v1, d, scale, k))
                    })
                    .sum::<f64>()
            }
        }
    }
}

/// The range `[v1, v2]` of `v = sqrt(side (at - xi))` over `[lo, hi]` (v1 at the end nearer `at`).
fn root_range(lo: f64, hi: f64, at: f64, side: f64) -> (f64, f64) {
    let (a, b) = ((side * (at - lo)).max(0.0), (side * (at - hi)).max(0.0));
    (a.min(b).sqrt(), a.max(b).sqrt())
}

/// `H_k(v) = integral 2 v^(2k+2) ln(|d - v^2|/l) dv` (so that the integral of
/// `r^(k+1/2) ln(|d - r|/l)` over r from `v1^2` to `v2^2` is `H_k(v2) - H_k(v1)`): by parts,
/// `H_k = 2 v^(2k+3)/(2k+3) ln(|d - v^2|/l) + 4/(2k+3) J_(k+2)(v)` with
/// `J_m = integral v^(2m)/(d - v^2) dv = -sum_(j<m) d^j v^(2m-2j-1)/(2m-2j-1) + d^m L(v)`,
/// `L = integral dv/(d - v^2)`. For `d > 0` the logarithms are combined so that `v = sqrt(d)` is
/// regular; for `|d| > 8 v^2`, where the closed form cancels, `J_m` is its series
/// `sum_(i>=0) v^(2m+2i+1)/((2m+2i+1) d^(i+1))`.
fn root_antiderivative(v: f64, d: f64, scale: f64, k: usize) -> f64 {
    let v2 = v * v;
    let p = 2 * k + 3;
    let vp = v.powi(p as i32);
    let m = k + 2;
    let over = 1.0 / p as f64;
    if d.abs() > 8.0 * v2 {
        let ratio = v2 / d;
        let (mut term, mut sum, mut q) = (v.powi(2 * m as i32 + 1) / d, 0.0f64, (2 * m + 1) as f64);
        while term.abs() > 1e-18 * sum.abs().max(f64::MIN_POSITIVE) {
            sum += term / q;
            term *= ratio;
            q += 2.0;
        }
        return 2.0 * over * vp * ((d - v2).abs() / scale).ln() + 4.0 * over * sum;
    }
    // The polynomial part of J_m.
    let poly: f64 = (0..m)
        .map(|j| {
            let e = 2 * (m - j) - 1;
            d.powi(j as i32) * v.powi(e as i32) / e as f64
        })
        .sum();
    if d > 0.0 {
        let s = d.sqrt();
        let sp = s.powi(p as i32);
        let far = 2.0 * over * (vp + sp) * (s + v).ln();
        let near = if v == s {
            0.0
        } else {
            2.0 * over * (vp - sp) * (s - v).abs().ln()
        };
        far + near - 2.0 * over * vp * scale.ln() - 4.0 * over * poly
    } else if d < 0.0 {
        // L = -atan(v/s)/s with s = sqrt(-d).
        let s = (-d).sqrt();
        2.0 * over * vp * ((v2 - d) / scale).ln()
            + 4.0 * over * (-d.powi(m as i32) * (v / s).atan() / s - poly)
    } else if v == 0.0 {
        0.0
    } else {
        2.0 * over * vp * (v2 / scale).ln() - 4.0 * over * poly
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Whether `G - shift I` is positive definite: the dense route's Cholesky factorisation
    /// (`solve.rs`) succeeds on it.
    fn positive_definite_after(row: &[f64], shift: f64) -> bool {
        let n = row.len();
        let g: Vec<f64> = (0..n * n)
            .map(|k| row[(k / n).abs_diff(k % n)] - if k / n == k % n { shift } else { 0.0 })
            .collect();
        let mut z = vec![0.0; n];
        super::super::solve::dense_stick_solve(&g, &vec![true; n], &vec![1.0; n], &mut z, 0).is_ok()
    }

    #[test]
    fn the_smallest_eigenvalue_is_the_zigzag_modes_catalan_bound() {
        // On grids with the marcher's scale (twice the grid's length): G minus the bound (less
        // 1e-9 of it, for rounding) factorises, so every eigenvalue exceeds it, and G minus the
        // bound plus a margin does not, so the smallest is within that margin: 3e-4 at 100 cells
        // and 2e-5 at 400 (numpy's eigvalsh puts them 2.0e-4 and 1.2e-5 above).
        for (n, margin) in [(16, 1e-2), (100, 3e-4), (400, 2e-5)] {
            let w = 0.01;
            let row = cell_row(n, w, 2.0 * n as f64 * w);
            let bound = smallest_eigenvalue_bound(w);
            assert!(
                positive_definite_after(&row, bound * (1.0 - 1e-9)),
                "{n} cells: an eigenvalue below the Catalan bound {bound}"
            );
            assert!(
                !positive_definite_after(&row, bound * (1.0 + margin)),
                "{n} cells: the smallest eigenvalue is more than {margin} above the bound {bound}"
            );
        }
    }

    /// `integral_lo^hi g` by Gauss-Legendre on panels graded geometrically towards both ends
    /// (44 halvings), which resolves log and square-root end singularities: the independent
    /// reference of these tests.
    fn graded(lo: f64, hi: f64, g: &dyn Fn(f64) -> f64) -> f64 {
        let mid = 0.5 * (lo + hi);
        let mut sum = 0.0;
        for (end, towards) in [(lo, mid), (hi, mid)] {
            let mut outer = towards;
            for _ in 0..44 {
                let inner = end + 0.5 * (outer - end);
                let (p, q) = (inner.min(outer), inner.max(outer));
                sum += gauss_legendre(p, q, |t| [g(t)])[0];
                outer = inner;
            }
        }
        sum
    }

    /// `-integral_lo^hi f(xi) ln(|xi - x|/l) dxi` by [`graded`] panels between the singular points.
    fn brute(lo: f64, hi: f64, x: f64, scale: f64, f: impl Fn(f64) -> f64, breaks: &[f64]) -> f64 {
        let mut points = vec![lo, hi];
        points.extend(breaks.iter().copied().filter(|b| *b > lo && *b < hi));
        points.sort_by(f64::total_cmp);
        points
            .windows(2)
            .map(|w| graded(w[0], w[1], &|t| -f(t) * ((t - x).abs() / scale).ln()))
            .sum()
    }

    #[test]
    fn element_kernels_match_quadrature_near_and_far() {
        // Closed forms and multipole series against graded quadrature, at points inside, at the
        // ends, just outside and far away; 1e-12 of the kernel's scale (the quadrature resolves
        // the log and square-root end singularities to ~1e-14).
        let scale = 4.0;
        let (lo, hi) = (0.2, 0.45);
        let cases = [
            (
                Shape::Affine {
                    centre: 0.3,
                    value: 1.0,
                    slope: 0.0,
                },
                None,
            ),
            (
                Shape::Affine {
                    centre: 0.3,
                    value: 0.7,
                    slope: -2.0,
                },
                None,
            ),
            (
                Shape::Root {
                    at: 0.45,
                    side: 1.0,
                    window: 0.3,
                },
                Some(0.45),
            ),
            (
                Shape::Root {
                    at: 0.2,
                    side: -1.0,
                    window: 1.0,
                },
                Some(0.2),
            ),
            (
                Shape::Root {
                    at: 0.6,
                    side: 1.0,
                    window: 0.45,
                },
                Some(0.6),
            ),
        ];
        for (shape, at) in cases {
            let e = Element::new(lo, hi, shape);
            for x in [0.3, 0.2, 0.45, 0.47, 0.61, -0.1, 1.3, 3.0, -2.7, 0.05] {
                let mut breaks = vec![x];
                breaks.extend(at);
                let exact = brute(lo, hi, x, scale, |t| e.value(t), &breaks);
                let got = e.kernel(x, scale);
                assert!(
                    (got - exact).abs() < 1e-12,
                    "{shape:?} at x = {x}: {got} vs {exact}"
                );
            }
            // The moments against the same quadrature.
            for (k, about) in [(0, 0.3), (1, 0.3), (1, 0.0)] {
                let m = graded(lo, hi, &|t| e.value(t) * (t - about).powi(k as i32));
                assert!(
                    (e.moment(k, about) - m).abs() < 1e-13,
                    "{shape:?} moment {k}"
                );
            }
        }
    }

    #[test]
    fn slope_column_matches_its_definition_and_the_linear_element() {
        // The series beyond eight cells and the antiderivatives before agree with the linear
        // element's kernel (independent code path near, series far) to 1e-15 of w^2.
        let (w, n) = (0.01, 40);
        let g = slope_column(n, w);
        let e = Element::new(
            -0.5 * w,
            0.5 * w,
            Shape::Affine {
                centre: 0.0,
                value: 0.0,
                slope: 1.0,
            },
        );
        let one = Element::new(
            -0.5 * w,
            0.5 * w,
            Shape::Affine {
                centre: 0.0,
                value: 1.0,
                slope: 0.0,
            },
        );
        for (k, gk) in g.iter().enumerate() {
            let reference = e.kernel(k as f64 * w, 7.0);
            assert!(
                (gk - reference).abs() <= 1e-12 * reference.abs(),
                "k = {k}: {gk} vs {reference}"
            );
            // cell_kernels at integer and half-integer distances, both signs.
            for d in [k as f64 * w, (k as f64 + 0.37) * w, -(k as f64 + 0.37) * w] {
                let [g0, g1] = cell_kernels(d, 0.5 * w, 7.0);
                let (r0, r1) = (one.kernel(d, 7.0), e.kernel(d, 7.0));
                assert!(
                    (g0 - r0).abs() <= 1e-14 * r0.abs(),
                    "g0 at {d}: {g0} vs {r0}"
                );
                assert!(
                    (g1 - r1).abs() <= 1e-11 * r1.abs() + 1e-20,
                    "g1 at {d}: {g1} vs {r1}"
                );
            }
        }
        // Far field: w^2/(12 k) to leading order.
        assert!((g[39] / (w * w / (12.0 * 39.0)) - 1.0).abs() < 1e-3);
    }
}
