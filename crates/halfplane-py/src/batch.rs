//! `steady_batch` on numpy columns: every row solved by [`halfplane::batch::SteadyRow`] on the
//! library's batch engine, with the GIL released; between chunks the calling thread takes the GIL
//! back just long enough to see Ctrl-C.

use crate::errors;
use halfplane::batch::{Batch, ProfileKind, SteadyRow, SteadySummary, STEADY_INPUT_COLUMNS};
use halfplane::{Error, Regime, SteadyOptions};
use numpy::{PyArray1, PyReadonlyArray1};
use pyo3::exceptions::PyValueError;
use pyo3::prelude::*;
use std::ops::ControlFlow;

/// The regime names, by the codes [`steady_batch_columns`] returns (-1: the row failed).
pub const REGIMES: [&str; 3] = ["gross-sliding", "full-stick", "partial-slip"];

fn code(regime: Regime) -> i8 {
    match regime {
        Regime::GrossSliding { .. } => 0,
        Regime::FullStick => 1,
        Regime::PartialSlip => 2,
    }
}

/// The numeric input columns, in the order [`steady_batch_columns`] takes them: the library's
/// documented input columns without `profile` (passed as codes).
fn numeric_columns() -> impl Iterator<Item = &'static str> {
    STEADY_INPUT_COLUMNS.into_iter().filter(|c| *c != "profile")
}

/// How many numeric input columns there are.
const NUMERIC_COUNT: usize = STEADY_INPUT_COLUMNS.len() - 1;

/// Regime codes, the eight numbers of `STEADY_COLUMNS`, and (row, message) of failed rows.
type Output<'py> = (
    Bound<'py, PyArray1<i8>>,
    Vec<Bound<'py, PyArray1<f64>>>,
    Vec<(usize, String)>,
);

/// Solves the rows of the columns (in the order of `numeric_columns`; `None` for an absent profile
/// parameter) with profile `profile_names[profile_index[i]]` (-1: missing), on `threads` workers.
#[pyfunction]
#[pyo3(signature = (columns, profile_index, profile_names, threads=None))]
pub fn steady_batch_columns<'py>(
    py: Python<'py>,
    columns: Vec<Option<PyReadonlyArray1<'py, f64>>>,
    profile_index: PyReadonlyArray1<'py, i64>,
    profile_names: Vec<String>,
    threads: Option<usize>,
) -> PyResult<Output<'py>> {
    let index = profile_index
        .as_slice()
        .map_err(|e| PyValueError::new_err(format!("profile codes: {e}")))?;
    let rows = index.len();
    if columns.len() != NUMERIC_COUNT {
        return Err(PyValueError::new_err(format!(
            "expected {NUMERIC_COUNT} numeric columns, found {}",
            columns.len()
        )));
    }
    let mut slices: Vec<Option<&[f64]>> = Vec::with_capacity(NUMERIC_COUNT);
    for (name, column) in numeric_columns().zip(&columns) {
        let slice = match column {
            Some(c) => {
                let s = c
                    .as_slice()
                    .map_err(|e| PyValueError::new_err(format!("column {name:?}: {e}")))?;
                if s.len() != rows {
                    return Err(PyValueError::new_err(format!(
                        "column {name:?} has {} rows, the profile column {rows}",
                        s.len()
                    )));
                }
                Some(s)
            }
            None => None,
        };
        slices.push(slice);
    }
    let kinds: Vec<Result<ProfileKind, Error>> = profile_names
        .iter()
        .map(|n| ProfileKind::from_name(n))
        .collect();
    let batch = Batch::new(threads).map_err(|e| errors::from_library(py, &e))?;
    let options = SteadyOptions::default();
    let value = |column: usize, row: usize| slices[column].map_or(f64::NAN, |s| s[row]);
    let solve = |i: usize| -> Result<SteadySummary, Error> {
        let kind = match usize::try_from(index[i]).ok().and_then(|k| kinds.get(k)) {
            Some(k) => k.clone()?,
            None => {
                return Err(Error::InvalidText {
                    field: "profile".into(),
                    value: String::new(),
                    valid: "one of \"hertz\", \"flat-rounded\", \"power-law\" (the row has none)",
                })
            }
        };
        let v = |c: usize| value(c, i);
        SteadyRow {
            youngs_modulus: v(0),
            poisson_ratio: v(1),
            friction: v(2),
            profile: kind,
            shape: [v(3), v(4), v(5), v(6)],
            point1: [v(7), v(8), v(9)],
            point2: [v(10), v(11), v(12)],
        }
        .steady_summary(&options)
    };
    let mut regimes: Vec<i8> = Vec::with_capacity(rows);
    let mut numbers: [Vec<f64>; 8] = std::array::from_fn(|_| Vec::with_capacity(rows));
    let mut failed = Vec::new();
    let outcome = py.detach(|| {
        batch.run(rows, solve, |first, results| {
            for (k, r) in results.into_iter().enumerate() {
                match r {
                    Ok(s) => {
                        regimes.push(code(s.regime()));
                        for (column, x) in numbers.iter_mut().zip(s.numbers()) {
                            column.push(x);
                        }
                    }
                    Err(e) => {
                        regimes.push(-1);
                        for column in numbers.iter_mut() {
                            column.push(f64::NAN);
                        }
                        failed.push((first + k, e.to_string()));
                    }
                }
            }
            match Python::attach(|py| py.check_signals()) {
                Ok(()) => ControlFlow::Continue(()),
                Err(interrupt) => ControlFlow::Break(interrupt),
            }
        })
    });
    match outcome {
        Err(e) => Err(errors::from_library(py, &e)),
        Ok(Some(interrupt)) => Err(interrupt),
        Ok(None) => Ok((
            PyArray1::from_vec(py, regimes),
            numbers
                .into_iter()
                .map(|v| PyArray1::from_vec(py, v))
                .collect(),
            failed,
        )),
    }
}
