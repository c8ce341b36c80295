//! Whether the steady-state analysis applies to a partial-slip cycle: both slip zones must grow
//! monotonically through each half-cycle (docs/validity.md, section 2). `check_slip_grows`
//! tests the start of each half exactly, which decides for every convex profile;
//! `sample_slip_growth` follows the partial path along each half, for other profiles and as an
//! independent check of that theorem (the tests run both on their own). Private to the crate:
//! `steady::analyse` is the public route.
//!
//! Conventions: point 1 is the end with the smaller Q, `dQ = Q2 - Q1 >= 0`,
//! `dsigma = sigma1 - sigma2`, x positive in the direction of positive Q (the right stick
//! boundary is `n`, the left `-m`); half 1 runs from the first point as given to the second.

use super::path::{edge_speeds, SegmentPath};
use super::{stick_zone, Segment, SteadyOptions, StickZone};
use crate::error::{Error, Result};
use crate::labels::{Edge, Half, PerEdge, PerPoint};
use crate::load::{Cycle, LoadPoint};
use crate::normal::Contact;
use crate::normal_moment::NormalContact;
use std::f64::consts::PI;

/// Samples per half-cycle for the along-the-half check of [`check_slip_grows`] on a profile that
/// is not convex, or under a moment whose rotation bounds do not settle it.
const SAMPLES_PER_HALF: usize = 32;

/// The partial path of one half-cycle at fraction t: the stick zone, the bounds
/// `[max(b1_s, b1(t)), min(b2_s, b2(t))]` the stick boundaries must stay inside (the start's
/// and the current contact's common part), and the outward speeds (`dm/dt` left, `dn/dt` right)
/// of the stick boundaries.
struct PathPoint {
    zone: StickZone,
    limit: PerEdge<f64>,
    boundary_rate: PerEdge<f64>,
}

impl PathPoint {
    /// The stick zone a step `h` further along the half, predicted to first order from the
    /// boundary speeds: the next sample's Newton starting point (`d' = (m' + n')/2`,
    /// `e' = (n' - m')/2`).
    fn predict(&self, h: f64) -> (f64, f64) {
        let PerEdge { left, right } = self.boundary_rate;
        (
            self.zone.half_width() + 0.5 * (left + right) * h,
            self.zone.eccentricity() + 0.5 * (right - left) * h,
        )
    }
}

/// One half-cycle from the reversal point `start` towards `end`, with the cycle's `dQ >= 0` and
/// `dsigma = sigma1 - sigma2` (point 1 the end of smaller Q).
///
/// At fraction t the partial path from `start` is, labelled by Q as the stick-zone equations need
/// it, the segment with `P1 + P2 = 2 P_start + t (P_end - P_start)`, shear range `t dQ`, tension
/// range `t dsigma` and mean rotation `(theta_start + theta(t))/2`, on either half (on the rising
/// half the current point replaces point 2, on the falling half point 1; both give these).
struct HalfPath<'a> {
    contact: &'a Contact,
    start: LoadPoint,
    end: LoadPoint,
    start_contact: NormalContact,
    shear_range: f64,
    bulk_range: f64,
    options: &'a SteadyOptions,
}

