//! `halfplane.Case`: a case as the command reads it. Every case, however made (a file, TOML text,
//! keywords, unpickling), is resolved by the command's own case-file parser
//! (`halfplane_case::case`), so its checks and messages are the command's. A case also keeps its
//! canonical form: its TOML text with any tables (profile and history CSV) inline as
//! `data = """..."""`, which is what it pickles to and what makes two cases equal. Nothing is
//! written to disk.

use crate::errors;
use halfplane::Shape;
use halfplane_case::case::{self, Case};
use pyo3::exceptions::PyTypeError;
use pyo3::prelude::*;
use pyo3::types::{PyBool, PyDict, PyFloat, PyInt, PyList, PyString, PyTuple};
use std::collections::BTreeMap;
use std::fmt::Write;
use std::path::Path;

/// The sections that may hold a table, and the name `Case.tables` gives each table.
const TABLES: [(&str, &str); 2] = [("profile", "profile.csv"), ("history", "history.csv")];

/// A contact case: material, friction, profile and, optionally, a cycle, a load history and
/// solver settings (the sections of a case file).
#[pyclass(module = "halfplane._halfplane", name = "Case", frozen)]
pub struct PyCase {
    pub(crate) case: Case,
    pub(crate) text: String,
}

/// The canonical text of case text whose relative paths start at `dir`: every table named by a
/// `file` field inline as `data`, its text taken from `files` (by the name written) or read.
fn canonical(text: &str, dir: &Path, files: &BTreeMap<String, String>) -> anyhow::Result<String> {
    let mut doc: toml::Table = toml::from_str(text)?;
    for (section, _) in TABLES {
        let Some(table) = doc.get_mut(section).and_then(|s| s.as_table_mut()) else {
            continue;
        };
        let Some(file) = table.get("file").and_then(|f| f.as_str()) else {
            continue;
        };
        if table.contains_key("data") {
            // Both: left for the parser, which names both fields.
            continue;
        }
        let contents = match files.get(file) {
            Some(c) => c.clone(),
            None => std::fs::read_to_string(dir.join(file))?,
        };
        table.remove("file");
        table.insert("data".into(), toml::Value::String(contents));
    }
    Ok(toml::to_string(&doc)?)
}

impl PyCase {
    /// The case of text whose tables are inline or given in `files` (by the file names the text
    /// gives): those are put inline first, then the text is parsed from memory. Nothing is
    /// written; a table the text names by a file that `files` lacks is read from the current
    /// directory, as `Case.from_toml` reads it.
    pub(crate) fn from_tables(
        py: Python<'_>,
        text: &str,
        files: &BTreeMap<String, String>,
    ) -> PyResult<Self> {
        let text =
            canonical(text, Path::new(""), files).map_err(|e| errors::from_anyhow(py, &e, None))?;
        let case =
            case::parse(&text, Path::new("")).map_err(|e| errors::from_anyhow(py, &e, None))?;
        Ok(Self { case, text })
    }

    pub(crate) fn from_text(py: Python<'_>, text: &str, dir: &Path) -> PyResult<Self> {
        let text = text.strip_prefix('\u{feff}').unwrap_or(text);
        let case = case::parse(text, dir).map_err(|e| errors::from_anyhow(py, &e, None))?;
        let text = canonical(text, dir, &BTreeMap::new())
            .map_err(|e| errors::from_anyhow(py, &e, None))?;
        Ok(Self { case, text })
    }

    /// Reads a case file as `halfplane CASE` does.
    pub(crate) fn read(py: Python<'_>, path: &Path) -> PyResult<Self> {
        let case = case::load(path).map_err(|e| errors::from_anyhow(py, &e, None))?;
        let text = std::fs::read_to_string(path)
            .map_err(|e| errors::from_anyhow(py, &anyhow::Error::from(e), None))?;
        let text = text.strip_prefix('\u{feff}').unwrap_or(&text);
        let dir = path.parent().map(Path::to_path_buf).unwrap_or_default();
        let text = canonical(text, &dir, &BTreeMap::new())
            .map_err(|e| errors::from_anyhow(py, &e, None))?;
        Ok(Self { case, text })
    }
}

