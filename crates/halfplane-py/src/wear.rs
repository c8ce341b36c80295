//! `wear`: fretting wear over `[wear] cycles` load cycles (`halfplane wear`). Runs the library's
//! cycle-jumping loop on the case's worn march (with any `[wear]` fields the caller overrides)
//! with the GIL released, and hands back the command's `--json` report with its `checkpoints` as
//! one numpy array per `--csv` column, plus the fields of every checkpoint (`--fields`) as
//! (checkpoints, cells) arrays.

use crate::analyses::{csv_keys, SIGNAL_CHECK_INTERVAL};
use crate::case::{to_toml, PyCase};
use crate::convert;
use crate::errors;
use halfplane::fatigue::CycleTractions;
use halfplane::march::Worn;
use halfplane::wear::{self, CheckpointFields, CycleWear, WornCycle};
use halfplane::Error;
use halfplane_case::case::Reached;
use halfplane_case::report::wear::{WearReport, WearRow, LOOP_COLUMNS};
use numpy::{PyArray1, PyArrayMethods};
use pyo3::exceptions::PyBaseException;
use pyo3::prelude::*;
use pyo3::types::PyDict;
use std::time::Instant;

/// The worn march, taking the GIL back between cycles every so often to see Ctrl-C (the wear
/// loop's observer only runs at checkpoints, which may be many cycles apart).
struct Watched<'a> {
    worn: &'a mut Worn,
    last_check: Instant,
    /// The KeyboardInterrupt (or other signal handler's exception) that stopped the run.
    interrupt: Option<PyErr>,
}

impl WornCycle for Watched<'_> {
    fn x(&self) -> &[f64] {
        self.worn.x()
    }

    fn width(&self) -> f64 {
        self.worn.width()
    }

    fn elastic_approach(&self) -> f64 {
        self.worn.elastic_approach()
    }

    fn pressure_stiffness(&self) -> f64 {
        self.worn.pressure_stiffness()
    }

    fn cycle(&mut self, depth: &[f64]) -> halfplane::Result<CycleWear> {
        if self.last_check.elapsed() >= SIGNAL_CHECK_INTERVAL {
            self.last_check = Instant::now();
            if let Err(interrupt) = Python::attach(|py| py.check_signals()) {
                self.interrupt = Some(interrupt);
                // Stops the loop; `wear_report` raises the interrupt instead of this error.
                return Err(Error::NoCycle {
                    what: "wear run (interrupted)",
                });
            }
        }
        self.worn.cycle(depth)
    }

    fn tractions(&mut self) -> halfplane::Result<Option<CycleTractions>> {
        self.worn.tractions()
    }
}

/// The fields of a checkpoint, as `--fields` names its columns after `x`.
type Field = fn(&CheckpointFields) -> &[f64];
const FIELDS: [(&str, Field); 6] = [
    ("depth", |f| &f.depth),
    ("depth_pad", |f| &f.depth_pad),
    ("depth_specimen", |f| &f.depth_specimen),
    ("pressure", |f| &f.pressure),
    ("traction", |f| &f.traction),
    ("slip_range", |f| &f.slip_range),
];

/// `wear_report`'s result: the report, the parameters `--fatigue` leaves out, and the error of a
/// run that stopped part way (raised by the Python side, with the report attached).
type WearOutcome<'py> = (Bound<'py, PyDict>, Vec<String>, Option<Py<PyBaseException>>);

