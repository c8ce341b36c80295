//! Tests of the solver's internals (the stick-zone solve of a load segment, the two validity
//! checks) that the public API cannot reach: moved here from the integration tests when these
//! became private to the crate. Helpers as in `tests/common`.

use super::{analyse, stick_zone, validity, Method, Regime, Segment, SteadyOptions};
use crate::labels::{Edge, Half, PerEdge};
use crate::{reference, Contact, Cycle, Error, Friction, LoadPoint, Material, Profile, Shape};
use std::f64::consts::PI;

const RADIUS: f64 = reference::RADIUS;

fn contact(profile: Profile) -> Contact {
    reference::contact(profile)
}

fn point(normal: f64, shear: f64, bulk: f64) -> LoadPoint {
    LoadPoint::new("test", normal, shear, bulk).unwrap()
}

fn rel(a: f64, b: f64) -> f64 {
    (a - b).abs() / b.abs()
}

/// A profile's shape for messages, a table by its length.
fn label(profile: &Profile) -> String {
    match profile.shape() {
        Shape::Tabulated { x, .. } => format!("table of {} rows", x.len()),
        other => format!("{other:?}"),
    }
}

#[test]
fn a_segment_that_would_slide_has_no_stick_zone() {
    // dQ >= f (P1 + P2): no stick zone exists; the public solver says so by name.
    let segment = Segment {
        normal_sum: 2000.0,
        shear_range: 1300.0,
        bulk_range: 0.0,
        rotation: 0.0,
    };
    for method in [Method::Auto, Method::Implicit] {
        let options = SteadyOptions::default().with_method(method);
        for profile in [
            Profile::hertz(RADIUS).unwrap(),
            Profile::flat_rounded(0.3, RADIUS).unwrap(),
        ] {
            let err = stick_zone(&contact(profile), &segment, None, &options).unwrap_err();
            assert_eq!(
                err,
                Error::NoStickZone {
                    shear_range: 1300.0,
                    limit: 0.6 * 2000.0
                },
                "{err}"
            );
        }
    }
}

#[test]
fn start_of_half_speeds_hold_for_any_profile() {
    // The start-of-half test uses n'(0) = (f dP - dS_right)/(2 f dP/da), which rests on the
    // identity A dP/da = a integral_0^pi g''(a cos t) dt (docs/validity.md). Check it against a
    // finite difference of the stick-zone equations themselves on non-Hertz profiles: the partial
    // path at t = 1e-6 must move the boundary by t n'(0) to 1e-4 relative (the second-order term).
    for profile in [
        Profile::flat_rounded(0.3, RADIUS).unwrap(),
        Profile::power_law(0.01, 2.5).unwrap(),
    ] {
        let c = contact(profile);
        // The falling half of a cycle with a large tension range fails at its right edge.
        let (p2, p1) = (point(1400.0, 250.0, 200.0), point(1000.0, -250.0, -200.0));
        let err = validity::check_slip_grows(&c, &Cycle::new(p2, p1), &SteadyOptions::default())
            .unwrap_err();
        let Error::SlipReversesInHalf {
            half: Half::First,
            edge: Edge::Right,
            fraction: 0.0,
            boundary_rate,
            ..
        } = err
        else {
            panic!("{:?}: {err:?}", c.profile.shape());
        };
        let t = 1e-6;
        let segment = Segment {
            normal_sum: 2.0 * 1400.0 - t * 400.0,
            shear_range: t * 500.0,
            bulk_range: t * (-400.0),
            rotation: 0.0,
        };
        let a2 = c.half_width(1400.0).unwrap();
        let (zone, _) = stick_zone(&c, &segment, None, &SteadyOptions::default()).unwrap();
        let difference = (zone.right - a2) / t;
        assert!(
            rel(difference, boundary_rate) < 1e-4,
            "{:?}: dn/dt {boundary_rate} vs finite difference {difference}",
            c.profile.shape()
        );
    }
}

