//! Marching until the cycle repeats (`history.cycles = "steady"`), on a case whose ramp leaves
//! cells at the friction limit inside the permanent stick zone that then shake down
//! geometrically over several cycles (issue 17, item 3).

use halfplane::history::{History, Ramp, Steady};
use halfplane::march::{march, march_steady, MarchOptions, MarchResult};
use halfplane::steady::{self, SteadyOptions, StickZone};
use halfplane::{Contact, Cycle, Error, Friction, LoadPoint, Material, Profile};

const STEPS_PER_HALF: usize = 20;

fn shakedown_case() -> (Contact, Cycle) {
    let contact = Contact::new(
        Profile::hertz(27.83).unwrap(),
        Material::new(197783.0, 0.163).unwrap(),
        Friction::new(1.048).unwrap(),
    );
    let cycle = Cycle::new(
        LoadPoint::new("point1", 1972.57, 1157.01, -17.21).unwrap(),
        LoadPoint::new("point2", 1302.01, 426.22, 10.44).unwrap(),
    );
    (contact, cycle)
}

fn history(cycle: &Cycle, cycles: usize) -> History {
    let (p1, p2) = cycle.as_given();
    History::in_phase(p1, p2, cycles, STEPS_PER_HALF, Ramp::NormalFirst, 19).unwrap()
}

fn options() -> MarchOptions {
    MarchOptions::default().with_cells(400).unwrap()
}

fn steady_zone(contact: &Contact, cycle: &Cycle) -> StickZone {
    steady::analyse(contact, cycle, &SteadyOptions::default())
        .unwrap()
        .stick_zone
        .unwrap()
}

/// The largest stick interval at the last increment (point 1) as a stick zone.
fn zone_at_end(r: &MarchResult) -> StickZone {
    let [left, right] = r.steps.last().unwrap().largest_stick().unwrap();
    StickZone { left, right }
}

#[test]
fn cells_left_at_the_limit_by_the_ramp_shake_down_geometrically() {
    // The ramp (P, then Q at constant P) leaves the cells of 0.55 < |x| < 0.665 at the friction
    // limit inside the permanent stick zone [-0.6722, 0.6686]; each cycle they slip about a
    // tenth of what they slipped in the cycle before. Their slip is not zero, so a number of
    // cycles fixed in advance may end before they stop.
    let (contact, cycle) = shakedown_case();
    let r = march(&contact, &history(&cycle, 4), &options(), |_, _| {}).unwrap();
    let band: Vec<f64> = r
        .cycles
        .iter()
        .map(|c| {
            r.x.iter()
                .zip(&c.slip_range)
                .filter(|(x, _)| (0.55..0.665).contains(&x.abs()))
                .fold(0.0f64, |m, (_, s)| m.max(*s))
        })
        .collect();
    let shown: Vec<String> = band.iter().map(|v| format!("{v:.2e}")).collect();
    eprintln!("largest slip range in 0.55 < |x| < 0.665, cycles 1-4: {shown:?} mm");
    // Geometric from the second cycle: the same ratio, about 10, each cycle (the first cycle
    // also carries the settling of the ramp's end, 15x the second's).
    assert!(band[0] > band[1], "slip ranges {band:?}");
    for w in band[1..].windows(2) {
        let ratio = w[0] / w[1];
        assert!(
            w[1] > 0.0 && (5.0..20.0).contains(&ratio),
            "slip ranges {band:?}"
        );
    }
}

