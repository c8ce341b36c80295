//! Errors as Python exceptions. The exception classes live in `halfplane/errors.py` (they need
//! multiple inheritance: `InputError` is both a `HalfplaneError` and a `ValueError`). An error's
//! class comes from the library's [`halfplane::Error::kind`] and its `variant` from
//! [`halfplane::Error::name`], never from its text; it keeps the CLI's message (the error chain
//! joined by ": ", as `halfplane` prints it after "error: ").

use halfplane::error::Alternative;
use halfplane::Error;
use pyo3::exceptions::{PyBaseException, PyFileNotFoundError, PyOSError};
use pyo3::prelude::*;

/// The library's kind of an error decides its Python class (see `class_name`).
pub use halfplane::error::ErrorKind as Kind;

/// The class in `halfplane.errors` that errors of `kind` become: `InputError(HalfplaneError,
/// ValueError)`, `OutsideAnalysisError(HalfplaneError, ValueError)` or `SolverError(HalfplaneError,
/// RuntimeError)`.
pub fn class_name(kind: Kind) -> &'static str {
    match kind {
        Kind::Input => "InputError",
        Kind::OutsideAnalysis => "OutsideAnalysisError",
        Kind::Solver => "SolverError",
    }
}

/// The exception `kind(message)` with `.variant` set to the library's variant name (or None).
pub fn exception(py: Python<'_>, kind: Kind, message: &str, variant: Option<&str>) -> PyErr {
    let make = || -> PyResult<PyErr> {
        let class = py.import("halfplane.errors")?.getattr(class_name(kind))?;
        let value = class.call1((message,))?;
        value.setattr("variant", variant)?;
        Ok(PyErr::from_value(value))
    };
    make().unwrap_or_else(|e| e)
}

/// What to do next in Python, for an error that another route of the library may avoid.
fn hint(error: &Error) -> &'static str {
    match error.alternative() {
        Some(Alternative::March) => {
            " (halfplane.march, numerical time marching, has no such restriction: give the case a \
             history)"
        }
        Some(Alternative::OtherTest) => {
            " (choose another test geometry, or the other matching route: exact=True or \
             exact=False)"
        }
        None => "",
    }
}

/// A library error as its Python exception: the class by [`Error::kind`], `.variant` by
/// [`Error::name`].
pub fn from_library(py: Python<'_>, error: &Error) -> PyErr {
    let message = format!("{error}{}", hint(error));
    exception(py, error.kind(), &message, Some(error.name()))
}

/// One exception of every library error variant ([`halfplane::error::one_of_each`]), made as any
/// error is: for the test that every variant reaches Python with its own name and class.
#[pyfunction]
pub fn _error_examples(py: Python<'_>) -> Vec<(String, String, Py<PyBaseException>)> {
    halfplane::error::one_of_each()
        .iter()
        .map(|e| {
            (
                e.name().to_string(),
                e.kind().as_str().to_string(),
                from_library(py, e).into_value(py),
            )
        })
        .collect()
}

/// A run refused by its size estimate: an `InputError` whose variant is `"TooLarge"`, with the
/// keyword that lifts the limit.
pub fn too_large(py: Python<'_>, error: &halfplane_case::limits::TooLarge) -> PyErr {
    let message = format!("{error} (pass no_size_limit=True to run it anyway)");
    exception(py, Kind::Input, &message, Some("TooLarge"))
}

/// A front-end error (case file, report) as its Python exception: the library error in its chain
/// decides the class; an I/O error is `FileNotFoundError` or `OSError`; anything else is bad input
/// (the case file's own checks). `hide` is removed from the message (a temporary directory).
pub fn from_anyhow(py: Python<'_>, error: &anyhow::Error, hide: Option<&str>) -> PyErr {
    let mut message = format!("{error:#}");
    if let Some(h) = hide {
        message = message.replace(h, "");
    }
    if let Some(e) = error.chain().find_map(|e| e.downcast_ref::<Error>()) {
        message.push_str(hint(e));
        return exception(py, e.kind(), &message, Some(e.name()));
    }
    if let Some(io) = error
        .chain()
        .find_map(|e| e.downcast_ref::<std::io::Error>())
    {
        return match io.kind() {
            std::io::ErrorKind::NotFound => PyFileNotFoundError::new_err(message),
            _ => PyOSError::new_err(message),
        };
    }
    exception(py, Kind::Input, &message, None)
}
