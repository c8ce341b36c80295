//! Runs one benchmark history once, for profiling and for the pass counts of BENCHMARKS.md:
//! `valgrind --tool=callgrind target/release/examples/profile_march CELLS [flat-rounded|cattaneo]`.
//! Default: the reference cycle of examples/march-cycle.toml (Hertz, 30 ramp + 270 cycle
//! increments); `flat-rounded`: the same cycle on b = 0.3, R = 50; `cattaneo`: Hertz, P = 1000
//! pressed in one increment, then Q = 0.5 f P in one more (two increments).
use halfplane::history::{History, Ramp};
use halfplane::march::{march, MarchOptions};
use halfplane::reference;

fn main() {
    let cells = std::env::args()
        .nth(1)
        .and_then(|s| s.parse().ok())
        .unwrap_or(1000);
    let mode = std::env::args().nth(2);
    let contact = match mode.as_deref() {
        Some("flat-rounded") => reference::flat_rounded(),
        _ => reference::hertz(),
    };
    let history = if mode.as_deref() == Some("cattaneo") {
        let f = contact.friction.value();
        History::from_rows(&[[1000.0, 0.0, 0.0], [1000.0, 0.5 * f * 1000.0, 0.0]]).unwrap()
    } else {
        let (p1, p2) = (reference::point1(), reference::point2());
        History::in_phase(p1, p2, 3, 45, Ramp::NormalFirst, 15).unwrap()
    };
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
