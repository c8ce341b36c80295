//! The native module `halfplane._halfplane` behind the Python package in `python/`. It holds no
//! physics and no formats of its own: cases are read by the command's case parser
//! (`halfplane_case::case`), reports are the command's report rows, converted to Python objects
//! and numpy arrays without text (the `convert` module), and batches run on [`halfplane::batch`].
//! The Python layer (`python/halfplane/__init__.py`) builds the public API (typed result classes,
//! DataFrames) on these functions.

mod analyses;
mod batch;
mod case;
mod convert;
mod crack;
mod errors;
mod matching;
mod subsurface;
mod wear;

use pyo3::prelude::*;

/// The native half of the `halfplane` package; use `halfplane` itself.
#[pymodule]
fn _halfplane(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_class::<case::PyCase>()?;
    m.add_function(wrap_pyfunction!(case::read_case, m)?)?;
    m.add_function(wrap_pyfunction!(case::_case_from_state, m)?)?;
    m.add_function(wrap_pyfunction!(analyses::steady_report, m)?)?;
    m.add_function(wrap_pyfunction!(analyses::evolve_report, m)?)?;
    m.add_function(wrap_pyfunction!(analyses::march_report, m)?)?;
    m.add_function(wrap_pyfunction!(batch::steady_batch_columns, m)?)?;
    m.add_function(wrap_pyfunction!(subsurface::stress_points, m)?)?;
    m.add_function(wrap_pyfunction!(subsurface::fatigue_report, m)?)?;
    m.add_function(wrap_pyfunction!(crack::crack_report, m)?)?;
    m.add_function(wrap_pyfunction!(matching::match_report, m)?)?;
    m.add_function(wrap_pyfunction!(wear::wear_report, m)?)?;
    m.add_function(wrap_pyfunction!(errors::_error_examples, m)?)?;
    m.add("REGIMES", batch::REGIMES.to_vec())?;
    m.add("STEADY_COLUMNS", halfplane::batch::STEADY_COLUMNS.to_vec())?;
    m.add(
        "STEADY_INPUT_COLUMNS",
        halfplane::batch::STEADY_INPUT_COLUMNS.to_vec(),
    )?;
    m.add(
        "SHAPE_COLUMNS",
        halfplane::batch::row::SHAPE_COLUMNS.to_vec(),
    )?;
    m.add("THREADS_VARIABLE", halfplane::batch::THREADS_VARIABLE)?;
    m.add("__version__", env!("CARGO_PKG_VERSION"))?;
    Ok(())
}
