//! Steady-state analysis of an in-phase cycle (the paper's main result): regime, permanent stick
//! zone `[-m, n]` and slip-zone extents, for any profile under P, Q, sigma and a moment M.
//!
//! Conventions: point 1 is the end with the smaller Q, `dQ = Q2 - Q1 >= 0`,
//! `dsigma = sigma1 - sigma2`, `d = (m + n)/2` (half-width), `e = (n - m)/2` (eccentricity,
//! positive to the right, x increasing in the direction of positive Q). Under a moment each
//! point's contact `[b1, b2]` is off centre and the pad rotates by theta (docs/theory.md,
//! "Moment"); the tangential problem then sees the slope `g' + theta`, so the stick-zone
//! equations gain the mean rotation of the segment's two ends. Which cycles the analysis applies
//! to, and why, is derived in `docs/validity.md`.

use crate::error::{Error, Result};
pub use crate::labels::GivenPoint;
use crate::labels::{display_as_str, Edge, PerEdge, PerPoint};
use crate::load::{Cycle, LoadPoint};
use crate::normal::Contact;
use crate::normal_moment::NormalContact;
use crate::profile::Shape;
use std::f64::consts::PI;
mod path;
#[cfg(test)]
mod tests;
mod validity;
mod zone;
pub(crate) use path::SegmentPath;
pub(crate) use zone::{stick_zone, STICK_ZONE_EQUATIONS};

/// How the stick zone is found.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
#[non_exhaustive]
pub enum Method {
    /// Closed form for Hertz, the implicit equations otherwise (default).
    #[default]
    Auto,
    /// Always the two implicit equations (useful to check the closed form).
    Implicit,
}

/// Solver parameters, valid by construction: start from [`SteadyOptions::default`] and change
/// them with the `with_*` methods, which refuse a value outside its range.
///
/// ```
/// use halfplane::steady::{Method, SteadyOptions};
///
/// let options = SteadyOptions::default().with_method(Method::Implicit).with_tolerance(1e-12)?;
/// assert_eq!(options.tolerance(), 1e-12);
/// assert!(SteadyOptions::default().with_max_iterations(0).is_err());
/// # Ok::<(), halfplane::Error>(())
/// ```
///
/// No value skips the checks:
///
/// ```compile_fail,E0451
/// let options = halfplane::SteadyOptions { max_iterations: 0, ..Default::default() };
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SteadyOptions {
    method: Method,
    tolerance: f64,
    max_iterations: usize,
}

impl Default for SteadyOptions {
    fn default() -> Self {
        Self {
            method: Method::Auto,
            tolerance: 1e-14,
            max_iterations: 60,
        }
    }
}

impl SteadyOptions {
    /// Most Newton iterations allowed (3-6 are typical; the line search halves a step at most 40
    /// times, so this bounds the work of a solve).
    pub const MAX_ITERATIONS: usize = 10_000;

    /// Stick-zone method; default [`Method::Auto`].
    pub fn method(&self) -> Method {
        self.method
    }

    /// Newton stops when both steps are below `tolerance * d`; default 1e-14 (the integrals are
    /// exact to rounding, so the answer is limited by rounding, about 1e-15 relative).
    pub fn tolerance(&self) -> f64 {
        self.tolerance
    }

    /// Newton iteration cap; default 60 (3-6 are typical).
    pub fn max_iterations(&self) -> usize {
        self.max_iterations
    }

    /// The same options with another method (every method is valid).
    pub fn with_method(self, method: Method) -> Self {
        Self { method, ..self }
    }

    /// The same options with the Newton tolerance `tolerance`, relative to the stick zone's
    /// half-width: `1e-16 <= tolerance < 1` (below 1e-16 the steps never get there in f64).
    ///
    /// # Errors
    /// [`Error::InvalidInput`] naming `steady.tolerance` outside that range.
    pub fn with_tolerance(self, tolerance: f64) -> Result<Self> {
        if !(tolerance.is_finite() && (1e-16..1.0).contains(&tolerance)) {
            return Err(Error::InvalidInput {
                field: "steady.tolerance".into(),
                value: tolerance,
                valid: "a number with 1e-16 <= t < 1 (relative to the stick zone's half-width)",
            });
        }
        Ok(Self { tolerance, ..self })
    }

