//! Runs the benchmark history once, for profiling:
//! `valgrind --tool=callgrind target/release/examples/profile_march CELLS`.
use halfplane::history::{History, Ramp};
use halfplane::march::{march, MarchOptions};
use halfplane::{Contact, Friction, LoadPoint, Material, Profile};

fn main() {
    let cells = std::env::args()
        .nth(1)
        .and_then(|s| s.parse().ok())
        .unwrap_or(1000);
    let contact = Contact::new(
        Profile::hertz(50.0).unwrap(),
        Material::new(200_000.0, 0.3).unwrap(),
        Friction::new(0.6).unwrap(),
    );
    let p1 = LoadPoint::new("p1", 1000.0, -250.0, -20.0).unwrap();
    let p2 = LoadPoint::new("p2", 1400.0, 250.0, 20.0).unwrap();
    let history = History::in_phase(p1, p2, 3, 45, Ramp::NormalFirst, 15).unwrap();
    let (mut passes, mut runs) = (0, 0);
    let r = march(
        &contact,
        &history,
        &MarchOptions::default().with_cells(cells).unwrap(),
        |s, _| {
            passes += s.passes;
            if std::env::var_os("HP_PASSES").is_some() {
                eprint!("{} ", s.passes);
            }
            runs = runs.max(s.stick_intervals.len());
        },
    )
    .unwrap();
    println!(
        "{} steps, {passes} passes, at most {runs} stick intervals",
        r.steps.len()
    );
}
