//! Symmetric gap profiles g(x) and the integrals of their slope g'(x) that the normal and
//! tangential problems need.
//!
//! Everything downstream needs only integrals over a zone `[e - d, e + d]` in the variable
//! `xi = e + d cos(theta)`, which makes the square-root weights of the paper regular
//! (docs/theory.md, "Permanent stick zone"):
//!
//! - `J0(d, e) = integral_0^pi g'(e + d cos theta) dtheta`
//! - `J1(d, e) = integral_0^pi xi g'(xi) dtheta`
//!
//! and their partial derivatives. The contact law is `P(a) = J1(a, 0)/A`.
//!
//! Two routes compute them:
//! - **piecewise polynomial** (Hertz, flat-rounded, tabulated spline): g' is a polynomial of
//!   degree <= 2 on each piece, so every integral is a combination of the moments
//!   `integral cos^j theta dtheta` over the piece: exact to rounding, with kinks handled by
//!   construction;
//! - **power law** `g = B|x|^k`: Gauss-Jacobi quadrature with weight `|theta - theta0|^(k-1)` on
//!   each side of x = 0, which absorbs the algebraic singularity of g' there.
//!
//! Rooms, one stage each: this file holds the shapes, their constructors and the dispatch between
//! the two routes; `table` validates tabulated profiles and fits their spline pieces; `pieces`
//! integrates piecewise-polynomial slopes exactly; `power` is the Gauss-Jacobi route of the power
//! law; `pressure` is the closed-form pressure kernel of piecewise slopes.

mod pieces;
mod power;
mod pressure;
mod table;

use crate::error::{physical, physical_positive, Error, Result};
use crate::quadrature::Rule;
use pieces::{Piece, Pieces};
use power::PowerSlope;
pub(crate) use pressure::pressure_log_term;
pub use table::MAX_TABLE_ROWS;

/// The user-facing description of a profile, as constructed.
#[derive(Debug, Clone, PartialEq)]
pub enum Shape {
    /// Parabolic (Hertz) profile `g = x^2/(2R)`.
    Hertz {
        /// Relative radius of curvature R.
        radius: f64,
    },
    /// Flat punch with rounded edges: `g' = 0` for `|x| <= b`, `g' = sign(x)(|x| - b)/R` beyond.
    FlatRounded {
        /// Half-width b of the flat.
        flat_half_width: f64,
        /// Edge radius R.
        edge_radius: f64,
    },
    /// Power law `g = B|x|^k`, k >= 1.
    PowerLaw {
        /// B.
        coefficient: f64,
        /// k.
        exponent: f64,
    },
    /// Tabulated `g(x)` for x >= 0, extended symmetrically, interpolated by clamped cubic splines
    /// split at the stated kinks.
    Tabulated {
        /// Abscissae, from 0, strictly increasing.
        x: Vec<f64>,
        /// Gap values, non-decreasing.
        g: Vec<f64>,
        /// Abscissae (from `x`) where g' may have a corner or a jump.
        kinks: Vec<f64>,
    },
}

/// A validated symmetric profile, ready for integration.
#[derive(Debug, Clone, PartialEq)]
pub struct Profile {
    shape: Shape,
    slope: Slope,
}

#[derive(Debug, Clone, PartialEq)]
enum Slope {
    Pieces(Pieces),
    Power(PowerSlope),
}

/// J0, J1 and their partial derivatives with respect to d and e.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub(crate) struct StickIntegrals {
    pub j0: f64,
    pub j1: f64,
    pub j0_d: f64,
    pub j0_e: f64,
    pub j1_d: f64,
    pub j1_e: f64,
}

impl Profile {
    /// Hertz profile of relative radius `radius` > 0.
    pub fn hertz(radius: f64) -> Result<Self> {
        physical_positive("profile.radius", radius)?;
        let piece = Piece {
            start: 0.0,
            end: f64::INFINITY,
            origin: 0.0,
            coeffs: [0.0, 1.0 / radius, 0.0],
        };
        Ok(Self {
            shape: Shape::Hertz { radius },
            slope: Slope::Pieces(Pieces::whole_line(piece)),
        })
    }

    /// Flat punch with rounded edges: flat half-width `flat_half_width` >= 0 (0 gives Hertz),
    /// edge radius `edge_radius` > 0.
    pub fn flat_rounded(flat_half_width: f64, edge_radius: f64) -> Result<Self> {
        if !(flat_half_width >= 0.0 && physical("profile.flat_half_width", flat_half_width).is_ok())
        {
            return Err(Error::InvalidInput {
                field: "profile.flat_half_width".into(),
                value: flat_half_width,
                valid: "a finite number from 0 to 1e30",
            });
        }
        physical_positive("profile.radius", edge_radius)?;
        let b = flat_half_width;
        let mut pieces = Vec::new();
        if b > 0.0 {
            pieces.push(Piece {
                start: 0.0,
                end: b,
                origin: 0.0,
                coeffs: [0.0; 3],
            });
        }
        pieces.push(Piece {
            start: b,
            end: f64::INFINITY,
            origin: b,
            coeffs: [0.0, 1.0 / edge_radius, 0.0],
        });
        Ok(Self {
            shape: Shape::FlatRounded {
                flat_half_width,
                edge_radius,
            },
            slope: Slope::Pieces(Pieces::symmetric(pieces, &[])),
        })
    }

