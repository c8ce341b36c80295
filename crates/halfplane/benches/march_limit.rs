//! The march at its limit (issue 20): examples/march-cycle.toml (the reference cycle, 300
//! increments, Hertz) at 400-6400 cells and a two-increment Cattaneo load (Hertz, P = 1000 pressed
//! in one increment, then Q = 0.5 f P in one) at 6400-25600 cells.
//! Run: `cargo bench -p halfplane --bench march_limit`; active-set passes per case:
//! `target/release/examples/profile_march CELLS [cattaneo]`. `cattaneo_sub_cell` is the same load
//! with the stick-slip boundaries located inside their cells
//! (`MarchOptions::with_sub_cell_boundaries`).

use divan::black_box;
use halfplane::history::{History, Ramp};
use halfplane::march::{march, MarchOptions};
use halfplane::reference;

fn main() {
    divan::main();
}

fn run(history: &History, cells: usize) {
    run_with(history, MarchOptions::default().with_cells(cells).unwrap());
}

fn run_with(history: &History, options: MarchOptions) {
    let r = march(
        black_box(&reference::hertz()),
        black_box(history),
        &options,
        |_, _| {},
    )
    .unwrap();
    black_box(r);
}

fn cattaneo() -> History {
    let f = reference::hertz().friction().value();
    History::from_rows(&[[1000.0, 0.0, 0.0], [1000.0, 0.5 * f * 1000.0, 0.0]]).unwrap()
}

#[divan::bench(args = [400, 800, 1600, 3200, 6400], sample_count = 3, sample_size = 1)]
fn march_cycle(b: divan::Bencher, cells: usize) {
    let (p1, p2) = (reference::point1(), reference::point2());
    let history = History::in_phase(p1, p2, 3, 45, Ramp::NormalFirst, 15).unwrap();
    b.bench(|| run(&history, cells));
}

#[divan::bench(args = [400, 1600, 6400, 12800, 25600], sample_count = 3, sample_size = 1)]
fn cattaneo_two_increments(b: divan::Bencher, cells: usize) {
    let history = cattaneo();
    b.bench(|| run(&history, cells));
}

#[divan::bench(args = [400, 1600, 6400, 25600], sample_count = 3, sample_size = 1)]
fn cattaneo_sub_cell(b: divan::Bencher, cells: usize) {
    let history = cattaneo();
    let options = MarchOptions::default()
        .with_cells(cells)
        .unwrap()
        .with_sub_cell_boundaries(true)
        .unwrap();
    b.bench(|| run_with(&history, options));
}
