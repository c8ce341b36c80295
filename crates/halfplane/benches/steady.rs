//! One steady-state solve (`steady::analyse`: both contact half-widths, regime checks and the
//! permanent stick zone) per profile, on the reference cycle.
//! Run: `cargo bench -p halfplane --bench steady`.

use divan::black_box;
use halfplane::reference::{self, contact};
use halfplane::steady::{self, Method, SteadyOptions};
use halfplane::{Contact, Profile};

fn main() {
    divan::main();
}

fn solve(c: &Contact, options: &SteadyOptions) {
    let s = steady::analyse(black_box(c), black_box(&reference::cycle()), options).unwrap();
    black_box(s);
}

#[divan::bench]
fn hertz_closed_form(b: divan::Bencher) {
    let c = reference::hertz();
    b.bench(|| solve(&c, &SteadyOptions::default()));
}

#[divan::bench]
fn hertz_implicit(b: divan::Bencher) {
    let c = reference::hertz();
    let options = SteadyOptions::default().with_method(Method::Implicit);
    b.bench(|| solve(&c, &options));
}

#[divan::bench]
fn flat_rounded(b: divan::Bencher) {
    let c = reference::flat_rounded();
    b.bench(|| solve(&c, &SteadyOptions::default()));
}

#[divan::bench(args = [1.5, 2.5, 3.0])]
fn power_law(b: divan::Bencher, exponent: f64) {
    let c = contact(Profile::power_law(0.01, exponent).unwrap());
    b.bench(|| solve(&c, &SteadyOptions::default()));
}

#[divan::bench(args = [41, 401])]
fn tabulated(b: divan::Bencher, rows: usize) {
    // The bundled example's table at `rows` = 41: flat-rounded b = 0.3, R = 50 on [0, 2].
    let c = contact(reference::flat_rounded_table(rows).unwrap());
    b.bench(|| solve(&c, &SteadyOptions::default()));
}
