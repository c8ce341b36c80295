//! `steady_batch` on numpy columns: every row solved by [`halfplane::batch::SteadyRow`] on the
//! library's batch engine ([`Batch::fill`]: each worker writes its own rows of the output arrays),
//! with the GIL released; between chunks the calling thread takes the GIL back just long enough
//! to see Ctrl-C.

use crate::errors;
use halfplane::batch::{
    self, Batch, ProfileKind, SteadyRow, SteadySummary, STEADY_INPUT_COLUMNS, STEADY_NUMBERS,
};
use halfplane::{Error, Regime, SteadyOptions};
use numpy::{PyArray1, PyArray2, PyArrayMethods, PyReadonlyArray1};
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

/// Regime codes, the numbers of `STEADY_COLUMNS` as one (`STEADY_NUMBERS`, rows) array (a column
/// per row of it), the failed rows, in order, and their messages.
type Output<'py> = (
    Bound<'py, PyArray1<i8>>,
    Bound<'py, PyArray2<f64>>,
    Bound<'py, PyArray1<i64>>,
    Vec<String>,
);

/// The columns one worker writes: regime codes and the eight numbers, for a block of rows.
type Block<'a> = (&'a mut [i8], [&'a mut [f64]; STEADY_NUMBERS]);

/// `values` (STEADY_NUMBERS x rows, row-major) as one slice per column.
fn number_columns(values: &mut [f64], rows: usize) -> [&mut [f64]; STEADY_NUMBERS] {
    let mut rest = values;
    std::array::from_fn(|_| {
        let (column, tail) = std::mem::take(&mut rest).split_at_mut(rows);
        rest = tail;
        column
    })
}

/// Solves the rows of the columns (in the order of `numeric_columns`; `None` for an absent profile
/// parameter) with profile `profile_names[profile_index[i]]` (-1: missing), on `threads` workers
/// (`None`: `HALFPLANE_NUM_THREADS` if set, else every core), each worker writing its own rows of
/// the output.
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
                    let mismatch = Error::LengthMismatch {
                        field: format!("column {name:?}"),
                        length: s.len(),
                        expected: rows,
                        per: "one value per row of the profile column",
                    };
                    return Err(errors::from_library(py, &mismatch));
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
    let threads = match threads {
        Some(n) => Some(n),
        None => {
            let value = std::env::var_os(batch::THREADS_VARIABLE).unwrap_or_default();
            batch::threads_from_text(&value.to_string_lossy())
                .map_err(|e| errors::from_library(py, &e))?
        }
    };
    let batch = Batch::new(threads).map_err(|e| errors::from_library(py, &e))?;
    let options = SteadyOptions::default();
    let value = |column: usize, row: usize| slices[column].map_or(f64::NAN, |s| s[row]);
    let summary = |i: usize| -> Result<SteadySummary, Error> {
        let kind = match usize::try_from(index[i]).ok().and_then(|k| kinds.get(k)) {
            Some(Ok(k)) => *k,
            Some(Err(e)) => return Err(e.clone()),
            None => {
                return Err(Error::InvalidText {
                    field: "profile".into(),
                    value: String::new(),
                    valid: "one of \"hertz\", \"flat-rounded\", \"power-law\" (the row has none)",
                })
            }
        };
        let v = |c: usize| value(c, i);
        // The moments default to 0 where the table has no such column.
        let m = |c: usize| slices[c].map_or(0.0, |s| s[i]);
        SteadyRow {
            youngs_modulus: v(0),
            poisson_ratio: v(1),
            friction: v(2),
            profile: kind,
            shape: [v(3), v(4), v(5), v(6)],
            point1: [v(7), v(8), v(9)],
            point2: [v(10), v(11), v(12)],
            moment: [m(13), m(14)],
        }
        .steady_summary(&options)
    };
    // The outputs are numpy's own arrays, written in place while the GIL is released: numpy
    // backs large arrays with huge pages, so the first write into 65 bytes per row faults far
    // less than a fresh Vec does. Every row writes all its values: the zeros are never read.
    let regimes = PyArray1::<i8>::zeros(py, rows, false);
    let numbers = PyArray2::<f64>::zeros(py, [STEADY_NUMBERS, rows], false);
    let mut regimes_view = regimes.readwrite();
    let mut numbers_view = numbers.readwrite();
    let contiguous = |e: numpy::AsSliceError| PyValueError::new_err(e.to_string());
    let out: Block = (
        regimes_view.as_slice_mut().map_err(contiguous)?,
        number_columns(numbers_view.as_slice_mut().map_err(contiguous)?, rows),
    );
    let solve = |first: usize, (regime, mut numbers): Block| -> Vec<(usize, String)> {
        let mut failed = Vec::new();
        for (k, code_out) in regime.iter_mut().enumerate() {
            let row = match summary(first + k) {
                Ok(s) => {
                    *code_out = code(s.regime());
                    s.numbers()
                }
                Err(e) => {
                    *code_out = -1;
                    failed.push((first + k, e.to_string()));
                    [f64::NAN; STEADY_NUMBERS]
                }
            };
            for (column, x) in numbers.iter_mut().zip(row) {
                column[k] = x;
            }
        }
        failed
    };
    let mut failed: Vec<(usize, String)> = Vec::new();
    let outcome = py.detach(|| {
        batch.fill(out, solve, |_, blocks| {
            failed.extend(blocks.into_iter().flatten());
            match Python::attach(|py| py.check_signals()) {
                Ok(()) => ControlFlow::Continue(()),
                Err(interrupt) => ControlFlow::Break(interrupt),
            }
        })
    });
    match outcome {
        Err(e) => Err(errors::from_library(py, &e)),
        Ok(Some(interrupt)) => Err(interrupt),
        Ok(None) => {
            let (failed_rows, messages): (Vec<i64>, Vec<String>) =
                failed.into_iter().map(|(r, m)| (r as i64, m)).unzip();
            drop((regimes_view, numbers_view));
            Ok((
                regimes,
                numbers,
                PyArray1::from_vec(py, failed_rows),
                messages,
            ))
        }
    }
}
