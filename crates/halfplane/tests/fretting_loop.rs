//! The fretting loop: the bodies' relative displacement against Q, marched, against the
//! Cattaneo-Mindlin cylinder's closed form (first loading and the steady loop by
//! Mindlin-Deresiewicz superposition), and the loop's area against the energy the march
//! dissipates.

mod common;
use common::integrate;
use halfplane::closed_form;
use halfplane::history::{History, Ramp};
use halfplane::march::{self, MarchOptions, MarchResult};
use halfplane::{reference, LoadPoint};

const P: f64 = 1000.0;
const Q: f64 = 300.0;
const RAMP: usize = 10;

fn fretting(steps_per_half: usize, cells: usize) -> MarchResult {
    fretting_with(
        steps_per_half,
        MarchOptions::default().with_cells(cells).unwrap(),
    )
}

/// Hertz, P to 1000 and Q to -300 (ramps of RAMP increments), then two cycles of +-300.
fn fretting_with(steps_per_half: usize, options: MarchOptions) -> MarchResult {
    let a = LoadPoint::new("a", P, -Q, 0.0).unwrap();
    let b = LoadPoint::new("b", P, Q, 0.0).unwrap();
    let history = History::in_phase(a, b, 2, steps_per_half, Ramp::NormalFirst, RAMP).unwrap();
    march::march(&reference::hertz(), &history, &options, |_, _| {}).unwrap()
}

/// The largest difference between the marched and the closed-form displacement over the ramp's
/// shear leg and the second cycle, with the datum `d`, as a fraction of the closed form's
/// largest value.
fn loop_error(run: &MarchResult, steps_per_half: usize, datum: f64) -> f64 {
    let contact = reference::hertz();
    let compliance = contact.compliance().value();
    let a = closed_form::hertz_half_width(compliance, reference::RADIUS, P);
    let f = reference::FRICTION;
    let first = |q: f64| closed_form::cattaneo_mindlin_displacement(compliance, a, f, P, q, datum);
    let scale = first(Q).abs();
    let mut worst: f64 = 0.0;
    for (k, step) in run.steps.iter().enumerate() {
        let q = step.load.shear();
        let exact = if k < 2 * RAMP {
            first(q)
        } else {
            // Cycles start at -Q: rising for the first half, falling for the second.
            let in_cycle = (k - 2 * RAMP) % (2 * steps_per_half);
            let rising = in_cycle < steps_per_half;
            closed_form::cattaneo_mindlin_loop_displacement(
                compliance, a, f, P, Q, q, rising, datum,
            )
        };
        let marched = step.relative_displacement.at(datum).unwrap();
        worst = worst.max((marched - exact).abs() / scale);
    }
    worst
}

#[test]
fn the_loop_is_cattaneo_mindlins() {
    // Hertz R = 50, P = 1000, f = 0.6, Q to -300 then two cycles +-300 (30 increments per
    // half). The closed form is exact at every increment (constant P: the state depends on the
    // load path only, not the step), so what is left is the grid's: the stick-slip boundaries
    // sit on cells (traction errors up to 8e-3 f p0 at 400 cells, docs/convergence.md), which
    // the displacement, an integral of the traction, feels far less. Measured: 8.7e-5 (datum
    // a) and 2.3e-5 (datum 10 a) of the largest displacement at 400 cells, 1.0e-5 and 2.7e-6
    // at 1600; the tolerances are twice those at 400 cells, and refining must cut the error
    // at least four times.
    let a = closed_form::hertz_half_width(
        reference::hertz().compliance().value(),
        reference::RADIUS,
        P,
    );
    let (coarse, fine) = (fretting(30, 400), fretting(30, 1600));
    for (datum, tolerance) in [(a, 2e-4), (10.0 * a, 5e-5)] {
        let e400 = loop_error(&coarse, 30, datum);
        let e1600 = loop_error(&fine, 30, datum);
        assert!(
            e400 < tolerance,
            "datum {datum}: the marched fretting loop is {e400:e} off Cattaneo-Mindlin's at 400 cells"
        );
        assert!(
            e1600 < 0.25 * e400,
            "datum {datum}: the loop does not converge with cells ({e400:e} at 400, {e1600:e} at 1600)"
        );
    }
}

