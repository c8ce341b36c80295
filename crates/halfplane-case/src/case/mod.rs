//! The case file: raw TOML is parsed first, then resolved into validated library values. Every
//! error names the field (as the file spells it) and what would be valid.

use anyhow::{anyhow, bail, Context, Result};
use halfplane::history::{History, Steady};
use halfplane::march::MarchOptions;
use halfplane::{Contact, Cycle, Friction, LoadPoint, Material, Profile};
use serde::Deserialize;
use std::io::Read;
use std::path::Path;

mod count;
mod crack;
mod csv;
mod fatigue;
mod history;
mod table;
mod wear;

use count::{count_in, RawCount};
pub use csv::{read_csv, read_csv_with, LineLimit, Table, MAX_LINE_BYTES};
pub use fatigue::FatigueSettings;
pub use history::Sliding;
use history::{resolve_history, resolve_sliding, resolve_steady, RawHistory};
pub use wear::{Reached, WearFatigue, WearSettings, DEFAULT_SPAN};

/// The range of `solver.cells` and `--cells`: the library's (its maximum is set by memory).
const MIN_CELLS: usize = MarchOptions::MIN_CELLS;
const MAX_CELLS: usize = MarchOptions::MAX_CELLS;

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
    crack: Option<toml::Table>,
    wear: Option<toml::Table>,
}

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
struct RawSolver {
    cells: Option<RawCount>,
    slip_tolerance: Option<f64>,
    /// Any TOML value, checked when resolved so that `= 3` or `= "yes"` is an error naming the
    /// field (serde's own message would say only "expected a boolean").
    sub_cell_boundaries: Option<toml::Value>,
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
    left_radius: Option<f64>,
    right_radius: Option<f64>,
    flat_half_width: Option<f64>,
    coefficient: Option<f64>,
    exponent: Option<f64>,
    file: Option<String>,
    data: Option<String>,
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
    moment: Option<f64>,
}

/// A resolved case: a validated contact and, when the file has them, a cycle and a history.
#[derive(Debug, Clone)]
pub struct Case {
    /// `[material]`, `[friction]` and `[profile]`.
    pub contact: Contact,
    /// `[cycle]`, if the file has one.
    pub cycle: Option<Cycle>,
    /// `[history] kind = "sliding"` (then there is no load history: `wear` runs it).
    pub sliding: Option<Sliding>,
    history: Option<History>,
    /// `history.cycles = "steady"`: march until the cycle repeats (the history holds one cycle,
    /// which the march repeats).
    until_steady: bool,
    /// `history.max_cycles` and `history.steady_tolerance` (defaults where absent).
    steady: Steady,
    /// `[solver]` (defaults where absent).
    pub solver: MarchOptions,
    /// The unit names of `[units]` (default N, mm, MPa), for labels only.
    pub units: crate::units::Units,
    /// `[fatigue]` as written, resolved by [`Case::fatigue`] when a command needs it.
    fatigue: Option<toml::Table>,
    /// `[crack]` as written, resolved by [`Case::crack`] when a command needs it.
    crack: Option<toml::Table>,
    /// `[wear]` as written, resolved by [`Case::wear`] when a command needs it.
    wear: Option<toml::Table>,
}

impl Case {
    /// The history, or an error saying what `[history]` needs. A history marched until steady
    /// (`history.cycles = "steady"`) is an error here: its length is known only once marched, so
    /// only the commands that take [`Case::march_history`] run it.
    pub fn history(&self) -> Result<History> {
        if self.until_steady {
            bail!("history.cycles = \"steady\" is run by march, sweep (analysis = \"march\") and Python's halfplane.march only: give this command a number of cycles (march reports cycles_run, the count the cycle took to repeat)");
        }
        self.march_history().map(|(history, _)| history)
    }

    /// The history and, for `history.cycles = "steady"`, the criterion to march it by (the
    /// history then holds its ramp and one cycle, which the march repeats).
    pub fn march_history(&self) -> Result<(History, Option<Steady>)> {
        if self.sliding.is_some() {
            bail!("[history] kind = \"sliding\" is run by halfplane wear (and Python's halfplane.wear): its Q is f P while the bodies slide, which a load history cannot step to; give kind = \"cycle\", \"harmonic\" or a file for this command");
        }
        let history = self.history.clone().ok_or_else(|| anyhow!("missing section [history]: give file = \"history.csv\" (or its rows as data = \"\"\"...\"\"\"), or kind = \"cycle\" (with [cycle]) or kind = \"harmonic\""))?;
        Ok((history, self.until_steady.then_some(self.steady)))
    }