    /// Power law `g = coefficient |x|^exponent` with coefficient > 0 and exponent >= 1.
    pub fn power_law(coefficient: f64, exponent: f64) -> Result<Self> {
        physical_positive("profile.coefficient", coefficient)?;
        if !(exponent.is_finite() && (1.0..=64.0).contains(&exponent)) {
            return Err(Error::InvalidInput {
                field: "profile.exponent".into(),
                value: exponent,
                valid: "a finite number with 1 <= k <= 64",
            });
        }
        // R(t) in the integrand is analytic with its nearest singularity at t = 2, so the error
        // falls like 5.8^(-2n): 12 nodes are below rounding.
        let rule = Rule::jacobi(12, exponent - 1.0)?;
        Ok(Self {
            shape: Shape::PowerLaw {
                coefficient,
                exponent,
            },
            slope: Slope::Power(PowerSlope {
                coefficient,
                exponent,
                rule,
            }),
        })
    }

    /// The profile as constructed.
    pub fn shape(&self) -> &Shape {
        &self.shape
    }

    /// Whether the profile is convex (g' non-decreasing): always for Hertz, the flat punch with
    /// rounded edges and the power law (exponent >= 1); for a tabulated profile, whether its
    /// spline is (a fall of g' by 1e-12 of its largest value is taken as rounding). For a convex
    /// profile the start-of-half test decides whether slip keeps one direction through each
    /// half-cycle; for any other the steady analysis also samples each half (docs/validity.md).
    pub fn is_convex(&self) -> bool {
        match &self.slope {
            Slope::Pieces(p) => p.convex,
            Slope::Power(_) => true,
        }
    }

    /// Largest |x| where the profile is defined (infinite for analytic profiles).
    pub fn extent(&self) -> f64 {
        match &self.slope {
            Slope::Pieces(p) => p.extent,
            Slope::Power(_) => f64::INFINITY,
        }
    }

    /// Points x >= 0 where g' is not smooth (g'' jumps, or g' itself jumps); the profile is
    /// symmetric, so -x is one too.
    pub fn kinks(&self) -> Vec<f64> {
        match &self.shape {
            Shape::Hertz { .. } => vec![],
            Shape::FlatRounded {
                flat_half_width, ..
            } => {
                if *flat_half_width > 0.0 {
                    vec![*flat_half_width]
                } else {
                    vec![]
                }
            }
            Shape::PowerLaw { exponent, .. } => {
                let smooth = exponent.fract() == 0.0 && (*exponent as i64) % 2 == 0;
                if smooth {
                    vec![]
                } else {
                    vec![0.0]
                }
            }
            Shape::Tabulated { kinks, .. } => kinks.clone(),
        }
    }

    /// Profile slope `g'(x)` (odd in x). Errors beyond a tabulated profile's last row.
    pub fn slope(&self, x: f64) -> Result<f64> {
        match &self.slope {
            Slope::Pieces(p) => {
                p.check_extent("profile evaluation", x.abs())?;
                Ok(p.slope(x))
            }
            Slope::Power(p) => Ok(p.slope(x)),
        }
    }

    /// Every x in `(lo, hi)` where the slope formula changes: piece boundaries (spline knots and
    /// kinks) or x = 0 for the power law.
    pub(crate) fn breaks_within(&self, lo: f64, hi: f64) -> Vec<f64> {
        match &self.slope {
            Slope::Pieces(p) => p
                .pieces
                .iter()
                .map(|q| q.start)
                .filter(|&x| x > lo && x < hi)
                .collect(),
            Slope::Power(_) => [0.0].into_iter().filter(|&x| x > lo && x < hi).collect(),
        }
    }

    /// For a tabulated profile: the knot interval `(lo, J1(lo)), (hi, J1(hi))` holding the half-width
    /// whose symmetric moment is `target`, or `Err(last knot)` when the table is too short.
    /// `None` for analytic profiles.
    pub(crate) fn moment_bracket(
        &self,
        target: f64,
    ) -> Option<std::result::Result<[(f64, f64); 2], f64>> {
        let Slope::Pieces(p) = &self.slope else {
            return None;
        };
        let table = &p.knot_moments;
        let last = *table.last()?;
        let i = table.partition_point(|&(_, m)| m < target);
        Some(if i == table.len() {
            Err(last.0 * (target / last.1).sqrt())
        } else {
            Ok([if i == 0 { (0.0, 0.0) } else { table[i - 1] }, table[i]])
        })
    }

