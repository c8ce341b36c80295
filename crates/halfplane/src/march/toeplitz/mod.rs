//! Symmetric positive definite Toeplitz matrices: products by FFT and exact inverses of their
//! leading blocks.
//!
//! On a uniform grid the discretised log kernel is symmetric Toeplitz, so every contiguous run of
//! n cells sees the same matrix `T_n` (its leading n x n block), wherever the run lies. `T_n^{-1}`
//! has the Gohberg-Semencul form (Gohberg & Semencul 1972; Golub & Van Loan, Matrix
//! Computations, 4th ed., section 4.7)
//!
//! `T_n^{-1} = (1/x_0) [L(x) L(x)^T - L(y) L(y)^T]`, with `x = T_n^{-1} e_0`, `y = Z J x`,
//!
//! where `L(v)` is the lower-triangular Toeplitz matrix with first column v, J reverses and Z
//! shifts down. So a solve costs a few FFTs once x is known. x comes either from a cached
//! generator of a nearby order, by Levinson steps (O(n) each, the reflection coefficient computed
//! from x itself), or, when no cached order is near, by conjugate gradients preconditioned by
//! T. Chan's optimal circulant (T. Chan 1988; R. Chan & Ng, SIAM Review 38 (1996) 427, section 2),
//! O(n log n) per iteration; no step costs O(n^2) beyond the short runs formed directly.
//!
//! Owns the Toeplitz algebra and its generator cache (the generators are made in
//! `generators.rs`). Never knows what the matrix means (the
//! kernel is `kernel.rs`'s) nor which cells stick (`solve.rs` chooses the runs).

use crate::error::{Error, Result};
use realfft::num_complex::Complex;
use realfft::{ComplexToReal, RealFftPlanner, RealToComplex};
use std::sync::Arc;

mod generators;
#[cfg(test)]
use generators::step_down;
use generators::step_up;

/// Below this size the Gohberg-Semencul products are formed directly (O(n^2) beats the FFTs).
const DIRECT_BELOW: usize = 48;
/// Generators kept for reuse (stick runs change length by a few cells per increment).
const CACHE: usize = 12;
/// Below this order a generator with no cached neighbour is built by Levinson from order 1.
const CG_FROM: usize = 256;

/// The FFT length for a circulant embedding of at least `min` points: the smallest even number
/// at or above it with no prime factor beyond 5, which rustfft transforms about as fast per
/// point as a power of two (400 cells: 800 points instead of 1024).
fn fft_size(min: usize) -> usize {
    let smooth = |mut m: usize| {
        for p in [2, 3, 5] {
            while m.is_multiple_of(p) {
                m /= p;
            }
        }
        m == 1
    };
    (min.max(2)..)
        .find(|m| m.is_multiple_of(2) && smooth(*m))
        .unwrap_or(min.next_power_of_two())
}

/// Real FFTs of one size with their work buffers.
struct Fft {
    m: usize,
    forward: Arc<dyn RealToComplex<f64>>,
    inverse: Arc<dyn ComplexToReal<f64>>,
    real: Vec<f64>,
    scratch: Vec<Complex<f64>>,
}

impl Fft {
    fn new(planner: &mut RealFftPlanner<f64>, m: usize) -> Self {
        let forward = planner.plan_fft_forward(m);
        let inverse = planner.plan_fft_inverse(m);
        let len = forward.get_scratch_len().max(inverse.get_scratch_len());
        Self {
            m,
            forward,
            inverse,
            real: vec![0.0; m],
            scratch: vec![Complex::default(); len],
        }
    }

    /// Spectrum of `v` zero-padded to m.
    fn spectrum(&mut self, v: &[f64], out: &mut [Complex<f64>]) {
        self.real[..v.len()].copy_from_slice(v);
        self.real[v.len()..].fill(0.0);
        self.forward
            .process_with_scratch(&mut self.real, out, &mut self.scratch)
            .expect("FFT sizes are consistent");
    }

    /// First `out.len()` samples of the inverse transform of `spec` (consumed), scaled by 1/m.
    fn invert(&mut self, spec: &mut [Complex<f64>], out: &mut [f64]) {
        // A real signal's spectrum has real DC and Nyquist terms; rounding may leave a trace.
        spec[0].im = 0.0;
        if self.m.is_multiple_of(2) {
            spec[self.m / 2].im = 0.0;
        }
        self.inverse
            .process_with_scratch(spec, &mut self.real, &mut self.scratch)
            .expect("FFT sizes are consistent");
        let scale = 1.0 / self.m as f64;
        for (o, r) in out.iter_mut().zip(&self.real) {
            *o = r * scale;
        }
    }
}