#[test]
fn for_convex_profiles_the_start_of_half_test_decides() {
    // `check_slip_grows` stops after the start-of-half test for convex profiles: docs/validity.md
    // proves that a cycle passing it keeps both stick boundaries moving inwards and inside the
    // receding contact all along both halves. The independent check: on a grid of cycles around
    // the reversal boundary (friction, P rising and falling with Q, tension ranges from 0 to past
    // the boundary), every cycle `analyse` accepts as partial slip also passes the partial path
    // solved at 64 points per half, for each kind of convex profile. The scan's own margin is
    // -1e-9 a_s (rounding of the Newton solves); a failure of the theorem would show as a
    // boundary speed of the wrong sign, far outside it.
    let profiles = [
        Profile::hertz(RADIUS).unwrap(),
        Profile::flat_rounded(0.3, RADIUS).unwrap(),
        Profile::flat_rounded(0.6, 20.0).unwrap(),
        Profile::power_law(0.05, 1.1).unwrap(),
        Profile::power_law(0.02, 1.5).unwrap(),
        Profile::power_law(0.01, 2.5).unwrap(),
        Profile::power_law(0.02, 4.0).unwrap(),
        reference::flat_rounded_table(41).unwrap(),
    ];
    let options = SteadyOptions::default();
    for profile in profiles {
        assert!(profile.is_convex(), "{:?}", profile.shape());
        let shape = label(&profile);
        let (mut sampled, mut rejected) = (0, 0);
        for f in [0.3, 0.5, 0.8] {
            let c = Contact::new(
                profile.clone(),
                Material::new(200_000.0, 0.3).unwrap(),
                Friction::new(f).unwrap(),
            );
            for p2 in [600.0, 1400.0, 2500.0] {
                for q in [100.0, 200.0, 350.0] {
                    for s in (0..=16).map(|k| 25.0 * k as f64) {
                        let cycle = Cycle::new(point(1000.0, -q, -s), point(p2, q, s));
                        match analyse(&c, &cycle, &options) {
                            Ok(state) if state.regime == Regime::PartialSlip => {
                                validity::sample_slip_growth(&c, &cycle, 64, &options)
                                    .unwrap_or_else(|e| {
                                        panic!("{shape}, f {f}, P2 {p2}, Q ±{q}, sigma ±{s}: accepted, but sampling finds {e}")
                                    });
                                sampled += 1;
                            }
                            Err(Error::SlipReversesInHalf { .. }) => rejected += 1,
                            _ => {}
                        }
                    }
                }
            }
        }
        assert!(
            sampled >= 50 && rejected >= 8,
            "{shape}: the grid must straddle the boundary: {sampled} sampled, {rejected} rejected"
        );
    }
}

#[test]
fn sampling_finds_the_reversal_the_start_of_half_test_reports() {
    // The two routes agree on rejected cycles too: where the start-of-half test fails at an edge,
    // the sampled partial path finds the same half and edge within the first sample interval.
    let c = contact(Profile::flat_rounded(0.3, RADIUS).unwrap());
    let cycle = Cycle::new(point(1400.0, 250.0, 200.0), point(1000.0, -250.0, -200.0));
    let options = SteadyOptions::default();
    let Err(Error::SlipReversesInHalf { half, edge, .. }) =
        validity::check_slip_grows(&c, &cycle, &options)
    else {
        panic!("the start-of-half test must fail");
    };
    let Err(Error::SlipReversesInHalf {
        half: sampled_half,
        edge: sampled_edge,
        fraction,
        ..
    }) = validity::sample_slip_growth(&c, &cycle, 32, &options)
    else {
        panic!("sampling must fail too");
    };
    assert_eq!((half, edge), (sampled_half, sampled_edge));
    assert!(fraction <= 1.0 / 32.0 + 1e-9, "found at t = {fraction}");
    assert!(matches!(
        validity::sample_slip_growth(&c, &cycle, 0, &options),
        Err(Error::InvalidCount { .. })
    ));
}

