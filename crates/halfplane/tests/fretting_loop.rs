//! The fretting loop: the bodies' relative displacement against Q, marched, against the
//! Cattaneo-Mindlin cylinder's closed form (first loading and the steady loop by
//! Mindlin-Deresiewicz superposition), and the loop's area against the energy the march
//! dissipates.

use halfplane::closed_form;
use halfplane::history::{History, Ramp};
use halfplane::march::{self, MarchOptions, MarchResult};
use halfplane::{reference, LoadPoint};

const P: f64 = 1000.0;
const Q: f64 = 300.0;
const RAMP: usize = 10;

fn fretting(steps_per_half: usize, cells: usize) -> MarchResult {
    let a = LoadPoint::new("a", P, -Q, 0.0).unwrap();
    let b = LoadPoint::new("b", P, Q, 0.0).unwrap();
    let history = History::in_phase(a, b, 2, steps_per_half, Ramp::NormalFirst, RAMP).unwrap();
    let options = MarchOptions::default().with_cells(cells).unwrap();
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
