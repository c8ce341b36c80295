//! The normal problem under a normal load P and a moment M, for any profile (symmetric or not):
//! contact ends `b1 < b2`, pressure, edge intensities K_N at both ends and the pad's rotation.
//!
//! Conventions (docs/theory.md, "Normal contact under a moment"): P > 0 compresses; the moment
//! is taken about x = 0 of the profile's coordinate, `M = integral p(x) x dx`, so the pressure
//! centroid sits at `x = M/P` (M > 0 moves the contact towards +x). The pad is free to rotate
//! rigidly: the relative gap is `h(x) = g(x) + theta x + const`, so a negative rotation theta
//! closes the gap on the +x side. The contact `[b1, b2]` has centre `c = (b1 + b2)/2` and
//! half-width `a = (b2 - b1)/2`, `xi = c + a cos(phi)`.
//!
//! The pressure bounded at both ends of the singular integral equation
//! `(1/pi) PV integral p(xi)/(x - xi) dxi = h'(x)/A` (Johnson, Contact Mechanics, eq. 2.25a,
//! summed over two elastically similar bodies; Barber, Elasticity, ch. 12) exists only when
//! the consistency condition `integral_0^pi h'(xi) dphi = 0` holds, which fixes the rotation:
//! `theta = -I_0/pi` with `I_j = integral_0^pi g'(xi) cos(j phi) dphi`. Its resultants are then
//! `A P = a I_1` and `A M = c A P + a^2 I_2/2` (theta drops out of both), and
//! `p(x) = sqrt((x - b1)(b2 - x))/(pi A) integral_0^pi (g'(xi) - g'(x))/(xi - x) dphi`. These
//! are the two conditions for the two unknown ends. Andresen, Hills & Vázquez (Closed-form
//! solutions for tilted three-part piecewise-quadratic half-plane contacts, Int. J. Mech. Sci.
//! 2019) solve the same problem in closed form for piecewise-quadratic profiles (the tilted
//! flat-and-rounded punch among them); [`crate::closed_form::flat_rounded_tilted`] evaluates
//! the integrals above in closed form for that punch and checks this module in the tests.

use crate::error::{physical, physical_positive, Error, Result};
use crate::labels::PerEdge;
use crate::load::LoadPoint;
use crate::normal::Contact;
use crate::profile::{ContactIntegrals, Shape};
use std::f64::consts::PI;

mod centre;
mod state;
pub use state::NormalContact;

/// `A P`, `A M`, their partial derivatives in c and a, and `I_0`, at one contact `(c, a)`.
#[derive(Debug, Clone, Copy)]
struct Resultants {
    load: f64,
    moment: f64,
    load_c: f64,
    load_a: f64,
    moment_c: f64,
    moment_a: f64,
    i0: f64,
}

impl Resultants {
    /// `A P = a I_1`, `A M = c a I_1 + a^2 I_2 / 2` and their derivatives (module docs).
    fn new(c: f64, a: f64, s: &ContactIntegrals) -> Self {
        let [i0, i1, i2] = s.i;
        let load = a * i1;
        let load_a = i1 + a * s.i_a[1];
        let load_c = a * s.i_c[1];
        Self {
            load,
            moment: c * load + 0.5 * a * a * i2,
            load_c,
            load_a,
            moment_c: load + c * load_c + 0.5 * a * a * s.i_c[2],
            moment_a: c * load_a + a * i2 + 0.5 * a * a * s.i_a[2],
            i0,
        }
    }
}

