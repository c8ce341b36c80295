//! Prototype-to-test matching against its defining equalities, each recomputed here from the test
//! loads alone (contact law, eq. (31), eq. (32), `steady::analyse`), not read from the report.
//!
//! Tolerances: the matcher solves K_N to 1e-15 relative in the half-width and the rest in closed
//! form, so the asymptotic equalities hold to rounding through P(a) and a(P) (about 1e-14); 1e-10
//! leaves room for the flat-rounded contact law's Newton. The exact mode adds the stick-zone
//! integrals and `steady::analyse`'s Newton (1e-14), hence 1e-8 as the issue asks.

mod common;
use common::*;
use halfplane::asymptotic::{shear_intensity, Edge};
use halfplane::history::{History, Ramp};
use halfplane::matching::{
    map_history, map_point, match_cycle, LoadIndex, MatchConstraint, MatchSide, Mode,
};
use halfplane::steady::{self, SteadyOptions};
use halfplane::{reference, Contact, Cycle, Error, GivenPoint, LoadPoint, PerPoint, Profile};

/// Flat-rounded and power-law prototypes, each with a Hertz test that has a valid match in both
/// modes (R chosen so that the test neither slides nor sticks fully).
fn pairs() -> Vec<(&'static str, Contact, Contact)> {
    vec![
        (
            "flat-rounded b = 0.3, R = 50 -> Hertz R = 50",
            reference::flat_rounded(),
            reference::hertz(),
        ),
        (
            "power law k = 2.5 -> Hertz R = 100",
            contact(Profile::power_law(2e-3, 2.5).unwrap()),
            contact(Profile::hertz(100.0).unwrap()),
        ),
        (
            "power law k = 3 -> Hertz R = 100",
            contact(Profile::power_law(1e-3, 3.0).unwrap()),
            contact(Profile::hertz(100.0).unwrap()),
        ),
        (
            "Hertz R = 50 -> flat-rounded b = 0.3, R = 50",
            reference::hertz(),
            reference::flat_rounded(),
        ),
    ]
}

/// K_N (eq. (31)) and K_T at both edges (eq. (32)) of a load, from its P alone.
fn intensities(c: &Contact, p: &LoadPoint) -> (f64, [f64; 2]) {
    let a = c.half_width(p.normal()).unwrap();
    let kt = Edge::BOTH.map(|e| shear_intensity(p.shear(), p.bulk(), a, e));
    (c.normal_intensity(a).unwrap(), kt)
}

fn given(c: &Cycle) -> PerPoint<LoadPoint> {
    let (first, second) = c.as_given();
    PerPoint { first, second }
}

fn assert_loads_equal(a: &Cycle, b: &Cycle, tol: f64, what: &str) {
    assert_eq!(a.swapped(), b.swapped(), "{what}: point order");
    for p in GivenPoint::BOTH {
        let (x, y) = (given(a)[p], given(b)[p]);
        for (name, u, v) in [
            ("P", x.normal(), y.normal()),
            ("Q", x.shear(), y.shear()),
            ("sigma", x.bulk(), y.bulk()),
        ] {
            let close = (u - v).abs() <= tol * u.abs().max(v.abs());
            assert!(close, "{what}: {name} at the {p} point {u} != {v}");
        }
    }
}

#[test]
fn a_hertz_prototype_matched_onto_its_own_geometry_returns_its_own_loads() {
    let c = reference::hertz();
    let (p1, p2) = (reference::point1(), reference::point2());
    for cycle in [Cycle::new(p1, p2), Cycle::new(p2, p1)] {
        for mode in [Mode::Asymptotic, Mode::Exact] {
            let r = match_cycle(&c, &cycle, &c, mode).unwrap();
            assert_loads_equal(
                &r.test.cycle,
                &cycle,
                1e-10,
                &format!("{mode}, swapped {}", cycle.swapped()),
            );
            assert!(
                r.warnings.is_empty(),
                "identity match warned: {:?}",
                r.warnings
            );
        }
    }
}

#[test]
fn asymptotic_match_equalises_k_n_and_k_t_at_both_edges_at_both_points() {
    let cycle = reference::cycle();
    for (what, proto, test) in pairs() {
        let r = match_cycle(&proto, &cycle, &test, Mode::Asymptotic).unwrap();
        let mut worst: f64 = 0.0;
        for p in GivenPoint::BOTH {
            let (kn, kt) = intensities(&proto, &given(&cycle)[p]);
            let (kn_t, kt_t) = intensities(&test, &given(&r.test.cycle)[p]);
            worst = worst.max(rel(kn_t, kn));
            assert!(
                rel(kn_t, kn) <= 1e-10,
                "{what}: K_N at the {p} point {kn_t} != {kn}"
            );
            for (e, (x, y)) in kt_t.iter().zip(kt).enumerate() {
                worst = worst.max(rel(*x, y));
                assert!(
                    rel(*x, y) <= 1e-10,
                    "{what}: K_T at edge {e}, {p} point {x} != {y}"
                );
            }
        }
        eprintln!("{what}: largest relative K mismatch {worst:.1e}");
    }
}

