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
//! Owns the Toeplitz algebra and its generator cache. Never knows what the matrix means (the
//! kernel is `kernel.rs`'s) nor which cells stick (`solve.rs` chooses the runs).

use crate::error::{Error, Result};
use realfft::num_complex::Complex;
use realfft::{ComplexToReal, RealFftPlanner, RealToComplex};
use std::sync::Arc;

/// Below this size the Gohberg-Semencul products are formed directly (O(n^2) beats the FFTs).
const DIRECT_BELOW: usize = 48;
/// Generators kept for reuse (stick runs change length by a few cells per increment).
const CACHE: usize = 12;
/// A cached generator is stepped to a new order by Levinson steps (O(n) each) only when it is
/// at most this many orders away; farther, conjugate gradients (O(n log n) per iteration, a few
/// tens of iterations) cost less.
const LEVINSON_STEPS_MAX: usize = 64;
/// [`Toeplitz::solve_ones`] borders its last vector across at most this many orders.
const ONES_STEPS_MAX: usize = 32;
/// [`Toeplitz::solve_ones`] solves afresh after this many bordering steps in all.
const ONES_REFRESH: usize = 256;
/// Below this order a generator with no cached neighbour is built by Levinson from order 1.
const CG_FROM: usize = 256;
/// Most conjugate-gradient iterations for a generator.
const CG_ITERATIONS: usize = 200;
/// Iterations without a lower residual after which CG has reached its rounding floor.
const CG_STALL: usize = 8;

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
    /// `T_m^{-1} 1` for the last order m asked of [`Toeplitz::solve_ones`].
    ones: Vec<f64>,
    /// Bordering steps taken since `ones` was last solved.
    ones_steps: usize,
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
            ones: Vec::new(),
            ones_steps: 0,
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

    /// `z = T_n^{-1} 1` for n = z.len(). A stick run's order changes by a cell or two from one
    /// set to the next, so the last order's vector is bordered to n (O(n) per order, exact in
    /// exact arithmetic) when it is at most [`ONES_STEPS_MAX`] orders away, and solved afresh
    /// otherwise or after [`ONES_REFRESH`] steps (rounding accumulates over the steps).
    ///
    /// Bordering (Golub & Van Loan, 4th ed., section 4.7): with `c = J x` the last column of
    /// `T_{k+1}^{-1}` (persymmetry; x its first column, the generator), the inverse of the
    /// bordered matrix gives `T_{k+1}^{-1} 1 = [T_k^{-1} 1; 0] + (sum(x)/x_0) c`: its last entry
    /// is the last column's sum, as it must be. Going down inverts the same relation.
    pub fn solve_ones(&mut self, z: &mut [f64]) {
        let n = z.len();
        let m = self.ones.len();
        let steps = m.abs_diff(n);
        if m >= DIRECT_BELOW && steps <= ONES_STEPS_MAX && self.ones_steps + steps <= ONES_REFRESH {
            if steps > 0 {
                let g = self.generator(m);
                let mut x = self.cache[g].x.clone();
                let v = &mut self.ones;
                while v.len() < n {
                    step_up(&mut x, &self.row);
                    let (k, f) = (x.len(), x.iter().sum::<f64>() / x[0]);
                    v.push(0.0);
                    for (i, vi) in v.iter_mut().enumerate() {
                        *vi += f * x[k - 1 - i];
                    }
                }
                while v.len() > n {
                    let (k, f) = (x.len(), x.iter().sum::<f64>() / x[0]);
                    v.pop();
                    for (i, vi) in v.iter_mut().enumerate() {
                        *vi -= f * x[k - 1 - i];
                    }
                    step_down(&mut x);
                }
                self.ones_steps += steps;
            }
        } else {
            let ones = vec![1.0; n];
            let mut v = vec![0.0; n];
            self.solve(&ones, &mut v);
            self.ones = v;
            self.ones_steps = 0;
        }
        z.copy_from_slice(&self.ones);
    }

    /// Index in the cache of the generator of order n: from the nearest cached one by Levinson
    /// steps when that costs less than conjugate gradients, else by [`Self::generator_by_cg`].
    fn generator(&mut self, n: usize) -> usize {
        if let Some(i) = self.cache.iter().position(|g| g.n == n) {
            return i;
        }
        let nearest = self
            .cache
            .iter()
            .filter(|g| g.n.abs_diff(n) <= LEVINSON_STEPS_MAX)
            .min_by_key(|g| g.n.abs_diff(n));
        let x = match nearest {
            Some(g) => {
                let mut x = g.x.clone();
                while x.len() < n {
                    step_up(&mut x, &self.row);
                }
                while x.len() > n {
                    step_down(&mut x);
                }
                x
            }
            None if n < CG_FROM => {
                let mut x = vec![1.0 / self.row[0]];
                while x.len() < n {
                    step_up(&mut x, &self.row);
                }
                x
            }
            None => {
                // Start CG from the nearest cached generator, cut or zero-padded to order n.
                let start = self.cache.iter().min_by_key(|g| g.n.abs_diff(n)).map(|g| {
                    g.x.iter()
                        .copied()
                        .chain(std::iter::repeat(0.0))
                        .take(n)
                        .collect()
                });
                self.generator_by_cg(n, start)
            }
            .unwrap_or_else(|| {
                let mut x = vec![1.0 / self.row[0]];
                while x.len() < n {
                    step_up(&mut x, &self.row);
                }
                x
            }),
        };
        let x0 = x[0];
        let spectra = (n >= DIRECT_BELOW).then(|| {
            let mut fft = Fft::new(&mut self.planner, fft_size(2 * n));
            let h = fft.m / 2 + 1;
            let mut sx = vec![Complex::default(); h];
            let mut sy = vec![Complex::default(); h];
            fft.spectrum(&x, &mut sx);
            let y: Vec<f64> = (0..n)
                .map(|i| if i == 0 { 0.0 } else { x[n - i] })
                .collect();
            fft.spectrum(&y, &mut sy);
            if self.work.len() < h {
                self.work.resize(h, Complex::default());
                self.work2.resize(h, Complex::default());
            }
            (fft, sx, sy)
        });
        if self.cache.len() == CACHE {
            self.cache.remove(0);
        }
        self.cache.push(Generator { n, x, x0, spectra });
        self.cache.len() - 1
    }

    /// `x = T_n^{-1} e_0` by conjugate gradients (Golub & Van Loan, 4th ed., algorithm 11.5.1)
    /// preconditioned by T. Chan's optimal circulant of `T_n`, whose first column is
    /// `c_k = ((n - k) t_k + k t_{n-k}) / n` (R. Chan & Ng 1996, eq. 2.5); it is positive
    /// definite when `T_n` is. Products with `T_n` use its own circulant embedding. Stops when
    /// the residual is below 1e-15 of `|e_0|`, near rounding (the Gohberg-Semencul form
    /// multiplies the error of x by up to the condition number, ~N here), or when it has not
    /// fallen for [`CG_STALL`] iterations at a residual below 1e-12 (the rounding floor of very
    /// long runs); `None` otherwise after [`CG_ITERATIONS`] (the caller then uses Levinson,
    /// exact but O(n^2)).
    fn generator_by_cg(&mut self, n: usize, start: Option<Vec<f64>>) -> Option<Vec<f64>> {
        let t = &self.row[..n];
        let m = fft_size(2 * n);
        let mut big = Fft::new(&mut self.planner, m);
        let h = m / 2 + 1;
        let mut column = vec![0.0; m];
        column[..n].copy_from_slice(t);
        for k in 1..n {
            column[m - k] = t[k];
        }
        let mut embedding = vec![Complex::default(); h];
        big.spectrum(&column, &mut embedding);
        let mut small = Fft::new(&mut self.planner, n);
        let chan: Vec<f64> = (0..n)
            .map(|k| {
                let wrap = if k == 0 { 0.0 } else { t[n - k] };
                ((n - k) as f64 * t[k] + k as f64 * wrap) / n as f64
            })
            .collect();
        let mut eigen = vec![Complex::default(); n / 2 + 1];
        small.spectrum(&chan, &mut eigen);
        let mut spec = vec![Complex::default(); h.max(n / 2 + 1)];
        let mut precondition = |small: &mut Fft, r: &[f64], y: &mut [f64]| {
            let s = &mut spec[..n / 2 + 1];
            small.spectrum(r, s);
            for (v, e) in s.iter_mut().zip(&eigen) {
                *v /= e.re;
            }
            small.invert(s, y);
        };
        let mut w = vec![Complex::default(); h];
        let mut product = |big: &mut Fft, v: &[f64], out: &mut [f64]| {
            big.spectrum(v, &mut w);
            for (a, e) in w.iter_mut().zip(&embedding) {
                *a *= e;
            }
            big.invert(&mut w, out);
        };
        let (mut y, mut ap) = (vec![0.0; n], vec![0.0; n]);
        let mut x = start.unwrap_or_else(|| vec![0.0; n]);
        product(&mut big, &x, &mut ap);
        let mut r: Vec<f64> = ap.iter().map(|v| -v).collect();
        r[0] += 1.0;
        precondition(&mut small, &r, &mut y);
        let mut p = y.clone();
        let mut rz: f64 = r.iter().zip(&y).map(|(a, b)| a * b).sum();
        let mut best = (f64::INFINITY, 0);
        for _ in 0..CG_ITERATIONS {
            product(&mut big, &p, &mut ap);
            let alpha = rz / p.iter().zip(&ap).map(|(a, b)| a * b).sum::<f64>();
            for i in 0..n {
                x[i] += alpha * p[i];
                r[i] -= alpha * ap[i];
            }
            let residual = r.iter().map(|v| v * v).sum::<f64>().sqrt();
            if residual <= 1e-15 {
                return Some(x);
            }
            if residual < best.0 {
                best = (residual, 0);
            } else {
                best.1 += 1;
                if best.1 == CG_STALL && best.0 <= 1e-12 {
                    // Rounding floor reached (it grows with the condition number, ~n).
                    return Some(x);
                }
            }
            precondition(&mut small, &r, &mut y);
            let next: f64 = r.iter().zip(&y).map(|(a, b)| a * b).sum();
            let beta = next / rz;
            rz = next;
            for i in 0..n {
                p[i] = y[i] + beta * p[i];
            }
        }
        None
    }
}

