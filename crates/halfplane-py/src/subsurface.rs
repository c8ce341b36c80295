//! Below the surface: `stress` (the stresses at points at one marched increment) and `fatigue`
//! (the initiation parameters over the steady cycle). Both run the CLI's own functions and report
//! rows with the GIL released, so the numbers are the command's by construction; the reports
//! reach Python as objects and numpy arrays, not text ([`crate::convert`]).

use crate::analyses::csv_keys;
use crate::case::PyCase;
use crate::convert;
use crate::errors;
use halfplane::fatigue;
use halfplane_case::report::fatigue::{FatigueReport, FatigueRow};
use halfplane_case::stress as stress_command;
use numpy::{PyArray1, PyReadonlyArray1};
use pyo3::prelude::*;
use pyo3::types::PyDict;

/// `halfplane stress CASE --step STEP` at the points `(x[i], z[i])` (z the depth, >= 0): the
/// increment used, its load (`step`, `normal`, `shear`, `bulk`, `half_width`, `moment`,
/// `contact_left`, `contact_right`) and the arrays
/// `sxx`, `szz`, `syy`, `sxz`, one value per point.
#[pyfunction]
#[pyo3(signature = (case, x, z, step=None, cells=None))]
pub fn stress_points<'py>(
    py: Python<'py>,
    case: &PyCase,
    x: PyReadonlyArray1<'py, f64>,
    z: PyReadonlyArray1<'py, f64>,
    step: Option<usize>,
    cells: Option<usize>,
) -> PyResult<Bound<'py, PyDict>> {
    let case = &case.case;
    let x: Vec<f64> = x.as_array().iter().copied().collect();
    let z: Vec<f64> = z.as_array().iter().copied().collect();
    let input = |e: anyhow::Error| errors::from_anyhow(py, &e, None);
    if x.len() > stress_command::MAX_POINTS {
        return Err(input(anyhow::anyhow!(
            "invalid x: {} points, more than the {} a run takes",
            x.len(),
            stress_command::MAX_POINTS
        )));
    }
    halfplane::stress::check_points(&x, &z).map_err(|e| errors::from_library(py, &e))?;
    let history = case.history().map_err(input)?;
    let options = case
        .solver_with_cells_named(cells, "cells")
        .map_err(input)?;
    let step = stress_command::check_step(step, &history, "step").map_err(input)?;
    let contact = &case.contact;
    let units = &case.units;
    let report = py
        .detach(|| stress_command::report(contact, &history, &options, step, &x, &z, units))
        .map_err(input)?;
    let out = PyDict::new(py);
    out.set_item("step", report.step)?;
    out.set_item("normal", report.normal)?;
    out.set_item("shear", report.shear)?;
    out.set_item("bulk", report.bulk)?;
    out.set_item("half_width", report.half_width)?;
    out.set_item("moment", report.moment)?;
    out.set_item("contact_left", report.contact_left)?;
    out.set_item("contact_right", report.contact_right)?;
    let column = |f: fn(&halfplane_case::report::stress::StressRow) -> f64| {
        PyArray1::from_iter(py, report.points.iter().map(f))
    };
    out.set_item("sxx", column(|r| r.sxx))?;
    out.set_item("szz", column(|r| r.szz))?;
    out.set_item("syy", column(|r| r.syy))?;
    out.set_item("sxz", column(|r| r.sxz))?;
    Ok(out)
}

/// `halfplane fatigue CASE --cells CELLS`: the `--json` report as a dict whose `parameters` are
/// one array per `--csv` column, plus `grid_x`, `grid_z` and `maps` (each grid parameter's
/// values over the `[fatigue]` grid, row after row, z outer), and the lines the command writes on
/// stderr for the parameters `[fatigue]` leaves out.
#[pyfunction]
#[pyo3(signature = (case, cells=None))]
pub fn fatigue_report<'py>(
    py: Python<'py>,
    case: &PyCase,
    cells: Option<usize>,
) -> PyResult<(Bound<'py, PyAny>, Vec<String>)> {
    let case = &case.case;
    let input = |e: anyhow::Error| errors::from_anyhow(py, &e, None);
    let settings = case.fatigue().map_err(input)?;
    let history = case.history().map_err(input)?;
    let options = case
        .solver_with_cells_named(cells, "cells")
        .map_err(input)?;
    let contact = &case.contact;
    let result = py
        .detach(|| {
            fatigue::analyse(
                contact,
                &history,
                &options,
                &settings.constants,
                &settings.grid,
            )
        })
        .map_err(|e| errors::from_library(py, &e))?;
    let report = FatigueReport::new(&result, &case.units);
    let (summary, rows) = convert::to_node(&report)?.take("parameters");
    let out = summary.into_py(py)?;
    let columns = convert::columns(py, &rows, &csv_keys(&FatigueRow::COLUMNS))?;
    out.set_item("parameters", columns)?;
    // The fields behind the maxima (what `plot fatigue-map` contours): the grid's axes and each
    // grid parameter's values row after row (z outer), kept out of the `--json` object.
    out.set_item("grid_x", PyArray1::from_slice(py, &result.grid_x))?;
    out.set_item("grid_z", PyArray1::from_slice(py, &result.grid_z))?;
    let maps = PyDict::new(py);
    for (parameter, values) in &result.maps {
        maps.set_item(parameter.name(), PyArray1::from_slice(py, values))?;
    }
    out.set_item("maps", maps)?;
    Ok((out, settings.skipped()))
}
