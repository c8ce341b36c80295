//! The cost of a moment: the steady solve and a march of the same profile and cycle with and
//! without a moment (issue 19's targets: steady within 2x of the symmetric solve, march within
//! 1.2x). The cycle is the reference one; with a moment, M = 50 at point 1 and 120 at point 2
//! (N mm/mm), so that the centroid moves along the cycle and every route of the moment's analysis
//! runs (the rotation-rate bounds, the nine contacts along the segment, independent ends in the
//! march).
//! Run: `cargo bench -p halfplane --bench moment`.

use divan::black_box;
use halfplane::history::{History, Ramp};
use halfplane::march::{march, MarchOptions};
use halfplane::reference::{self, contact};
use halfplane::steady::{self, SteadyOptions};
use halfplane::{Contact, Cycle, Profile};

fn main() {
    divan::main();
}

const PROFILES: [&str; 4] = ["hertz", "flat-rounded", "power-law", "table-41"];

fn profile(name: &str) -> Contact {
    contact(match name {
        "hertz" => Profile::hertz(reference::RADIUS).unwrap(),
        "flat-rounded" => Profile::flat_rounded(0.3, reference::RADIUS).unwrap(),
        "power-law" => Profile::power_law(0.01, 2.5).unwrap(),
        _ => reference::flat_rounded_table(41).unwrap(),
    })
}

/// The reference cycle, with the moments `m1`, `m2`.
fn cycle(m1: f64, m2: f64) -> Cycle {
    let (p1, p2) = reference::cycle().as_given();
    Cycle::new(
        p1.with_moment("bench", m1).unwrap(),
        p2.with_moment("bench", m2).unwrap(),
    )
}

fn solve(c: &Contact, cycle: &Cycle) {
    let s = steady::analyse(black_box(c), black_box(cycle), &SteadyOptions::default()).unwrap();
    black_box(s);
}

#[divan::bench(args = PROFILES)]
fn steady_without_moment(b: divan::Bencher, name: &str) {
    let (c, cycle) = (profile(name), cycle(0.0, 0.0));
    b.bench(|| solve(&c, &cycle));
}

#[divan::bench(args = PROFILES)]
fn steady_with_moment(b: divan::Bencher, name: &str) {
    let (c, cycle) = (profile(name), cycle(50.0, 120.0));
    b.bench(|| solve(&c, &cycle));
}

#[divan::bench]
fn steady_unequal_radii(b: divan::Bencher) {
    let c = contact(Profile::flat_rounded_asymmetric(0.3, 40.0, 70.0).unwrap());
    let cycle = cycle(50.0, 120.0);
    b.bench(|| solve(&c, &cycle));
}

/// Two in-phase cycles of 30 increments per half after a 10-increment normal-first ramp, at 400
/// cells.
fn march_cycles(c: &Contact, cycle: &Cycle) {
    let (p1, p2) = cycle.as_given();
    let history = History::in_phase(p1, p2, 2, 30, Ramp::NormalFirst, 10).unwrap();
    let options = MarchOptions::default().with_cells(400).unwrap();
    let r = march(black_box(c), &history, &options, |_, _| {}).unwrap();
    black_box(r);
}

#[divan::bench(args = ["hertz", "flat-rounded"], sample_count = 10)]
fn march_without_moment(b: divan::Bencher, name: &str) {
    let (c, cycle) = (profile(name), cycle(0.0, 0.0));
    b.bench(|| march_cycles(&c, &cycle));
}

#[divan::bench(args = ["hertz", "flat-rounded"], sample_count = 10)]
fn march_with_moment(b: divan::Bencher, name: &str) {
    let (c, cycle) = (profile(name), cycle(50.0, 120.0));
    b.bench(|| march_cycles(&c, &cycle));
}
