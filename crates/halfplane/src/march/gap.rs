//! The normal problem of a gap given at the cell centres of the marching grid (a worn profile,
//! whose gap need not be smooth or convex, and whose contact may split): the pressure
//! piecewise constant on the cells, by an active set on the contact cells.
//!
//! Conventions as the analytic normal problem's (`normal_moment/`): P > 0 compresses, the
//! moment M of the pressure is taken about x = 0, the pad rotates freely by theta and the gap
//! gains `theta x`. The surfaces' relative normal displacement under the pressure is
//! `u(x) = -(A/pi) integral p(xi) ln|x - xi| dxi` (Johnson, *Contact Mechanics*, eq. 2.25a,
//! summed over two similar bodies); its constant is absorbed by the approach `delta`. With the
//! cell matrix `G_ij` of `kernel.rs` (the integral of `-ln(|xi - x_i|/l)` over cell j) the
//! deformed gap at cell i is
//!
//! `h_i = g_i + theta x_i - delta + (A/pi) sum_j G_ij p_j`,
//!
//! and the solution has `p_i >= 0`, `h_i >= 0`, `p_i h_i = 0`, `w sum p = P`,
//! `w sum p x = M` (w the cell width). On a contact set S the pressure is
//! `p = u_g + delta u_1 - theta u_x` with `K u_g = -g`, `K u_1 = 1`, `K u_x = x`,
//! `K = (A/pi) G_SS`, and the two resultants fix delta and theta. The active set drops the
//! cells of negative pressure and adds those of negative gap until neither is left (Kalker's
//! NORM algorithm, *Three-dimensional elastic bodies in rolling contact*, 1990, section 5.3).
//! `K` is SPD Toeplitz on every run of contiguous cells: conjugate gradients with the exact
//! inverse of each run's block as preconditioner (`toeplitz/`), so a contact of one run is
//! solved in one step.
//!
//! Never deals with shear; never knows why the gap is what it is (the wear module's).

use super::toeplitz::Toeplitz;
use crate::error::{Error, Result};

/// Most active-set passes of one solve.
const MAX_PASSES: usize = 500;
/// A pressure below this fraction of the contact's mean pressure is rounding (`Grid::solve`).
const ROUNDING: f64 = 1e-11;
/// Most conjugate-gradient iterations of one system.
const CG_ITERATIONS: usize = 200;

/// A solved contact of a gap on the grid.
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct GapContact {
    /// Pressure per cell (zero out of contact).
    pub(crate) pressure: Vec<f64>,
    /// The rigid approach delta.
    pub(crate) approach: f64,
    /// The pad's rotation theta (the gap gains `theta x`).
    pub(crate) rotation: f64,
}

impl GapContact {
    /// The contact cells (pressure > 0).
    pub(crate) fn in_contact(&self, i: usize) -> bool {
        self.pressure[i] > 0.0
    }
}

/// The grid's data the solve needs: the kernel of the cells, their centres and width, and A.
pub(crate) struct Grid<'a> {
    pub(crate) kernel: &'a mut Toeplitz,
    pub(crate) x: &'a [f64],
    pub(crate) width: f64,
    pub(crate) compliance: f64,
}

