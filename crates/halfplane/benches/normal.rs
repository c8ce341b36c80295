//! The normal solve with a moment (`Contact::normal_contact`: ends, rotation, K_N at both edges)
//! against the symmetric solve of the same profile (`Contact::half_width` then
//! `Contact::normal_intensity`: the same outputs for M = 0), at P = 1000 N/mm on the reference
//! material. Run: `cargo bench -p halfplane --bench normal`.

use divan::black_box;
use halfplane::reference::{self, contact};
use halfplane::{Contact, Profile};

fn main() {
    divan::main();
}

const NORMAL: f64 = 1000.0;

fn profiles() -> [(&'static str, Contact); 4] {
    [
        ("hertz", reference::hertz()),
        ("flat_rounded", reference::flat_rounded()),
        (
            "power_law_2.5",
            contact(Profile::power_law(0.01, 2.5).unwrap()),
        ),
        (
            "table_41",
            contact(reference::flat_rounded_table(41).unwrap()),
        ),
    ]
}

fn pick(name: &str) -> Contact {
    profiles()
        .into_iter()
        .find(|(n, _)| *n == name)
        .map(|(_, c)| c)
        .unwrap()
}

const NAMES: [&str; 4] = ["hertz", "flat_rounded", "power_law_2.5", "table_41"];

#[divan::bench(args = NAMES)]
fn symmetric(b: divan::Bencher, name: &str) {
    let c = pick(name);
    b.bench(|| {
        let a = black_box(&c).half_width(black_box(NORMAL)).unwrap();
        black_box(c.normal_intensity(a).unwrap())
    });
}

/// M = 0: the general route on the symmetric contact.
#[divan::bench(args = NAMES)]
fn moment_zero(b: divan::Bencher, name: &str) {
    let c = pick(name);
    b.bench(|| {
        black_box(
            black_box(&c)
                .normal_contact(black_box(NORMAL), 0.0)
                .unwrap(),
        )
    });
}

/// M = 300 N·mm/mm (centroid at x = 0.3 mm, both edges on the arcs of the flat-rounded pad).
#[divan::bench(args = NAMES)]
fn moment(b: divan::Bencher, name: &str) {
    let c = pick(name);
    b.bench(|| {
        black_box(
            black_box(&c)
                .normal_contact(black_box(NORMAL), 300.0)
                .unwrap(),
        )
    });
}

/// The flat-rounded pad with unequal radii (20 and 80 mm), M = 300.
#[divan::bench]
fn moment_unequal_radii(b: divan::Bencher) {
    let c = contact(Profile::flat_rounded_asymmetric(0.3, 20.0, 80.0).unwrap());
    b.bench(|| {
        black_box(
            black_box(&c)
                .normal_contact(black_box(NORMAL), 300.0)
                .unwrap(),
        )
    });
}
