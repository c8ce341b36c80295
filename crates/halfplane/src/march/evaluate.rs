//! One solve of a sub-step on a [`Layout`](super::layout::Layout): the traction increments, the
//! slips and, at each boundary inside a cell, the jump of the traction there
//! (`docs/convergence.md`, "Sub-cell stick-slip boundaries").
//!
//! The traction increment is the sum of
//! - known parts: on slipping cells the limit `s f p` less the old traction, both as a cell
//!   mean and a first-moment slope (`moments.rs`); on cells out of contact minus the old traction;
//!   on the slip part of a boundary cell the limit less the old traction there; minus the
//!   sub-cell shapes of old boundaries that this layout erases (`boundary.rs`), and on each
//!   boundary element the square roots of the start's kinks it holds (`chain.rs`, `Held`);
//! - one unknown constant per free stick cell (a run of them sees the Toeplitz kernel);
//! - per boundary inside a cell, two more unknowns: the constant of its boundary element and the
//!   amplitude of the square root `sqrt(|x - at|)` over its zone, the shape the traction takes at
//!   a stick-slip boundary (its slip grows like `|x - at|^(3/2)`);
//! - on the boundary element, a known ramp with the limit's slope through zero at `at`: the stick
//!   side is `s f p(x) - K sqrt(|x - at|) + O(|x - at|^(3/2))`: a kink `|x - at|` on one side
//!   would put a term `d log d` into the tangential strain in the stick zone, which stick (a
//!   rigid displacement increment there) forbids, while half-integer powers put nothing there.
//!   A constant alone misplaced `at` by the limit's slope times half the element (0.013 cells
//!   seven cells from a contact edge).
//!
//! Stick holds at the free cells' centres, at each element's collocation point and at each
//! boundary itself; the resultant is the shear. The free cells are eliminated with the solver of
//! `solve.rs` (one solve for the load, one per boundary unknown, and the cached all-ones solve),
//! leaving a small dense system (Golub & Van Loan, *Matrix Computations*, 4th ed., section
//! 3.2.11, block elimination). The jump `s q(at-) - f p(at)` is what `boundary.rs` drives to zero
//! by moving `at`: it vanishes only where the stick traction meets the limit continuously.
//!
//! Sign convention as in `marcher.rs`. Owns this solve only. Never moves a boundary and never
//! changes the marcher's state fields (it writes the increments into work buffers).

use super::chain::{merged_amplitude, Held, Piece, SAME_KINK};
use super::kernel::{cell_kernels, Element, Shape};
use super::layout::{Layout, Role};
use super::marcher::Marcher;
use super::moments::root_moments;
use super::solve::apply;
use crate::error::{Error, Result};
use std::f64::consts::PI;

/// The solution at one boundary inside a cell.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(super) struct EndSolution {
    /// The boundary element's constant increment.
    pub constant: f64,
    /// The amplitude of `sqrt(|x - at|)` in the traction (the increment's, and those of the
    /// located start's kinks the boundary took over, `chain.rs`).
    pub amplitude: f64,
    /// The amplitudes of the start's kinks held at their own places within
    /// [`super::chain::SAME_KINK`] cells of the boundary: reported with its own (the stresses'
    /// node form has one node there), not kept with it.
    pub nearby: f64,
    /// `s q(at-) - f p(at)`: how far the stick side's traction at the boundary exceeds the limit.
    pub jump: f64,
}

/// An unknown's traction shape: an element exact everywhere, or, for a boundary's root, exact
/// near the boundary (`near`) and by cell means and slopes beyond (`far`).
pub(super) struct Special {
    pub near: Element,
    /// The whole root, for its value at a point.
    whole: Option<Element>,
    pub far: Option<(Vec<f64>, Vec<f64>)>,
}

impl Special {
    fn exact(element: Element) -> Self {
        Self {
            near: element,
            whole: None,
            far: None,
        }
    }

    /// The shape's value at `y`.
    fn value(&self, y: f64) -> f64 {
        self.whole.as_ref().unwrap_or(&self.near).value(y)
    }

    /// Its integral.
    fn integral(&self, width: f64) -> f64 {
        self.near.moment(0, 0.0)
            + self
                .far
                .as_ref()
                .map_or(0.0, |(m, _)| width * m.iter().sum::<f64>())
    }
}

/// Cells within which a root is integrated exactly (beyond, by its cell means and slopes).
const NEAR: f64 = 3.0;

/// A traction shape with a known coefficient.
pub(super) struct Known {
    pub element: Element,
    pub coefficient: f64,
}