/// A Python value as a TOML value (numbers, strings, booleans, lists and dicts).
pub(crate) fn to_toml(value: &Bound<'_, PyAny>, field: &str) -> PyResult<toml::Value> {
    if value.is_instance_of::<PyBool>() {
        return Ok(toml::Value::Boolean(value.extract()?));
    }
    if value.is_instance_of::<PyInt>()
        || value.hasattr("__index__")? && !value.is_instance_of::<PyFloat>()
    {
        if let Ok(i) = value.extract::<i64>() {
            return Ok(toml::Value::Integer(i));
        }
    }
    if let Ok(x) = value.extract::<f64>() {
        if !value.is_instance_of::<PyString>() {
            return Ok(toml::Value::Float(x));
        }
    }
    if let Ok(s) = value.cast::<PyString>() {
        return Ok(toml::Value::String(s.to_string()));
    }
    if let Ok(d) = value.cast::<PyDict>() {
        let mut table = toml::Table::new();
        for (k, v) in d.iter() {
            let key: String = k.extract().map_err(|_| {
                PyTypeError::new_err(format!("{field}: keys must be strings, found {k:?}"))
            })?;
            let sub = format!("{field}.{key}");
            table.insert(key, to_toml(&v, &sub)?);
        }
        return Ok(toml::Value::Table(table));
    }
    if value.is_instance_of::<PyList>() || value.is_instance_of::<PyTuple>() {
        let items: Vec<Bound<'_, PyAny>> = value.extract()?;
        let list = items
            .iter()
            .map(|v| to_toml(v, field))
            .collect::<PyResult<Vec<_>>>()?;
        return Ok(toml::Value::Array(list));
    }
    Err(PyTypeError::new_err(format!(
        "{field}: cannot use a value of type {} (give numbers, strings, lists or dicts)",
        value.get_type().name()?
    )))
}

/// A load point given as `(P, Q)`, `(P, Q, sigma)`, `(P, Q, sigma, M)` or a dict with `normal`,
/// `shear`, `bulk`, `moment`.
fn point_table(value: &Bound<'_, PyAny>, field: &str) -> PyResult<toml::Value> {
    if value.is_instance_of::<PyDict>() {
        return to_toml(value, field);
    }
    let numbers: Vec<f64> = value.extract().map_err(|_| {
        PyTypeError::new_err(format!(
            "{field} must be (normal, shear[, bulk[, moment]]) numbers or a dict with those keys"
        ))
    })?;
    if !(2..=4).contains(&numbers.len()) {
        return Err(PyTypeError::new_err(format!(
            "{field} must have 2 to 4 numbers (normal P, shear Q[, bulk sigma[, moment M]]), found {}",
            numbers.len()
        )));
    }
    let mut t = toml::Table::new();
    for (key, x) in ["normal", "shear", "bulk", "moment"].iter().zip(numbers) {
        t.insert((*key).into(), toml::Value::Float(x));
    }
    Ok(toml::Value::Table(t))
}

/// CSV text with a header and one line per row (Rust's shortest round-trip numbers).
fn csv_table(header: &str, rows: &[Vec<f64>]) -> String {
    let mut o = format!("{header}\n");
    for r in rows {
        let cells: Vec<String> = r.iter().map(|x| format!("{x:?}")).collect();
        let _ = writeln!(o, "{}", cells.join(","));
    }
    o
}

fn section<'a>(doc: &'a mut toml::Table, name: &str) -> &'a mut toml::Table {
    doc.entry(name)
        .or_insert_with(|| toml::Value::Table(toml::Table::new()))
        .as_table_mut()
        .expect("sections are created as tables")
}

