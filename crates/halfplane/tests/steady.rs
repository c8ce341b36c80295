//! Steady-state stick zone: closed forms, independent routes, symmetries and assumption checks.

mod common;
use common::*;
use halfplane::steady::{self, Method, Regime, SteadyOptions};
use halfplane::{closed_form, Contact, Cycle, Error, Half, Profile};
use std::f64::consts::PI;

fn solve(c: &Contact, cycle: &Cycle) -> halfplane::SteadyState {
    steady::analyse(c, cycle, &SteadyOptions::default()).unwrap()
}

fn implicit(c: &Contact, cycle: &Cycle) -> halfplane::SteadyState {
    steady::analyse(
        c,
        cycle,
        &SteadyOptions::default().with_method(Method::Implicit),
    )
    .unwrap()
}

fn zone(s: &halfplane::SteadyState) -> (f64, f64) {
    let z = s.stick_zone.expect("a stick zone");
    (z.left, z.right)
}

#[test]
fn hertz_example_matches_the_independent_marching_check() {
    // docs/theory.md quotes 5 significant figures from a separate time-marching computation.
    let s = solve(&contact(Profile::hertz(RADIUS).unwrap()), &theory_cycle());
    assert_eq!(s.regime, Regime::PartialSlip);
    let (left, right) = zone(&s);
    for (got, want, name) in [
        (left, -0.66607, "-m"),
        (right, 0.68123, "n"),
        (s.half_width.first, 0.76113, "a1"),
        (s.half_width.second, 0.90059, "a2"),
        (s.stick_zone.unwrap().half_width(), 0.67365, "d"),
        (s.stick_zone.unwrap().eccentricity(), 0.0075833, "e"),
    ] {
        assert!(rel(got, want) < 1e-5, "{name} = {got}, reference {want}");
    }
}

#[test]
fn general_routes_equal_the_hertz_closed_form() {
    // Tier 1 (1e-10, the requirement): the implicit equations solved by Newton on
    // (a) the exact piecewise moments of the Hertz profile, (b) Gauss-Jacobi quadrature of the
    // power law k = 2, B = 1/(2R), (c) the spline of a tabulated parabola, (d) flat-rounded b = 0.
    let cycle = theory_cycle();
    let exact = zone(&solve(&contact(Profile::hertz(RADIUS).unwrap()), &cycle));
    let (x, g) = sampled(|x| x * x / (2.0 * RADIUS), 2.0, 20);
    for (name, profile) in [
        ("Hertz, implicit", Profile::hertz(RADIUS).unwrap()),
        (
            "power law k=2 (quadrature)",
            Profile::power_law(0.5 / RADIUS, 2.0).unwrap(),
        ),
        (
            "tabulated parabola",
            Profile::tabulated(x, g, vec![]).unwrap(),
        ),
        (
            "flat-rounded b=0",
            Profile::flat_rounded(0.0, RADIUS).unwrap(),
        ),
    ] {
        let got = zone(&implicit(&contact(profile), &cycle));
        assert!(
            rel(got.0, exact.0) < 1e-10 && rel(got.1, exact.1) < 1e-10,
            "{name}: {got:?} vs closed form {exact:?}"
        );
    }
}

#[test]
fn stick_zone_does_not_depend_on_the_order_of_the_points() {
    // Relabelling by Q makes the two orders the same computation: identical to rounding.
    let (p1, p2) = (point(1000.0, -250.0, -20.0), point(1400.0, 250.0, 20.0));
    for profile in [
        Profile::hertz(RADIUS).unwrap(),
        Profile::flat_rounded(0.3, RADIUS).unwrap(),
        Profile::power_law(0.01, 2.5).unwrap(),
    ] {
        let c = contact(profile);
        let a = solve(&c, &Cycle::new(p1, p2));
        let b = solve(&c, &Cycle::new(p2, p1));
        assert!(b.cycle.swapped());
        assert_eq!(zone(&a), zone(&b), "{:?}", c.profile().shape());
        let (sa, sb) = (a.slip_zones.unwrap(), b.slip_zones.unwrap());
        assert_eq!(
            sa.right.first, sb.right.second,
            "slip zones follow the points as given"
        );
        assert_eq!(a.half_width.first, b.half_width.second);
    }
}

#[test]
fn constant_normal_load_and_tension_reduce_to_p_k() {
    // dP = dsigma = 0: the stick zone is centred with half-width a(P_K), P_K = P0 - dQ/(2f)
    // (paper eq. PK). Independent: a(P_K) by the contact law inversion alone. Tier 1: 1e-12.
    let cycle = Cycle::new(point(1200.0, -250.0, 7.0), point(1200.0, 250.0, 7.0));
    let p_k = 1200.0 - 500.0 / (2.0 * 0.6);
    let (x, g) = sampled(|x| 0.01 * x.powi(3), 2.0, 40);
    for profile in [
        Profile::flat_rounded(0.3, RADIUS).unwrap(),
        Profile::power_law(0.01, 2.5).unwrap(),
        Profile::tabulated(x, g, vec![]).unwrap(),
        flat_rounded_table(0.3, RADIUS),
    ] {
        let c = contact(profile);
        let s = solve(&c, &cycle);
        let z = s.stick_zone.unwrap();
        let a_k = c.half_width(p_k).unwrap();
        assert!(
            rel(z.half_width(), a_k) < 1e-12,
            "{:?}: d = {}, a(P_K) = {a_k}",
            c.profile().shape(),
            z.half_width()
        );
        assert!(
            z.eccentricity().abs() < 1e-12 * a_k,
            "e = {}",
            z.eccentricity()
        );
    }
}

