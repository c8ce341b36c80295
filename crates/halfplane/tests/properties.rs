//! Property tests of the steady-state analysis and the normal problem (proptest).
//!
//! Inputs cover realistic ranges: E 1e4..1e6 MPa, nu 0..0.49, f 0.1..1, P 1..1e4 N/mm with the
//! two loads of a cycle within a factor of 2, |Q| < f P, and bulk tension up to 1.2 times the
//! largest range the paper's analysis accepts (so slip reversal, an error, is reached too), on
//! Hertz, flat-rounded and power-law profiles. Errors are acceptable outcomes but must be the
//! library's typed [`halfplane::Error`]; a panic fails the property.
//!
//! Symmetries (docs/theory.md sign conventions; `g` is even, so `g'` is odd):
//! - Swapping the caller's two points changes nothing: the cycle is labelled by Q internally.
//! - Mirror `x -> -x`: shear traction and Q change sign, but the bulk tension sigma is a normal
//!   stress `sigma_xx` and does not. In the equations, `(-Q, sigma)` relabels the ends (point 1 is
//!   the end of smaller Q), so `dsigma = sigma1 - sigma2` changes sign with dQ and P1 + P2 kept;
//!   `J0(d, -e) = -J0(d, e)` and `J1(d, -e) = J1(d, e)` then give `(d, -e)`: the stick zone
//!   `[-m, n]` becomes `[-n, m]` and the left and right slip zones trade places. (The equivalent
//!   shear at the new left edge, `-Q + pi a sigma/4`, is minus the old right edge's
//!   `Q - pi a sigma/4`.)
//! - Reversal of all tangential loads `(-Q, -sigma)`: every shear traction and slip changes sign,
//!   `dsigma` is unchanged by the relabelling, and the stick zone stays where it is.
//!
//! 1024 cases per property: the whole file takes about 0.6 s in the debug profile (budget ~5 s).

use halfplane::steady::analyse;
use halfplane::{
    asymptotic, evolution, Contact, Cycle, Error, Friction, GivenPoint, LoadPoint, Material,
    Profile, Regime, SteadyOptions, SteadyState,
};
use proptest::prelude::*;

const CASES: u32 = 1024;

/// A value log-uniformly distributed over [lo, hi].
fn log_uniform(lo: f64, hi: f64) -> impl Strategy<Value = f64> {
    (lo.log10()..=hi.log10()).prop_map(|e| 10f64.powf(e))
}

fn profile() -> impl Strategy<Value = Profile> {
    prop_oneof![
        log_uniform(1.0, 1000.0).prop_map(|r| Profile::hertz(r).unwrap()),
        (0.0..2.0f64, log_uniform(1.0, 1000.0))
            .prop_map(|(b, r)| Profile::flat_rounded(b, r).unwrap()),
        (log_uniform(1e-4, 1.0), 1.0..4.0f64).prop_map(|(c, k)| Profile::power_law(c, k).unwrap()),
    ]
}

fn contact() -> impl Strategy<Value = Contact> {
    (profile(), log_uniform(1e4, 1e6), 0.0..0.49f64, 0.1..1.0f64).prop_map(|(profile, e, nu, f)| {
        Contact::new(
            profile,
            Material::new(e, nu).unwrap(),
            Friction::new(f).unwrap(),
        )
    })
}

/// A contact and the two points of a cycle, as given.
#[derive(Debug, Clone)]
struct Case {
    contact: Contact,
    first: LoadPoint,
    second: LoadPoint,
}

impl Case {
    /// The same case with every point transformed by `(P, Q, sigma) -> map(P, Q, sigma)`.
    fn map(&self, map: impl Fn(f64, f64, f64) -> (f64, f64, f64)) -> Case {
        let point = |p: &LoadPoint| {
            let (n, s, b) = map(p.normal(), p.shear(), p.bulk());
            LoadPoint::new("mapped", n, s, b).unwrap()
        };
        Case {
            contact: self.contact.clone(),
            first: point(&self.first),
            second: point(&self.second),
        }
    }

    fn analyse(&self) -> Result<SteadyState, Error> {
        analyse(
            &self.contact,
            &Cycle::new(self.first, self.second),
            &SteadyOptions::default(),
        )
    }
}