#[test]
#[ignore = "random cycles, 256 samples per half: cargo test --release -p halfplane --lib -- --ignored random_cycles"]
fn on_random_cycles_sampling_never_contradicts_the_start_of_half_test() {
    // The long form of `for_convex_profiles_the_start_of_half_test_decides`: 20,000 random
    // cycles per profile (friction 0.2-1, P from 300 to 2500 at each end, shear and tension of
    // any mean and range), each accepted partial-slip cycle sampled at 256 points per half.
    let profiles = [
        Profile::flat_rounded(0.3, RADIUS).unwrap(),
        Profile::flat_rounded(1.0, 10.0).unwrap(),
        Profile::power_law(0.05, 1.05).unwrap(),
        Profile::power_law(0.02, 1.5).unwrap(),
        Profile::power_law(0.01, 2.5).unwrap(),
        Profile::power_law(0.05, 6.0).unwrap(),
        reference::flat_rounded_table(41).unwrap(),
    ];
    let mut state = 0x9e37_79b9_7f4a_7c15_u64;
    let mut uniform = |lo: f64, hi: f64| {
        state = state
            .wrapping_mul(6_364_136_223_846_793_005)
            .wrapping_add(1);
        lo + (hi - lo) * ((state >> 11) as f64 / (1u64 << 53) as f64)
    };
    let options = SteadyOptions::default();
    for profile in profiles {
        let (mut sampled, mut rejected, mut outside) = (0, 0, 0);
        for _ in 0..20_000 {
            let f = uniform(0.2, 1.0);
            let c = Contact::new(
                profile.clone(),
                Material::new(200_000.0, 0.3).unwrap(),
                Friction::new(f).unwrap(),
            );
            let (q_mean, q_amp) = (uniform(-200.0, 200.0), uniform(0.0, 600.0));
            let (s_mean, s_amp) = (uniform(-200.0, 200.0), uniform(0.0, 300.0));
            let cycle = Cycle::new(
                point(uniform(300.0, 2500.0), q_mean - q_amp, s_mean - s_amp),
                point(uniform(300.0, 2500.0), q_mean + q_amp, s_mean + s_amp),
            );
            match analyse(&c, &cycle, &options) {
                Ok(state) if state.regime == Regime::PartialSlip => {
                    if let Err(e) = validity::sample_slip_growth(&c, &cycle, 256, &options) {
                        panic!("{}, f {f}, {cycle:?}: {e}", label(&profile));
                    }
                    sampled += 1;
                }
                Err(Error::SlipReversesInHalf { .. }) => rejected += 1,
                // The corollary in docs/validity.md: a zone outside the smaller contact fails
                // the start-of-half test too.
                Err(Error::StickZoneOutsideContact { .. }) => {
                    assert!(
                        validity::check_slip_grows(&c, &cycle, &options).is_err(),
                        "{}, f {f}, {cycle:?}: zone outside the contact, start of half passed",
                        label(&profile)
                    );
                    outside += 1;
                }
                _ => {}
            }
        }
        let shape = label(&profile);
        eprintln!(
            "{shape}: {sampled} accepted and sampled, {rejected} rejected at the start of a half, \
             {outside} with the zone outside the smaller contact (all also failing it)"
        );
        assert!(
            sampled > 1000 && rejected > 100,
            "{shape}: {sampled}, {rejected}"
        );
    }
}

