//! Normal contact: contact laws, pressure and K_N against closed forms and equilibrium.

mod common;
use common::*;
use halfplane::closed_form;
use halfplane::{Contact, Friction, Material, Profile};
use std::f64::consts::PI;

#[test]
fn hertz_contact_law_by_general_routes_equals_closed_form() {
    // Tier 1 (1e-12): the power law with k = 2, B = 1/(2R) is the Hertz profile; its half-width
    // comes from the Wallis/Gamma closed form, its load from Gauss-Jacobi-free moments; the
    // tabulated spline route integrates the same parabola exactly.
    let hertz = contact(Profile::hertz(RADIUS).unwrap());
    let power = contact(Profile::power_law(0.5 / RADIUS, 2.0).unwrap());
    let (x, g) = sampled(|x| x * x / (2.0 * RADIUS), 3.0, 30);
    let table = contact(Profile::tabulated(x, g, vec![]).unwrap());
    let a_comp = hertz.compliance().value();
    for p in [10.0, 1000.0, 5000.0] {
        let exact = closed_form::hertz_half_width(a_comp, RADIUS, p);
        for (name, c) in [("power law k=2", &power), ("tabulated parabola", &table)] {
            let a = c.half_width(p).unwrap();
            assert!(rel(a, exact) < 1e-12, "{name}: a({p}) = {a}, Hertz {exact}");
            assert!(rel(c.load(exact).unwrap(), p) < 1e-12, "{name}: P(a) != P");
        }
    }
}

#[test]
fn flat_rounded_contact_law_equals_closed_form() {
    // The piecewise moments and the phi0 formula of docs/theory.md are different expressions.
    let (b, r) = (0.3, RADIUS);
    let c = contact(Profile::flat_rounded(b, r).unwrap());
    let a_comp = c.compliance().value();
    for a in [0.31, 0.5, 1.0, 2.5] {
        let exact = closed_form::flat_rounded_load(a_comp, b, r, a);
        assert!(rel(c.load(a).unwrap(), exact) < 1e-13, "P({a})");
        assert!(rel(c.half_width(exact).unwrap(), a) < 1e-13, "a(P({a}))");
    }
}

#[test]
fn power_law_contact_law_equals_direct_integration() {
    // Closed form (Gamma functions) against P = (1/A) integral x g'(x)/sqrt(a^2-x^2) dx summed in
    // the test with x = a sin(phi); the integrand ~ phi^k at 0, so 2000 panels give ~1e-13.
    for k in [1.0, 1.5, 2.5, 3.0, 4.7] {
        let coefficient = 0.02;
        let c = contact(Profile::power_law(coefficient, k).unwrap());
        let a_comp = c.compliance().value();
        let a = 0.8;
        let direct = 2.0 / a_comp
            * integrate(0.0, PI / 2.0, 2000, |phi| {
                let x = a * phi.sin();
                a * phi.sin() * coefficient * k * x.powf(k - 1.0)
            });
        assert!(
            rel(c.load(a).unwrap(), direct) < 1e-11,
            "k = {k}: {} vs {direct}",
            c.load(a).unwrap()
        );
    }
}

#[test]
fn general_pressure_route_equals_hertz_pressure() {
    // The power law k = 2 takes the general principal-value route; tier 1 agreement (1e-10).
    let power = contact(Profile::power_law(0.5 / RADIUS, 2.0).unwrap());
    let a_comp = power.compliance().value();
    let a = 0.8;
    for x in [-0.79, -0.5, 0.0, 0.1, 0.6, 0.799] {
        let exact = closed_form::hertz_pressure(a_comp, RADIUS, a, x);
        let p = power.pressure(a, x).unwrap();
        assert!(
            (p - exact).abs() < 1e-10 * exact.max(1.0),
            "p({x}) = {p}, Hertz {exact}"
        );
    }
}

