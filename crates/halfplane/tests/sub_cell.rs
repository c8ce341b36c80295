//! Stick-slip boundaries located inside their cells (`MarchOptions::with_sub_cell_boundaries`,
//! issue 20 item 1) against the closed forms: the Cattaneo-Mindlin traction and stick zone, and the
//! surface stresses of the Mindlin loading and unloading (McEwen's fields superposed).

#![cfg(feature = "sub-cell")]

mod common;
use common::*;
use halfplane::history::History;
use halfplane::march::{march, Fields, MarchOptions, MarchResult, StepReport};
use halfplane::stress::closed_form::{mcewen_pressure, mcewen_shear};
use halfplane::stress::{self, Traction};
use halfplane::{closed_form, Profile};

const F: f64 = 0.6;
const P: f64 = 1000.0;

fn options(cells: usize) -> MarchOptions {
    MarchOptions::default()
        .with_cells(cells)
        .unwrap()
        .with_sub_cell_boundaries(true)
        .unwrap()
}

/// Marches `rows` (Hertz) with located boundaries and keeps each increment's report and a copy
/// of its fields.
fn run(rows: &[[f64; 3]], cells: usize) -> (MarchResult, Vec<(StepReport, Kept)>) {
    march_kept(rows, &options(cells))
}

/// The same with cell-edge boundaries.
fn run_cell_level(rows: &[[f64; 3]], cells: usize) -> (MarchResult, Vec<(StepReport, Kept)>) {
    march_kept(rows, &MarchOptions::default().with_cells(cells).unwrap())
}

fn march_kept(rows: &[[f64; 3]], options: &MarchOptions) -> (MarchResult, Vec<(StepReport, Kept)>) {
    let c = contact(Profile::hertz(RADIUS).unwrap());
    let mut kept = Vec::new();
    let r = march(
        &c,
        &History::from_rows(rows).unwrap(),
        options,
        |s, f: &Fields| kept.push((s.clone(), Kept::of(f))),
    )
    .unwrap();
    (r, kept)
}

/// An owned copy of an increment's fields.
struct Kept {
    x: Vec<f64>,
    pressure: Vec<f64>,
    traction: Vec<f64>,
    slip: Vec<f64>,
    slip_increment: Vec<f64>,
    kinks: Vec<halfplane::march::TractionKink>,
}

impl Kept {
    fn of(f: &Fields) -> Self {
        Self {
            x: f.x.to_vec(),
            pressure: f.pressure.to_vec(),
            traction: f.traction.to_vec(),
            slip: f.slip.to_vec(),
            slip_increment: f.slip_increment.to_vec(),
            kinks: f.kinks.to_vec(),
        }
    }

    fn fields(&self) -> Fields<'_> {
        Fields {
            x: &self.x,
            pressure: &self.pressure,
            traction: &self.traction,
            slip: &self.slip,
            slip_increment: &self.slip_increment,
            kinks: &self.kinks,
        }
    }
}

/// The Hertz pressure of the contact of half-width `b` (`p0 b/a sqrt(1 - x^2/b^2)` in the
/// notation of the Cattaneo-Mindlin traction `f (p_a - p_c)`, Johnson section 7.1).
fn hertz(b: f64, x: f64) -> f64 {
    let a_comp = contact(Profile::hertz(RADIUS).unwrap())
        .compliance()
        .value();
    closed_form::hertz_pressure(a_comp, RADIUS, b, x)
}

/// The largest difference between two increments' centre tractions, as a fraction of `f p0`
/// (`scale`).
fn apart(a: &Kept, b: &Kept, scale: f64) -> f64 {
    a.traction
        .iter()
        .zip(&b.traction)
        .map(|(x, y)| (x - y).abs())
        .fold(0.0, f64::max)
        / scale
}

/// Largest |q - f (p_a - p_c)| over the cell centres, as a fraction of f p0, and the stick
/// half-width error in cells, for the last increment of a Cattaneo load to `q`.
fn cattaneo_errors(r: &MarchResult, kept: &[(StepReport, Kept)], q: f64) -> (f64, f64) {
    let (last, fields) = kept.last().unwrap();
    let a = last.half_width;
    let c = closed_form::cattaneo_mindlin_stick_half_width(a, F, P, q);
    let p0 = hertz(a, 0.0);
    let worst = fields
        .x
        .iter()
        .zip(&fields.traction)
        .map(|(x, t)| (t - F * (hertz(a, *x) - hertz(c, *x))).abs())
        .fold(0.0, f64::max)
        / (F * p0);
    let w = r.x[1] - r.x[0];
    let [left, right] = last.largest_stick().unwrap();
    let edge = (right - c).abs().max((left + c).abs()) / w;
    (worst, edge)
}

#[test]
fn cattaneo_traction_converges_monotonically_to_the_issues_targets() {
    // P pressed in one increment, then Q = 0.5 f P in one (the benchmark's load). Targets of
    // issue 20: the largest traction error falls with every refinement and is at most 1e-3 f p0
    // at 400 cells and 2e-4 at 1600; the stick half-width within 0.05 cells. Measured:
    // 2.0e-4, 1.0e-4, 5.3e-5 at 400, 800, 1600 cells; half-widths within 0.0003 cells. (Cell-level
    // boundaries: 8.3e-3, 5.1e-3, 3.5e-3 and up to 0.58 cells.)
    let rows = [[P, 0.0, 0.0], [P, 0.5 * F * P, 0.0]];
    let mut previous = f64::INFINITY;
    for (cells, target) in [(400, 1e-3), (800, 1e-3), (1600, 2e-4)] {
        let (r, kept) = run(&rows, cells);
        let (worst, edge) = cattaneo_errors(&r, &kept, 0.5 * F * P);
        eprintln!("{cells} cells: max traction error {worst:.3e} f p0, stick edge {edge:.4} cells");
        assert!(
            worst <= target,
            "{cells} cells: {worst:e} f p0 > {target:e}"
        );
        assert!(
            worst < previous,
            "{cells} cells: {worst:e} not below {previous:e}"
        );
        assert!(
            edge < 0.05,
            "{cells} cells: stick half-width off by {edge} cells"
        );
        previous = worst;
    }
}

#[test]
fn cattaneo_in_thirty_increments_is_located_as_well() {
    // The same load in 30 increments after a 10-increment press (the convergence study's
    // history). The slip zones only grow at a constant pressure, so the whole loading is one
    // stretch from the pressed state (`march/chain.rs`) and every increment is located as
    // Cattaneo in one increment: the path does not matter in exact theory, and the reported
    // traction at the last increment equals the one-increment load's to rounding (measured
    // 2.0e-4 f p0 from the closed form at 400 cells in both; the bound on their difference is
    // far below that error and far above rounding). When each increment was solved from the
    // cell-level state before it, the last was 3.5e-4 f p0 off; from the first located
    // increment, 6.8e-5 (both with the boundary element of before 2026-11-27, layout.rs).
    let mut rows: Vec<[f64; 3]> = (1..=10).map(|i| [100.0 * i as f64, 0.0, 0.0]).collect();
    rows.extend((1..=30).map(|i| [P, 300.0 * i as f64 / 30.0, 0.0]));
    let (r, kept) = run(&rows, 400);
    let (worst, edge) = cattaneo_errors(&r, &kept, 300.0);
    eprintln!("30 increments: max traction error {worst:.3e} f p0, stick edge {edge:.4} cells");
    assert!(worst <= 1e-3 && edge < 0.05, "{worst:e} f p0, {edge} cells");
    let (_, once) = run(&[[P, 0.0, 0.0], [P, 300.0, 0.0]], 400);
    let f_p0 = F * hertz(kept[0].0.half_width, 0.0);
    let apart = apart(&kept.last().unwrap().1, &once.last().unwrap().1, f_p0);
    eprintln!("30 increments against one: {apart:.1e} f p0");
    assert!(
        apart < 1e-9,
        "Cattaneo's traction depends on the path: {apart:e} f p0 between 30 increments and one"
    );
}