/// An FFT plan with the spectra of a generator's x and y.
type Spectra = (Fft, Vec<Complex<f64>>, Vec<Complex<f64>>);

/// `T_n^{-1}` for one n.
struct Generator {
    n: usize,
    x: Vec<f64>,
    x0: f64,
    /// For n >= DIRECT_BELOW: spectra of x and y zero-padded to the FFT size (>= 2n).
    spectra: Option<Spectra>,
}

/// A symmetric positive definite Toeplitz matrix of order N, given by its first row.
pub(crate) struct Toeplitz {
    row: Vec<f64>,
    planner: RealFftPlanner<f64>,
    full: Fft,
    full_spectrum: Vec<Complex<f64>>,
    /// Spectrum of the circulant embedding of the skew slope matrix (`kernel::slope_column`),
    /// when given.
    slope_spectrum: Vec<Complex<f64>>,
    cache: Vec<Generator>,
    work: Vec<Complex<f64>>,
    work2: Vec<Complex<f64>>,
    buf: Vec<f64>,
    buf2: Vec<f64>,
    /// `T_m^{-1} 1` and `T_m^{-1} (0, 1, .., m - 1)` for the last orders m asked of
    /// [`Toeplitz::solve_ones`] and [`Toeplitz::solve_ramp`].
    ones: Bordered,
    ramp: Bordered,
}

/// The right-hand sides fixed but for their order, whose solutions are bordered from order to
/// order (`generators.rs`).
#[derive(Clone, Copy)]
enum Family {
    Ones,
    Ramp,
}

/// A family's solution for the last order asked, and the bordering steps taken since it was last
/// solved afresh.
#[derive(Default)]
struct Bordered {
    v: Vec<f64>,
    steps: usize,
}

impl Toeplitz {
    /// Errors if a Levinson reflection coefficient of the first [`CG_FROM`] orders reaches 1
    /// (the matrix is not positive definite). Larger orders are not checked here (that would
    /// cost O(N^2)): the log kernel is positive definite by construction (`kernel.rs`).
    pub fn new(row: Vec<f64>) -> Result<Self> {
        let n = row.len();
        let mut f = vec![1.0 / row[0]];
        while f.len() < n.min(CG_FROM) {
            let k = f.len();
            let e: f64 = f.iter().enumerate().map(|(j, v)| row[k - j] * v).sum();
            if e.is_nan() || e.abs() >= 1.0 || row[0] <= 0.0 {
                return Err(Error::NoConvergence {
                    what: "Levinson recursion (kernel not positive definite)",
                    iterations: k,
                    last_step: e,
                });
            }
            step_up(&mut f, &row);
        }
        let mut planner = RealFftPlanner::new();
        // Circulant embedding of T_N: first column [t_0 .. t_{N-1}, 0, t_{N-1} .. t_1].
        let m = fft_size(2 * n);
        let mut full = Fft::new(&mut planner, m);
        let mut column = vec![0.0; m];
        column[..n].copy_from_slice(&row);
        for k in 1..n {
            column[m - k] = row[k];
        }
        let mut full_spectrum = vec![Complex::default(); m / 2 + 1];
        full.spectrum(&column, &mut full_spectrum);
        Ok(Self {
            row,
            planner,
            full,
            full_spectrum,
            slope_spectrum: Vec::new(),
            cache: Vec::new(),
            work: vec![Complex::default(); m / 2 + 1],
            work2: vec![Complex::default(); m / 2 + 1],
            buf: vec![0.0; m],
            buf2: vec![0.0; m],
            ones: Bordered::default(),
            ramp: Bordered::default(),
        })
    }

    /// The first row (and column) of the full matrix.
    pub fn row(&self) -> &[f64] {
        &self.row
    }

    /// `y = T_N v` (full grid), by the circulant embedding.
    pub fn apply(&mut self, v: &[f64], y: &mut [f64]) {
        let n = self.row.len();
        let m = self.full.m;
        self.full.spectrum(v, &mut self.work[..m / 2 + 1]);
        for (w, s) in self.work.iter_mut().zip(&self.full_spectrum) {
            *w *= s;
        }
        self.full.invert(&mut self.work[..m / 2 + 1], &mut y[..n]);
    }