    /// The same options with at most `iterations` Newton iterations, 1 to [`Self::MAX_ITERATIONS`].
    ///
    /// # Errors
    /// [`Error::InvalidCount`] naming `steady.max_iterations` outside that range.
    pub fn with_max_iterations(self, iterations: usize) -> Result<Self> {
        if !(1..=Self::MAX_ITERATIONS).contains(&iterations) {
            return Err(Error::InvalidCount {
                field: "steady.max_iterations".into(),
                value: iterations as u64,
                min: 1,
                max: Self::MAX_ITERATIONS as u64,
            });
        }
        Ok(Self {
            max_iterations: iterations,
            ..self
        })
    }
}

/// A stick zone `[left, right] = [-m, n]`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct StickZone {
    /// Left end, `-m`.
    pub left: f64,
    /// Right end, `n`.
    pub right: f64,
}

impl StickZone {
    /// Builds `[-m, n]` from half-width d and eccentricity e: `n = d + e`, `-m = -d + e`.
    pub fn from_half_width(d: f64, e: f64) -> Self {
        Self {
            left: e - d,
            right: e + d,
        }
    }

    /// `d = (m + n)/2`.
    pub fn half_width(&self) -> f64 {
        0.5 * (self.right - self.left)
    }

    /// `e = (n - m)/2`.
    pub fn eccentricity(&self) -> f64 {
        0.5 * (self.right + self.left)
    }
}

/// The regime of the steady state.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Regime {
    /// `|Q| >= f P` at an end of the cycle: rigid sliding, no steady partial-slip state.
    GrossSliding {
        /// The end that slides (the first one found, as given).
        point: GivenPoint,
    },
    /// Eq. (1) holds: the whole contact sticks in the steady state.
    FullStick,
    /// A permanent stick zone with oscillating slip zones at both edges.
    PartialSlip,
}

impl Regime {
    /// "gross-sliding", "full-stick" or "partial-slip": the names the CLI prints.
    pub fn as_str(&self) -> &'static str {
        match self {
            Regime::GrossSliding { .. } => "gross-sliding",
            Regime::FullStick => "full-stick",
            Regime::PartialSlip => "partial-slip",
        }
    }
}

display_as_str!(Regime);

/// The figures the regime was decided from.
#[derive(Debug, Clone, Copy, PartialEq)]
#[non_exhaustive]
pub struct Criteria {
    /// `|Q|/P` at the first and second points as given (gross sliding when >= f).
    pub shear_ratio: PerPoint<f64>,
    /// `(|dQ| + pi a_max |dsigma|/4)/|dP|` (eq. 1; full stick when <= f). Infinite when dP = 0.
    /// Under a moment, the largest over both edges and along the segment of `|dS|/|dP_edge|`,
    /// with `dP_edge` the change of the pressure's edge coefficient at that edge
    /// ([`NormalContact::edge_load_changes`]); without one this is eq. (1).
    pub full_stick_ratio: f64,
    /// `pi a_max |dsigma|/4`, the bulk-tension term of eq. (1); partial slip is analysed only when
    /// `dQ - bulk_term > f |dP|` (see [`analyse`]).
    pub bulk_term: f64,
    /// f.
    pub friction: f64,
}

/// Slip-zone extents (lengths from the contact edge to the stick zone) at both ends of the cycle:
/// per edge, then per point as given (`a_i - m` at the left edge, `a_i - n` at the right; under
/// a moment `-m - b1_i` and `b2_i - n` with `[b1_i, b2_i]` the contact at point i).
pub type SlipZones = PerEdge<PerPoint<f64>>;

/// Result of [`analyse`].
#[derive(Debug, Clone, PartialEq)]
#[non_exhaustive]
pub struct SteadyState {
    /// The cycle, labelled by Q.
    pub cycle: Cycle,
    /// Contact half-widths at the first and second points as given.
    pub half_width: PerPoint<f64>,
    /// The normal contacts at the first and second points as given: ends, rotation and K_N at
    /// each edge (centred, `[-a, a]`, on a symmetric profile under no moment).
    pub contacts: PerPoint<NormalContact>,
    /// The regime.
    pub regime: Regime,
    /// What decided it.
    pub criteria: Criteria,
    /// `[-m, n]`: the permanent stick zone in partial slip; the smaller contact in full stick;
    /// `None` in gross sliding.
    pub stick_zone: Option<StickZone>,
    /// Slip-zone extents (zero in full stick); `None` in gross sliding.
    pub slip_zones: Option<SlipZones>,
    /// Newton iterations used (0 for a closed form).
    pub iterations: usize,
}

