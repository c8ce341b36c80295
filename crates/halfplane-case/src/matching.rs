//! `match`: the test loads that reproduce a prototype's contact-edge state, written as a complete
//! test case (docs/matching.md). [`compute`] finds them and writes nothing: the command writes
//! the files, the Python package returns the text.

use crate::case::Case;
use anyhow::{anyhow, bail, Result};
use halfplane::history::History;
use halfplane::matching::{self, MatchReport, Mode};
use halfplane::written::Written;
use halfplane::{Contact, Error, Friction, LoadPoint, Material, Profile};
use std::fmt::Write as _;
use std::path::{Path, PathBuf};

/// The profile kinds a matched test may have.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum TestProfile {
    /// Parabolic, needs `radius`.
    Hertz,
    /// Flat punch with rounded edges, needs `flat_half_width` and `radius`.
    FlatRounded,
    /// g = B|x|^k, needs `coefficient` and `exponent`.
    PowerLaw,
}

/// The test geometry and how to match it: `halfplane match`'s options and Python's keywords.
/// Material and friction default to the prototype's.
#[derive(Clone, Debug, PartialEq)]
pub struct TestOptions {
    /// The test's profile kind.
    pub profile: TestProfile,
    /// hertz: radius R; flat-rounded: edge radius R (length).
    pub radius: Option<f64>,
    /// flat-rounded: flat half-width b >= 0 (length).
    pub flat_half_width: Option<f64>,
    /// power-law: B > 0 in g = B|x|^k.
    pub coefficient: Option<f64>,
    /// power-law: k in g = B|x|^k, 1 <= k <= 64.
    pub exponent: Option<f64>,
    /// The test's Young's modulus E (default: the prototype's).
    pub youngs_modulus: Option<f64>,
    /// The test's Poisson's ratio (default: the prototype's).
    pub poisson_ratio: Option<f64>,
    /// The test's friction coefficient f (default: the prototype's).
    pub friction: Option<f64>,
    /// The exact match (K_N at both points, the exact slip zones at point2) instead of the
    /// asymptotic one.
    pub exact: bool,
    /// The prototype's edge whose K_N the test takes (under a moment, or on an asymmetric
    /// profile, the two edges' differ); `None`: the edge whose K_T changes more over the cycle.
    pub edge: Option<halfplane::Edge>,
}

/// What `match` runs on.
#[derive(Debug, Clone)]
pub struct MatchConfig {
    /// The prototype's case (it has a `[cycle]`).
    pub prototype: Case,
    /// The prototype's file, named in the test case's header and the report.
    pub prototype_path: PathBuf,
    /// The prototype's `[history]`, `[solver]` and `[units]` as written, carried over.
    pub carried: toml::Table,
    /// The test contact.
    pub test: Contact,
    /// Asymptotic or exact.
    pub mode: Mode,
    /// The prototype's edge whose K_N the test takes (`None`: the edge whose K_T changes more).
    pub edge: Option<halfplane::Edge>,
    /// The test case file to name (the mapped history's table is named after it).
    pub output: PathBuf,
}

impl MatchConfig {
    /// The configuration of a prototype already read: `text` is its case file (its `[history]`,
    /// `[solver]` and `[units]` are carried over as written), `prototype_path` the name the test
    /// case's header and the report give it, `output` the test case file to name.
    pub fn from_case(
        prototype: Case,
        text: &str,
        prototype_path: PathBuf,
        test: &TestOptions,
        output: PathBuf,
    ) -> Result<Self> {
        prototype.cycle()?;
        let raw: toml::Table = toml::from_str(text.strip_prefix('\u{feff}').unwrap_or(text))
            .map_err(|e| anyhow!("{}", e.to_string().trim_end()))?;
        let carried = raw
            .into_iter()
            .filter(|(k, _)| ["history", "solver", "units"].contains(&k.as_str()))
            .collect();
        Ok(Self {
            test: test_contact(test, &prototype.contact)?,
            prototype,
            prototype_path,
            carried,
            mode: mode(test),
            edge: test.edge,
            output,
        })
    }
}

/// The exact match when asked for, else the asymptotic one.
pub fn mode(args: &TestOptions) -> Mode {
    if args.exact {
        Mode::Exact
    } else {
        Mode::Asymptotic
    }
}