#[test]
fn reversing_the_tension_range_mirrors_the_stick_zone() {
    // J0 is odd and J1 even in e, so (e, dsigma) -> (-e, -dsigma) solves the same equations.
    let forward = theory_cycle();
    let mirrored = Cycle::new(point(1000.0, -250.0, 20.0), point(1400.0, 250.0, -20.0));
    for profile in [
        Profile::flat_rounded(0.3, RADIUS).unwrap(),
        Profile::power_law(0.01, 2.5).unwrap(),
        flat_rounded_table(0.3, RADIUS),
    ] {
        let c = contact(profile);
        let (l, r) = zone(&solve(&c, &forward));
        let (ml, mr) = zone(&solve(&c, &mirrored));
        assert!(
            (ml + r).abs() < 1e-12 && (mr + l).abs() < 1e-12,
            "{:?}: [{l}, {r}] vs mirrored [{ml}, {mr}]",
            c.profile().shape()
        );
        assert!(
            r + l > 1e-4,
            "the case must be eccentric for the test to mean anything"
        );
    }
}

#[test]
fn kinks_inside_the_stick_zone_keep_full_accuracy() {
    // Flat-rounded with tension: the kinks at +-b lie inside [-m, n]. The solution must satisfy
    // both equations when they are re-evaluated by the tests' own quadrature, split at the kink
    // angles (tier 1, 1e-12 relative); the tabulated profile with its kink stated must agree with
    // the analytic one (the spline is exact on each side of the kink), 1e-11.
    let (b, r) = (0.3, RADIUS);
    let c = contact(Profile::flat_rounded(b, r).unwrap());
    let cycle = theory_cycle();
    let s = solve(&c, &cycle);
    let z = s.stick_zone.unwrap();
    let (d, e) = (z.half_width(), z.eccentricity());
    assert!(
        z.left < -b && z.right > b,
        "kinks must be inside the stick zone"
    );
    let slope = |x: f64| {
        if x.abs() <= b {
            0.0
        } else {
            x.signum() * (x.abs() - b) / r
        }
    };
    let mut cuts = [0.0, PI, ((b - e) / d).acos(), ((-b - e) / d).acos()];
    cuts.sort_by(f64::total_cmp);
    let j = |weight: &dyn Fn(f64) -> f64| -> f64 {
        cuts.windows(2)
            .map(|w| {
                integrate(w[0], w[1], 8, |t| {
                    let xi = e + d * t.cos();
                    weight(xi) * slope(xi)
                })
            })
            .sum()
    };
    let (a_comp, f) = (c.compliance().value(), 0.6);
    let dsigma = cycle.bulk_range();
    let consistency = j(&|_| 1.0) + PI * a_comp * dsigma / (8.0 * f);
    let lhs = f * (cycle.low().normal() + cycle.high().normal())
        - cycle.shear_range()
        - PI * e * dsigma / 4.0;
    let equilibrium = lhs - 2.0 * f / a_comp * j(&|xi| xi);
    assert!(
        consistency.abs() < 1e-12 * (PI * a_comp * dsigma / (8.0 * f)).abs(),
        "consistency residual {consistency}"
    );
    assert!(
        equilibrium.abs() < 1e-12 * lhs,
        "equilibrium residual {equilibrium}"
    );
    let t = zone(&solve(&contact(flat_rounded_table(b, r)), &cycle));
    assert!(
        rel(t.0, z.left) < 1e-11 && rel(t.1, z.right) < 1e-11,
        "tabulated {t:?} vs analytic {z:?}"
    );
}

#[test]
fn regimes_full_stick_and_gross_sliding() {
    let c = contact(Profile::hertz(RADIUS).unwrap());
    let stick = solve(
        &c,
        &Cycle::new(point(1000.0, 0.0, 0.0), point(1400.0, 100.0, 5.0)),
    );
    assert_eq!(stick.regime, Regime::FullStick);
    assert!(stick.criteria.full_stick_ratio <= 0.6);
    assert_eq!(stick.slip_zones.unwrap().right.to_array(), [0.0, 0.0]);
    let slide = solve(
        &c,
        &Cycle::new(point(1000.0, -250.0, 0.0), point(1400.0, 900.0, 0.0)),
    );
    assert!(matches!(
        slide.regime,
        Regime::GrossSliding {
            point: steady::GivenPoint::Second
        }
    ));
    assert!(slide.stick_zone.is_none());
    // Constant load: nothing moves, full stick.
    let still = solve(
        &c,
        &Cycle::new(point(1000.0, 100.0, 5.0), point(1000.0, 100.0, 5.0)),
    );
    assert_eq!(still.regime, Regime::FullStick);
}

