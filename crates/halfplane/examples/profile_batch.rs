//! Solves batch rows one after another, for profiling the per-row path of `steady_batch`:
//! `valgrind --tool=callgrind target/release/examples/profile_batch KIND ROWS` with KIND hertz |
//! flat-rounded. Rows vary as the Python benchmark's do (a fixed pseudo-random sequence).
use halfplane::batch::{ProfileKind, SteadyRow};
use halfplane::SteadyOptions;

fn main() {
    let mut args = std::env::args().skip(1);
    let kind = args.next().unwrap_or_else(|| "hertz".into());
    let rows: usize = args.next().and_then(|n| n.parse().ok()).unwrap_or(100_000);
    let profile = match kind.as_str() {
        "flat-rounded" => ProfileKind::FlatRounded,
        _ => ProfileKind::Hertz,
    };
    // A linear congruential sequence in [0, 1): no dependency, the same rows every run.
    let mut state = 12345u64;
    let mut uniform = move |lo: f64, hi: f64| {
        state = state
            .wrapping_mul(6364136223846793005)
            .wrapping_add(1442695040888963407);
        lo + (hi - lo) * ((state >> 11) as f64 / (1u64 << 53) as f64)
    };
    let options = SteadyOptions::default();
    let (mut solved, mut sum) = (0usize, 0.0);
    for _ in 0..rows {
        let (q, s) = (uniform(100.0, 400.0), uniform(0.0, 30.0));
        let flat = match profile {
            ProfileKind::FlatRounded => uniform(0.1, 0.5),
            _ => f64::NAN,
        };
        let row = SteadyRow {
            youngs_modulus: uniform(1e5, 2.1e5),
            poisson_ratio: 0.3,
            friction: uniform(0.4, 0.8),
            profile,
            shape: [uniform(20.0, 80.0), flat, f64::NAN, f64::NAN],
            point1: [uniform(800.0, 1200.0), -q, -s],
            point2: [uniform(800.0, 1400.0), q, s],
            moment: [0.0, 0.0],
        };
        if let Ok(summary) = row.steady_summary(&options) {
            solved += 1;
            sum += summary.numbers()[2];
        }
    }
    println!("{solved} of {rows} solved, sum of a1 {sum}");
}