/// The data of a load segment that the stick-zone equations need.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct Segment {
    /// `P1 + P2`.
    pub(crate) normal_sum: f64,
    /// `dQ = Q2 - Q1 >= 0`.
    pub(crate) shear_range: f64,
    /// `dsigma = sigma1 - sigma2`.
    pub(crate) bulk_range: f64,
    /// The mean rotation `(theta1 + theta2)/2` of the two ends' contacts (0 without a moment on
    /// a symmetric profile).
    pub(crate) rotation: f64,
}

impl Segment {
    /// The segment between `low` (smaller Q) and `high`, whose contacts' mean rotation is
    /// `rotation`.
    pub(crate) fn between(low: &LoadPoint, high: &LoadPoint, rotation: f64) -> Self {
        Self {
            normal_sum: low.normal() + high.normal(),
            shear_range: high.shear() - low.shear(),
            bulk_range: low.bulk() - high.bulk(),
            rotation,
        }
    }
}

/// The normal contact at `point`, with a moment outside a table reported under `name.moment`
/// (for example `cycle.point1.moment`).
pub(crate) fn contact_named(
    contact: &Contact,
    point: &LoadPoint,
    name: &str,
) -> Result<NormalContact> {
    contact
        .contact_at(point)
        .map_err(|e| e.with_moment_field(&format!("{name}.moment")))
}

/// Analyses the steady state of the in-phase cycle: regime, stick zone and slip zones.
///
/// The partial-slip result (the paper's permanent stick zone `[-m, n]`) is exact only when, in
/// each half-cycle, both slip zones grow monotonically from the reversal: at a point a fraction t
/// along a half, the stick zone of the partial path from the reversal point (the same two
/// equations) must have boundaries that never move outwards (`dn/dt <= 0`,
/// `dm/dt <= 0`) and stay inside both the starting and the current contact. Otherwise material
/// re-sticks, or a receding edge keeps slipping in the previous half's direction and reverses
/// later in the half, and the result is not exact (`docs/validity.md` derives this and records the
/// comparison with time marching). Checked here:
///
/// - at the start of each half, exactly and for any profile: with `a_s` the contact half-width
///   there and `dP` the change of P over that half, both edges need
///   `dQ -/+ pi a_s dsigma/4 > f |dP|` (`-` at the left edge, `+` at the right); over the
///   two halves this is `dQ - pi a_max |dsigma|/4 > f |P2 - P1|`, which contains the paper's
///   end-point test `dQ > pi a_max |dsigma|/4` as the case `dP = 0`;
/// - along each half: for a convex profile ([`crate::Profile::is_convex`]: Hertz, flat-rounded,
///   power law, a convex table) the start-of-half test implies it (proved in
///   `docs/validity.md`), so nothing more is computed; for any other profile the partial path
///   is followed at 32 evenly spaced points of each half.
///
/// Errors: [`Error::SlipReversesInHalf`] (with the half, edge and fraction where the slip zone
/// first stops growing) and [`Error::StickZoneOutsideContact`] when `[-m, n]` is not inside the
/// smaller contact, `-min(a1, a2) < -m < n < min(a1, a2)` (it need not contain x = 0). Both
/// mean that the cycle is outside this analysis; a numerical time-marching solution
/// ([`crate::march`]) has no such restriction.
pub fn analyse(contact: &Contact, cycle: &Cycle, options: &SteadyOptions) -> Result<SteadyState> {
    let f = contact.friction.value();
    let (first, second) = cycle.as_given();
    let given = PerPoint { first, second };
    let shear_ratio = given.map(|p| p.shear().abs() / p.normal());
    let contacts = PerPoint {
        first: contact_named(contact, &first, "cycle.point1")?,
        second: contact_named(contact, &second, "cycle.point2")?,
    };
    let half_width = contacts.map(|c| c.half_width());
    let a_max = half_width.first.max(half_width.second);
    let d_q = cycle.shear_range();
    let bulk_term = PI * a_max * cycle.bulk_range().abs() / 4.0;
    let mut state = SteadyState {
        cycle: *cycle,
        half_width,
        contacts,
        regime: Regime::PartialSlip,
        criteria: Criteria {
            shear_ratio,
            full_stick_ratio: f64::INFINITY,
            bulk_term,
            friction: f,
        },
        stick_zone: None,
        slip_zones: None,
        iterations: 0,
    };
    if let Some(point) = GivenPoint::BOTH.into_iter().find(|&p| shear_ratio[p] >= f) {
        state.regime = Regime::GrossSliding { point };
        return Ok(state);
    }
    let (low, high) = if cycle.swapped() {
        (contacts.second, contacts.first)
    } else {
        (contacts.first, contacts.second)
    };
    let path = SegmentPath::new(contact, cycle, low, high)?;
    let common = PerEdge {
        left: low.end(Edge::Left).max(high.end(Edge::Left)),
        right: low.end(Edge::Right).min(high.end(Edge::Right)),
    };
    // Eq. (1) with a = a_max, written without dividing by dP, generalised edge by edge along
    // the segment (`SegmentPath::sticks`); a constant load sticks.
    let (sticks, ratio) = path.sticks(f);
    state.criteria.full_stick_ratio = ratio;
    if sticks || (d_q == 0.0 && bulk_term == 0.0) {
        state.regime = Regime::FullStick;
        state.stick_zone = Some(StickZone {
            left: common.left,
            right: common.right,
        });
        state.slip_zones = Some(SlipZones::default());
        return Ok(state);
    }
    let segment = Segment::between(
        &cycle.low(),
        &cycle.high(),
        0.5 * (low.rotation() + high.rotation()),
    );
    // Under a moment, a start from the end contacts (the smaller scaled to P_K as
    // a ~ P^n, centred between the two) instead of the fresh normal solves of `zone_guess`
    // (none for Hertz's closed-form zone).
    let closed_form =
        options.method() == Method::Auto && matches!(contact.profile.shape(), Shape::Hertz { .. });
    let guess = (!path.is_centred() && !closed_form).then(|| {
        let p_k = 0.5 * segment.normal_sum - segment.shear_range / (2.0 * f);
        if let Some(found) = power_law_zone_guess(contact, &segment, p_k) {
            return found;
        }
        let small = if low.half_width() < high.half_width() {
            low
        } else {
            high
        };
        (
            small.half_width() * (p_k.max(0.0) / small.normal()).powf(load_exponent(&small)),
            0.5 * (low.centre() + high.centre()),
        )
    });
    let (zone, iterations) = match stick_zone(contact, &segment, guess, options) {
        Ok(found) => found,
        // A start that does not converge, or leaves a table: the careful start instead.
        Err(_) if guess.is_some() => stick_zone(contact, &segment, None, options)?,
        Err(e) => return Err(e),
    };
    if !(common.left < zone.left && zone.left < zone.right && zone.right < common.right) {
        return Err(Error::StickZoneOutsideContact {
            left: zone.left,
            right: zone.right,
            common: [common.left, common.right],
        });
    }
    validity::check_slip_grows_with(contact, cycle, contacts, &path, options)?;
    state.stick_zone = Some(zone);
    state.slip_zones = Some(PerEdge {
        left: contacts.map(|c| zone.left - c.end(Edge::Left)),
        right: contacts.map(|c| c.end(Edge::Right) - zone.right),
    });
    state.iterations = iterations;
    Ok(state)
}

