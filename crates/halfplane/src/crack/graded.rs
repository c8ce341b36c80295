//! A second solution of the open surface-breaking crack, discretised apart from `solve.rs` so that
//! the two check each other (docs/crack.md, "Inclined edge crack under remote tension"). It
//! shares with `solve.rs` only the elasticity (the half-plane dislocation of `kernel.rs`, which its
//! own tests pin by its two defining properties), the dense LU and the barycentric interpolation
//! formula; the representation of the densities, the singular integrals, the collocation and the
//! tip factors are its own.
//!
//! **Why a second discretisation.** Where the crack meets the surface at `90° - θ` the body is two
//! wedges with free faces, of `90° - θ` and `90° + θ`. The obtuse one has a free-free
//! eigenfunction `r^λ` (Williams 1952: `sin(λ φ) = -λ sin φ` for the wedge angle `φ`) whose `λ`
//! falls towards 1 as the crack leans: 1.53 at `θ = 60°`, 1.20 at 75°, 1.13 at 80° (none between
//! 1 and 3 up to 45°). The density then behaves like `s^(λ-1)` at the mouth, which the global polynomial of
//! `solve.rs` approaches slowly. Here the density is piecewise polynomial on panels graded
//! geometrically towards the mouth, which resolves any such power without knowing it.
//!
//! **Representation.** Glide and climb densities `b_j` (frame of `solve.rs`: `e1` from the mouth
//! to the tip, `e2` a quarter turn towards `+z` from `+x`) are written
//! `A b_j(ξ) = phi_j(ξ)/sqrt(l - ξ)`, `A` the kernel's unit, with `phi_j` a polynomial of degree
//! `nodes - 1` on each panel (Lagrange through the panel's Gauss-Legendre points, not continuous
//! across panels). Panels: `[0, l r^levels]`, then `[l r^(k+1), l r^k]` for `k = levels - 1 .. 0`
//! (ratio `r`, the last panel ending at the tip).
//!
//! **Equations.** At each panel's Gauss-Legendre points the traction `s22`, `s12` of the
//! dislocations equals minus the uncracked one. On its own line a whole-plane dislocation gives
//! `s22 = A b2/(s - ξ)`, `s12 = A b1/(s - ξ)` (`kernel.rs`); the rest of the half-plane kernel (the
//! image part, bounded on the crack line) is integrated by Gauss-Legendre on each panel. The
//! Cauchy part is integrated by product integration:
//! `PV ∫ L(ξ)/((s - ξ) sqrt(l - ξ)) dξ = ∫ (L(ξ) - L(s))/((s - ξ) sqrt(l - ξ)) dξ + L(s) J`, with
//! `J = ∫_a^b dξ/((s - ξ) sqrt(l - ξ))` in closed form (`u = sqrt(l - ξ)`:
//! `(1/sqrt d)[ln|(s-a)/(s-b)| + 2 ln((u_b + sqrt d)/(u_a + sqrt d))]`, `d = l - s > 0`; ahead of
//! the tip, `d' = s - l`, `(2/sqrt d')[atan(u_a/sqrt d') - atan(u_b/sqrt d')]`), the remainder
//! regular; on the panel at the tip the substitution `ξ = l - u^2` makes it a polynomial in `u`.
//!
//! **Tip factors**, from the crack opening near the tip (not from `solve.rs`): the opening is
//! `delta_2(r) = ∫ b_2 = 2 phi_2(l) sqrt(r)/A` at distance `r` from the tip, and in plane strain
//! `delta = 8 K_I (1 - nu^2)/E sqrt(r/(2 pi))` (Irwin's near-tip field), so with
//! `A = E/(4 pi (1 - nu^2))`, `K_I = pi sqrt(2 pi) phi_2(l)` and likewise
//! `K_II = -pi sqrt(2 pi) phi_1(l)` for the shear `tau = e_s . sigma . n`, `n = -e2` (sign of the
//! module doc of [`super`]). [`GradedCrack::traction_ahead`] gives the stress the dislocations
//! carry on the crack line ahead of the tip, for checking both factors and their signs against
//! `lim sqrt(2 pi r) sigma` directly.

use super::kernel::{dislocation_stress, C};
use super::quadrature::{barycentric_weights, lagrange_basis};
use super::solve::{resolve, Lu, TipFactors};
use super::Crack;
use crate::error::{Error, Result};
use crate::quadrature::Rule;
use std::f64::consts::PI;

/// Most panels below the one at the tip.
pub const MAX_LEVELS: usize = 200;
/// Most points (the polynomial degree plus one) per panel.
pub const MAX_NODES: usize = 40;

/// The panels of a [`GradedCrack`] (module doc).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct GradedMesh {
    levels: usize,
    nodes: usize,
    ratio: f64,
}