#[test]
fn the_located_boundary_holds_wherever_it_falls_in_its_cell() {
    // Q from 100 to 110 in 40 increments after the press (one stretch: each increment located
    // as if loaded at once) moves c across four cells at 1600 cells. The located boundary's
    // error was a function of where c falls in its cell: with the boundary element of before
    // 2026-11-27 (`march/layout.rs`: the stick part alone from half a cell up, merged below,
    // each collocated at its own centre) -7.1e-4 to +3.5e-4 cells with a jump at mid-cell, which
    // the bound fails. Now +1.3e-4 to +2.6e-4 cells, whatever the position.
    let mut rows = vec![[P, 0.0, 0.0]];
    rows.extend((0..=40).map(|i| [P, 100.0 + 10.0 * i as f64 / 40.0, 0.0]));
    let (r, kept) = run(&rows, 1600);
    let w = r.x[1] - r.x[0];
    let mut worst = 0.0f64;
    for (s, f) in kept.iter().skip(1) {
        let c = closed_form::cattaneo_mindlin_stick_half_width(s.half_width, F, P, s.load.shear());
        for k in &f.kinks {
            worst = worst.max((k.x.abs() - c).abs() / w);
        }
    }
    eprintln!("Q = 100-110: located boundaries within {worst:.2e} cells of c");
    assert!(
        worst < 3e-4,
        "a stick-slip boundary {worst:e} cells from Cattaneo-Mindlin's c"
    );
}

#[test]
fn near_gross_sliding_the_located_traction_beats_the_cell_level_one() {
    // Q = r f P in one increment, 400 cells: the stick zone shrinks to a few cells. Measured
    // largest traction error, located / cell-level: 9.3e-5 / 8.1e-3, 6.5e-5 / 1.6e-3,
    // 7.8e-5 / 3.6e-3, 7.9e-5 / 8.2e-4, 5.7e-4 / 8.7e-4 f p0 at r = 0.8, 0.9, 0.95, 0.99, 0.998.
    // At r = 0.99 the boundary falls on a cell edge (c = 20 cells): reported without a root
    // there (the search's first jumps below its threshold), it was 2.0e-3. With the root's taper
    // `(1 - t)^2`, whose own `r^(3/2)` term grows as the zone shrinks (`march/kernel.rs`), it was
    // 2.9e-3 at 0.998 (a reviewer's case). Bound: below 1e-3 and below the cell-level march's
    // error.
    for r in [0.8, 0.9, 0.95, 0.99, 0.998] {
        let q = r * F * P;
        let rows = [[P, 0.0, 0.0], [P, q, 0.0]];
        let (located, kept) = run(&rows, 400);
        let (on, _) = cattaneo_errors(&located, &kept, q);
        let (cell_level, plain) = run_cell_level(&rows, 400);
        let (off, _) = cattaneo_errors(&cell_level, &plain, q);
        eprintln!("Q = {r} f P: {on:.1e} f p0 located, {off:.1e} cell-level");
        assert!(
            on < 1e-3 && on < off,
            "Q = {r} f P: the located traction is {on:e} f p0 off, the cell-level {off:e}"
        );
    }
}

#[test]
fn a_stretch_does_not_depend_on_the_path_from_a_stuck_start() {
    // Within a stretch (constant pressure, slip zones only growing) one solve from the
    // stretch's start is exact whatever the path, so the located result of a ramp in ten
    // increments is the one of a single increment from the same start, to rounding. The start
    // here: Q = 300 at P = 1000, then P raised to 1100 at constant Q, which sticks every cell
    // (the cell-level state is then its own located solution, `march/boundary.rs`), then Q to
    // 420. Measured 7.9e-13 f p0 apart; without that stuck start, 4.6e-4.
    let mut start = vec![[P, 0.0, 0.0], [P, 300.0, 0.0]];
    start.extend((1..=5).map(|i| [P + 20.0 * i as f64, 300.0, 0.0]));
    let (from, normal, to) = (300.0, P + 100.0, 420.0);
    let mut ten = start.clone();
    ten.extend((1..=10).map(|i| [normal, from + (to - from) * i as f64 / 10.0, 0.0]));
    let mut one = start.clone();
    one.push([normal, to, 0.0]);
    let (_, a) = run(&ten, 400);
    let (_, b) = run(&one, 400);
    let f_p0 = F * hertz(a[0].0.half_width, 0.0);
    let apart = apart(&a.last().unwrap().1, &b.last().unwrap().1, f_p0);
    eprintln!("after a ramp of P: ten increments against one, {apart:.1e} f p0");
    assert!(
        apart < 1e-9,
        "the located traction depends on the path within a stretch, {apart:e} f p0"
    );
}

/// `sxx` on the surface under Hertz pressure of half-width `a` and the shear
/// `sum_k q_k sqrt(1 - x^2/b_k^2)` (McEwen's fields superposed).
fn closed_sxx(a: f64, shears: &[(f64, f64)], x: f64) -> f64 {
    let p0 = hertz(a, 0.0);
    mcewen_pressure(p0, a, x, 0.0)[0]
        + shears
            .iter()
            .map(|&(q0, b)| mcewen_shear(q0, b, x, 0.0)[0])
            .sum::<f64>()
}

/// The largest error of the surface `sxx` (fraction of p0) at and near the boundaries of the
/// last two increments of `rows` (Hertz, 1600 cells): a load to Q = 300 at P = 1000 and one
/// increment back to Q = 280, against McEwen's fields of the Mindlin tractions
/// `q = f p0 [S_a - (c/a) S_c]` (loading) and `q - 2 f p0 [S_a - (c'/a) S_c']` (unloading),
/// `c' = a sqrt(1 - (Q* - Q)/(2 f P))`, `S_b` the unit semi-ellipse of half-width b; the points
/// are 5, 2, 1 and 0.5 cells either side of each boundary, the boundary itself, and (after the
/// reversal) five cells inside the contact edges. Returns, for the loading state and for the
/// state after the reversal, the largest error at the boundaries themselves and the largest
/// elsewhere, each with where.
fn mindlin_surface_error(rows: &[[f64; 3]]) -> [[(f64, String); 2]; 2] {
    let (r, kept) = run(rows, 1600);
    let material = contact(Profile::hertz(RADIUS).unwrap()).material();
    let w = r.x[1] - r.x[0];
    let (load, unload) = (kept.len() - 2, kept.len() - 1);
    let sxx = |k: usize, x: f64| {
        let (s, f) = &kept[k];
        let t = Traction::from_march_ends(s.ends, &f.fields()).unwrap();
        stress::at(&t, 0.0, &material, x, 0.0).unwrap().sxx
    };
    let a = kept[load].0.half_width;
    let p0 = hertz(a, 0.0);
    let c = closed_form::cattaneo_mindlin_stick_half_width(a, F, P, 300.0);
    let cp = a * (1.0 - 20.0 / (2.0 * F * P)).sqrt();
    let loading = [(F * p0, a), (-F * p0 * c / a, c)];
    let unloading = [
        (-F * p0, a),
        (-F * p0 * c / a, c),
        (2.0 * F * p0 * cp / a, cp),
    ];
    // (increment, its shear as semi-ellipses, x, whether x is the boundary itself)
    type Point<'s> = (usize, &'s [(f64, f64)], f64, bool);
    let mut points: Vec<Point> = Vec::new();
    for (k, shears, at) in [(load, &loading[..], c), (unload, &unloading[..], cp)] {
        for side in [-1.0, 1.0] {
            for d in [-5.0, -2.0, -1.0, -0.5, 0.0, 0.5, 1.0, 2.0] {
                points.push((k, shears, side * (at + d * w), d == 0.0));
            }
            if k == unload {
                points.push((k, shears, side * (a - 5.0 * w), false));
                // The loading's boundary, held in the stick zone after the reversal.
                for d in [-1.0, -0.5, 0.0, 0.5, 1.0] {
                    points.push((k, shears, side * (c + d * w), d == 0.0));
                }
            }
        }
    }
    let mut worst: [[(f64, String); 2]; 2] = Default::default();
    for (k, shears, x, on) in points {
        let error = (sxx(k, x) - closed_sxx(a, shears, x)).abs() / p0;
        let slot = &mut worst[usize::from(k == unload)][usize::from(!on)];
        if error > slot.0 {
            let name = if k == load { "loading" } else { "unloading" };
            *slot = (error, format!("{name}, x = {x:.5}"));
        }
    }
    worst
}

