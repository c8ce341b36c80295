//! Validity of the steady-state analysis and of the exact evolution: which cycles `analyse`
//! accepts, checked against the time-marching solver (the independent route).
//!
//! Tolerance for every comparison with marching: one cell. The marched stick boundary is a cell
//! edge, so it can sit up to one cell from the exact boundary however fine the grid (the
//! discretisation error of the boundary itself is below that, see `docs/convergence.md`).

mod common;
use common::*;
use halfplane::history::{History, Ramp};
use halfplane::march::{march, MarchOptions, MarchResult};
use halfplane::steady::{self, SteadyOptions};
use halfplane::{Contact, Cycle, Friction, Material, Profile};

/// Hertz R = 50 with f = 0.3: the reversal cases.
fn hertz_f03() -> Contact {
    Contact::new(
        Profile::hertz(RADIUS).unwrap(),
        Material::new(200_000.0, 0.3).unwrap(),
        Friction::new(0.3).unwrap(),
    )
}

/// P 1000 -> 1400, Q -250 -> 250, sigma -s -> s: passes the old end-point test
/// dQ > pi a_max |dsigma|/4 for s < 353.
fn tension_cycle(s: f64) -> Cycle {
    Cycle::new(point(1000.0, -250.0, -s), point(1400.0, 250.0, s))
}

/// Two in-phase cycles after a normal-first ramp; returns the result and the index of the first
/// step of the second cycle (the steady one).
fn march_cycle(c: &Contact, cycle: &Cycle, cells: usize, steps: usize) -> (MarchResult, usize) {
    let (p1, p2) = cycle.as_given();
    let history = History::in_phase(p1, p2, 2, steps, Ramp::NormalFirst, 10).unwrap();
    let r = march(
        c,
        &history,
        &MarchOptions {
            cells,
            ..Default::default()
        },
        |_, _| {},
    )
    .unwrap();
    let start = history.cycles.unwrap().first_step + 2 * steps;
    (r, start)
}

#[test]
fn stick_zone_clear_of_the_centre_is_accepted_and_agrees_with_marching() {
    // The stick zone need not contain x = 0: the analysis needs -min(a1, a2) < -m < n < min(a1, a2)
    // only. Values from the stick-zone equations (independently confirmed by marching within 0.6
    // cell at 1600 cells); here 1e-5 relative and one cell at 800 cells.
    let c = contact(Profile::flat_rounded(0.5, RADIUS).unwrap());
    let cycle = Cycle::new(point(1000.0, -580.0, -100.0), point(1400.0, 820.0, 100.0));
    let s = steady::analyse(&c, &cycle, &SteadyOptions::default())
        .expect("a stick zone inside the smaller contact must be accepted, centred or not");
    let z = s.stick_zone.unwrap();
    assert!(
        rel(z.left, 0.086111) < 1e-5 && rel(z.right, 0.662988) < 1e-5,
        "stick zone {z:?}"
    );
    assert!(z.left > 0.0, "the case must not contain x = 0 to mean anything");
    let steps = 20;
    let (r, start) = march_cycle(&c, &cycle, 800, steps);
    let w = r.x[1] - r.x[0];
    for end in [start + steps - 1, start + 2 * steps - 1] {
        let [l, rr] = r.steps[end].largest_stick().unwrap();
        assert!(
            (l - z.left).abs() <= w && (rr - z.right).abs() <= w,
            "permanent stick zone: marched [{l:.5}, {rr:.5}] vs steady [{:.5}, {:.5}], cell {w:.5}",
            z.left,
            z.right
        );
    }
}

#[test]
fn slip_that_reverses_inside_a_half_is_rejected() {
    // sigma +-345 passes the end-point test (dQ = 500 > pi a_max |dsigma|/4 = 488), but at the
    // start of the falling half the right edge recedes faster than its stick boundary: it keeps
    // slipping forward and reverses later (marching, below), so the partial-path relation, and
    // the permanent stick zone from it, are not exact.
    let c = hertz_f03();
    let cycle = tension_cycle(345.0);
    let result = steady::analyse(&c, &cycle, &SteadyOptions::default());
    assert!(
        result.is_err(),
        "slip reversal inside the falling half not detected: {result:?}"
    );
}

#[test]
fn just_beyond_the_reversal_boundary_is_rejected() {
    // The exact boundary for this cycle is sigma = +-268.6 (docs/validity.md): +-275 must fail.
    let c = hertz_f03();
    let result = steady::analyse(&c, &tension_cycle(275.0), &SteadyOptions::default());
    assert!(result.is_err(), "sigma +-275 accepted: {result:?}");
}