fn case() -> impl Strategy<Value = Case> {
    (
        contact(),
        log_uniform(1.0, 1e4),
        -0.3..0.3f64,
        -1.0..1.0f64,
        -1.0..1.0f64,
        -1.0..1.0f64,
        -1.0..1.0f64,
    )
        .prop_map(|(contact, p1, ratio, u1, u2, t1, t2)| {
            let p2 = (p1 * 10f64.powf(ratio)).clamp(1.0, 1e4);
            let f = contact.friction().value();
            // |u| < 1 strictly, so |Q| < f P.
            let (q1, q2) = (u1 * f * p1, u2 * f * p2);
            // Bulk tension up to 1.2 times the range with pi a_max |dsigma|/4 = dQ.
            let a_max = contact.half_width(p1.max(p2)).unwrap_or(1.0);
            let scale = 1.2 * 2.0 * (q2 - q1).abs() / (std::f64::consts::PI * a_max);
            Case {
                first: LoadPoint::new("first", p1, q1, t1 * scale).unwrap(),
                second: LoadPoint::new("second", p2, q2, t2 * scale).unwrap(),
                contact,
            }
        })
}

/// The result with the caller's points in the other order, mapped back to the original order.
fn unswap(s: &SteadyState) -> SteadyState {
    let mut s = s.clone();
    s.half_width.swap();
    s.criteria.shear_ratio.swap();
    if let Some(z) = s.slip_zones.as_mut() {
        z.left.swap();
        z.right.swap();
    }
    s
}

/// Same error variant (the values inside may be mirrored).
fn same_variant(a: &Error, b: &Error) -> bool {
    std::mem::discriminant(a) == std::mem::discriminant(b)
}

fn close(a: f64, b: f64, tol: f64) -> bool {
    (a - b).abs() <= tol
}

/// Which regime, ignoring which point slides.
fn regime_kind(r: &Regime) -> u8 {
    match r {
        Regime::GrossSliding { .. } => 0,
        Regime::FullStick => 1,
        Regime::PartialSlip => 2,
    }
}