#[test]
fn surface_stresses_at_the_boundary_and_after_a_reversal_match_mindlin() {
    // The issue's case (Hertz R = 50, E = 200 GPa, nu = 0.3, f = 0.6, P = 1000, Q = +-300 at 30
    // increments per half, one increment after the reversal); target 2e-3 p0 at 1600 cells "at
    // and near the stick-slip boundary"; cell-level boundaries gave 1.8e-2 p0 at x = c and
    // 1.4e-2 p0 five cells inside the edge after the reversal. Three histories reach Q = 300 and
    // go back to 280: in one increment, in 30, and round the issue's cycle.
    //
    // At Q = 300, every history: 2.2e-5 p0 at c and 7.3e-5 near (5.6e-5 and 1.1e-4 with the
    // boundary element of before 2026-11-27). The first loading is one
    // stretch from the pressed state and each half-cycle one from the last extreme's located
    // state (`march/chain.rs`). Solved from the cell-level state at every increment, it was
    // 1.14e-2 p0 at c round the cycle (the old boundary's cell-level kink locked into the stick
    // zone where the new boundary lands) and 1.56e-3 in 30 increments; with the first loading
    // started from its first located increment, 7.2e-4 round the cycle; the bound at c, 5e-4
    // p0 (a quarter of the issue's target), fails all three. The boundary element
    // follows the limit's slope (with a constant alone,
    // `c'` was 0.013 cells off next to the contact edge, 3.4e-3 p0 at `c'`) and the node form
    // carries each root over four cells (over one, 2.0-2.2e-3 p0 one cell inside the
    // boundaries); the bound near them is the issue's halved, so that a root over one cell
    // (2.2e-3) or two (1.5e-3) fails it.
    //
    // After the reversal, every history: 2.8e-4 p0 at x = c' and 7.4e-4 near. With the boundary
    // element of before 2026-11-27 (`march/layout.rs`) it was 2.8e-3 at c': the located `c'`
    // was 7.5e-4 cells inside, so c' lay on the slip side of the computed kink, where the surface
    // stress of a square-root kink varies like the square root of the distance (with the exact
    // centre tractions and amplitude but that position: 3.4e-3). The bound at the points is half
    // the issue's target, which that fails.
    let mut thirty: Vec<[f64; 3]> = (1..=10).map(|i| [100.0 * i as f64, 0.0, 0.0]).collect();
    thirty.extend((1..=30).map(|i| [P, 300.0 * i as f64 / 30.0, 0.0]));
    thirty.push([P, 280.0, 0.0]);
    let one = [[P, 0.0, 0.0], [P, 300.0, 0.0], [P, 280.0, 0.0]];
    // Mindlin: the state at +300 after a half-cycle from -300 is the monotonic one again.
    let cycle = issue_cycle(1, &[[P, 280.0, 0.0]]);
    for (name, rows) in [
        ("Q in one increment", &one[..]),
        ("Q in 30", &thirty[..]),
        ("the +-300 cycle", &cycle[..]),
    ] {
        let worst = mindlin_surface_error(rows);
        for (state, [on, near], [on_bound, near_bound]) in [
            ("Q = 300", &worst[0], [5e-4, 1e-3]),
            ("after the reversal", &worst[1], [1e-3, 1e-3]),
        ] {
            eprintln!(
                "{name}, {state}: largest surface sxx error {:.3e} p0 at a boundary ({}), \
                 {:.3e} p0 near ({})",
                on.0, on.1, near.0, near.1
            );
            assert!(
                near.0 <= near_bound,
                "{name}, {state}: {:e} p0 at {}",
                near.0,
                near.1
            );
            assert!(
                on.0 <= on_bound,
                "{name}, {state}: {:e} p0 at {}",
                on.0,
                on.1
            );
        }
    }
}

#[test]
fn surface_stresses_at_the_boundary_hold_over_the_cattaneo_load_range() {
    // Q in one increment, 1600 cells, surface sxx against McEwen's fields of the
    // Cattaneo-Mindlin traction: measured at x = c 5.1e-6, 9.6e-6, 3.6e-5, 2.0e-5, 2.6e-5 p0 at
    // Q = 20, 40, 100, 200, 400, and at most 2.1e-4 at 0.5-5 cells either side. With the
    // boundary element of before 2026-11-27 (`march/layout.rs`) the located boundary was up to
    // 8.2e-4 cells off and the point up to 1.13e-3 p0, which the bound at the point (a quarter of
    // the issue's 2e-3) fails; near it the bound is half the issue's.
    let material = contact(Profile::hertz(RADIUS).unwrap()).material();
    for q in [20.0, 40.0, 100.0, 200.0, 400.0] {
        let (r, kept) = run(&[[P, 0.0, 0.0], [P, q, 0.0]], 1600);
        let (s, f) = kept.last().unwrap();
        let w = r.x[1] - r.x[0];
        let a = s.half_width;
        let p0 = hertz(a, 0.0);
        let c = closed_form::cattaneo_mindlin_stick_half_width(a, F, P, q);
        let t = Traction::from_march_ends(s.ends, &f.fields()).unwrap();
        let shears = [(F * p0, a), (-F * p0 * c / a, c)];
        let error = |x: f64| {
            (stress::at(&t, 0.0, &material, x, 0.0).unwrap().sxx - closed_sxx(a, &shears, x)).abs()
                / p0
        };
        for side in [-1.0, 1.0] {
            let at = error(side * c);
            let near = [-5.0, -2.0, -1.0, -0.5, 0.5, 1.0, 2.0]
                .iter()
                .map(|d| error(side * (c + d * w)))
                .fold(0.0, f64::max);
            eprintln!(
                "Q = {q}: sxx error {at:.2e} p0 at x = {:+.5}, {near:.2e} near",
                side * c
            );
            assert!(
                at <= 5e-4 && near <= 1e-3,
                "Q = {q}: surface sxx {at:e} p0 at x = {}, {near:e} near",
                side * c
            );
        }
    }
}

/// The largest traction error at the centres of increment `step` (1-based) of `kept` against the
/// Cattaneo-Mindlin traction of a load to `q` from rest (the state Mindlin's memory rule gives
/// after a history whose earlier peaks are all below |q|, or at -q after +q), as a fraction
/// of f p0.
fn virgin_error(kept: &[(StepReport, Kept)], step: usize, q: f64) -> f64 {
    let (s, f) = &kept[step - 1];
    let a = s.half_width;
    let c = closed_form::cattaneo_mindlin_stick_half_width(a, F, P, q.abs());
    f.x.iter()
        .zip(&f.traction)
        .filter(|(x, _)| x.abs() < a)
        .map(|(x, t)| (t - q.signum() * F * (hertz(a, *x) - hertz(c, *x))).abs())
        .fold(0.0, f64::max)
        / (F * hertz(a, 0.0))
}