    /// Adds the skew Toeplitz matrix `S_ij = g_(i-j)`, `g_(-k) = -g_k`, given by its first column
    /// g (of length N), for [`Self::apply_moments`].
    pub fn with_slopes(mut self, column: &[f64]) -> Self {
        let n = self.row.len();
        let m = self.full.m;
        let mut embedding = vec![0.0; m];
        embedding[..n].copy_from_slice(column);
        for k in 1..n {
            embedding[m - k] = -column[k];
        }
        let mut spectrum = vec![Complex::default(); m / 2 + 1];
        self.full.spectrum(&embedding, &mut spectrum);
        self.slope_spectrum = spectrum;
        self
    }

    /// `y = T_N mean + S slope` (full grid), both by the circulant embeddings: the displacement
    /// kernel of cells carrying `mean + slope (xi - x_j)`.
    pub fn apply_moments(&mut self, mean: &[f64], slope: &[f64], y: &mut [f64]) {
        let n = self.row.len();
        let h = self.full.m / 2 + 1;
        let (w1, w2) = (&mut self.work[..h], &mut self.work2[..h]);
        self.full.spectrum(mean, w1);
        self.full.spectrum(slope, w2);
        for ((a, b), (s, t)) in w1
            .iter_mut()
            .zip(w2.iter())
            .zip(self.full_spectrum.iter().zip(&self.slope_spectrum))
        {
            *a = *a * s + b * t;
        }
        self.full.invert(w1, &mut y[..n]);
    }

    /// `z = T_n^{-1} b` for the leading block of order n = b.len().
    pub fn solve(&mut self, b: &[f64], z: &mut [f64]) {
        let n = b.len();
        let g = self.generator(n);
        let Generator { x, x0, spectra, .. } = &mut self.cache[g];
        let x0 = *x0;
        match spectra {
            None => {
                // y = Z J x: y_0 = 0, y_i = x_{n-i}.
                let y = |i: usize| if i == 0 { 0.0 } else { x[n - i] };
                // t1 = L(x)^T b, t2 = L(y)^T b; z = (L(x) t1 - L(y) t2)/x0.
                let t1: Vec<f64> = (0..n)
                    .map(|i| (i..n).map(|j| x[j - i] * b[j]).sum())
                    .collect();
                let t2: Vec<f64> = (0..n)
                    .map(|i| (i..n).map(|j| y(j - i) * b[j]).sum())
                    .collect();
                for i in 0..n {
                    let s: f64 = (0..=i).map(|j| x[i - j] * t1[j] - y(i - j) * t2[j]).sum();
                    z[i] = s / x0;
                }
            }
            Some((fft, sx, sy)) => {
                let h = fft.m / 2 + 1;
                let (w1, w2) = (&mut self.work[..h], &mut self.work2[..h]);
                // L(v)^T b = J L(v) J b.
                let rev: &mut Vec<f64> = &mut self.buf;
                rev.clear();
                rev.extend(b.iter().rev());
                fft.spectrum(rev, w1);
                for ((a, c), (p, q)) in w1
                    .iter_mut()
                    .zip(w2.iter_mut())
                    .zip(sx.iter().zip(sy.iter()))
                {
                    *c = *a * q;
                    *a *= p;
                }
                let t1 = &mut self.buf2;
                t1.resize(n, 0.0);
                fft.invert(w1, t1);
                t1.reverse();
                let t2 = &mut self.buf;
                t2.resize(n, 0.0);
                fft.invert(w2, t2);
                t2.reverse();
                fft.spectrum(t1, w1);
                fft.spectrum(t2, w2);
                for ((a, c), (p, q)) in w1.iter_mut().zip(w2.iter()).zip(sx.iter().zip(sy.iter())) {
                    *a = (*a * p - c * q) / x0;
                }
                fft.invert(w1, z);
            }
        }
    }
}

#[cfg(test)]
pub(super) mod tests {
    use super::*;