impl Marcher {
    /// Solves the current sub-step on `layout` (tension change `d_sigma`, total shear `shear`)
    /// from the start whose centre values are `traction`, whose smooth part has the cell means
    /// and slopes `start_mean` and `start_slope`, and, from a located start (`chain.rs`), its
    /// pieces and kinks. Writes `dq` (centre values), `end_model` (the model's cells at the
    /// end), `sub_slip`, `known` and `g_known` (for `dissipation.rs`) and the
    /// rigid shift; returns the solution at each boundary.
    pub(super) fn evaluate(
        &mut self,
        layout: &Layout,
        d_sigma: f64,
        shear: f64,
        step: usize,
    ) -> Result<Vec<EndSolution>> {
        let n = self.x.len();
        let (w, f, scale) = (self.width, self.friction, self.scale);
        // Known increments of whole cells as a mean and a slope: the start's smooth part goes
        // (`start_mean`, `start_slope`: the cell-level constants, or a located start's,
        // `chain.rs`) and the limit of a slipping cell comes.
        let (mut km, mut ks) = (vec![0.0; n], vec![0.0; n]);
        for i in 0..n {
            (km[i], ks[i]) = match layout.roles[i] {
                Role::Out => (-self.start_mean[i], -self.start_slope[i]),
                Role::Slip(s) => (
                    s * self.limit_mean[i] - self.start_mean[i],
                    s * self.limit_slope[i] - self.start_slope[i],
                ),
                Role::Free | Role::Element => (0.0, 0.0),
            };
        }
        let mut g_std = vec![0.0; n];
        self.kernel.apply_moments(&km, &ks, &mut g_std);
        // Known special shapes: on each boundary's cells the old traction goes (the element
        // carries a constant of its own and the roots) and the slip part takes the limit, linear
        // with its exact mean and first moment.
        let slopes = layout
            .ends
            .iter()
            .map(|e| self.element_slope(e))
            .collect::<Result<Vec<f64>>>()?;
        let mut known: Vec<Known> = Vec::new();
        for (j, e) in layout.ends.iter().enumerate() {
            let [lo, hi] = e.slip_part;
            if hi > lo {
                let [value, slope] = self.limit_fit(e.cell, e.sign, lo, hi);
                known.push(Known {
                    element: Element::new(
                        lo,
                        hi,
                        Shape::Affine {
                            centre: 0.5 * (lo + hi),
                            value,
                            slope,
                        },
                    ),
                    coefficient: 1.0,
                });
            }
            // The element's traction follows the limit's slope on top of its constant: near a
            // boundary the stick side is `s f p(x) - K sqrt(|x - at|) + O(|x - at|^(3/2))`.
            let [lo, hi] = e.support;
            known.push(Known {
                element: Element::new(
                    lo,
                    hi,
                    Shape::Affine {
                        centre: e.at,
                        value: 0.0,
                        slope: slopes[j],
                    },
                ),
                coefficient: 1.0,
            });
            for i in [e.cell, e.merged] {
                let xi = self.x[i];
                known.push(Known {
                    element: Element::new(
                        xi - 0.5 * w,
                        xi + 0.5 * w,
                        Shape::Affine {
                            centre: xi,
                            value: self.start_mean[i],
                            slope: self.start_slope[i],
                        },
                    ),
                    coefficient: -1.0,
                });
            }
        }
        // A located start's exact pieces go where the cell does not stay stuck, and its kinks
        // inside an element come back on it (`chain.rs`, `Held`).
        let start = self.stretch.as_ref().map(|s| &s.start);
        let pieces: &[Piece] = start.map_or(&[], |m| &m.cells.pieces);
        let held: Vec<Vec<Held>> = layout
            .ends
            .iter()
            .map(|e| start.map_or(Vec::new(), |m| m.held(e, w)))
            .collect();
        let pieces_resultant: f64 = pieces
            .iter()
            .map(|p| p.coefficient * p.element.moment(0, 0.0))
            .sum();
        for p in pieces.iter().filter(|p| layout.roles[p.cell] != Role::Free) {
            known.push(Known {
                element: p.element.clone(),
                coefficient: -p.coefficient,
            });
        }
        for (e, hs) in layout.ends.iter().zip(&held) {
            for h in hs {
                known.push(Known {
                    element: h.root(e),
                    coefficient: h.kink.amplitude,
                });
            }
        }
        // Unknown special shapes: per boundary, its element's constant and its square root (the
        // root exact within NEAR cells of its boundary, by cell means and slopes beyond, where it
        // is smooth: its closed form at every centre cost 17 times the cell-level march).
        let mut unknown: Vec<Special> = Vec::new();
        for e in &layout.ends {
            let [lo, hi] = e.support;
            unknown.push(Special::exact(Element::new(
                lo,
                hi,
                Shape::Affine {
                    centre: 0.5 * (lo + hi),
                    value: 1.0,
                    slope: 0.0,
                },
            )));
            unknown.push(self.root_special(e));
        }
        // Collocation points beyond the free centres: each element's, and each boundary.
        let points: Vec<f64> = layout.ends.iter().flat_map(|e| [e.colloc, e.at]).collect();
        let known_field = |y: f64| {
            known
                .iter()
                .map(|k| k.coefficient * k.element.kernel(y, scale))
                .sum::<f64>()
        };
        let spec: Vec<f64> = self.x.iter().map(|&y| known_field(y)).collect();
        let spec_points: Vec<f64> = points.iter().map(|&y| known_field(y)).collect();
        let columns: Vec<Vec<f64>> = (0..unknown.len())
            .map(|q| self.special_column(&unknown[q]))
            .collect();
        // Right-hand sides: stick means G dq = -(pi/4) d_sigma x - c at every collocation point.
        let free = layout.free();
        let quarter = 0.25 * PI * d_sigma;
        let rhs: Vec<f64> = (0..n)
            .map(|i| {
                if free[i] {
                    -(g_std[i] + spec[i]) - quarter * self.x[i]
                } else {
                    0.0
                }
            })
            .collect();
        let rhs_points: Vec<f64> = points
            .iter()
            .zip(&spec_points)
            .map(|(&y, s)| -(self.standard_at(y, &km, &ks) + s) - quarter * y)
            .collect();
        // Eliminate the free cells.
        let mut u = vec![0.0; n];
        self.solve_set(&free, &rhs, &mut u, step)?;
        self.solve_ones(&free, step)?;
        let v = self.v.clone();
        let mut ws: Vec<Vec<f64>> = Vec::with_capacity(unknown.len());
        for col in &columns {
            let b: Vec<f64> = (0..n).map(|i| if free[i] { col[i] } else { 0.0 }).collect();
            let mut z = vec![0.0; n];
            self.solve_set(&free, &b, &mut z, step)?;
            ws.push(z);
        }
        // The small system in the special unknowns and the shift c.
        let m = unknown.len();
        let size = m + 1;
        let mut a = vec![0.0; size * size];
        let mut r = vec![0.0; size];
        for (p, &y) in points.iter().enumerate() {
            let row = self.free_row(y, &free);
            let dot = |z: &[f64]| row.iter().zip(z).map(|(g, z)| g * z).sum::<f64>();
            for q in 0..m {
                a[p * size + q] = self.special_at(&unknown[q], y) - dot(&ws[q]);
            }
            a[p * size + m] = 1.0 - dot(&v);
            r[p] = rhs_points[p] - dot(&u);
        }
        let sum = |z: &[f64]| {
            z.iter()
                .zip(&free)
                .filter(|p| *p.1)
                .map(|p| p.0)
                .sum::<f64>()
        };
        for q in 0..m {
            a[m * size + q] = unknown[q].integral(w) - w * sum(&ws[q]);
        }
        a[m * size + m] = -w * sum(&v);
        let old: f64 = w * (self.start_mean.iter().sum::<f64>() + km.iter().sum::<f64>())
            + pieces_resultant
            + known
                .iter()
                .map(|k| k.coefficient * k.element.moment(0, 0.0))
                .sum::<f64>();
        r[m] = shear - old - w * sum(&u);
        let solution = if m == 0 && !free.contains(&true) {
            // No cell centre is stuck in contact (a contact narrower than a cell): nothing can
            // carry the shear's change, as with the cell-level solver; the shift is arbitrary.
            vec![0.0]
        } else {
            lu_solve(&mut a, &mut r, size).ok_or(Error::ActiveSet {
                step,
                iterations: 0,
            })?
        };
        let (specials, c) = (&solution[..m], solution[m]);
        // Free cells' constants.
        let mut z = vec![0.0; n];
        for i in 0..n {
            if free[i] {
                z[i] = u[i] - c * v[i] - (0..m).map(|q| ws[q][i] * specials[q]).sum::<f64>();
            }
        }
        self.shift = c;
        self.increments(layout, &unknown, specials, &slopes, &held, &z);
        let start = self.stretch.as_ref().map(|s| &s.start);
        self.end_model =
            Some(self.located_model(layout, &unknown, specials, &slopes, &held, &z, start));
        // Displacement at every centre, for the slips: G dq.
        let mut g_free = vec![0.0; n];
        apply(&mut self.kernel, &self.dense, &z, &mut g_free);
        let c_disp = self.compliance / PI;
        for i in 0..n {
            let g = g_std[i]
                + spec[i]
                + g_free[i]
                + (0..m).map(|q| columns[q][i] * specials[q]).sum::<f64>();
            self.sub_slip[i] = match layout.roles[i] {
                Role::Out | Role::Free => 0.0,
                _ if layout.sticks(i, self.x[i]) => 0.0,
                _ => -c_disp * (g + quarter * self.x[i] + c),
            };
        }
        self.known.copy_from_slice(&km);
        self.g_known.copy_from_slice(&g_std);
        // The jump at each boundary: the stick side's traction there against the limit.
        let mut out = Vec::with_capacity(layout.ends.len());
        for (j, e) in layout.ends.iter().enumerate() {
            let roots: f64 = layout
                .ends
                .iter()
                .enumerate()
                .filter(|(_, o)| o.zone == e.zone)
                .map(|(q, _)| specials[2 * q + 1] * unknown[2 * q + 1].near.value(e.at))
                .sum();
            let q = specials[2 * j] + roots;
            let p = self.pressure_at(e.at)?;
            out.push(EndSolution {
                constant: specials[2 * j],
                amplitude: specials[2 * j + 1] + merged_amplitude(&held[j]),
                nearby: (held[j].iter())
                    .filter(|h| !h.merged && (h.kink.x - e.at).abs() < SAME_KINK * w)
                    .map(|h| h.kink.amplitude)
                    .sum(),
                jump: e.sign * q - f * p,
            });
        }
        Ok(out)
    }

