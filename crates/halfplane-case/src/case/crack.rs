//! The `[crack]` section (`docs/crack.md`): where the crack starts, its angle, the lengths to
//! analyse and its faces' friction. Every error names the field, the value and what is valid.

use super::count::{count_in, RawCount};
use anyhow::{anyhow, bail, Result};
use halfplane::crack::{
    CrackOptions, EffectiveRange, Position, CRITICAL_PLANE_PARAMETERS, MAX_POINTS, MIN_POINTS,
};
use halfplane::fatigue::Parameter;
use halfplane::written::Written;
use toml::Value;

/// Most lengths of a `{ from, to, count }` range.
const MAX_COUNT: usize = 1000;

/// Resolves `[crack]` (required by `halfplane crack`).
pub(super) fn resolve(table: Option<&toml::Table>) -> Result<CrackOptions> {
    let table = table.ok_or_else(|| {
        anyhow!("missing section [crack]: give at least lengths, e.g. lengths = {{ from = 0.005, to = 0.2, count = 20 }}")
    })?;
    const FIELDS: [&str; 7] = [
        "position",
        "angle",
        "lengths",
        "face_friction",
        "points",
        "effective_range",
        "initiation_parameter",
    ];
    if let Some(k) = table.keys().find(|k| !FIELDS.contains(&k.as_str())) {
        bail!(
            "unknown field crack.{k}: [crack] takes {}",
            FIELDS.join(", ")
        );
    }
    let position = match table.get("position") {
        None => Position::LargerRange,
        Some(Value::String(s)) if s == "left-edge" => Position::LeftEdge,
        Some(Value::String(s)) if s == "right-edge" => Position::RightEdge,
        Some(v) => match number(v) {
            Some(x) => Position::At(x),
            None => bail!("invalid crack.position = {v}: must be \"left-edge\", \"right-edge\" or an x value on the surface"),
        },
    };
    let critical_plane =
        matches!(table.get("angle"), Some(Value::String(s)) if s == "critical-plane");
    let angle = match table.get("angle") {
        None => 0.0,
        Some(_) if critical_plane => 0.0,
        Some(v) => number(v).ok_or_else(|| {
            anyhow!("invalid crack.angle = {v}: must be an angle in degrees from the surface normal, strictly between -90 and 90, or \"critical-plane\"")
        })?,
    };
    let parameter = match table.get("initiation_parameter") {
        None => Parameter::Swt,
        Some(_) if !critical_plane => bail!(
            "crack.initiation_parameter is used only with angle = \"critical-plane\": remove it, or set that angle"
        ),
        Some(v) => v
            .as_str()
            .and_then(|s| Parameter::ALL.into_iter().find(|p| p.name() == s))
            .ok_or_else(|| {
                anyhow!("invalid crack.initiation_parameter = {v}: must be {CRITICAL_PLANE_PARAMETERS}")
            })?,
    };
    let lengths = lengths(table.get("lengths"))?;
    let face_friction = match table.get("face_friction") {
        None => 0.0,
        Some(v) => number(v).ok_or_else(|| {
            anyhow!("invalid crack.face_friction = {v}: must be a friction coefficient >= 0")
        })?,
    };
    let mut options = CrackOptions::new(position, angle, lengths, face_friction)?;
    if critical_plane {
        options = options.with_critical_plane(parameter)?;
    }
    if let Some(v) = table.get("points") {
        let raw: RawCount = v
            .clone()
            .try_into()
            .map_err(|e| anyhow!("crack.points: {e}"))?;
        options = options.with_points(count_in(&raw, "crack.points", MIN_POINTS, MAX_POINTS)?)?;
    }
    options = options.with_effective(match table.get("effective_range") {
        None => EffectiveRange::Mts,
        Some(Value::String(s)) if s == "mts" => EffectiveRange::Mts,
        Some(Value::String(s)) if s == "quadratic" => EffectiveRange::Quadratic,
        Some(v) => bail!("invalid crack.effective_range = {v}: must be \"mts\" (maximum tangential stress) or \"quadratic\" (sqrt(dK_I^2 + dK_II^2))"),
    });
    Ok(options)
}

fn number(v: &Value) -> Option<f64> {
    match v {
        Value::Float(f) => Some(*f),
        Value::Integer(i) => Some(*i as f64),
        _ => None,
    }
}

/// A list of lengths, or `{ from, to, count }` spaced geometrically.
fn lengths(v: Option<&Value>) -> Result<Vec<f64>> {
    let bad = |v: &Value| {
        anyhow!("invalid crack.lengths = {v}: must be a list of lengths > 0 in ascending order, or {{ from, to, count }} (geometric spacing, 0 < from < to, count from 2 to {MAX_COUNT})")
    };
    match v {
        None => bail!(
            "missing field crack.lengths: give a list of crack lengths, or {{ from, to, count }}"
        ),
        Some(Value::Array(a)) => a.iter().map(|x| number(x).ok_or_else(|| bad(x))).collect(),
        Some(Value::Table(t)) => {
            if let Some(k) = t
                .keys()
                .find(|k| !["from", "to", "count"].contains(&k.as_str()))
            {
                bail!("unknown field crack.lengths.{k}: the range takes from, to, count");
            }
            let get = |k: &str| t.get(k).and_then(number);
            let (Some(from), Some(to)) = (get("from"), get("to")) else {
                return Err(bad(v.unwrap_or(&Value::Boolean(false))));
            };
            let raw: RawCount = t
                .get("count")
                .cloned()
                .ok_or_else(|| anyhow!("missing field crack.lengths.count: give the number of lengths (2 to {MAX_COUNT})"))?
                .try_into()
                .map_err(|e| anyhow!("crack.lengths.count: {e}"))?;
            let count = count_in(&raw, "crack.lengths.count", 2, MAX_COUNT)?;
            if !(from.is_finite() && to.is_finite() && from > 0.0 && to > from) {
                bail!(
                    "invalid crack.lengths = {{ from = {}, to = {} }}: must have 0 < from < to",
                    Written(from),
                    Written(to)
                );
            }
            let ratio = (to / from).powf(1.0 / (count - 1) as f64);
            Ok((0..count)
                .map(|i| {
                    if i + 1 == count {
                        to
                    } else {
                        from * ratio.powi(i as i32)
                    }
                })
                .collect())
        }
        Some(other) => Err(bad(other)),
    }
}
