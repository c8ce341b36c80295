//! One steady-state solve (`steady::analyse`: both contact half-widths, regime checks and the
//! permanent stick zone) per profile, on THEORY.md's example cycle.
//! Run: `cargo bench -p halfplane --bench steady`.

use divan::black_box;
use halfplane::steady::{self, Method, SteadyOptions};
use halfplane::{Contact, Cycle, Friction, LoadPoint, Material, Profile};

fn main() {
    divan::main();
}

fn contact(profile: Profile) -> Contact {
    Contact::new(
        profile,
        Material::new(200_000.0, 0.3).unwrap(),
        Friction::new(0.6).unwrap(),
    )
}

fn cycle() -> Cycle {
    Cycle::new(
        LoadPoint::new("p1", 1000.0, -250.0, -20.0).unwrap(),
        LoadPoint::new("p2", 1400.0, 250.0, 20.0).unwrap(),
    )
}

/// The bundled example's table (`rows` = 41): flat-rounded b = 0.3, R = 50 on [0, 2], kink at 0.3.
fn table(rows: usize) -> Profile {
    let n = rows - 1;
    let x: Vec<f64> = (0..=n).map(|i| 2.0 * i as f64 / n as f64).collect();
    let g = x
        .iter()
        .map(|&x: &f64| {
            if x <= 0.3 {
                0.0
            } else {
                (x - 0.3).powi(2) / 100.0
            }
        })
        .collect();
    Profile::tabulated(x, g, vec![0.3]).unwrap()
}

fn solve(c: &Contact, options: &SteadyOptions) {
    let s = steady::analyse(black_box(c), black_box(&cycle()), options).unwrap();
    black_box(s);
}

#[divan::bench]
fn hertz_closed_form(b: divan::Bencher) {
    let c = contact(Profile::hertz(50.0).unwrap());
    b.bench(|| solve(&c, &SteadyOptions::default()));
}

#[divan::bench]
fn hertz_implicit(b: divan::Bencher) {
    let c = contact(Profile::hertz(50.0).unwrap());
    let options = SteadyOptions {
        method: Method::Implicit,
        ..Default::default()
    };
    b.bench(|| solve(&c, &options));
}

#[divan::bench]
fn flat_rounded(b: divan::Bencher) {
    let c = contact(Profile::flat_rounded(0.3, 50.0).unwrap());
    b.bench(|| solve(&c, &SteadyOptions::default()));
}

#[divan::bench(args = [1.5, 2.5, 3.0])]
fn power_law(b: divan::Bencher, exponent: f64) {
    let c = contact(Profile::power_law(0.01, exponent).unwrap());
    b.bench(|| solve(&c, &SteadyOptions::default()));
}

#[divan::bench(args = [41, 401])]
fn tabulated(b: divan::Bencher, rows: usize) {
    let c = contact(table(rows));
    b.bench(|| solve(&c, &SteadyOptions::default()));
}
