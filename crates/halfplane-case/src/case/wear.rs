//! The `[wear]` section (`docs/wear.md`): the wear law and its coefficient, the pad's share of
//! the depth, the physical cycles and their checkpoints, the bound on a jump's depth and the
//! grid's width. Every error names the field, the value and what is valid.

use super::count::{count_in, RawCount};
use super::FatigueSettings;
use anyhow::{anyhow, bail, Result};
use halfplane::fatigue::{self, FatigueConstants, FatigueGrid, FatigueResult};
use halfplane::wear::{Checkpoint, Law, WearOptions, MAX_CHECKPOINTS, MAX_CYCLES};
use halfplane::written::Written;
use halfplane::Material;
use toml::Value;

/// The grid's width over the unworn contact's, by default: room for a partial-slip contact
/// that grows a little and for the first widening of a sliding scar (a long sliding run needs
/// more: `span`).
pub const DEFAULT_SPAN: f64 = 2.0;

/// `[wear]` resolved: the options and the grid's span factor.
#[derive(Debug, Clone, PartialEq)]
pub struct WearSettings {
    /// The wear options.
    pub options: WearOptions,
    /// The grid's width over the unworn contact's.
    pub span: f64,
    /// The fretting loop's datum (a length); `None`: the march's default.
    pub loop_datum: Option<f64>,
}

/// The fatigue parameters of each checkpoint's cycle (`halfplane wear --fatigue`, Python's
/// `wear(..., fatigue=True)`), with the case's `[fatigue]` constants and grid.
pub struct WearFatigue {
    material: Material,
    constants: FatigueConstants,
    grid: FatigueGrid,
    /// The parameters `[fatigue]` leaves out, one line each (the warnings).
    pub skipped: Vec<String>,
}

impl WearFatigue {
    /// `[fatigue]` of the case `source` names (in the error when it gives no constant).
    pub(super) fn new(material: Material, settings: FatigueSettings, source: &str) -> Result<Self> {
        if settings.constants == FatigueConstants::default() {
            bail!(
                "--fatigue needs material constants in [fatigue], and {source} gives none: add the \
                 constants of the parameters to report (fatigue.findley_k, \
                 fatigue.crossland_alpha, fatigue.fatemi_socie_k with fatigue.yield_stress, \
                 fatigue.axial_fatigue_limit with fatigue.torsional_fatigue_limit, \
                 fatigue.mcdiarmid_shear_limit with fatigue.ultimate_strength, the \
                 strain-life constants, fatigue.threshold with fatigue.endurance_range; \
                 docs/fatigue.md)"
            );
        }
        Ok(Self {
            material,
            skipped: settings.skipped(),
            constants: settings.constants,
            grid: settings.grid,
        })
    }

    /// The parameters over the checkpoint's cycle, on the `[fatigue]` grid scaled on the unworn
    /// contact `[b1, b2]`; `None` when the march did not record the cycle's tractions.
    pub fn evaluate(
        &self,
        checkpoint: &Checkpoint,
        unworn: [f64; 2],
    ) -> Option<Result<FatigueResult>> {
        let cycle = checkpoint.tractions.as_ref()?;
        Some(
            fatigue::analyse_cycle(&self.material, cycle, unworn, &self.constants, &self.grid)
                .map_err(|e| anyhow!("--fatigue at cycle {}: {e}", checkpoint.cycle)),
        )
    }
}

/// What a wear run keeps of each checkpoint as the loop reaches it (the CLI and Python observe
/// the same way): the checkpoint without its cycle's tractions and, with `--fatigue`, the
/// parameters of that cycle; the first evaluation that fails stops the others and is kept.
pub struct Reached {
    fatigue: Option<WearFatigue>,
    unworn: [f64; 2],
    /// The checkpoints reached, in order.
    pub checkpoints: Vec<Checkpoint>,
    /// `--fatigue`: the parameters of each checkpoint's cycle, in order.
    pub parameters: Vec<FatigueResult>,
    /// The first `--fatigue` evaluation that failed.
    pub error: Option<anyhow::Error>,
}

impl Reached {
    /// For a run whose unworn contact is `[b1, b2]` (the fatigue grid is scaled on it).
    pub fn new(fatigue: Option<WearFatigue>, unworn: [f64; 2]) -> Self {
        Self {
            fatigue,
            unworn,
            checkpoints: Vec::new(),
            parameters: Vec::new(),
            error: None,
        }
    }

    /// Keeps `checkpoint` (evaluating its cycle with `--fatigue`).
    pub fn observe(&mut self, checkpoint: &Checkpoint) {
        if let (Some(f), None) = (&self.fatigue, &self.error) {
            match f.evaluate(checkpoint, self.unworn) {
                Some(Ok(r)) => self.parameters.push(r),
                Some(Err(e)) => self.error = Some(e),
                None => {}
            }
        }
        let mut kept = checkpoint.clone();
        kept.tractions = None;
        self.checkpoints.push(kept);
    }

    /// Whether the parameters are evaluated (`--fatigue`).
    pub fn with_fatigue(&self) -> bool {
        self.fatigue.is_some()
    }
}

