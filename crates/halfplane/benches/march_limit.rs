//! The march at its limit (issue 20): examples/march-cycle.toml (the reference cycle, 300
//! increments, Hertz) at 400-6400 cells and a two-increment Cattaneo load (Hertz, P = 1000 pressed
//! in one increment, then Q = 0.5 f P in one) at 6400-25600 cells.
//! Run: `cargo bench -p halfplane --bench march_limit`; active-set passes per case:
//! `target/release/examples/profile_march CELLS [cattaneo]`. `cattaneo_sub_cell` is the same load
//! with the stick-slip boundaries located inside their cells
//! (`MarchOptions::with_sub_cell_boundaries`). `fft_pair` times the FFT work under one sub-step
//! of the cycle at 6400 cells, for the floor in BENCHMARKS.md.

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

/// The FFT work under one sub-step of the cycle at 6400 cells (BENCHMARKS.md, "The floor under
/// the cycle's rules"): a forward and an inverse real FFT of length m. A stick-run solve
/// (Gohberg-Semencul) makes three such pairs at `m = 10800` (the FFT length for the mean stick
/// run of 5318 cells, at least twice its order with no prime factor beyond 5) and a kernel
/// product one pair at `m = 12800` (the grid's circulant embedding).
#[divan::bench(args = [10800, 12800])]
fn fft_pair(b: divan::Bencher, m: usize) {
    let mut planner = realfft::RealFftPlanner::<f64>::new();
    let (forward, inverse) = (planner.plan_fft_forward(m), planner.plan_fft_inverse(m));
    let mut real: Vec<f64> = (0..m).map(|k| (k as f64 * 0.37).sin()).collect();
    let mut spectrum = forward.make_output_vec();
    let mut scratch = forward.make_scratch_vec();
    scratch.resize(
        scratch.len().max(inverse.get_scratch_len()),
        Default::default(),
    );
    b.bench_local(|| {
        forward
            .process_with_scratch(&mut real, &mut spectrum, &mut scratch)
            .unwrap();
        spectrum[0].im = 0.0;
        spectrum[m / 2].im = 0.0;
        inverse
            .process_with_scratch(&mut spectrum, &mut real, &mut scratch)
            .unwrap();
        real.iter_mut().for_each(|v| *v /= m as f64);
    });
}