    /// The root of boundary `e` as an unknown's shape: exact on the cells within [`NEAR`] cells
    /// of the boundary, cell means and slopes on the rest of its window.
    fn root_special(&self, e: &super::layout::SoftEnd) -> Special {
        let (lo, hi, shape) = e.root();
        let w = self.width;
        let edge0 = self.x[0] - 0.5 * w;
        // The near part, from a cell edge NEAR cells or more from the boundary.
        let (near_lo, near_hi) = if e.side > 0.0 {
            let k = ((e.at - NEAR * w - edge0) / w).floor();
            ((edge0 + k * w).max(lo), hi)
        } else {
            let k = ((e.at + NEAR * w - edge0) / w).ceil();
            (lo, (edge0 + k * w).min(hi))
        };
        let near = Element::new(near_lo, near_hi, shape);
        let whole = Element::new(lo, hi, shape);
        let (a, b) = if e.side > 0.0 {
            (lo, near_lo)
        } else {
            (near_hi, hi)
        };
        if b <= a {
            return Special::exact(near);
        }
        let n = self.x.len();
        let (mut mean, mut slope) = (vec![0.0; n], vec![0.0; n]);
        let first = ((a - edge0) / w).floor().max(0.0) as usize;
        for j in first..n {
            let xc = self.x[j];
            let (cl, ch) = ((xc - 0.5 * w).max(a), (xc + 0.5 * w).min(b));
            if cl >= b {
                break;
            }
            if ch <= cl {
                continue;
            }
            let [m0, m1] = root_moments(e.at, e.side, e.window, xc, cl, ch);
            mean[j] = m0 / w;
            slope[j] = 12.0 * m1 / (w * w * w);
        }
        Special {
            near,
            whole: Some(whole),
            far: Some((mean, slope)),
        }
    }

