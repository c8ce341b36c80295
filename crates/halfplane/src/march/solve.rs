//! The stick cells' linear systems `G_SS z = b`: the exact inverse of one stick run (via
//! `toeplitz/`), block elimination of a few extra stick cells (Schur complement), conjugate
//! gradients preconditioned by each run's exact inverse, and the dense Cholesky route of
//! [`LinearSolver::Dense`](super::LinearSolver::Dense); also the kernel product `y = G v`.
//!
//! Owns how a system is solved and the solver caches. Never changes the active set or the
//! state fields (cells, pressure, traction, slip): it reads the stick set and writes only the
//! solutions `u`, `v` and its own caches.

use super::marcher::{Cell, Marcher};
use super::toeplitz::Toeplitz;
use crate::error::{Error, Result};

/// See [`Marcher::schur_solve`].
pub(super) struct SchurCache {
    mask: Vec<bool>,
    start: usize,
    end: usize,
    extra: Vec<usize>,
    /// `G_BB^{-1} G_BE`, one column of length `end - start` per extra cell.
    w: Vec<f64>,
    /// Cholesky factor of the Schur complement, row-major k x k.
    l: Vec<f64>,
}

pub(super) enum Rhs {
    Vector,
    Ones,
}

/// Cells whose known increment changed since the last pass, at most, for `G known` to be
/// updated by their kernel columns (`k N` multiply-adds) rather than by a full FFT product: at
/// 6400 cells 16 columns are 1e5 multiply-adds, against 51 us for the product's forward and
/// inverse FFT (`benches/march_limit.rs`, `fft_pair`).
const CHANGED_COLUMNS: usize = 16;

impl Marcher {
    /// The known traction increments of the current cells into `known` (slip cells to the
    /// friction limit, `f p sign - q`; released cells to zero, `-q`; stick cells none) and
    /// `G known` into `g_known`. Within a sub-step the tractions and pressures do not change,
    /// so after its first pass only the cells that changed state have new values; when at most
    /// [`CHANGED_COLUMNS`] did, `g_known` gets their kernel columns (`G` is Toeplitz:
    /// `G_ik = row[|i - k|]`) instead of a full product, and those changes `(cell, change)` are
    /// returned (for [`Self::solve_after_cut`]). The two routes agree to rounding.
    pub(super) fn known_increments(&mut self, first_pass: bool) -> Option<Vec<(usize, f64)>> {
        let f = self.friction;
        let mut changed = Vec::new();
        for i in 0..self.x.len() {
            let known = match self.cells[i] {
                Cell::Out => -self.traction[i],
                Cell::Slip(sign) => sign * f * self.pressure[i] - self.traction[i],
                Cell::Stick => 0.0,
            };
            if !first_pass && known != self.known[i] && changed.len() <= CHANGED_COLUMNS {
                changed.push((i, known - self.known[i]));
            }
            self.known[i] = known;
        }
        if first_pass || changed.len() > CHANGED_COLUMNS {
            apply(
                &mut self.kernel,
                &self.dense,
                &self.known,
                &mut self.g_known,
            );
            return None;
        }
        for &(k, d) in &changed {
            add_column(&mut self.g_known, self.kernel.row(), k, d);
        }
        Some(changed)
    }

    /// The stick solution `u` of a pass whose stick set is the last pass's single run `from`
    /// less a few cells at its ends (`to`, the current single run from [`Self::single_run`]),
    /// which `changed` (from [`Self::known_increments`]) flagged to slip, without a fresh solve:
    /// returns `to`, or `None` (nothing done) when the pass is not of that kind.
    ///
    /// The last pass solved `T_S u = b` on its run S. This pass's right-hand side on the
    /// shorter run S' is `b - sum_f d_f G e_f` (the flagged cells' known increments `d_f`, as in
    /// `g_known`), and `G e_f` on S is `T_S e_f` because f was in S; so `u - sum_f d_f e_f`
    /// solves S's system with this pass's right-hand side on S', and cutting it to S'
    /// (`Toeplitz::cut`, O(n) per cell) gives the solution there, exact up to rounding.
    pub(super) fn solve_after_cut(
        &mut self,
        from: (usize, usize),
        (s, e): (usize, usize),
        changed: &[(usize, f64)],
    ) -> Option<(usize, usize)> {
        const CUT_MAX: usize = 8;
        let cut = |i: usize| (from.0..s).contains(&i) || (e..from.1).contains(&i);
        if s < from.0
            || e > from.1
            || (s - from.0) + (from.1 - e) > CUT_MAX
            || !changed.iter().all(|&(i, _)| cut(i))
        {
            return None;
        }
        for &(i, d) in changed {
            self.u[i] -= d;
        }
        let mut z = self.u[from.0..from.1].to_vec();
        self.kernel.cut(from, (s, e), &mut z);
        self.u.fill(0.0);
        self.u[s..e].copy_from_slice(&z);
        Some((s, e))
    }

