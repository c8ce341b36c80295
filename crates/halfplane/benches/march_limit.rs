//! The march at its limit (issue 20): examples/march-cycle.toml (the reference cycle, 300
//! increments, Hertz) at 400-6400 cells and a two-increment Cattaneo load (Hertz, P = 1000 pressed
//! in one increment, then Q = 0.5 f P in one) at 6400-25600 cells.
//! Run: `cargo bench -p halfplane --bench march_limit`; active-set passes per case:
//! `target/release/examples/profile_march CELLS [cattaneo]`.

use divan::black_box;
use halfplane::history::{History, Ramp};
use halfplane::march::{march, MarchOptions};
use halfplane::reference;

fn main() {
    divan::main();
}

fn run(history: &History, cells: usize) {
    let r = march(
        black_box(&reference::hertz()),
        black_box(history),
        &MarchOptions::default().with_cells(cells).unwrap(),
        |_, _| {},
    )
    .unwrap();
    black_box(r);
}

#[divan::bench(args = [400, 800, 1600, 3200, 6400], sample_count = 3, sample_size = 1)]
fn march_cycle(b: divan::Bencher, cells: usize) {
    let (p1, p2) = (reference::point1(), reference::point2());
    let history = History::in_phase(p1, p2, 3, 45, Ramp::NormalFirst, 15).unwrap();
    b.bench(|| run(&history, cells));
}

#[divan::bench(args = [400, 1600, 6400, 12800, 25600], sample_count = 3, sample_size = 1)]
fn cattaneo_two_increments(b: divan::Bencher, cells: usize) {
    let f = reference::hertz().friction().value();
    let history =
        History::from_rows(&[[1000.0, 0.0, 0.0], [1000.0, 0.5 * f * 1000.0, 0.0]]).unwrap();
    b.bench(|| run(&history, cells));
}