/// `halfplane wear CASE --cells CELLS --json` with the `[wear]` fields in `overrides` (a dict of
/// the section's fields, e.g. `{"cycles": 1000}`) put in: the report as a dict whose
/// `checkpoints` are one array per `--csv` column, with `x` (the cell centres) and each field of
/// `--fields` as a (checkpoints, cells) array, and the fretting loops as (checkpoints, points)
/// arrays `loop_shear` and `loop_relative_displacement`. With `fatigue` (`--fatigue`), the
/// checkpoints gain the columns `fatigue.<parameter>.<field>` of the `--csv`, and the second item
/// of the result lists the parameters `[fatigue]` leaves out (the command's warnings). A run
/// that stops part way after reaching some checkpoints returns their report (`stopped` set,
/// `simulated_cycles` None) with the exception to raise; one that reaches none raises it.
#[pyfunction]
#[pyo3(signature = (case, cells=None, overrides=None, fatigue=false))]
pub fn wear_report<'py>(
    py: Python<'py>,
    case: &PyCase,
    cells: Option<usize>,
    overrides: Option<&Bound<'py, PyDict>>,
    fatigue: bool,
) -> PyResult<WearOutcome<'py>> {
    let case = &case.case;
    let input = |e: anyhow::Error| errors::from_anyhow(py, &e, None);
    let evaluator = fatigue
        .then(|| case.wear_fatigue("the case"))
        .transpose()
        .map_err(input)?;
    let settings = match overrides.map(|d| to_toml(d.as_any(), "wear")).transpose()? {
        Some(toml::Value::Table(t)) if !t.is_empty() => case.wear_with(&t),
        _ => case.wear(),
    }
    .map_err(input)?;
    let options = &settings.options;
    // Building the march marches the ramp: released too.
    let mut worn = py
        .detach(|| case.worn_march_named(&settings, cells, "cells"))
        .map_err(input)?;
    if evaluator.is_some() {
        worn.record_tractions();
    }
    let (approach, datum) = (worn.elastic_approach(), worn.loop_datum());
    let skipped = evaluator
        .as_ref()
        .map_or_else(Vec::new, |f| f.skipped.clone());
    let mut reached = Reached::new(evaluator, worn.unworn_contact());
    let mut watched = Watched {
        worn: &mut worn,
        last_check: Instant::now(),
        interrupt: None,
    };
    let outcome = py.detach(|| wear::run(&mut watched, options, |c| reached.observe(c)));
    if let Some(interrupt) = watched.interrupt {
        return Err(interrupt);
    }
    if let Some(e) = reached.error.take() {
        return Err(input(e));
    }
    let checkpoints = &reached.checkpoints;
    let (simulated, stopped) = match &outcome {
        Ok(r) => (Some(r.simulated_cycles), None),
        Err(e) => (None, Some(e.to_string())),
    };
    let error = match outcome {
        Ok(_) => None,
        Err(e) if checkpoints.is_empty() => return Err(errors::from_library(py, &e)),
        Err(e) => Some(errors::from_library(py, &e).into_value(py)),
    };
    let mut report = WearReport::new(
        checkpoints,
        simulated,
        approach,
        datum,
        options,
        &case.units,
        stopped,
    );
    if reached.with_fatigue() {
        report = report.with_fatigue(&reached.parameters);
    }
    let (summary, rows) = convert::to_node(&report)?.take("checkpoints");
    let out = summary.into_py(py)?.cast_into::<PyDict>()?;
    let keys = csv_keys(&WearRow::COLUMNS);
    let columns = convert::columns(py, &rows, &keys)?;
    for (name, values) in report.fatigue_table() {
        let numbers: Vec<f64> = values.iter().map(|v| v.unwrap_or(f64::NAN)).collect();
        columns.set_item(name, PyArray1::from_vec(py, numbers))?;
    }
    out.set_item("checkpoints", columns)?;
    let x = worn.x().to_vec();
    let shape = [checkpoints.len(), x.len()];
    out.set_item("x", PyArray1::from_vec(py, x))?;
    for (name, field) in FIELDS {
        let values: Vec<f64> = checkpoints
            .iter()
            .flat_map(|c| field(&c.fields).iter().copied())
            .collect();
        out.set_item(name, PyArray1::from_vec(py, values).reshape(shape)?)?;
    }
    // Every checkpoint's cycle has the same increments, so its loop as many points.
    let points = checkpoints.first().map_or(0, |c| c.fretting_loop.len());
    for (name, value) in LOOP_COLUMNS {
        let values: Vec<f64> = checkpoints
            .iter()
            .flat_map(|c| c.fretting_loop.iter().map(value))
            .collect();
        out.set_item(
            format!("loop_{name}"),
            PyArray1::from_vec(py, values).reshape([checkpoints.len(), points])?,
        )?;
    }
    Ok((out, skipped, error))
}