/// Every number of a successful analysis is finite (`full_stick_ratio` is +inf when dP = 0, as
/// documented, and never NaN).
fn assert_finite(s: &SteadyState) -> Result<(), TestCaseError> {
    let c = &s.criteria;
    let mut values = vec![
        s.half_width.first,
        s.half_width.second,
        c.shear_ratio.first,
        c.shear_ratio.second,
        c.bulk_term,
        c.friction,
    ];
    if let Some(z) = s.stick_zone {
        values.extend([z.left, z.right]);
    }
    if let Some(z) = s.slip_zones {
        values.extend(z.left.into_iter().chain(z.right));
    }
    for v in values {
        prop_assert!(v.is_finite(), "non-finite value {v} in {s:?}");
    }
    prop_assert!(
        !c.full_stick_ratio.is_nan() && c.full_stick_ratio >= 0.0,
        "full_stick_ratio {} in {s:?}",
        c.full_stick_ratio
    );
    if c.full_stick_ratio.is_infinite() {
        prop_assert_eq!(s.cycle.normal_range(), 0.0);
    }
    Ok(())
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(CASES))]

    /// Swapping the two points of the cycle changes nothing: same regime (the sliding point is
    /// the same physical point), the bit-identical stick zone, and slip zones, half-widths and
    /// shear ratios that trade their point index. Errors are identical.
    #[test]
    fn swapping_the_points_changes_nothing(case in case()) {
        let given = case.analyse();
        let swapped = Case { first: case.second, second: case.first, ..case.clone() }.analyse();
        match (&given, &swapped) {
            (Ok(a), Ok(b)) => {
                let b = unswap(b);
                prop_assert_eq!(regime_kind(&a.regime), regime_kind(&b.regime));
                if let (Regime::GrossSliding { point: pa }, Regime::GrossSliding { point: pb }) =
                    (a.regime, swapped.as_ref().unwrap().regime)
                {
                    // The first sliding point found, as given: the same physical point unless
                    // both ends slide.
                    let f = a.criteria.friction;
                    let both = a.criteria.shear_ratio.iter().all(|&r| r >= f);
                    prop_assert_eq!(pa == pb, both);
                }
                prop_assert_eq!(a.stick_zone, b.stick_zone);
                prop_assert_eq!(a.slip_zones, b.slip_zones);
                prop_assert_eq!(a.half_width, b.half_width);
                prop_assert_eq!(a.criteria, b.criteria);
                prop_assert_eq!(a.iterations, b.iterations);
            }
            (Err(a), Err(Error::SlipReversesInHalf { half, edge, fraction, boundary_rate, limit_rate })) => {
                // Half 1 runs from the first point as given: swapping renumbers the halves.
                let b = Error::SlipReversesInHalf {
                    half: half.other(),
                    edge: *edge,
                    fraction: *fraction,
                    boundary_rate: *boundary_rate,
                    limit_rate: *limit_rate,
                };
                prop_assert_eq!(a, &b);
            }
            (Err(a), Err(b)) => prop_assert_eq!(a, b),
            _ => prop_assert!(false, "given {given:?} but swapped {swapped:?}"),
        }
    }

    /// The mirror x -> -x, i.e. (P, Q, sigma) -> (P, -Q, sigma), mirrors the stick zone:
    /// `[-m, n]` -> `[-n, m]`, and swaps the left and right slip zones. Tolerance 1e-12 of the
    /// largest contact: Newton stops at 1e-14 relative on the implicit route, and the mirrored
    /// iteration need not round identically.
    #[test]
    fn mirror_mirrors_the_stick_zone(case in case()) {
        let given = case.analyse();
        let mirrored = case.map(|p, q, s| (p, -q, s)).analyse();
        match (&given, &mirrored) {
            (Ok(a), Ok(b)) => {
                prop_assert_eq!(a.regime, b.regime);
                prop_assert_eq!(a.half_width, b.half_width);
                let tol = 1e-12 * a.half_width.first.max(a.half_width.second);
                if let (Some(za), Some(zb)) = (a.stick_zone, b.stick_zone) {
                    prop_assert!(
                        close(za.left, -zb.right, tol) && close(za.right, -zb.left, tol),
                        "stick zone {za:?}, mirrored {zb:?}"
                    );
                } else {
                    prop_assert_eq!(a.stick_zone.is_some(), b.stick_zone.is_some());
                }
                if let (Some(sa), Some(sb)) = (a.slip_zones, b.slip_zones) {
                    for i in GivenPoint::BOTH {
                        prop_assert!(
                            close(sa.left[i], sb.right[i], tol) && close(sa.right[i], sb.left[i], tol),
                            "slip zones {sa:?}, mirrored {sb:?}"
                        );
                    }
                } else {
                    prop_assert_eq!(a.slip_zones.is_some(), b.slip_zones.is_some());
                }
            }
            (Err(a), Err(b)) => prop_assert!(same_variant(a, b), "{a:?} but mirrored {b:?}"),
            _ => prop_assert!(false, "given {given:?} but mirrored {mirrored:?}"),
        }
    }

    /// Reversing every tangential load, (P, Q, sigma) -> (P, -Q, -sigma), leaves the stick zone
    /// and the slip zones where they are (tolerance as for the mirror).
    #[test]
    fn reversing_the_tangential_loads_keeps_the_stick_zone(case in case()) {
        let given = case.analyse();
        let reversed = case.map(|p, q, s| (p, -q, -s)).analyse();
        match (&given, &reversed) {
            (Ok(a), Ok(b)) => {
                prop_assert_eq!(a.regime, b.regime);
                let tol = 1e-12 * a.half_width.first.max(a.half_width.second);
                if let (Some(za), Some(zb)) = (a.stick_zone, b.stick_zone) {
                    prop_assert!(
                        close(za.left, zb.left, tol) && close(za.right, zb.right, tol),
                        "stick zone {za:?}, reversed {zb:?}"
                    );
                }
                if let (Some(sa), Some(sb)) = (a.slip_zones, b.slip_zones) {
                    for i in GivenPoint::BOTH {
                        prop_assert!(
                            close(sa.left[i], sb.left[i], tol) && close(sa.right[i], sb.right[i], tol),
                            "slip zones {sa:?}, reversed {sb:?}"
                        );
                    }
                }
            }
            (Err(a), Err(b)) => prop_assert!(same_variant(a, b), "{a:?} but reversed {b:?}"),
            _ => prop_assert!(false, "given {given:?} but reversed {reversed:?}"),
        }
    }

    /// P(a(P)) = P to 1e-10 relative. a(P) is a closed form (Hertz, power law) or a Newton
    /// iteration to 1e-15 relative in a (flat-rounded), and P(a) is evaluated exactly to rounding
    /// (piecewise-polynomial moments, or a Gauss-Jacobi rule below rounding for the power law).
    /// The relative error in P is the one in a times `a P'/P`: 2 for Hertz, k <= 4 for the power
    /// law, larger on a flat-rounded punch just past its flat, where P ~ (a - b)^(3/2). 1e-10
    /// leaves room for a conditioning factor of 1e4 over a few ulps.
    #[test]
    fn load_of_half_width_is_the_load(contact in contact(), p in log_uniform(1.0, 1e4)) {
        let a = contact.half_width(p);
        prop_assert!(a.is_ok(), "half_width({p}) failed: {a:?}");
        let a = a.unwrap();
        prop_assert!(a.is_finite() && a > 0.0, "a({p}) = {a}");
        let back = contact.load(a).unwrap();
        prop_assert!(
            (back - p).abs() <= 1e-10 * p,
            "P(a(P)) = {back} for P = {p} (a = {a}, relative error {:e})",
            (back - p).abs() / p
        );
    }

    /// In partial slip the stick zone lies strictly inside the smaller contact, with both slip
    /// zones of positive length at both points.
    #[test]
    fn partial_slip_stick_zone_lies_inside_the_smaller_contact(case in case()) {
        if let Ok(s) = case.analyse() {
            if s.regime == Regime::PartialSlip {
                let a_min = s.half_width.first.min(s.half_width.second);
                let z = s.stick_zone.unwrap();
                prop_assert!(
                    -a_min < z.left && z.left < z.right && z.right < a_min,
                    "stick zone {z:?} not inside [-{a_min}, {a_min}]"
                );
                let slip = s.slip_zones.unwrap();
                for w in slip.left.into_iter().chain(slip.right) {
                    prop_assert!(w > 0.0, "slip zone {w} in {slip:?}");
                }
            }
        }
    }

    /// Nothing is NaN: steady analysis, the asymptotic description, the evolution along the cycle
    /// (5 points per half) and the pressure are finite whenever they succeed.
    #[test]
    fn successful_results_are_finite(case in case(), x in -1.0..1.0f64) {
        let cycle = Cycle::new(case.first, case.second);
        if let Ok(s) = case.analyse() {
            assert_finite(&s)?;
            let a = s.half_width.first;
            let p = case.contact.pressure(a, x * a);
            prop_assert!(matches!(p, Ok(v) if v.is_finite() && v >= 0.0), "p({}) = {p:?}", x * a);
        }
        if let Ok(e) = evolution::evolve(&case.contact, &cycle, 5, &SteadyOptions::default()) {
            for p in &e.points {
                let values = [
                    p.fraction,
                    p.half_width,
                    p.stick_zone.left,
                    p.stick_zone.right,
                    p.asymptotic_stick_zone.left,
                    p.asymptotic_stick_zone.right,
                ];
                prop_assert!(values.iter().all(|v| v.is_finite()), "{p:?}");
            }
        }
        if let Ok(a) = asymptotic::steady(&case.contact, &cycle) {
            let mut values = vec![a.stick_load[0], a.stick_load[1], a.stick_zone.left, a.stick_zone.right];
            for e in &a.edges {
                values.extend([e.half_width, e.normal_intensity]);
                values.extend(e.shear_intensity.into_iter().chain(e.equivalent_shear));
            }
            values.extend(a.slip_zones.into_iter().flatten());
            prop_assert!(values.iter().all(|v| v.is_finite()), "{a:?}");
        }
    }
}