#[test]
fn the_loop_area_is_the_energy_dissipated() {
    // Over a cycle at constant P and bulk stress the elastic energy returns, so the work of Q,
    // the loop's area, is what friction dissipates (any datum: it only shears the loop). The
    // march integrates the dissipation to second order in the step and the area here is the
    // trapezoidal rule on the increments, second order too: measured 1.1e-3 of the energy at 30
    // increments per half and 1.2e-4 at 90 (8.9 times less for 3 times the increments); the
    // tolerances are twice those, and the error must fall at least six times.
    let mut errors = Vec::new();
    for (steps, datum) in [(30, 1.0), (90, 25.0)] {
        let run = fretting(steps, 400);
        let cycle = &run.steps[run.steps.len() - 2 * steps - 1..];
        let area: f64 = cycle
            .windows(2)
            .map(|w| {
                let [d0, d1] = [0, 1].map(|k| w[k].relative_displacement.at(datum).unwrap());
                0.5 * (w[0].load.shear() + w[1].load.shear()) * (d1 - d0)
            })
            .sum();
        let energy = run.cycles.last().unwrap().energy;
        errors.push(((area - energy) / energy).abs());
    }
    assert!(
        errors[0] < 2.2e-3 && errors[1] < 2.4e-4,
        "the fretting loop's area is not the energy dissipated: {errors:?} off at 30 and 90 increments per half"
    );
    assert!(
        errors[1] < errors[0] / 6.0,
        "the loop's area does not converge to the energy at second order: {errors:?}"
    );
}

#[test]
fn a_datum_must_be_a_positive_length() {
    let run = fretting(5, 100);
    let d = run.steps.last().unwrap().relative_displacement;
    for bad in [0.0, -1.0, f64::NAN, f64::INFINITY] {
        let e = d.at(bad).unwrap_err().to_string();
        assert!(e.contains("relative displacement datum"), "{bad}: {e}");
    }
}

/// The reference contact's compliance, half-width at P, friction and peak pressure.
fn hertz_at_p() -> (f64, f64, f64, f64) {
    let compliance = reference::hertz().compliance().value();
    let a = closed_form::hertz_half_width(compliance, reference::RADIUS, P);
    let p0 = closed_form::hertz_pressure(compliance, reference::RADIUS, a, 0.0);
    (compliance, a, reference::FRICTION, p0)
}

/// The integral of `f` over `[lo, hi]` in `x = lo + (hi - lo)(3 s^2 - 2 s^3)`, flat at both
/// ends: a square root or a logarithm at an end becomes smooth in s.
fn graded(lo: f64, hi: f64, f: impl Fn(f64) -> f64) -> f64 {
    let h = hi - lo;
    integrate(0.0, 1.0, 40, |s| {
        f(lo + h * s * s * (3.0 - 2.0 * s)) * 6.0 * s * (1.0 - s) * h
    })
}

#[test]
fn the_slip_and_the_loop_energy_closed_forms_agree_with_quadrature() {
    // Independent routes to the two closed forms (closed_form.rs derives them).
    // (1) The slip is u(x) - u(0), u = (A/pi) integral q(xi) ln|x - xi| dxi with Johnson's
    //     traction; the quadrature subtracts q(x) under the logarithm (whose integral is exact)
    //     and splits at the kinks, with panels graded to them. (2) The energy per cycle is
    //     4 integral f p s dx with the slip at the amplitude, integrated in x = a sin(t), where p
    //     is smooth. (3) The sum for small amplitudes meets the closed form at e = 0.1.
    //     Measured: 4.4e-11 of the largest slip; 1.8e-14 (Q* = 30, the sum) to 4e-16 relative;
    //     6e-12 across e = 0.1 +- 1e-12 relative, which is the energy's own change there
    //     (W ~ e^3). Tolerances 1e-9, 1e-12 and 1e-10.
    let (compliance, a, f, p0) = hertz_at_p();
    let q = 300.0;
    let c = closed_form::cattaneo_mindlin_stick_half_width(a, f, P, q);
    let traction = |x: f64| {
        let root = |b: f64| (b * b - x * x).max(0.0).sqrt();
        f * p0 / a * (root(a) - root(c))
    };
    let u = |x: f64| {
        // integral_{-a}^{a} ln|x - xi| dxi, exact.
        let log_integral = |t: f64| if t == 0.0 { 0.0 } else { t * t.abs().ln() - t };
        let exact = log_integral(a - x) + log_integral(a + x);
        let mut knots = vec![-a, -c, c, a, x];
        knots.sort_by(f64::total_cmp);
        knots.dedup();
        let qx = traction(x);
        let rest: f64 = knots
            .windows(2)
            .map(|k| graded(k[0], k[1], |xi| (traction(xi) - qx) * (x - xi).abs().ln()))
            .sum();
        compliance / std::f64::consts::PI * (rest + qx * exact)
    };
    let largest = closed_form::cattaneo_mindlin_slip(compliance, a, f, P, q, a);
    let mut worst = 0.0f64;
    for k in 0..=40 {
        let x = -a + 2.0 * a * k as f64 / 40.0;
        let quadrature = u(x) - u(0.0);
        let closed = closed_form::cattaneo_mindlin_slip(compliance, a, f, P, q, x);
        let slipping = x.abs() > c;
        let expected = if slipping { quadrature } else { 0.0 };
        worst = worst.max((closed - expected).abs() / largest);
        if !slipping {
            // Stick: u is the same everywhere in the stick zone.
            worst = worst.max(quadrature.abs() / largest);
        }
    }
    assert!(
        worst < 1e-9,
        "the Cattaneo-Mindlin slip is {worst:e} of its largest value off the log-kernel integral"
    );
    for amplitude in [30.0, 150.0, 300.0, 500.0] {
        let c = closed_form::cattaneo_mindlin_stick_half_width(a, f, P, amplitude);
        let work = |t: f64| {
            let x = a * t.sin();
            let s = closed_form::cattaneo_mindlin_slip(compliance, a, f, P, amplitude, x);
            f * p0 * t.cos() * s * a * t.cos()
        };
        let from_slip = 8.0 * graded((c / a).asin(), std::f64::consts::FRAC_PI_2, work);
        let closed = closed_form::cattaneo_mindlin_loop_energy(compliance, f, P, amplitude);
        let off = (closed - from_slip).abs() / closed;
        assert!(
            off < 1e-12,
            "Q* = {amplitude}: the loop energy {closed:e} is {off:e} off 4 integral f p s dx"
        );
    }
    let e = 0.1 * f * P;
    let [below, above] = [e * (1.0 - 1e-12), e * (1.0 + 1e-12)]
        .map(|q| closed_form::cattaneo_mindlin_loop_energy(compliance, f, P, q));
    assert!(
        (below - above).abs() / above < 1e-10,
        "the small-amplitude sum and the closed form do not meet: {below:e} and {above:e}"
    );
}

