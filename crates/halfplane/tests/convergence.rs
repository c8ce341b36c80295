//! Convergence study of the time-marching solver (long; ignored by default):
//!
//! `cargo test --release -p halfplane --test convergence -- --ignored --nocapture`
//!
//! Prints the tables recorded in `docs/convergence.md` and asserts that the errors fall.

mod common;
use common::*;
use halfplane::history::{History, Ramp};
use halfplane::march::{march, MarchOptions};
use halfplane::steady::{analyse, SteadyOptions};
use halfplane::{closed_form, Profile};

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

/// Energy per cycle (the second of two) of the paper's Hertz cycle, proportional ramp.
fn cycle_energy(c: &halfplane::Contact, cells: usize, steps_per_half: usize) -> f64 {
    let (p1, p2) = theory_cycle().as_given();
    let history = History::in_phase(p1, p2, 2, steps_per_half, Ramp::Proportional, 10).unwrap();
    let r = march(
        c,
        &history,
        &MarchOptions::default().with_cells(cells).unwrap(),
        |_, _| {},
    )
    .unwrap();
    r.cycles[1].energy
}

#[test]
#[ignore = "long convergence study; run with --ignored (see docs/convergence.md)"]
fn energy_per_cycle_in_time_and_in_space() {
    // Time and space refined separately: converging in one at a fixed other proves nothing.
    for (name, profile) in [
        ("Hertz", Profile::hertz(RADIUS).unwrap()),
        (
            "flat-rounded b = 0.3",
            Profile::flat_rounded(0.3, RADIUS).unwrap(),
        ),
    ] {
        let c = contact(profile);
        for cells in [200, 800] {
            let reference = cycle_energy(&c, cells, 2560);
            println!("\n{name}, {cells} cells: energy per cycle against steps per half (reference: 2560 steps per half, {reference:.10e})");
            println!("| steps per half | energy per cycle | error / reference | observed order |");
            println!("|---|---|---|---|");
            let mut previous: Option<f64> = None;
            for steps in [10, 20, 40, 80, 160, 320, 640, 1280] {
                let e = cycle_energy(&c, cells, steps);
                let err = (e - reference).abs();
                let order =
                    previous.map_or(String::from("-"), |p| format!("{:.2}", (p / err).log2()));
                println!(
                    "| {steps} | {e:.8e} | {:+.2e} | {order} |",
                    (e - reference) / reference
                );
                previous = Some(err);
                // The old first-order scheme was 1.3% off at 10 steps per half.
                assert!(
                    err < 2e-4 * reference,
                    "time-step error {err:e} at {steps} steps per half"
                );
            }
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