/// For a power law, the stick zone's start `(d, e)` from closed forms: the zone is the contact
/// under `p_k` with the rotation `tilt = theta_m + A dsigma/(8f)` ([`zone_guess`]); the moment
/// giving the symmetric contact (no rotation) that tilt to first order is
/// `M = -tilt pi a0^2/(2A)` ([`NormalContact::rotation_change`]), and that contact is
/// [`Contact::power_law_guess`]. `None` for other profiles or `p_k <= 0`.
fn power_law_zone_guess(contact: &Contact, segment: &Segment, p_k: f64) -> Option<(f64, f64)> {
    if p_k <= 0.0 || !matches!(contact.profile.shape(), Shape::PowerLaw { .. }) {
        return None;
    }
    let a_comp = contact.compliance().value();
    let f = contact.friction.value();
    let tilt = segment.rotation + a_comp * segment.bulk_range / (8.0 * f);
    let a0 = contact.half_width(p_k).ok()?;
    let moment = -tilt * PI * a0 * a0 / (2.0 * a_comp);
    let (c, a) = contact.power_law_guess(p_k, moment)?;
    Some((a, c))
}

/// The local exponent `n = (P/a) da/dP` of the contact law at `c`, P changing with the moment
/// about the centre held (both ends' edge coefficients change by dP): the mean of the ends'
/// outward speeds ([`path::edge_speeds`]) over a. 1/2 for Hertz, 1/k for the power law; 1/2 where
/// K_N is not known (0 at an end).
fn load_exponent(c: &NormalContact) -> f64 {
    let speeds = path::edge_speeds(c, 1.0, c.centre());
    let n = 0.5 * (speeds.left + speeds.right) * c.normal() / c.half_width();
    if n.is_finite() && n > 0.0 {
        n
    } else {
        0.5
    }
}