    /// `history.max_cycles` and `history.steady_tolerance` (defaults where absent): the
    /// tolerance also decides whether a march of a fixed number of cycles reached its steady
    /// cycle (`steady_converged`).
    pub fn steady(&self) -> Steady {
        self.steady
    }

    /// The solver settings, with `cells` (from `--cells`) overriding `[solver] cells`.
    pub fn solver_with_cells(&self, cells: Option<usize>) -> Result<MarchOptions> {
        self.solver_with_cells_named(cells, "--cells")
    }

    /// [`Case::solver_with_cells`] for another front end: an invalid `cells` is reported under
    /// `name`, as that front end spells it (Python's `cells` keyword).
    pub fn solver_with_cells_named(
        &self,
        cells: Option<usize>,
        name: &str,
    ) -> Result<MarchOptions> {
        let mut options = self.solver;
        if let Some(n) = cells {
            let n = count_in(&RawCount::Integer(n as i128), name, MIN_CELLS, MAX_CELLS)?;
            options = options.with_cells(n)?;
        }
        Ok(options)
    }

    /// `[fatigue]`: the material constants (each validated) and the grid (defaults where absent).
    pub fn fatigue(&self) -> Result<FatigueSettings> {
        fatigue::resolve(self.fatigue.as_ref())
    }

    /// What `wear --fatigue` evaluates at each checkpoint: `[fatigue]`, which must give
    /// constants (the error names the case as `source` does).
    pub fn wear_fatigue(&self, source: &str) -> Result<WearFatigue> {
        WearFatigue::new(self.contact.material(), self.fatigue()?, source)
    }

    /// `[crack]`: the crack's position, angle, lengths and faces (`halfplane crack`).
    pub fn crack(&self) -> Result<halfplane::crack::CrackOptions> {
        crack::resolve(self.crack.as_ref())
    }

    /// `[wear]`: the wear law, the cycles and their checkpoints (`halfplane wear`).
    pub fn wear(&self) -> Result<WearSettings> {
        wear::resolve(self.wear.as_ref())
    }

    /// `[wear]` with the fields of `overrides` put in (added, or replacing those written),
    /// resolved and checked exactly as the section itself (Python's `halfplane.wear`).
    pub fn wear_with(&self, overrides: &toml::Table) -> Result<WearSettings> {
        let mut table = self.wear.clone().unwrap_or_default();
        for (k, v) in overrides {
            table.insert(k.clone(), v.clone());
        }
        wear::resolve(Some(&table))
    }

    /// The march `halfplane wear` runs: the sliding history, or the ramp and first cycle of the
    /// load history (which must have exactly one cycle: the physical ones are `[wear] cycles`),
    /// on a grid `[wear] span` times the unworn contact with `cells` cells (`--cells`), its
    /// fretting loop measured from `[wear] loop_datum`.
    pub fn worn_march(
        &self,
        wear: &WearSettings,
        cells: Option<usize>,
    ) -> Result<halfplane::march::Worn> {
        self.worn_march_named(wear, cells, "--cells")
    }

    /// [`Case::worn_march`] for another front end: an invalid `cells` is reported under `name`
    /// (Python's `cells` keyword).
    pub fn worn_march_named(
        &self,
        wear: &WearSettings,
        cells: Option<usize>,
        name: &str,
    ) -> Result<halfplane::march::Worn> {
        let worn = self.worn_on_grid(wear.span, cells, name)?;
        Ok(match wear.loop_datum {
            Some(d) => worn.with_loop_datum(d)?,
            None => worn,
        })
    }

