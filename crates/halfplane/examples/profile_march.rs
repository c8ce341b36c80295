//! Runs the benchmark history once, for profiling:
//! `valgrind --tool=callgrind target/release/examples/profile_march CELLS [flat-rounded]`
//! (Hertz unless the second argument is `flat-rounded`: b = 0.3, R = 50).
use halfplane::history::{History, Ramp};
use halfplane::march::{march, MarchOptions};
use halfplane::reference;

fn main() {
    let cells = std::env::args()
        .nth(1)
        .and_then(|s| s.parse().ok())
        .unwrap_or(1000);
    let contact = match std::env::args().nth(2).as_deref() {
        Some("flat-rounded") => reference::flat_rounded(),
        _ => reference::hertz(),
    };
    let (p1, p2) = (reference::point1(), reference::point2());
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