#[test]
fn exact_match_equalises_k_n_slip_zones_at_point2_and_mean_k_t() {
    let cycle = reference::cycle();
    let options = SteadyOptions::default();
    for (what, proto, test) in pairs() {
        let r = match_cycle(&proto, &cycle, &test, Mode::Exact).unwrap();
        let exact_proto = steady::analyse(&proto, &cycle, &options).unwrap();
        let exact_test = steady::analyse(&test, &r.test.cycle, &options).unwrap();
        let (ws, wt) = (
            exact_proto.slip_zones.unwrap(),
            exact_test.slip_zones.unwrap(),
        );
        let mut worst: f64 = 0.0;
        for e in Edge::BOTH {
            let (x, y) = (wt[e].second, ws[e].second);
            worst = worst.max(rel(x, y));
            assert!(
                rel(x, y) <= 1e-8,
                "{what}: slip zone at the {e} edge at point2 {x} != {y}"
            );
        }
        let mut mean = [[0.0; 2]; 2];
        for p in GivenPoint::BOTH {
            let (kn, kt) = intensities(&proto, &given(&cycle)[p]);
            let (kn_t, kt_t) = intensities(&test, &given(&r.test.cycle)[p]);
            worst = worst.max(rel(kn_t, kn));
            assert!(
                rel(kn_t, kn) <= 1e-8,
                "{what}: K_N at the {p} point {kn_t} != {kn}"
            );
            for e in 0..2 {
                mean[0][e] += 0.5 * kt[e];
                mean[1][e] += 0.5 * kt_t[e];
            }
        }
        for (e, (t, p)) in mean[1].iter().zip(mean[0]).enumerate() {
            worst = worst.max(rel(*t, p));
            assert!(rel(*t, p) <= 1e-8, "{what}: mean K_T at edge {e}");
        }
        eprintln!("{what}: largest relative mismatch of the exact equalities {worst:.1e}");
        // The report says the same.
        for e in Edge::BOTH {
            assert!(r.slip_zones[e].second.mismatch.unwrap().abs() <= 1e-8);
        }
    }
}

#[test]
fn the_inverse_is_the_same_match_with_the_roles_swapped() {
    let cycle = reference::cycle();
    for (what, proto, test) in pairs() {
        for (mode, tol) in [(Mode::Asymptotic, 1e-10), (Mode::Exact, 1e-8)] {
            let forward = match_cycle(&proto, &cycle, &test, mode).unwrap();
            let back = match_cycle(&test, &forward.test.cycle, &proto, mode).unwrap();
            assert_loads_equal(
                &back.test.cycle,
                &cycle,
                tol,
                &format!("{what}, {mode}, back"),
            );
        }
    }
}

#[test]
fn a_history_maps_row_by_row_with_each_row_matched() {
    let (proto, test) = (reference::flat_rounded(), reference::hertz());
    let history = History::in_phase(
        reference::point1(),
        reference::point2(),
        1,
        10,
        Ramp::NormalFirst,
        5,
    )
    .unwrap();
    let rows = map_history(&proto, &test, history.loads()).unwrap();
    assert_eq!(rows.len(), history.loads().len());
    for (i, (p, t)) in history.loads().iter().zip(&rows).enumerate() {
        let ((kn, kt), (kn_t, kt_t)) = (intensities(&proto, p), intensities(&test, t));
        assert!(rel(kn_t, kn) <= 1e-10, "row {}: K_N", i + 1);
        for e in 0..2 {
            assert!(
                (kt_t[e] - kt[e]).abs() <= 1e-10 * kt[0].abs().max(kt[1].abs()).max(1e-300),
                "row {}: K_T",
                i + 1
            );
        }
        let (alone, _) = map_point(&proto, &test, p, LoadIndex::Row(i + 1), None).unwrap();
        assert!(
            rel(alone.normal(), t.normal()) <= 1e-13,
            "row {}: warm start changed P",
            i + 1
        );
    }
    // The cycle's points map as the asymptotic match maps them (two ramp legs of 5 rows reach
    // point 1).
    let r = match_cycle(&proto, &reference::cycle(), &test, Mode::Asymptotic).unwrap();
    assert_eq!(history.loads()[9], reference::point1());
    let end_of_ramp = rows[9];
    assert!(rel(end_of_ramp.normal(), given(&r.test.cycle).first.normal()) <= 1e-13);
    assert!(rel(end_of_ramp.shear(), given(&r.test.cycle).first.shear()) <= 1e-13);
}