    /// The single stick run of the current cells, `None` when there are several or none, or
    /// with the dense solver (which [`Self::solve_after_cut`] and the curvature term's column
    /// route do not serve).
    pub(super) fn single_run(&self) -> Option<(usize, usize)> {
        let set: Vec<bool> = self.cells.iter().map(|c| *c == Cell::Stick).collect();
        match runs_of(&set)[..] {
            [run] if self.dense.is_none() => Some(run),
            _ => None,
        }
    }

    /// Solves `G_SS z = b` on the stick cells S, into `u` (b = rhs) or `v` (b = 1).
    pub(super) fn solve_stick(&mut self, which: &Rhs, step: usize) -> Result<()> {
        let set: Vec<bool> = self.cells.iter().map(|c| *c == Cell::Stick).collect();
        match which {
            Rhs::Vector => {
                let (b, mut out) = (std::mem::take(&mut self.rhs), std::mem::take(&mut self.u));
                let result = self.solve_set(&set, &b, &mut out, step);
                (self.rhs, self.u) = (b, out);
                result
            }
            Rhs::Ones => self.solve_ones(&set, step),
        }
    }

    /// `v = G_SS^{-1} 1` on the set S, kept while S is unchanged (most passes and sub-steps keep it).
    pub(super) fn solve_ones(&mut self, set: &[bool], step: usize) -> Result<()> {
        if self.v_mask == set {
            return Ok(());
        }
        self.v_mask.clear();
        let mut out = std::mem::take(&mut self.v);
        let runs = runs_of(set);
        let result = if let ([(s, e)], None) = (&runs[..], &self.dense) {
            out.fill(0.0);
            self.kernel.solve_ones(&mut out[*s..*e]);
            Ok(())
        } else {
            let b: Vec<f64> = set.iter().map(|s| if *s { 1.0 } else { 0.0 }).collect();
            self.solve_set(set, &b, &mut out, step)
        };
        self.v = out;
        if result.is_ok() {
            self.v_mask.extend_from_slice(set);
        }
        result
    }

    /// `z = G_SS^{-1} b` on the cells of `set` (zero elsewhere): the exact Toeplitz inverse of a
    /// single run, block elimination of a few cells outside the longest run, conjugate
    /// gradients otherwise, or dense Cholesky with [`LinearSolver::Dense`](super::LinearSolver).
    pub(super) fn solve_set(
        &mut self,
        set: &[bool],
        b: &[f64],
        out: &mut [f64],
        step: usize,
    ) -> Result<()> {
        let runs = runs_of(set);
        out.iter_mut().for_each(|v| *v = 0.0);
        if let Some(g) = &self.dense {
            dense_stick_solve(g, set, b, out, step)
        } else if runs.len() == 1 {
            let (s, e) = runs[0];
            self.kernel.solve(&b[s..e], &mut out[s..e]);
            Ok(())
        } else if self.schur_solve(set, &runs, b, out) {
            Ok(())
        } else {
            out.iter_mut().for_each(|v| *v = 0.0);
            self.pcg(set, &runs, b, out, step)
        }
    }

