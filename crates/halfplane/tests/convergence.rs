//! Convergence study of the time-marching solver (long; ignored by default):
//!
//! `cargo test --release -p halfplane --test convergence -- --ignored --nocapture`
//!
//! Prints the tables recorded in `docs/convergence.md` and asserts that the errors fall.

mod common;
use common::*;
use halfplane::history::{Harmonic, History, Ramp};
use halfplane::march::{march, MarchOptions};
use halfplane::steady::{analyse, SteadyOptions};
use halfplane::{closed_form, Contact, Profile};

#[test]
#[ignore = "long convergence study; run with --ignored (see docs/convergence.md)"]
fn convergence_against_cattaneo_mindlin_and_the_steady_state() {
    let c = contact(Profile::hertz(RADIUS).unwrap());
    let a_comp = c.compliance().value();
    let mut rows: Vec<[f64; 3]> = (1..=10).map(|i| [100.0 * i as f64, 0.0, 0.0]).collect();
    rows.extend((1..=30).map(|i| [1000.0, 10.0 * i as f64, 0.0]));
    let history = History::from_rows(&rows).unwrap();
    println!("Cattaneo-Mindlin (Hertz, P = 1000 N/mm, Q = 0 -> 300 N/mm in 30 steps)");
    println!("| cells | cell / a | stick edge error / a | max traction error / f p0 | mean traction error / f p0 | time (ms) |");
    println!("|---|---|---|---|---|---|");
    let mut previous_mean = f64::INFINITY;
    for cells in [100, 200, 400, 800, 1600, 3200] {
        let mut q = Vec::new();
        let t = std::time::Instant::now();
        let r = march(
            &c,
            &history,
            &MarchOptions::default().with_cells(cells).unwrap(),
            |s, f| {
                if s.step == 40 {
                    q = f.traction.to_vec();
                }
            },
        )
        .unwrap();
        let ms = t.elapsed().as_secs_f64() * 1e3;
        let last = r.steps.last().unwrap();
        let a = last.half_width;
        let exact_c = closed_form::cattaneo_mindlin_stick_half_width(a, 0.6, 1000.0, 300.0);
        let [l, rr] = last.largest_stick().unwrap();
        let edge = (rr - exact_c).abs().max((l + exact_c).abs()) / a;
        let p0 = closed_form::hertz_pressure(a_comp, RADIUS, a, 0.0);
        let exact = |x: f64| {
            0.6 * (closed_form::hertz_pressure(a_comp, RADIUS, a, x)
                - closed_form::hertz_pressure(a_comp, RADIUS, exact_c, x))
        };
        let errors: Vec<f64> =
            r.x.iter()
                .zip(&q)
                .filter(|(x, _)| x.abs() < a)
                .map(|(x, v)| (v - exact(*x)).abs() / (0.6 * p0))
                .collect();
        let max = errors.iter().fold(0.0f64, |m, v| m.max(*v));
        let mean = errors.iter().sum::<f64>() / errors.len() as f64;
        let w = r.x[1] - r.x[0];
        println!(
            "| {cells} | {:.2e} | {edge:.2e} | {max:.2e} | {mean:.2e} | {ms:.1} |",
            w / a
        );
        assert!(
            edge <= w / a,
            "stick edge more than a cell off at {cells} cells"
        );
        assert!(mean < previous_mean, "mean traction error must fall with N");
        previous_mean = mean;
    }

    let cycle = theory_cycle();
    let exact = analyse(&c, &cycle, &SteadyOptions::default())
        .unwrap()
        .stick_zone
        .unwrap();
    let (p1, p2) = cycle.as_given();
    let history = History::in_phase(p1, p2, 2, 45, Ramp::NormalFirst, 15).unwrap();
    println!("\\nPaper's Hertz cycle (docs/theory.md): permanent stick zone [{:.5}, {:.5}] after two cycles of 90 steps", exact.left, exact.right);
    println!("| cells | cell width | -m error | n error | time (ms) |");
    println!("|---|---|---|---|---|");
    for cells in [125, 250, 500, 1000, 2000, 4000] {
        let t = std::time::Instant::now();
        let r = march(
            &c,
            &history,
            &MarchOptions::default().with_cells(cells).unwrap(),
            |_, _| {},
        )
        .unwrap();
        let ms = t.elapsed().as_secs_f64() * 1e3;
        let [l, rr] = r.steps.last().unwrap().largest_stick().unwrap();
        let w = r.x[1] - r.x[0];
        println!(
            "| {cells} | {w:.2e} | {:+.2e} | {:+.2e} | {ms:.1} |",
            l - exact.left,
            rr - exact.right
        );
        assert!((l - exact.left).abs() <= w && (rr - exact.right).abs() <= w);
    }
}