#[test]
fn a_dwell_keeps_the_located_traction() {
    // A dwell at the extreme: the cell-level solve leaves slips of 1e-19 on the slipping cells,
    // which once broke the stretch (a reviewer's case: 8.2e-3 f p0 at the second repeat, its
    // boundary 0.71 cells off). In exact theory the state at Q = -300 after +300 is the virgin
    // one, and so is the located state, each half-cycle being one stretch from the last extreme
    // and the first loading one from the pressed state: the state at -300 and its two repeats
    // equal Q = -300 loaded in one increment to rounding (measured 400 cells: within 2.0e-4 f p0
    // of Cattaneo-Mindlin, the located traction's own error; from the one-increment state
    // 2e-11 or less; the bound is far below that error). A first loading whose stretch starts at
    // its first located increment fails it (it was 2.3e-4 f p0 from Cattaneo-Mindlin when the
    // one-increment load gave 1.5e-4).
    let dwell = issue_cycle(0, &{
        let mut tail: Vec<[f64; 3]> = (1..=30)
            .map(|i| [P, 300.0 - 600.0 * i as f64 / 30.0, 0.0])
            .collect();
        tail.extend([[P, -300.0, 0.0], [P, -300.0, 0.0]]);
        tail
    });
    let (_, kept) = run(&dwell, 400);
    let (_, once) = run(&[[P, 0.0, 0.0], [P, -300.0, 0.0]], 400);
    let virgin = &once.last().unwrap().1;
    let f_p0 = F * hertz(kept[0].0.half_width, 0.0);
    let n = kept.len();
    for step in [n - 2, n - 1, n] {
        let error = virgin_error(&kept, step, -300.0);
        let apart = apart(&kept[step - 1].1, virgin, f_p0);
        eprintln!(
            "dwell at Q = -300, increment {step}: {error:.2e} f p0 from Cattaneo-Mindlin, \
             {apart:.1e} from Q = -300 in one increment"
        );
        assert!(
            apart < 1e-9,
            "increment {step} of a dwell: {apart:e} f p0 from the virgin state"
        );
    }
}

/// Mindlin's memory for the Hertz contact at P (Mindlin and Deresiewicz 1953): the traction at
/// `x` after the turning points `turns` (oldest first, from rest) and the current load `q`,
/// each closed loop forgotten: the first loading's Cattaneo-Mindlin traction to the first point,
/// then twice Cattaneo-Mindlin's for half of each later change. With bulk stress `bulk_ratio`
/// times Q, each first loading is Nowell and Hills's: the stick zone offset by
/// `e = A R Delta sigma / (4 f)` (Hills and Nowell, *Mechanics of Fretting Fatigue*, 1994).
struct Memory {
    turns: Vec<f64>,
    direction: f64,
    last: f64,
    bulk_ratio: f64,
}

impl Memory {
    fn new(bulk_ratio: f64) -> Self {
        Self {
            turns: Vec::new(),
            direction: 0.0,
            last: 0.0,
            bulk_ratio,
        }
    }

    /// Moves to `q`, keeping the turning points the history still remembers.
    fn load(&mut self, q: f64) {
        let direction = (q - self.last).signum();
        if self.direction != 0.0 && direction != self.direction {
            self.turns.push(self.last);
        }
        (self.direction, self.last) = (direction, q);
        // A loop closes when the excursion's half reaches the one before (the first loading's
        // whole, from rest).
        while let Some(&turn) = self.turns.last() {
            let before = self.turns.len().checked_sub(2).map(|k| self.turns[k]);
            let reach = before.map_or(turn.abs(), |b| 0.5 * (turn - b).abs());
            if 0.5 * (q - turn).abs() < reach {
                break;
            }
            self.turns.pop();
            if before.is_some() {
                self.turns.pop();
            }
        }
    }

    fn traction(&self, a: f64, x: f64) -> f64 {
        let compliance = contact(Profile::hertz(RADIUS).unwrap())
            .compliance()
            .value();
        let cattaneo = |change: f64| {
            let c = closed_form::cattaneo_mindlin_stick_half_width(a, F, P, change.abs());
            let offset = compliance * RADIUS * self.bulk_ratio * change.abs() / (4.0 * F);
            change.signum() * F * (hertz(a, x) - hertz(c, x - offset))
        };
        let mut points = vec![0.0];
        points.extend(&self.turns);
        points.push(self.last);
        points
            .windows(2)
            .enumerate()
            .map(|(k, w)| match k {
                0 => cattaneo(w[1] - w[0]),
                _ => 2.0 * cattaneo(0.5 * (w[1] - w[0])),
            })
            .sum()
    }
}

/// The next number in [0, 1) of a linear congruential sequence (Knuth's MMIX constants).
fn lcg(seed: &mut u64) -> f64 {
    *seed = seed
        .wrapping_mul(6364136223846793005)
        .wrapping_add(1442695040888963407);
    (*seed >> 11) as f64 / (1u64 << 53) as f64
}

/// P pressed to 1000 in ten increments, then `count` reversals of Q, ten increments each, to
/// `|Q|` drawn from `[low, low + span)` (`seed`), the bulk stress `bulk_ratio` times Q; with the
/// last Q and the sign of the next reversal.
fn random_reversals(
    seed: u64,
    count: usize,
    [low, span]: [f64; 2],
    bulk_ratio: f64,
) -> (Vec<[f64; 3]>, f64, f64) {
    let mut rows: Vec<[f64; 3]> = (1..=10).map(|i| [100.0 * i as f64, 0.0, 0.0]).collect();
    let (mut seed, mut q, mut sign) = (seed, 0.0f64, 1.0f64);
    for _ in 0..count {
        let target = sign * (low + span * lcg(&mut seed));
        rows.extend((1..=10).map(|i| {
            let shear = q + (target - q) * i as f64 / 10.0;
            [P, shear, bulk_ratio * shear]
        }));
        (q, sign) = (target, -sign);
    }
    (rows, q, sign)
}

#[test]
fn variable_amplitudes_follow_mindlins_memory_at_every_increment() {
    // 40 reversals between |Q| = 100 and 300 (ten increments each), then beyond every earlier
    // peak to |Q| = 317, at constant P. Each increment is a turning point's located solution
    // plus twice a located solve from rest (`march/memory.rs`), so it follows Mindlin's memory
    // with the error of a Cattaneo load, and the last state is the virgin one at 317, as loaded
    // at once. Largest error over every increment against the memory rule, 400 cells: measured
    // 3.1e-3 f p0 (the cell-level march 3.4e-2); the last state equals Q = 317 at once to
    // 4.3e-11 f p0. Solved from the last increment's located start, as before `memory.rs`:
    // 4.2e-2, more than the cell level, and 1.7e-3 from the load at once. Bounds: 4e-3 and a
    // fifth of the cell level's; 1e-9.
    let (mut rows, q, sign) = random_reversals(12345, 40, [100.0, 200.0], 0.0);
    let last = sign * 317.0;
    rows.extend((1..=10).map(|i| [P, q + (last - q) * i as f64 / 10.0, 0.0]));
    let (_, kept) = run(&rows, 400);
    let (_, plain) = run_cell_level(&rows, 400);
    let (located, cell_level) = (memory_error(&kept, 0.0), memory_error(&plain, 0.0));
    let (_, once) = run(&[[P, 0.0, 0.0], [P, last, 0.0]], 400);
    let f_p0 = F * hertz(kept[0].0.half_width, 0.0);
    let virgin = apart(&kept.last().unwrap().1, &once.last().unwrap().1, f_p0);
    eprintln!(
        "40 reversals: largest error {located:.2e} f p0 (cell level {cell_level:.2e}); \
         at Q = {last}, {virgin:.1e} from the load at once"
    );
    assert!(
        located < 4e-3 && located < cell_level / 5.0,
        "variable amplitudes: {located:e} f p0 off Mindlin's memory (cell level {cell_level:e})"
    );
    assert!(
        virgin < 1e-9,
        "beyond every earlier peak the state is not the virgin one: {virgin:e} f p0 from it"
    );
}