    /// `G_SS z = b` when S is one long run B plus a few other cells E (typically cells that
    /// have just entered contact at an advancing edge and stick while their neighbours slip), by
    /// block elimination (the Schur complement; Golub & Van Loan, *Matrix Computations*, 4th ed.,
    /// section 3.2.11): `W = G_BB^{-1} G_BE`, `S = G_EE - G_EB W` (symmetric positive definite
    /// because G is), `z_E = S^{-1} (b_E - G_EB G_BB^{-1} b_B)`, `z_B = G_BB^{-1} b_B - W z_E`.
    /// W and the Cholesky factor of S are kept while the stick set is unchanged. Exact up to
    /// rounding, like the single-run solve. Returns false (nothing solved) when E is too large
    /// or S is not numerically positive definite; the caller then uses CG.
    fn schur_solve(
        &mut self,
        set: &[bool],
        runs: &[(usize, usize)],
        b: &[f64],
        z: &mut [f64],
    ) -> bool {
        const MAX_EXTRA: usize = 32;
        let same = self.schur.as_ref().is_some_and(|c| c.mask == set);
        if !same {
            self.schur = None;
            // No stick cell at all (no cell centre inside the contact yet): nothing to eliminate.
            let Some(&(s0, e0)) = runs.iter().max_by_key(|(s, e)| e - s) else {
                return false;
            };
            let extra: Vec<usize> = runs
                .iter()
                .filter(|r| r.0 != s0)
                .flat_map(|&(s, e)| s..e)
                .collect();
            let (k, nb) = (extra.len(), e0 - s0);
            if k > MAX_EXTRA || nb == 0 {
                return false;
            }
            let row = self.kernel.row().to_vec();
            let mut w = vec![0.0; k * nb];
            let mut column = vec![0.0; nb];
            for (j, &e) in extra.iter().enumerate() {
                for (i, c) in column.iter_mut().enumerate() {
                    *c = row[(s0 + i).abs_diff(e)];
                }
                self.kernel.solve(&column, &mut w[j * nb..(j + 1) * nb]);
            }
            // S = G_EE - G_EB W, then its Cholesky factor (lower, row-major).
            let mut l = vec![0.0; k * k];
            for a in 0..k {
                for c in 0..=a {
                    let coupling: f64 = (0..nb)
                        .map(|i| row[(s0 + i).abs_diff(extra[a])] * w[c * nb + i])
                        .sum();
                    l[a * k + c] = row[extra[a].abs_diff(extra[c])] - coupling;
                }
            }
            for a in 0..k {
                for c in 0..=a {
                    let mut sum = l[a * k + c];
                    for m in 0..c {
                        sum -= l[a * k + m] * l[c * k + m];
                    }
                    if a == c {
                        if sum.is_nan() || sum <= 0.0 {
                            return false;
                        }
                        l[a * k + a] = sum.sqrt();
                    } else {
                        l[a * k + c] = sum / l[c * k + c];
                    }
                }
            }
            self.schur = Some(SchurCache {
                mask: set.to_vec(),
                start: s0,
                end: e0,
                extra,
                w,
                l,
            });
        }
        let Some(cache) = self.schur.as_ref() else {
            return false;
        };
        let (s0, e0, k) = (cache.start, cache.end, cache.extra.len());
        let nb = e0 - s0;
        let mut y = vec![0.0; nb];
        if b[s0..e0].iter().all(|v| *v == 1.0) {
            // The unit solve (`solve_ones`): bordered from the last order, as for a single run.
            self.kernel.solve_ones(&mut y);
        } else {
            self.kernel.solve(&b[s0..e0], &mut y);
        }
        let row = self.kernel.row();
        let mut r: Vec<f64> = cache
            .extra
            .iter()
            .map(|&e| {
                b[e] - (0..nb)
                    .map(|i| row[(s0 + i).abs_diff(e)] * y[i])
                    .sum::<f64>()
            })
            .collect();
        // Forward and back substitution with L L^T.
        for a in 0..k {
            let sum: f64 = (0..a).map(|m| cache.l[a * k + m] * r[m]).sum();
            r[a] = (r[a] - sum) / cache.l[a * k + a];
        }
        for a in (0..k).rev() {
            let sum: f64 = (a + 1..k).map(|m| cache.l[m * k + a] * r[m]).sum();
            r[a] = (r[a] - sum) / cache.l[a * k + a];
        }
        for (j, &e) in cache.extra.iter().enumerate() {
            z[e] = r[j];
            for (yi, wi) in y.iter_mut().zip(&cache.w[j * nb..(j + 1) * nb]) {
                *yi -= wi * r[j];
            }
        }
        z[s0..e0].copy_from_slice(&y);
        true
    }

