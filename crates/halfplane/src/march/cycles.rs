//! The march driver: [`march`] sizes the grid from the whole history, steps a [`Marcher`]
//! through it, and accounts each cycle (its energy and per-cell peak-to-peak slip range), the
//! change of the slip ranges between consecutive cycles, and the shakedown test (the first
//! cycle the next one repeats). [`march_steady`] repeats the history's last cycle until that
//! change meets a [`Steady`] tolerance, so that no cycle count is guessed.
//!
//! Owns the cycle accounting. Never changes the marcher's state except through
//! [`Marcher::step`], and never prints or writes: the observer sees each increment and, through
//! [`march_until`] or [`march_steady_until`], may stop the march.

use super::marcher::Marcher;
use super::types::{CycleReport, Fields, MarchOptions, MarchResult, StepReport};
use crate::error::{Error, Result};
use crate::history::{CycleStructure, History, Steady, MAX_INCREMENTS};
use crate::labels::Edge;
use crate::load::LoadPoint;
use crate::normal::Contact;
use crate::normal_moment::NormalContact;
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
    uninterrupted(march_until(contact, history, options, |report, fields| {
        observer(report, fields);
        ControlFlow::<Infallible>::Continue(())
    }))
}

/// The result of a march whose observer never stops it.
fn uninterrupted(outcome: Result<ControlFlow<Infallible, MarchResult>>) -> Result<MarchResult> {
    match outcome? {
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
    observer: impl FnMut(&StepReport, &Fields) -> ControlFlow<B>,
) -> Result<ControlFlow<B, MarchResult>> {
    drive(contact, history, options, None, observer)
}

/// Marches through the ramp and cycles of `history`, then repeats its last cycle, until the
/// cycle repeats within `steady`'s tolerance ([`Steady`]: no cell's slip range over a cycle
/// changes by more than `tolerance A f P_max` from the previous cycle's). The march stops at the
/// end of the first cycle that repeats the one before, which may come before the history's own
/// cycles are done; the result's `cycles` then tell how many were run.
///
/// # Errors
/// Those of [`march`]; [`Error::NoCycle`] for a history without cycles;
/// [`Error::TooManyIncrements`] when the ramp and `max_cycles` cycles would pass
/// [`MAX_INCREMENTS`](crate::history::MAX_INCREMENTS); [`Error::NotSteady`] (naming the last
/// change) when `max_cycles` cycles go by without a repeat.
pub fn march_steady(
    contact: &Contact,
    history: &History,
    steady: &Steady,
    options: &MarchOptions,
    mut observer: impl FnMut(&StepReport, &Fields),
) -> Result<MarchResult> {
    uninterrupted(march_steady_until(
        contact,
        history,
        steady,
        options,
        |report, fields| {
            observer(report, fields);
            ControlFlow::<Infallible>::Continue(())
        },
    ))
}

/// [`march_steady`] with an observer that may stop the march, as in [`march_until`].
///
/// # Errors
/// Those of [`march_steady`], for the increments solved before a stop.
pub fn march_steady_until<B>(
    contact: &Contact,
    history: &History,
    steady: &Steady,
    options: &MarchOptions,
    observer: impl FnMut(&StepReport, &Fields) -> ControlFlow<B>,
) -> Result<ControlFlow<B, MarchResult>> {
    drive(contact, history, options, Some(steady), observer)
}

/// The increments to march: the history's loads, or, for a steady march, its ramp and cycles
/// with the last cycle repeated up to `max_cycles` cycles in all.
struct Plan<'a> {
    loads: &'a [LoadPoint],
    structure: Option<CycleStructure>,
    /// Cycles the plan may run (the history's count, or `max_cycles`).
    cycles: usize,
    total: usize,
}

impl<'a> Plan<'a> {
    fn new(history: &'a History, steady: Option<&Steady>) -> Result<Self> {
        let loads = history.loads();
        let structure = history.cycles();
        let Some(steady) = steady else {
            return Ok(Self {
                loads,
                structure,
                cycles: structure.map_or(0, |s| s.count()),
                total: loads.len(),
            });
        };
        let s = structure.ok_or(Error::NoCycle {
            what: "steady march (history.cycles = \"steady\")",
        })?;
        let total = s
            .steps_per_cycle()
            .checked_mul(steady.max_cycles())
            .and_then(|c| c.checked_add(s.first_step()))
            .filter(|&t| t <= MAX_INCREMENTS)
            .ok_or_else(|| Error::TooManyIncrements {
                field: "history.max_cycles x increments per cycle".into(),
                max: MAX_INCREMENTS,
            })?;
        Ok(Self {
            loads,
            structure,
            cycles: steady.max_cycles(),
            total,
        })
    }

    /// The load of increment `k` (0-based) and, inside a cycle, that cycle (0-based) and the
    /// increment's place in it.
    fn at(&self, k: usize) -> (LoadPoint, Option<(usize, usize)>) {
        let Some(s) = self.structure else {
            return (self.loads[k], None);
        };
        let Some(from_first) = k.checked_sub(s.first_step()) else {
            return (self.loads[k], None);
        };
        let (c, place) = (
            from_first / s.steps_per_cycle(),
            from_first % s.steps_per_cycle(),
        );
        if c >= self.cycles {
            return (self.loads[k], None);
        }
        let source = c.min(s.count() - 1);
        let load = self.loads[s.first_step() + source * s.steps_per_cycle() + place];
        (load, Some((c, place)))
    }
}