    fn worn_on_grid(
        &self,
        span: f64,
        cells: Option<usize>,
        name: &str,
    ) -> Result<halfplane::march::Worn> {
        let options = self.solver_with_cells_named(cells, name)?;
        if let Some(s) = &self.sliding {
            return Ok(halfplane::march::Worn::sliding(
                &self.contact,
                s.load,
                s.amplitude,
                s.steps_per_half,
                s.ramp_steps,
                &options,
                span,
            )?);
        }
        let history = self.history()?;
        match history.cycles() {
            Some(c) if c.count() == 1 => {}
            Some(c) => bail!("invalid history.cycles = {}: wear marches the history's one cycle again and again: give cycles = 1 (the physical cycles are [wear] cycles)", c.count()),
            None => bail!("wear needs a cyclic [history] (kind = \"cycle\", \"harmonic\" or \"sliding\"), not rows from a file"),
        }
        Ok(halfplane::march::Worn::new(
            &self.contact,
            &history,
            &options,
            span,
        )?)
    }

    /// `[crack]` with the fields of `overrides` put in (added, or replacing those written),
    /// resolved and checked exactly as the section itself (Python's `halfplane.crack`).
    pub fn crack_with(&self, overrides: &toml::Table) -> Result<halfplane::crack::CrackOptions> {
        let mut table = self.crack.clone().unwrap_or_default();
        if overrides.contains_key("angle") {
            // A new angle replaces the critical-plane choice written with the old one.
            table.remove("initiation_parameter");
        }
        for (k, v) in overrides {
            table.insert(k.clone(), v.clone());
        }
        crack::resolve(Some(&table))
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

/// An error about one field of the case, which it names as the file spells it: a number missing,
/// a count that is not a whole number in range. Its own type (its message is the text the command
/// prints), so that a front end can show the message beside that field (the web page's form)
/// without reading the text.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct FieldError {
    /// The field, e.g. `material.youngs_modulus`.
    pub field: String,
    /// The whole message, which names the field.
    pub message: String,
}

impl std::fmt::Display for FieldError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(&self.message)
    }
}

impl std::error::Error for FieldError {}

/// A switch of the case: `true` or `false`, anything else an error naming the field and value.
fn flag(value: &toml::Value, field: &str) -> Result<bool> {
    match value {
        toml::Value::Boolean(on) => Ok(*on),
        other => Err(FieldError {
            field: field.into(),
            message: format!("invalid {field} = {other}: must be true or false"),
        }
        .into()),
    }
}

fn required(value: Option<f64>, field: &str, what: &str) -> Result<f64> {
    value.ok_or_else(|| {
        FieldError {
            field: field.into(),
            message: format!("missing field {field}: give {what}"),
        }
        .into()
    })
}

/// The largest case file or sweep spec read: room for an inline history of
/// [`halfplane::history::MAX_INCREMENTS`] rows.
pub const MAX_TEXT_BYTES: u64 = 1 << 30;

/// Reads the text of a case file or sweep spec (`what`, for messages), refusing at the first NUL
/// byte, which TOML never allows: a binary file, or an endless one like /dev/zero, is not read whole.
pub fn read_text(path: &Path, what: &str) -> Result<String> {
    let context = || format!("cannot read {what} {}", path.display());
    let file = std::fs::File::open(path).with_context(context)?;
    let mut reader = file.take(MAX_TEXT_BYTES + 1);
    let (mut bytes, mut chunk) = (Vec::new(), vec![0u8; 1 << 16]);
    loop {
        let n = match reader.read(&mut chunk) {
            Ok(0) => break,
            Ok(n) => n,
            Err(e) if e.kind() == std::io::ErrorKind::Interrupted => continue,
            Err(e) => return Err(e).with_context(context),
        };
        if let Some(at) = chunk[..n].iter().position(|&b| b == 0) {
            bail!(
                "{}: not a text file (a NUL byte at byte {})",
                context(),
                bytes.len() + at
            );
        }
        bytes.extend_from_slice(&chunk[..n]);
    }
    if bytes.len() as u64 > MAX_TEXT_BYTES {
        bail!("{}: larger than {MAX_TEXT_BYTES} bytes", context());
    }
    String::from_utf8(bytes).map_err(|e| anyhow!("{}: not UTF-8 text ({e})", context()))
}

