//! Runs the crack benchmark's cases once, for profiling and for timing the stages:
//! `valgrind --tool=callgrind target/release/examples/profile_crack [stages|curve] [FRICTION]`
//! (`stages`: one 0.05 mm length at the trailing edge over the 120-increment cycle, each stage
//! timed; `curve`: the 30-length analysis with the march).
use halfplane::crack::{self, Crack, CrackOptions, CrackSolver, Position};
use halfplane::fatigue::FatigueConstants;
use halfplane::{reference, stress};
use std::time::Instant;

#[path = "../benches/support/crack_cases.rs"]
mod crack_cases;
use crack_cases::{history, loads, options};

fn main() {
    let args: Vec<String> = std::env::args().collect();
    let what = args.get(1).map(String::as_str).unwrap_or("stages");
    let friction: f64 = args.get(2).and_then(|s| s.parse().ok()).unwrap_or(0.0);
    let options = options();
    let contact = reference::hertz();
    let h = history();
    if what == "curve" {
        let constants = FatigueConstants::default()
            .with_threshold(160.0)
            .and_then(|c| c.with_endurance_range(700.0))
            .unwrap();
        let lengths: Vec<f64> = (0..30).map(|i| 0.002 * 1.19f64.powi(i)).collect();
        let opts = CrackOptions::new(Position::LeftEdge, 0.0, lengths, friction).unwrap();
        let t = Instant::now();
        let r = crack::analyse(&contact, &h, &options, &constants, &opts).unwrap();
        println!("{:?} in {:.3} s", r.verdict, t.elapsed().as_secs_f64());
        return;
    }
    let steps: Vec<usize> = (h.loads().len() - 119..=h.loads().len()).collect();
    let t = Instant::now();
    let kept = stress::marched(&contact, &h, &options, &steps).unwrap();
    let march = t.elapsed().as_secs_f64();
    let c = Crack::new(-kept[0].half_width, 0.0, 0.05).unwrap();
    let t = Instant::now();
    let s = CrackSolver::new(&c, &contact.material(), 40).unwrap();
    let assembly = t.elapsed().as_secs_f64();
    let t = Instant::now();
    let increments: Vec<(&stress::Traction, f64)> =
        kept.iter().map(|k| (&k.traction, k.load.bulk())).collect();
    let loads = loads(&s, &increments, &contact.material());
    let loading = t.elapsed().as_secs_f64();
    let t = Instant::now();
    let out = s.cycle(&loads, friction).unwrap();
    let faces = t.elapsed().as_secs_f64();
    println!(
        "march {march:.4} s, assembly {assembly:.4} s, stress {loading:.4} s, faces {faces:.4} s; \
         k1 at the last increment {}",
        out.last().unwrap().factors.k1
    );
}