#[pymethods]
impl PyCase {
    /// Builds a case from keywords, the case file's fields (errors name them as the file does,
    /// e.g. `material.youngs_modulus`). Units are those of the numbers (N, mm, MPa by default).
    #[new]
    #[pyo3(signature = (*, youngs_modulus, poisson_ratio, friction, profile, radius=None,
        flat_half_width=None, coefficient=None, exponent=None, table=None, kinks=None,
        point1=None, point2=None, history=None, cells=None, slip_tolerance=None, units=None,
        left_radius=None, right_radius=None, sub_cell_boundaries=None))]
    #[allow(clippy::too_many_arguments)]
    fn new(
        py: Python<'_>,
        youngs_modulus: f64,
        poisson_ratio: f64,
        friction: f64,
        profile: String,
        radius: Option<f64>,
        flat_half_width: Option<f64>,
        coefficient: Option<f64>,
        exponent: Option<f64>,
        table: Option<(Vec<f64>, Vec<f64>)>,
        kinks: Option<Vec<f64>>,
        point1: Option<Bound<'_, PyAny>>,
        point2: Option<Bound<'_, PyAny>>,
        history: Option<Bound<'_, PyAny>>,
        cells: Option<i64>,
        slip_tolerance: Option<f64>,
        units: Option<Bound<'_, PyAny>>,
        left_radius: Option<f64>,
        right_radius: Option<f64>,
        sub_cell_boundaries: Option<bool>,
    ) -> PyResult<Self> {
        let mut doc = toml::Table::new();
        let m = section(&mut doc, "material");
        m.insert("youngs_modulus".into(), youngs_modulus.into());
        m.insert("poisson_ratio".into(), poisson_ratio.into());
        section(&mut doc, "friction").insert("coefficient".into(), friction.into());
        let p = section(&mut doc, "profile");
        p.insert("kind".into(), profile.into());
        for (key, value) in [
            ("radius", radius),
            ("left_radius", left_radius),
            ("right_radius", right_radius),
            ("flat_half_width", flat_half_width),
            ("coefficient", coefficient),
            ("exponent", exponent),
        ] {
            if let Some(v) = value {
                p.insert(key.into(), v.into());
            }
        }
        if let Some((x, g)) = table {
            if x.len() != g.len() {
                return Err(errors::exception(
                    py,
                    errors::Kind::Input,
                    &format!(
                        "table: x has {} values but g has {}; give equal-length x and g",
                        x.len(),
                        g.len()
                    ),
                    None,
                ));
            }
            let rows: Vec<Vec<f64>> = x.iter().zip(&g).map(|(x, g)| vec![*x, *g]).collect();
            p.insert("data".into(), csv_table("x,g", &rows).into());
        }
        if let Some(k) = kinks {
            p.insert(
                "kinks".into(),
                toml::Value::Array(k.into_iter().map(toml::Value::Float).collect()),
            );
        }
        if point1.is_some() || point2.is_some() {
            let c = section(&mut doc, "cycle");
            for (key, value) in [("point1", &point1), ("point2", &point2)] {
                if let Some(v) = value {
                    c.insert(key.into(), point_table(v, &format!("cycle.{key}"))?);
                }
            }
        }
        if let Some(h) = history {
            if h.is_instance_of::<PyDict>() {
                doc.insert("history".into(), to_toml(&h, "history")?);
            } else {
                let rows: Vec<Vec<f64>> = h.extract().map_err(|_| {
                    PyTypeError::new_err(
                        "history must be a dict (the [history] section's fields) or rows of \
                         (normal, shear, bulk[, moment]) numbers",
                    )
                })?;
                // Every row as long as the first: normal, shear, bulk and optionally moment.
                let width = rows.first().map_or(3, |r| r.len().clamp(3, 4));
                if let Some(bad) = rows.iter().position(|r| r.len() != width) {
                    return Err(errors::exception(
                        py,
                        errors::Kind::Input,
                        &format!(
                            "history row {}: has {} values; give normal, shear, bulk (and \
                             moment, in every row or none), {width} as the first row",
                            bad + 1,
                            rows[bad].len()
                        ),
                        None,
                    ));
                }
                // Checked here, so that a bad row is reported as the row of the list it is
                // ("history row 3"), not as a line of the CSV file the case keeps it in.
                let full: Vec<[f64; 4]> = rows
                    .iter()
                    .map(|r| [r[0], r[1], r[2], r.get(3).copied().unwrap_or(0.0)])
                    .collect();
                halfplane::history::History::from_moment_rows(&full)
                    .map_err(|e| errors::from_library(py, &e))?;
                let header = if width == 4 {
                    "normal,shear,bulk,moment"
                } else {
                    "normal,shear,bulk"
                };
                section(&mut doc, "history").insert("data".into(), csv_table(header, &rows).into());
            }
        }
        if cells.is_some() || slip_tolerance.is_some() || sub_cell_boundaries.is_some() {
            let s = section(&mut doc, "solver");
            if let Some(n) = cells {
                s.insert("cells".into(), n.into());
            }
            if let Some(t) = slip_tolerance {
                s.insert("slip_tolerance".into(), t.into());
            }
            if let Some(on) = sub_cell_boundaries {
                s.insert("sub_cell_boundaries".into(), on.into());
            }
        }
        if let Some(u) = units {
            doc.insert("units".into(), to_toml(&u, "units")?);
        }
        let text = toml::to_string(&doc).map_err(|e| PyTypeError::new_err(e.to_string()))?;
        Self::from_tables(py, &text, &BTreeMap::new())
    }

    /// Parses case-file text (TOML). Table files it names are read relative to `base_dir`
    /// (default: the current directory).
    #[staticmethod]
    #[pyo3(signature = (text, base_dir=None))]
    fn from_toml(
        py: Python<'_>,
        text: &str,
        base_dir: Option<std::path::PathBuf>,
    ) -> PyResult<Self> {
        Self::from_text(py, text, &base_dir.unwrap_or_else(|| ".".into()))
    }

    /// The canonical TOML text, complete in itself: tables are inline as `data = """..."""`.
    fn to_toml(&self) -> String {
        self.text.clone()
    }

    /// The CSV tables the case holds: `profile.csv` (a tabulated profile) and `history.csv` (a
    /// history's rows), as text.
    #[getter]
    fn tables(&self) -> BTreeMap<String, String> {
        let doc: toml::Table = toml::from_str(&self.text).unwrap_or_default();
        TABLES
            .iter()
            .filter_map(|(section, name)| {
                let data = doc.get(*section)?.get("data")?.as_str()?;
                Some((name.to_string(), data.to_string()))
            })
            .collect()
    }

    /// The profile kind: "hertz", "flat-rounded", "power-law" or "tabulated".
    #[getter]
    fn profile(&self) -> &'static str {
        kind(self.case.contact.profile().shape())
    }

    /// Young's modulus E of both bodies (stress unit, MPa by default).
    #[getter]
    fn youngs_modulus(&self) -> f64 {
        self.case.contact.material().youngs_modulus()
    }

    /// Poisson's ratio of both bodies.
    #[getter]
    fn poisson_ratio(&self) -> f64 {
        self.case.contact.material().poisson_ratio()
    }

    /// The Coulomb friction coefficient f.
    #[getter]
    fn friction(&self) -> f64 {
        self.case.contact.friction().value()
    }

    /// The composite compliance A = 4(1 - nu^2)/E.
    #[getter]
    fn compliance(&self) -> f64 {
        self.case.contact.compliance().value()
    }

    /// The first cycle point as given, (P, Q, sigma), or None without a cycle.
    #[getter]
    fn point1(&self) -> Option<(f64, f64, f64)> {
        self.case.cycle.map(|c| triple(c.as_given().0))
    }

    /// The second cycle point as given, (P, Q, sigma), or None without a cycle.
    #[getter]
    fn point2(&self) -> Option<(f64, f64, f64)> {
        self.case.cycle.map(|c| triple(c.as_given().1))
    }

    /// The moments M (about x = 0) at the first and second cycle points as given, or None
    /// without a cycle; (0.0, 0.0) without a moment.
    #[getter]
    fn moments(&self) -> Option<(f64, f64)> {
        self.case.cycle.map(|c| {
            let (a, b) = c.as_given();
            (a.moment(), b.moment())
        })
    }

    /// Increments of the load history, or None without one (or when it is marched until its
    /// cycle repeats, `cycles = "steady"`, so that its length is known only once marched).
    #[getter]
    fn increments(&self) -> Option<usize> {
        self.case.history().ok().map(|h| h.loads().len())
    }

    /// Cells of the marching grid (`[solver] cells`, default 400).
    #[getter]
    fn cells(&self) -> usize {
        self.case.solver.cells()
    }

    fn __repr__(&self) -> String {
        let c = &self.case.contact;
        let mut o = format!("Case(profile={:?}", kind(c.profile().shape()));
        match c.profile().shape() {
            Shape::Hertz { radius } => {
                let _ = write!(o, ", radius={radius:?}");
            }
            Shape::FlatRounded {
                flat_half_width,
                edge_radius,
            } => match c.profile().edge_radii() {
                Some((left, right)) if left != right => {
                    let _ = write!(
                        o,
                        ", left_radius={left:?}, right_radius={right:?}, flat_half_width={flat_half_width:?}"
                    );
                }
                _ => {
                    let _ = write!(
                        o,
                        ", radius={edge_radius:?}, flat_half_width={flat_half_width:?}"
                    );
                }
            },
            Shape::PowerLaw {
                coefficient,
                exponent,
            } => {
                let _ = write!(o, ", coefficient={coefficient:?}, exponent={exponent:?}");
            }
            Shape::Tabulated { x, .. } => {
                let _ = write!(o, ", table=<{} rows>", x.len());
            }
        }
        let _ = write!(
            o,
            ", youngs_modulus={:?}, poisson_ratio={:?}, friction={:?}",
            c.material().youngs_modulus(),
            c.material().poisson_ratio(),
            c.friction().value()
        );
        if let Some(cycle) = self.case.cycle {
            let (a, b) = cycle.as_given();
            let _ = write!(o, ", point1={:?}, point2={:?}", triple(a), triple(b));
            if a.moment() != 0.0 || b.moment() != 0.0 {
                let _ = write!(o, ", moments=({:?}, {:?})", a.moment(), b.moment());
            }
        }
        if let Ok((h, until_steady)) = self.case.march_history() {
            let _ = write!(o, ", history=<{} increments", h.loads().len());
            match (h.cycles(), until_steady) {
                (Some(_), Some(s)) => {
                    let _ = write!(o, ", cycles until steady (at most {})", s.max_cycles());
                }
                (Some(s), None) => {
                    let _ = write!(o, ", {} cycles", s.count());
                }
                (None, _) => {}
            }
            let _ = write!(o, ">, cells={}", self.case.solver.cells());
        }
        o.push(')');
        o
    }

    fn __eq__(&self, other: &Bound<'_, PyAny>) -> bool {
        other
            .cast::<PyCase>()
            .is_ok_and(|o| o.get().text == self.text)
    }

    #[allow(clippy::type_complexity)]
    fn __reduce__<'py>(
        slf: &Bound<'py, Self>,
    ) -> PyResult<(Bound<'py, PyAny>, (String, BTreeMap<String, String>))> {
        let py = slf.py();
        let f = py
            .import("halfplane._halfplane")?
            .getattr("_case_from_state")?;
        Ok((f, (slf.get().text.clone(), BTreeMap::new())))
    }
}

fn triple(p: halfplane::LoadPoint) -> (f64, f64, f64) {
    (p.normal(), p.shear(), p.bulk())
}

fn kind(shape: &Shape) -> &'static str {
    match shape {
        Shape::Hertz { .. } => "hertz",
        Shape::FlatRounded { .. } => "flat-rounded",
        Shape::PowerLaw { .. } => "power-law",
        Shape::Tabulated { .. } => "tabulated",
    }
}

/// Unpickles a case from its canonical text (`files`: the tables by the file names the text
/// gives, as pickles made before tables were inline hold them; empty now).
#[pyfunction]
pub fn _case_from_state(
    py: Python<'_>,
    text: String,
    files: BTreeMap<String, String>,
) -> PyResult<PyCase> {
    PyCase::from_tables(py, &text, &files)
}

/// Reads a case file (TOML), as `halfplane steady CASE` does; tables are read relative to it.
#[pyfunction]
pub fn read_case(py: Python<'_>, path: std::path::PathBuf) -> PyResult<PyCase> {
    PyCase::read(py, &path)
}