/// Levinson step (Golub & Van Loan, 4th ed., section 4.7.3): x solves `T_k x = e_0`; returns
/// x' solving `T_{k+1} x' = e_0`, `x' = ([x; 0] - e [0; J x]) / (1 - e^2)`, with the reflection
/// coefficient `e = sum_j t_{k-j} x_j` (the last row of `T_{k+1}` times `[x; 0]`).
fn step_up(x: &mut Vec<f64>, row: &[f64]) {
    let k = x.len();
    let e: f64 = x.iter().enumerate().map(|(j, v)| row[k - j] * v).sum();
    let scale = 1.0 / (1.0 - e * e);
    x.push(0.0);
    // Pairs (i, k - i) depend only on each other.
    for i in 0..=k / 2 {
        let (a, b) = (x[i], x[k - i]);
        x[i] = (a - e * b) * scale;
        x[k - i] = (b - e * a) * scale;
    }
}

/// Inverse of [`step_up`]: order k + 1 -> k. The reflection coefficient is `e = -x'_k / x'_0`
/// (the last and first entries of the formula in [`step_up`]).
fn step_down(x: &mut Vec<f64>) {
    let k = x.len() - 1;
    let e = -x[k] / x[0];
    for i in 1..=k / 2 {
        let (a, b) = (x[i], x[k - i]);
        x[i] = a + e * b;
        x[k - i] = b + e * a;
    }
    x[0] *= 1.0 - e * e;
    x.truncate(k);
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
    fn bordered_unit_solves_match_fresh_ones() {
        // T_n^{-1} 1 carried from order to order by bordering, along a walk of the orders a
        // stick run takes (up and down by one to 32 cells, 300 steps), against a fresh solve of
        // the same order. The log kernel's condition grows like n, so each step adds about
        // n eps relative; refreshed every 256 steps it stays near 4e-13, and 1e-10 leaves two
        // decades.
        let row = log_row(3000);
        let mut t = Toeplitz::new(row.clone()).unwrap();
        let mut fresh = Toeplitz::new(row).unwrap();
        let mut n = 1500usize;
        let mut worst = 0.0f64;
        for k in 0..300 {
            let step = 1 + (k * 7) % 32;
            n = if (k / 5) % 2 == 0 { n + step } else { n - step };
            let mut carried = vec![0.0; n];
            t.solve_ones(&mut carried);
            let mut direct = vec![0.0; n];
            fresh.solve(&vec![1.0; n], &mut direct);
            let scale = direct.iter().fold(0.0f64, |m, v| m.max(v.abs()));
            for (a, b) in carried.iter().zip(&direct) {
                worst = worst.max((a - b).abs() / scale);
            }
        }
        eprintln!("bordered T^-1 1: largest difference {worst:.2e} of the largest entry");
        assert!(
            worst < 1e-10,
            "bordered T^-1 1 off by {worst:e} of its largest entry"
        );
        // Bordering did the work: at most one fresh solve per 256 steps.
        assert!(t.ones_steps > 0, "the walk's last vector was bordered");
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
