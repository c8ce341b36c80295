//! `[history]`: a table, a cycle repeated, a harmonic or a gross-sliding history, resolved into
//! the library's [`History`] or a [`Sliding`] history; `cycles = "steady"` with its tolerance.

use super::count::{count_in, RawCount};
use super::{reject_unused, table};
use anyhow::{anyhow, bail, Result};
use halfplane::history::{Harmonic, History, Ramp, Steady};
use halfplane::written::Written;
use halfplane::{Cycle, LoadPoint};
use serde::Deserialize;
use std::path::Path;

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub(super) struct RawHistory {
    pub(super) kind: Option<String>,
    file: Option<String>,
    data: Option<String>,
    cycles: Option<RawCount>,
    max_cycles: Option<RawCount>,
    steady_tolerance: Option<f64>,
    steps_per_half: Option<RawCount>,
    steps_per_cycle: Option<RawCount>,
    ramp: Option<String>,
    ramp_steps: Option<RawCount>,
    normal: Option<RawLoad>,
    shear: Option<RawLoad>,
    bulk: Option<RawLoad>,
    moment: Option<RawLoad>,
    amplitude: Option<f64>,
}

/// A load of `[history]`: a number (`kind = "sliding"`) or a harmonic (`kind = "harmonic"`).
#[derive(Debug, Deserialize)]
#[serde(untagged)]
enum RawLoad {
    Number(f64),
    Harmonic(RawHarmonic),
}

impl RawLoad {
    /// The harmonic, or the error naming `history.{name}` written as a number.
    fn harmonic(self, name: &str) -> Result<RawHarmonic> {
        match self {
            RawLoad::Harmonic(h) => Ok(h),
            RawLoad::Number(v) => bail!(
                "invalid history.{name} = {v}: kind = \"harmonic\" takes {{ mean = ..., amplitude = ..., phase = degrees }}"
            ),
        }
    }

    /// The number, or the error naming `history.{name}` written as a harmonic.
    fn number(self, name: &str) -> Result<f64> {
        match self {
            RawLoad::Number(v) => Ok(v),
            RawLoad::Harmonic(_) => bail!(
                "invalid history.{name}: kind = \"sliding\" takes a number (the constant {name})"
            ),
        }
    }
}

/// A gross-sliding history (`[history] kind = "sliding"`): P (and M, sigma) ramped, then Q rising
/// to f P, the bodies sliding by `amplitude`, Q falling to -f P, sliding back, each cycle; run by
/// `halfplane wear` (docs/wear.md).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Sliding {
    /// The constant normal load (with its moment and bulk tension).
    pub load: LoadPoint,
    /// The bodies' relative sliding displacement once sliding, beyond the partial-slip onset:
    /// the distance they slide each way once Q reaches f P (> 0).
    pub amplitude: f64,
    /// Increments of Q from -f P to f P and back, per half-cycle.
    pub steps_per_half: usize,
    /// Increments of the ramp of P.
    pub ramp_steps: usize,
}

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
struct RawHarmonic {
    mean: Option<f64>,
    amplitude: Option<f64>,
    phase: Option<f64>,
}

/// `history.cycles = "steady"` (the word, as [`RawCount`] keeps it quoted), with
/// `history.max_cycles` (only then) and `history.steady_tolerance` (also with a number of
/// cycles, where it decides `steady_converged`).
pub(super) fn resolve_steady(h: &RawHistory) -> Result<(bool, Steady)> {
    let until_steady = match &h.cycles {
        Some(RawCount::Other(word)) if word == "\"steady\"" => true,
        Some(RawCount::Other(word)) => bail!(
            "invalid history.cycles = {word}: must be a whole number from 1 to {}, or \"steady\" (march until the cycle repeats)",
            halfplane::history::MAX_INCREMENTS
        ),
        _ => false,
    };
    let mut steady = Steady::default();
    if let Some(raw) = &h.max_cycles {
        if !until_steady {
            bail!("history.max_cycles is used only with history.cycles = \"steady\" (it bounds the cycles marched until the cycle repeats)");
        }
        let max = count_in(raw, "history.max_cycles", 2, Steady::MAX_CYCLES)?;
        steady = steady.with_max_cycles(max)?;
    }
    if let Some(t) = h.steady_tolerance {
        steady = steady.with_tolerance(t)?;
    }
    Ok((until_steady, steady))
}