    /// Dense Gaussian elimination with partial pivoting: the independent reference for the
    /// Toeplitz and PCG solves.
    pub(in crate::march) fn dense_solve(mut a: Vec<Vec<f64>>, b: &[f64]) -> Vec<f64> {
        let n = b.len();
        let mut b = b.to_vec();
        for c in 0..n {
            let p = (c..n)
                .max_by(|&i, &j| a[i][c].abs().total_cmp(&a[j][c].abs()))
                .unwrap();
            a.swap(c, p);
            b.swap(c, p);
            let pivot = a[c].clone();
            for r in c + 1..n {
                let f = a[r][c] / pivot[c];
                for (x, y) in a[r][c..].iter_mut().zip(&pivot[c..]) {
                    *x -= f * y;
                }
                b[r] -= f * b[c];
            }
        }
        let mut x = vec![0.0; n];
        for i in (0..n).rev() {
            x[i] = (b[i] - (i + 1..n).map(|k| a[i][k] * x[k]).sum::<f64>()) / a[i][i];
        }
        x
    }

    fn toeplitz_matrix(row: &[f64], n: usize) -> Vec<Vec<f64>> {
        (0..n)
            .map(|i| (0..n).map(|j| row[i.abs_diff(j)]).collect())
            .collect()
    }

    fn log_row(n: usize) -> Vec<f64> {
        // -integral over a unit cell of ln(|xi - x_i|/l), l = 4n: the project's kernel.
        crate::march::kernel::cell_row(n, 1.0, 4.0 * n as f64)
    }

    #[test]
    fn inverse_blocks_match_dense_elimination() {
        // Tier 1: both are direct methods on a matrix with condition ~ n; 1e-11 relative.
        let row = log_row(300);
        let mut t = Toeplitz::new(row.clone()).unwrap();
        for n in [1, 2, 7, 47, 48, 120, 300, 119, 3] {
            let b: Vec<f64> = (0..n).map(|i| ((i * 7 + 3) % 11) as f64 - 4.0).collect();
            let mut z = vec![0.0; n];
            t.solve(&b, &mut z);
            let exact = dense_solve(toeplitz_matrix(&row, n), &b);
            let scale = exact.iter().fold(0.0f64, |m, v| m.max(v.abs()));
            for (a, e) in z.iter().zip(&exact) {
                assert!((a - e).abs() < 1e-11 * scale, "n = {n}: {a} vs {e}");
            }
        }
    }

    #[test]
    fn full_product_matches_the_definition() {
        let row = log_row(37);
        let mut t = Toeplitz::new(row.clone()).unwrap();
        let v: Vec<f64> = (0..37).map(|i| (i as f64 * 0.37).sin()).collect();
        let mut y = vec![0.0; 37];
        t.apply(&v, &mut y);
        for i in 0..37usize {
            let e: f64 = (0..37).map(|j| row[i.abs_diff(j)] * v[j]).sum();
            assert!((y[i] - e).abs() < 1e-12 * e.abs().max(1.0), "{i}");
        }
    }

    #[test]
    fn bordered_unit_and_ramp_solves_match_fresh_ones() {
        // T_n^{-1} 1 and T_n^{-1} (0, 1, .., n - 1) carried from order to order by bordering,
        // along a walk of the orders a stick run takes (up and down by one to 32 cells, 300
        // steps), against fresh solves of the same order. The log kernel's condition grows like
        // n, so each step adds about n eps relative; refreshed every 256 steps they stay near
        // 4e-13 and 7e-12, and 1e-10 leaves a decade or more.
        let row = log_row(3000);
        let mut t = Toeplitz::new(row.clone()).unwrap();
        let mut fresh = Toeplitz::new(row).unwrap();
        let mut n = 1500usize;
        let mut worst = [0.0f64; 2];
        for k in 0..300 {
            let step = 1 + (k * 7) % 32;
            n = if (k / 5) % 2 == 0 { n + step } else { n - step };
            for (family, worst) in worst.iter_mut().enumerate() {
                let mut carried = vec![0.0; n];
                let rhs: Vec<f64> = if family == 0 {
                    t.solve_ones(&mut carried);
                    vec![1.0; n]
                } else {
                    t.solve_ramp(&mut carried);
                    (0..n).map(|i| i as f64).collect()
                };
                let mut direct = vec![0.0; n];
                fresh.solve(&rhs, &mut direct);
                let scale = direct.iter().fold(0.0f64, |m, v| m.max(v.abs()));
                for (a, b) in carried.iter().zip(&direct) {
                    *worst = worst.max((a - b).abs() / scale);
                }
            }
        }
        eprintln!(
            "bordered T^-1 1 and T^-1 ramp: largest differences {:.2e} and {:.2e} of the largest entry",
            worst[0],
            worst[1]
        );
        assert!(
            worst.iter().all(|w| *w < 1e-10),
            "bordered solves off by {worst:?} of their largest entry (1, ramp)"
        );
        // Bordering did the work: at most one fresh solve per 256 steps.
        assert!(
            t.ones.steps > 0 && t.ramp.steps > 0,
            "the walk's last vectors were bordered"
        );
    }

