//! The crack's influence matrices and the open-crack solve: the distributed dislocation
//! technique (Hills et al. 1996) with the half-plane kernel of `kernel.rs` and the rule of
//! `quadrature.rs`.
//!
//! Unknowns: the densities of glide (`b1`, along `e1`, mouth to tip) and climb (`b2`, along
//! `e2`, a quarter turn from `e1` towards `+z` from `+x`) dislocations, written
//! `A b_j = w(t) psi_j(t)` (`A` of `kernel.rs`). Equations: at each collocation point the
//! traction `s22`, `s12` (frame `e1`, `e2`) of the uncracked stress plus the dislocations'
//! vanishes (open faces). Opening and slip are `delta_j(s) = integral_s^l b_j`, the displacement
//! of the `+e2` face less that of the `-e2` face (positive opening under tension).
//! `K_I = pi sqrt(2 pi l) psi_2(1)`: a Griffith crack's density near its tip is
//! `b_2 = K_I/(A pi sqrt(2 pi r))` at distance `r` (the Griffith crack under tension `sigma` has
//! `b_2 = sigma xi/(A pi sqrt(a^2 - xi^2))` with the kernel's `A/(s - xi)` on its line, and
//! `K_I = sigma sqrt(pi a)`), and `sqrt(l - xi) w(t) -> sqrt(l)` at the tip. `K_II = -pi sqrt(2 pi l) psi_1(1)`: the same with
//! the shear `tau` on the normal `n = -e2` of the module doc of [`super`].

use super::kernel::{dislocation_stress, C};
use super::quadrature::Rule;
use super::Crack;
use crate::error::{Error, Result};
use crate::material::Material;

/// Fewest and most quadrature points per component.
pub const MIN_POINTS: usize = 4;
/// See [`MIN_POINTS`]; the dense system has `2 x points` unknowns.
pub const MAX_POINTS: usize = 400;

/// Stress intensity factors at the tip (stress times square root of length).
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct TipFactors {
    /// Mode I.
    pub k1: f64,
    /// Mode II (sign of the module doc of [`super`]).
    pub k2: f64,
}

/// One crack assembled. The densities `psi` solve `M psi = t`, `M` the influence of the
/// densities on the tractions `t` (`s22` at every collocation point, then `s12`) that the
/// dislocations must produce: `t = c - load` with `load` the uncracked tractions and `c` the
/// tractions the faces carry (zero where they are apart). Everything the face contact needs is
/// linear in `t`, so it is kept as maps of `t`: the face displacements (the face compliance
/// `W = D M^-1`, `D` the tail integrals) and the tip factors.
#[derive(Debug, Clone)]
pub struct CrackSolver {
    pub(super) crack: Crack,
    pub(super) n: usize,
    /// `A = 2 mu/(pi (kappa + 1)) = E/(4 pi (1 - nu^2))`.
    pub(super) a: f64,
    /// `W` (row-major, 2n x 2n): rows `A delta_1` (slip) at `k` then `A delta_2` (opening) at `k`;
    /// columns `t` (`s22` at `k` then `s12` at `k`).
    pub(super) compliance: Vec<f64>,
    /// `K_I` and `K_II` per unit `t` (rows of length 2n).
    pub(super) tip_rows: [Vec<f64>; 2],
    /// Collocation points (body coordinates) and their distance from the mouth.
    x: Vec<f64>,
    z: Vec<f64>,
    s: Vec<f64>,
}