impl GradedMesh {
    /// `levels` panels (1 to [`MAX_LEVELS`]) below the one at the tip, each `ratio` (strictly
    /// between 0 and 1) the length of the next towards the tip, and `nodes` points per panel (2
    /// to [`MAX_NODES`]). The panel at the mouth is `ratio^levels` of the crack long.
    pub fn new(levels: usize, nodes: usize, ratio: f64) -> Result<Self> {
        let count = |field: &str, value: usize, min: usize, max: usize| {
            if (min..=max).contains(&value) {
                Ok(())
            } else {
                Err(Error::InvalidCount {
                    field: field.into(),
                    value: value as u64,
                    min: min as u64,
                    max: max as u64,
                })
            }
        };
        count("graded mesh levels", levels, 1, MAX_LEVELS)?;
        count("graded mesh nodes", nodes, 2, MAX_NODES)?;
        if !(ratio > 0.0 && ratio < 1.0) {
            return Err(Error::InvalidInput {
                field: "graded mesh ratio".into(),
                value: ratio,
                valid: "a ratio strictly between 0 and 1",
            });
        }
        Ok(Self {
            levels,
            nodes,
            ratio,
        })
    }

    /// Unknowns per component.
    pub fn unknowns(&self) -> usize {
        (self.levels + 1) * self.nodes
    }

    /// Panel ends `0, l r^levels, ..., l r, l`.
    fn breaks(&self, l: f64) -> Vec<f64> {
        let mut b = vec![0.0];
        b.extend(
            (0..=self.levels)
                .rev()
                .map(|k| l * self.ratio.powi(k as i32)),
        );
        b
    }
}

/// Lagrange interpolation through the Gauss-Legendre points of [0, 1].
#[derive(Debug, Clone)]
struct Lagrange {
    nodes: Vec<f64>,
    bary: Vec<f64>,
}

impl Lagrange {
    fn new(n: usize) -> Result<Self> {
        let nodes = Rule::jacobi(n, 0.0)?.nodes;
        let bary = barycentric_weights(&nodes);
        Ok(Self { nodes, bary })
    }

    /// Every basis polynomial at `t` (`t` may lie outside [0, 1]).
    fn at(&self, t: f64) -> Vec<f64> {
        lagrange_basis(&self.nodes, &self.bary, t)
    }
}

/// A quadrature of `∫_a^b f(ξ) dξ/sqrt(l - ξ)` on one panel, with the basis at its points.
#[derive(Debug, Clone)]
struct Panel {
    a: f64,
    b: f64,
    xi: Vec<f64>,
    weights: Vec<f64>,
    basis: Vec<Vec<f64>>,
}

/// The open crack solved on a [`GradedMesh`].
#[derive(Debug, Clone)]
pub struct GradedCrack {
    crack: Crack,
    mesh: GradedMesh,
    lagrange: Lagrange,
    panels: Vec<Panel>,
    /// `phi_j` at the panels' points, glide (`j = 0`) then climb, panel by panel.
    phi: [Vec<f64>; 2],
}