    /// Conjugate gradients on the stick cells, preconditioned by the exact inverse of each run.
    pub(super) fn pcg(
        &mut self,
        set: &[bool],
        runs: &[(usize, usize)],
        b: &[f64],
        z: &mut [f64],
        step: usize,
    ) -> Result<()> {
        let [r, p, ap, y] = &mut self.pcg;
        r.copy_from_slice(b);
        let b_norm = b.iter().map(|v| v * v).sum::<f64>().sqrt();
        if b_norm == 0.0 {
            return Ok(());
        }
        let precondition = |kernel: &mut Toeplitz, r: &[f64], y: &mut [f64]| {
            y.iter_mut().for_each(|v| *v = 0.0);
            for &(s, e) in runs {
                kernel.solve(&r[s..e], &mut y[s..e]);
            }
        };
        precondition(&mut self.kernel, r, y);
        p.copy_from_slice(y);
        let mut rz: f64 = r.iter().zip(y.iter()).map(|(a, b)| a * b).sum();
        for _ in 0..500 {
            self.kernel.apply(p, ap);
            for (a, s) in ap.iter_mut().zip(set) {
                if !s {
                    *a = 0.0;
                }
            }
            let alpha = rz / p.iter().zip(ap.iter()).map(|(a, b)| a * b).sum::<f64>();
            for i in 0..z.len() {
                z[i] += alpha * p[i];
                r[i] -= alpha * ap[i];
            }
            if r.iter().map(|v| v * v).sum::<f64>().sqrt() <= 1e-13 * b_norm {
                return Ok(());
            }
            precondition(&mut self.kernel, r, y);
            let next: f64 = r.iter().zip(y.iter()).map(|(a, b)| a * b).sum();
            let beta = next / rz;
            rz = next;
            for i in 0..p.len() {
                p[i] = y[i] + beta * p[i];
            }
        }
        Err(Error::ActiveSet {
            step,
            iterations: 500,
        })
    }
}

/// `g += d G e_k`: column k of the Toeplitz matrix with first row `row` (`G_ik = row[|i - k|]`),
/// scaled by d, in two contiguous runs (the rows above k read the row backwards).
pub(super) fn add_column(g: &mut [f64], row: &[f64], k: usize, d: f64) {
    let (above, below) = g.split_at_mut(k);
    for (gi, r) in above.iter_mut().zip(row[1..=k].iter().rev()) {
        *gi += d * r;
    }
    for (gi, r) in below.iter_mut().zip(row) {
        *gi += d * r;
    }
}

/// The sum of `v` with four running partial sums, which the processor adds side by side (a
/// single running sum waits on each addition in turn). It differs from the sequential sum by
/// rounding only.
pub(super) fn sum(v: &[f64]) -> f64 {
    let chunks = v.chunks_exact(4);
    let rest: f64 = chunks.remainder().iter().sum();
    let mut partial = [0.0; 4];
    for c in chunks {
        for (p, x) in partial.iter_mut().zip(c) {
            *p += x;
        }
    }
    (partial[0] + partial[1]) + (partial[2] + partial[3]) + rest
}

/// `y = G v`, by FFT or by the dense matrix.
pub(super) fn apply(kernel: &mut Toeplitz, dense: &Option<Vec<f64>>, v: &[f64], y: &mut [f64]) {
    match dense {
        None => kernel.apply(v, y),
        Some(g) => {
            let n = v.len();
            for (i, yi) in y.iter_mut().enumerate() {
                *yi = g[i * n..(i + 1) * n]
                    .iter()
                    .zip(v)
                    .map(|(a, b)| a * b)
                    .sum();
            }
        }
    }
}

/// Cholesky solve of `G_SS z = b` over all stick cells (the dense route).
pub(super) fn dense_stick_solve(
    g: &[f64],
    set: &[bool],
    b: &[f64],
    z: &mut [f64],
    step: usize,
) -> Result<()> {
    let n_all = set.len();
    let s: Vec<usize> = (0..n_all).filter(|&i| set[i]).collect();
    let n = s.len();
    let mut l = vec![0.0; n * n];
    for i in 0..n {
        for j in 0..=i {
            let mut sum = g[s[i] * n_all + s[j]];
            for k in 0..j {
                sum -= l[i * n + k] * l[j * n + k];
            }
            if i == j {
                if sum <= 0.0 || sum.is_nan() {
                    return Err(Error::NonPositivePivot { step, index: s[i] });
                }
                l[i * n + i] = sum.sqrt();
            } else {
                l[i * n + j] = sum / l[j * n + j];
            }
        }
    }
    let mut y: Vec<f64> = s.iter().map(|&i| b[i]).collect();
    for i in 0..n {
        let sum: f64 = (0..i).map(|k| l[i * n + k] * y[k]).sum();
        y[i] = (y[i] - sum) / l[i * n + i];
    }
    for i in (0..n).rev() {
        let sum: f64 = (i + 1..n).map(|k| l[k * n + i] * y[k]).sum();
        y[i] = (y[i] - sum) / l[i * n + i];
    }
    for (k, &i) in s.iter().enumerate() {
        z[i] = y[k];
    }
    Ok(())
}