impl CrackSolver {
    /// Assembles `crack` in `material` with `points` quadrature points per component
    /// ([`MIN_POINTS`] to [`MAX_POINTS`]).
    pub fn new(crack: &Crack, material: &Material, points: usize) -> Result<Self> {
        if !(MIN_POINTS..=MAX_POINTS).contains(&points) {
            return Err(Error::InvalidCount {
                field: "crack.points".into(),
                value: points as u64,
                min: MIN_POINTS as u64,
                max: MAX_POINTS as u64,
            });
        }
        let n = points;
        let n2 = 2 * n;
        let rule = Rule::new(n)?;
        let l = crack.length;
        let (e1, e2) = crack.frame();
        let along = C::new(e1[0], e1[1]);
        let at = |s: f64| C::new(s * e1[0], s * e1[1]); // relative to the mouth
        let xi: Vec<f64> = rule.nodes.iter().map(|t| 0.5 * l * (1.0 + t)).collect();
        let s: Vec<f64> = rule
            .collocation
            .iter()
            .map(|u| 0.5 * l * (1.0 + u))
            .collect();
        let mut influence = vec![0.0; n2 * n2];
        for (k, &sk) in s.iter().enumerate() {
            for (i, &xii) in xi.iter().enumerate() {
                let scale = 0.5 * l * rule.weights[i];
                for (j, b) in [along, C::new(e2[0], e2[1])].into_iter().enumerate() {
                    let st = dislocation_stress(at(sk), at(xii), b);
                    let [s22, s12] = resolve(st, e1, e2);
                    influence[k * n2 + j * n + i] = scale * s22;
                    influence[(n + k) * n2 + j * n + i] = scale * s12;
                }
            }
        }
        let tail: Vec<Vec<f64>> = rule
            .collocation
            .iter()
            .map(|&u| rule.tail_integrals(u).iter().map(|v| 0.5 * l * v).collect())
            .collect();
        let lu = Lu::factor(influence, n2).ok_or(Error::NoConvergence {
            what: "the crack's influence matrix (singular)",
            iterations: 0,
            last_step: f64::NAN,
        })?;
        // M^-1 column by column, stored row-major.
        let mut inverse = vec![0.0; n2 * n2];
        let mut e = vec![0.0; n2];
        for c in 0..n2 {
            e.fill(0.0);
            e[c] = 1.0;
            lu.solve(&mut e);
            for (r, v) in e.iter().enumerate() {
                inverse[r * n2 + c] = *v;
            }
        }
        let row = |r: usize| &inverse[r * n2..(r + 1) * n2];
        let mut compliance = vec![0.0; n2 * n2];
        for (k, tk) in tail.iter().enumerate() {
            for j in 0..2 {
                let out = &mut compliance[(j * n + k) * n2..(j * n + k + 1) * n2];
                for (i, w) in tk.iter().enumerate() {
                    for (o, v) in out.iter_mut().zip(row(j * n + i)) {
                        *o += w * v;
                    }
                }
            }
        }
        // K_I = c psi_2(1), K_II = -c psi_1(1), psi_j(1) the interpolant at the tip.
        let at_tip = rule.basis(1.0);
        let c = std::f64::consts::PI * (2.0 * std::f64::consts::PI * l).sqrt();
        let mut tip_rows = [vec![0.0; n2], vec![0.0; n2]];
        for (i, w) in at_tip.iter().enumerate() {
            for (c1, v) in tip_rows[0].iter_mut().zip(row(n + i)) {
                *c1 += c * w * v;
            }
            for (c2, v) in tip_rows[1].iter_mut().zip(row(i)) {
                *c2 -= c * w * v;
            }
        }
        let nu = material.poisson_ratio();
        Ok(Self {
            crack: *crack,
            n,
            a: material.youngs_modulus() / (4.0 * std::f64::consts::PI * (1.0 - nu * nu)),
            compliance,
            tip_rows,
            x: s.iter().map(|&si| crack.mouth + si * e1[0]).collect(),
            z: s.iter().map(|&si| si * e1[1]).collect(),
            s,
        })
    }

    /// The crack.
    pub fn crack(&self) -> &Crack {
        &self.crack
    }

    /// The collocation points' `x` (body coordinates of [`crate::stress`]), tip first.
    pub fn x(&self) -> &[f64] {
        &self.x
    }

    /// The collocation points' depths `z`, tip first.
    pub fn z(&self) -> &[f64] {
        &self.z
    }

    /// The collocation points' distances from the mouth along the crack, tip first.
    pub fn distances(&self) -> &[f64] {
        &self.s
    }

    /// The normal stress `s_nn` and the shear stress `tau = e_s . s . n` on the crack line from
    /// the stress components `(sxx, szz, sxz)` (the frame of the module doc of [`super`]).
    pub fn resolve(&self, sxx: f64, szz: f64, sxz: f64) -> (f64, f64) {
        let (e1, e2) = self.crack.frame();
        let [s22, s12] = resolve([sxx, szz, sxz], e1, e2);
        (s22, -s12)
    }

    /// The tip factors of the open crack whose faces carry no traction, given the uncracked
    /// normal stress `normal` and shear stress `shear` at the collocation points (as
    /// [`Self::resolve`] gives them), with no face contact: `K_I` may come out negative
    /// (interpenetration; see [`Self::cycle`] for the contact solution). Errors: lengths not
    /// equal to the number of points, or values not finite.
    pub fn open(&self, normal: &[f64], shear: &[f64]) -> Result<TipFactors> {
        self.check_loads(normal, shear)?;
        let t = self.free_tractions(normal, shear);
        Ok(self.tip(&t))
    }

