//! Will the crack grow (issue 21): one crack length over a 120-increment steady cycle (assembly,
//! the uncracked stress at the collocation points of every increment, face contact through the
//! cycle), the two stress routes for those points, and a whole 30-length analysis including the
//! march.
//! Run: `cargo bench -p halfplane --bench crack`.

use divan::black_box;
use halfplane::crack::{self, CrackOptions, CrackSolver, Position};
use halfplane::fatigue::FatigueConstants;
use halfplane::{reference, stress};

#[path = "support/crack_cases.rs"]
mod crack_cases;
use crack_cases::{history, loads, options};

fn main() {
    divan::main();
}

/// One length (0.05 mm at the trailing edge) over the 120 kept increments, frictionless faces and
/// f = 0.3: assembly, the uncracked stress at the collocation points of every increment
/// (`stress::fields`) and face contact through the cycle, as `crack::analyse` does per length.
#[divan::bench(args = [0.0, 0.3], sample_count = 10, sample_size = 1)]
fn one_length_120_increments(b: divan::Bencher, friction: f64) {
    let h = history();
    let steps: Vec<usize> = (h.loads().len() - 119..=h.loads().len()).collect();
    let contact = reference::hertz();
    let kept = stress::marched(&contact, &h, &options(), &steps).unwrap();
    let a = kept[0].half_width;
    let c = crack::Crack::new(-a, 0.0, 0.05).unwrap();
    let increments: Vec<(&stress::Traction, f64)> =
        kept.iter().map(|k| (&k.traction, k.load.bulk())).collect();
    b.bench(|| {
        let s = CrackSolver::new(&c, &contact.material(), 40).unwrap();
        let loads = loads(&s, &increments, &contact.material());
        black_box(s.cycle(&loads, friction).unwrap())
    });
}

/// The uncracked stress at one length's 40 collocation points under the 120 increments, by the
/// two routes: `stress::field` once per increment (the fast method's set-up each time, the route
/// the crack analysis took before) and `stress::fields` (the logarithms once for all increments).
#[divan::bench(args = ["field per increment", "fields"], sample_count = 10, sample_size = 1)]
fn uncracked_stress_40_points(b: divan::Bencher, route: &str) {
    let h = history();
    let steps: Vec<usize> = (h.loads().len() - 119..=h.loads().len()).collect();
    let contact = reference::hertz();
    let m = contact.material();
    let kept = stress::marched(&contact, &h, &options(), &steps).unwrap();
    let c = crack::Crack::new(-kept[0].half_width, 0.0, 0.05).unwrap();
    let s = CrackSolver::new(&c, &m, 40).unwrap();
    let increments: Vec<(&stress::Traction, f64)> =
        kept.iter().map(|k| (&k.traction, k.load.bulk())).collect();
    b.bench(|| match route {
        "fields" => black_box(stress::fields(&increments, &m, s.x(), s.z()).unwrap()),
        _ => black_box(
            increments
                .iter()
                .map(|(t, bulk)| stress::field(t, *bulk, &m, s.x(), s.z()).unwrap())
                .collect(),
        ),
    });
}

/// `crack::analyse` over 30 lengths, march included.
#[divan::bench(sample_count = 5, sample_size = 1)]
fn analyse_30_lengths(b: divan::Bencher) {
    let h = history();
    let constants = FatigueConstants::default()
        .with_threshold(160.0)
        .and_then(|c| c.with_endurance_range(700.0))
        .unwrap();
    let lengths: Vec<f64> = (0..30).map(|i| 0.002 * 1.19f64.powi(i)).collect();
    let opts = CrackOptions::new(Position::LeftEdge, 0.0, lengths, 0.0).unwrap();
    let contact = reference::hertz();
    b.bench(|| black_box(crack::analyse(&contact, &h, &options(), &constants, &opts).unwrap()));
}
