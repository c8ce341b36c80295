//! The normal contact problem for any symmetric profile: contact law P(a), its inverse a(P), the
//! pressure p(x) and the edge intensity K_N.
//!
//! Sign convention: P > 0 compresses; p(x) >= 0 is the contact pressure.

use crate::closed_form;
use crate::error::{positive, Error, Result};
use crate::material::{Compliance, Friction, Material};
use crate::profile::{pressure_log_term, Profile, Shape};
use crate::quadrature::gauss_legendre;
use std::f64::consts::PI;

/// A contact: profile, material of both bodies, and friction. All parts are validated on
/// construction, so a `Contact` is always physically meaningful; its parts are read through
/// [`Contact::profile`], [`Contact::material`] and [`Contact::friction`], never written:
///
/// ```compile_fail,E0616
/// let mut contact = halfplane::reference::hertz();
/// contact.friction = halfplane::Friction::new(0.1).unwrap();
/// ```
#[derive(Debug, Clone, PartialEq)]
pub struct Contact {
    pub(crate) profile: Profile,
    pub(crate) material: Material,
    pub(crate) friction: Friction,
}

impl Contact {
    /// Bundles the three validated parts.
    pub fn new(profile: Profile, material: Material, friction: Friction) -> Self {
        Self {
            profile,
            material,
            friction,
        }
    }

    /// Gap profile g(x).
    pub fn profile(&self) -> &Profile {
        &self.profile
    }

    /// Elastic constants of both (similar) bodies.
    pub fn material(&self) -> Material {
        self.material
    }

    /// Coulomb friction coefficient.
    pub fn friction(&self) -> Friction {
        self.friction
    }

    /// Composite compliance A.
    pub fn compliance(&self) -> Compliance {
        self.material.compliance()
    }

    /// Normal load for contact half-width `a`:
    /// `P(a) = (1/A) integral_{-a}^{a} x g'(x)/sqrt(a^2 - x^2) dx` (docs/theory.md, "Normal contact").
    /// Errors when P(a) is not finite and >= 0 (scales that overflow, or cancellation on a punch
    /// whose flat is many orders of magnitude wider than a - b).
    pub fn load(&self, half_width: f64) -> Result<f64> {
        positive("contact half-width", half_width)?;
        let p = self.profile.symmetric_moment(half_width)?.0 / self.compliance().value();
        in_range(
            p,
            p >= 0.0,
            "contact half-width",
            half_width,
            "a half-width whose load P(a) is finite and >= 0 for this profile and material",
        )
    }

    /// `dP/da`, exact for every profile (derivative of the same integral); for Hertz its closed
    /// form `dP/da = pi a/(A R)`, the derivative of `P = pi a^2/(2 A R)` (paper eq. (24)).
    /// Errors when dP/da is not finite and >= 0, as [`Contact::load`].
    #[inline]
    pub fn load_rate(&self, half_width: f64) -> Result<f64> {
        positive("contact half-width", half_width)?;
        let rate = match self.profile.shape() {
            Shape::Hertz { radius } => PI * half_width / (self.compliance().value() * radius),
            _ => self.profile.symmetric_moment(half_width)?.1 / self.compliance().value(),
        };
        in_range(
            rate,
            rate >= 0.0,
            "contact half-width",
            half_width,
            "a half-width whose load rate dP/da is finite and >= 0 for this profile and material",
        )
    }

    /// Contact half-width for normal load `normal` > 0: closed form for Hertz and the power law,
    /// otherwise a bracketed Newton iteration on [`Contact::load`] to 1e-15 relative.
    ///
    /// Errors also when the inputs' scales make the half-width overflow or underflow (for
    /// example P = 1e-300 on R = 1e-300), so an `Ok` half-width is always finite and > 0.
    #[inline]
    pub fn half_width(&self, normal: f64) -> Result<f64> {
        let a = self.solve_half_width(normal)?;
        in_range(a, a > 0.0, "normal load", normal, "a load whose contact half-width is finite and > 0 for this profile and material (the scales overflow or underflow)")
    }

    /// The closed forms inline (a steady analysis asks for a few half-widths, a batch for millions);
    /// the iteration of the other profiles is [`Contact::iterate_half_width`].
    #[inline]
    fn solve_half_width(&self, normal: f64) -> Result<f64> {
        positive("normal load", normal)?;
        let a_comp = self.compliance().value();
        match self.profile.shape() {
            Shape::Hertz { radius } => Ok(closed_form::hertz_half_width(a_comp, *radius, normal)),
            Shape::PowerLaw {
                coefficient,
                exponent,
            } => Ok(closed_form::power_law_half_width(
                a_comp,
                *coefficient,
                *exponent,
                normal,
            )),
            _ => self.iterate_half_width(normal, a_comp),
        }
    }