#[test]
fn under_a_moment_every_accepted_cycle_passes_the_sampled_partial_path() {
    // Under a moment `check_slip_grows` accepts a cycle on a convex profile when the bounds on
    // the rotation's rate settle it (docs/validity.md, "Under a moment"), and samples both halves
    // otherwise. The independent check, as for the symmetric theorem above: on a grid of cycles
    // with moments changing along the cycle (centroids from -0.2 to 0.2 mm, contacts of 0.6 to
    // 1.3 mm) and tension around the reversal boundary, every cycle `analyse` accepts as partial
    // slip passes the partial path solved at 64 points per half. Hertz, symmetric and asymmetric
    // flat-rounded punches and a power law; the grid must reach both verdicts for each.
    let profiles = [
        Profile::hertz(RADIUS).unwrap(),
        Profile::flat_rounded(0.3, RADIUS).unwrap(),
        Profile::flat_rounded_asymmetric(0.3, 25.0, 70.0).unwrap(),
        Profile::power_law(0.02, 2.5).unwrap(),
    ];
    let options = SteadyOptions::default();
    for profile in profiles {
        let shape = label(&profile);
        let (mut sampled, mut rejected) = (0, 0);
        for f in [0.4, 0.8] {
            let c = Contact::new(
                profile.clone(),
                Material::new(200_000.0, 0.3).unwrap(),
                Friction::new(f).unwrap(),
            );
            for p2 in [700.0, 1400.0] {
                for (e1, e2) in [(0.0, 0.1), (0.1, -0.1), (-0.2, 0.05), (0.15, 0.2)] {
                    for s in (0..=6).map(|k| 40.0 * k as f64) {
                        let first = point(1000.0, -200.0, -s)
                            .with_moment("p", e1 * 1000.0)
                            .unwrap();
                        let second = point(p2, 200.0, s).with_moment("p", e2 * p2).unwrap();
                        let cycle = Cycle::new(first, second);
                        match analyse(&c, &cycle, &options) {
                            Ok(state) if state.regime == Regime::PartialSlip => {
                                validity::sample_slip_growth(&c, &cycle, 64, &options)
                                    .unwrap_or_else(|e| {
                                        panic!("{shape}, f {f}, P2 {p2}, centroids {e1}, {e2}, sigma ±{s}: accepted, but sampling finds {e}")
                                    });
                                sampled += 1;
                            }
                            Err(Error::SlipReversesInHalf { .. })
                            | Err(Error::StickZoneOutsideContact { .. }) => rejected += 1,
                            _ => {}
                        }
                    }
                }
            }
        }
        assert!(
            sampled >= 10 && rejected >= 5,
            "{shape}: the grid must straddle the boundary: {sampled} sampled, {rejected} rejected"
        );
    }
}

#[test]
fn start_of_half_speeds_under_a_moment_are_the_edge_coefficients() {
    // At the start of a half the right stick boundary moves at (f dP_right - dS_right)/(f K_N
    // pi sqrt(2a)) (docs/validity.md, "Under a moment"): checked against a finite difference of
    // the solved partial-path zone, a step t = 1e-6 into the rising half of an asymmetric punch
    // under a changing moment. The zone at t is the stick-zone equations for the segment from
    // point 1 with the mean rotation of point 1's and the current contact; first order in t, so
    // 1e-4 relative (the second-order term over the rate, about t/t_curvature).
    let c = contact(Profile::flat_rounded_asymmetric(0.3, 25.0, 70.0).unwrap());
    let (p1, p2) = (
        point(1000.0, -250.0, -20.0).with_moment("p", 50.0).unwrap(),
        point(1400.0, 250.0, 20.0).with_moment("p", 160.0).unwrap(),
    );
    let start = c.contact_at(&p1).unwrap();
    let t = 1e-6;
    let x = p1.lerp(&p2, t);
    let now = c.contact_at(&x).unwrap();
    let segment = Segment::between(&p1, &x, 0.5 * (start.rotation() + now.rotation()));
    let (zone, _) = stick_zone(&c, &segment, None, &SteadyOptions::default()).unwrap();
    let finite = PerEdge {
        left: (start.end(Edge::Left) - zone.left) / t,
        right: (zone.right - start.end(Edge::Right)) / t,
    };
    let (d_p, d_m) = (400.0, 110.0);
    let d_edge = start.edge_load_changes(d_p, d_m);
    let a = start.half_width();
    // dS over the rising half: dQ -/+ pi a dsigma/4 with the paper's dsigma = sigma1 - sigma2.
    let d_s = PerEdge {
        left: 500.0 - PI * a * (-40.0) / 4.0,
        right: 500.0 + PI * a * (-40.0) / 4.0,
    };
    for edge in Edge::BOTH {
        let f = 0.6;
        let speed = (f * d_edge[edge] - d_s[edge])
            / (f * start.normal_intensity(edge) * PI * (2.0 * a).sqrt());
        assert!(
            (finite[edge] - speed).abs() <= 1e-4 * speed.abs(),
            "{edge:?}: finite difference {} against {speed}",
            finite[edge]
        );
    }
}