    /// An unknown shape's kernel at every centre.
    fn special_column(&mut self, sp: &Special) -> Vec<f64> {
        let mut col: Vec<f64> = self
            .x
            .iter()
            .map(|&y| sp.near.kernel(y, self.scale))
            .collect();
        if let Some((mean, slope)) = &sp.far {
            let mut far = vec![0.0; col.len()];
            self.kernel.apply_moments(mean, slope, &mut far);
            for (c, f) in col.iter_mut().zip(far) {
                *c += f;
            }
        }
        col
    }

    /// An unknown shape's kernel at a point `y`.
    fn special_at(&self, sp: &Special, y: f64) -> f64 {
        sp.near.kernel(y, self.scale)
            + sp.far
                .as_ref()
                .map_or(0.0, |(m, s)| self.standard_at(y, m, s))
    }

    /// `sum_j [mean_j G(y, cell j) + slope_j S(y, cell j)]` at a point y: the kernel of the
    /// cells' means and slopes at a point that need not be a centre.
    fn standard_at(&self, y: f64, mean: &[f64], slope: &[f64]) -> f64 {
        let h = 0.5 * self.width;
        self.x
            .iter()
            .zip(mean.iter().zip(slope))
            .filter(|(_, (m, s))| **m != 0.0 || **s != 0.0)
            .map(|(&xc, (m, s))| {
                let [g0, g1] = cell_kernels(y - xc, h, self.scale);
                m * g0 + s * g1
            })
            .sum()
    }