fn constraint_of(e: &Error) -> (MatchSide, MatchConstraint) {
    match e {
        Error::NoValidMatch {
            side, constraint, ..
        } => (*side, *constraint),
        other => panic!("expected NoValidMatch, got {other:?}"),
    }
}

#[test]
fn impossible_matches_are_errors_naming_the_side_and_the_constraint() {
    let cycle = reference::cycle();
    let point = |p, q, s| LoadPoint::new("point", p, q, s).unwrap();
    let hertz = reference::hertz();
    // The test slides: a narrow flat punch needs a tiny P for the prototype's K_N.
    let narrow = contact(Profile::flat_rounded(0.5, 20.0).unwrap());
    let e = match_cycle(
        &reference::flat_rounded(),
        &cycle,
        &narrow,
        Mode::Asymptotic,
    )
    .unwrap_err();
    assert_eq!(
        constraint_of(&e),
        (MatchSide::Test, MatchConstraint::GrossSliding)
    );
    assert!(
        e.to_string()
            .contains("test's cycle fails the gross-sliding constraint"),
        "{e}"
    );
    // The prototype's slip zones do not fit into the test's contact (R = 100: a' = 2.5).
    let wide = contact(Profile::hertz(100.0).unwrap());
    let e = match_cycle(&reference::flat_rounded(), &cycle, &wide, Mode::Exact).unwrap_err();
    assert_eq!(
        constraint_of(&e),
        (MatchSide::Test, MatchConstraint::StickZoneOutsideContact)
    );
    // Slip reverses in the prototype (docs/validity.md: f = 0.3, sigma +/-345).
    let low_friction = Contact::new(
        hertz.profile().clone(),
        hertz.material(),
        halfplane::Friction::new(0.3).unwrap(),
    );
    let reversing = Cycle::new(point(1000.0, -250.0, -345.0), point(1400.0, 250.0, 345.0));
    let e = match_cycle(&low_friction, &reversing, &hertz, Mode::Asymptotic).unwrap_err();
    assert_eq!(
        constraint_of(&e),
        (MatchSide::Prototype, MatchConstraint::SlipReversal)
    );
    // A sliding prototype; a fully sticking one in exact mode (no slip zones to match).
    let sliding = Cycle::new(point(1000.0, -700.0, 0.0), point(1400.0, 250.0, 0.0));
    let e = match_cycle(&hertz, &sliding, &hertz, Mode::Asymptotic).unwrap_err();
    assert_eq!(
        constraint_of(&e),
        (MatchSide::Prototype, MatchConstraint::GrossSliding)
    );
    let sticking = Cycle::new(point(1000.0, -50.0, 0.0), point(1400.0, 50.0, 0.0));
    let e = match_cycle(&hertz, &sticking, &hertz, Mode::Exact).unwrap_err();
    assert_eq!(
        constraint_of(&e),
        (MatchSide::Prototype, MatchConstraint::FullStick)
    );
    // ... which the asymptotic mode matches (onto itself: the same loads).
    let r = match_cycle(&hertz, &sticking, &hertz, Mode::Asymptotic).unwrap();
    assert_loads_equal(&r.test.cycle, &sticking, 1e-10, "full stick onto itself");
    // A power law with k = 3/2 has the same K_N at every load: nothing to bracket.
    let flat_kn = contact(Profile::power_law(1e-2, 1.5).unwrap());
    match match_cycle(&hertz, &cycle, &flat_kn, Mode::Asymptotic).unwrap_err() {
        Error::MatchNotBracketed {
            load,
            target,
            searched,
        } => {
            assert_eq!(load, LoadIndex::Point(GivenPoint::First));
            assert!(
                target > 0.0 && searched[0] < 1e-20 && searched[1] > 1e20,
                "{searched:?}"
            );
        }
        other => panic!("expected MatchNotBracketed, got {other:?}"),
    }
}

#[test]
fn a_test_whose_contact_moves_much_more_is_flagged() {
    // Hertz R = 100 needs 8x the load for the same K_N: the test's edge moves 4x as far and its
    // exact steady state is full stick (eq. (1)), while the K's match exactly.
    let wide = contact(Profile::hertz(100.0).unwrap());
    let r = match_cycle(
        &reference::hertz(),
        &reference::cycle(),
        &wide,
        Mode::Asymptotic,
    )
    .unwrap();
    let kinds: Vec<String> = r.warnings.iter().map(|w| format!("{w:?}")).collect();
    assert!(
        kinds.iter().any(|k| k.starts_with("EdgeMotion")),
        "{kinds:?}"
    );
    assert!(kinds.iter().any(|k| k.starts_with("Regime")), "{kinds:?}");
    assert!(rel(r.edge_motion.test, 4.0 * r.edge_motion.prototype) <= 1e-12);
}
