//! Exact evolution of the stick zone along the cycle.

mod common;
use common::*;
use halfplane::evolution::{evolve, EvolutionWarning, PointState};
use halfplane::steady::{self, Regime, SteadyOptions};
use halfplane::{Cycle, Error, Half, Profile};
use std::f64::consts::PI;

#[test]
fn hertz_evolution_follows_the_partial_path_closed_form() {
    // docs/theory.md: on the rising half d_X^2 = (A R/pi)(P1 + PX - (QX - Q1)/f), e_X = -A R
    // (sigma1 - sigmaX)/(8f); the falling half mirrors it from point 2. Tier 1: 1e-12.
    let c = contact(Profile::hertz(RADIUS).unwrap());
    let cycle = theory_cycle();
    let ev = evolve(&c, &cycle, 11, &SteadyOptions::default()).unwrap();
    let ar = c.compliance().value() * RADIUS;
    let (lo, hi) = (cycle.low(), cycle.high());
    let mut checked = 0;
    for p in &ev.points {
        if p.state != PointState::PartialSlip {
            continue;
        }
        let x = p.load;
        let (sum, dq, ds) = if p.half == Half::First {
            (
                lo.normal() + x.normal(),
                x.shear() - lo.shear(),
                lo.bulk() - x.bulk(),
            )
        } else {
            (
                x.normal() + hi.normal(),
                hi.shear() - x.shear(),
                x.bulk() - hi.bulk(),
            )
        };
        let d = (ar / PI * (sum - dq / 0.6)).sqrt();
        let e = -ar * ds / (8.0 * 0.6);
        assert!(
            rel(p.stick_zone.right, d + e) < 1e-12 && rel(p.stick_zone.left, e - d) < 1e-12,
            "half {} at {}",
            p.half,
            p.fraction
        );
        checked += 1;
    }
    assert!(checked >= 18, "only {checked} partial-slip points");
}

#[test]
fn evolution_ends_on_the_permanent_stick_zone() {
    // At the end of each half the partial path is the whole cycle: same equations, same zone.
    for profile in [
        Profile::flat_rounded(0.3, RADIUS).unwrap(),
        Profile::power_law(0.01, 2.5).unwrap(),
    ] {
        let c = contact(profile);
        let cycle = theory_cycle();
        let zone = steady::analyse(&c, &cycle, &SteadyOptions::default())
            .unwrap()
            .stick_zone
            .unwrap();
        let ev = evolve(&c, &cycle, 6, &SteadyOptions::default()).unwrap();
        for end in [5, 11] {
            let z = ev.points[end].stick_zone;
            assert!(
                rel(z.left, zone.left) < 1e-12 && rel(z.right, zone.right) < 1e-12,
                "{:?} point {end}",
                c.profile().shape()
            );
        }
        assert_eq!(
            ev.points[0].state,
            PointState::FullStick,
            "the contact sticks at a reversal"
        );
        assert!(ev.warnings.is_empty(), "{:?}", ev.warnings);
    }
}

#[test]
fn stick_zone_shrinks_monotonically_in_each_half_for_the_example() {
    let c = contact(Profile::flat_rounded(0.3, RADIUS).unwrap());
    let ev = evolve(&c, &theory_cycle(), 41, &SteadyOptions::default()).unwrap();
    for w in ev.points.windows(2) {
        if w[0].half == w[1].half && w[0].state == PointState::PartialSlip {
            assert!(
                w[1].stick_zone.right <= w[0].stick_zone.right
                    && w[1].stick_zone.left >= w[0].stick_zone.left
            );
        }
    }
    assert!(!ev
        .warnings
        .iter()
        .any(|w| matches!(w, EvolutionWarning::NonMonotoneSlip { .. })));
}

#[test]
fn points_given_in_either_order_give_the_same_cycle_halves() {
    // Half 1 runs from the first point as given; swapping the points swaps the halves.
    let c = contact(Profile::hertz(RADIUS).unwrap());
    let (p1, p2) = (point(1000.0, -250.0, -20.0), point(1400.0, 250.0, 20.0));
    let a = evolve(&c, &Cycle::new(p1, p2), 5, &SteadyOptions::default()).unwrap();
    let b = evolve(&c, &Cycle::new(p2, p1), 5, &SteadyOptions::default()).unwrap();
    for i in 0..5 {
        assert_eq!(a.points[i].stick_zone, b.points[i + 5].stick_zone);
        assert_eq!(a.points[i + 5].stick_zone, b.points[i].stick_zone);
    }
}

#[test]
fn full_stick_and_gross_sliding_cycles() {
    let c = contact(Profile::hertz(RADIUS).unwrap());
    let stick = evolve(
        &c,
        &Cycle::new(point(1000.0, 0.0, 0.0), point(1400.0, 100.0, 5.0)),
        5,
        &SteadyOptions::default(),
    )
    .unwrap();
    assert_eq!(stick.regime, Regime::FullStick);
    assert!(stick
        .points
        .iter()
        .all(|p| p.state == PointState::FullStick && p.stick_zone.right == p.half_width));
    let err = evolve(
        &c,
        &Cycle::new(point(1000.0, -250.0, 0.0), point(1400.0, 900.0, 0.0)),
        5,
        &SteadyOptions::default(),
    )
    .unwrap_err();
    assert!(matches!(err, Error::GrossSliding { .. }), "{err}");
    let err = evolve(&c, &theory_cycle(), 1, &SteadyOptions::default()).unwrap_err();
    assert!(
        matches!(err, Error::InvalidCount { ref field, value: 1, min: 2, .. } if field == "points"),
        "{err}"
    );
}