/// Reads and resolves a case file.
pub fn load(path: &Path) -> Result<Case> {
    let text = read_text(path, "case file")?;
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
                let r = raw.ok_or_else(|| anyhow!("missing field cycle.{name}: give {{ normal = P > 0, shear = Q, bulk = sigma, moment = M }}"))?;
                let field = format!("cycle.{name}");
                let moment = r.moment.unwrap_or(0.0);
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
                )?
                .with_moment(&field, moment)?)
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
        if let Some(v) = &raw_solver.sub_cell_boundaries {
            solver = solver.with_sub_cell_boundaries(flag(v, "solver.sub_cell_boundaries")?)?;
        }
    }
    // Resolved now so that every command reports a bad [history], required only by `march`.
    let (sliding, raw_history) = match raw.history {
        Some(h) if h.kind.as_deref() == Some("sliding") => (Some(resolve_sliding(h)?), None),
        other => (None, other),
    };
    let (history, until_steady, steady) = match raw_history {
        Some(h) => {
            let (until_steady, steady) = resolve_steady(&h)?;
            let history = resolve_history(h, cycle.as_ref(), until_steady, dir)?;
            (Some(history), until_steady, steady)
        }
        None => (None, false, Steady::default()),
    };
    Ok(Case {
        contact: Contact::new(profile, material, friction),
        cycle,
        sliding,
        history,
        until_steady,
        steady,
        solver,
        units: crate::units::Units::resolve(raw.units)?,
        fatigue: raw.fatigue,
        crack: raw.crack,
        wear: raw.wear,
    })
}

fn resolve_profile(p: RawProfile, dir: &Path) -> Result<Profile> {
    let kind = p.kind.clone().ok_or_else(|| anyhow!("missing field profile.kind: give one of \"hertz\", \"flat-rounded\", \"power-law\", \"tabulated\""))?;
    let used: &[&str] = match kind.as_str() {
        "hertz" => &["radius"],
        "flat-rounded" => &["radius", "left_radius", "right_radius", "flat_half_width"],
        "power-law" => &["coefficient", "exponent"],
        "tabulated" => &["file", "data", "kinks"],
        other => bail!("invalid profile.kind = \"{other}\": must be one of \"hertz\", \"flat-rounded\", \"power-law\", \"tabulated\""),
    };
    let given = [
        ("radius", p.radius.is_some()),
        ("left_radius", p.left_radius.is_some()),
        ("right_radius", p.right_radius.is_some()),
        ("flat_half_width", p.flat_half_width.is_some()),
        ("coefficient", p.coefficient.is_some()),
        ("exponent", p.exponent.is_some()),
        ("file", p.file.is_some()),
        ("data", p.data.is_some()),
        ("kinks", p.kinks.is_some()),
    ];
    reject_unused("profile", &kind, used, &given)?;
    Ok(match kind.as_str() {
        "hertz" => Profile::hertz(required(
            p.radius,
            "profile.radius",
            "the relative radius of curvature R > 0 (mm)",
        )?)?,
        "flat-rounded" => {
            let b = required(
                p.flat_half_width,
                "profile.flat_half_width",
                "the flat half-width b >= 0 (mm)",
            )?;
            match (p.radius, p.left_radius, p.right_radius) {
                (Some(r), None, None) => Profile::flat_rounded(b, r)?,
                (None, Some(left), Some(right)) => {
                    Profile::flat_rounded_asymmetric(b, left, right)?
                }
                (Some(_), _, _) => bail!("profile.radius and profile.left_radius/right_radius both given: give radius (equal edges) or left_radius and right_radius (unequal edges), not both"),
                (None, Some(_), None) => bail!("missing field profile.right_radius: give the right edge radius R_R > 0 (mm) with left_radius, or radius alone for equal edges"),
                (None, None, Some(_)) => bail!("missing field profile.left_radius: give the left edge radius R_L > 0 (mm) with right_radius, or radius alone for equal edges"),
                (None, None, None) => bail!("missing field profile.radius: give the edge radius R > 0 (mm), or left_radius and right_radius for unequal edges"),
            }
        }
        "power-law" => Profile::power_law(
            required(p.coefficient, "profile.coefficient", "B > 0 in g = B|x|^k")?,
            required(p.exponent, "profile.exponent", "k >= 1 in g = B|x|^k")?,
        )?,
        _ => {
            let table = table::source("profile", p.file.as_deref(), p.data.as_deref(), dir)?
                .ok_or_else(|| anyhow!("missing field profile.file: give the CSV file (columns x,g from x = 0, mirrored, or over both sides from a negative x), relative to the case file, or its text as profile.data"))?;
            table::profile_table(&table, p.kinks.unwrap_or_default())?
        }
    })
}
