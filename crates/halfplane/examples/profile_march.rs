//! Runs one benchmark history once, for profiling and for the pass counts of BENCHMARKS.md:
//! `valgrind --tool=callgrind target/release/examples/profile_march CELLS [flat-rounded|cattaneo]`.
//! Default: the reference cycle of examples/march-cycle.toml (Hertz, 30 ramp + 270 cycle
//! increments); `flat-rounded`: the same cycle on b = 0.3, R = 50; `cattaneo`: Hertz, P = 1000
//! pressed in one increment, then Q = 0.5 f P in one more (two increments; a third argument
//! sets Q / f P, e.g. `profile_march 3200 cattaneo 0.97`); `reversal`: the same, then Q to minus
//! that in one more increment. A fourth argument `flat-rounded` runs `cattaneo` or `reversal`
//! on the flat-rounded contact (passes only: the errors are against Hertz's closed form). `HP_PASSES` prints each increment's passes. With `HP_SUB_CELL`
//! set, the march locates its stick-slip boundaries inside their cells
//! (`MarchOptions::with_sub_cell_boundaries`).
use halfplane::history::{History, Ramp};
use halfplane::march::{march, MarchOptions};
use halfplane::{closed_form, reference};

fn main() {
    let cells = std::env::args()
        .nth(1)
        .and_then(|s| s.parse().ok())
        .unwrap_or(1000);
    let mode = std::env::args().nth(2);
    let flat = mode.as_deref() == Some("flat-rounded")
        || std::env::args().nth(4).as_deref() == Some("flat-rounded");
    let contact = if flat {
        reference::flat_rounded()
    } else {
        reference::hertz()
    };
    let ratio: f64 = std::env::args()
        .nth(3)
        .and_then(|s| s.parse().ok())
        .unwrap_or(0.5);
    let f = contact.friction().value();
    let history = if mode.as_deref() == Some("cattaneo") {
        History::from_rows(&[[1000.0, 0.0, 0.0], [1000.0, ratio * f * 1000.0, 0.0]]).unwrap()
    } else if mode.as_deref() == Some("reversal") {
        let q = ratio * f * 1000.0;
        History::from_rows(&[[1000.0, 0.0, 0.0], [1000.0, q, 0.0], [1000.0, -q, 0.0]]).unwrap()
    } else {
        let (p1, p2) = (reference::point1(), reference::point2());
        History::in_phase(p1, p2, 3, 45, Ramp::NormalFirst, 15).unwrap()
    };
    let (mut passes, mut runs) = (0, 0);
    let mut traction = Vec::new();
    let r = march(
        &contact,
        &history,
        &MarchOptions::default()
            .with_cells(cells)
            .unwrap()
            .with_sub_cell_boundaries(std::env::var_os("HP_SUB_CELL").is_some())
            .unwrap(),
        |s, f| {
            passes += s.passes;
            if std::env::var_os("HP_PASSES").is_some() {
                eprint!("{} ", s.passes);
            }
            runs = runs.max(s.stick_intervals.len());
            traction = f.traction.to_vec();
        },
    )
    .unwrap();
    println!(
        "{} steps, {passes} passes, at most {runs} stick intervals",
        r.steps.len()
    );
    if !flat && matches!(mode.as_deref(), Some("cattaneo" | "reversal")) {
        // Error against Cattaneo-Mindlin (Johnson, section 7.1): q = f (p(a) - p(c)); after
        // the reversal to -Q, Mindlin's reversed slip zone is the whole slip zone and q is its
        // mirror, -f (p(a) - p(c)) (Johnson, section 7.2).
        let last = r.steps.last().unwrap();
        let (a, w) = (last.half_width, r.x[1] - r.x[0]);
        let f = contact.friction().value();
        let compliance = contact.compliance().value();
        let c = closed_form::cattaneo_mindlin_stick_half_width(a, f, 1000.0, ratio * f * 1000.0);
        let sign = last.load.shear().signum();
        let p = |b: f64, x: f64| closed_form::hertz_pressure(compliance, reference::RADIUS, b, x);
        let max =
            r.x.iter()
                .zip(&traction)
                .map(|(x, q)| (q - sign * f * (p(a, *x) - p(c, *x))).abs())
                .fold(0.0, f64::max);
        let [left, right] = last.largest_stick().unwrap();
        let edge = (right - c).abs().max((left + c).abs()) / w;
        println!(
            "max traction error {:.3e} f p0, stick half-width error {edge:.3} cells",
            max / (f * p(a, 0.0))
        );
    }
}
