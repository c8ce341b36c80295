//! Subsurface stresses (`stress::field`) from the 1000-cell traction of a marched increment, and a
//! whole fatigue run (`fatigue::analyse`: march, stress history on a 100 x 50 grid over a
//! 120-increment cycle, critical-plane search), as issue 10 sets them.
//! Run: `cargo bench -p halfplane --bench stress`.

use divan::black_box;
use halfplane::fatigue;
use halfplane::march::MarchOptions;
use halfplane::{reference, stress};

#[path = "support/stress_cases.rs"]
mod stress_cases;
use stress_cases::{fatigue_case, grid, traction};

fn main() {
    divan::main();
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

/// A whole fatigue run on a 100 x 50 grid over a 120-increment cycle.
#[divan::bench(args = [400, 1000], sample_count = 3, sample_size = 1)]
fn fatigue_100x50_grid(b: divan::Bencher, cells: usize) {
    let (history, constants, grid) = fatigue_case();
    let options = MarchOptions::default().with_cells(cells).unwrap();
    b.bench(|| {
        black_box(
            fatigue::analyse(&reference::hertz(), &history, &options, &constants, &grid).unwrap(),
        )
    });
}