impl GradedCrack {
    /// Solves `crack` with faces free of traction (open everywhere, no face contact) under the
    /// uncracked stress `stress(x, z) = [sxx, szz, sxz]` of [`crate::stress`]'s coordinates.
    /// Errors: a stress that is not finite at a collocation point, or a singular system.
    pub fn solve(
        crack: &Crack,
        mesh: &GradedMesh,
        stress: impl Fn(f64, f64) -> [f64; 3],
    ) -> Result<Self> {
        let l = crack.length;
        let q = mesh.nodes;
        let lagrange = Lagrange::new(q)?;
        // Exact for the product-integration remainder on the tip panel (degree 2q - 4 in u).
        let rule = Rule::jacobi(2 * q + 10, 0.0)?;
        let breaks = mesh.breaks(l);
        let panels: Vec<Panel> = breaks
            .windows(2)
            .map(|w| {
                let (a, b) = (w[0], w[1]);
                let (xi, weights): (Vec<f64>, Vec<f64>) = if b == l {
                    let top = (l - a).sqrt();
                    rule.nodes
                        .iter()
                        .zip(&rule.weights)
                        .map(|(r, w)| {
                            let u = top * r;
                            (l - u * u, 2.0 * w * top)
                        })
                        .unzip()
                } else {
                    rule.nodes
                        .iter()
                        .zip(&rule.weights)
                        .map(|(r, w)| {
                            let x = a + (b - a) * r;
                            (x, w * (b - a) / (l - x).sqrt())
                        })
                        .unzip()
                };
                let basis = xi.iter().map(|x| lagrange.at((x - a) / (b - a))).collect();
                Panel {
                    a,
                    b,
                    xi,
                    weights,
                    basis,
                }
            })
            .collect();
        let mut this = Self {
            crack: *crack,
            mesh: *mesh,
            lagrange,
            panels,
            phi: [Vec::new(), Vec::new()],
        };
        let nc = mesh.unknowns();
        let n2 = 2 * nc;
        let (e1, e2) = crack.frame();
        let mut matrix = vec![0.0; n2 * n2];
        let mut rhs = vec![0.0; n2];
        let points: Vec<f64> = this
            .panels
            .iter()
            .flat_map(|p| {
                this.lagrange
                    .nodes
                    .iter()
                    .map(move |t| p.a + (p.b - p.a) * t)
            })
            .collect();
        for (k, &s) in points.iter().enumerate() {
            let rows = this.line_influence(s);
            for r in 0..2 {
                for j in 0..2 {
                    matrix[(r * nc + k) * n2 + j * nc..(r * nc + k) * n2 + (j + 1) * nc]
                        .copy_from_slice(&rows[r][j]);
                }
            }
            let x = crack.mouth + s * e1[0];
            let z = s * e1[1];
            let st = stress(x, z);
            if st.iter().any(|v| !v.is_finite()) {
                return Err(Error::InvalidInput {
                    field: "crack stress".into(),
                    value: st
                        .iter()
                        .copied()
                        .find(|v| !v.is_finite())
                        .unwrap_or(f64::NAN),
                    valid: "a finite uncracked stress at every collocation point",
                });
            }
            let [s22, s12] = resolve(st, e1, e2);
            rhs[k] = -s22;
            rhs[nc + k] = -s12;
        }
        let lu = Lu::factor(matrix, n2).ok_or(Error::NoConvergence {
            what: "the graded crack's system (singular)",
            iterations: 0,
            last_step: f64::NAN,
        })?;
        lu.solve(&mut rhs);
        let climb = rhs.split_off(nc);
        this.phi = [rhs, climb];
        Ok(this)
    }

    /// The crack.
    pub fn crack(&self) -> &Crack {
        &self.crack
    }

    /// The mesh.
    pub fn mesh(&self) -> &GradedMesh {
        &self.mesh
    }

    /// `K_I` and `K_II` from `phi_j` at the tip (module doc).
    pub fn tip_factors(&self) -> TipFactors {
        let q = self.mesh.nodes;
        let last = self.panels.len() - 1;
        let at_tip = self.lagrange.at(1.0);
        let value = |phi: &[f64]| -> f64 {
            phi[last * q..]
                .iter()
                .zip(&at_tip)
                .map(|(p, l)| p * l)
                .sum()
        };
        let c = PI * (2.0 * PI).sqrt();
        TipFactors {
            k1: c * value(&self.phi[1]),
            k2: -c * value(&self.phi[0]),
        }
    }

    /// The normal stress `s_nn` and shear `tau = e_s . sigma . n` that the dislocations alone
    /// carry on the crack line at distance `r > 0` beyond the tip (add the uncracked stress there
    /// for the whole): `sqrt(2 pi r)` times the whole tends to `K_I` and `K_II` as `r -> 0`.
    pub fn traction_ahead(&self, r: f64) -> (f64, f64) {
        let rows = self.line_influence(self.crack.length + r);
        let dot = |row: &[f64], phi: &[f64]| row.iter().zip(phi).map(|(a, b)| a * b).sum::<f64>();
        let s22 = dot(&rows[0][0], &self.phi[0]) + dot(&rows[0][1], &self.phi[1]);
        let s12 = dot(&rows[1][0], &self.phi[0]) + dot(&rows[1][1], &self.phi[1]);
        (s22, -s12)
    }