    /// The slope formula of the smooth piece containing `inside`, continued analytically to `at`
    /// (`None` where no continuation exists: a non-integer power law across x = 0).
    pub(crate) fn slope_branch(&self, inside: f64, at: f64) -> Option<f64> {
        match &self.slope {
            Slope::Pieces(p) => Some(p.pieces[p.index(inside)].eval(at)),
            Slope::Power(p) => (inside.signum() == at.signum()).then(|| p.slope(at)),
        }
    }

    /// `J1(a, 0) = integral_0^pi a cos(t) g'(a cos t) dt` and its derivative in a: the contact law
    /// is `P = J1/A` (docs/theory.md, "Normal contact").
    pub(crate) fn symmetric_moment(&self, a: f64) -> Result<(f64, f64)> {
        match &self.slope {
            Slope::Pieces(p) => p.symmetric_moment(a),
            Slope::Power(p) => Ok(p.symmetric_moment(a)),
        }
    }

    /// J0, J1 and derivatives over the zone `[e - d, e + d]`.
    pub(crate) fn stick_integrals(&self, d: f64, e: f64) -> Result<StickIntegrals> {
        match &self.slope {
            Slope::Pieces(p) => p.integrals(d, e),
            Slope::Power(p) => Ok(p.integrals(d, e)),
        }
    }
}

/// Independent check of the exact routes for the unit tests of this module's rooms: composite
/// Gauss-Legendre in theta on the pointwise slope, 64 panels between consecutive kink angles (so
/// each panel is smooth).
#[cfg(test)]
fn brute(profile: &Profile, d: f64, e: f64) -> (f64, f64) {
    use crate::quadrature::gauss_legendre;
    use std::f64::consts::PI;
    let mut cuts = vec![0.0, PI];
    for k in profile.kinks() {
        for x in [k, -k] {
            let c = (x - e) / d;
            if c.abs() < 1.0 {
                cuts.push(c.acos());
            }
        }
    }
    cuts.sort_by(f64::total_cmp);
    let mut j = [0.0; 2];
    let n = 64;
    for w in cuts.windows(2) {
        for i in 0..n {
            let a = w[0] + (w[1] - w[0]) * i as f64 / n as f64;
            let b = w[0] + (w[1] - w[0]) * (i + 1) as f64 / n as f64;
            let [u, v] = gauss_legendre(a, b, |t| {
                let xi = e + d * t.cos();
                let s = profile.slope(xi).unwrap();
                [s, xi * s]
            });
            j[0] += u;
            j[1] += v;
        }
    }
    (j[0], j[1])
}

#[cfg(test)]
mod tests {
    /// Fuzz finding (lib_steady): an edge radius of 5e-324 was accepted; 1/R = inf made the
    /// moments NaN (P(a) = NaN for a flat-rounded punch with b = 1, a = 2). Radii are now bounded
    /// to 1e-30..1e30 (MAGNITUDE_LIMIT).
    /// A Hertz profile is built directly as one polynomial on the whole line (the batch builds
    /// one per row); it must be the general construction's result bit for bit, signed zeros
    /// included, so that every integral is unchanged.
    #[test]
    fn hertz_slope_is_the_general_symmetric_construction() {
        use super::pieces::{Piece, Pieces};
        use super::{Profile, Slope};
        for radius in [1e-30, 0.37, 50.0, 1e30] {
            let piece = Piece {
                start: 0.0,
                end: f64::INFINITY,
                origin: 0.0,
                coeffs: [0.0, 1.0 / radius, 0.0],
            };
            let general = Pieces::symmetric(vec![piece], &[]);
            let profile = Profile::hertz(radius).expect("valid radius");
            let Slope::Pieces(direct) = &profile.slope else {
                panic!("Hertz must use the piecewise-polynomial route");
            };
            let bits = |p: &Pieces| {
                let pieces: Vec<[u64; 6]> = p
                    .pieces
                    .iter()
                    .map(|q| {
                        [
                            q.start,
                            q.end,
                            q.origin,
                            q.coeffs[0],
                            q.coeffs[1],
                            q.coeffs[2],
                        ]
                        .map(f64::to_bits)
                    })
                    .collect();
                (
                    pieces,
                    p.jumps.clone(),
                    p.extent.to_bits(),
                    p.knot_moments.clone(),
                    p.convex,
                )
            };
            assert_eq!(bits(direct), bits(&general), "R = {radius}");
        }
    }

    #[test]
    fn radius_outside_the_magnitude_range_is_rejected() {
        for r in [5e-324, 1e-310, 9.9e-31, 1.1e30] {
            assert!(super::Profile::hertz(r).is_err(), "R = {r}");
            assert!(super::Profile::flat_rounded(1.0, r).is_err(), "R = {r}");
        }
        assert!(super::Profile::hertz(1e-30).is_ok() && super::Profile::hertz(1e30).is_ok());
    }
}