impl HalfPath<'_> {
    fn normal_change(&self) -> f64 {
        self.end.normal() - self.start.normal()
    }

    fn moment_change(&self) -> f64 {
        self.end.moment() - self.start.moment()
    }

    /// The stick zone at fraction t > 0 and the boundary speeds from the implicit function
    /// theorem: with `R(d, e; t) = 0` the two stick-zone equations of [`super::stick_zone`] and `J`
    /// their exact Jacobian in (d, e), `(d', e') = -J^-1 dR/dt`, where
    /// `dR1/dt = pi theta'/2 + pi A dsigma/(8f)` and
    /// `dR2/dt = (2f/A) pi e theta'/2 + pi e dsigma/4 - f (P_end - P_start) + dQ`, theta' the
    /// rate of the current contact's rotation (0 without a moment on a symmetric profile); then
    /// `n' = d' + e'`, `m' = d' - e'` (docs/validity.md, "Along the half").
    ///
    /// `near` holds a contact close to the one at t and is replaced by it.
    fn at(&self, t: f64, guess: Option<(f64, f64)>, near: &mut NormalContact) -> Result<PathPoint> {
        let f = self.contact.friction.value();
        let a_comp = self.contact.compliance().value();
        let load = self.start.lerp(&self.end, t);
        *near = self
            .contact
            .contact_near(load.normal(), load.moment(), near)?;
        let rotation_rate =
            near.rotation_change(a_comp, self.normal_change(), self.moment_change());
        let rotation = 0.5 * (self.start_contact.rotation() + near.rotation());
        let segment = Segment {
            normal_sum: 2.0 * self.start.normal() + t * self.normal_change(),
            shear_range: t * self.shear_range,
            bulk_range: t * self.bulk_range,
            rotation,
        };
        let (zone, _) = stick_zone(self.contact, &segment, guess, self.options)?;
        let (d, e) = (zone.half_width(), zone.eccentricity());
        let s = self.contact.profile.stick_integrals(d, e)?;
        let bulk = t * self.bulk_range;
        let jac = [
            [s.j0_d, s.j0_e],
            [
                2.0 * f / a_comp * s.j1_d,
                2.0 * f / a_comp * (s.j1_e + PI * rotation) + PI * bulk / 4.0,
            ],
        ];
        let r_t = [
            0.5 * PI * rotation_rate + PI * a_comp * self.bulk_range / (8.0 * f),
            f / a_comp * PI * e * rotation_rate + PI * e * self.bulk_range / 4.0
                - f * self.normal_change()
                + self.shear_range,
        ];
        let det = jac[0][0] * jac[1][1] - jac[0][1] * jac[1][0];
        let d_t = -(jac[1][1] * r_t[0] - jac[0][1] * r_t[1]) / det;
        let e_t = -(-jac[1][0] * r_t[0] + jac[0][0] * r_t[1]) / det;
        Ok(PathPoint {
            zone,
            limit: PerEdge {
                left: self.start_contact.end(Edge::Left).max(near.end(Edge::Left)),
                right: self
                    .start_contact
                    .end(Edge::Right)
                    .min(near.end(Edge::Right)),
            },
            boundary_rate: PerEdge {
                left: d_t - e_t,
                right: d_t + e_t,
            },
        })
    }

    /// The outward speed of the contact edge `edge` at `near`, the contact at some fraction.
    fn edge_rate(&self, near: &NormalContact, edge: Edge) -> f64 {
        edge_speeds(near, self.normal_change(), self.moment_change())[edge]
    }
}