/// The test contact from the geometry options; material and friction default to the
/// prototype's. Every error names the option, its value and what is valid.
pub fn test_contact(args: &TestOptions, prototype: &Contact) -> Result<Contact> {
    let (kind, used): (&str, &[&str]) = match args.profile {
        TestProfile::Hertz => ("hertz", &["--radius"]),
        TestProfile::FlatRounded => ("flat-rounded", &["--flat-half-width", "--radius"]),
        TestProfile::PowerLaw => ("power-law", &["--coefficient", "--exponent"]),
    };
    for (name, given) in [
        ("--radius", args.radius),
        ("--flat-half-width", args.flat_half_width),
        ("--coefficient", args.coefficient),
        ("--exponent", args.exponent),
    ] {
        if given.is_some() && !used.contains(&name) {
            bail!(
                "{name} is not used by --profile {kind} (it takes: {})",
                used.join(", ")
            );
        }
    }
    let need = |v: Option<f64>, name: &str, what: &str| {
        v.ok_or_else(|| anyhow!("missing {name}: --profile {kind} needs {what}"))
    };
    let profile = match args.profile {
        TestProfile::Hertz => Profile::hertz(need(args.radius, "--radius", "the radius R > 0")?),
        TestProfile::FlatRounded => Profile::flat_rounded(
            need(
                args.flat_half_width,
                "--flat-half-width",
                "the flat half-width b >= 0",
            )?,
            need(args.radius, "--radius", "the edge radius R > 0")?,
        ),
        TestProfile::PowerLaw => Profile::power_law(
            need(args.coefficient, "--coefficient", "B > 0 in g = B|x|^k")?,
            need(
                args.exponent,
                "--exponent",
                "k with 1 <= k <= 64 in g = B|x|^k",
            )?,
        ),
    }
    .map_err(option_error)?;
    let material = Material::new(
        args.youngs_modulus
            .unwrap_or(prototype.material().youngs_modulus()),
        args.poisson_ratio
            .unwrap_or(prototype.material().poisson_ratio()),
    )
    .map_err(option_error)?;
    let friction = Friction::new(args.friction.unwrap_or(prototype.friction().value()))
        .map_err(option_error)?;
    Ok(Contact::new(profile, material, friction))
}

/// A constructor's error with its case-file field renamed to the command-line option.
fn option_error(e: Error) -> anyhow::Error {
    match e {
        Error::InvalidInput {
            field,
            value,
            valid,
        } => {
            let option = match field.as_str() {
                "profile.radius" => "--radius",
                "profile.flat_half_width" => "--flat-half-width",
                "profile.coefficient" => "--coefficient",
                "profile.exponent" => "--exponent",
                "material.youngs_modulus" => "--youngs-modulus",
                "material.poisson_ratio" => "--poisson-ratio",
                "friction.coefficient" => "--friction",
                other => other,
            };
            anyhow!("invalid {option} = {}: must be {valid}", Written(value))
        }
        other => other.into(),
    }
}

/// What `match` finds: the library's report, the warnings and notes (one line each), the test
/// case's TOML and, when the prototype's `[history]` is not the in-phase cycle, the mapped history
/// as `(path, CSV)` that the test case names (beside `output`).
pub struct Matched {
    /// The matched test and its comparison with the prototype.
    pub report: MatchReport,
    /// Warnings and notes, as the command prints them on stderr.
    pub notes: Vec<String>,
    /// The test case file's text.
    pub test_case: String,
    /// The mapped `[history]` rows, `normal,shear,bulk`, and the path to write them to.
    pub history_csv: Option<(PathBuf, String)>,
}

/// Finds the test and builds the test case, writing nothing: what `halfplane match` writes and
/// prints, which the Python package returns too.
pub fn compute(config: &MatchConfig) -> Result<Matched> {
    let cycle = config.prototype.cycle()?;
    let report = matching::match_cycle_at(
        &config.prototype.contact,
        &cycle,
        &config.test,
        config.mode,
        config.edge,
    )?;
    let mut notes: Vec<String> = report
        .warnings
        .iter()
        .map(|w| format!("warning: {w}"))
        .collect();
    let (history, history_csv) = match mapped_history(config, &report, &mut notes)? {
        Some((section, csv)) => (Some(section), csv),
        None => (None, None),
    };
    let test_case = test_case(config, &report, history.as_ref())?;
    Ok(Matched {
        report,
        notes,
        test_case,
        history_csv,
    })
}