impl Contact {
    /// `(P, M)` carried by the contact `[left, right]` (`left < right`): the forward problem,
    /// `A P = a I_1`, `A M = c A P + a^2 I_2/2` (module docs; Johnson, Contact Mechanics, eq.
    /// 2.25a). Errors where the contact leaves a tabulated profile.
    pub fn load_and_moment(&self, left: f64, right: f64) -> Result<(f64, f64)> {
        physical("contact end b1", left)?;
        physical("contact end b2", right)?;
        if right <= left {
            return Err(Error::InvalidInput {
                field: "contact end b2".into(),
                value: right,
                valid: "a contact end greater than b1",
            });
        }
        let r = self.resultants(0.5 * (left + right), 0.5 * (right - left))?;
        let a_comp = self.compliance().value();
        Ok((r.load / a_comp, r.moment / a_comp))
    }

    /// The normal contact under normal load `normal` (P > 0) and moment `moment` (M about x = 0,
    /// any sign): ends, rotation and K_N at both ends (module docs for the conventions).
    ///
    /// Solved as two nested bracketed Newton iterations, using that for a convex profile
    /// (non-negative K_N at both ends of every contact) P grows with either end moving outwards and, along a
    /// curve of constant P (both ends moving the same way), M grows with the centre c: the inner
    /// iteration finds the half-width a(c) carrying P at a fixed centre (P increases with a), the
    /// outer one the centre where M(c, a(c)) = M, with the exact derivative
    /// `dM/dc = M_c - M_a P_c/P_a`. Each keeps a bracket and bisects whenever Newton would leave
    /// it; both stop at a relative step of 1e-15. The first centre tried is the centroid M/P
    /// (exact for Hertz). On a tabulated profile, a centre whose contact cannot carry P inside
    /// the table brackets the root from that side; if M lies beyond the moment carried with an
    /// end on the table's first or last row, the error [`Error::MomentOutsideTable`] gives the
    /// valid range at this P. Errors too when the contact found has a negative K_N at an end (a
    /// non-convex profile whose pressure would be negative there).
    pub fn normal_contact(&self, normal: f64, moment: f64) -> Result<NormalContact> {
        physical_positive("normal load", normal)?;
        physical("moment", moment)?;
        let a_comp = self.compliance().value();
        let (target_p, target_m) = (a_comp * normal, a_comp * moment);
        let (c, a, r) = self.solve_centre(normal, moment, target_p, target_m)?;
        self.finish(normal, moment, c, a, &r)
    }

    /// The normal contact at `point` (P and M), by the cheapest exact route: on a symmetric
    /// profile under no moment the centred contact `[-a, a]` of the symmetric contact law
    /// ([`Contact::half_width`], [`Contact::normal_intensity`]), otherwise
    /// [`Contact::normal_contact`]. The two agree to rounding where both apply (the tests check
    /// 1e-14).
    pub fn contact_at(&self, point: &LoadPoint) -> Result<NormalContact> {
        self.contact_for(point.normal(), point.moment())
    }

    /// [`Contact::contact_at`] for P and M given apart.
    pub(crate) fn contact_for(&self, normal: f64, moment: f64) -> Result<NormalContact> {
        if let Some(found) = self.closed_form_contact(normal, moment)? {
            return Ok(found);
        }
        // Newton on both resultants from the centroid and the symmetric contact's half-width
        // (exact for Hertz, close for a pad whose ends stay off its flat); the bracketed solve
        // when that does not settle.
        physical_positive("normal load", normal)?;
        physical("moment", moment)?;
        let e = moment / normal;
        let (c, a) = if let Some(guess) = self.power_law_guess(normal, moment) {
            guess
        } else if self.profile.is_symmetric()
            && matches!(self.profile.shape(), Shape::Tabulated { .. })
        {
            // A mirrored table: the contact under P alone, by the knot table of the symmetric
            // contact law (the other kinds' first guesses below are closed forms).
            (e, self.half_width(normal).unwrap_or(0.0))
        } else {
            let a = match self.first_half_width(normal) {
                a if a > 0.0 => a,
                _ => {
                    let (lower, upper) = self.profile.bounds();
                    0.5 * (e - lower).min(upper - e)
                }
            };
            (e, a)
        };
        if a > 0.0 && a.is_finite() {
            if let Some(found) = self.newton(normal, moment, c, a, 1e-15)? {
                return Ok(found);
            }
        }
        self.normal_contact(normal, moment)
    }