    /// The kernel `G(y, cell j)` of every free cell at the point y (zero elsewhere).
    fn free_row(&self, y: f64, free: &[bool]) -> Vec<f64> {
        let h = 0.5 * self.width;
        self.x
            .iter()
            .zip(free)
            .map(|(&xc, &fr)| {
                if fr {
                    cell_kernels(y - xc, h, self.scale)[0]
                } else {
                    0.0
                }
            })
            .collect()
    }

    /// The increments of the cells' centre values (`dq`) from a solution: free constants `z`,
    /// special unknowns `specials` (per boundary, the element's constant and the root's
    /// amplitude).
    fn increments(
        &mut self,
        layout: &Layout,
        unknown: &[Special],
        specials: &[f64],
        slopes: &[f64],
        held: &[Vec<Held>],
        z: &[f64],
    ) {
        let f = self.friction;
        let roots_at = |y: f64| -> f64 {
            (0..layout.ends.len())
                .map(|q| specials[2 * q + 1] * unknown[2 * q + 1].value(y))
                .sum()
        };
        for (i, &zi) in z.iter().enumerate() {
            let xi = self.x[i];
            self.dq[i] = match layout.roles[i] {
                Role::Out => -self.traction[i],
                Role::Slip(s) => s * f * self.pressure[i] - self.traction[i],
                Role::Free => zi + roots_at(xi),
                Role::Element => {
                    let (q, e) = layout
                        .ends
                        .iter()
                        .enumerate()
                        .find(|(_, e)| e.cell == i || e.merged == i)
                        .expect("an element cell belongs to a boundary");
                    // The element's constant with the roots on the stick side, the limit beyond.
                    let q_new = if e.side * (xi - e.at) < 0.0 {
                        specials[2 * q]
                            + slopes[q] * (xi - e.at)
                            + roots_at(xi)
                            + held[q]
                                .iter()
                                .map(|h| h.kink.amplitude * h.root(e).value(xi))
                                .sum::<f64>()
                    } else {
                        e.sign * f * self.pressure[i]
                    };
                    q_new - self.traction[i]
                }
            };
        }
    }

    /// The slope of the limit `s f p` across boundary `e`'s element (the secant over its
    /// support), which the element's traction follows on top of its constant.
    fn element_slope(&self, e: &super::layout::SoftEnd) -> Result<f64> {
        let [lo, hi] = e.support;
        let dp = self.pressure_at(hi)? - self.pressure_at(lo)?;
        Ok(e.sign * self.friction * dp / (hi - lo))
    }

    /// The limit `s f p` on `[lo, hi]` inside cell `i` as `[value at the midpoint, slope]`, with
    /// its exact mean and first moment (`moments.rs`).
    pub(super) fn limit_fit(&self, i: usize, sign: f64, lo: f64, hi: f64) -> [f64; 2] {
        let len = hi - lo;
        if len <= 0.0 {
            return [0.0; 2];
        }
        let c = 0.5 * (lo + hi);
        let [m0, m1] = self.shape.moments(i, c, self.width, lo, hi);
        let f = self.friction;
        [
            sign * f * m0 / len,
            sign * f * 12.0 * m1 / (len * len * len),
        ]
    }
}

/// Solves the dense `size x size` system `a x = r` (row-major) by Gaussian elimination with
/// partial pivoting; `None` if it is singular.
pub(super) fn lu_solve(a: &mut [f64], r: &mut [f64], size: usize) -> Option<Vec<f64>> {
    for c in 0..size {
        let p =
            (c..size).max_by(|&i, &j| a[i * size + c].abs().total_cmp(&a[j * size + c].abs()))?;
        if a[p * size + c] == 0.0 || !a[p * size + c].is_finite() {
            return None;
        }
        if p != c {
            for k in 0..size {
                a.swap(c * size + k, p * size + k);
            }
            r.swap(c, p);
        }
        for i in c + 1..size {
            let factor = a[i * size + c] / a[c * size + c];
            for k in c..size {
                a[i * size + k] -= factor * a[c * size + k];
            }
            r[i] -= factor * r[c];
        }
    }
    let mut x = vec![0.0; size];
    for i in (0..size).rev() {
        let s: f64 = (i + 1..size).map(|k| a[i * size + k] * x[k]).sum();
        x[i] = (r[i] - s) / a[i * size + i];
    }
    x.iter().all(|v| v.is_finite()).then_some(x)
}
