//! The case file: raw TOML is parsed first, then resolved into validated library values. Every
//! error names the field (as the file spells it) and what would be valid.

use anyhow::{anyhow, bail, Context, Result};
use halfplane::history::{Harmonic, History, Ramp};
use halfplane::march::MarchOptions;
use halfplane::{Contact, Cycle, Friction, LoadPoint, Material, Profile};
use serde::{Deserialize, Deserializer};
use std::io::BufRead;
use std::path::Path;

/// The range of `solver.cells` and `--cells`: the library's (its maximum is set by memory).
const MIN_CELLS: usize = MarchOptions::MIN_CELLS;
const MAX_CELLS: usize = MarchOptions::MAX_CELLS;

/// A count as the case file gives it. Any TOML value is taken here and checked when resolved,
/// so that the error names the field, the value and the valid range (serde's own message would
/// say "expected usize", and a negative or huge integer would not name the field).
#[derive(Debug, Clone, PartialEq)]
enum RawCount {
    Integer(i128),
    Float(f64),
    /// Anything else, as written.
    Other(String),
}

impl<'de> Deserialize<'de> for RawCount {
    fn deserialize<D: Deserializer<'de>>(d: D) -> std::result::Result<Self, D::Error> {
        struct Visitor;
        impl serde::de::Visitor<'_> for Visitor {
            type Value = RawCount;
            fn expecting(&self, f: &mut std::fmt::Formatter) -> std::fmt::Result {
                f.write_str("a whole number")
            }
            fn visit_i64<E>(self, v: i64) -> std::result::Result<RawCount, E> {
                Ok(RawCount::Integer(v.into()))
            }
            fn visit_u64<E>(self, v: u64) -> std::result::Result<RawCount, E> {
                Ok(RawCount::Integer(v.into()))
            }
            fn visit_i128<E>(self, v: i128) -> std::result::Result<RawCount, E> {
                Ok(RawCount::Integer(v))
            }
            fn visit_u128<E>(self, v: u128) -> std::result::Result<RawCount, E> {
                Ok(i128::try_from(v)
                    .map_or_else(|_| RawCount::Other(v.to_string()), RawCount::Integer))
            }
            fn visit_f64<E>(self, v: f64) -> std::result::Result<RawCount, E> {
                Ok(RawCount::Float(v))
            }
            fn visit_bool<E>(self, v: bool) -> std::result::Result<RawCount, E> {
                Ok(RawCount::Other(v.to_string()))
            }
            fn visit_str<E>(self, v: &str) -> std::result::Result<RawCount, E> {
                Ok(RawCount::Other(format!("\"{v}\"")))
            }
        }
        d.deserialize_any(Visitor)
    }
}

/// Checks a count: a whole number (an integer, or a float with no fraction) from `min` to
/// `max`. The library checks its own ranges again; this turns values that do not fit a `usize`
/// (negative, huge, fractional, not a number) into the same kind of message.
fn count_in(value: &RawCount, field: &str, min: usize, max: usize) -> Result<usize> {
    let whole = match value {
        RawCount::Integer(i) => Some(*i),
        // Every float of magnitude below 2^100 converts exactly when it has no fraction.
        RawCount::Float(f) if f.is_finite() && f.fract() == 0.0 && f.abs() < 1e30 => {
            Some(*f as i128)
        }
        _ => None,
    };
    match whole.and_then(|w| usize::try_from(w).ok()) {
        Some(n) if (min..=max).contains(&n) => Ok(n),
        _ => {
            let shown = match value {
                RawCount::Integer(i) => i.to_string(),
                RawCount::Float(f) => f.to_string(),
                RawCount::Other(s) => s.clone(),
            };
            bail!("invalid {field} = {shown}: must be a whole number from {min} to {max}")
        }
    }
}

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
struct RawCase {
    material: Option<RawMaterial>,
    friction: Option<RawFriction>,
    profile: Option<RawProfile>,
    cycle: Option<RawCycle>,
    history: Option<RawHistory>,
    solver: Option<RawSolver>,
    units: Option<crate::units::RawUnits>,
    fatigue: Option<toml::Table>,
}

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
struct RawHistory {
    kind: Option<String>,
    file: Option<String>,
    cycles: Option<RawCount>,
    steps_per_half: Option<RawCount>,
    steps_per_cycle: Option<RawCount>,
    ramp: Option<String>,
    ramp_steps: Option<RawCount>,
    normal: Option<RawHarmonic>,
    shear: Option<RawHarmonic>,
    bulk: Option<RawHarmonic>,
}

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
struct RawHarmonic {
    mean: Option<f64>,
    amplitude: Option<f64>,
    phase: Option<f64>,
}

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
struct RawSolver {
    cells: Option<RawCount>,
    slip_tolerance: Option<f64>,
}

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
struct RawMaterial {
    youngs_modulus: Option<f64>,
    poisson_ratio: Option<f64>,
}

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
struct RawFriction {
    coefficient: Option<f64>,
}

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
struct RawProfile {
    kind: Option<String>,
    radius: Option<f64>,
    flat_half_width: Option<f64>,
    coefficient: Option<f64>,
    exponent: Option<f64>,
    file: Option<String>,
    kinks: Option<Vec<f64>>,
}

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
struct RawCycle {
    point1: Option<RawPoint>,
    point2: Option<RawPoint>,
}

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
struct RawPoint {
    normal: Option<f64>,
    shear: Option<f64>,
    bulk: Option<f64>,
}