    /// For a power law, the contact `(c, a)` under P and M to second order in e/a0 (e = M/P, a0
    /// the symmetric half-width), `None` for the other profiles. Both resultants expanded about
    /// the symmetric contact, where dP/dc = 0: with g'' = B k (k-1)|x|^(k-2),
    /// g''' = B k (k-1)(k-2)|x|^(k-3) sign x and the Wallis ratio W_(k-2) = k W_k/(k-1),
    /// `A dM/dc = A P + a^2 dI_2/dc / 2 = A P k/2`, so c = 2e/k, and
    /// `d^2 I_1/dc^2 = k (k-2) I_1/a^2`, so keeping P shrinks the half-width by the factor
    /// `1 - (k-2) c^2/(2 a0^2)` (Hertz, k = 2: the shifted symmetric contact). From it Newton
    /// needs three evaluations on the reference cycle (e/a0 up to 0.1) instead of four from the
    /// centroid and a0.
    pub(crate) fn power_law_guess(&self, normal: f64, moment: f64) -> Option<(f64, f64)> {
        let Shape::PowerLaw { exponent: k, .. } = self.profile.shape() else {
            return None;
        };
        let a0 = self.first_half_width(normal);
        let c = 2.0 * moment / (normal * k);
        let a = a0 * (1.0 - 0.5 * (k - 2.0) * (c / a0).powi(2)).clamp(0.5, 2.0);
        (a > 0.0 && a.is_finite() && c.is_finite()).then_some((c, a))
    }

    /// The closed forms: the centred contact of a symmetric profile under no moment (the
    /// symmetric contact law), and Hertz under a moment, the symmetric contact moved by the
    /// centroid e = M/P with the rotation `-e/R` and the symmetric K_N at both ends (the module's
    /// equations with `g' = x/R`: `I_0 = pi c/R`, `I_1 = pi a/(2R)`, `I_2 = 0`). `None` for the
    /// other contacts.
    fn closed_form_contact(&self, normal: f64, moment: f64) -> Result<Option<NormalContact>> {
        if moment == 0.0 && self.profile.is_symmetric() {
            let a = self.half_width(normal)?;
            return Ok(Some(NormalContact::centred(
                normal,
                a,
                self.normal_intensity(a)?,
            )));
        }
        let Shape::Hertz { radius } = self.profile.shape() else {
            return Ok(None);
        };
        physical("moment", moment)?;
        let a = self.half_width(normal)?;
        let k_n = self.normal_intensity(a)?;
        let e = moment / normal;
        resolvable(moment, e, a)?;
        Ok(Some(NormalContact {
            normal,
            moment,
            ends: PerEdge {
                left: e - a,
                right: e + a,
            },
            rotation: -e / radius,
            intensity: PerEdge::from_fn(|_| k_n),
            on_flat: PerEdge::default(),
            centred: false,
        }))
    }

    /// [`Contact::contact_for`] started from `near`, the contact of a nearby load: Newton's
    /// method on both resultants at once ([`Contact::newton`]), which converges in two or three
    /// steps from a neighbour along a load path; the bracketed solve of
    /// [`Contact::normal_contact`] when it does not settle. The answer agrees with the solve
    /// from scratch to rounding.
    pub(crate) fn contact_near(
        &self,
        normal: f64,
        moment: f64,
        near: &NormalContact,
    ) -> Result<NormalContact> {
        self.contact_from(normal, moment, (near.centre(), near.half_width()), 1e-15)
    }

