//! Evaluates the stresses of a 1000-cell marched traction once, for profiling:
//! `valgrind --tool=callgrind target/release/examples/profile_stress POINTS [direct]`
//! (points on a square grid over |x| <= 1.5 a, 0 <= z <= a), or a whole fatigue run with
//! `profile_stress fatigue CELLS` (the benchmark's 100 x 50 grid over a 120-increment cycle).
//! The loadings are the stress benchmark's own (`benches/support/stress_cases.rs`).
use halfplane::fatigue;
use halfplane::march::MarchOptions;
use halfplane::{reference, stress};

#[path = "../benches/support/stress_cases.rs"]
mod stress_cases;
use stress_cases::{fatigue_case, grid, traction};

fn main() {
    let args: Vec<String> = std::env::args().collect();
    let number =
        |i: usize, default: usize| args.get(i).and_then(|s| s.parse().ok()).unwrap_or(default);
    if args.get(1).map(String::as_str) == Some("fatigue") {
        let (history, constants, grid) = fatigue_case();
        let options = MarchOptions::default().with_cells(number(2, 400)).unwrap();
        let r =
            fatigue::analyse(&reference::hertz(), &history, &options, &constants, &grid).unwrap();
        println!("{} parameters", r.parameters.len());
        return;
    }
    let (t, a) = traction(1000);
    let (x, z) = grid(number(1, 100_000), a);
    let m = reference::material();
    let f = if args.get(2).map(String::as_str) == Some("direct") {
        stress::field_direct(&t, 100.0, &m, &x, &z).unwrap()
    } else {
        stress::field(&t, 100.0, &m, &x, &z).unwrap()
    };
    println!("{} points, sxx[0] = {}", f.len(), f.sxx[0]);
}
