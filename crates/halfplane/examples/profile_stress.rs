//! Evaluates the stresses of a 1000-cell marched traction once, for profiling:
//! `valgrind --tool=callgrind target/release/examples/profile_stress POINTS [direct]`
//! (points on a square grid over |x| <= 1.5 a, 0 <= z <= a), or a whole fatigue run with
//! `profile_stress fatigue CELLS` (the benchmark's 100 x 50 grid over a 120-increment cycle).
use halfplane::fatigue::{self, FatigueConstants, FatigueGrid};
use halfplane::history::{History, Ramp};
use halfplane::march::MarchOptions;
use halfplane::stress;
use halfplane::{reference, LoadPoint};

fn main() {
    let args: Vec<String> = std::env::args().collect();
    let number =
        |i: usize, default: usize| args.get(i).and_then(|s| s.parse().ok()).unwrap_or(default);
    if args.get(1).map(String::as_str) == Some("fatigue") {
        fatigue_run(number(2, 400));
        return;
    }
    let points = number(1, 100_000);
    let history = History::in_phase(
        reference::point1(),
        reference::point2(),
        1,
        20,
        Ramp::NormalFirst,
        10,
    )
    .unwrap();
    let last = history.loads().len();
    let options = MarchOptions::default().with_cells(1000).unwrap();
    let kept = stress::marched(&reference::hertz(), &history, &options, &[last]).unwrap();
    let (t, a) = (&kept[0].traction, kept[0].half_width);
    let side = (points as f64).sqrt().round() as usize;
    let (mut x, mut z) = (Vec::new(), Vec::new());
    for j in 0..side {
        for i in 0..side {
            x.push(a * (-1.5 + 3.0 * i as f64 / (side - 1) as f64));
            z.push(a * j as f64 / (side - 1) as f64);
        }
    }
    let m = reference::material();
    let f = if args.get(2).map(String::as_str) == Some("direct") {
        stress::field_direct(t, 100.0, &m, &x, &z).unwrap()
    } else {
        stress::field(t, 100.0, &m, &x, &z).unwrap()
    };
    println!("{} points, sxx[0] = {}", f.len(), f.sxx[0]);
}

fn fatigue_run(cells: usize) {
    let history = History::in_phase(
        LoadPoint::new("point1", 1000.0, -300.0, -60.0).unwrap(),
        LoadPoint::new("point2", 1000.0, 300.0, 60.0).unwrap(),
        2,
        60,
        Ramp::NormalFirst,
        10,
    )
    .unwrap();
    let constants = FatigueConstants::default()
        .with_fatigue_strength(1800.0)
        .and_then(|c| c.with_fatigue_strength_exponent(-0.1))
        .and_then(|c| c.with_fatigue_ductility(0.5))
        .and_then(|c| c.with_fatigue_ductility_exponent(-0.6))
        .and_then(|c| c.with_shear_fatigue_strength(1040.0))
        .and_then(|c| c.with_shear_fatigue_ductility(0.87))
        .and_then(|c| c.with_fatemi_socie_k(0.5))
        .and_then(|c| c.with_findley_k(0.25))
        .and_then(|c| c.with_crossland_alpha(0.4))
        .and_then(|c| c.with_yield_stress(900.0))
        .and_then(|c| c.with_threshold(160.0))
        .and_then(|c| c.with_endurance_range(700.0))
        .unwrap();
    let options = MarchOptions::default().with_cells(cells).unwrap();
    let grid = FatigueGrid::new(100, 50, 1.5, 1.0).unwrap();
    let r = fatigue::analyse(&reference::hertz(), &history, &options, &constants, &grid).unwrap();
    println!("{} parameters", r.parameters.len());
}