#[test]
fn pressure_integrates_to_the_load() {
    // Equilibrium, integral p dx = P(a), with x = a sin(phi) to remove the edge square root. The
    // pressure has (x - b) ln|x - b| terms at +-b, so the test splits there and grades its panels
    // towards the breaks; what remains is the pressure's own error (tier 2: 1e-10).
    for profile in [
        Profile::flat_rounded(0.3, RADIUS).unwrap(),
        flat_rounded_table(0.3, RADIUS),
    ] {
        let c = contact(profile);
        let a: f64 = 0.9;
        let kink = (0.3_f64 / a).asin();
        let cuts = [-PI / 2.0, -kink, kink, PI / 2.0];
        let total: f64 = cuts
            .windows(2)
            .map(|w| {
                integrate_graded(w[0], w[1], |phi| {
                    c.pressure(a, a * phi.sin()).unwrap() * a * phi.cos()
                })
            })
            .sum();
        let load = c.load(a).unwrap();
        assert!(
            rel(total, load) < 1e-10,
            "{:?}: integral p = {total}, P = {load}",
            c.profile().shape()
        );
    }
}

#[test]
fn normal_intensity_is_the_edge_limit_of_the_pressure() {
    // p(a - s) = K_N sqrt(s) (1 + O(s/a)); at s = 1e-6 a the O term is ~1e-6.
    for profile in [
        Profile::hertz(RADIUS).unwrap(),
        Profile::flat_rounded(0.3, RADIUS).unwrap(),
    ] {
        let c = contact(profile);
        let a = 0.9;
        let s = 1e-6 * a;
        let k_n = c.normal_intensity(a).unwrap();
        let p = c.pressure(a, a - s).unwrap();
        assert!(
            rel(p / s.sqrt(), k_n) < 1e-5,
            "{:?}: p/sqrt(s) = {}, K_N = {k_n}",
            c.profile().shape(),
            p / s.sqrt()
        );
    }
}

#[test]
fn contact_beyond_a_table_is_an_error_not_an_extrapolation() {
    let (x, g) = sampled(|x| x * x / 100.0, 0.5, 10);
    let c = contact(Profile::tabulated(x, g, vec![]).unwrap());
    let err = c.half_width(5000.0).unwrap_err();
    assert!(matches!(err, halfplane::Error::BeyondTable { .. }), "{err}");
    assert!(err.to_string().contains("extend the table"), "{err}");
}

/// Fuzz findings (lib_steady): extreme but valid inputs gave `Ok` half-widths of 0 or infinity
/// and loads of NaN or below zero; each now is a typed error.
#[test]
fn scales_that_overflow_or_underflow_are_errors_not_values() {
    let material = Material::new(200_000.0, 0.3).unwrap();
    let friction = Friction::new(0.6).unwrap();
    let hertz = |r: f64| Contact::new(Profile::hertz(r).unwrap(), material, friction);
    // Radii outside 1e-30..1e30 are rejected where they are made ...
    assert!(Profile::hertz(1e-300).is_err() && Profile::hertz(1e300).is_err());
    // ... and a half-width passed in directly can still make P(a) and dP/da overflow.
    assert!(hertz(1e-30).load(1e300).is_err());
    assert!(hertz(1e-30).normal_intensity(1e300).is_err());
    assert!(hertz(1e-30).half_width(1e-300).is_err());
    // A flat 1e13 times wider than a - b: the moment cancels to a negative load.
    let flat = Contact::new(
        Profile::flat_rounded(6686747539482.72, 0.4999999999999999).unwrap(),
        material,
        friction,
    );
    match flat.load(6686747539482.721) {
        Ok(p) => assert!(p.is_finite() && p >= 0.0, "P = {p}"),
        Err(e) => assert!(matches!(e, halfplane::Error::InvalidInput { .. })),
    }
    // Ordinary scales are unaffected.
    let a = hertz(50.0).half_width(1000.0).unwrap();
    assert!((hertz(50.0).load(a).unwrap() - 1000.0).abs() < 1e-9);
}