/// A resolved case: a validated contact and, when the file has them, a cycle and a history.
#[derive(Debug, Clone)]
pub struct Case {
    /// `[material]`, `[friction]` and `[profile]`.
    pub contact: Contact,
    /// `[cycle]`, if the file has one.
    pub cycle: Option<Cycle>,
    history: Option<History>,
    /// `[solver]` (defaults where absent).
    pub solver: MarchOptions,
    /// The unit names of `[units]` (default N, mm, MPa), for labels only.
    pub units: crate::units::Units,
    /// `[fatigue]` as written, resolved by the `fatigue` command.
    pub fatigue: Option<toml::Table>,
}

impl Case {
    /// The history, or an error saying what `[history]` needs.
    pub fn history(&self) -> Result<History> {
        self.history.clone().ok_or_else(|| anyhow!("missing section [history]: give file = \"history.csv\", or kind = \"cycle\" (with [cycle]) or kind = \"harmonic\""))
    }

    /// The solver settings, with `cells` (from `--cells`) overriding `[solver] cells`.
    pub fn solver_with_cells(&self, cells: Option<usize>) -> Result<MarchOptions> {
        let mut options = self.solver;
        if let Some(n) = cells {
            let n = count_in(
                &RawCount::Integer(n as i128),
                "--cells",
                MIN_CELLS,
                MAX_CELLS,
            )?;
            options = options.with_cells(n)?;
        }
        Ok(options)
    }

    /// The cycle, or an error saying the `[cycle]` section is needed.
    pub fn cycle(&self) -> Result<Cycle> {
        self.cycle.ok_or_else(|| anyhow!("missing section [cycle]: give point1 and point2, e.g. point1 = {{ normal = 1000.0, shear = -250.0, bulk = -20.0 }}"))
    }
}

/// Rejects fields that `kind` does not use, so a typo or a leftover never passes silently.
fn reject_unused(section: &str, kind: &str, used: &[&str], given: &[(&str, bool)]) -> Result<()> {
    for (name, present) in given {
        if *present && !used.contains(name) {
            bail!(
                "{section}.{name} is not used by kind \"{kind}\" (it takes: {})",
                used.join(", ")
            );
        }
    }
    Ok(())
}

fn required(value: Option<f64>, field: &str, what: &str) -> Result<f64> {
    value.ok_or_else(|| anyhow!("missing field {field}: give {what}"))
}

/// Reads and resolves a case file.
pub fn load(path: &Path) -> Result<Case> {
    let text = std::fs::read_to_string(path)
        .with_context(|| format!("cannot read case file {}", path.display()))?;
    // An editor on Windows may save UTF-8 with a byte-order mark, which TOML does not allow.
    let text = text.strip_prefix('\u{feff}').unwrap_or(&text);
    let dir = path.parent().map(Path::to_path_buf).unwrap_or_default();
    parse(text, &dir).with_context(|| format!("in case file {}", path.display()))
}