#[test]
fn the_steady_march_finds_the_steady_stick_zone_without_a_cycle_count() {
    let (contact, cycle) = shakedown_case();
    let exact = steady_zone(&contact, &cycle);
    let template = history(&cycle, 1);
    let r = march_steady(
        &contact,
        &template,
        &Steady::default(),
        &options(),
        |_, _| {},
    )
    .unwrap();
    let cell = r.x[1] - r.x[0];
    let got = zone_at_end(&r);
    let cycles_run = r.cycles.len();
    let change = r.steady_change.unwrap();
    eprintln!(
        "steady march: {cycles_run} cycles, last change {change:e} A f P; stick at point 1 \
         [{:.6}, {:.6}] against steady [{:.6}, {:.6}]: d {:+.3} cells, e {:+.3} cells",
        got.left,
        got.right,
        exact.left,
        exact.right,
        (got.half_width() - exact.half_width()) / cell,
        (got.eccentricity() - exact.eccentricity()) / cell,
    );
    assert!(Steady::default().is_met(change));
    // The steady zone's half-width and centre to 0.2 cells: the march's zone is bounded by cell
    // edges, so each end is within half a cell of the exact end at best, and the issue measured
    // 0.2 cells for d and e after 10 fixed cycles (0.15 and 0.06 here).
    assert!((got.half_width() - exact.half_width()).abs() <= 0.2 * cell);
    assert!((got.eccentricity() - exact.eccentricity()).abs() <= 0.2 * cell);
    // After three fixed cycles the zone is still 29 cells inside at each end: a count chosen in
    // advance would have been too small.
    let three = march(&contact, &history(&cycle, 3), &options(), |_, _| {}).unwrap();
    let early = zone_at_end(&three);
    assert!(early.left - exact.left > 25.0 * cell, "{early:?}");
    // The cycle count is what it takes: one cycle fewer has not met the tolerance.
    let fewer = march(
        &contact,
        &history(&cycle, cycles_run - 1),
        &options(),
        |_, _| {},
    )
    .unwrap();
    assert!(!Steady::default().is_met(fewer.steady_change.unwrap()));
    // Two routes: the steady march is the fixed march of as many cycles, increment for increment.
    let fixed = march(
        &contact,
        &history(&cycle, cycles_run),
        &options(),
        |_, _| {},
    )
    .unwrap();
    assert_eq!(r, fixed);
}

#[test]
fn a_march_that_does_not_repeat_within_max_cycles_names_the_last_change() {
    let (contact, cycle) = shakedown_case();
    let steady = Steady::default().with_max_cycles(3).unwrap();
    let fixed = march(&contact, &history(&cycle, 3), &options(), |_, _| {}).unwrap();
    match march_steady(
        &contact,
        &history(&cycle, 1),
        &steady,
        &options(),
        |_, _| {},
    ) {
        Err(Error::NotSteady {
            max_cycles,
            change,
            tolerance,
        }) => {
            assert_eq!(max_cycles, 3);
            assert_eq!(Some(change), fixed.steady_change);
            assert_eq!(tolerance, Steady::DEFAULT_TOLERANCE);
        }
        other => panic!("expected NotSteady, got {other:?}"),
    }
}

#[test]
fn steady_settings_and_histories_are_checked() {
    assert!(matches!(
        Steady::default().with_max_cycles(1),
        Err(Error::InvalidCount { field, value: 1, min: 2, .. }) if field == "history.max_cycles"
    ));
    for bad in [0.0, 1.0, f64::NAN, -1e-9] {
        assert!(matches!(
            Steady::default().with_tolerance(bad),
            Err(Error::InvalidInput { field, .. }) if field == "history.steady_tolerance"
        ));
    }
    let (contact, _) = shakedown_case();
    let rows = History::from_rows(&[[1000.0, 0.0, 0.0], [1000.0, 100.0, 0.0]]).unwrap();
    assert!(matches!(
        march_steady(&contact, &rows, &Steady::default(), &options(), |_, _| {}),
        Err(Error::NoCycle { .. })
    ));
    // A plan longer than the increment limit is refused before any increment is solved.
    let (_, cycle) = shakedown_case();
    let (p1, p2) = cycle.as_given();
    let long = History::in_phase(p1, p2, 1, 1000, Ramp::NormalFirst, 19).unwrap();
    let steady = Steady::default()
        .with_max_cycles(Steady::MAX_CYCLES)
        .unwrap();
    let mut calls = 0;
    assert!(matches!(
        march_steady(&contact, &long, &steady, &options(), |_, _| calls += 1),
        Err(Error::TooManyIncrements { field, .. }) if field.contains("history.max_cycles")
    ));
    assert_eq!(calls, 0);
}
