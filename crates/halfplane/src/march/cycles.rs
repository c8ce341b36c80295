//! The march driver: [`march`] sizes the grid from the whole history, steps a [`Marcher`]
//! through it, and accounts each cycle (its energy and per-cell peak-to-peak slip range) and the
//! shakedown test (the first cycle the next one repeats).
//!
//! Owns the cycle accounting. Never changes the marcher's state except through
//! [`Marcher::step`], and never prints or writes: the observer sees each increment.

use super::marcher::Marcher;
use super::types::{CycleReport, Fields, MarchOptions, MarchResult, StepReport};
use crate::error::Result;
use crate::history::History;
use crate::normal::Contact;

/// Marches through `history`. `observer` sees each increment's report and fields as it is made
/// (for progress bars and field output); nothing is printed or written here.
pub fn march(
    contact: &Contact,
    history: &History,
    options: &MarchOptions,
    mut observer: impl FnMut(&StepReport, &Fields),
) -> Result<MarchResult> {
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
        observer(&report, &marcher.fields());
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
    Ok(MarchResult {
        x: marcher.x.clone(),
        steps,
        cycles,
        shakedown_cycle,
    })
}