/// The test case's `[history]` section and the CSV it names (path, text), if any.
type MappedHistory = (toml::Table, Option<(PathBuf, String)>);

/// The test's `[history]`: the prototype's carried over when it is the in-phase cycle (it refers
/// to `[cycle]`, which now holds the test's points); otherwise every row mapped by the asymptotic
/// match, as a CSV to write beside the test case: returned as the section naming it and
/// `(path, CSV)`.
fn mapped_history(
    config: &MatchConfig,
    report: &MatchReport,
    notes: &mut Vec<String>,
) -> Result<Option<MappedHistory>> {
    let Some(toml::Value::Table(section)) = config.carried.get("history") else {
        return Ok(None);
    };
    if section.get("kind").and_then(|k| k.as_str()) == Some("cycle") {
        return Ok(Some((section.clone(), None)));
    }
    let history: History = config.prototype.history()?;
    let rows = matching::map_history_at(
        &config.prototype.contact,
        &report.test.contact,
        history.loads(),
        report.prototype.edge,
    )?;
    if config.mode == Mode::Exact {
        notes.push(
            "note: the [history] rows were mapped by the asymptotic match (K_N and K_T at both \
             edges equal at every row); the exact match is defined at the cycle's two points only"
                .into(),
        );
    }
    let stem = config
        .output
        .file_stem()
        .and_then(|s| s.to_str())
        .unwrap_or("test");
    let name = format!("{stem}-history.csv");
    let path = config.output.parent().unwrap_or(Path::new("")).join(&name);
    let mut csv = String::from("normal,shear,bulk\n");
    for r in &rows {
        let _ = writeln!(csv, "{:?},{:?},{:?}", r.normal(), r.shear(), r.bulk());
    }
    let mut table = toml::Table::new();
    table.insert("file".into(), toml::Value::String(name));
    Ok(Some((table, Some((path, csv)))))
}

/// The test case as TOML: the test's material, friction, profile and cycle, then the carried
/// sections. Numbers are written in Rust's shortest round-trip form, so they read back exactly.
fn test_case(
    config: &MatchConfig,
    report: &MatchReport,
    history: Option<&toml::Table>,
) -> Result<String> {
    let c = &report.test.contact;
    let mut o = String::new();
    let _ = writeln!(
        o,
        "# Test case matched to the prototype {} by `halfplane match` ({} match).",
        config.prototype_path.display(),
        config.mode
    );
    let _ = writeln!(
        o,
        "[material]\nyoungs_modulus = {:?}\npoisson_ratio = {:?}\n",
        c.material().youngs_modulus(),
        c.material().poisson_ratio()
    );
    let _ = writeln!(o, "[friction]\ncoefficient = {:?}\n", c.friction().value());
    let _ = writeln!(o, "[profile]");
    match c.profile().shape() {
        halfplane::Shape::Hertz { radius } => {
            let _ = writeln!(o, "kind = \"hertz\"\nradius = {radius:?}");
        }
        halfplane::Shape::FlatRounded {
            flat_half_width,
            edge_radius,
        } => {
            let _ = writeln!(
                o,
                "kind = \"flat-rounded\"\nflat_half_width = {flat_half_width:?}\nradius = {edge_radius:?}"
            );
        }
        halfplane::Shape::PowerLaw {
            coefficient,
            exponent,
        } => {
            let _ = writeln!(
                o,
                "kind = \"power-law\"\ncoefficient = {coefficient:?}\nexponent = {exponent:?}"
            );
        }
        halfplane::Shape::Tabulated { .. } => bail!("a tabulated test profile cannot be written"),
    }
    let (first, second) = report.test.cycle.as_given();
    let point = |p: LoadPoint| {
        format!(
            "{{ normal = {:?}, shear = {:?}, bulk = {:?} }}",
            p.normal(),
            p.shear(),
            p.bulk()
        )
    };
    let _ = writeln!(
        o,
        "\n[cycle]\npoint1 = {}\npoint2 = {}",
        point(first),
        point(second)
    );
    let mut rest = toml::Table::new();
    if let Some(h) = history {
        rest.insert("history".into(), toml::Value::Table(h.clone()));
    }
    for key in ["solver", "units"] {
        if let Some(v) = config.carried.get(key) {
            rest.insert(key.into(), v.clone());
        }
    }
    if !rest.is_empty() {
        o.push('\n');
        o.push_str(&toml::to_string(&rest)?);
    }
    Ok(o)
}