/// The largest difference from Mindlin's memory rule (bulk stress `bulk_ratio` times Q) over
/// every loaded increment, in f p0.
fn memory_error(kept: &[(StepReport, Kept)], bulk_ratio: f64) -> f64 {
    let mut memory = Memory::new(bulk_ratio);
    let mut worst = 0.0f64;
    for (s, f) in kept.iter().skip(10) {
        memory.load(s.load.shear());
        let a = s.half_width;
        let error = (f.x.iter().zip(&f.traction))
            .map(|(x, t)| (t - memory.traction(a, *x)).abs())
            .fold(0.0, f64::max);
        worst = worst.max(error / (F * hertz(a, 0.0)));
    }
    worst
}

#[test]
fn beyond_the_memory_and_off_the_line_the_located_solve_falls_back_safely() {
    // A memory holds 16 turning points (`march/chain.rs`). Twenty nested loops inside a +500 /
    // -100 one, then down to -300 (closing every loop but the first): beyond 16 the oldest
    // turning points are gone, and the increments that would need them are solved from their
    // stretch's start. A reviewer found them taken from rest instead before the memory knew it
    // had lost them: 0.569 f p0 from the memory rule at 400 cells. Measured now 3.63e-2 (the
    // cell level 3.86e-2; within the memory's 16, ten nested loops gave 5.2e-3); bound: 1.2
    // times the cell level's error.
    let mut rows: Vec<[f64; 3]> = (1..=10).map(|i| [100.0 * i as f64, 0.0, 0.0]).collect();
    let mut targets = vec![500.0, -100.0];
    targets.extend((0..20).map(|k| (95.0 - 4.0 * k as f64) * if k % 2 == 0 { 1.0 } else { -1.0 }));
    targets.extend([-300.0, 0.0]);
    let mut q = 0.0;
    for t in targets {
        rows.extend((1..=10).map(|i| [P, q + (t - q) * i as f64 / 10.0, 0.0]));
        q = t;
    }
    let (on, off) = (
        memory_error(&run(&rows, 400).1, 0.0),
        memory_error(&run_cell_level(&rows, 400).1, 0.0),
    );
    eprintln!("20 nested loops: {on:.2e} f p0 off Mindlin's memory (cell level {off:.2e})");
    assert!(
        on < off,
        "beyond the memory: {on:e} f p0 (cell level {off:e})"
    );
    // Bulk stress cycled at constant Q is not one-parametric with the shear ramp before it: the
    // memory does not apply (`march/memory.rs`), and the increments are solved from their
    // stretch's start. Before that restriction a turning point was taken wrongly and the
    // reported traction broke the friction limit by 2.9 f p0. Asserted: the limit holds at every
    // centre to rounding, and no energy increment is negative beyond rounding (measured 1.8e-16
    // f p0 and none negative).
    let mut rows: Vec<[f64; 3]> = (1..=10).map(|i| [100.0 * i as f64, 0.0, 0.0]).collect();
    rows.extend((1..=10).map(|i| [P, 20.0 * i as f64, 0.0]));
    let mut sigma = 0.0;
    for k in 0..6 {
        let to = if k % 2 == 0 { 150.0 } else { -150.0 };
        rows.extend((1..=10).map(|i| [P, 200.0, sigma + (to - sigma) * i as f64 / 10.0]));
        sigma = to;
    }
    let (r, kept) = run(&rows, 400);
    let f_p0 = F * hertz(kept[0].0.half_width, 0.0);
    let over_limit = |kept: &[(StepReport, Kept)]| {
        (kept
            .iter()
            .flat_map(|(_, f)| f.traction.iter().zip(&f.pressure)))
        .map(|(q, p)| q.abs() - F * p)
        .fold(f64::MIN, f64::max)
    };
    let over = over_limit(&kept);
    let energy = r.steps.last().unwrap().energy;
    let least = r
        .steps
        .iter()
        .map(|s| s.energy_increment)
        .fold(0.0, f64::min);
    eprintln!("bulk stress alone: |q| - f p at most {:.1e} f p0; least energy increment {least:.1e} of {energy:.3e}", over / f_p0);
    assert!(
        over <= 1e-9 * f_p0 && least >= -1e-12 * energy,
        "bulk stress cycled alone: |q| exceeds f p by {over:e}, or an energy increment is {least:e}"
    );
    // Q to 300 alone, then Q and bulk stress in phase (off the line from the pressed state): the
    // increment solved from its stretch's start, and again from the cell level, broke the limit
    // by 7.1e-3 f p0 here (2.24e-3 in a reviewer's similar history); an increment whose located
    // solution breaks it now reports the cell-level one (measured 2.8e-14 f p0 over). Bound
    // 1e-9.
    let mut rows: Vec<[f64; 3]> = (1..=10).map(|i| [100.0 * i as f64, 0.0, 0.0]).collect();
    rows.extend((1..=15).map(|i| [P, 20.0 * i as f64, 0.0]));
    let mut from = [300.0, 0.0];
    for to in [
        [-300.0, -60.0],
        [300.0, 60.0],
        [-300.0, -60.0],
        [300.0, 60.0],
    ] {
        rows.extend((1..=20).map(|i| {
            let t = i as f64 / 20.0;
            [
                P,
                from[0] + (to[0] - from[0]) * t,
                from[1] + (to[1] - from[1]) * t,
            ]
        }));
        from = to;
    }
    let over = over_limit(&run(&rows, 400).1);
    eprintln!(
        "Q first, then Q and bulk in phase: |q| - f p at most {:.1e} f p0",
        over / f_p0
    );
    assert!(
        over <= 1e-9 * f_p0,
        "Q and bulk stress in phase after Q alone: |q| exceeds f p by {over:e}"
    );
}

/// The issue's history: P to 1000 in ten increments, Q to 300 in 15, then `cycles` cycles
/// +300 -> -300 -> +300 at 30 increments per half, then `tail`.
fn issue_cycle(cycles: usize, tail: &[[f64; 3]]) -> Vec<[f64; 3]> {
    let mut rows: Vec<[f64; 3]> = (1..=10).map(|i| [100.0 * i as f64, 0.0, 0.0]).collect();
    rows.extend((1..=15).map(|i| [P, 300.0 * i as f64 / 15.0, 0.0]));
    for _ in 0..cycles {
        rows.extend((1..=30).map(|i| [P, 300.0 - 600.0 * i as f64 / 30.0, 0.0]));
        rows.extend((1..=30).map(|i| [P, -300.0 + 600.0 * i as f64 / 30.0, 0.0]));
    }
    rows.extend_from_slice(tail);
    rows
}

