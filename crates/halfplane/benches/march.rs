//! Time marching through a ramp and three in-phase cycles (the reference cycle of docs/theory.md: 30 ramp + 270
//! cycle increments = 300), by cell count and linear solver.
//! Run: `cargo bench -p halfplane --bench march`.

use divan::black_box;
use halfplane::history::{History, Ramp};
use halfplane::march::{march, LinearSolver, MarchOptions};
use halfplane::{reference, Contact};

fn main() {
    divan::main();
}

fn case(contact: Contact) -> (Contact, History) {
    let (p1, p2) = (reference::point1(), reference::point2());
    (
        contact,
        History::in_phase(p1, p2, 3, 45, Ramp::NormalFirst, 15).unwrap(),
    )
}

fn run(contact: &Contact, history: &History, cells: usize, solver: LinearSolver) {
    let r = march(
        black_box(contact),
        black_box(history),
        &MarchOptions::default()
            .with_cells(cells)
            .unwrap()
            .with_solver(solver)
            .unwrap(),
        |_, _| {},
    )
    .unwrap();
    black_box(r);
}

#[divan::bench(args = [100, 250, 500, 1000, 2000], sample_count = 5, sample_size = 1)]
fn hertz_toeplitz(b: divan::Bencher, cells: usize) {
    let (c, h) = case(reference::hertz());
    b.bench(|| run(&c, &h, cells, LinearSolver::Toeplitz));
}

// 1000 cells takes about 2 minutes per sample (see BENCHMARKS.md); kept out of the routine run.
#[divan::bench(args = [100, 250, 500], sample_count = 3, sample_size = 1)]
fn hertz_dense(b: divan::Bencher, cells: usize) {
    let (c, h) = case(reference::hertz());
    b.bench(|| run(&c, &h, cells, LinearSolver::Dense));
}

#[divan::bench(args = [1000], sample_count = 5, sample_size = 1)]
fn flat_rounded_toeplitz(b: divan::Bencher, cells: usize) {
    let (c, h) = case(reference::flat_rounded());
    b.bench(|| run(&c, &h, cells, LinearSolver::Toeplitz));
}

#[divan::bench(args = [8000], sample_count = 1, sample_size = 1)]
fn hertz_toeplitz_large(b: divan::Bencher, cells: usize) {
    let (c, h) = case(reference::hertz());
    b.bench(|| run(&c, &h, cells, LinearSolver::Toeplitz));
}