    /// [`Contact::contact_near`] from a guessed contact `(c, a)` (a > 0, a prediction along a
    /// load path) instead of a solved one, to the relative step `tolerance` (at least 1e-15, the
    /// solve to rounding; a looser one suits contacts that only bound a quantity along a path,
    /// far inside the bound's own margin; its rotation and K_N are good to about the square
    /// root of the tolerance). The bracketed solve (to rounding) when
    /// Newton does not settle.
    pub(crate) fn contact_from(
        &self,
        normal: f64,
        moment: f64,
        (c, a): (f64, f64),
        tolerance: f64,
    ) -> Result<NormalContact> {
        if let Some(found) = self.closed_form_contact(normal, moment)? {
            return Ok(found);
        }
        physical_positive("normal load", normal)?;
        physical("moment", moment)?;
        if a > 0.0 && a.is_finite() && c.is_finite() {
            if let Some(found) = self.newton(normal, moment, c, a, tolerance.max(1e-15))? {
                return Ok(found);
            }
        }
        self.normal_contact(normal, moment)
    }

    /// Newton's method on both resultants, `(A P, A M)` against `(c, a)` with the exact Jacobian
    /// (module docs), from `(c, a)`: at most 8 steps, stopping at a step of `tolerance` times
    /// `a + |c|` (1e-15 is the bracketed solve's rule, so the two agree to rounding); a looser
    /// tolerance also stops after a step below its square root, keeping the stepped contact.
    /// `None` when a step leaves the profile or is not finite, or Newton has not settled.
    fn newton(
        &self,
        normal: f64,
        moment: f64,
        c: f64,
        a: f64,
        tolerance: f64,
    ) -> Result<Option<NormalContact>> {
        let a_comp = self.compliance().value();
        let (target_p, target_m) = (a_comp * normal, a_comp * moment);
        let (mut c, mut a) = (c, a);
        for _ in 0..8 {
            let Ok(r) = self.resultants(c, a) else {
                return Ok(None);
            };
            let (f1, f2) = (r.load - target_p, r.moment - target_m);
            let det = r.load_c * r.moment_a - r.load_a * r.moment_c;
            let step_c = -(r.moment_a * f1 - r.load_a * f2) / det;
            let step_a = -(-r.moment_c * f1 + r.load_c * f2) / det;
            if !(step_c.is_finite() && step_a.is_finite()) || a + step_a <= 0.0 {
                return Ok(None);
            }
            let (size, scale) = (step_c.abs().max(step_a.abs()), a + c.abs());
            if size <= tolerance * scale {
                return self.finish(normal, moment, c, a, &r).map(Some);
            }
            if tolerance > 1e-15 && size * size <= tolerance * scale * scale {
                // A loose solve: with a Lipschitz Jacobian the step from a point `size` off
                // lands about size^2/scale from the root, inside the tolerance, so the stepped
                // contact is taken without another evaluation (its rotation and K_N are those
                // before the step, good to about `size`).
                return self
                    .finish(normal, moment, c + step_c, a + step_a, &r)
                    .map(Some);
            }
            c += step_c;
            a += step_a;
        }
        Ok(None)
    }

    /// The solved contact `(c, a)` with its resultants `r`: K_N at both ends, checked to be
    /// non-negative, the rotation and the ends' positions against the flat.
    fn finish(
        &self,
        normal: f64,
        moment: f64,
        c: f64,
        a: f64,
        r: &Resultants,
    ) -> Result<NormalContact> {
        let a_comp = self.compliance().value();
        let scale = (2.0 / a).sqrt() / (PI * a_comp);
        let intensity = PerEdge {
            left: scale * (r.load_a - r.load_c),
            right: scale * (r.load_a + r.load_c),
        };
        let floor = -1e-9 * intensity.left.abs().max(intensity.right.abs());
        if intensity.left < floor || intensity.right < floor {
            return Err(Error::InvalidInput {
                field: "moment".into(),
                value: moment,
                valid: "a moment whose contact has a non-negative pressure intensity K_N at both ends (the profile is not convex there)",
            });
        }
        resolvable(moment, c, a)?;
        let ends = PerEdge {
            left: c - a,
            right: c + a,
        };
        let on_flat = match self.profile.shape() {
            Shape::FlatRounded {
                flat_half_width, ..
            } => PerEdge::from_fn(|e| ends[e].abs() <= *flat_half_width),
            _ => PerEdge {
                left: false,
                right: false,
            },
        };
        Ok(NormalContact {
            normal,
            moment,
            ends,
            rotation: -r.i0 / PI,
            intensity: PerEdge {
                left: intensity.left.max(0.0),
                right: intensity.right.max(0.0),
            },
            on_flat,
            centred: false,
        })
    }