#[test]
fn full_stick_boundary_meets_the_partial_slip_solution() {
    // With dsigma = 0 and dQ just above f dP, the Hertz stick zone fills the smaller contact:
    // d -> a1 as dQ -> f dP (continuity between the regimes).
    let c = contact(Profile::hertz(RADIUS).unwrap());
    let dq = 0.6 * 400.0 * (1.0 + 1e-9);
    let s = solve(
        &c,
        &Cycle::new(point(1000.0, -dq / 2.0, 0.0), point(1400.0, dq / 2.0, 0.0)),
    );
    assert_eq!(s.regime, Regime::PartialSlip);
    assert!(rel(s.stick_zone.unwrap().half_width(), s.half_width.first) < 1e-8);
}

#[test]
fn cases_outside_the_papers_assumptions_are_named_errors() {
    let c = contact(Profile::hertz(RADIUS).unwrap());
    // Large tension range: slip would reverse at one edge. At the start of half 2 (falling, from
    // a2) the right edge's equivalent-shear range dQ - pi a2 |dsigma|/4 = 500 - 283 is below
    // f |dP| = 240 (half 1, from a1: 500 - 239 > 240 passes).
    let err = steady::analyse(
        &c,
        &Cycle::new(point(1000.0, -250.0, -200.0), point(1400.0, 250.0, 200.0)),
        &SteadyOptions::default(),
    )
    .unwrap_err();
    assert!(
        matches!(
            err,
            Error::SlipReversesInHalf {
                half: Half::Second,
                edge: halfplane::asymptotic::Edge::Right,
                fraction: 0.0,
                ..
            }
        ),
        "{err:?}"
    );
    // Large normal-load range with tension: d = 0.748, e = 0.023, so n = 0.771 > a1 = 0.761.
    let err = steady::analyse(
        &c,
        &Cycle::new(point(1000.0, -100.0, -60.0), point(3000.0, 1140.0, 60.0)),
        &SteadyOptions::default(),
    )
    .unwrap_err();
    assert!(
        matches!(err, Error::StickZoneOutsideContact { .. }),
        "{err:?}"
    );
    // The library names the condition; advice on which command to run is the CLI's.
    assert!(!err.to_string().contains("halfplane"), "{err}");
    assert!(
        err.to_string()
            .contains("-min(a1, a2) < -m < n < min(a1, a2)"),
        "{err}"
    );
}

#[test]
fn hertz_closed_form_module_is_the_papers_formula() {
    // eqs. (28) and (30) by hand for the example.
    let a_comp = 4.0 * (1.0 - 0.09) / 200_000.0;
    let (d, e) = closed_form::hertz_stick_zone(a_comp, RADIUS, 0.6, 2400.0, 500.0, -40.0).unwrap();
    assert!(rel(e, a_comp * RADIUS * 40.0 / 4.8) < 1e-15);
    assert!(rel(d * d, a_comp * RADIUS / PI * (2400.0 - 500.0 / 0.6)) < 1e-15);
}

#[test]
fn steady_options_refuse_values_outside_their_ranges() {
    // Options are valid by construction, like MarchOptions: before, any tolerance (NaN, 0,
    // negative) and 0 iterations could be written into public fields.
    for t in [0.0, -1e-12, 1e-17, 1.0, f64::NAN, f64::INFINITY] {
        match SteadyOptions::default().with_tolerance(t) {
            Err(Error::InvalidInput { field, .. }) => assert_eq!(field, "steady.tolerance"),
            other => panic!("tolerance {t} accepted: {other:?}"),
        }
    }
    for n in [0, SteadyOptions::MAX_ITERATIONS + 1] {
        match SteadyOptions::default().with_max_iterations(n) {
            Err(Error::InvalidCount {
                field, min, max, ..
            }) => assert_eq!(
                (field.as_str(), min, max),
                (
                    "steady.max_iterations",
                    1,
                    SteadyOptions::MAX_ITERATIONS as u64
                )
            ),
            other => panic!("{n} iterations accepted: {other:?}"),
        }
    }
    let options = SteadyOptions::default()
        .with_method(Method::Implicit)
        .with_tolerance(1e-10)
        .and_then(|o| o.with_max_iterations(1))
        .expect("valid");
    assert_eq!(
        (
            options.method(),
            options.tolerance(),
            options.max_iterations()
        ),
        (Method::Implicit, 1e-10, 1)
    );
    // One Newton step from the symmetric start does not reach 1e-10 on a tensioned cycle: the
    // cap is honoured and named.
    let c = contact(Profile::flat_rounded(0.3, RADIUS).unwrap());
    match steady::analyse(&c, &theory_cycle(), &options) {
        Err(Error::NoConvergence { iterations, .. }) => assert_eq!(iterations, 1),
        other => panic!("{other:?}"),
    }
}