    /// `[traction][component]`: the traction `s22` (0) and `s12` (1) at distance `s` from the
    /// mouth on the crack line per unit `phi` of glide (0) and climb (1) at every point.
    fn line_influence(&self, s: f64) -> [[Vec<f64>; 2]; 2] {
        let l = self.crack.length;
        let q = self.mesh.nodes;
        let nc = self.mesh.unknowns();
        let (e1, e2) = self.crack.frame();
        let at = |d: f64| C::new(d * e1[0], d * e1[1]);
        let burgers = [C::new(e1[0], e1[1]), C::new(e2[0], e2[1])];
        let mut out = [
            [vec![0.0; nc], vec![0.0; nc]],
            [vec![0.0; nc], vec![0.0; nc]],
        ];
        let mut cauchy = vec![0.0; q];
        for (p, panel) in self.panels.iter().enumerate() {
            let range = p * q..(p + 1) * q;
            // The Cauchy part, by product integration near the panel and directly far from it.
            cauchy.fill(0.0);
            let h = panel.b - panel.a;
            if s > panel.a - h && s < panel.b + h {
                let at_s = self.lagrange.at((s - panel.a) / h);
                for ((x, w), basis) in panel.xi.iter().zip(&panel.weights).zip(&panel.basis) {
                    for ((c, bv), sv) in cauchy.iter_mut().zip(basis).zip(&at_s) {
                        *c += w * (bv - sv) / (s - x);
                    }
                }
                let j = endpoint_integral(s, panel.a, panel.b, l);
                for (c, sv) in cauchy.iter_mut().zip(&at_s) {
                    *c += sv * j;
                }
            } else {
                for ((x, w), basis) in panel.xi.iter().zip(&panel.weights).zip(&panel.basis) {
                    for (c, bv) in cauchy.iter_mut().zip(basis) {
                        *c += w * bv / (s - x);
                    }
                }
            }
            out[0][1][range.clone()].copy_from_slice(&cauchy);
            out[1][0][range.clone()].copy_from_slice(&cauchy);
            // The image part: the half-plane kernel less the whole-plane one, bounded here.
            for ((x, w), basis) in panel.xi.iter().zip(&panel.weights).zip(&panel.basis) {
                let whole = 1.0 / (s - x);
                for (j, b) in burgers.iter().enumerate() {
                    let [mut s22, mut s12] = resolve(dislocation_stress(at(s), at(*x), *b), e1, e2);
                    if j == 0 {
                        s12 -= whole;
                    } else {
                        s22 -= whole;
                    }
                    for (i, bv) in basis.iter().enumerate() {
                        out[0][j][p * q + i] += w * bv * s22;
                        out[1][j][p * q + i] += w * bv * s12;
                    }
                }
            }
        }
        out
    }
}

/// `∫_a^b dξ/((s - ξ) sqrt(l - ξ))` (principal value for `a < s < b`), `b <= l`, `s != l`
/// (module doc). The form with `ln|(s - a)/(s - b)|` keeps its precision where `a`, `b` and `s`
/// are tiny beside `l` (panels at the mouth).
fn endpoint_integral(s: f64, a: f64, b: f64, l: f64) -> f64 {
    let (ua, ub) = ((l - a).sqrt(), (l - b).sqrt());
    if s < l {
        let sd = (l - s).sqrt();
        // ln((ub + sqrt d)/(ua + sqrt d)) with ub - ua = (a - b)/(ua + ub): no cancellation.
        let near = ((a - b) / ((ua + ub) * (ua + sd))).ln_1p();
        (((s - a) / (s - b)).abs().ln() + 2.0 * near) / sd
    } else {
        let sd = (s - l).sqrt();
        2.0 * ((ua / sd).atan() - (ub / sd).atan()) / sd
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_endpoint_integral_against_quadrature() {
        // Away from the panel the integrand is smooth: a fine composite midpoint sum in
        // u = sqrt(l - ξ) agrees to 1e-9; inside, the principal value from the symmetric limit.
        let l = 1.0;
        let numeric = |s: f64, a: f64, b: f64| -> f64 {
            let (ua, ub) = ((l - a).sqrt(), (l - b).sqrt());
            let n = 200_000;
            let h = (ua - ub) / n as f64;
            (0..n)
                .map(|k| {
                    let u = ub + h * (k as f64 + 0.5);
                    2.0 * h / (s - (l - u * u))
                })
                .sum()
        };
        for (s, a, b) in [
            (0.1, 0.3, 0.6),
            (0.9, 0.2, 0.5),
            (0.2, 0.5, 1.0),
            (1.2, 0.5, 1.0),
        ] {
            let e = endpoint_integral(s, a, b, l);
            let n = numeric(s, a, b);
            assert!((e - n).abs() < 1e-9, "{s} {a} {b} {e} {n}");
        }
        // Principal value: the regular remainder by the midpoint sum plus the logarithm of the
        // Cauchy part (the subtraction, done numerically in ξ, not in u).
        let (s, a, b) = (0.4, 0.25, 0.7);
        let f = |x: f64| 1.0 / (l - x).sqrt();
        let n = 400_000;
        let h = (b - a) / n as f64;
        let regular: f64 = (0..n)
            .map(|k| {
                let x = a + h * (k as f64 + 0.5);
                h * (f(x) - f(s)) / (s - x)
            })
            .sum();
        let pv = regular + f(s) * ((s - a) / (b - s)).ln();
        let e = endpoint_integral(s, a, b, l);
        assert!((e - pv).abs() < 1e-8, "{e} {pv}");
    }

    #[test]
    fn a_mesh_outside_its_limits_is_an_error() {
        assert!(GradedMesh::new(0, 8, 0.5).is_err());
        assert!(GradedMesh::new(10, 1, 0.5).is_err());
        assert!(GradedMesh::new(10, 8, 1.0).is_err());
        assert!(GradedMesh::new(10, 8, f64::NAN).is_err());
        assert_eq!(GradedMesh::new(10, 8, 0.5).unwrap().unknowns(), 88);
    }
}
