//! Convergence of the march-derived stresses and fatigue parameters with cells and with the time
//! step (docs/convergence.md, "Stresses and fatigue parameters"). A long study, ignored by
//! default:
//!
//! `cargo test --release -p halfplane --test fatigue_convergence -- --ignored --nocapture`

use halfplane::fatigue::{self, FatigueConstants, FatigueGrid, Parameter};
use halfplane::history::{History, Ramp};
use halfplane::march::MarchOptions;
use halfplane::stress::{self, closed_form::NowellHills};
use halfplane::{reference, LoadPoint};

const Q0: f64 = 300.0;
const S0: f64 = 60.0;

/// Constant P = 1000, Q and sigma in phase between -(300, 60) and (300, 60), two cycles.
fn history(steps_per_half: usize) -> History {
    History::in_phase(
        LoadPoint::new("point1", 1000.0, -Q0, -S0).unwrap(),
        LoadPoint::new("point2", 1000.0, Q0, S0).unwrap(),
        2,
        steps_per_half,
        Ramp::NormalFirst,
        10,
    )
    .unwrap()
}

/// What one run gives: sxx at the trailing edge (-a, 0) and at (-0.5a, 0.2a) at the cycle's peak
/// (Q = +Q0) with their errors against Nowell-Hills, and the grid maxima of SWT, Findley, the
/// MWCM and Ruiz F2.
struct Run {
    edge: f64,
    edge_error: f64,
    inside: f64,
    inside_error: f64,
    parameters: [f64; 4],
    /// Where Findley peaks: x/a, z/a and the increment's place in the cycle (0 to 1).
    findley_at: (f64, f64, f64),
}

fn run(cells: usize, steps_per_half: usize) -> Run {
    run_with(
        MarchOptions::default().with_cells(cells).unwrap(),
        steps_per_half,
    )
}

fn run_with(options: MarchOptions, steps_per_half: usize) -> Run {
    let contact = reference::hertz();
    let h = history(steps_per_half);
    let c = h.cycles().unwrap();
    let peak = c.first_step() + (c.count() - 1) * c.steps_per_cycle() + steps_per_half;
    let state = stress::marched(&contact, &h, &options, &[peak])
        .unwrap()
        .remove(0);
    assert_eq!(state.load.shear(), Q0, "the peak of the cycle");
    let a = state.half_width;
    let nh = NowellHills::hertz(a, 0.6, 1000.0, Q0, S0);
    let m = reference::material();
    let at = |x: f64, z: f64| stress::at(&state.traction, S0, &m, x, z).unwrap().sxx;
    let (edge, inside) = (at(-a, 0.0), at(-0.5 * a, 0.2 * a));
    let p0 = nh.peak_pressure;
    let constants = FatigueConstants::default()
        .with_findley_k(0.25)
        .and_then(|c| c.with_fatigue_limits(350.0, 220.0))
        .unwrap();
    // 41 x 9 points over |x| <= 1.2 a, 0 <= z <= 0.2 a: the same points at every refinement.
    let grid = FatigueGrid::new(41, 9, 1.2, 0.2).unwrap();
    let result = fatigue::analyse(&contact, &h, &options, &constants, &grid).unwrap();
    let value = |p| result.parameter(p).unwrap().value;
    let f = result.parameter(Parameter::Findley).unwrap();
    let first = result.steps[0];
    let findley_at = (
        f.x / a,
        f.z / a,
        (f.step + 1 - first) as f64 / result.steps.len() as f64,
    );
    Run {
        edge,
        edge_error: (edge - nh.trailing_edge_peak()) / p0,
        inside,
        inside_error: (inside - nh.stress(-0.5 * a, 0.2 * a)[0]) / p0,
        parameters: [
            value(Parameter::Swt),
            value(Parameter::Findley),
            value(Parameter::Mwcm),
            value(Parameter::RuizF2),
        ],
        findley_at,
    }
}

/// The observed order from three successive values on halving grids.
fn order(values: &[f64]) -> String {
    match values {
        // Changes within rounding (1e-12 of the value) have no order.
        [.., a, b, c] if (c - b).abs() > 1e-12 * c.abs() && (b - a).abs() > 1e-12 * c.abs() => {
            let r = (b - a).abs() / (c - b).abs();
            if r.is_finite() && r > 0.0 {
                format!("{:.2}", r.log2())
            } else {
                "-".into()
            }
        }
        _ => "-".into(),
    }
}