/// Resolves case text; relative paths are taken from `dir`.
pub fn parse(text: &str, dir: &Path) -> Result<Case> {
    let raw: RawCase = toml::from_str(text).map_err(|e| anyhow!("{}", e.to_string().trim_end()))?;
    let m = raw.material.ok_or_else(|| {
        anyhow!("missing section [material]: give youngs_modulus and poisson_ratio")
    })?;
    let material = Material::new(
        required(
            m.youngs_modulus,
            "material.youngs_modulus",
            "Young's modulus E > 0 (MPa in N-mm-MPa units)",
        )?,
        required(
            m.poisson_ratio,
            "material.poisson_ratio",
            "Poisson's ratio with 0 <= nu < 0.5",
        )?,
    )?;
    let fr = raw
        .friction
        .ok_or_else(|| anyhow!("missing section [friction]: give coefficient = f > 0"))?;
    let friction = Friction::new(required(
        fr.coefficient,
        "friction.coefficient",
        "the Coulomb friction coefficient f > 0",
    )?)?;
    let p = raw.profile.ok_or_else(|| anyhow!("missing section [profile]: give kind = \"hertz\" | \"flat-rounded\" | \"power-law\" | \"tabulated\" and its parameters"))?;
    let profile = resolve_profile(p, dir)?;
    let cycle = match raw.cycle {
        None => None,
        Some(c) => {
            let point = |raw: Option<RawPoint>, name: &str| -> Result<LoadPoint> {
                let r = raw.ok_or_else(|| anyhow!("missing field cycle.{name}: give {{ normal = P > 0, shear = Q, bulk = sigma }}"))?;
                let field = format!("cycle.{name}");
                Ok(LoadPoint::new(
                    &field,
                    required(
                        r.normal,
                        &format!("{field}.normal"),
                        "the normal load P > 0 (N/mm)",
                    )?,
                    required(
                        r.shear,
                        &format!("{field}.shear"),
                        "the shear load Q (N/mm)",
                    )?,
                    r.bulk.unwrap_or(0.0),
                )?)
            };
            Some(Cycle::new(
                point(c.point1, "point1")?,
                point(c.point2, "point2")?,
            ))
        }
    };
    let mut solver = MarchOptions::default();
    if let Some(raw_solver) = raw.solver {
        if let Some(cells) = &raw_solver.cells {
            solver = solver.with_cells(count_in(cells, "solver.cells", MIN_CELLS, MAX_CELLS)?)?;
        }
        if let Some(t) = raw_solver.slip_tolerance {
            solver = solver.with_slip_tolerance(t)?;
        }
    }
    // Resolved now so that every command reports a bad [history], required only by `march`.
    let history = match raw.history {
        Some(h) => Some(resolve_history(h, cycle.as_ref(), dir)?),
        None => None,
    };
    Ok(Case {
        contact: Contact::new(profile, material, friction),
        cycle,
        history,
        solver,
        units: crate::units::Units::resolve(raw.units)?,
        fatigue: raw.fatigue,
    })
}