/// Energy per cycle and per-cell slip range of the second of two cycles of the paper's cycle,
/// reached by a proportional ramp of 10 increments.
fn second_cycle(c: &Contact, cells: usize, steps_per_half: usize) -> (f64, Vec<f64>) {
    let (p1, p2) = theory_cycle().as_given();
    let history = History::in_phase(p1, p2, 2, steps_per_half, Ramp::Proportional, 10).unwrap();
    let mut r = march(
        c,
        &history,
        &MarchOptions::default().with_cells(cells).unwrap(),
        |_, _| {},
    )
    .unwrap();
    let cycle = r.cycles.swap_remove(1);
    (cycle.energy, cycle.slip_range)
}

fn cycle_energy(c: &Contact, cells: usize, steps_per_half: usize) -> f64 {
    second_cycle(c, cells, steps_per_half).0
}

/// Cell centres the contact edge crosses on one side in each half-cycle (a1 < x < a2).
fn crossings_per_half(c: &Contact, cells: usize) -> usize {
    let (p1, p2) = theory_cycle().as_given();
    let (a1, a2) = (
        c.half_width(p1.normal()).unwrap(),
        c.half_width(p2.normal()).unwrap(),
    );
    let (lo, hi) = (a1.min(a2), a1.max(a2));
    let w = 2.0 * hi / cells as f64;
    (0..cells)
        .map(|i| -hi + (i as f64 + 0.5) * w)
        .filter(|x| *x > lo && *x < hi)
        .count()
}