#[test]
fn located_reports_repeat_over_cycles() {
    // The located solutions are reported only (`march/report.rs` checks that the marched
    // state is the option off's to rounding).
    //
    // Each half-cycle's located solve starts from the last extreme's located state, and the
    // first loading's from the pressed state: Mindlin's state at Q = 300 is the first loading's
    // again at every cycle, and so is the located one, to rounding (measured 3.1e-12 to 1.6e-11
    // f p0 over four cycles at 400 cells). When the first loading started from its first
    // located increment, the extreme drifted by 4.4e-5, 3.3e-5, 2.6e-5, 2.0e-5 f p0 a cycle.
    // The bound is sixty times the largest change measured. The reported (located) slip ranges
    // and energies of the cycles repeat likewise (measured 2.9e-14 of the largest range and
    // 5.9e-14 of the energy; bound 1e-9).
    let rows = issue_cycle(4, &[]);
    let (_, kept) = run(&rows, 400);
    // Cycle k runs from the extreme after increment 25 + 60 k (index 24 + 60 k) round to the next.
    let cycles: Vec<(Vec<f64>, f64)> = (0..4)
        .map(|k| {
            let span = &kept[24 + 60 * k..=24 + 60 * (k + 1)];
            let range = (0..span[0].1.slip.len())
                .map(|i| {
                    let s = span.iter().map(|(_, f)| f.slip[i]);
                    s.clone().fold(f64::MIN, f64::max) - s.fold(f64::MAX, f64::min)
                })
                .collect();
            (
                range,
                span[1..].iter().map(|(r, _)| r.energy_increment).sum(),
            )
        })
        .collect();
    let largest = cycles[0].0.iter().fold(0.0f64, |m, r| m.max(*r));
    let (mut ranges, mut energies) = (0.0f64, 0.0f64);
    for w in cycles.windows(2) {
        for (a, b) in w[0].0.iter().zip(&w[1].0) {
            ranges = ranges.max((a - b).abs() / largest);
        }
        energies = energies.max((w[0].1 - w[1].1).abs() / w[0].1);
    }
    eprintln!("cycle to cycle: slip ranges {ranges:.1e} of the largest, energies {energies:.1e}");
    assert!(
        ranges < 1e-9 && energies < 1e-9,
        "the located slip ranges or energies do not repeat: {ranges:e}, {energies:e}"
    );
    let f_p0 = F * hertz(kept[0].0.half_width, 0.0);
    let extremes: Vec<&Kept> = (0..=4).map(|k| &kept[24 + 60 * k].1).collect();
    let changes: Vec<f64> = extremes
        .windows(2)
        .map(|w| apart(w[0], w[1], f_p0))
        .collect();
    eprintln!("change of the located traction at Q = 300 per cycle: {changes:?} f p0");
    assert!(
        changes.iter().all(|c| *c < 1e-9),
        "the located reports at the cycle's extreme do not repeat: {changes:?}"
    );
}

#[test]
fn a_worn_march_is_the_cell_level_one_with_the_option_on() {
    // Over a worn gap the pressure is known at the cell centres only, so the march reports its
    // cell-level solution whatever the option says; the option must not change a wear cycle
    // (partial slip, then gross sliding with its slides at q = f p) or make it fail. The located
    // boundaries never feed back into the march's state, but their solves share the kernel's
    // cache of stick-run inverses, so the two marches agree to rounding only: measured 1e-13 of
    // each field's largest value; asserted 1e-10.
    use halfplane::history::Ramp;
    use halfplane::march::Worn;
    use halfplane::wear::WornCycle;
    use halfplane::{reference, LoadPoint};
    let cells = 400;
    let plain = MarchOptions::default().with_cells(cells).unwrap();
    let hertz = reference::hertz();
    let (a, b) = (
        LoadPoint::new("a", P, -300.0, 0.0).unwrap(),
        LoadPoint::new("b", P, 300.0, 0.0).unwrap(),
    );
    let fretting = History::in_phase(a, b, 1, 10, Ramp::NormalFirst, 5).unwrap();
    let load = LoadPoint::new("load", P, 0.0, 0.0).unwrap();
    let build = |o: &MarchOptions| {
        [
            Worn::new(&hertz, &fretting, o, 2.0).unwrap(),
            Worn::sliding(&hertz, load, 0.01, 10, 10, o, 8.0).unwrap(),
        ]
    };
    let close = |what: &str, cycle: usize, a: &[f64], b: &[f64]| {
        let scale = b.iter().fold(0.0f64, |m, v| m.max(v.abs()));
        let off = a
            .iter()
            .zip(b)
            .fold(0.0f64, |m, (x, y)| m.max((x - y).abs()));
        assert!(
            off <= 1e-10 * scale,
            "cycle {cycle}: {what} off by {off:e} of {scale:e}"
        );
    };
    for (mut on, mut off) in build(&options(cells)).into_iter().zip(build(&plain)) {
        let mut depth = vec![0.0; cells];
        for cycle in 0..3 {
            let (with, without) = (on.cycle(&depth).unwrap(), off.cycle(&depth).unwrap());
            close("pressure", cycle, &with.pressure, &without.pressure);
            close("traction", cycle, &with.traction, &without.traction);
            close("p |ds|", cycle, &with.pressure_slip, &without.pressure_slip);
            close("slip range", cycle, &with.slip_range, &without.slip_range);
            close("contact", cycle, &with.contact, &without.contact);
            assert_eq!(
                with.stick.is_some(),
                without.stick.is_some(),
                "cycle {cycle}"
            );
            if let (Some(s), Some(t)) = (with.stick, without.stick) {
                close("stick zone", cycle, &s, &t);
            }
            // Some wear, so that the next cycle is over a worn gap.
            for (d, ps) in depth.iter_mut().zip(&without.pressure_slip) {
                *d += 1e-4 * ps;
            }
        }
    }
}

#[test]
fn the_fast_stress_route_sums_the_boundaries_roots_as_the_direct_one_does() {
    // Each located boundary's square root spans several cells on its stick side, more than the
    // one element the fast route's boxes give a contact edge's root; it is summed exactly at every
    // point instead. Tolerance as in `tests/stress_fast.rs` (1e-11 of the peak: expansions
    // truncated at 1e-13 of each box's field; a root in the wrong box would miss by orders).
    let (_, kept) = run(&[[P, 0.0, 0.0], [P, 300.0, 0.0], [P, 280.0, 0.0]], 1600);
    let (s, f) = kept.last().unwrap();
    assert_eq!(
        f.kinks.len(),
        4,
        "the reversal has a boundary on each side, and the loading's held in each stick zone"
    );
    let t = Traction::from_march_ends(s.ends, &f.fields()).unwrap();
    let a = s.half_width;
    let (mut x, mut z) = (Vec::new(), Vec::new());
    for i in 0..2400 {
        let u = -1.2 * a + 2.4 * a * (i as f64 + 0.37) / 2400.0;
        for depth in [0.0, 1e-6 * a, 1e-3 * a, 0.05 * a, 0.5 * a] {
            x.push(u);
            z.push(depth);
        }
    }
    let material = contact(Profile::hertz(RADIUS).unwrap()).material();
    let fast = stress::field(&t, 0.0, &material, &x, &z).unwrap();
    let direct = stress::field_direct(&t, 0.0, &material, &x, &z).unwrap();
    let pairs = [
        (&fast.sxx, &direct.sxx),
        (&fast.szz, &direct.szz),
        (&fast.sxz, &direct.sxz),
    ];
    let peak = pairs
        .iter()
        .flat_map(|(_, d)| d.iter())
        .fold(0.0f64, |m, v| m.max(v.abs()));
    let worst = pairs
        .iter()
        .flat_map(|(f, d)| f.iter().zip(d.iter()))
        .fold(0.0f64, |m, (a, b)| m.max((a - b).abs()));
    assert!(
        worst <= 1e-11 * peak,
        "fast stresses differ from the direct sum by {:e} of the peak",
        worst / peak
    );
}