fn resolve_history(h: RawHistory, cycle: Option<&Cycle>, dir: &Path) -> Result<History> {
    let kind = match (&h.kind, &h.file) {
        (Some(k), _) => k.clone(),
        (None, Some(_)) => "file".to_string(),
        (None, None) => bail!("missing field history.kind: give \"file\" (with file = ...), \"cycle\" or \"harmonic\""),
    };
    let used: &[&str] = match kind.as_str() {
        "file" => &["file"],
        "cycle" => &["cycles", "steps_per_half", "ramp", "ramp_steps"],
        "harmonic" => &[
            "cycles",
            "steps_per_cycle",
            "ramp_steps",
            "normal",
            "shear",
            "bulk",
        ],
        other => bail!(
            "invalid history.kind = \"{other}\": must be one of \"file\", \"cycle\", \"harmonic\""
        ),
    };
    let given = [
        ("file", h.file.is_some()),
        ("cycles", h.cycles.is_some()),
        ("steps_per_half", h.steps_per_half.is_some()),
        ("steps_per_cycle", h.steps_per_cycle.is_some()),
        ("ramp", h.ramp.is_some()),
        ("ramp_steps", h.ramp_steps.is_some()),
        ("normal", h.normal.is_some()),
        ("shear", h.shear.is_some()),
        ("bulk", h.bulk.is_some()),
    ];
    reject_unused("history", &kind, used, &given)?;
    let max = halfplane::history::MAX_INCREMENTS;
    let count = |v: &Option<RawCount>, field: &str, min: usize, what: &str| match v {
        Some(v) => count_in(v, &format!("history.{field}"), min, max),
        None => Err(anyhow!("missing field history.{field}: give {what}")),
    };
    let ramp_steps = match &h.ramp_steps {
        Some(v) => count_in(v, "history.ramp_steps", 1, max)?,
        None => 20,
    };
    Ok(match kind.as_str() {
        "file" => {
            let file = h.file.ok_or_else(|| anyhow!("missing field history.file: give the CSV (columns normal,shear,bulk), relative to the case file"))?;
            let path = dir.join(&file);
            let (values, lines) = read_csv(
                &path,
                "history.file",
                &["normal", "shear", "bulk"],
                halfplane::history::MAX_INCREMENTS,
            )?;
            let rows: Vec<[f64; 3]> = values.chunks_exact(3).map(|r| [r[0], r[1], r[2]]).collect();
            History::from_rows(&rows).map_err(|e| match e {
                halfplane::Error::InvalidRow {
                    row,
                    column,
                    value,
                    valid,
                    ..
                } => {
                    let line = lines.get(row.wrapping_sub(1)).copied().unwrap_or(0);
                    anyhow!(
                        "history.file {}, line {line}: {column} = {value}: must be {valid}",
                        path.display()
                    )
                }
                other => anyhow!("history.file {}: {other}", path.display()),
            })?
        }
        "cycle" => {
            let c = cycle.ok_or_else(|| {
                anyhow!("history.kind = \"cycle\" needs the [cycle] section with point1 and point2")
            })?;
            let (first, second) = c.as_given();
            let ramp = match h.ramp.as_deref().unwrap_or("normal-first") {
                "normal-first" => Ramp::NormalFirst,
                "proportional" => Ramp::Proportional,
                other => bail!("invalid history.ramp = \"{other}\": must be \"normal-first\" (P, then Q and sigma) or \"proportional\""),
            };
            History::in_phase(
                first,
                second,
                count(&h.cycles, "cycles", 1, "the number of cycles >= 1")?,
                count(
                    &h.steps_per_half,
                    "steps_per_half",
                    1,
                    "increments per half-cycle >= 1",
                )?,
                ramp,
                ramp_steps,
            )?
        }
        _ => {
            let harmonic = |raw: Option<RawHarmonic>, name: &str| -> Result<Harmonic> {
                let field = format!("history.{name}");
                let Some(r) = raw else {
                    return Ok(Harmonic::new(&field, 0.0, 0.0, 0.0)?);
                };
                let mean = r.mean.ok_or_else(|| {
                    anyhow!("missing field history.{name}.mean: give the mean value")
                })?;
                Ok(Harmonic::new(
                    &field,
                    mean,
                    r.amplitude.unwrap_or(0.0),
                    r.phase.unwrap_or(0.0),
                )?)
            };
            if h.normal.is_none() {
                bail!("missing field history.normal: give {{ mean = P0 > 0, amplitude = ..., phase = degrees }}");
            }
            History::harmonic(
                harmonic(h.normal, "normal")?,
                harmonic(h.shear, "shear")?,
                harmonic(h.bulk, "bulk")?,
                count(&h.cycles, "cycles", 1, "the number of cycles >= 1")?,
                count(
                    &h.steps_per_cycle,
                    "steps_per_cycle",
                    2,
                    "increments per cycle >= 2",
                )?,
                ramp_steps,
            )?
        }
    })
}