fn profiles() -> [(&'static str, Profile); 2] {
    [
        ("Hertz", Profile::hertz(RADIUS).unwrap()),
        (
            "flat-rounded b = 0.3",
            Profile::flat_rounded(0.3, RADIUS).unwrap(),
        ),
    ]
}

#[test]
fn energy_per_cycle_converges_at_second_order_in_the_time_step() {
    // Three step counts in the asymptotic range of `docs/convergence.md` at 200 cells (15 edge
    // crossings per half-cycle; 320 steps per half and more). The observed order from the
    // differences E(h) - E(h/2) and E(h/2) - E(h/4) was 1.93 (Hertz) and 2.04 (flat-rounded);
    // the study shows single refinements between 1.9 and 2.2 in this range, so 1.8 allows that
    // scatter and still fails any first-order scheme (the previous energy rule gave 0.82 here).
    for (name, profile) in profiles() {
        let c = contact(profile);
        let e: Vec<f64> = [320, 640, 1280]
            .iter()
            .map(|&steps| cycle_energy(&c, 200, steps))
            .collect();
        let order = ((e[0] - e[1]).abs() / (e[1] - e[2]).abs()).log2();
        assert!(
            order >= 1.8,
            "{name}: energy per cycle converges at order {order:.2} in the time step, not 2 \
             ({:.10e}, {:.10e}, {:.10e} at 320, 640, 1280 steps per half)",
            e[0],
            e[1],
            e[2]
        );
    }
}

#[test]
#[ignore = "long convergence study; run with --ignored (see docs/convergence.md)"]
fn energy_per_cycle_in_time_and_in_space() {
    // Time and space refined separately: converging in one at a fixed other proves nothing.
    // Each time table is measured against a fine-step run at the SAME cells, so that it holds
    // the time error alone.
    for (name, profile) in profiles() {
        let c = contact(profile);
        for (cells, fine) in [(200, 10240), (800, 5120), (3200, 5120)] {
            let (reference, reference_range) = second_cycle(&c, cells, fine);
            let largest = reference_range.iter().fold(0.0f64, |m, v| m.max(*v));
            println!(
                "\n{name}, {cells} cells ({} edge crossings per half-cycle): energy per cycle \
                 against steps per half (reference: {fine} steps per half, {reference:.10e})",
                crossings_per_half(&c, cells)
            );
            println!("| steps per half | energy per cycle | error / reference | observed order | slip range error / largest range |");
            println!("|---|---|---|---|---|");
            let mut previous: Option<f64> = None;
            for steps in [5, 10, 20, 40, 80, 160, 320, 640] {
                let (e, range) = second_cycle(&c, cells, steps);
                let err = (e - reference).abs();
                let order =
                    previous.map_or(String::from("-"), |p| format!("{:.2}", (p / err).log2()));
                let range_error = range
                    .iter()
                    .zip(&reference_range)
                    .fold(0.0f64, |m, (a, b)| m.max((a - b).abs()))
                    / largest;
                println!(
                    "| {steps} | {e:.10e} | {:+.2e} | {order} | {range_error:.1e} |",
                    (e - reference) / reference
                );
                previous = Some(err);
                // The largest error measured is 2.5e-4 (200 cells, 5 steps per half); the
                // previous energy rule stayed above 1e-5 up to 1280 steps per half.
                assert!(
                    err < 3e-4 * reference,
                    "time-step error {err:e} at {steps} steps per half"
                );
                // The end state of an increment does not depend on the path inside it, so the
                // slip ranges have no time-step error beyond rounding.
                assert!(
                    range_error < 1e-10,
                    "slip range error {range_error:e} at {steps} steps per half"
                );
            }
            // Once the step is shorter than the interval between edge crossings the error is
            // second order; at 640 steps per half it is below 2e-7 at every cell count.
            assert!(
                previous.unwrap() < 2e-7 * reference,
                "time-step error at 640 steps per half"
            );
        }
        println!("\n{name}: energy per cycle against cells (400 steps per half)");
        println!("| cells | energy per cycle | change from previous | observed order |");
        println!("|---|---|---|---|");
        let (mut last, mut last_change): (Option<f64>, Option<f64>) = (None, None);
        for cells in [100, 200, 400, 800, 1600, 3200] {
            let e = cycle_energy(&c, cells, 400);
            let change = last.map(|l| e - l);
            let order = match (last_change, change) {
                (Some(a), Some(b)) => format!("{:.2}", (a.abs() / b.abs()).log2()),
                _ => "-".into(),
            };
            println!(
                "| {cells} | {e:.8e} | {} | {order} |",
                change.map_or("-".into(), |d| format!("{:+.2e}", d / e))
            );
            last = Some(e);
            last_change = change;
        }
    }
}

/// Energy of the second cycle of an out-of-phase harmonic history (Hertz, 200 cells: P 1200 ± 200,
/// Q ± 250 at 90°, σ ± 20 MPa at 45°) whose increments follow the polyline of `steps` points per
/// cycle, each chord cut into `cut` equal increments.
fn out_of_phase_energy(c: &Contact, steps: usize, cut: usize) -> f64 {
    let harmonic = |name: &str, mean: f64, amplitude: f64, phase: f64| {
        Harmonic::new(name, mean, amplitude, phase).unwrap()
    };
    let h = History::harmonic(
        harmonic("normal", 1200.0, 200.0, 0.0),
        harmonic("shear", 0.0, 250.0, 90.0),
        harmonic("bulk", 0.0, 20.0, 45.0),
        2,
        steps,
        10,
    )
    .unwrap();
    let points: Vec<[f64; 3]> = h
        .loads()
        .iter()
        .map(|l| [l.normal(), l.shear(), l.bulk()])
        .collect();
    let mut rows = points[..10].to_vec();
    for chord in points[9..].windows(2) {
        rows.extend((1..=cut).map(|j| {
            let t = j as f64 / cut as f64;
            [0, 1, 2].map(|m| chord[0][m] + (chord[1][m] - chord[0][m]) * t)
        }));
    }
    let mut energy = Vec::new();
    march(
        c,
        &History::from_rows(&rows).unwrap(),
        &MarchOptions::default().with_cells(200).unwrap(),
        |s, _| energy.push(s.energy),
    )
    .unwrap();
    let n = energy.len();
    energy[n - 1] - energy[n - 1 - steps * cut]
}

#[test]
#[ignore = "long convergence study; run with --ignored (see docs/convergence.md)"]
fn energy_per_cycle_out_of_phase() {
    // A harmonic history adds a second time error, the chords between its samples, which the
    // energy rule cannot remove. Cutting every chord into 64 increments keeps the load path and
    // leaves the energy rule's own error: this table.
    let c = contact(Profile::hertz(RADIUS).unwrap());
    println!("\nOut-of-phase harmonic history, Hertz, 200 cells: the energy rule's error (same polyline, each chord cut in 64)");
    println!(
        "| steps per cycle | energy per cycle | error / 64-times-cut polyline | observed order |"
    );
    println!("|---|---|---|---|");
    let mut previous: Option<f64> = None;
    for steps in [40, 80, 160, 320] {
        let (coarse, fine) = (
            out_of_phase_energy(&c, steps, 1),
            out_of_phase_energy(&c, steps, 64),
        );
        let err = (coarse - fine).abs();
        let order = previous.map_or(String::from("-"), |p| format!("{:.2}", (p / err).log2()));
        println!(
            "| {steps} | {coarse:.10e} | {:+.2e} | {order} |",
            (coarse - fine) / fine
        );
        previous = Some(err);
        // Measured 1.2e-5 at most; the previous rule gave 1.1e-3 at 40 steps per cycle.
        assert!(
            err < 5e-5 * fine,
            "energy rule error {err:e} at {steps} steps per cycle"
        );
    }
}

/// The next number in [0, 1) of a linear congruential sequence (Knuth's MMIX constants).
fn lcg(seed: &mut u64) -> f64 {
    *seed = seed
        .wrapping_mul(6364136223846793005)
        .wrapping_add(1442695040888963407);
    (*seed >> 11) as f64 / (1u64 << 53) as f64
}

/// The traction after every increment at `cells` cells, with or without located boundaries.
fn tractions(c: &Contact, rows: &[[f64; 3]], cells: usize, located: bool) -> Vec<Vec<f64>> {
    let options = MarchOptions::default()
        .with_cells(cells)
        .unwrap()
        .with_sub_cell_boundaries(located)
        .unwrap();
    let mut out = Vec::new();
    march(c, &History::from_rows(rows).unwrap(), &options, |_, f| {
        out.push(f.traction.to_vec())
    })
    .unwrap();
    out
}

#[cfg(feature = "sub-cell")]
#[test]
#[ignore = "long convergence study; run with --ignored (see docs/convergence.md)"]
fn located_boundaries_off_mindlins_line() {
    // Constant P, bulk stress and Q on paths where Mindlin's memory may not hold, at 400, 1200
    // and 3600 cells against the located march at 10800: odd ratios, so every coarse centre is
    // a fine one and the tractions compare at the same points (the contact edge's partly loaded
    // cell and its neighbours below 2% of p0 left out).
    let c = contact(Profile::hertz(RADIUS).unwrap());
    let a = closed_form::hertz_half_width(c.compliance().value(), RADIUS, 1000.0);
    let p0 = closed_form::hertz_pressure(c.compliance().value(), RADIUS, a, 0.0);
    let f_p0 = c.friction().value() * p0;
    let mut seed = 5u64;
    let reversals = |seed: &mut u64, bulk: &dyn Fn(&mut u64, f64) -> f64| -> Vec<[f64; 2]> {
        (0..30)
            .map(|k| {
                let q = if k % 2 == 0 { 1.0 } else { -1.0 } * (100.0 + 200.0 * lcg(seed));
                [q, bulk(seed, q)]
            })
            .collect()
    };
    let proportional = reversals(&mut seed, &|_, q| 0.2 * q);
    let independent = reversals(&mut seed, &|s, _| 150.0 * (2.0 * lcg(s) - 1.0));
    let mut alone = vec![[200.0, 0.0]];
    for _ in 0..3 {
        alone.extend([[200.0, 150.0], [200.0, -150.0], [200.0, 0.0]]);
    }
    let bent = [
        [200.0, 0.0],
        [200.0, 60.0],
        [260.0, 60.0],
        [100.0, 100.0],
        [100.0, 0.0],
        [250.0, -50.0],
    ];
    let (nested, square) = (nested_loops_bulk_stepped(), square_path(10));
    println!("\nLocated boundaries off Mindlin's line: largest (median) error over the increments against the located march at 10800 cells, f p0, located / cell level");
    println!("| history | 400 cells | 1200 cells | 3600 cells |");
    println!("|---|---|---|---|");
    for (name, targets, steps) in [
        ("bulk stress 0.2 Q, random Q", &proportional[..], 10),
        ("bulk stress independent of Q, random", &independent[..], 10),
        ("bulk stress cycled alone at constant Q", &alone[..], 10),
        (
            "a bent path (Q, then bulk stress, then both)",
            &bent[..],
            10,
        ),
        ("20 nested loops, bulk stress stepped", &nested[..], 4),
        ("a square in (Q, bulk stress), ten times", &square[..], 6),
    ] {
        let rows = ramps(targets, steps);
        let fine = tractions(&c, &rows, 10800, true);
        let pressure = |i: usize, cells: usize| {
            let x = (i as f64 + 0.5) * 2.0 / cells as f64 - 1.0;
            (1.0 - x * x).max(0.0).sqrt()
        };
        let mut line = format!("| {name} |");
        let mut previous = f64::INFINITY;
        for cells in [400, 1200, 3600] {
            let r = 10800 / cells;
            let errors = |coarse: &[Vec<f64>]| -> (f64, f64) {
                let mut per: Vec<f64> = coarse
                    .iter()
                    .zip(&fine)
                    .map(|(q, qf)| {
                        (0..cells)
                            .filter(|&i| pressure(i, cells) > 0.02)
                            .map(|i| (q[i] - qf[r * i + r / 2]).abs() / f_p0)
                            .fold(0.0, f64::max)
                    })
                    .collect();
                per.sort_by(f64::total_cmp);
                (per[per.len() - 1], per[per.len() / 2])
            };
            let (on, off) = (
                errors(&tractions(&c, &rows, cells, true)),
                errors(&tractions(&c, &rows, cells, false)),
            );
            line += &format!(
                " {:.1e} ({:.1e}) / {:.1e} ({:.1e}) |",
                on.0, on.1, off.0, off.1
            );
            // The located boundaries' median error is below the cell level's, and from 1200
            // cells on the largest too (at 400 cells an emerging stick zone five cells wide
            // leaves the located boundary 0.4 cells off: docs/convergence.md); their largest
            // error falls at every refinement.
            assert!(
                on.1 < off.1 && (cells < 1200 || on.0 < off.0) && on.0 < previous,
                "{name}, {cells} cells: located {on:?} against the cell level's {off:?}"
            );
            previous = on.0;
        }
        println!("{line}");
    }
}
