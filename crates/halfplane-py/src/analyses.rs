//! The single-case analyses: `steady`, `evolve` and `march`. Each computes with the GIL released
//! and returns the CLI's own report (the same rows and JSON), which the Python layer turns into
//! result objects and DataFrames. A march, which may run for minutes, takes the GIL back between
//! increments every so often to see Ctrl-C.

use crate::case::PyCase;
use crate::errors;
use halfplane::march::{self, Fields};
use halfplane::{asymptotic, evolution, steady, Regime, SteadyOptions};
use halfplane_case::limits;
use halfplane_case::report::evolve::EvolveReport;
use halfplane_case::report::march::MarchReport;
use halfplane_case::report::steady::SteadyReport;
use numpy::{PyArray1, PyArrayMethods};
use pyo3::exceptions::PyMemoryError;
use pyo3::prelude::*;
use pyo3::types::PyDict;
use std::ops::ControlFlow;
use std::time::{Duration, Instant};

/// `steady --json` of the case, and the note the CLI prints on stderr when the asymptotic
/// estimate is unavailable.
#[pyfunction]
pub fn steady_json(py: Python<'_>, case: &PyCase) -> PyResult<(String, Option<String>)> {
    let case = &case.case;
    let cycle = case
        .cycle()
        .map_err(|e| errors::from_anyhow(py, &e, None))?;
    let contact = &case.contact;
    let computed = py.detach(|| {
        let state = steady::analyse(contact, &cycle, &SteadyOptions::default())?;
        let asym = match state.regime {
            Regime::PartialSlip => Some(asymptotic::steady(contact, &cycle)),
            _ => None,
        };
        Ok::<_, halfplane::Error>((state, asym))
    });
    let (state, asym) = computed.map_err(|e| errors::from_library(py, &e))?;
    let asym_ok = asym.as_ref().and_then(|a| a.as_ref().ok());
    let report = SteadyReport::new(contact, &state, asym_ok, &case.units)
        .map_err(|e| errors::from_anyhow(py, &e, None))?;
    let json = report
        .json()
        .map_err(|e| errors::from_anyhow(py, &e.into(), None))?;
    let note = match asym {
        Some(Err(e)) => Some(format!("no asymptotic estimate: {e}")),
        _ => None,
    };
    Ok((json, note))
}

/// `evolve --csv` of the case at `points` points per half, the regime, and the warnings the CLI
/// prints on stderr.
#[pyfunction]
pub fn evolve_csv(
    py: Python<'_>,
    case: &PyCase,
    points: usize,
) -> PyResult<(String, &'static str, Vec<String>)> {
    let case = &case.case;
    let cycle = case
        .cycle()
        .map_err(|e| errors::from_anyhow(py, &e, None))?;
    let contact = &case.contact;
    let ev = py
        .detach(|| evolution::evolve(contact, &cycle, points, &SteadyOptions::default()))
        .map_err(|e| errors::from_library(py, &e))?;
    let report = EvolveReport::new(&ev, &case.units);
    Ok((report.csv(), ev.regime.as_str(), report.warnings().to_vec()))
}

/// Fields of every increment, increments x cells, in one allocation each.
struct Recorded {
    cells: usize,
    pressure: Vec<f64>,
    traction: Vec<f64>,
    slip: Vec<f64>,
    slip_increment: Vec<f64>,
}

impl Recorded {
    /// Room for `increments` x `cells` values of each field, or None when memory cannot be had.
    fn new(increments: usize, cells: usize) -> Option<Self> {
        let n = increments.checked_mul(cells)?;
        let vec = || {
            let mut v = Vec::new();
            v.try_reserve_exact(n).ok().map(|_| v)
        };
        Some(Self {
            cells,
            pressure: vec()?,
            traction: vec()?,
            slip: vec()?,
            slip_increment: vec()?,
        })
    }

    fn observe(&mut self, f: &Fields) {
        self.pressure.extend_from_slice(f.pressure);
        self.traction.extend_from_slice(f.traction);
        self.slip.extend_from_slice(f.slip);
        self.slip_increment.extend_from_slice(f.slip_increment);
    }
}

/// How often a march takes the GIL back, between increments, to see Ctrl-C: often enough that an
/// interrupt feels immediate, rarely enough that the check costs nothing measurable.
const SIGNAL_CHECK_INTERVAL: Duration = Duration::from_millis(50);