fn drive<B>(
    contact: &Contact,
    history: &History,
    options: &MarchOptions,
    steady: Option<&Steady>,
    mut observer: impl FnMut(&StepReport, &Fields) -> ControlFlow<B>,
) -> Result<ControlFlow<B, MarchResult>> {
    let plan = Plan::new(history, steady)?;
    // A History is valid by construction: at least one row, every load a valid LoadPoint.
    let p_max = history
        .loads()
        .iter()
        .map(|p| p.normal())
        .fold(0.0, f64::max);
    let mut marcher =
        if contact.profile().is_symmetric() && history.loads().iter().all(|p| p.moment() == 0.0) {
            Marcher::new(contact, contact.half_width(p_max)?, options)?
        } else {
            Marcher::spanning(contact, grid_span(contact, history)?, options)?
        };
    let n = options.cells();
    let slip_scale = contact.compliance().value() * contact.friction.value() * p_max;
    let mut steps = Vec::with_capacity(history.loads().len());
    let mut cycles: Vec<CycleReport> = Vec::new();
    let mut steady_change = None;
    let (mut low, mut high) = (vec![0.0; n], vec![0.0; n]);
    let mut cycle_energy_start = 0.0;
    let steps_per_cycle = plan.structure.map_or(0, |s| s.steps_per_cycle());
    for k in 0..plan.total {
        let (load, place) = plan.at(k);
        if place.is_some_and(|(_, i)| i == 0) {
            let (slip, _, energy, _) = marcher.reported();
            low.copy_from_slice(slip);
            high.copy_from_slice(slip);
            cycle_energy_start = energy;
        }
        let report = marcher.step(load)?;
        if let ControlFlow::Break(value) = observer(&report, &marcher.fields()) {
            return Ok(ControlFlow::Break(value));
        }
        steps.push(report);
        let Some((c, i)) = place else { continue };
        let (slip, _, energy, _) = marcher.reported();
        for j in 0..n {
            low[j] = low[j].min(slip[j]);
            high[j] = high[j].max(slip[j]);
        }
        if i + 1 < steps_per_cycle {
            continue;
        }
        let cycle = CycleReport {
            index: c + 1,
            energy: energy - cycle_energy_start,
            slip_range: high.iter().zip(&low).map(|(h, l)| h - l).collect(),
        };
        steady_change = cycles
            .last()
            .map(|previous| range_change(&previous.slip_range, &cycle.slip_range, slip_scale));
        cycles.push(cycle);
        if let (Some(s), Some(change)) = (steady, steady_change) {
            if s.is_met(change) {
                break;
            }
            if c + 1 == plan.cycles {
                return Err(Error::NotSteady {
                    max_cycles: s.max_cycles(),
                    change,
                    tolerance: s.tolerance(),
                });
            }
        }
    }
    let shakedown_cycle = shakedown(&cycles, options.shakedown_tolerance(), slip_scale, p_max);
    Ok(ControlFlow::Continue(MarchResult {
        x: marcher.x.clone(),
        steps,
        cycles,
        shakedown_cycle,
        steady_change,
    }))
}

/// The grid of a march whose contacts are not centred (a moment, or an asymmetric profile): the
/// span of every row's contact, widened by 1% of its length at each end, since an end may pass
/// beyond both rows of an increment between them (the march refuses a load whose contact leaves
/// the grid, naming it).
fn grid_span(contact: &Contact, history: &History) -> Result<[f64; 2]> {
    let mut near: Option<NormalContact> = None;
    let (mut lower, mut upper) = (f64::INFINITY, f64::NEG_INFINITY);
    for (k, load) in history.loads().iter().enumerate() {
        let found = match &near {
            Some(n) => contact.contact_near(load.normal(), load.moment(), n),
            None => contact.contact_at(load),
        }
        .map_err(|e| e.with_moment_field(&format!("history row {}.moment", k + 1)))?;
        lower = lower.min(found.end(Edge::Left));
        upper = upper.max(found.end(Edge::Right));
        near = Some(found);
    }
    let margin = 0.01 * (upper - lower);
    Ok([lower - margin, upper + margin])
}

/// The largest change of a cell's slip range between two cycles, as a fraction of `scale`
/// (`A f P_max`, the scale of [`Steady`]'s tolerance).
fn range_change(previous: &[f64], current: &[f64], scale: f64) -> f64 {
    previous
        .iter()
        .zip(current)
        .fold(0.0f64, |m, (a, b)| m.max((a - b).abs()))
        / scale
}

/// The first cycle that the next one repeats: slip ranges within `tol` of the largest range and
/// energies within `tol` (each with a floor of 1e-12 of `slip_scale`, so that cycles with no
/// slip compare equal rather than by rounding).
fn shakedown(cycles: &[CycleReport], tol: f64, slip_scale: f64, p_max: f64) -> Option<usize> {
    let slip_floor = 1e-12 * slip_scale;
    cycles.windows(2).find_map(|w| {
        let scale = w[0].slip_range.iter().fold(slip_floor, |m, v| m.max(*v));
        let ranges = w[0]
            .slip_range
            .iter()
            .zip(&w[1].slip_range)
            .all(|(a, b)| (a - b).abs() <= tol * scale);
        let energy =
            (w[0].energy - w[1].energy).abs() <= tol * w[0].energy.abs().max(slip_floor * p_max);
        (ranges && energy).then_some(w[0].index)
    })
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