    /// The half-width of a profile without a closed form (flat-rounded, tabulated): bracketed
    /// Newton on [`Contact::load`]; `a_comp` is the compliance A.
    fn iterate_half_width(&self, normal: f64, a_comp: f64) -> Result<f64> {
        // Bracket [lo, hi] with P(lo) <= normal <= P(hi) (P increases with a), and a first guess.
        let (mut lo, mut hi, mut a) = match self.profile.moment_bracket(a_comp * normal) {
            // Tabulated: the knot table gives a one-interval bracket; interpolate as if J1 ~ a^2.
            Some(Ok([(a0, m0), (a1, m1)])) => {
                let t = (a_comp * normal - m0) / (m1 - m0);
                (a0, a1, (a0 * a0 + t * (a1 * a1 - a0 * a0)).sqrt())
            }
            Some(Err(needed)) => {
                return Err(Error::BeyondTable {
                    what: "contact",
                    needed,
                    table_end: self.profile.extent(),
                })
            }
            None => {
                let (lo, mut hi) = match self.profile.shape() {
                    Shape::FlatRounded {
                        flat_half_width,
                        edge_radius,
                    } => {
                        let b = *flat_half_width;
                        (
                            b,
                            b + closed_form::hertz_half_width(a_comp, *edge_radius, normal),
                        )
                    }
                    _ => (0.0, 1.0),
                };
                let mut lo = lo;
                while self.load(hi)? < normal {
                    lo = hi;
                    hi *= 2.0;
                }
                (lo, hi, 0.5 * (lo + hi))
            }
        };
        for _ in 0..200 {
            let (j1, j1_d) = self.profile.symmetric_moment(a)?;
            let residual = j1 / a_comp - normal;
            let newton = a - residual * a_comp / j1_d;
            // Converged steps are tested before the bracket: at the root the Newton point equals
            // the bracket end just updated, and bisecting there would walk away from it.
            if (newton - a).abs() <= 1e-15 * a {
                return Ok(newton);
            }
            if residual > 0.0 {
                hi = a;
            } else {
                lo = a;
            }
            a = if newton > lo && newton < hi {
                newton
            } else {
                0.5 * (lo + hi)
            };
            if hi - lo <= 1e-15 * hi {
                return Ok(a);
            }
        }
        Err(Error::NoConvergence {
            what: "contact half-width",
            iterations: 200,
            last_step: (hi - lo) / hi,
        })
    }

    /// Contact pressure at `x` for the contact of half-width `a` (docs/theory.md, "Normal contact"):
    /// `p(x) = (sqrt(a^2 - x^2)/(pi A)) PV integral g'(xi)/(sqrt(a^2 - xi^2)(xi - x)) dxi`.
    /// Hertz uses its closed form. Otherwise the principal value is removed by subtracting
    /// `g'(x)` (the PV integral of the bare kernel vanishes inside the contact), leaving
    /// `integral_0^pi (g'(a cos t) - g'(x))/(a cos t - x) dt`, split at x and wherever the slope formula changes. On a
    /// piece that does not hold x, the piece's own slope formula continued to x, `c`, is
    /// subtracted too, so the remaining integrand is regular even when x is close to the piece,
    /// and `(c - g'(x)) integral dt/(a cos t - x)` is added in closed form. Piecewise-polynomial
    /// slopes (Hertz, flat-rounded, tabulated) are then integrated exactly in closed form; the
    /// power law by 20-point Gauss-Legendre per piece, about 1e-6 relative near x = 0 for a
    /// non-integer exponent (no continuation across 0), exact to rounding elsewhere.
    ///
    /// Errors when the pressure is not finite (scales that overflow).
    pub fn pressure(&self, half_width: f64, x: f64) -> Result<f64> {
        let p = self.solve_pressure(half_width, x)?;
        in_range(
            p,
            true,
            "contact half-width",
            half_width,
            "a half-width whose pressure is finite for this profile and material",
        )
    }

    fn solve_pressure(&self, half_width: f64, x: f64) -> Result<f64> {
        positive("contact half-width", half_width)?;
        let a = half_width;
        crate::error::finite("position x", x)?;
        if x.abs() >= a {
            return Ok(0.0);
        }
        let a_comp = self.compliance().value();
        if let Shape::Hertz { radius } = self.profile.shape() {
            return Ok(closed_form::hertz_pressure(a_comp, *radius, a, x));
        }
        let gx = self.profile.slope(x)?;
        self.profile.slope(a)?;
        if !self.profile.is_symmetric() {
            self.profile.slope(-a)?;
        }
        let root = (a * a - x * x).sqrt();
        let sum = self.pressure_kernel(0.0, a, x, gx, root);
        Ok((root / (PI * a_comp) * sum).max(0.0))
    }

