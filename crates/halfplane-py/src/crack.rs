//! `crack`: will a crack grow (`halfplane crack`). Runs the library's analysis on the case's
//! `[crack]` (with any fields the caller overrides) with the GIL released, and hands back the
//! command's report: the `--json` object with its `rows` as one numpy array per `--csv` column.

use crate::analyses::csv_keys;
use crate::case::{to_toml, PyCase};
use crate::convert;
use crate::errors;
use halfplane::crack;
use halfplane_case::report::crack::{CrackReport, CrackRow};
use pyo3::prelude::*;
use pyo3::types::PyDict;

/// `halfplane crack CASE --cells CELLS --json` with the `[crack]` fields in `overrides` (a dict
/// of the section's fields, e.g. `{"lengths": [0.01, 0.02]}`) put in: the report as a dict whose
/// `rows` are one array per `--csv` column.
#[pyfunction]
#[pyo3(signature = (case, cells=None, overrides=None))]
pub fn crack_report<'py>(
    py: Python<'py>,
    case: &PyCase,
    cells: Option<usize>,
    overrides: Option<&Bound<'py, PyDict>>,
) -> PyResult<Bound<'py, PyAny>> {
    let case = &case.case;
    let input = |e: anyhow::Error| errors::from_anyhow(py, &e, None);
    let options = match overrides
        .map(|d| to_toml(d.as_any(), "crack"))
        .transpose()?
    {
        Some(toml::Value::Table(t)) if !t.is_empty() => case.crack_with(&t),
        _ => case.crack(),
    }
    .map_err(input)?;
    let constants = case.fatigue().map_err(input)?.constants;
    let history = case.history().map_err(input)?;
    let march = case
        .solver_with_cells_named(cells, "cells")
        .map_err(input)?;
    let contact = &case.contact;
    let result = py
        .detach(|| crack::analyse(contact, &history, &march, &constants, &options))
        .map_err(|e| errors::from_library(py, &e))?;
    let report = CrackReport::new(&result, &case.units);
    let (summary, rows) = convert::to_node(&report)?.take("rows");
    let out = summary.into_py(py)?;
    out.set_item(
        "rows",
        convert::columns(py, &rows, &csv_keys(&CrackRow::COLUMNS))?,
    )?;
    Ok(out)
}