/// Marches the case's history (until its cycle repeats for `history.cycles = "steady"`):
/// `march --csv` (the steps), the cycles (index, energy, largest slip amplitude, as
/// `march --json`), the shakedown cycle, `cycles_run`, `steady_change` and `steady_converged`
/// (as `march --json`), the cell centres and, with `fields`, the four fields of every increment
/// as (increments, cells) arrays. Unless `no_size_limit`, a march estimated to take too long, or
/// fields too large for memory, is refused before it starts (`halfplane_case::limits`).
#[pyfunction]
#[pyo3(signature = (case, cells=None, fields=false, no_size_limit=false))]
pub fn march_report<'py>(
    py: Python<'py>,
    case: &PyCase,
    cells: Option<usize>,
    fields: bool,
    no_size_limit: bool,
) -> PyResult<Bound<'py, PyDict>> {
    let case = &case.case;
    let (history, until_steady) = case
        .march_history()
        .map_err(|e| errors::from_anyhow(py, &e, None))?;
    let steady = case.steady();
    let options = case
        .solver_with_cells_named(cells, "cells")
        .map_err(|e| errors::from_anyhow(py, &e, None))?;
    if !no_size_limit {
        let field = match cells {
            Some(n) => format!("cells={n}"),
            None => format!("solver.cells = {}", options.cells()),
        };
        let planned = limits::planned_increments(&history, until_steady.as_ref());
        let checked = limits::check_march(planned, &options, &field).and_then(|()| match fields {
            true => limits::check_fields_memory(planned, &options, &field),
            false => Ok(()),
        });
        checked.map_err(|e| errors::too_large(py, &e))?;
    }
    // Marched until steady, the fields grow past the history's one cycle as the march goes.
    let increments = history.loads().len();
    let mut recorded = match fields {
        true => Some(Recorded::new(increments, options.cells()).ok_or_else(|| {
            PyMemoryError::new_err(format!(
                "fields=True needs 4 x {increments} increments x {} cells x 8 bytes; use fewer \
                 cells or increments",
                options.cells()
            ))
        })?),
        false => None,
    };
    let contact = &case.contact;
    let mut last_check = Instant::now();
    let outcome = py.detach(|| {
        let observer = |_: &march::StepReport, f: &Fields| {
            if let Some(r) = recorded.as_mut() {
                r.observe(f);
            }
            if last_check.elapsed() < SIGNAL_CHECK_INTERVAL {
                return ControlFlow::Continue(());
            }
            last_check = Instant::now();
            match Python::attach(|py| py.check_signals()) {
                Ok(()) => ControlFlow::Continue(()),
                Err(interrupt) => ControlFlow::Break(interrupt),
            }
        };
        match &until_steady {
            Some(s) => march::march_steady_until(contact, &history, s, &options, observer),
            None => march::march_until(contact, &history, &options, observer),
        }
    });
    let result = match outcome.map_err(|e| errors::from_library(py, &e))? {
        ControlFlow::Continue(result) => result,
        ControlFlow::Break(interrupt) => return Err(interrupt),
    };
    let report = MarchReport::new(&result, &case.units, &steady, until_steady.is_some());
    let out = PyDict::new(py);
    out.set_item("steps_csv", report.csv())?;
    let cycles: Vec<(usize, f64, f64)> = result
        .cycles
        .iter()
        .map(|c| (c.index, c.energy, c.max_slip_amplitude()))
        .collect();
    out.set_item("cycles", cycles)?;
    out.set_item("shakedown_cycle", result.shakedown_cycle)?;
    out.set_item("cycles_run", result.cycles.len())?;
    out.set_item("steady_change", result.steady_change)?;
    out.set_item(
        "steady_converged",
        result.steady_change.map(|c| steady.is_met(c)),
    )?;
    out.set_item("x", PyArray1::from_vec(py, result.x.clone()))?;
    if let Some(r) = recorded {
        let shape = [result.steps.len(), r.cells];
        for (name, values) in [
            ("pressure", r.pressure),
            ("traction", r.traction),
            ("slip", r.slip),
            ("slip_increment", r.slip_increment),
        ] {
            out.set_item(name, PyArray1::from_vec(py, values).reshape(shape)?)?;
        }
    }
    Ok(out)
}
