//! The discretised log kernel: the cell matrix `G_ij = -integral_cell_j ln(|xi - x_i|/l) dxi`
//! of piecewise-constant tractions on equal cells collocated at their centres (docs/theory.md,
//! "Time marching": the kernel, scaled by `l = 4L` with L the half-span, is symmetric positive
//! definite Toeplitz on the cells).
//!
//! Owns the one formula for the kernel (the antiderivative `t ln(|t|/l) - t`), its first row and
//! its dense N x N form; the marcher and every test build the kernel here, never from their own
//! copy. Never solves a system and never knows about stick, slip or loads.

/// `F(t) = t ln(|t|/l) - t`, the antiderivative of `ln(|t|/l)` (with `F(0) = 0`, its limit).
fn log_antiderivative(t: f64, scale: f64) -> f64 {
    if t == 0.0 {
        0.0
    } else {
        t * (t.abs() / scale).ln() - t
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