    /// The contact pressure of `state` at `x`, by the route `state` was solved with: the
    /// symmetric [`Contact::pressure`] for a centred contact, [`Contact::pressure_in`] otherwise.
    pub fn pressure_at(&self, state: &NormalContact, x: f64) -> Result<f64> {
        if state.centred {
            return self.pressure(state.half_width(), x);
        }
        if let Shape::Hertz { radius } = self.profile.shape() {
            // The Hertz pressure about the contact's centre (closed_form::hertz_pressure).
            crate::error::finite("position x", x)?;
            let a_comp = self.compliance().value();
            let (c, a) = (state.centre(), state.half_width());
            return Ok(crate::closed_form::hertz_pressure(
                a_comp,
                *radius,
                a,
                x - c,
            ));
        }
        self.pressure_in(state, x)
    }

    /// The contact pressure of `state` at `x` (zero outside `[b1, b2]`):
    /// `p(x) = sqrt((x - b1)(b2 - x))/(pi A) integral_0^pi (g'(xi) - g'(x))/(xi - x) dphi`, the
    /// same kernel and routes as [`Contact::pressure`] about the centre c.
    pub fn pressure_in(&self, state: &NormalContact, x: f64) -> Result<f64> {
        crate::error::finite("position x", x)?;
        let PerEdge { left, right } = state.ends;
        if x <= left || x >= right {
            return Ok(0.0);
        }
        let (c, a) = (state.centre(), state.half_width());
        let root = ((x - left) * (right - x)).sqrt();
        if root == 0.0 || (x - c).abs() >= a {
            // Within rounding of an end, where the pressure vanishes.
            return Ok(0.0);
        }
        let gx = self.profile.slope(x)?;
        let sum = self.pressure_kernel(c, a, x, gx, root);
        let p = root / (PI * self.compliance().value()) * sum;
        if p.is_finite() {
            Ok(p.max(0.0))
        } else {
            Err(Error::InvalidInput {
                field: "position x".into(),
                value: x,
                valid: "a position whose pressure is finite for this contact (the scales overflow)",
            })
        }
    }

    fn resultants(&self, c: f64, a: f64) -> Result<Resultants> {
        Ok(Resultants::new(
            c,
            a,
            &self.profile.contact_integrals(c, a)?,
        ))
    }
}

/// The most half-widths a contact's centre may lie from x = 0: farther, its ends `c -+ a` keep
/// fewer than about 1e-11 of their value for the contact itself (and a march grid's cells, whose
/// positions are c plus fractions of a, fewer still), so results would be lost to rounding.
const MAX_ARM: f64 = 1e5;

/// Refuses a contact of centre `c` and half-width `a` whose centre lies more than [`MAX_ARM`]
/// half-widths from x = 0 (a moment arm M/P far beyond the contact: Hertz's contact moves by
/// M/P whatever its size). The error names `moment` ([`Error::with_moment_field`] renames it).
fn resolvable(moment: f64, c: f64, a: f64) -> Result<()> {
    if c.abs() > MAX_ARM * a {
        return Err(Error::InvalidInput {
            field: "moment".into(),
            value: moment,
            valid: "a moment whose contact lies within 1e5 contact half-widths of x = 0 (|M/P| for Hertz): farther, the contact's ends are lost to rounding",
        });
    }
    Ok(())
}