/// Checks that both slip zones grow monotonically through both halves of a partial-slip cycle,
/// the condition for the partial-path relation and so the permanent stick zone to be exact (see
/// [`super::analyse`], which calls it, and docs/validity.md). Half 1 runs from the first point as given
/// to the second. Returns [`Error::SlipReversesInHalf`] at the first failure. Conventions: point 1
/// is the end with the smaller Q, `dQ = Q2 - Q1 >= 0`, `dsigma = sigma1 - sigma2`, x positive in
/// the direction of positive Q (so the right edge is `n`, the left `-m`).
///
/// At the start of a half (t = 0, the stick zone is the whole contact `[b1_s, b2_s]`) the test is
/// exact for any profile, edge by edge: the equivalent shear must change by more than f times
/// the pressure's edge coefficient, `dS_edge > f |dP_edge|` with `dS_left = dQ - pi a_s dsigma/4`,
/// `dS_right = dQ + pi a_s dsigma/4` and `dP_edge` from [`NormalContact::edge_load_changes`]
/// (dP at both edges without a moment: the symmetric test `dS >= f |dP|`; docs/validity.md,
/// "Start of a half" and "Under a moment"). The boundary speed reported is
/// `(f dP_edge - dS_edge)/(f K_N pi sqrt(2 a_s))`, which is `(f dP - dS)/(2 f P'(a_s))` for a
/// centred contact. Along the half `m, n` must be non-increasing and stay inside the start's and
/// the current contact. For a convex profile ([`crate::Profile::is_convex`]) without a moment
/// the start-of-half test implies that (docs/validity.md, "Along the half"); under a moment the
/// bounds on the rotation's rate along the segment ([`SegmentPath::bounds`]) settle it when
/// `a_s max|kappa + (pi/2) theta'| < A |c|` and
/// `a_max max|kappa - (pi/2) theta'| < A (dQ + f dP)/(2f)` ("Under a moment"); any other
/// cycle is followed at 32 points per half by [`sample_slip_growth`]'s scan.
#[cfg(test)]
pub(super) fn check_slip_grows(
    contact: &Contact,
    cycle: &Cycle,
    options: &SteadyOptions,
) -> Result<()> {
    let contacts = contacts(contact, cycle)?;
    let path = path_of(contact, cycle, contacts)?;
    check_slip_grows_with(contact, cycle, contacts, &path, options)
}

/// [`check_slip_grows`] with the contacts at the two points (as given) and along the segment
/// known.
pub(super) fn check_slip_grows_with(
    contact: &Contact,
    cycle: &Cycle,
    contacts: PerPoint<NormalContact>,
    path: &SegmentPath,
    options: &SteadyOptions,
) -> Result<()> {
    let f = contact.friction.value();
    let (d_q, d_sigma) = (cycle.shear_range(), cycle.bulk_range());
    let halves = halves(cycle, contacts);
    // The start of each half first: exact, and where a failure is most often found.
    for &(half, start, end, start_contact) in &halves {
        let d_p = end.normal() - start.normal();
        let d_m = end.moment() - start.moment();
        let a_s = start_contact.half_width();
        let d_edge = start_contact.edge_load_changes(d_p, d_m);
        let speeds = edge_speeds(&start_contact, d_p, d_m);
        for edge in Edge::BOTH {
            let equivalent_shear_range = path.shear_change(a_s, edge);
            if equivalent_shear_range <= f * d_edge[edge].abs() {
                let root = PI * (2.0 * a_s).sqrt();
                return Err(Error::SlipReversesInHalf {
                    half,
                    edge,
                    fraction: 0.0,
                    boundary_rate: (f * d_edge[edge] - equivalent_shear_range)
                        / (f * start_contact.normal_intensity(edge) * root),
                    limit_rate: speeds[edge].min(0.0),
                });
            }
        }
    }
    if contact.profile.is_convex()
        && (path.is_centred() || settled_by_bounds(contact, cycle, &halves, path))
    {
        return Ok(());
    }
    scan(contact, &halves, d_q, d_sigma, SAMPLES_PER_HALF, options)
}

/// Under a moment on a convex profile: whether the bounds on the rotation's rate along the
/// segment prove that both stick boundaries move inwards through each half and stay inside the
/// current contact (docs/validity.md, "Under a moment"). With `kappa = pi A dsigma/(8f)` and
/// `c = (f dP - dQ)/(2f) < 0` on each half: the boundaries move inwards while
/// `d |kappa + (pi/2) theta'| < A |c|`, and the zone stays inside the current contact when
/// `a(t) |kappa - (pi/2) theta_mean'| < A (dQ + f dP)/(2f)`; d never exceeds `a_s`, and the
/// rates are bounded by the segment's samples. False means "not proven", not "fails".
fn settled_by_bounds(
    contact: &Contact,
    cycle: &Cycle,
    halves: &[HalfCycle; 2],
    path: &SegmentPath,
) -> bool {
    let f = contact.friction.value();
    let a_comp = contact.compliance().value();
    let d_q = cycle.shear_range();
    let kappa = PI * a_comp * cycle.bulk_range() / (8.0 * f);
    let bounds = path.bounds();
    halves.iter().all(|&(_, start, end, start_contact)| {
        let d_p = end.normal() - start.normal();
        let reversed = start != cycle.low();
        let c = (f * d_p - d_q) / (2.0 * f);
        let inwards =
            start_contact.half_width() * bounds.largest_sum(kappa, reversed) < a_comp * c.abs();
        let inside = bounds.half_width * bounds.largest_sum(-kappa, reversed)
            < a_comp * (d_q + f * d_p) / (2.0 * f);
        c < 0.0 && inwards && inside
    })
}