impl Grid<'_> {
    /// The contact of the gap `gap` (one value per cell) under P = `normal` and M = `moment`,
    /// from the contact set of `start` when given (a neighbouring solution), else from the cells
    /// whose gap is within a Hertz-like approach of the smallest.
    ///
    /// # Errors
    /// [`Error::ActiveSet`] (step 0) when the active set does not settle within its passes;
    /// [`Error::InvalidInput`] naming `gap` when no contact set carries P and M with
    /// non-negative pressure (a moment beyond the grid).
    pub(crate) fn solve(
        &mut self,
        gap: &[f64],
        normal: f64,
        moment: f64,
        start: Option<&GapContact>,
    ) -> Result<GapContact> {
        let n = self.x.len();
        let mut set: Vec<bool> = match start {
            Some(s) => (0..n).map(|i| s.in_contact(i)).collect(),
            None => self.first_set(gap, normal),
        };
        for _ in 0..MAX_PASSES {
            let (pressure, approach, rotation) = self.on_set(&set, gap, normal, moment)?;
            // Drop the negative pressures first; only a set without them is tested for overlap.
            // A pressure within rounding of zero counts as zero (dropped): left in, a cell worn
            // down to touch at the edge of a worn annulus stayed in contact carrying 1.5e-12 of
            // the mean pressure, on one side only. Dropping it opens a gap of about 1e-11/N of
            // the gap's scale (N cells in contact), below the overlap test's 1e-12.
            let mean = pressure.iter().sum::<f64>() / set.iter().filter(|s| **s).count() as f64;
            let negative: Vec<usize> = (0..n)
                .filter(|&i| set[i] && pressure[i] <= ROUNDING * mean)
                .collect();
            if !negative.is_empty() {
                for i in negative {
                    set[i] = false;
                }
                continue;
            }
            let deformed = self.deformed(&pressure, gap, approach, rotation);
            let scale = gap_scale(gap);
            let overlap: Vec<usize> = (0..n)
                .filter(|&i| !set[i] && deformed[i] < -1e-12 * scale)
                .collect();
            if overlap.is_empty() {
                return Ok(GapContact {
                    pressure,
                    approach,
                    rotation,
                });
            }
            for i in overlap {
                set[i] = true;
            }
        }
        Err(Error::ActiveSet {
            step: 0,
            iterations: MAX_PASSES,
        })
    }

    /// A first contact set: the cells whose gap is within `2 A P/pi` (about a Hertz contact's
    /// approach, times a few) of the smallest gap, at least the smallest's cell.
    fn first_set(&self, gap: &[f64], normal: f64) -> Vec<bool> {
        let low = gap.iter().copied().fold(f64::INFINITY, f64::min);
        let reach = 2.0 * self.compliance * normal / std::f64::consts::PI;
        gap.iter().map(|&g| g - low <= reach).collect()
    }

    /// The pressure, approach and rotation on the contact set `set`.
    fn on_set(
        &mut self,
        set: &[bool],
        gap: &[f64],
        normal: f64,
        moment: f64,
    ) -> Result<(Vec<f64>, f64, f64)> {
        let n = self.x.len();
        if !set.iter().any(|&s| s) {
            return Err(Error::InvalidInput {
                field: "gap".into(),
                value: normal,
                valid: "a gap whose contact carries the load with a non-negative pressure",
            });
        }
        let masked = |f: &dyn Fn(usize) -> f64| -> Vec<f64> {
            (0..n).map(|i| if set[i] { f(i) } else { 0.0 }).collect()
        };
        let u_g = self.cg(set, &masked(&|i| -gap[i]))?;
        let u_1 = self.cg(set, &masked(&|_| 1.0))?;
        let u_x = self.cg(set, &masked(&|i| self.x[i]))?;
        // w sum p = P and w sum p x = M with p = u_g + delta u_1 - theta u_x.
        let w = self.width;
        let sum = |v: &[f64]| w * v.iter().sum::<f64>();
        let first = |v: &[f64]| w * v.iter().zip(self.x).map(|(v, x)| v * x).sum::<f64>();
        let (a11, a12, b1) = (sum(&u_1), -sum(&u_x), normal - sum(&u_g));
        let (a21, a22, b2) = (first(&u_1), -first(&u_x), moment - first(&u_g));
        let det = a11 * a22 - a12 * a21;
        // A single cell cannot take a moment about its own centre: then only the load is held.
        let (approach, rotation) = if det.abs() > 1e-14 * (a11 * a22).abs() {
            ((b1 * a22 - a12 * b2) / det, (a11 * b2 - a21 * b1) / det)
        } else {
            (b1 / a11, 0.0)
        };
        let pressure = (0..n)
            .map(|i| u_g[i] + approach * u_1[i] - rotation * u_x[i])
            .collect();
        Ok((pressure, approach, rotation))
    }

    /// The deformed gap `h_i = g_i + theta x_i - delta + (A/pi) (G p)_i` at every cell.
    fn deformed(
        &mut self,
        pressure: &[f64],
        gap: &[f64],
        approach: f64,
        rotation: f64,
    ) -> Vec<f64> {
        let mut u = vec![0.0; pressure.len()];
        self.kernel.apply(pressure, &mut u);
        let c = self.compliance / std::f64::consts::PI;
        (0..gap.len())
            .map(|i| gap[i] + rotation * self.x[i] - approach + c * u[i])
            .collect()
    }

    /// `K v` on the set: `(A/pi) (G v)_S`, zero elsewhere.
    fn operator(&mut self, set: &[bool], v: &[f64], out: &mut [f64]) {
        self.kernel.apply(v, out);
        let c = self.compliance / std::f64::consts::PI;
        for (i, o) in out.iter_mut().enumerate() {
            *o = if set[i] { c * *o } else { 0.0 };
        }
    }

    /// The preconditioner: each run of contiguous contact cells solved exactly by its block,
    /// `(pi/A) T_n^{-1}`.
    fn precondition(&mut self, set: &[bool], r: &[f64], z: &mut [f64]) {
        z.fill(0.0);
        let c = std::f64::consts::PI / self.compliance;
        let n = set.len();
        let mut i = 0;
        while i < n {
            if !set[i] {
                i += 1;
                continue;
            }
            let start = i;
            while i < n && set[i] {
                i += 1;
            }
            self.kernel.solve(&r[start..i], &mut z[start..i]);
            for v in &mut z[start..i] {
                *v *= c;
            }
        }
    }

    /// Solves `K u = b` on the set (b zero off it) by preconditioned conjugate gradients to
    /// 1e-13 of `|b|` (the preconditioner is exact for a single run: one step).
    fn cg(&mut self, set: &[bool], b: &[f64]) -> Result<Vec<f64>> {
        let n = b.len();
        let norm = |v: &[f64]| v.iter().map(|v| v * v).sum::<f64>().sqrt();
        let target = 1e-13 * norm(b);
        let mut u = vec![0.0; n];
        let mut r = b.to_vec();
        let mut z = vec![0.0; n];
        self.precondition(set, &r, &mut z);
        let mut d = z.clone();
        let mut rz: f64 = r.iter().zip(&z).map(|(r, z)| r * z).sum();
        let mut kd = vec![0.0; n];
        for _ in 0..CG_ITERATIONS {
            if norm(&r) <= target {
                return Ok(u);
            }
            self.operator(set, &d, &mut kd);
            let dkd: f64 = d.iter().zip(&kd).map(|(d, k)| d * k).sum();
            if dkd <= 0.0 {
                break;
            }
            let alpha = rz / dkd;
            for i in 0..n {
                u[i] += alpha * d[i];
                r[i] -= alpha * kd[i];
            }
            self.precondition(set, &r, &mut z);
            let rz_next: f64 = r.iter().zip(&z).map(|(r, z)| r * z).sum();
            let beta = rz_next / rz;
            rz = rz_next;
            for i in 0..n {
                d[i] = z[i] + beta * d[i];
            }
        }
        if norm(&r) <= 1e-9 * norm(b).max(f64::MIN_POSITIVE) {
            return Ok(u);
        }
        Err(Error::NoConvergence {
            what: "pressure of a gap on the grid (conjugate gradients)",
            iterations: CG_ITERATIONS,
            last_step: norm(&r) / norm(b),
        })
    }
}

