//! Time marching against closed forms, the steady-state analysis and the exact evolution.

mod common;
use common::*;
use halfplane::evolution::evolve;
use halfplane::history::{History, Ramp};
use halfplane::march::{march, MarchOptions, MarchResult};
use halfplane::steady::SteadyOptions;
use halfplane::{closed_form, Contact, Cycle, Error, Half, Profile};

fn run(c: &Contact, rows: &[[f64; 3]], cells: usize) -> MarchResult {
    march(
        c,
        &History::from_rows(rows).unwrap(),
        &MarchOptions::default().with_cells(cells).unwrap(),
        |_, _| {},
    )
    .unwrap()
}

/// Hertz at P = 1000: ramp P in 10 steps, Q to `q_max` in `n_load` steps, then to `q_end`.
fn cattaneo_rows(q_max: f64, n_load: usize, q_end: f64, n_unload: usize) -> Vec<[f64; 3]> {
    let mut rows: Vec<[f64; 3]> = (1..=10).map(|i| [100.0 * i as f64, 0.0, 0.0]).collect();
    rows.extend((1..=n_load).map(|i| [1000.0, q_max * i as f64 / n_load as f64, 0.0]));
    rows.extend((1..=n_unload).map(|i| {
        [
            1000.0,
            q_max + (q_end - q_max) * i as f64 / n_unload as f64,
            0.0,
        ]
    }));
    rows
}

/// Cattaneo-Mindlin traction for Hertz under monotonic Q: `q = f (p_a - p_c)`,
/// `p_c = sqrt(c^2 - x^2)/(A R)` (Johnson, Contact Mechanics, section 7.1).
fn cattaneo_traction(a_comp: f64, a: f64, c: f64, x: f64) -> f64 {
    0.6 * (closed_form::hertz_pressure(a_comp, RADIUS, a, x)
        - closed_form::hertz_pressure(a_comp, RADIUS, c, x))
}

/// Largest |numerical - exact| traction over the contact cells, relative to f p0.
fn traction_error(
    r: &MarchResult,
    fields: &[f64],
    exact: impl Fn(f64) -> f64,
    a: f64,
    p0: f64,
) -> f64 {
    r.x.iter()
        .zip(fields)
        .filter(|(x, _)| x.abs() < a)
        .map(|(x, q)| (q - exact(*x)).abs())
        .fold(0.0, f64::max)
        / (0.6 * p0)
}

fn traction_at(
    c: &Contact,
    rows: &[[f64; 3]],
    cells: usize,
    step: usize,
) -> (MarchResult, Vec<f64>) {
    let mut q = Vec::new();
    let r = march(
        c,
        &History::from_rows(rows).unwrap(),
        &MarchOptions::default().with_cells(cells).unwrap(),
        |s, f| {
            if s.step == step {
                q = f.traction.to_vec();
            }
        },
    )
    .unwrap();
    (r, q)
}