/// The along-the-half part of [`check_slip_grows`] on its own, for any profile: the partial path
/// (docs/validity.md, "Along the half") solved at `samples_per_half` evenly spaced points of each
/// half, with the boundary speeds `(d', e') = -J^-1 dR/dt` from the exact Jacobian of the
/// stick-zone equations; the margins `-n'`, `-m'`, `(min(b2_s, b2(t)) - n)/t` and
/// `(-m - max(b1_s, b1(t)))/t` must stay above `-1e-9 a_s`, and the first failure is located by
/// bisection to 1e-10 of the half. It does not repeat the start-of-half test. A violation that
/// starts and ends between two samples is missed.
///
/// [`check_slip_grows`] calls it for profiles that are not convex and for moments whose bounds
/// do not settle the question; for convex ones without a moment it is the numerical check of the
/// theorem that makes it unnecessary (the tests run it on a grid of cycles).
///
/// # Errors
/// [`Error::SlipReversesInHalf`] at the first failure found; [`Error::InvalidCount`] when
/// `samples_per_half` is 0; the errors of the stick-zone solve.
#[cfg(test)]
pub(super) fn sample_slip_growth(
    contact: &Contact,
    cycle: &Cycle,
    samples_per_half: usize,
    options: &SteadyOptions,
) -> Result<()> {
    if samples_per_half == 0 {
        return Err(Error::InvalidCount {
            field: "samples_per_half".into(),
            value: 0,
            min: 1,
            max: u64::MAX,
        });
    }
    let halves = halves(cycle, contacts(contact, cycle)?);
    scan(
        contact,
        &halves,
        cycle.shear_range(),
        cycle.bulk_range(),
        samples_per_half,
        options,
    )
}

/// One half-cycle: which half as given, its start and end points, and the contact at its start.
type HalfCycle = (Half, LoadPoint, LoadPoint, NormalContact);

/// Both halves, the one that starts from the larger contact first (where the weak edge binds; Q
/// rising first on a tie), so that the failure reported does not depend on the order the points
/// were given in; `Half` numbers them as given.
fn halves(cycle: &Cycle, contacts: PerPoint<NormalContact>) -> [HalfCycle; 2] {
    let (low, high) = (cycle.low(), cycle.high());
    let PerPoint { first, second } = contacts;
    let (rising, falling, c_low, c_high) = if cycle.swapped() {
        (Half::Second, Half::First, second, first)
    } else {
        (Half::First, Half::Second, first, second)
    };
    let mut halves = [(rising, low, high, c_low), (falling, high, low, c_high)];
    if halves[1].3.half_width() > halves[0].3.half_width() {
        halves.swap(0, 1);
    }
    halves
}

/// The contacts at the two points of the cycle, as given.
#[cfg(test)]
fn contacts(contact: &Contact, cycle: &Cycle) -> Result<PerPoint<NormalContact>> {
    let (first, second) = cycle.as_given();
    Ok(PerPoint {
        first: contact.contact_at(&first)?,
        second: contact.contact_at(&second)?,
    })
}

