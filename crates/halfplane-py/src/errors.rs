//! Errors as Python exceptions. The exception classes live in `halfplane/errors.py` (they need
//! multiple inheritance: `InputError` is both a `HalfplaneError` and a `ValueError`); an error is
//! classified by the library's variant, never by its text, and keeps the CLI's message (the
//! error chain joined by ": ", as `halfplane` prints it after "error: ").

use halfplane::Error;
use pyo3::exceptions::{PyFileNotFoundError, PyOSError};
use pyo3::prelude::*;

/// The Python class an error becomes.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Kind {
    /// `InputError(HalfplaneError, ValueError)`: a value, field or column is invalid.
    Input,
    /// `OutsideAnalysisError(HalfplaneError, ValueError)`: the case is valid but outside what the
    /// analysis covers (gross sliding where partial slip is needed, slip reversing in a half).
    OutsideAnalysis,
    /// `SolverError(HalfplaneError, RuntimeError)`: a numerical solve or the worker pool failed.
    Solver,
}

impl Kind {
    fn class_name(self) -> &'static str {
        match self {
            Kind::Input => "InputError",
            Kind::OutsideAnalysis => "OutsideAnalysisError",
            Kind::Solver => "SolverError",
        }
    }

    /// The class of a library error.
    pub fn of(error: &Error) -> Self {
        match error {
            Error::SlipReversal { .. }
            | Error::SlipReversesInHalf { .. }
            | Error::NoStickZone { .. }
            | Error::StickZoneOutsideContact { .. }
            | Error::GrossSliding { .. }
            | Error::AsymptoticBreakdown { .. }
            | Error::SlidesAtStep { .. } => Kind::OutsideAnalysis,
            Error::ActiveSet { .. }
            | Error::NonPositivePivot { .. }
            | Error::NoConvergence { .. }
            | Error::NotSteady { .. }
            | Error::ThreadPool { .. } => Kind::Solver,
            _ => Kind::Input,
        }
    }
}

/// The exception `kind(message)` with `.variant` set to the library's variant name (or None).
pub fn exception(py: Python<'_>, kind: Kind, message: &str, variant: Option<&str>) -> PyErr {
    let make = || -> PyResult<PyErr> {
        let class = py.import("halfplane.errors")?.getattr(kind.class_name())?;
        let value = class.call1((message,))?;
        value.setattr("variant", variant)?;
        Ok(PyErr::from_value(value))
    };
    make().unwrap_or_else(|e| e)
}

/// The variant's name as the Rust enum spells it (`InvalidInput`, `SlipReversesInHalf`, ...), so
/// that Python code can tell errors apart without reading messages.
fn variant_name(error: &Error) -> &'static str {
    match error {
        Error::InvalidInput { .. } => "InvalidInput",
        Error::InvalidCount { .. } => "InvalidCount",
        Error::TooManyIncrements { .. } => "TooManyIncrements",
        Error::InvalidRow { .. } => "InvalidRow",
        Error::EmptyTable { .. } => "EmptyTable",
        Error::TooManyRows { .. } => "TooManyRows",
        Error::InvalidTable { .. } => "InvalidTable",
        Error::BeyondTable { .. } => "BeyondTable",
        Error::SlipReversal { .. } => "SlipReversal",
        Error::SlipReversesInHalf { .. } => "SlipReversesInHalf",
        Error::NoStickZone { .. } => "NoStickZone",
        Error::StickZoneOutsideContact { .. } => "StickZoneOutsideContact",
        Error::GrossSliding { .. } => "GrossSliding",
        Error::AsymptoticBreakdown { .. } => "AsymptoticBreakdown",
        Error::SlidesAtStep { .. } => "SlidesAtStep",
        Error::ActiveSet { .. } => "ActiveSet",
        Error::NonPositivePivot { .. } => "NonPositivePivot",
        Error::NoConvergence { .. } => "NoConvergence",
        Error::NotSteady { .. } => "NotSteady",
        Error::InvalidText { .. } => "InvalidText",
        Error::NotUsed { .. } => "NotUsed",
        Error::ThreadPool { .. } => "ThreadPool",
        _ => "Other",
    }
}

/// What to do next, for a cycle outside the steady-state analysis (chosen by the variant).
fn hint(error: &Error) -> &'static str {
    match error {
        Error::SlipReversesInHalf { .. } | Error::StickZoneOutsideContact { .. } => {
            " (halfplane.march, numerical time marching, has no such restriction: give the case a \
             history)"
        }
        _ => "",
    }
}

/// A library error as its Python exception.
pub fn from_library(py: Python<'_>, error: &Error) -> PyErr {
    let message = format!("{error}{}", hint(error));
    exception(py, Kind::of(error), &message, Some(variant_name(error)))
}

/// A front-end error (case file, report) as its Python exception: the library error in its chain
/// decides the class; an I/O error is `FileNotFoundError` or `OSError`; anything else is bad input
/// (the case file's own checks). `hide` is removed from the message (a temporary directory).
/// A run refused by its size estimate: an `InputError` whose variant is `"TooLarge"`, with the
/// keyword that lifts the limit.
pub fn too_large(py: Python<'_>, error: &halfplane_case::limits::TooLarge) -> PyErr {
    let message = format!("{error} (pass no_size_limit=True to run it anyway)");
    exception(py, Kind::Input, &message, Some("TooLarge"))
}

pub fn from_anyhow(py: Python<'_>, error: &anyhow::Error, hide: Option<&str>) -> PyErr {
    let mut message = format!("{error:#}");
    if let Some(h) = hide {
        message = message.replace(h, "");
    }
    if let Some(e) = error.chain().find_map(|e| e.downcast_ref::<Error>()) {
        message.push_str(hint(e));
        return exception(py, Kind::of(e), &message, Some(variant_name(e)));
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