/// The observed order of an error against a reference, from two successive errors.
fn error_order(errors: &[f64]) -> String {
    match errors {
        [.., a, b] => format!("{:.2}", (a.abs() / b.abs()).log2()),
        _ => "-".into(),
    }
}

fn table(label: &str, sweep: &[usize], run: impl Fn(usize) -> Run) {
    println!(
        "| {label} | trailing-edge sxx / p0 error | order | sxx(-a/2, a/5) / p0 error | order | SWT max | order | Findley max | order | MWCM max | order | Ruiz F2 max | order |"
    );
    println!("|---|---|---|---|---|---|---|---|---|---|---|---|---|");
    let mut runs: Vec<Run> = Vec::new();
    for &n in sweep {
        let start = std::time::Instant::now();
        runs.push(run(n));
        let r = runs.last().unwrap();
        let edges: Vec<f64> = runs.iter().map(|r| r.edge_error).collect();
        let insides: Vec<f64> = runs.iter().map(|r| r.inside_error).collect();
        let mut row = format!(
            "| {n} | {:+.2e} | {} | {:+.2e} | {} |",
            r.edge_error,
            error_order(&edges),
            r.inside_error,
            error_order(&insides)
        );
        for j in 0..4 {
            let values: Vec<f64> = runs.iter().map(|r| r.parameters[j]).collect();
            row += &format!(" {:.6e} | {} |", r.parameters[j], order(&values));
        }
        println!(
            "{row} <!-- {:.1} s; sxx {:.3} at the edge, {:.3} inside; Findley at x/a {:.3}, z/a {:.3}, cycle fraction {:.4} -->",
            start.elapsed().as_secs_f64(),
            r.edge,
            r.inside,
            r.findley_at.0,
            r.findley_at.1,
            r.findley_at.2
        );
    }
}

#[test]
#[ignore = "long convergence study; run with --ignored (see docs/convergence.md)"]
fn stresses_and_fatigue_parameters_converge_in_cells_and_in_time() {
    if std::env::var_os("ONLY_TIME").is_none() {
        println!("\nCells, at 80 increments per half-cycle:\n");
        table("cells", &[200, 400, 800, 1600, 3200], |n| run(n, 80));
    }
    println!("\nIncrements per half-cycle, at 800 cells:\n");
    table("steps per half", &[10, 20, 40, 80, 160], |n| run(800, n));
}

#[cfg(feature = "sub-cell")]
#[test]
#[ignore = "long convergence study; run with --ignored (see docs/convergence.md)"]
fn located_boundaries_make_the_fatigue_maxima_converge_faster() {
    // Issue 20: with the stick-slip boundaries inside their cells the maxima should converge
    // faster in cells. Measured (80 increments per half): Findley -0.018%, -0.006%, -0.004% and
    // the MWCM -0.013%, -0.005%, -0.002% from 400 to 3200 cells, against -0.07%, -0.22% and
    // -0.04%, -0.12% from 1600 with cell edges (with the boundary element and root taper of
    // before 2026-11-27, `march/layout.rs` and `march/kernel.rs`, Findley -0.026%, -0.023%,
    // +0.008%: the changes did not keep one sign at that size). The located maxima do not depend on the time step: 80 and 160 increments per
    // half give the same digits. Asserted: every change below 0.05%, the last below a third of
    // the cell-edge change over the same doubling.
    let located = |cells: usize| {
        let options = MarchOptions::default()
            .with_cells(cells)
            .unwrap()
            .with_sub_cell_boundaries(true)
            .unwrap();
        run_with(options, 80).parameters
    };
    let on: Vec<[f64; 4]> = [400, 800, 1600, 3200].map(located).to_vec();
    let off: Vec<[f64; 4]> = [1600, 3200].map(|n| run(n, 80).parameters).to_vec();
    for (j, name) in [(1, "Findley"), (2, "MWCM")] {
        let change = |a: f64, b: f64| (b - a) / a;
        let changes: Vec<f64> = on.windows(2).map(|w| change(w[0][j], w[1][j])).collect();
        let last = changes[changes.len() - 1];
        let cell_edges = change(off[0][j], off[1][j]);
        println!("{name}: located {changes:?}; cell edges 1600 to 3200 {cell_edges:+.3e}");
        assert!(
            changes.iter().all(|c| c.abs() < 5e-4),
            "{name} with located boundaries: changes {changes:?} per doubling from 400 cells"
        );
        assert!(
            last.abs() < cell_edges.abs() / 3.0,
            "{name}: 1600 to 3200 cells moves {last:e} located, {cell_edges:e} with cell edges"
        );
    }
}