/// `[history] kind = "sliding"`: normal (> 0), amplitude (> 0), steps_per_half and ramp_steps
/// (default 20), optional moment and bulk, and `cycles = 1` if given (the physical cycles are
/// `[wear] cycles`); nothing else.
pub(super) fn resolve_sliding(h: RawHistory) -> Result<Sliding> {
    let used = [
        "normal",
        "moment",
        "bulk",
        "amplitude",
        "steps_per_half",
        "ramp_steps",
        "cycles",
    ];
    let given = [
        ("file", h.file.is_some()),
        ("data", h.data.is_some()),
        ("max_cycles", h.max_cycles.is_some()),
        ("steady_tolerance", h.steady_tolerance.is_some()),
        ("steps_per_cycle", h.steps_per_cycle.is_some()),
        ("ramp", h.ramp.is_some()),
        ("shear", h.shear.is_some()),
    ];
    reject_unused("history", "sliding", &used, &given)?;
    let max = halfplane::history::MAX_INCREMENTS;
    let normal = h
        .normal
        .ok_or_else(|| {
            anyhow!("missing field history.normal: give the constant normal load P > 0 (N/mm)")
        })?
        .number("normal")?;
    let number = |v: Option<RawLoad>, name: &str| v.map_or(Ok(0.0), |v| v.number(name));
    let (bulk, moment) = (number(h.bulk, "bulk")?, number(h.moment, "moment")?);
    let load = LoadPoint::new("history", normal, 0.0, bulk)?.with_moment("history", moment)?;
    let amplitude = h.amplitude.ok_or_else(|| {
        anyhow!("missing field history.amplitude: give the distance the bodies slide each way once Q reaches f P (> 0, mm)")
    })?;
    if !(amplitude.is_finite() && amplitude > 0.0) {
        bail!(
            "invalid history.amplitude = {}: must be a finite sliding displacement > 0 (mm)",
            Written(amplitude)
        );
    }
    let steps_per_half = match &h.steps_per_half {
        Some(v) => count_in(v, "history.steps_per_half", 1, max)?,
        None => bail!(
            "missing field history.steps_per_half: give the increments of Q per half-cycle >= 1"
        ),
    };
    let ramp_steps = match &h.ramp_steps {
        Some(v) => count_in(v, "history.ramp_steps", 1, max)?,
        None => 20,
    };
    if let Some(v) = &h.cycles {
        count_in(v, "history.cycles", 1, 1)?;
    }
    Ok(Sliding {
        load,
        amplitude,
        steps_per_half,
        ramp_steps,
    })
}

pub(super) fn resolve_history(
    h: RawHistory,
    cycle: Option<&Cycle>,
    until_steady: bool,
    dir: &Path,
) -> Result<History> {
    let kind = match (&h.kind, h.file.is_some() || h.data.is_some()) {
        (Some(k), _) => k.clone(),
        (None, true) => "file".to_string(),
        (None, false) => bail!("missing field history.kind: give \"file\" (with file = ... or data = ...), \"cycle\", \"harmonic\" or \"sliding\" (wear only)"),
    };
    let used: &[&str] = match kind.as_str() {
        "file" => &["file", "data"],
        "cycle" => &[
            "cycles",
            "max_cycles",
            "steady_tolerance",
            "steps_per_half",
            "ramp",
            "ramp_steps",
        ],
        "harmonic" => &[
            "cycles",
            "max_cycles",
            "steady_tolerance",
            "steps_per_cycle",
            "ramp_steps",
            "normal",
            "shear",
            "bulk",
            "moment",
        ],
        other => bail!(
            "invalid history.kind = \"{other}\": must be one of \"file\", \"cycle\", \"harmonic\", \"sliding\""
        ),
    };
    let given = [
        ("file", h.file.is_some()),
        ("data", h.data.is_some()),
        ("cycles", h.cycles.is_some()),
        ("max_cycles", h.max_cycles.is_some()),
        ("steady_tolerance", h.steady_tolerance.is_some()),
        ("steps_per_half", h.steps_per_half.is_some()),
        ("steps_per_cycle", h.steps_per_cycle.is_some()),
        ("ramp", h.ramp.is_some()),
        ("ramp_steps", h.ramp_steps.is_some()),
        ("normal", h.normal.is_some()),
        ("shear", h.shear.is_some()),
        ("bulk", h.bulk.is_some()),
        ("moment", h.moment.is_some()),
        ("amplitude", h.amplitude.is_some()),
    ];
    reject_unused("history", &kind, used, &given)?;
    let max = halfplane::history::MAX_INCREMENTS;
    let count = |v: &Option<RawCount>, field: &str, min: usize, what: &str| match v {
        Some(v) => count_in(v, &format!("history.{field}"), min, max),
        None => Err(anyhow!("missing field history.{field}: give {what}")),
    };
    // Marched until steady, the history holds one cycle; the march repeats it.
    let cycles = |h: &RawHistory| match until_steady {
        true => Ok(1),
        false => count(
            &h.cycles,
            "cycles",
            1,
            "the number of cycles >= 1, or \"steady\" (until the cycle repeats)",
        ),
    };
    let ramp_steps = match &h.ramp_steps {
        Some(v) => count_in(v, "history.ramp_steps", 1, max)?,
        None => 20,
    };
    Ok(match kind.as_str() {
        "file" => {
            let table = table::source("history", h.file.as_deref(), h.data.as_deref(), dir)?
                .ok_or_else(|| anyhow!("missing field history.file: give the CSV (columns normal,shear,bulk, and moment if any), relative to the case file, or its text as history.data"))?;
            table::history_rows(&table)?
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
                cycles(&h)?,
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
            let harmonic = |raw: Option<RawLoad>, name: &str| -> Result<Harmonic> {
                let field = format!("history.{name}");
                let Some(r) = raw else {
                    return Ok(Harmonic::new(&field, 0.0, 0.0, 0.0)?);
                };
                let r = r.harmonic(name)?;
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
            let cycle_count = cycles(&h)?;
            if h.normal.is_none() {
                bail!("missing field history.normal: give {{ mean = P0 > 0, amplitude = ..., phase = degrees }}");
            }
            History::harmonic_with_moment(
                [
                    harmonic(h.normal, "normal")?,
                    harmonic(h.shear, "shear")?,
                    harmonic(h.bulk, "bulk")?,
                    harmonic(h.moment, "moment")?,
                ],
                cycle_count,
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