#[test]
fn where_the_normal_load_changes_the_cell_level_solution_is_reported() {
    // Blocks of random Q cycles at P = 1000, 1200 and 1000, P changed at Q = 0. Where P changes,
    // the located solve (of the increment's last sub-step, from the cell level) was up to 9.1e-2
    // f p0 from the option off at 400 cells (8.6e-2 from a 10800-cell reference, where the cell
    // level is 3.5e-2): those increments now report the cell-level solution (to 1e-9 f p0 of the
    // option off; measured 8e-14). And no turning point of another pressure is remembered: a
    // first version that skipped those increments kept the last block's memory, and the first
    // excursion at the new pressure was 0.42 f p0 off. Bound on the rest: 5e-2 f p0 from the
    // option off (measured 3.5e-2, about the cell level's own error near the boundaries).
    let mut rows: Vec<[f64; 3]> = (1..=10).map(|i| [100.0 * i as f64, 0.0, 0.0]).collect();
    let (mut seed, mut sign) = (31u64, 1.0f64);
    for p in [1000.0, 1200.0, 1000.0] {
        let from = rows.last().unwrap()[0];
        rows.extend((1..=5).map(|i| [from + (p - from) * i as f64 / 5.0, 0.0, 0.0]));
        let mut q = 0.0;
        for _ in 0..6 {
            let target = sign * (50.0 + 300.0 * lcg(&mut seed));
            rows.extend((1..=8).map(|i| [p, q + (target - q) * i as f64 / 8.0, 0.0]));
            (q, sign) = (target, -sign);
        }
        rows.extend((1..=8).map(|i| [p, q - q * i as f64 / 8.0, 0.0]));
    }
    let (_, on) = run(&rows, 400);
    let (_, off) = run_cell_level(&rows, 400);
    let (mut pressed, mut rest) = (0.0f64, 0.0f64);
    for (k, ((s, a), (_, b))) in on.iter().zip(&off).enumerate() {
        let f_p0 = F * a.pressure.iter().fold(0.0f64, |m, p| m.max(*p));
        let apart = apart(a, b, f_p0);
        let before = if k == 0 {
            0.0
        } else {
            on[k - 1].0.load.normal()
        };
        if s.load.normal() != before {
            pressed = pressed.max(apart);
        } else {
            rest = rest.max(apart);
        }
    }
    eprintln!(
        "P blocks: option on against off {pressed:.1e} f p0 where P changes, {rest:.1e} elsewhere"
    );
    assert!(
        pressed <= 1e-9 && rest < 5e-2,
        "P blocks: located {pressed:e} f p0 from the cell level where P changes, {rest:e} elsewhere"
    );
}

#[test]
fn with_bulk_stress_in_proportion_the_memory_is_nowell_and_hills() {
    // Bulk stress 0.2 Q, 30 random reversals (|Q| 50 to 350, ten increments each) at constant
    // P: one-parametric, so the memory rule holds with Nowell and Hills's offset first loading
    // (`Memory`). Largest error over every increment, measured: located 3.2e-3 f p0 at 400 cells
    // (cell level 3.4e-2). Bounds: 4e-3 and a fifth of the cell level's.
    let (rows, _, _) = random_reversals(5, 30, [50.0, 300.0], 0.2);
    let (located, cell_level) = (
        memory_error(&run(&rows, 400).1, 0.2),
        memory_error(&run_cell_level(&rows, 400).1, 0.2),
    );
    eprintln!(
        "bulk stress 0.2 Q: {located:.2e} f p0 off the memory rule (cell level {cell_level:.2e})"
    );
    assert!(
        located < 4e-3 && located < cell_level / 5.0,
        "bulk stress in proportion: {located:e} f p0 off Nowell and Hills's memory (cell level {cell_level:e})"
    );
}

#[test]
fn where_the_moment_changes_the_cell_level_solution_is_reported_too() {
    // Flat-rounded punch at constant P = 1000, twelve random Q reversals each with a new moment
    // (|M| up to 40 N mm/mm), then a step back in Q at that moment (a reviewer's history). A
    // moment moves the pressure as P does; located there, those increments were 1.18e-1 f p0
    // from a 3600-cell march at 400 cells (cell level 3.97e-2). Now they report the cell-level
    // solution (to 1e-9 f p0 of the option off; measured 5.5e-14), and the rest stay within
    // 6e-2 of it (measured 4.5e-2; the largest error from the 3600-cell march is 4.8e-2 with
    // the option on or off).
    let c = halfplane::reference::flat_rounded();
    let mut rows = vec![[P, 0.0, 0.0, 0.0]];
    rows.extend((1..=5).map(|i| [P, 30.0 * i as f64, 0.0, 0.0]));
    let (mut seed, mut last) = (7u64, [P, 150.0, 0.0, 0.0]);
    for k in 0..12 {
        let q = if k % 2 == 0 { -1.0 } else { 1.0 } * (80.0 + 150.0 * lcg(&mut seed));
        let m = 40.0 * (2.0 * lcg(&mut seed) - 1.0);
        for (to, n) in [([P, q, 0.0, m], 6), ([P, 0.8 * q, 0.0, m], 3)] {
            rows.extend((1..=n).map(|i| {
                let t = i as f64 / n as f64;
                std::array::from_fn::<f64, 4, _>(|j| last[j] + t * (to[j] - last[j]))
            }));
            last = to;
        }
    }
    let history = History::from_moment_rows(&rows).unwrap();
    let kept = |options: &MarchOptions| {
        let mut kept = Vec::new();
        march(&c, &history, options, |s, f: &Fields| {
            kept.push((s.clone(), Kept::of(f)))
        })
        .unwrap();
        kept
    };
    let (on, off) = (
        kept(&options(400)),
        kept(&MarchOptions::default().with_cells(400).unwrap()),
    );
    let (mut moved, mut rest) = (0.0f64, 0.0f64);
    for (k, ((s, a), (_, b))) in on.iter().zip(&off).enumerate() {
        let f_p0 = F * a.pressure.iter().fold(0.0f64, |m, p| m.max(*p));
        let apart = apart(a, b, f_p0);
        if k > 0 && s.load.moment() != on[k - 1].0.load.moment() {
            moved = moved.max(apart);
        } else {
            rest = rest.max(apart);
        }
    }
    eprintln!("moment blocks: option on against off {moved:.1e} f p0 where M changes, {rest:.1e} elsewhere");
    assert!(
        moved <= 1e-9 && rest < 6e-2,
        "moment blocks: located {moved:e} f p0 from the cell level where M changes, {rest:e} elsewhere"
    );
}

#[test]
fn a_dwell_reports_the_last_located_solution() {
    // Q to 280, then 20 nested loops of falling amplitude with the bulk stress stepped through
    // -30, 0, 30, each followed by a repeated row (a reviewer's history). In exact theory a
    // dwell moves nothing; solved again by another route (from the stretch's start after an
    // increment solved from the cell level), the located traction moved by 3.2e-2 f p0 over a
    // dwell at 400 cells and one energy increment was -7.6e-7 of 0.24. A dwell now reports the
    // last located solution: asserted unchanged to 1e-12 f p0 with no energy, and no energy
    // increment anywhere below -1e-12 of the total.
    let mut rows: Vec<[f64; 3]> = vec![[P, 0.0, 0.0]];
    rows.extend((1..=6).map(|i| [P, 280.0 * i as f64 / 6.0, 0.0]));
    for k in 0..20 {
        let from = *rows.last().unwrap();
        let to = [
            P,
            280.0 * (1.0 - (k as f64 + 1.0) / 22.0) * if k % 2 == 0 { -1.0 } else { 1.0 },
            30.0 * ((k % 3) as f64 - 1.0),
        ];
        rows.extend((1..=4).map(|i| {
            let t = i as f64 / 4.0;
            [
                P,
                from[1] + t * (to[1] - from[1]),
                from[2] + t * (to[2] - from[2]),
            ]
        }));
        rows.push(to);
    }
    let (r, kept) = run(&rows, 400);
    let f_p0 = F * hertz(kept[0].0.half_width, 0.0);
    let moved = (1..kept.len())
        .filter(|&k| rows[k] == rows[k - 1])
        .map(|k| {
            let dwell = apart(&kept[k].1, &kept[k - 1].1, f_p0);
            dwell.max(kept[k].0.energy_increment.abs() / f_p0)
        })
        .fold(0.0, f64::max);
    let energy = r.steps.last().unwrap().energy;
    let least = (r.steps.iter().map(|s| s.energy_increment)).fold(0.0, f64::min);
    eprintln!("dwells: located traction moved {moved:.1e} f p0; least energy increment {least:.1e} of {energy:.3e}");
    assert!(
        moved <= 1e-12 && least >= -1e-12 * energy,
        "a dwell moved the located traction by {moved:e} f p0, or an energy increment is {least:e}"
    );
}