/// The segment's contacts for [`check_slip_grows`].
#[cfg(test)]
fn path_of(
    contact: &Contact,
    cycle: &Cycle,
    contacts: PerPoint<NormalContact>,
) -> Result<SegmentPath> {
    let (low, high) = if cycle.swapped() {
        (contacts.second, contacts.first)
    } else {
        (contacts.first, contacts.second)
    };
    SegmentPath::new(contact, cycle, low, high)
}

/// The sampling of [`sample_slip_growth`] over the two halves.
fn scan(
    contact: &Contact,
    halves: &[HalfCycle; 2],
    d_q: f64,
    d_sigma: f64,
    samples_per_half: usize,
    options: &SteadyOptions,
) -> Result<()> {
    for &(half, start, end, start_contact) in halves {
        let path = HalfPath {
            contact,
            start,
            end,
            start_contact,
            shear_range: d_q,
            bulk_range: d_sigma,
            options,
        };
        let a_s = start_contact.half_width();
        // Along the half: margins that must stay >= 0, per edge: -(boundary speed), and the
        // distance inside the common part of the start's and the current contact, over t.
        let tolerance = 1e-9 * a_s;
        let margins = |p: &PathPoint, t: f64| -> [PerEdge<f64>; 2] {
            [
                p.boundary_rate.map(|rate| -rate),
                PerEdge {
                    left: (p.zone.left - p.limit.left) / t,
                    right: (p.limit.right - p.zone.right) / t,
                },
            ]
        };
        let mut guess = Some((a_s, start_contact.centre()));
        let mut near = start_contact;
        let mut previous_t = 0.0;
        let h = 1.0 / samples_per_half as f64;
        for k in 1..=samples_per_half {
            let t = k as f64 * h;
            let before = near;
            let p = path.at(t, guess, &mut near)?;
            guess = Some(p.predict(h));
            let failing = margins(&p, t);
            if !failing
                .iter()
                .flat_map(|m| m.to_array())
                .any(|v| v < -tolerance)
            {
                previous_t = t;
                continue;
            }
            // Bisect each failing margin on [previous_t, t] and report the earliest root.
            let mut first_failure: Option<(f64, Edge)> = None;
            for (kind, edge) in [0, 1].into_iter().flat_map(|k| Edge::BOTH.map(|e| (k, e))) {
                if failing[kind][edge] >= -tolerance {
                    continue;
                }
                let (mut lo, mut hi) = (previous_t, t);
                while hi - lo > 1e-10 {
                    let mid = 0.5 * (lo + hi);
                    let mut near_mid = before;
                    let q = path.at(mid, guess, &mut near_mid)?;
                    if margins(&q, mid)[kind][edge] < -tolerance {
                        hi = mid;
                    } else {
                        lo = mid;
                    }
                }
                if first_failure.is_none_or(|(t0, _)| hi < t0) {
                    first_failure = Some((hi, edge));
                }
            }
            // At least one margin failed at t, so its bisection set first_failure.
            let Some((fraction, edge)) = first_failure else {
                continue;
            };
            let mut near_failure = before;
            let q = path.at(fraction, guess, &mut near_failure)?;
            return Err(Error::SlipReversesInHalf {
                half,
                edge,
                fraction,
                boundary_rate: q.boundary_rate[edge],
                limit_rate: path.edge_rate(&near_failure, edge).min(0.0),
            });
        }
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use crate::steady::{analyse, Regime, SteadyOptions};
    use crate::{reference, Profile};

    #[test]
    fn the_moment_about_the_zone_centre_has_the_derivatives_the_proof_uses() {
        // docs/validity.md, "Along the half": with K = J1 - e J0 (the load moment about the
        // zone's centre), dK/dd = d dJ0/de and dK/de = d dJ0/dd for every profile. Checked with
        // the derivatives of the integrals at zones straddling a kink, off centre, and inside the
        // flat part's reach. Tolerances, of the derivatives' scale: 1e-12 for piecewise profiles,
        // whose integrals are exact (rounding of sums of a few dozen terms); 1e-8 for the power
        // law, whose derivative integrals by Gauss-Jacobi measure 3e-10 to 2.3e-9 off here. A
        // wrong identity would be off by O(1).
        for (profile, tolerance) in [
            (
                Profile::flat_rounded(0.3, reference::RADIUS).unwrap(),
                1e-12,
            ),
            (Profile::power_law(0.02, 1.5).unwrap(), 1e-8),
            (Profile::power_law(0.01, 2.5).unwrap(), 1e-8),
            (reference::flat_rounded_table(41).unwrap(), 1e-12),
        ] {
            for (d, e) in [(0.5, 0.0), (0.45, 0.1), (0.35, -0.2), (0.8, 0.31)] {
                let s = profile.stick_integrals(d, e).unwrap();
                let k_d = s.j1_d - e * s.j0_d;
                let k_e = s.j1_e - s.j0 - e * s.j0_e;
                let scale = s.j1_d.abs() + s.j1_e.abs() + d * (s.j0_d.abs() + s.j0_e.abs());
                assert!(
                    (k_d - d * s.j0_e).abs() <= tolerance * scale
                        && (k_e - d * s.j0_d).abs() <= tolerance * scale,
                    "{:?} at d = {d}, e = {e}: dK/dd {k_d} vs d dJ0/de {}, dK/de {k_e} vs d dJ0/dd {}",
                    profile.shape(),
                    d * s.j0_e,
                    d * s.j0_d
                );
            }
        }
    }

    #[test]
    fn built_in_profiles_are_convex_and_a_concave_table_is_not() {
        for profile in [
            Profile::hertz(50.0).unwrap(),
            Profile::flat_rounded(0.3, 50.0).unwrap(),
            Profile::power_law(0.02, 1.0).unwrap(),
            Profile::power_law(0.02, 3.5).unwrap(),
            reference::flat_rounded_table(41).unwrap(),
        ] {
            assert!(profile.is_convex(), "{:?}", profile.shape());
        }
        // g = sqrt(x): increasing, as tables must be, but g' falls.
        let x: Vec<f64> = (0..=20).map(|i| 0.1 * i as f64).collect();
        let g = x.iter().map(|x| x.sqrt()).collect();
        let concave = Profile::tabulated(x, g, vec![0.0]).unwrap();
        assert!(!concave.is_convex());
    }

    #[test]
    fn a_non_convex_table_is_sampled_and_agrees_with_hertz_inside_its_convex_part() {
        // g = x^2/100 (Hertz, R = 50) up to x = 1, then a straight line whose slope 0.015 is
        // below g'(1) = 0.02: not convex, so analyse samples both halves. The reference cycle's
        // contact (a < 0.8) lies in the Hertz part, where a cubic spline reproduces x^2 exactly,
        // so the stick zone must be Hertz's closed form to the Newton tolerance (1e-14 relative;
        // 1e-10 allows for the spline's rounding).
        let x: Vec<f64> = (0..=40).map(|i| 0.05 * i as f64).collect();
        let g = x
            .iter()
            .map(|&x| {
                if x <= 1.0 {
                    x * x / 100.0
                } else {
                    0.01 + 0.015 * (x - 1.0)
                }
            })
            .collect();
        let table = Profile::tabulated(x, g, vec![1.0]).unwrap();
        assert!(!table.is_convex());
        let options = SteadyOptions::default();
        let cycle = reference::cycle();
        let sampled = analyse(&reference::contact(table), &cycle, &options).unwrap();
        let hertz = analyse(&reference::hertz(), &cycle, &options).unwrap();
        assert_eq!(sampled.regime, Regime::PartialSlip);
        let (s, h) = (sampled.stick_zone.unwrap(), hertz.stick_zone.unwrap());
        for (a, b) in [(s.left, h.left), (s.right, h.right)] {
            assert!((a - b).abs() <= 1e-10 * h.half_width(), "{a} vs Hertz {b}");
        }
    }
}
