//! `match`: the test that reproduces a prototype's contact-edge state. It runs the CLI's own
//! [`halfplane_case::matching::compute`] (the same test contact from the options, the same report
//! and test case text), writing no file; the report reaches Python as nested dicts
//! ([`crate::convert`]), not JSON text.

use crate::case::PyCase;
use crate::convert;
use crate::errors;
use halfplane_case::matching::{compute, MatchConfig};
use halfplane_case::matching::{TestOptions, TestProfile};
use halfplane_case::report::matching::MatchReportOut;
use pyo3::prelude::*;
use std::path::PathBuf;

/// The name the report and the test case's header give a prototype from Python.
const PROTOTYPE_NAME: &str = "<prototype>";
/// The test case's file name: the mapped history's table is named after it.
const TEST_NAME: &str = "test.toml";

/// `halfplane match CASE -o test.toml --json` with the test options: the report as nested dicts,
/// the test case (read back from the text `match` writes) and the warnings and notes.
#[pyfunction]
#[pyo3(signature = (case, profile, radius=None, flat_half_width=None, coefficient=None,
    exponent=None, youngs_modulus=None, poisson_ratio=None, friction=None, exact=false, edge=None))]
#[allow(clippy::too_many_arguments)]
pub fn match_report<'py>(
    py: Python<'py>,
    case: &PyCase,
    profile: &str,
    radius: Option<f64>,
    flat_half_width: Option<f64>,
    coefficient: Option<f64>,
    exponent: Option<f64>,
    youngs_modulus: Option<f64>,
    poisson_ratio: Option<f64>,
    friction: Option<f64>,
    exact: bool,
    edge: Option<&str>,
) -> PyResult<(Bound<'py, PyAny>, PyCase, String, Vec<String>)> {
    let input = |e: anyhow::Error| errors::from_anyhow(py, &e, None);
    let profile = match profile {
        "hertz" => TestProfile::Hertz,
        "flat-rounded" => TestProfile::FlatRounded,
        "power-law" => TestProfile::PowerLaw,
        other => {
            return Err(input(anyhow::anyhow!(
            "invalid profile = \"{other}\": must be \"hertz\", \"flat-rounded\" or \"power-law\""
        )))
        }
    };
    let edge = match edge {
        None => None,
        Some("left") => Some(halfplane::Edge::Left),
        Some("right") => Some(halfplane::Edge::Right),
        Some(other) => {
            return Err(input(anyhow::anyhow!(
                "invalid edge = \"{other}\": must be \"left\" or \"right\" (or None: the edge whose K_T changes more)"
            )))
        }
    };
    let test = TestOptions {
        profile,
        radius,
        flat_half_width,
        coefficient,
        exponent,
        youngs_modulus,
        poisson_ratio,
        friction,
        exact,
        edge,
    };
    let config = MatchConfig::from_case(
        case.case.clone(),
        &case.text,
        PathBuf::from(PROTOTYPE_NAME),
        &test,
        PathBuf::from(TEST_NAME),
    )
    .map_err(input)?;
    let matched = py.detach(|| compute(&config)).map_err(input)?;
    let report = MatchReportOut::new(&matched.report, &config, &matched.notes);
    let report = convert::to_node(&report)?.into_py(py)?;
    // The mapped history's table, by the name the test case gives it (no file is written).
    let tables = matched
        .history_csv
        .iter()
        .map(|(path, csv)| (path.display().to_string(), csv.clone()))
        .collect();
    let test_case = PyCase::from_tables(py, &matched.test_case, &tables)?;
    Ok((report, test_case, matched.test_case, matched.notes))
}