/// Maximal runs `[start, end)` of cells in `set`.
fn runs_of(set: &[bool]) -> Vec<(usize, usize)> {
    let mut runs = Vec::new();
    let mut start = None;
    for i in 0..=set.len() {
        let stick = i < set.len() && set[i];
        match (stick, start) {
            (true, None) => start = Some(i),
            (false, Some(s)) => {
                runs.push((s, i));
                start = None;
            }
            _ => {}
        }
    }
    runs
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::march::{kernel, toeplitz, MarchOptions};
    use crate::normal::Contact;
    use crate::{Friction, Material, Profile};

    #[test]
    fn several_stick_runs_are_solved_exactly_by_block_elimination_and_by_pcg() {
        // Two stick runs couple through the kernel; block elimination of the shorter run and PCG
        // (run-exact preconditioner) must both agree with dense elimination of G_SS to 1e-10
        // relative (PCG stops at 1e-13 on the residual; the kernel's condition number is ~1e3).
        let contact = Contact::new(
            Profile::hertz(50.0).unwrap(),
            Material::new(200_000.0, 0.3).unwrap(),
            Friction::new(0.6).unwrap(),
        );
        let mut m = Marcher::new(
            &contact,
            1.0,
            &MarchOptions::default().with_cells(64).unwrap(),
        )
        .unwrap();
        let stick: Vec<usize> = (5..20).chain(31..52).collect();
        for (i, c) in m.cells.iter_mut().enumerate() {
            *c = if stick.contains(&i) {
                Cell::Stick
            } else {
                Cell::Slip(1.0)
            };
        }
        for i in 0..64 {
            m.rhs[i] = if stick.contains(&i) {
                (i as f64 * 0.7).sin() + 0.3
            } else {
                0.0
            };
        }
        m.solve_stick(&Rhs::Vector, 1).unwrap();
        // Dense reference from the kernel's definition (half-span 1, so l = 4).
        let g = kernel::cell_row(64, m.cell_width(), 4.0);
        let matrix = stick
            .iter()
            .map(|&i| stick.iter().map(|&j| g[i.abs_diff(j)]).collect())
            .collect();
        let b: Vec<f64> = stick.iter().map(|&i| m.rhs[i]).collect();
        let z = toeplitz::tests::dense_solve(matrix, &b);
        let size = z.iter().fold(0.0f64, |s, v| s.max(v.abs()));
        for (k, &i) in stick.iter().enumerate() {
            assert!(
                (m.u[i] - z[k]).abs() < 1e-10 * size,
                "cell {i}: {} vs {}",
                m.u[i],
                z[k]
            );
        }
        assert!(m
            .u
            .iter()
            .enumerate()
            .all(|(i, v)| stick.contains(&i) || *v == 0.0));
        // The same system by CG alone (the route for many cells outside the longest run).
        let set: Vec<bool> = m.cells.iter().map(|c| *c == Cell::Stick).collect();
        let runs = runs_of(&set);
        let b = m.rhs.clone();
        let mut by_cg = vec![0.0; 64];
        m.pcg(&set, &runs, &b, &mut by_cg, 1).unwrap();
        for (k, &i) in stick.iter().enumerate() {
            assert!(
                (by_cg[i] - z[k]).abs() < 1e-10 * size,
                "CG, cell {i}: {} vs {}",
                by_cg[i],
                z[k]
            );
        }
    }

    #[test]
    fn a_failed_cholesky_pivot_is_its_own_error() {
        // The kernel block is positive definite in exact arithmetic; a matrix that is not must be
        // reported as a non-positive pivot at the cell where it fails, not as an active-set
        // failure. [[1, 2], [2, 1]] fails at its second pivot (1 - 4 < 0).
        let g = [1.0, 2.0, 2.0, 1.0];
        let mut z = [0.0; 2];
        let err = dense_stick_solve(&g, &[true, true], &[1.0, 1.0], &mut z, 7).unwrap_err();
        assert_eq!(err, Error::NonPositivePivot { step: 7, index: 1 });
        assert!(err.to_string().contains("step 7"), "{err}");
    }
}