/// Resolves `[wear]` (required by `halfplane wear`).
pub(super) fn resolve(table: Option<&toml::Table>) -> Result<WearSettings> {
    let table = table.ok_or_else(|| {
        anyhow!("missing section [wear]: give law = \"archard\" or \"energy\", coefficient (1/stress) and cycles")
    })?;
    const FIELDS: [&str; 8] = [
        "law",
        "coefficient",
        "share",
        "cycles",
        "checkpoints",
        "max_depth_increment",
        "span",
        "loop_datum",
    ];
    if let Some(k) = table.keys().find(|k| !FIELDS.contains(&k.as_str())) {
        bail!("unknown field wear.{k}: [wear] takes {}", FIELDS.join(", "));
    }
    let law = match table.get("law") {
        Some(Value::String(s)) if s == "archard" => Law::Archard,
        Some(Value::String(s)) if s == "energy" => Law::Energy,
        Some(v) => bail!("invalid wear.law = {v}: must be \"archard\" (depth = k p |slip|) or \"energy\" (depth = alpha q slip, the dissipated energy)"),
        None => bail!("missing field wear.law: give \"archard\" or \"energy\""),
    };
    let coefficient = number(table, "coefficient")?.ok_or_else(|| {
        anyhow!("missing field wear.coefficient: give k (archard) or alpha (energy) > 0, in 1/stress (1/MPa with N, mm, MPa)")
    })?;
    let cycles = match table.get("cycles") {
        Some(v) => count(v, "wear.cycles", 1, MAX_CYCLES)?,
        None => bail!("missing field wear.cycles: give the physical cycles, 1 to {MAX_CYCLES}"),
    };
    let mut options = match table.get("checkpoints") {
        None => WearOptions::logarithmic(law, coefficient, cycles, 7)?,
        Some(Value::Array(list)) => {
            let points = list
                .iter()
                .enumerate()
                .map(|(i, v)| count(v, &format!("wear.checkpoints[{i}]"), 1, cycles))
                .collect::<Result<Vec<u64>>>()?;
            WearOptions::new(law, coefficient, cycles, &points)?
        }
        Some(v) => {
            let n = count(v, "wear.checkpoints", 1, MAX_CHECKPOINTS as u64)?;
            WearOptions::logarithmic(law, coefficient, cycles, n as usize)?
        }
    };
    if let Some(share) = number(table, "share")? {
        options = options.with_share(share)?;
    }
    if let Some(bound) = number(table, "max_depth_increment")? {
        options = options.with_max_depth_increment(bound)?;
    }
    let span = number(table, "span")?.unwrap_or(DEFAULT_SPAN);
    if !(span.is_finite() && (1.0..=100.0).contains(&span)) {
        bail!("invalid wear.span = {}: must be a factor from 1 to 100 (the grid's width over the unworn contact's)", Written(span));
    }
    let loop_datum = number(table, "loop_datum")?;
    if let Some(d) = loop_datum.filter(|d| !(d.is_finite() && *d > 0.0)) {
        bail!("invalid wear.loop_datum = {}: must be a length > 0 (the distance from the contact at which the fretting loop's displacement is measured)", Written(d));
    }
    Ok(WearSettings {
        options,
        span,
        loop_datum,
    })
}

/// A number field (integers read as numbers), or the error naming it.
fn number(table: &toml::Table, key: &str) -> Result<Option<f64>> {
    match table.get(key) {
        None => Ok(None),
        Some(Value::Float(f)) => Ok(Some(*f)),
        Some(Value::Integer(i)) => Ok(Some(*i as f64)),
        Some(v) => bail!("invalid wear.{key} = {v}: must be a number"),
    }
}

/// A whole number from `min` to `max`, or the error naming `field`.
fn count(value: &Value, field: &str, min: u64, max: u64) -> Result<u64> {
    let raw = match value {
        Value::Integer(i) => RawCount::Integer(*i as i128),
        Value::Float(f) => RawCount::Float(*f),
        other => RawCount::Other(other.to_string()),
    };
    // count_in works in usize; the cycle counts fit (MAX_CYCLES < 2^53 <= usize::MAX on 64 bits).
    let n = count_in(&raw, field, min as usize, max as usize)?;
    Ok(n as u64)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn parse(text: &str) -> Result<WearSettings> {
        let table: toml::Table = toml::from_str(text).unwrap();
        resolve(Some(&table))
    }

    #[test]
    fn fields_are_read_and_bad_ones_named() {
        let s = parse("law = \"energy\"\ncoefficient = 1e-8\ncycles = 1000\ncheckpoints = [1, 10]\nshare = 0.3\nmax_depth_increment = 0.05").unwrap();
        assert_eq!(s.options.checkpoints(), &[1, 10, 1000]);
        assert_eq!(s.options.share(), 0.3);
        assert_eq!(s.span, DEFAULT_SPAN);
        let s = parse("law = \"archard\"\ncoefficient = 1e-8\ncycles = 1000000\ncheckpoints = 4")
            .unwrap();
        assert_eq!(s.options.checkpoints(), &[1, 100, 10_000, 1_000_000]);
        for (text, field) in [
            (
                "law = \"oops\"\ncoefficient = 1e-8\ncycles = 10",
                "wear.law",
            ),
            (
                "law = \"archard\"\ncoefficient = -1.0\ncycles = 10",
                "wear.coefficient",
            ),
            (
                "law = \"archard\"\ncoefficient = 1e-8\ncycles = 0",
                "wear.cycles",
            ),
            (
                "law = \"archard\"\ncoefficient = 1e-8\ncycles = 10\nshare = 2.0",
                "wear.share",
            ),
            (
                "law = \"archard\"\ncoefficient = 1e-8\ncycles = 10\ncheckpoints = [5, 3]",
                "wear.checkpoints[1]",
            ),
            (
                "law = \"archard\"\ncoefficient = 1e-8\ncycles = 10\nspan = 0.5",
                "wear.span",
            ),
            (
                "law = \"archard\"\ncoefficient = 1e-8\ncycles = 10\ncycle = 3",
                "wear.cycle",
            ),
            (
                "law = \"archard\"\ncoefficient = 1e-8\ncycles = 10\nloop_datum = 0",
                "wear.loop_datum",
            ),
        ] {
            let e = format!("{:#}", parse(text).unwrap_err());
            assert!(e.contains(field), "{text}: {e}");
        }
    }
}
