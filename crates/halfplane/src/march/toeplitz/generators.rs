//! The generators `x = T_n^{-1} e_0` of the Gohberg-Semencul inverse (`mod.rs`): from a cached
//! generator of a nearby order by Levinson steps, or by conjugate gradients with T. Chan's
//! circulant preconditioner, kept in the cache; and `T_n^{-1} 1` bordered from one order to the
//! next with them.
//!
//! Owns how a generator of a new order is made and the unit solve. Never applies the inverse
//! (`mod.rs` does).

use super::{fft_size, Bordered, Family, Fft, Generator, Toeplitz, CACHE, CG_FROM, DIRECT_BELOW};
use realfft::num_complex::Complex;

/// A cached generator is stepped to a new order by Levinson steps (O(n) each) only when it is
/// at most this many orders away; farther, conjugate gradients (O(n log n) per iteration, a few
/// tens of iterations) cost less.
const LEVINSON_STEPS_MAX: usize = 64;
/// [`Toeplitz::solve_ones`] borders its last vector across at most this many orders.
const ONES_STEPS_MAX: usize = 32;
/// [`Toeplitz::solve_ones`] solves afresh after this many bordering steps in all.
const ONES_REFRESH: usize = 256;
/// Most conjugate-gradient iterations for a generator.
const CG_ITERATIONS: usize = 200;
/// Iterations without a lower residual after which CG has reached its rounding floor.
const CG_STALL: usize = 8;

impl Toeplitz {
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
        self.solve_bordered(Family::Ones, z);
    }

    /// `z = T_n^{-1} r` for the ramp `r = (0, 1, .., n - 1)`, n = z.len() (a stick run's
    /// `T^{-1} x` is `x_s T^{-1} 1 + w T^{-1} r`), bordered from the last order as
    /// [`Self::solve_ones`] is, with the general rule: x the generator of order k + 1, a cell
    /// added after the run gives `[z; 0] + (k - t.z) J x` (`t_i = t_{k-i}`, the new row; the
    /// ramp's new entry is k), and a cell cut subtracts `(z_k / x_0) J x`.
    pub fn solve_ramp(&mut self, z: &mut [f64]) {
        self.solve_bordered(Family::Ramp, z);
    }

    /// [`Self::solve_ones`] and [`Self::solve_ramp`]: the family's last vector bordered to order
    /// n = z.len(), or solved afresh.
    fn solve_bordered(&mut self, family: Family, z: &mut [f64]) {
        let n = z.len();
        let (m, taken) = {
            let b = self.bordered(family);
            (b.v.len(), b.steps)
        };
        let steps = m.abs_diff(n);
        if m >= DIRECT_BELOW && steps <= ONES_STEPS_MAX && taken + steps <= ONES_REFRESH {
            if steps > 0 {
                let g = self.generator(m);
                let mut x = self.cache[g].x.clone();
                let row = std::mem::take(&mut self.row);
                let b = self.bordered(family);
                while b.v.len() < n {
                    step_up(&mut x, &row);
                    let k = b.v.len();
                    let a = match family {
                        Family::Ones => x.iter().sum::<f64>() / x[0],
                        Family::Ramp => {
                            k as f64
                                - b.v
                                    .iter()
                                    .enumerate()
                                    .map(|(i, v)| row[k - i] * v)
                                    .sum::<f64>()
                        }
                    };
                    b.v.push(0.0);
                    b.v.iter_mut()
                        .zip(x.iter().rev())
                        .for_each(|(v, xi)| *v += a * xi);
                }
                while b.v.len() > n {
                    let c = match family {
                        Family::Ones => x.iter().sum::<f64>() / x[0],
                        Family::Ramp => b.v[b.v.len() - 1] / x[0],
                    };
                    b.v.pop();
                    b.v.iter_mut()
                        .zip(x.iter().rev())
                        .for_each(|(v, xi)| *v -= c * xi);
                    step_down(&mut x);
                }
                b.steps += steps;
                self.row = row;
            }
        } else {
            let rhs: Vec<f64> = match family {
                Family::Ones => vec![1.0; n],
                Family::Ramp => (0..n).map(|i| i as f64).collect(),
            };
            let mut v = vec![0.0; n];
            self.solve(&rhs, &mut v);
            *self.bordered(family) = Bordered { v, steps: 0 };
        }
        z.copy_from_slice(&self.bordered(family).v);
    }

    fn bordered(&mut self, family: Family) -> &mut Bordered {
        match family {
            Family::Ones => &mut self.ones,
            Family::Ramp => &mut self.ramp,
        }
    }

    /// `z = T_k^{-1} b` on the run `[from.0, from.1)` (k its length) carried to the shorter run
    /// `[to.0, to.1)` inside it: the solution for the right-hand side cut with the run, whatever
    /// b was at the cells cut. O(k) per cell cut, against a few FFTs for a fresh solve.
    ///
    /// Bordering (Golub & Van Loan, 4th ed., section 4.7): with x the generator of order k + 1
    /// (the first column of `T_{k+1}^{-1}`, and by persymmetry `J x` its last), a cell added after
    /// a run gives `T_{k+1}^{-1} [b; beta] = [z; 0] + a J x` and one added before it
    /// `[0; z] + a x`, for some a; so cutting the last cell subtracts `(z'_k / x_0) J x` and
    /// cutting the first `(z'_0 / x_0) x`, whatever beta was.
    pub fn cut(&mut self, from: (usize, usize), to: (usize, usize), z: &mut Vec<f64>) {
        let (mut s, mut e) = from;
        let mut x = self.generator_near(e - s);
        while s < to.0 {
            let c = z[0] / x[0];
            z.remove(0);
            z.iter_mut().zip(&x[1..]).for_each(|(v, xi)| *v -= c * xi);
            step_down(&mut x);
            s += 1;
        }
        while e > to.1 {
            let c = z[z.len() - 1] / x[0];
            z.pop();
            z.iter_mut()
                .zip(x.iter().rev())
                .for_each(|(v, xi)| *v -= c * xi);
            step_down(&mut x);
            e -= 1;
        }
    }

    /// The generator of order n, stepped from the nearest cached one when that is at most
    /// [`LEVINSON_STEPS_MAX`] orders away (not cached itself, nor its spectra: a cut or a
    /// bordering needs x alone), else the cache's own.
    fn generator_near(&mut self, n: usize) -> Vec<f64> {
        let near = self
            .cache
            .iter()
            .filter(|g| g.n.abs_diff(n) <= LEVINSON_STEPS_MAX)
            .min_by_key(|g| g.n.abs_diff(n));
        let Some(g) = near else {
            let g = self.generator(n);
            return self.cache[g].x.clone();
        };
        let mut x = g.x.clone();
        while x.len() < n {
            step_up(&mut x, &self.row);
        }
        while x.len() > n {
            step_down(&mut x);
        }
        x
    }

    /// Index in the cache of the generator of order n: from the nearest cached one by Levinson
    /// steps when that costs less than conjugate gradients, else by [`Self::generator_by_cg`].
    pub(super) fn generator(&mut self, n: usize) -> usize {
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
    pub(super) fn generator_by_cg(
        &mut self,
        n: usize,
        start: Option<Vec<f64>>,
    ) -> Option<Vec<f64>> {
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
pub(super) fn step_up(x: &mut Vec<f64>, row: &[f64]) {
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
pub(super) fn step_down(x: &mut Vec<f64>) {
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
