//! The single-case analyses: `steady`, `evolve` and `march`. Each computes with the GIL released
//! and returns the CLI's own report as Python objects (nested dicts of floats and strings, numpy
//! columns for the row tables: [`crate::convert`], no JSON or CSV text in between), which the
//! Python layer wraps in typed result classes and DataFrames. A march, which may run for minutes,
//! takes the GIL back between increments every so often to see Ctrl-C.

use crate::case::PyCase;
use crate::convert::{self, Node};
use crate::errors;
use halfplane::march::{self, Fields};
use halfplane::{asymptotic, evolution, steady, Regime, SteadyOptions};
use halfplane_case::limits;
use halfplane_case::report::evolve::{EvolveReport, EvolveRow};
use halfplane_case::report::march::{MarchReport, MarchStepRow};
use halfplane_case::report::steady::SteadyReport;
use halfplane_case::report::{Cell, Column, Shown};
use numpy::{PyArray1, PyArrayMethods};
use pyo3::exceptions::PyMemoryError;
use pyo3::prelude::*;
use pyo3::types::PyDict;
use std::ops::ControlFlow;
use std::time::{Duration, Instant};

/// The keys of a report's CSV columns, in order.
pub(crate) fn csv_keys<R>(columns: &[Column<R>]) -> Vec<&'static str> {
    columns
        .iter()
        .filter(|c| c.shown != Shown::Table)
        .map(|c| c.key)
        .collect()
}

/// The `steady --json` report of the case as nested dicts, and the note the CLI prints on stderr
/// when the asymptotic estimate is unavailable.
#[pyfunction]
pub fn steady_report<'py>(
    py: Python<'py>,
    case: &PyCase,
) -> PyResult<(Bound<'py, PyAny>, Option<String>)> {
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
    let report = convert::to_node(&report)?.into_py(py)?;
    let note = match asym {
        Some(Err(e)) => Some(format!("no asymptotic estimate: {e}")),
        _ => None,
    };
    Ok((report, note))
}

/// The `evolve` report of the case at `points` points per half: its rows as one array per
/// `evolve --csv` column, the regime, and the warnings the CLI prints on stderr.
#[pyfunction]
pub fn evolve_report<'py>(
    py: Python<'py>,
    case: &PyCase,
    points: usize,
) -> PyResult<(Bound<'py, PyDict>, &'static str, Vec<String>)> {
    let case = &case.case;
    let cycle = case
        .cycle()
        .map_err(|e| errors::from_anyhow(py, &e, None))?;
    let contact = &case.contact;
    let ev = py
        .detach(|| evolution::evolve(contact, &cycle, points, &SteadyOptions::default()))
        .map_err(|e| errors::from_library(py, &e))?;
    let report = EvolveReport::new(&ev, &case.units);
    let node = convert::to_node(&report)?;
    let rows = node.get("points").unwrap_or(&Node::Null);
    let columns = convert::columns(py, rows, &csv_keys(&EvolveRow::COLUMNS))?;
    Ok((columns, ev.regime.as_str(), report.warnings().to_vec()))
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
pub(crate) const SIGNAL_CHECK_INTERVAL: Duration = Duration::from_millis(50);

/// A report cell as a Python value: a count as int, a number as float, text as str, a missing
/// value as None.
fn cell_node(cell: Cell) -> Node {
    match cell {
        Cell::Int(i) => Node::UInt(i as u64),
        Cell::Num(v) => Node::Float(v),
        Cell::Text(t) => Node::Str(t),
        Cell::Missing => Node::Null,
    }
}

/// One cycle as a row of `march --json`'s `cycles`.
fn cycle_row(c: &march::CycleReport) -> Node {
    Node::Map(vec![
        ("index".into(), Node::UInt(c.index as u64)),
        ("energy".into(), Node::Float(c.energy)),
        (
            "max_slip_amplitude".into(),
            Node::Float(c.max_slip_amplitude()),
        ),
    ])
}

/// Marches the case's history (until its cycle repeats for `history.cycles = "steady"`): the
/// steps (one array per `march --csv` column), the cycles (index, energy, largest slip amplitude,
/// as `march --json`), the shakedown cycle, `cycles_run`, `steady_change` and `steady_converged`
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
    let out = PyDict::new(py);
    // The rows of `march --csv`, through the report's own columns.
    let report = MarchReport::new(&result, &case.units, &steady, until_steady.is_some());
    let columns: Vec<&Column<MarchStepRow>> = MarchStepRow::COLUMNS
        .iter()
        .filter(|c| c.shown != Shown::Table)
        .collect();
    let steps: Vec<Node> = report
        .step_rows()
        .iter()
        .map(|row| {
            Node::Map(
                columns
                    .iter()
                    .map(|c| (c.key.to_string(), cell_node((c.get)(row))))
                    .collect(),
            )
        })
        .collect();
    let keys = csv_keys(&MarchStepRow::COLUMNS);
    out.set_item("steps", convert::columns(py, &Node::List(steps), &keys)?)?;
    let cycles = Node::List(result.cycles.iter().map(cycle_row).collect());
    let keys = ["index", "energy", "max_slip_amplitude"];
    out.set_item("cycles", convert::columns(py, &cycles, &keys)?)?;
    out.set_item("shakedown_cycle", result.shakedown_cycle)?;
    out.set_item("loop_datum", result.loop_datum())?;
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
