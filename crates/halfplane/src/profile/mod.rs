//! Gap profiles g(x) and the integrals of their slope g'(x) that the normal and tangential
//! problems need. Most profiles are symmetric (g' odd); two kinds may be asymmetric: a flat punch
//! with unequal edge radii ([`Profile::flat_rounded_asymmetric`]) and a tabulated profile whose
//! rows start at negative x ([`Profile::tabulated`]). Asymmetric profiles are solved only by the
//! normal problem under P and a moment ([`crate::normal::Contact::normal_contact`], which also
//! takes symmetric ones); the symmetric routes (`P(a)`, `a(P)`) refuse them with
//! [`Error::AsymmetricProfile`].
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
//! law; `pressure` is the closed-form pressure kernel of piecewise slopes; `offset` holds the
//! integrals of a contact `[c - a, c + a]` centred anywhere (the normal problem with a moment).

mod offset;
mod pieces;
mod power;
mod pressure;
mod table;

use crate::error::{physical, physical_positive, Error, Result};
use crate::quadrature::Rule;
pub(crate) use offset::ContactIntegrals;
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
    /// A pad with unequal edge radii ([`Profile::flat_rounded_asymmetric`]) also reports this
    /// shape, with its left radius here: [`Profile::edge_radii`] gives both.
    FlatRounded {
        /// Half-width b of the flat.
        flat_half_width: f64,
        /// Edge radius R (the left one when the radii differ).
        edge_radius: f64,
    },
    /// Power law `g = B|x|^k`, k >= 1.
    PowerLaw {
        /// B.
        coefficient: f64,
        /// k.
        exponent: f64,
    },
    /// Tabulated `g(x)`: from x = 0, extended symmetrically; or from a negative x (two-sided,
    /// used as given). Interpolated by clamped cubic splines split at the stated kinks.
    Tabulated {
        /// Abscissae, from 0 or from below 0, strictly increasing.
        x: Vec<f64>,
        /// Gap values: non-decreasing from x = 0; two-sided, non-increasing down to the lowest
        /// row and non-decreasing after it.
        g: Vec<f64>,
        /// Abscissae (from `x`) where g' may have a corner or a jump.
        kinks: Vec<f64>,
    },
}

/// A validated profile, ready for integration.
#[derive(Debug, Clone, PartialEq)]
pub struct Profile {
    shape: Shape,
    slope: Slope,
    /// The right edge radius of a flat-rounded pad whose radii differ (the left one is in
    /// `shape`); `None` for every other profile.
    right_radius: Option<f64>,
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
            right_radius: None,
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
            right_radius: None,
        })
    }

    /// Flat punch with rounded edges of unequal radii: flat `[-b, b]` with
    /// `b = flat_half_width >= 0`, `g' = (x + b)/R_L` for `x < -b` and `g' = (x - b)/R_R` for `x > b`
    /// (`R_L = left_radius`, `R_R = right_radius`, both > 0); g' is continuous everywhere and
    /// only g'' jumps at `x = -b` and `x = b`. Equal radii give exactly
    /// [`Profile::flat_rounded`]'s symmetric profile. Unequal radii make the profile asymmetric:
    /// only [`crate::normal::Contact::normal_contact`] solves it.
    pub fn flat_rounded_asymmetric(
        flat_half_width: f64,
        left_radius: f64,
        right_radius: f64,
    ) -> Result<Self> {
        physical_positive("profile.left_radius", left_radius)?;
        physical_positive("profile.right_radius", right_radius)?;
        let symmetric = Self::flat_rounded(flat_half_width, left_radius)?;
        if left_radius == right_radius {
            return Ok(symmetric);
        }
        let b = flat_half_width;
        let arc = |start: f64, end: f64, origin: f64, radius: f64| Piece {
            start,
            end,
            origin,
            coeffs: [0.0, 1.0 / radius, 0.0],
        };
        let mut pieces = vec![arc(f64::NEG_INFINITY, -b, -b, left_radius)];
        if b > 0.0 {
            pieces.push(Piece {
                start: -b,
                end: b,
                origin: 0.0,
                coeffs: [0.0; 3],
            });
        }
        pieces.push(arc(b, f64::INFINITY, b, right_radius));
        Ok(Self {
            shape: symmetric.shape,
            slope: Slope::Pieces(Pieces::two_sided(pieces, &[])),
            right_radius: Some(right_radius),
        })
    }

    /// The edge radii `(left, right)` of a flat punch with rounded edges (equal for
    /// [`Profile::flat_rounded`]); `None` for every other kind.
    pub fn edge_radii(&self) -> Option<(f64, f64)> {
        match self.shape {
            Shape::FlatRounded { edge_radius, .. } => {
                Some((edge_radius, self.right_radius.unwrap_or(edge_radius)))
            }
            _ => None,
        }
    }

    /// Whether g is symmetric (g' odd): every profile except a flat punch with unequal edge radii
    /// and a two-sided table. The symmetric contact law, its inverse and everything built on them
    /// (steady state, marching) need a symmetric profile.
    pub fn is_symmetric(&self) -> bool {
        match &self.slope {
            Slope::Pieces(p) => p.odd,
            Slope::Power(_) => true,
        }
    }

    /// The interval `[lower, upper]` where the profile is defined: `[-extent, extent]` for a
    /// symmetric profile ([`Profile::extent`]), the first and last rows of a two-sided table.
    pub fn bounds(&self) -> (f64, f64) {
        match &self.slope {
            Slope::Pieces(p) => p.bounds,
            Slope::Power(_) => (f64::NEG_INFINITY, f64::INFINITY),
        }
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
            right_radius: None,
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

    /// Largest |x| where the profile is defined (infinite for analytic profiles); for a two-sided
    /// table the larger of |first x| and last x (see [`Profile::bounds`]).
    pub fn extent(&self) -> f64 {
        match &self.slope {
            Slope::Pieces(p) => p.extent,
            Slope::Power(_) => f64::INFINITY,
        }
    }

    /// Points x >= 0 where g' is not smooth (g'' jumps, or g' itself jumps); the profile is
    /// symmetric, so -x is one too. For a flat-rounded pad with unequal radii the same (b, or 0
    /// when the flat has no width); for a two-sided table its kinks as given, with their signs.
    pub fn kinks(&self) -> Vec<f64> {
        match &self.shape {
            Shape::Hertz { .. } => vec![],
            Shape::FlatRounded {
                flat_half_width, ..
            } => {
                if *flat_half_width > 0.0 || self.right_radius.is_some() {
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

    /// Profile slope `g'(x)` (odd in x for a symmetric profile). Errors beyond a tabulated
    /// profile's rows.
    pub fn slope(&self, x: f64) -> Result<f64> {
        match &self.slope {
            Slope::Pieces(p) => {
                p.check_span("profile evaluation", x, x)?;
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