    #[test]
    fn cut_run_solves_match_fresh_ones() {
        // T^{-1} b on a run [s, e) of a 3000-cell grid, cut by up to five cells at either end or
        // both (as an active-set pass flags the cells at a stick run's ends), against a fresh
        // solve of b on the shorter run. The cut entries of b are arbitrary (the cut does not
        // depend on them). A few steps add a few n eps relative: 1e-11 leaves a decade.
        let row = log_row(3000);
        let mut t = Toeplitz::new(row).unwrap();
        let b = |i: usize| (i as f64 * 0.013).sin() + 0.4 * (i as f64 * 0.002).cos();
        let mut worst = 0.0f64;
        for (k, (s, e)) in [(100, 2900), (700, 1900), (1200, 1260), (5, 2995)]
            .into_iter()
            .enumerate()
        {
            for (left, right) in [(1, 0), (0, 1), (2, 3), (5, 5), (0, 4)] {
                let rhs: Vec<f64> = (s..e).map(b).collect();
                let mut z = vec![0.0; e - s];
                t.solve(&rhs, &mut z);
                let to = (s + left, e - right);
                t.cut((s, e), to, &mut z);
                let rhs: Vec<f64> = (to.0..to.1).map(b).collect();
                let mut fresh = vec![0.0; to.1 - to.0];
                t.solve(&rhs, &mut fresh);
                let scale = fresh.iter().fold(0.0f64, |m, v| m.max(v.abs()));
                assert_eq!(z.len(), fresh.len(), "run {k}: the cut's length");
                for (a, f) in z.iter().zip(&fresh) {
                    worst = worst.max((a - f).abs() / scale);
                }
            }
        }
        eprintln!("cut run solves: largest difference {worst:.2e} of the largest entry");
        assert!(
            worst < 1e-11,
            "cut solves off by {worst:e} of their largest entry"
        );
    }

    #[test]
    fn conjugate_gradient_generators_match_levinson() {
        // Two routes to x = T_n^{-1} e_0: CG with T. Chan's preconditioner and the exact
        // Levinson recursion. CG stops at a residual of 1e-15 on a matrix of condition ~n, so
        // 1e-11 relative leaves two decades for rounding.
        for n in [256, 700, 2000] {
            let row = log_row(n);
            let mut t = Toeplitz::new(row.clone()).unwrap();
            let mut exact = vec![1.0 / row[0]];
            while exact.len() < n {
                step_up(&mut exact, &row);
            }
            let by_cg = t.generator_by_cg(n, None).expect("CG converges");
            // Warm-started from x cut short by 37 and zero-padded, as the marcher starts from a
            // cached shorter generator.
            let start = exact[..n - 37].iter().copied().chain([0.0; 37]).collect();
            let warm = t.generator_by_cg(n, Some(start)).expect("CG converges");
            let scale = exact.iter().fold(0.0f64, |m, v| m.max(v.abs()));
            for (i, ((a, b), e)) in by_cg.iter().zip(&warm).zip(&exact).enumerate() {
                assert!((a - e).abs() < 1e-11 * scale, "n = {n}, {i}: {a} vs {e}");
                assert!(
                    (b - e).abs() < 1e-11 * scale,
                    "n = {n}, {i}: warm {b} vs {e}"
                );
            }
            // Levinson steps down and up again return the same generator.
            let mut x = exact.clone();
            for _ in 0..40 {
                step_down(&mut x);
            }
            for _ in 0..40 {
                step_up(&mut x, &row);
            }
            for (a, e) in x.iter().zip(&exact) {
                assert!((a - e).abs() < 1e-11 * scale, "n = {n}: steps {a} vs {e}");
            }
        }
    }

    #[test]
    fn indefinite_matrix_is_rejected() {
        assert!(Toeplitz::new(vec![1.0, 2.0, 0.5]).is_err());
    }
}