#[test]
fn a_start_kink_inside_a_new_boundary_element_keeps_its_place() {
    // Q to 280, then 20 nested loops of falling amplitude with the bulk stress stepped between
    // -30, 0 and 30 (off Mindlin's line, so each increment is solved from its stretch's start),
    // then out to +-290. A new boundary often lands within a cell or two of a kink of that start,
    // inside its element. Before 2026-11-27 a kink within half a cell was moved onto the
    // boundary and one further in sent the increment to the cell-level start: 4.6e-2 f p0 at
    // 400 cells against 10800 (cell level 4.6e-2) and 2.6e-2 at 1200 (cell level 1.8e-2). Now
    // the element holds each such kink at its own place (`march/chain.rs`): 8.5e-3 and 1.6e-3
    // against 10800 (`tests/convergence.rs`). Here against the located march at 1200 cells
    // (coinciding centres): measured 8.5e-3 located, 4.7e-2 cell level; with the rule before,
    // 3.4e-2 (its cell level the same, against its own 1200-cell march). Bound 1.5e-2 and a
    // third of the cell level's.
    let rows = ramps(&nested_loops_bulk_stepped(), 4);
    let fine = run(&rows, 1200).1;
    let f_p0 = F * hertz(fine[fine.len() - 1].0.half_width, 0.0);
    let error = |coarse: &[(StepReport, Kept)]| {
        (coarse.iter().zip(&fine))
            .map(|((_, c), (_, f))| apart3(c, f))
            .fold(0.0, f64::max)
            / f_p0
    };
    let (located, cell_level) = (
        error(&run(&rows, 400).1),
        error(&run_cell_level(&rows, 400).1),
    );
    eprintln!("nested loops, bulk stress stepped: {located:.2e} f p0 from 1200 cells (cell level {cell_level:.2e})");
    assert!(
        located < 1.5e-2 && located < cell_level / 3.0,
        "a start's kink in a new element: {located:e} f p0 from 1200 cells (cell level {cell_level:e})"
    );
}

#[test]
fn repeated_cycles_off_mindlins_line_do_not_drift() {
    // Q and bulk stress round a square, (300, 100) -> (300, -100) -> (-300, -100) -> (-300, 100),
    // six increments a side, ten times: off the line, so each increment is solved from its
    // stretch's start, and the boundaries come back to where the last cycle's kinks are. With only
    // the nearest kink beyond a boundary taken over, the others' amplitudes were lost and the
    // located traction drifted cycle after cycle (a reviewer's probe: 3e-3 to 5.3e-2 f p0 over 25
    // cycles at 400 cells, against a 3600-cell march). Largest difference from the located march
    // at 1200 cells, measured: 3.1e-3 in cycles 2-4 and 3.2e-3 in 8-10 (cell level 3.5e-2); with
    // the nearest kink alone 7.9e-3 and 2.4e-2; with kinks 0.01 cells inside the stick side kept
    // apart (`TAKE_OVER` zero, `march/chain.rs`) 3.1e-3 and 1.3e-2. Bound: the last three
    // cycles within 1.2 times the second to fourth, and below half the cell level's.
    let rows = ramps(&square_path(10), 6);
    let fine = run(&rows, 1200).1;
    let f_p0 = F * hertz(fine[fine.len() - 1].0.half_width, 0.0);
    // The largest difference over cycles `first..=last` (the first loading to the square's first
    // corner is cycle 0's first side).
    let cycles = |coarse: &[(StepReport, Kept)], [first, last]: [usize; 2]| {
        (10 + 24 * (first - 1)..10 + 24 * last)
            .map(|k| apart3(&coarse[k].1, &fine[k].1))
            .fold(0.0, f64::max)
            / f_p0
    };
    let located = run(&rows, 400).1;
    let cell_level = run_cell_level(&rows, 400).1;
    let (early, late, plain) = (
        cycles(&located, [2, 4]),
        cycles(&located, [8, 10]),
        cycles(&cell_level, [1, 10]),
    );
    eprintln!("square path: cycles 2-4 {early:.2e}, 8-10 {late:.2e} f p0 from 1200 cells (cell level {plain:.2e})");
    assert!(
        late <= 1.2 * early && late < plain / 2.0,
        "repeated cycles off the line drift: {early:e} then {late:e} f p0 (cell level {plain:e})"
    );
}

/// The largest difference between a 400-cell increment's centre tractions and a 1200-cell one's
/// at the same centres.
fn apart3(coarse: &Kept, fine: &Kept) -> f64 {
    (0..coarse.traction.len())
        .map(|i| (coarse.traction[i] - fine.traction[3 * i + 1]).abs())
        .fold(0.0, f64::max)
}

#[test]
fn kinks_held_in_stick_zones_carry_the_surface_stress() {
    // Ten random reversals of Q at P = 1000 (1600 cells): the stick zones hold the kinks of
    // earlier boundaries, which the march reports with the current ones (`march/boundary.rs`,
    // `with_locked_kinks`). Surface sxx at each held kink and half a cell either side, against
    // McEwen's fields of Mindlin's memory rule (each term a pair of semi-ellipses); and the same
    // with the current boundaries' kinks alone, as reported before 2026-11-27. Measured 1.8e-3
    // and 3.6e-2 p0; bound 2.5e-3 (the issue's 2e-3 near boundaries, for points half a cell
    // from a kink after up to ten loops) and a fifth of the boundaries-only figure.
    let (mut rows, _, _) = random_reversals(2024, 10, [100.0, 200.0], 0.0);
    rows.truncate(rows.len() - 5);
    let (r, kept) = run(&rows, 1600);
    let material = contact(Profile::hertz(RADIUS).unwrap()).material();
    let w = r.x[1] - r.x[0];
    let mut memory = Memory::new(0.0);
    let (mut worst, mut boundaries_only) = (0.0f64, 0.0f64);
    for (s, f) in kept.iter().skip(10) {
        memory.load(s.load.shear());
        let a = s.half_width;
        let p0 = hertz(a, 0.0);
        let mut points = vec![0.0];
        points.extend(&memory.turns);
        points.push(memory.last);
        let mut shears = vec![];
        for (j, pair) in points.windows(2).enumerate() {
            let (m, change) = match j {
                0 => (1.0, pair[1] - pair[0]),
                _ => (2.0, 0.5 * (pair[1] - pair[0])),
            };
            let c = closed_form::cattaneo_mindlin_stick_half_width(a, F, P, change.abs());
            shears.push((m * change.signum() * F * p0, a));
            shears.push((-m * change.signum() * F * p0 * c / a, c));
        }
        // A held kink's traction is inside the limit; a boundary's is at it.
        let held =
            |k: &&halfplane::march::TractionKink| k.shear.abs() < F * k.pressure * (1.0 - 1e-9);
        let current: Vec<_> = f.kinks.iter().filter(|k| !held(k)).copied().collect();
        let fields = f.fields();
        let all = Traction::from_march_ends(s.ends, &fields).unwrap();
        let fewer = halfplane::march::Fields {
            kinks: &current,
            ..fields
        };
        let fewer = Traction::from_march_ends(s.ends, &fewer).unwrap();
        for kink in f.kinks.iter().filter(held) {
            for d in [-0.5, 0.0, 0.5] {
                let x = kink.x + d * w;
                let exact = closed_sxx(a, &shears, x);
                let sxx = |t: &Traction| stress::at(t, 0.0, &material, x, 0.0).unwrap().sxx;
                worst = worst.max((sxx(&all) - exact).abs() / p0);
                boundaries_only = boundaries_only.max((sxx(&fewer) - exact).abs() / p0);
            }
        }
    }
    eprintln!("kinks held after ten random reversals: surface sxx within {worst:.2e} p0 ({boundaries_only:.2e} with the boundaries' alone)");
    assert!(
        worst < 2.5e-3 && worst < boundaries_only / 5.0,
        "surface sxx at held kinks: {worst:e} p0 ({boundaries_only:e} with the boundaries' alone)"
    );
}
