//! Clamped cubic spline used to interpolate a tabulated profile g(x), x >= 0.
//!
//! Clamped end slopes come from symmetry (g'(0) = 0) or from a one-sided cubic fit through the four
//! nearest points, so the spline reproduces any cubic exactly; g' is then continuous everywhere
//! inside a segment. The profile splits the table at stated kinks and fits each segment on its own.

/// One spline interval `[x0, x1]` with `g'(x) = slope[0] + slope[1] t + slope[2] t^2`, `t = x - x0`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct SlopeInterval {
    pub x0: f64,
    pub x1: f64,
    pub slope: [f64; 3],
}

/// Derivative at `x[0]` of the Lagrange polynomial through the first (up to) four points.
pub(crate) fn end_slope(x: &[f64], g: &[f64]) -> f64 {
    let n = x.len().min(4);
    let x0 = x[0];
    let mut slope = 0.0;
    for j in 0..n {
        let mut weight = if j == 0 {
            (1..n).map(|m| 1.0 / (x0 - x[m])).sum()
        } else {
            let mut num = 1.0;
            let mut den = 1.0;
            for m in 0..n {
                if m != j {
                    den *= x[j] - x[m];
                    if m != 0 {
                        num *= x0 - x[m];
                    }
                }
            }
            num / den
        };
        if j == 0 && n == 1 {
            weight = 0.0;
        }
        slope += weight * g[j];
    }
    slope
}

/// Clamped cubic spline through `(x, g)` with end slopes `s0`, `s1`; returns its slope intervals.
/// Needs at least two points with strictly increasing x.
pub(crate) fn clamped(x: &[f64], g: &[f64], s0: f64, s1: f64) -> Vec<SlopeInterval> {
    let n = x.len();
    let h: Vec<f64> = x.windows(2).map(|w| w[1] - w[0]).collect();
    let dy: Vec<f64> = (0..n - 1).map(|i| (g[i + 1] - g[i]) / h[i]).collect();
    // Tridiagonal system for the second derivatives M (sub, diag, sup, rhs).
    let mut sub = vec![0.0; n];
    let mut diag = vec![0.0; n];
    let mut sup = vec![0.0; n];
    let mut rhs = vec![0.0; n];
    diag[0] = 2.0 * h[0];
    sup[0] = h[0];
    rhs[0] = 6.0 * (dy[0] - s0);
    for i in 1..n - 1 {
        sub[i] = h[i - 1];
        diag[i] = 2.0 * (h[i - 1] + h[i]);
        sup[i] = h[i];
        rhs[i] = 6.0 * (dy[i] - dy[i - 1]);
    }
    sub[n - 1] = h[n - 2];
    diag[n - 1] = 2.0 * h[n - 2];
    rhs[n - 1] = 6.0 * (s1 - dy[n - 2]);
    // Thomas algorithm: the matrix is diagonally dominant, so no pivoting is needed.
    for i in 1..n {
        let w = sub[i] / diag[i - 1];
        diag[i] -= w * sup[i - 1];
        rhs[i] -= w * rhs[i - 1];
    }
    let mut m = vec![0.0; n];
    m[n - 1] = rhs[n - 1] / diag[n - 1];
    for i in (0..n - 1).rev() {
        m[i] = (rhs[i] - sup[i] * m[i + 1]) / diag[i];
    }
    (0..n - 1)
        .map(|i| {
            let b = dy[i] - h[i] * (2.0 * m[i] + m[i + 1]) / 6.0;
            let c = 0.5 * m[i];
            let d = (m[i + 1] - m[i]) / (6.0 * h[i]);
            SlopeInterval {
                x0: x[i],
                x1: x[i + 1],
                slope: [b, 2.0 * c, 3.0 * d],
            }
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn clamped_spline_with_fitted_ends_reproduces_a_cubic() {
        // g = 1 + 2x - x^2 + 0.5x^3 on an uneven grid: the spline must be exact (to rounding).
        let x = [0.0, 0.3, 0.7, 1.0, 1.6, 2.0];
        let g: Vec<f64> = x
            .iter()
            .map(|x| 1.0 + 2.0 * x - x * x + 0.5 * x * x * x)
            .collect();
        let xr: Vec<f64> = x.iter().rev().copied().collect();
        let gr: Vec<f64> = g.iter().rev().copied().collect();
        let s0 = end_slope(&x, &g);
        let s1 = end_slope(&xr, &gr);
        for iv in clamped(&x, &g, s0, s1) {
            for t in [0.0, 0.25, 0.5, 1.0] {
                let xx = iv.x0 + t * (iv.x1 - iv.x0);
                let u = xx - iv.x0;
                let slope = iv.slope[0] + iv.slope[1] * u + iv.slope[2] * u * u;
                let exact = 2.0 - 2.0 * xx + 1.5 * xx * xx;
                assert!(
                    (slope - exact).abs() < 1e-12,
                    "g'({xx}) = {slope}, exact {exact}"
                );
            }
        }
    }
}