#[cfg(feature = "sub-cell")]
#[test]
fn located_slips_energy_and_loop_are_cattaneo_mindlins() {
    // With the stick-slip boundaries located inside their cells, the reported slips, energy and
    // relative displacement are the located solution's (each half-cycle at constant P is one
    // stretch: exact in time). Against the closed forms, the second cycle, 30 increments per
    // half, located / cell-level, measured:
    //   slip range (against twice the first loading's slip), of the largest range:
    //     400 cells 3.4e-5 / 5.6e-4, 1600 cells 4.3e-6 / 8.1e-5;
    //   energy per cycle (against the closed form): 1.5e-5 / 2.1e-4, 7.3e-7 / 3.7e-5;
    //   loop (relative displacement, datum 10 a), of its largest value, ramp and both cycles:
    //     1.9e-7 / 2.3e-5, 7.8e-9 / 2.7e-6.
    // Bounds: twice the located values at 400 cells, each falling at least fourfold by 1600,
    // and a tenth of the cell-level error at 400 cells.
    let (compliance, a, f, _) = hertz_at_p();
    let c = closed_form::cattaneo_mindlin_stick_half_width(a, f, P, Q);
    let largest = 2.0 * closed_form::cattaneo_mindlin_slip(compliance, a, f, P, Q, a);
    let energy = closed_form::cattaneo_mindlin_loop_energy(compliance, f, P, Q);
    let errors = |run: &MarchResult| {
        let cycle = run.cycles.last().unwrap();
        let range = run
            .x
            .iter()
            .zip(&cycle.slip_range)
            .map(|(x, r)| {
                let exact = 2.0 * closed_form::cattaneo_mindlin_slip(compliance, a, f, P, Q, *x);
                (r - exact).abs()
            })
            .fold(0.0, f64::max)
            / largest;
        [
            range,
            (cycle.energy - energy).abs() / energy,
            loop_error(run, 30, 10.0 * a),
        ]
    };
    let names = ["slip range", "energy per cycle", "fretting loop"];
    let located = |cells| {
        let options = MarchOptions::default().with_cells(cells).unwrap();
        errors(&fretting_with(
            30,
            options.with_sub_cell_boundaries(true).unwrap(),
        ))
    };
    let (coarse, fine, cell_level) = (located(400), located(1600), errors(&fretting(30, 400)));
    eprintln!("stick half-width {c}: located at 400 cells {coarse:?}, 1600 {fine:?}; cell level 400 {cell_level:?}");
    for (k, (bound, name)) in [7e-5, 3e-5, 4e-7].iter().zip(names).enumerate() {
        assert!(
            coarse[k] < *bound && fine[k] < coarse[k] / 4.0 && coarse[k] < cell_level[k] / 10.0,
            "the located {name} is {:e} off Cattaneo-Mindlin at 400 cells, {:e} at 1600 \
             (cell level {:e})",
            coarse[k],
            fine[k],
            cell_level[k]
        );
    }
}