    /// `t` of the open crack: minus the uncracked `s22 = normal`, `s12 = -shear`.
    pub(super) fn free_tractions(&self, normal: &[f64], shear: &[f64]) -> Vec<f64> {
        normal
            .iter()
            .map(|v| -v)
            .chain(shear.iter().copied())
            .collect()
    }

    pub(super) fn check_loads(&self, normal: &[f64], shear: &[f64]) -> Result<()> {
        for (field, v) in [
            ("crack normal stress", normal),
            ("crack shear stress", shear),
        ] {
            if v.len() != self.n {
                return Err(Error::LengthMismatch {
                    field: field.into(),
                    length: v.len(),
                    expected: self.n,
                    per: "one value per collocation point of the crack",
                });
            }
            if let Some(bad) = v.iter().find(|x| !x.is_finite()) {
                return Err(Error::InvalidInput {
                    field: field.into(),
                    value: *bad,
                    valid: "a finite stress at every collocation point",
                });
            }
        }
        Ok(())
    }

    /// `K_I`, `K_II` of the tractions `t`.
    pub(super) fn tip(&self, t: &[f64]) -> TipFactors {
        let dot = |r: &[f64]| r.iter().zip(t).map(|(a, b)| a * b).sum::<f64>();
        TipFactors {
            k1: dot(&self.tip_rows[0]),
            k2: dot(&self.tip_rows[1]),
        }
    }
}

/// `[s22, s12]` of `[sxx, szz, sxz]` in the frame `(e1, e2)` (unit vectors in `(x, z)`).
pub(super) fn resolve(st: [f64; 3], e1: [f64; 2], e2: [f64; 2]) -> [f64; 2] {
    let [sxx, szz, sxz] = st;
    let s22 = e2[0] * e2[0] * sxx + 2.0 * e2[0] * e2[1] * sxz + e2[1] * e2[1] * szz;
    let s12 = e1[0] * e2[0] * sxx + (e1[0] * e2[1] + e1[1] * e2[0]) * sxz + e1[1] * e2[1] * szz;
    [s22, s12]
}

/// A dense LU factorisation with partial pivoting (Golub and Van Loan, *Matrix Computations*,
/// algorithm 3.4.1).
#[derive(Debug, Clone)]
pub(super) struct Lu {
    lu: Vec<f64>,
    piv: Vec<usize>,
    n: usize,
}

impl Lu {
    /// Factors the row-major `n x n` matrix `a`; `None` if a pivot is zero or not finite.
    pub fn factor(mut a: Vec<f64>, n: usize) -> Option<Self> {
        let mut piv: Vec<usize> = (0..n).collect();
        for c in 0..n {
            let p = (c..n).max_by(|&i, &j| a[i * n + c].abs().total_cmp(&a[j * n + c].abs()))?;
            let pivot = a[p * n + c];
            if pivot == 0.0 || !pivot.is_finite() {
                return None;
            }
            if p != c {
                for k in 0..n {
                    a.swap(p * n + k, c * n + k);
                }
                piv.swap(p, c);
            }
            // Rows below the pivot row, each updated from the pivot row's tail (slices, so the
            // update is a vector loop without bounds checks).
            let (upper, lower) = a.split_at_mut((c + 1) * n);
            let pivot_row = &upper[c * n + c + 1..(c + 1) * n];
            for row in lower.chunks_exact_mut(n) {
                let f = row[c] / pivot;
                row[c] = f;
                if f != 0.0 {
                    for (x, p) in row[c + 1..].iter_mut().zip(pivot_row) {
                        *x -= f * p;
                    }
                }
            }
        }
        Some(Self { lu: a, piv, n })
    }

    /// Solves in place.
    pub fn solve(&self, b: &mut [f64]) {
        let n = self.n;
        let mut x: Vec<f64> = self.piv.iter().map(|&p| b[p]).collect();
        for r in 0..n {
            let row = &self.lu[r * n..r * n + r];
            let s: f64 = row.iter().zip(&x[..r]).map(|(a, b)| a * b).sum();
            x[r] -= s;
        }
        for r in (0..n).rev() {
            let row = &self.lu[r * n + r + 1..(r + 1) * n];
            let s: f64 = row.iter().zip(&x[r + 1..]).map(|(a, b)| a * b).sum();
            x[r] = (x[r] - s) / self.lu[r * n + r];
        }
        b.copy_from_slice(&x);
    }
}
