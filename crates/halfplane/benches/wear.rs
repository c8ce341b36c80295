//! Fretting wear (issue 22's speed targets, one core): 1e6 cycles of the Hertz partial-slip
//! case (`examples/wear-partial-slip.toml`: P = 1000, Q = +-300, 20 steps per half, Archard
//! k = 3e-8) at 400 cells, and gross sliding (`examples/wear-sliding.toml`: P = 1000, 0.02 mm
//! each way, 10 steps per half) over 1e5 and 1e6 cycles at 400 cells (the grid 8 times the
//! unworn contact, room for the 1e6-cycle scar).
//! Run: `cargo bench -p halfplane --bench wear`.

use divan::black_box;
use halfplane::history::{History, Ramp};
use halfplane::march::{MarchOptions, Worn};
use halfplane::reference;
use halfplane::wear::{self, Law, WearOptions};
use halfplane::LoadPoint;

fn main() {
    divan::main();
}

fn options() -> MarchOptions {
    MarchOptions::default().with_cells(400).unwrap()
}

#[divan::bench(sample_count = 3, sample_size = 1)]
fn partial_slip_1e6_cycles(b: divan::Bencher) {
    let a = LoadPoint::new("a", 1000.0, -300.0, 0.0).unwrap();
    let c = LoadPoint::new("b", 1000.0, 300.0, 0.0).unwrap();
    let history = History::in_phase(a, c, 1, 20, Ramp::NormalFirst, 10).unwrap();
    let law = WearOptions::logarithmic(Law::Archard, 3e-8, 1_000_000, 7).unwrap();
    b.bench(|| {
        let mut worn = Worn::new(&reference::hertz(), &history, &options(), 2.0).unwrap();
        black_box(wear::run(&mut worn, black_box(&law), |_| {}).unwrap());
    });
}

#[divan::bench(args = [100_000, 1_000_000], sample_count = 1, sample_size = 1)]
fn gross_sliding(b: divan::Bencher, cycles: u64) {
    let load = LoadPoint::new("load", 1000.0, 0.0, 0.0).unwrap();
    let law = WearOptions::logarithmic(Law::Archard, 3e-8, cycles, 7).unwrap();
    b.bench(|| {
        let contact = reference::hertz();
        let mut worn = Worn::sliding(&contact, load, 0.02, 10, 10, &options(), 8.0).unwrap();
        black_box(wear::run(&mut worn, black_box(&law), |_| {}).unwrap());
    });
}
