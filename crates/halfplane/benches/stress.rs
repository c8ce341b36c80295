//! Subsurface stresses (`stress::field`) from the 1000-cell traction of a marched increment, and a
//! whole fatigue run (`fatigue::analyse`: march, stress history on a 100 x 50 grid over a
//! 120-increment cycle, critical-plane search), as issue 10 sets them.
//! Run: `cargo bench -p halfplane --bench stress`.

use divan::black_box;
use halfplane::fatigue::{self, FatigueConstants, FatigueGrid};
use halfplane::history::{History, Ramp};
use halfplane::march::MarchOptions;
use halfplane::stress::{self, Traction};
use halfplane::{reference, LoadPoint};

fn main() {
    divan::main();
}

/// The reference cycle's last increment on `cells` cells: a partial-slip Hertz traction.
fn traction(cells: usize) -> (Traction, f64) {
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
fn grid(n: usize, a: f64) -> (Vec<f64>, Vec<f64>) {
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

/// `stress::field` at `points` grid points from a 1000-cell traction.
#[divan::bench(args = [10_000, 100_000, 1_000_000], sample_count = 3, sample_size = 1)]
fn field_1000_cells(b: divan::Bencher, points: usize) {
    let (t, a) = traction(1000);
    let (x, z) = grid(points, a);
    let m = reference::material();
    b.bench(|| black_box(stress::field(black_box(&t), 100.0, &m, &x, &z).unwrap()));
}

/// The direct sum over every node (`stress::field_direct`), the reference: scale by points.
#[divan::bench(args = [10_000], sample_count = 3, sample_size = 1)]
fn field_direct_1000_cells(b: divan::Bencher, points: usize) {
    let (t, a) = traction(1000);
    let (x, z) = grid(points, a);
    let m = reference::material();
    b.bench(|| black_box(stress::field_direct(black_box(&t), 100.0, &m, &x, &z).unwrap()));
}

/// The fatigue example's loading (P = 1000 N/mm, Q and bulk tension in phase between
/// -(300, 60) and (300, 60)) with 60 increments per half: a 120-increment steady cycle.
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
    black_box(r);
}

/// A whole fatigue run on a 100 x 50 grid over a 120-increment cycle.
#[divan::bench(args = [400, 1000], sample_count = 3, sample_size = 1)]
fn fatigue_100x50_grid(b: divan::Bencher, cells: usize) {
    b.bench(|| fatigue_run(cells));
}
