//! The march driver: [`march`] sizes the grid from the whole history, steps a [`Marcher`]
//! through it, and accounts each cycle (its energy and per-cell peak-to-peak slip range) and the
//! shakedown test (the first cycle the next one repeats).
//!
//! Owns the cycle accounting. Never changes the marcher's state except through
//! [`Marcher::step`], and never prints or writes: the observer sees each increment and, through
//! [`march_until`], may stop the march.

use super::marcher::Marcher;
use super::types::{CycleReport, Fields, MarchOptions, MarchResult, StepReport};
use crate::error::Result;
use crate::history::History;
use crate::normal::Contact;
use std::convert::Infallible;
use std::ops::ControlFlow;

/// Marches through `history`. `observer` sees each increment's report and fields as it is made
/// (for progress bars and field output); nothing is printed or written here. To let the observer
/// stop the march (an interrupt, a time limit), use [`march_until`].
pub fn march(
    contact: &Contact,
    history: &History,
    options: &MarchOptions,
    mut observer: impl FnMut(&StepReport, &Fields),
) -> Result<MarchResult> {
    let outcome = march_until(contact, history, options, |report, fields| {
        observer(report, fields);
        ControlFlow::<Infallible>::Continue(())
    })?;
    match outcome {
        ControlFlow::Continue(result) => Ok(result),
        ControlFlow::Break(never) => match never {},
    }
}

/// Marches through `history` as [`march`] does, reporting each increment to `observer`, which
/// may stop the march by returning [`ControlFlow::Break`]: no further increment is solved and the
/// break value is returned (the increments made so far are not summarised). A march the observer
/// never stops returns `ControlFlow::Continue` with the same result as [`march`].
///
/// # Errors
/// Those of [`march`], for the increments solved before a stop.
pub fn march_until<B>(
    contact: &Contact,
    history: &History,
    options: &MarchOptions,
    mut observer: impl FnMut(&StepReport, &Fields) -> ControlFlow<B>,
) -> Result<ControlFlow<B, MarchResult>> {
    // A History is valid by construction: at least one row, every load a valid LoadPoint.
    let p_max = history
        .loads()
        .iter()
        .map(|p| p.normal())
        .fold(0.0, f64::max);
    let span = contact.half_width(p_max)?;
    let mut marcher = Marcher::new(contact, span, options)?;
    let n = options.cells();
    let mut steps = Vec::with_capacity(history.loads().len());
    let mut cycles = Vec::new();
    let (mut low, mut high) = (vec![0.0; n], vec![0.0; n]);
    let mut cycle_energy_start = 0.0;
    let structure = history.cycles();
    for (k, load) in history.loads().iter().enumerate() {
        let cycle = structure.and_then(|s| s.cycle_of(k).map(|c| (s, c)));
        if cycle.is_some_and(|(s, _)| s.starts_cycle(k)) {
            low.copy_from_slice(&marcher.slip);
            high.copy_from_slice(&marcher.slip);
            cycle_energy_start = marcher.energy;
        }
        let report = marcher.step(*load)?;
        if let ControlFlow::Break(value) = observer(&report, &marcher.fields()) {
            return Ok(ControlFlow::Break(value));
        }
        if let Some((s, c)) = cycle {
            for i in 0..n {
                low[i] = low[i].min(marcher.slip[i]);
                high[i] = high[i].max(marcher.slip[i]);
            }
            if s.ends_cycle(k) {
                cycles.push(CycleReport {
                    index: c + 1,
                    energy: marcher.energy - cycle_energy_start,
                    slip_range: high.iter().zip(&low).map(|(h, l)| h - l).collect(),
                });
            }
        }
        steps.push(report);
    }
    let tol = options.shakedown_tolerance();
    let slip_floor = 1e-12 * contact.compliance().value() * contact.friction.value() * p_max;
    let shakedown_cycle = cycles.windows(2).find_map(|w| {
        let scale = w[0].slip_range.iter().fold(slip_floor, |m, v| m.max(*v));
        let ranges = w[0]
            .slip_range
            .iter()
            .zip(&w[1].slip_range)
            .all(|(a, b)| (a - b).abs() <= tol * scale);
        let energy =
            (w[0].energy - w[1].energy).abs() <= tol * w[0].energy.abs().max(slip_floor * p_max);
        (ranges && energy).then_some(w[0].index)
    });
    Ok(ControlFlow::Continue(MarchResult {
        x: marcher.x.clone(),
        steps,
        cycles,
        shakedown_cycle,
    }))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::history::Ramp;
    use crate::reference;

    fn reference_march() -> (Contact, History, MarchOptions) {
        let (first, second) = reference::cycle().as_given();
        let history =
            History::in_phase(first, second, 2, 12, Ramp::NormalFirst, 6).expect("valid history");
        let options = MarchOptions::default().with_cells(80).expect("valid cells");
        (reference::hertz(), history, options)
    }

    #[test]
    fn an_observer_that_breaks_stops_the_march_at_that_increment() {
        let (contact, history, options) = reference_march();
        let total = history.loads().len();
        let stop_after = total / 3;
        let mut seen = Vec::new();
        let outcome = march_until(&contact, &history, &options, |report, _| {
            seen.push(report.clone());
            if seen.len() == stop_after {
                ControlFlow::Break(seen.len())
            } else {
                ControlFlow::Continue(())
            }
        })
        .expect("the reference cycle marches");
        assert_eq!(
            outcome,
            ControlFlow::Break(stop_after),
            "the break value comes back"
        );
        assert_eq!(
            seen.len(),
            stop_after,
            "no increment is solved after the stop"
        );
        let full = march(&contact, &history, &options, |_, _| {}).expect("marches");
        assert_eq!(
            seen,
            full.steps[..stop_after],
            "the increments before the stop are those of the whole march"
        );
    }

    #[test]
    fn an_observer_that_never_breaks_gives_the_march_result() {
        let (contact, history, options) = reference_march();
        let full = march(&contact, &history, &options, |_, _| {}).expect("marches");
        let mut calls = 0;
        let outcome = march_until(&contact, &history, &options, |_, _| {
            calls += 1;
            ControlFlow::<()>::Continue(())
        })
        .expect("marches");
        assert_eq!(calls, history.loads().len(), "one call per increment");
        assert_eq!(
            outcome,
            ControlFlow::Continue(full),
            "the same result as march"
        );
    }
}