/// The two reference contacts most march tests run on, with their names.
fn hertz_and_flat_rounded() -> [(&'static str, Contact); 2] {
    [
        ("Hertz", contact(Profile::hertz(RADIUS).unwrap())),
        (
            "flat-rounded",
            contact(Profile::flat_rounded(0.3, RADIUS).unwrap()),
        ),
    ]
}

/// One increment from Q = 0 to 0.5 or 0.97 f P moves each stick-slip boundary by a fifth of the
/// contact or more, and one back to minus that reverses the slip over the same distance: the
/// plain active set took one pass more per doubling of the cells (at 25,600 cells 14 passes for
/// the loading to 0.97 f P and 15 for the reversal from 0.5 f P), the extrapolated ends and the
/// re-stuck start of a reversal (`march/predict.rs`) at most 10 from 100 to 204,800 cells on the
/// Hertz and flat-rounded contacts. The answer is still the one complementarity fixes: on Hertz
/// the stick boundary within a cell of Cattaneo-Mindlin's, before and after the reversal (whose
/// reversed slip zone, for Q to -Q, is the whole slip zone: Johnson, section 7.2).
#[test]
fn boundaries_moved_by_many_cells_in_one_increment_take_a_bounded_number_of_passes() {
    for (name, c) in hertz_and_flat_rounded() {
        for ratio in [0.5, 0.97] {
            let q = ratio * 0.6 * 1000.0;
            let rows = [[1000.0, 0.0, 0.0], [1000.0, q, 0.0], [1000.0, -q, 0.0]];
            for cells in [400, 1600, 6400, 25600] {
                let r = run(&c, &rows, cells);
                for step in &r.steps[1..] {
                    assert!(
                        step.passes <= 10,
                        "{name}, Q to {ratio} f P and back, {cells} cells: {} active-set passes in increment {} (extrapolated stick ends: at most 10)",
                        step.passes,
                        step.step
                    );
                    if name == "Hertz" {
                        let exact_c = closed_form::cattaneo_mindlin_stick_half_width(
                            step.half_width,
                            0.6,
                            1000.0,
                            q,
                        );
                        let [l, rr] = step.largest_stick().unwrap();
                        let w = r.x[1] - r.x[0];
                        assert!(
                            (rr - exact_c).abs() <= w && (l + exact_c).abs() <= w,
                            "{cells} cells, Q to {ratio} f P, increment {}: Cattaneo-Mindlin stick boundary [{l}, {rr}] more than a cell from +-{exact_c}",
                            step.step
                        );
                    }
                }
            }
        }
    }
}

/// The extrapolated ends and a reversal's re-stuck start only choose trial sets: a load reaching
/// 0.97 f P in one increment and -0.97 f P in one more (both predicted) ends where the same load
/// in 16 increments each way does (passes of one or two cells, nothing to extrapolate). At
/// constant P and with Q monotone in each half, exact theory gives the same tractions and
/// energy for both paths (the slip of every cell is monotone in each half, the final stick set
/// never slipped in it). Measured on Hertz, 1600 cells: tractions 1.0e-12 f p0 apart, energies
/// equal to 12 digits. The tolerances, 1e-9 of f p0 and of the energy, sit above the solvers'
/// rounding along different paths to one set (up to 4e-11 relative at 25,600 cells) and far
/// below a cell's change of state (about 1e-2 f p0 in the traction).
#[test]
fn extrapolated_passes_end_where_small_increments_do() {
    for (name, c) in hertz_and_flat_rounded() {
        let q = 0.97 * 0.6 * 1000.0;
        let steps: Vec<[f64; 3]> = (1..=16)
            .map(|i| [1000.0, q * i as f64 / 16.0, 0.0])
            .chain((1..=16).map(|i| [1000.0, q - 2.0 * q * i as f64 / 16.0, 0.0]))
            .collect();
        let small: Vec<[f64; 3]> = [[1000.0, 0.0, 0.0]].into_iter().chain(steps).collect();
        let large = [[1000.0, 0.0, 0.0], [1000.0, q, 0.0], [1000.0, -q, 0.0]];
        let (r_large, q_large) = traction_at(&c, &large, 1600, 3);
        let (r_small, q_small) = traction_at(&c, &small, 1600, 33);
        let predicted = r_large.steps[2].passes;
        assert!(
            predicted > 3,
            "{name}: the reversal took {predicted} passes, too few for the ends to be extrapolated"
        );
        // Hertz's peak pressure at this P and half-width: the traction scale (for the
        // flat-rounded contact too).
        let a = r_large.steps[2].half_width;
        let f_p0 = 0.6 * 2.0 * 1000.0 / (std::f64::consts::PI * a);
        let worst = q_large
            .iter()
            .zip(&q_small)
            .map(|(a, b)| (a - b).abs())
            .fold(0.0, f64::max);
        assert!(
            worst <= 1e-9 * f_p0,
            "{name}: tractions after Q to +-0.97 f P in one increment each way differ from 16 increments each way by {worst:.3e} (f p0 = {f_p0:.3e})"
        );
        let (e_large, e_small) = (
            r_large.steps.last().unwrap().energy,
            r_small.steps.last().unwrap().energy,
        );
        assert!(
            (e_large - e_small).abs() <= 1e-9 * e_small,
            "{name}: dissipated energy {e_large:.12e} in two increments against {e_small:.12e} in 32"
        );
        assert_eq!(
            r_large.steps[2].largest_stick(),
            r_small.steps.last().unwrap().largest_stick(),
            "{name}: the stick zone differs"
        );
    }
}

#[test]
fn cattaneo_mindlin_loading() {
    let c = contact(Profile::hertz(RADIUS).unwrap());
    let a_comp = c.compliance().value();
    let rows = cattaneo_rows(300.0, 30, 300.0, 0);
    for cells in [200, 400, 800] {
        let (r, q) = traction_at(&c, &rows, cells, 40);
        let last = r.steps.last().unwrap();
        let a = last.half_width;
        let exact_c = closed_form::cattaneo_mindlin_stick_half_width(a, 0.6, 1000.0, 300.0);
        let [l, rr] = last.largest_stick().unwrap();
        let w = r.x[1] - r.x[0];
        let p0 = closed_form::hertz_pressure(a_comp, RADIUS, a, 0.0);
        let err = traction_error(&r, &q, |x| cattaneo_traction(a_comp, a, exact_c, x), a, p0);
        eprintln!("N = {cells}: stick [{l:.5}, {rr:.5}] vs c = {exact_c:.5} (cell {w:.5}); max traction error {err:.2e} f p0");
        // The stick edge is a cell edge: within one cell of the exact boundary. The traction's
        // largest error sits at that edge, where the exact traction has an infinite slope:
        // 2% of f p0 at 200 cells and falling.
        assert!(
            (rr - exact_c).abs() <= w && (l + exact_c).abs() <= w,
            "Cattaneo stick boundary more than a cell off"
        );
        assert!(err < 0.02, "Cattaneo traction error {err}");
    }
}

#[test]
fn mindlin_unloading() {
    // After Q* = 400, unloading to Q = 100 slips backwards outside c' = a sqrt(1 - (Q* - Q)/(2fP))
    // and q = q_L(Q*) - 2 f (p_a - p_c') (Mindlin & Deresiewicz; Johnson section 7.2).
    let c = contact(Profile::hertz(RADIUS).unwrap());
    let a_comp = c.compliance().value();
    let rows = cattaneo_rows(400.0, 20, 100.0, 30);
    let (r, q) = traction_at(&c, &rows, 400, rows.len());
    let last = r.steps.last().unwrap();
    let a = last.half_width;
    let c_load = closed_form::cattaneo_mindlin_stick_half_width(a, 0.6, 1000.0, 400.0);
    let c_unload = a * (1.0_f64 - 300.0 / (2.0 * 0.6 * 1000.0)).sqrt();
    let exact = |x: f64| {
        cattaneo_traction(a_comp, a, c_load, x) - 2.0 * cattaneo_traction(a_comp, a, c_unload, x)
    };
    let w = r.x[1] - r.x[0];
    let [l, rr] = last.largest_stick().unwrap();
    assert!(
        (rr - c_unload).abs() <= w && (l + c_unload).abs() <= w,
        "unloading stick zone [{l}, {rr}] vs c' = {c_unload}"
    );
    let p0 = closed_form::hertz_pressure(a_comp, RADIUS, a, 0.0);
    let err = traction_error(&r, &q, exact, a, p0);
    assert!(err < 0.02, "Mindlin unloading traction error {err} f p0");
    assert!(
        r.steps[29].stick_intervals.len() == 1,
        "single stick zone at the end of loading"
    );
}

#[test]
fn bulk_tension_shifts_the_stick_zone_as_nowell_and_hills() {
    // Constant P, Q and sigma rising together from zero: c = a sqrt(1 - Q/(fP)) centred at
    // e = A R sigma/(4f) (Nowell & Hills 1987; the monotonic counterpart of the paper's
    // e = -A R dsigma/(8f)). Within one cell.
    let c = contact(Profile::hertz(RADIUS).unwrap());
    let mut rows: Vec<[f64; 3]> = (1..=10).map(|i| [100.0 * i as f64, 0.0, 0.0]).collect();
    rows.extend((1..=30).map(|i| [1000.0, 10.0 * i as f64, 50.0 * i as f64 / 30.0]));
    let r = run(&c, &rows, 800);
    let last = r.steps.last().unwrap();
    let a = last.half_width;
    let half = closed_form::cattaneo_mindlin_stick_half_width(a, 0.6, 1000.0, 300.0);
    let e = c.compliance().value() * RADIUS * 50.0 / (4.0 * 0.6);
    let w = r.x[1] - r.x[0];
    let [l, rr] = last.largest_stick().unwrap();
    assert!(
        e > 5.0 * w,
        "the offset must be resolved for the test to mean anything"
    );
    assert!(
        (l - (e - half)).abs() <= w && (rr - (e + half)).abs() <= w,
        "stick [{l}, {rr}] vs [{}, {}]",
        e - half,
        e + half
    );
}

fn paper_case(profile: Profile, cells: usize) {
    // The paper's steady state: the stick zone at the end of every half-cycle is the permanent
    // zone; at 1/4, 1/2, 3/4 of each half it is the exact evolution. Within one cell (the reference cycle's
    // independent check was also to a cell).
    let c = contact(profile);
    let cycle = theory_cycle();
    let (p1, p2) = cycle.as_given();
    let steps = 40;
    let history = History::in_phase(p1, p2, 2, steps, Ramp::NormalFirst, 10).unwrap();
    let r = march(
        &c,
        &history,
        &MarchOptions::default().with_cells(cells).unwrap(),
        |_, _| {},
    )
    .unwrap();
    let exact = evolve(&c, &cycle, 5, &SteadyOptions::default()).unwrap();
    let w = r.x[1] - r.x[0];
    let start = history.cycles().unwrap().first_step() + 2 * steps; // second cycle
    for half in 0..2 {
        for j in 1..=4 {
            let step = &r.steps[start + half * steps + j * steps / 4 - 1];
            let want = exact.points[half * 5 + j].stick_zone;
            let [l, rr] = step.largest_stick().unwrap();
            assert!(
                (l - want.left).abs() <= w && (rr - want.right).abs() <= w,
                "{:?}, half {} at {}/4: marched [{l:.5}, {rr:.5}] vs exact [{:.5}, {:.5}], cell {w:.5}",
                c.profile().shape(),
                half + 1,
                j,
                want.left,
                want.right
            );
        }
    }
    assert_eq!(
        r.shakedown_cycle,
        Some(1),
        "the in-phase cycle repeats from the first"
    );
}

#[test]
fn paper_steady_state_and_evolution_hertz() {
    paper_case(Profile::hertz(RADIUS).unwrap(), 500);
}

#[test]
fn paper_steady_state_and_evolution_flat_rounded() {
    paper_case(Profile::flat_rounded(0.3, RADIUS).unwrap(), 500);
}

/// Energy of the last of `cycles` in-phase cycles and its largest slip range, for a
/// proportional ramp to `p1` (which carries no shear or tension, so the ramp itself sticks).
fn last_cycle(
    c: &Contact,
    p1: [f64; 3],
    p2: [f64; 3],
    cells: usize,
    steps: usize,
    cycles: usize,
) -> (f64, f64) {
    let history = History::in_phase(
        point(p1[0], p1[1], p1[2]),
        point(p2[0], p2[1], p2[2]),
        cycles,
        steps,
        Ramp::Proportional,
        10,
    )
    .unwrap();
    let r = march(
        c,
        &history,
        &MarchOptions::default().with_cells(cells).unwrap(),
        |_, _| {},
    )
    .unwrap();
    let last = r.cycles.last().unwrap();
    (last.energy, 2.0 * last.max_slip_amplitude())
}

/// In-phase cycles for which eq. (1) holds, `|dQ|/|dP| + pi a_max |dsigma| / (4 |dP|) < f`:
/// P rising with Q, with and without tension, and P falling while Q rises (that one sheds its
/// first-cycle slip and then sticks).
const FULL_STICK: [([f64; 3], [f64; 3]); 3] = [
    ([1000.0, 0.0, 0.0], [1400.0, 100.0, 0.0]),
    ([1000.0, 0.0, 0.0], [1400.0, 100.0, 5.0]),
    ([1400.0, 0.0, 0.0], [1000.0, 100.0, 5.0]),
];

/// Checks that a full-stick cycle dissipates nothing: below 1e-12 dQ^2 A per cycle. dQ^2 A is the
/// energy scale of the shear cycle (0.18 N mm/mm here), so this bound is rounding: a single cell
/// slipping by 1e-9 of the cycle's displacement scale A dQ would already exceed it. Before the
/// contact edges were treated exactly, a ratchet at the advancing edge gave 1e-6 to 3e-5 of it.
fn assert_full_stick(c: &Contact, name: &str, cells: usize, steps: usize) {
    let scale = 100.0 * 100.0 * c.compliance().value();
    for (p1, p2) in FULL_STICK {
        let (energy, slip) = last_cycle(c, p1, p2, cells, steps, 2);
        assert!(
            energy.abs() < 1e-12 * scale,
            "{name}, {p1:?} -> {p2:?}, {cells} cells, {steps} steps per half: a full-stick cycle \
             (eq. 1) dissipates {energy:e} = {:e} dQ^2 A per cycle",
            energy / scale
        );
        // Nothing moves either: the slip range is rounding of the displacement scale A dQ.
        assert!(
            slip < 1e-12 * 100.0 * c.compliance().value(),
            "{name}, {p1:?} -> {p2:?}, {cells} cells, {steps} steps per half: full-stick cycle \
             slips {slip:e} mm"
        );
    }
}

#[test]
fn full_stick_cycles_dissipate_nothing() {
    // A sample of the sweep in `full_stick_sweep` (ignored; see docs/convergence.md), chosen to
    // include the coarsest grid and time step, where the old advancing-edge ratchet was largest.
    for (name, c) in hertz_and_flat_rounded() {
        for (cells, steps) in [(100, 5), (400, 20), (250, 60)] {
            assert_full_stick(&c, name, cells, steps);
        }
    }
}

#[test]
#[ignore = "full sweep, ~1 min in release; see docs/convergence.md"]
fn full_stick_sweep() {
    // `cargo test --release -p halfplane --test march -- --ignored full_stick_sweep`
    for (name, c) in hertz_and_flat_rounded() {
        for cells in [100, 200, 400, 800, 1600, 3200] {
            for steps in [5, 10, 20, 50, 100, 200, 400] {
                assert_full_stick(&c, name, cells, steps);
            }
        }
    }
}

#[test]
fn slip_tolerance_changes_the_labels_not_the_solution() {
    // The threshold that labels a cell slipping must not enter the active set: with 1e-3 the
    // energy per cycle once moved by +41% and with 1e-2 the dissipation was negative. The
    // tractions and energies must be bit-identical; every increment dissipates >= 0 up to
    // rounding (1e-12 of the cycle's energy scale dQ^2 A).
    let c = contact(Profile::hertz(RADIUS).unwrap());
    let (p1, p2) = theory_cycle().as_given();
    let history = History::in_phase(p1, p2, 2, 45, Ramp::NormalFirst, 15).unwrap();
    let scale = 500.0 * 500.0 * c.compliance().value();
    let solve = |tolerance: f64| {
        let mut traction = Vec::new();
        let r = march(
            &c,
            &history,
            &MarchOptions::default()
                .with_cells(300)
                .unwrap()
                .with_slip_tolerance(tolerance)
                .unwrap(),
            |_, f| traction.extend_from_slice(f.traction),
        )
        .unwrap();
        for s in &r.steps {
            assert!(
                s.energy_increment >= -1e-12 * scale,
                "slip tolerance {tolerance}: negative dissipation {:e} at step {}",
                s.energy_increment,
                s.step
            );
        }
        (r, traction)
    };
    let (fine, q_fine) = solve(1e-10);
    let (coarse, q_coarse) = solve(1e-2);
    assert!(
        q_fine == q_coarse,
        "the slip-labelling threshold changed the tractions"
    );
    for (a, b) in fine.steps.iter().zip(&coarse.steps) {
        assert_eq!(
            a.energy, b.energy,
            "the slip-labelling threshold changed the energy at step {}",
            a.step
        );
    }
}

#[test]
fn stick_zone_at_both_ends_matches_steady_at_any_step_count() {
    // A normal-first ramp reaches point 1 with |Q|/P = 0.25 (0.4 in the second cycle), above the
    // cycle's, so it leaves cells at the friction limit inside the permanent stick zone. They return
    // to that limit at the end of every falling half and do not move in exact theory; they must
    // be labelled stuck at every time step, so that the stick zone at both ends of the last cycle
    // is the single steady interval [-m, n], within one cell.
    let c = contact(Profile::hertz(RADIUS).unwrap());
    for cycle in [
        theory_cycle(),
        Cycle::new(point(1000.0, -400.0, -20.0), point(1400.0, 250.0, 20.0)),
    ] {
        let exact = halfplane::steady::analyse(&c, &cycle, &SteadyOptions::default())
            .unwrap()
            .stick_zone
            .unwrap();
        let (p1, p2) = cycle.as_given();
        for steps in [15, 60, 200] {
            let history = History::in_phase(p1, p2, 2, steps, Ramp::NormalFirst, 15).unwrap();
            let r = march(
                &c,
                &history,
                &MarchOptions::default().with_cells(400).unwrap(),
                |_, _| {},
            )
            .unwrap();
            let w = r.x[1] - r.x[0];
            // Stick is what does not move: inside the steady zone (less a cell at each end)
            // the last cycle's slip range is exactly zero, not a creep of rounding size.
            let last = r.cycles.last().unwrap();
            for (x, range) in r.x.iter().zip(&last.slip_range) {
                assert!(
                    *x <= exact.left + w || *x >= exact.right - w || *range == 0.0,
                    "{p1:?} -> {p2:?}, {steps} steps per half: the permanent stick zone creeps \
                     {range:e} mm per cycle at x = {x}"
                );
            }
            let n = r.steps.len();
            for (end, k) in [("point 2", n - steps - 1), ("point 1", n - 1)] {
                let zones = &r.steps[k].stick_intervals;
                assert!(
                    zones.len() == 1
                        && (zones[0][0] - exact.left).abs() <= w
                        && (zones[0][1] - exact.right).abs() <= w,
                    "{p1:?} -> {p2:?}, {steps} steps per half: stick at {end} {zones:?}, \
                     steady [{:.5}, {:.5}], cell {w:.5}",
                    exact.left,
                    exact.right
                );
            }
        }
    }
}

#[test]
fn gross_sliding_is_reported_with_its_step() {
    let c = contact(Profile::hertz(RADIUS).unwrap());
    let rows = [
        [1000.0, 0.0, 0.0],
        [1000.0, 500.0, 0.0],
        [1000.0, 700.0, 0.0],
    ];
    let err = march(
        &c,
        &History::from_rows(&rows).unwrap(),
        &MarchOptions::default(),
        |_, _| {},
    )
    .unwrap_err();
    assert!(matches!(err, Error::SlidesAtStep { step: 3, .. }), "{err}");
    assert!(err.to_string().contains("step 3"));
}

#[test]
fn bad_histories_are_errors_naming_the_row() {
    let c = contact(Profile::hertz(RADIUS).unwrap());
    // The error carries the row and column as data (the CLI maps the row to a file line).
    let row_error = |rows: &[[f64; 3]]| match History::from_rows(rows) {
        Err(Error::InvalidRow { row, column, .. }) => (row, column),
        other => panic!("expected InvalidRow, got {other:?}"),
    };
    assert_eq!(
        row_error(&[[1000.0, 0.0, 0.0], [f64::NAN, 0.0, 0.0]]),
        (2, "normal")
    );
    assert_eq!(
        row_error(&[[1000.0, 0.0, 0.0], [-1.0, 0.0, 0.0]]),
        (2, "normal")
    );
    assert_eq!(row_error(&[[1000.0, f64::INFINITY, 0.0]]), (1, "shear"));
    let err = History::from_rows(&[[1000.0, 0.0, 2e30]]).unwrap_err();
    assert!(
        err.to_string().contains("history row 1: invalid bulk = 2"),
        "{err}"
    );
    assert!(History::from_rows(&[]).is_err());
    // The limit, the default grid and the history stay usable after a rejected setting.
    assert!(march(
        &c,
        &History::from_rows(&[[1000.0, 0.0, 0.0]]).unwrap(),
        &MarchOptions::default(),
        |_, _| {},
    )
    .is_ok());
}

#[test]
fn a_contact_narrower_than_a_cell_is_solved_not_a_panic() {
    // At P = 1 N/mm the contact (a = 0.024 mm) holds no cell centre of an 8-cell grid sized for
    // P = 1000 (cells 0.19 mm wide): there is no stick cell at all, yet shear is applied. The
    // first increment then carries nothing and the second is an ordinary partial-slip step.
    let c = contact(Profile::hertz(RADIUS).unwrap());
    let r = march(
        &c,
        &History::from_rows(&[[1.0, 0.1, 0.0], [1000.0, 100.0, 0.0]]).unwrap(),
        &MarchOptions::default().with_cells(8).unwrap(),
        |_, _| {},
    )
    .unwrap();
    assert!(r.steps[0].stick_intervals.is_empty() && r.steps[0].energy_increment == 0.0);
    assert!(r.steps[1].energy_increment >= 0.0);
}

#[test]
fn solver_options_are_valid_by_construction() {
    // Each rejected setting is a typed error naming the case-file field, the value and the
    // valid range (never a panic, never a silently clamped value).
    use halfplane::march::LinearSolver;
    let o = MarchOptions::default();
    for (err, field, range) in [
        (
            o.with_cells(0).unwrap_err(),
            "solver.cells",
            "from 8 to 1000000",
        ),
        (
            o.with_cells(7).unwrap_err(),
            "solver.cells",
            "from 8 to 1000000",
        ),
        (
            o.with_cells(MarchOptions::MAX_CELLS + 1).unwrap_err(),
            "solver.cells",
            "from 8 to 1000000",
        ),
        (
            o.with_cells(20_000)
                .unwrap()
                .with_solver(LinearSolver::Dense)
                .unwrap_err(),
            "solver.cells (with the dense solver)",
            "from 8 to 10000",
        ),
        (
            o.with_solver(LinearSolver::Dense)
                .unwrap()
                .with_cells(20_000)
                .unwrap_err(),
            "solver.cells (with the dense solver)",
            "from 8 to 10000",
        ),
        (
            o.with_max_passes(0).unwrap_err(),
            "solver.max_passes",
            "from 1 to",
        ),
        (
            o.with_slip_tolerance(0.0).unwrap_err(),
            "solver.slip_tolerance",
            "0 < t < 1",
        ),
        (
            o.with_slip_tolerance(f64::NAN).unwrap_err(),
            "solver.slip_tolerance",
            "0 < t < 1",
        ),
        (
            o.with_shakedown_tolerance(1.5).unwrap_err(),
            "solver.shakedown_tolerance",
            "0 < t < 1",
        ),
    ] {
        let text = err.to_string();
        assert!(
            matches!(err, Error::InvalidInput { .. } | Error::InvalidCount { .. })
                && text.contains(field)
                && text.contains(range),
            "{text}"
        );
    }
    let o = o
        .with_cells(MarchOptions::MAX_CELLS)
        .unwrap()
        .with_slip_tolerance(1e-6)
        .unwrap();
    assert_eq!(
        (o.cells(), o.slip_tolerance()),
        (MarchOptions::MAX_CELLS, 1e-6)
    );
}

#[test]
fn dissipation_is_non_negative_and_zero_without_slip() {
    let c = contact(Profile::flat_rounded(0.3, RADIUS).unwrap());
    let r = run(&c, &cattaneo_rows(300.0, 15, -200.0, 25), 300);
    assert!(r
        .steps
        .iter()
        .all(|s| s.energy_increment >= -1e-15 * s.energy.abs().max(1e-30)));
    assert!(
        r.steps[..10].iter().all(|s| s.energy_increment == 0.0),
        "pressing alone dissipates nothing"
    );
    assert!(r.steps.last().unwrap().energy > 0.0);
}

#[test]
fn toeplitz_and_dense_solvers_agree() {
    // Two independent linear-algebra routes through the same discrete problem: the stick zones
    // must be identical and the energies agree to rounding (1e-9 relative).
    use halfplane::march::LinearSolver;
    let c = contact(Profile::flat_rounded(0.3, RADIUS).unwrap());
    let (p1, p2) = theory_cycle().as_given();
    let history = History::in_phase(p1, p2, 1, 20, Ramp::Proportional, 10).unwrap();
    let fast = march(
        &c,
        &history,
        &MarchOptions::default().with_cells(160).unwrap(),
        |_, _| {},
    )
    .unwrap();
    let dense = march(
        &c,
        &history,
        &MarchOptions::default()
            .with_cells(160)
            .unwrap()
            .with_solver(LinearSolver::Dense)
            .unwrap(),
        |_, _| {},
    )
    .unwrap();
    for (a, b) in fast.steps.iter().zip(&dense.steps) {
        assert_eq!(a.stick_intervals, b.stick_intervals, "step {}", a.step);
        assert!(
            (a.energy - b.energy).abs() <= 1e-9 * b.energy.abs().max(1e-30),
            "step {}: {} vs {}",
            a.step,
            a.energy,
            b.energy
        );
    }
}

#[test]
fn a_receding_edge_that_is_not_rejected_slips_forward() {
    // Tension near the limit: at the start of the falling half the two-edge relation would keep
    // the right stick boundary beyond the receding edge (dQ - pi a2 |dsigma|/4 = 229.3 < f dP =
    // 240), which `evolve` used to show as the right edge sticking. Marching shows it slipping
    // forward instead (the previous half's direction) for most of the falling half, so
    // `analyse` and `evolve` now reject the cycle.
    use halfplane::asymptotic::Edge;
    let c = contact(Profile::hertz(RADIUS).unwrap());
    let cycle = Cycle::new(point(1000.0, -150.0, -50.0), point(1400.0, 150.0, 50.0));
    let err = evolve(&c, &cycle, 21, &SteadyOptions::default()).unwrap_err();
    assert!(
        matches!(
            err,
            Error::SlipReversesInHalf {
                half: Half::Second,
                edge: Edge::Right,
                fraction: 0.0,
                ..
            }
        ),
        "{err:?}"
    );
    let (p1, p2) = cycle.as_given();
    let steps = 20;
    let history = History::in_phase(p1, p2, 2, steps, Ramp::NormalFirst, 10).unwrap();
    let falling = history.cycles().unwrap().first_step() + 2 * steps + steps;
    // The falling half of cycle 2. The solver's own slip threshold (MarchOptions::slip_tolerance, 1e-10 A f P).
    let threshold = 1e-10 * c.compliance().value() * 0.6 * 1400.0;
    let mut forward_steps = 0;
    march(
        &c,
        &history,
        &MarchOptions::default().with_cells(400).unwrap(),
        |s, f| {
            let k = s.step - 1;
            if (falling..falling + steps / 2).contains(&k)
                && (0..f.x.len()).any(|i| f.x[i] > 0.5 && f.slip_increment[i] > threshold)
            {
                forward_steps += 1;
            }
        },
    )
    .unwrap();
    assert_eq!(
        forward_steps,
        steps / 2,
        "the right edge should slip forward through the first half of the falling half"
    );
}

#[test]
fn paper_steady_state_and_evolution_tabulated_and_power_law() {
    // The other two profile routes through the marching solver: a tabulated flat-rounded punch
    // (spline pieces, kink stated) and a wedge-like power law k = 1.5 (pressure by quadrature).
    paper_case(flat_rounded_table(0.3, RADIUS), 300);
    paper_case(Profile::power_law(0.02, 1.5).unwrap(), 300);
}