/// A length scale of the gap for the overlap tolerance: its spread over the grid.
fn gap_scale(gap: &[f64]) -> f64 {
    let (lo, hi) = gap
        .iter()
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(l, h), &g| {
            (l.min(g), h.max(g))
        });
    (hi - lo).max(f64::MIN_POSITIVE)
}

#[cfg(test)]
mod tests {
    use super::super::kernel;
    use super::*;
    use crate::closed_form;

    /// A grid of `n` cells over `[-half, half]` with its kernel.
    fn grid(n: usize, half: f64) -> (Vec<f64>, f64, Toeplitz) {
        let w = 2.0 * half / n as f64;
        let x = (0..n).map(|i| -half + (i as f64 + 0.5) * w).collect();
        let kernel = Toeplitz::new(kernel::cell_row(n, w, 4.0 * half)).unwrap();
        (x, w, kernel)
    }

    #[test]
    fn a_parabolic_gap_has_the_hertz_pressure() {
        // g = x^2/(2R): the cells' pressure against Hertz's sqrt(a^2 - x^2)/(A R) at the centres.
        // Piecewise-constant collocation is first order near the edges, where the exact pressure
        // has a square-root front: the error in the interior (|x| < a/2) is far smaller than at
        // the edges. Tolerances: P and M exact to 1e-12 (they are imposed); the contact's extent
        // within one cell of 2a; the interior pressure within 0.5% of p0 at 400 cells, the
        // largest error within 5% of p0 and halving with the cells.
        let (a_comp, radius, normal) = (1.82e-5, 50.0, 1000.0);
        let a = closed_form::hertz_half_width(a_comp, radius, normal);
        let p0 = closed_form::hertz_pressure(a_comp, radius, a, 0.0);
        for n in [200, 400, 800] {
            let (x, w, mut kernel) = grid(n, 1.5 * a);
            let gap: Vec<f64> = x.iter().map(|x| x * x / (2.0 * radius)).collect();
            let mut g = Grid {
                kernel: &mut kernel,
                x: &x,
                width: w,
                compliance: a_comp,
            };
            let s = g.solve(&gap, normal, 0.0, None).unwrap();
            let total: f64 = w * s.pressure.iter().sum::<f64>();
            let first: f64 = w * s.pressure.iter().zip(&x).map(|(p, x)| p * x).sum::<f64>();
            assert!((total - normal).abs() < 1e-12 * normal, "P {total}");
            assert!(first.abs() < 1e-12 * normal * a, "M {first}");
            assert!(
                s.rotation.abs() < 1e-12,
                "a symmetric gap does not tilt: {}",
                s.rotation
            );
            let cells = s.pressure.iter().filter(|&&p| p > 0.0).count() as f64;
            // One cell at each edge either way: an edge cell whose centre lies just outside the
            // exact contact may carry a small pressure.
            assert!(
                (cells * w - 2.0 * a).abs() <= 2.0 * w,
                "{cells} cells against 2a = {}",
                2.0 * a
            );
            let error = |inner: bool| {
                x.iter()
                    .zip(&s.pressure)
                    .filter(|(x, _)| !inner || x.abs() < 0.5 * a)
                    .map(|(&x, &p)| (p - closed_form::hertz_pressure(a_comp, radius, a, x)).abs())
                    .fold(0.0, f64::max)
                    / p0
            };
            let (inner, all) = (error(true), error(false));
            assert!(inner < 1e-4, "{n} cells: interior error {inner}");
            assert!(all < 0.02, "{n} cells: largest error {all}");
        }
    }