    /// `integral_0^pi (g'(xi) - g'(x))/(xi - x) dt` with `xi = centre + a cos t`, for x inside the
    /// contact `[centre - a, centre + a]`, `gx = g'(x)` and `root = sqrt(a^2 - (x - centre)^2)`
    /// (as the caller computed it): in closed form for piecewise slopes
    /// ([`Profile`]'s pressure integral), by Gauss-Legendre otherwise (see
    /// [`Contact::pressure`]). The pressure is `sqrt((x - b1)(b2 - x))/(pi A)` times it, for the
    /// symmetric contact (`centre = 0`) and the contact under a moment alike.
    pub(crate) fn pressure_kernel(&self, centre: f64, a: f64, x: f64, gx: f64, root: f64) -> f64 {
        if let Some(sum) = self.profile.pressure_integral(centre, a, x) {
            return sum;
        }
        let s = x - centre;
        // integral dt/(a cos t - s) = L(t) with tan(t/2) substitution; L(pi) = 0.
        let k = ((a - s) / (a + s)).sqrt();
        let log_kernel = |t: f64| {
            if t >= PI {
                0.0
            } else {
                pressure_log_term(k, (0.5 * t).tan(), root)
            }
        };
        let theta_x = (s / a).acos();
        let mut cuts = vec![0.0, PI, theta_x];
        cuts.extend(
            self.profile
                .breaks_within(centre - a, centre + a)
                .into_iter()
                .map(|b| ((b - centre) / a).acos()),
        );
        cuts.sort_by(f64::total_cmp);
        let mut sum = 0.0;
        for w in cuts.windows(2) {
            if w[1] > w[0] {
                let inside = centre + a * (0.5 * (w[0] + w[1])).cos();
                // Next to x the piece is x's own: no continuation (and L is infinite at x).
                let c = if w[0] == theta_x || w[1] == theta_x {
                    gx
                } else {
                    self.profile.slope_branch(inside, x).unwrap_or(gx)
                };
                let [v] = gauss_legendre(w[0], w[1], |t| {
                    let xi = centre + a * t.cos();
                    // For x within rounding of a contact end, the window next to it is so
                    // narrow that a node's xi can round to x: its term (weight ~ the window)
                    // is then dropped instead of being 0/0.
                    if xi == x {
                        return [0.0];
                    }
                    [(self.profile.slope(xi).unwrap_or(c) - c) / (xi - x)]
                });
                sum += v;
                if c != gx {
                    sum += (c - gx) * (log_kernel(w[1]) - log_kernel(w[0]));
                }
            }
        }
        sum
    }

    /// Normal edge intensity `K_N = (1/pi) sqrt(2/a) dP/da`, with `p ~ K_N sqrt(s)` at distance s
    /// from an edge (paper, section "Asymptotic representation"; Fleury et al. 2017).
    pub fn normal_intensity(&self, half_width: f64) -> Result<f64> {
        let k = (2.0 / half_width).sqrt() / PI * self.load_rate(half_width)?;
        in_range(
            k,
            k >= 0.0,
            "contact half-width",
            half_width,
            "a half-width whose edge intensity K_N is finite for this profile and material",
        )
    }
}

/// `Ok(value)` when it is finite and `ok` holds; otherwise the input that led to it is reported.
#[inline]
fn in_range(value: f64, ok: bool, field: &str, input: f64, valid: &'static str) -> Result<f64> {
    if value.is_finite() && ok {
        Ok(value)
    } else {
        Err(Error::InvalidInput {
            field: field.to_string(),
            value: input,
            valid,
        })
    }
}

#[cfg(test)]
mod tests {
    #[test]
    fn hertz_load_rate_closed_form_equals_the_general_route() {
        // The general route differentiates the piecewise-polynomial moment integral; both are
        // exact, so they agree to rounding (1e-13 relative: a few operations with an atan2).
        let contact = crate::reference::hertz();
        for a in [1e-3, 0.1, 0.761, 2.0, 50.0] {
            let general = contact.profile.symmetric_moment(a).expect("inside").1
                / contact.compliance().value();
            let closed = contact.load_rate(a).expect("valid");
            assert!(
                (closed - general).abs() <= 1e-13 * general,
                "a = {a}: dP/da closed form {closed} vs integral {general}"
            );
        }
    }
}