fn resolve_profile(p: RawProfile, dir: &Path) -> Result<Profile> {
    let kind = p.kind.clone().ok_or_else(|| anyhow!("missing field profile.kind: give one of \"hertz\", \"flat-rounded\", \"power-law\", \"tabulated\""))?;
    let used: &[&str] = match kind.as_str() {
        "hertz" => &["radius"],
        "flat-rounded" => &["radius", "flat_half_width"],
        "power-law" => &["coefficient", "exponent"],
        "tabulated" => &["file", "kinks"],
        other => bail!("invalid profile.kind = \"{other}\": must be one of \"hertz\", \"flat-rounded\", \"power-law\", \"tabulated\""),
    };
    let given = [
        ("radius", p.radius.is_some()),
        ("flat_half_width", p.flat_half_width.is_some()),
        ("coefficient", p.coefficient.is_some()),
        ("exponent", p.exponent.is_some()),
        ("file", p.file.is_some()),
        ("kinks", p.kinks.is_some()),
    ];
    reject_unused("profile", &kind, used, &given)?;
    Ok(match kind.as_str() {
        "hertz" => Profile::hertz(required(
            p.radius,
            "profile.radius",
            "the relative radius of curvature R > 0 (mm)",
        )?)?,
        "flat-rounded" => Profile::flat_rounded(
            required(
                p.flat_half_width,
                "profile.flat_half_width",
                "the flat half-width b >= 0 (mm)",
            )?,
            required(p.radius, "profile.radius", "the edge radius R > 0 (mm)")?,
        )?,
        "power-law" => Profile::power_law(
            required(p.coefficient, "profile.coefficient", "B > 0 in g = B|x|^k")?,
            required(p.exponent, "profile.exponent", "k >= 1 in g = B|x|^k")?,
        )?,
        _ => {
            let file = p.file.ok_or_else(|| anyhow!("missing field profile.file: give the CSV file (columns x,g with x >= 0), relative to the case file"))?;
            let path = dir.join(&file);
            let (values, lines) = read_csv(
                &path,
                "profile.file",
                &["x", "g"],
                halfplane::profile::MAX_TABLE_ROWS,
            )?;
            let (x, g) = values.chunks_exact(2).map(|r| (r[0], r[1])).unzip();
            Profile::tabulated(x, g, p.kinks.unwrap_or_default()).map_err(|e| match e {
                halfplane::Error::InvalidTable { row, problem }
                    if row >= 1 && row <= lines.len() =>
                {
                    anyhow!(
                        "profile.file {}, line {}: {problem}",
                        path.display(),
                        lines[row - 1]
                    )
                }
                other => anyhow!("profile.file {}: {other}", path.display()),
            })?
        }
    })
}

/// Reads a CSV whose header names `columns`, at most `max_rows` data rows; blank lines and lines
/// starting with `#` are skipped, a UTF-8 byte-order mark and CRLF line ends (a spreadsheet's
/// "CSV UTF-8") are accepted. Returns the values row after row (`columns.len()` per row) and
/// the file line of each row (for errors); `field` names the field that gave the path. Read
/// a line at a time: a file with too many rows is rejected without holding it.
pub(crate) fn read_csv(
    path: &Path,
    field: &str,
    columns: &[&str],
    max_rows: usize,
) -> Result<(Vec<f64>, Vec<usize>)> {
    let file = std::fs::File::open(path)
        .with_context(|| format!("cannot read {field} {}", path.display()))?;
    let mut reader = std::io::BufReader::new(file);
    let header_text = columns.join(",");
    let (mut values, mut numbers) = (Vec::new(), Vec::new());
    let mut header_seen = false;
    let mut line = String::new();
    for number in 1.. {
        line.clear();
        let read = reader
            .read_line(&mut line)
            .with_context(|| format!("cannot read {field} {}, line {number}", path.display()))?;
        if read == 0 {
            break;
        }
        let text = if number == 1 {
            line.strip_prefix('\u{feff}').unwrap_or(&line)
        } else {
            &line
        };
        // trim() also removes the '\r' of a CRLF line end.
        let text = text.trim();
        if text.is_empty() || text.starts_with('#') {
            continue;
        }
        if !header_seen {
            let names: Vec<String> = text
                .split(',')
                .map(|s| s.trim().to_ascii_lowercase())
                .collect();
            if names != columns {
                bail!(
                    "{field} {}, line {number}: header is \"{text}\", expected \"{header_text}\"",
                    path.display()
                );
            }
            header_seen = true;
            continue;
        }
        if numbers.len() == max_rows {
            bail!(
                "{field} {}, line {number}: the table has more than {max_rows} rows, the most a run takes",
                path.display()
            );
        }
        let mut found = 0;
        for cell in text.split(',').map(str::trim) {
            found += 1;
            let Some(name) = columns.get(found - 1) else {
                continue;
            };
            let value = cell.parse::<f64>().map_err(|_| {
                anyhow!(
                    "{field} {}, line {number}: {name} = \"{cell}\" is not a number",
                    path.display()
                )
            })?;
            values.push(value);
        }
        if found != columns.len() {
            bail!(
                "{field} {}, line {number}: expected {} columns ({header_text}), found {found}",
                path.display(),
                columns.len()
            );
        }
        numbers.push(number);
    }
    if !header_seen {
        bail!(
            "{field} {} is empty: it needs a header {header_text} and rows",
            path.display()
        );
    }
    if numbers.is_empty() {
        bail!("{field} {} has a header but no rows", path.display());
    }
    Ok((values, numbers))
}