    #[test]
    fn a_moment_moves_a_parabolic_contact_by_m_over_p() {
        // Hertz under M: the contact of the parabola moved by e = M/P, the rotation -e/R (the
        // analytic route's closed form). The cell pressure's centroid is M/P by construction; the
        // rotation within 1% (a cell's worth of the contact's asymmetry at 400 cells).
        let (a_comp, radius, normal, e) = (1.82e-5, 50.0, 1000.0, 0.2);
        let a = closed_form::hertz_half_width(a_comp, radius, normal);
        let (x, w, mut kernel) = grid(400, 1.5 * a + e);
        let gap: Vec<f64> = x.iter().map(|x| x * x / (2.0 * radius)).collect();
        let mut g = Grid {
            kernel: &mut kernel,
            x: &x,
            width: w,
            compliance: a_comp,
        };
        let s = g.solve(&gap, normal, e * normal, None).unwrap();
        let expected = -e / radius;
        assert!(
            (s.rotation - expected).abs() < 1e-2 * expected.abs(),
            "rotation {} against {expected}",
            s.rotation
        );
        let first = x.iter().zip(&s.pressure).find(|(_, &p)| p > 0.0).unwrap().0;
        assert!(
            (first - (e - a)).abs() <= w,
            "left end {first} against {}",
            e - a
        );
        // A gap of a pad pressed off its table cannot carry the moment: named error, not NaN.
        let far = g.solve(&gap, normal, 10.0 * a * normal, None);
        assert!(far.is_err() || far.unwrap().pressure.iter().all(|p| p.is_finite()));
    }
}
