//! The loadings shared by the stress benchmark (`benches/stress.rs`) and its profiling example
//! (`examples/profile_stress.rs`), so that callgrind profiles exactly what the benchmark times.

use halfplane::fatigue::{FatigueConstants, FatigueGrid};
use halfplane::history::{History, Ramp};
use halfplane::march::MarchOptions;
use halfplane::stress::{self, Traction};
use halfplane::{reference, LoadPoint};

/// The reference cycle's last increment on `cells` cells: a partial-slip Hertz traction, and the
/// contact half-width.
pub fn traction(cells: usize) -> (Traction, f64) {
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
    let options = MarchOptions::default().with_cells(cells).unwrap();
    let mut kept = stress::marched(&reference::hertz(), &history, &options, &[last]).unwrap();
    let t = kept.pop().unwrap();
    (t.traction, t.half_width)
}

/// `n` points on a square grid over |x| <= 1.5 a, 0 <= z <= a (the surface row included).
pub fn grid(n: usize, a: f64) -> (Vec<f64>, Vec<f64>) {
    let side = (n as f64).sqrt().round() as usize;
    let mut x = Vec::with_capacity(side * side);
    let mut z = Vec::with_capacity(side * side);
    for j in 0..side {
        for i in 0..side {
            x.push(a * (-1.5 + 3.0 * i as f64 / (side - 1) as f64));
            z.push(a * j as f64 / (side - 1) as f64);
        }
    }
    (x, z)
}

/// The fatigue example's run: loading (P = 1000 N/mm, Q and bulk tension in phase between
/// -(300, 60) and (300, 60)) with 60 increments per half, a 120-increment steady cycle; its
/// material constants (illustrative, high-strength steel); the 100 x 50 grid.
pub fn fatigue_case() -> (History, FatigueConstants, FatigueGrid) {
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
    (
        history,
        constants,
        FatigueGrid::new(100, 50, 1.5, 1.0).unwrap(),
    )
}
