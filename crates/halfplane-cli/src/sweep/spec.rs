//! The `[sweep]` section of a sweep spec: the plan (grid, random, Latin hypercube), the analysis
//! and the varied paths, each checked once, up front, against the case the rest of the file
//! describes. Every error names the path or field and what would be valid.

use anyhow::{anyhow, bail, Result};
use halfplane::design::{Design, GridAxis, Range, SampledAxis, Scale};
use toml::{Table, Value};

/// What each row runs.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Analysis {
    /// The steady state of the case's `[cycle]` (the default).
    Steady,
    /// Time marching through the case's `[history]`, plus the steady state when it has a
    /// `[cycle]`.
    March,
    /// The crack of the case's `[crack]` over the steady cycle of its `[history]` (its verdict
    /// and arrest length: a crack-arrest map), plus the steady state when it has a `[cycle]`.
    Crack,
    /// Fretting wear of the case's `[wear]` over its `[history]` cycle (`halfplane wear`),
    /// recorded at the last checkpoint, plus the steady state when it has a `[cycle]`.
    Wear,
}

/// A varied field: its dotted path as written, the path's keys, and whether the case writes it
/// as an integer (then every value is rounded to the nearest whole number).
#[derive(Debug, Clone, PartialEq)]
pub struct Varied {
    /// The path as written in `[sweep.vary]`: the column name.
    pub path: String,
    /// The keys from the case's top level down.
    pub keys: Vec<String>,
    /// The case writes an integer there.
    pub integer: bool,
}

/// A parsed sweep spec: the case (the file without `[sweep]`) and what varies over it.
#[derive(Debug, Clone)]
pub struct Spec {
    /// The case table, as written.
    pub case: Table,
    /// The varied fields, in the order written.
    pub varied: Vec<Varied>,
    /// The design of the rows.
    pub design: Design,
    /// What each row runs.
    pub analysis: Analysis,
    /// The largest value each varied field takes (in the spec's order): the end of its range or
    /// the largest listed value, for the size estimate of `sweep::size`.
    pub largest: Vec<f64>,
    /// What sets the number of rows, as the spec writes it (`sweep.samples = 1000`, or the
    /// grid's counts), for messages about the sweep's size.
    pub rows_from: String,
}

const MODES: &str = "\"grid\", \"random\" or \"latin-hypercube\"";

/// Parses a spec's text.
pub fn parse(text: &str) -> Result<Spec> {
    let mut case: Table = text
        .parse()
        .map_err(|e: toml::de::Error| anyhow!("{}", e.to_string().trim_end()))?;
    let sweep = match case.remove("sweep") {
        Some(Value::Table(t)) => t,
        Some(other) => bail!(
            "sweep must be a section [sweep], found a {}",
            other.type_str()
        ),
        None => bail!(
            "missing section [sweep]: give mode = {MODES} and a [sweep.vary] table of dotted paths"
        ),
    };
    for key in sweep.keys() {
        if !["mode", "samples", "seed", "analysis", "vary"].contains(&key.as_str()) {
            bail!(
                "unknown field sweep.{key}: [sweep] takes mode, samples, seed, analysis and vary"
            );
        }
    }
    let mode = match sweep.get("mode") {
        Some(Value::String(s)) => s.as_str(),
        Some(other) => bail!("invalid sweep.mode = {other}: must be {MODES}"),
        None => bail!("missing field sweep.mode: give {MODES}"),
    };
    let analysis = match sweep.get("analysis") {
        None => Analysis::Steady,
        Some(Value::String(s)) if s == "steady" => Analysis::Steady,
        Some(Value::String(s)) if s == "march" => Analysis::March,
        Some(Value::String(s)) if s == "crack" => Analysis::Crack,
        Some(Value::String(s)) if s == "wear" => Analysis::Wear,
        Some(other) => {
            bail!("invalid sweep.analysis = {other}: must be \"steady\" (the default), \"march\", \"crack\" or \"wear\"")
        }
    };
    let vary = match sweep.get("vary") {
        Some(Value::Table(t)) if !t.is_empty() => t,
        Some(Value::Table(_)) => {
            bail!("sweep.vary is empty: give at least one dotted path, e.g. \"friction.coefficient\" = [0.3, 0.6]")
        }
        Some(other) => bail!(
            "invalid sweep.vary = {other}: must be a table [sweep.vary] of dotted paths, each with \
             its values, e.g. \"friction.coefficient\" = [0.3, 0.6]"
        ),
        None => bail!("missing section [sweep.vary]: give the dotted paths to vary, e.g. \"friction.coefficient\" = [0.3, 0.6]"),
    };
    let mut varied = Vec::with_capacity(vary.len());
    for path in vary.keys() {
        varied.push(lookup(&case, path)?);
    }
    let names: Vec<String> = varied
        .iter()
        .map(|v| format!("sweep.vary.\"{}\"", v.path))
        .collect();
    let names: Vec<&str> = names.iter().map(String::as_str).collect();
    let rows_from;
    let design = match mode {
        "grid" => {
            for key in ["samples", "seed"] {
                if sweep.contains_key(key) {
                    bail!("sweep.{key} is used only by mode = \"random\" or \"latin-hypercube\" (a grid takes every combination)");
                }
            }
            let axes = vary
                .iter()
                .zip(&names)
                .map(|((_, v), name)| grid_axis(name, v))
                .collect::<Result<Vec<_>>>()?;
            let counts: Vec<String> = axes
                .iter()
                .map(|a| match a {
                    GridAxis::List(v) => v.len().to_string(),
                    GridAxis::Steps(_, n) => n.to_string(),
                })
                .collect();
            rows_from = format!("the grid's {} rows (sweep.vary)", counts.join(" x "));
            Design::grid(&names, axes)?
        }
        "random" | "latin-hypercube" => {
            let samples = whole(&sweep, "samples", "the number of rows, e.g. samples = 1000")?;
            let seed = whole(
                &sweep,
                "seed",
                "a whole number >= 0 that fixes the values, e.g. seed = 1",
            )?;
            let axes = vary
                .iter()
                .zip(&names)
                .map(|((_, v), name)| sampled_axis(name, v))
                .collect::<Result<Vec<_>>>()?;
            rows_from = format!("sweep.samples = {samples}");
            if mode == "random" {
                Design::random(&names, axes, samples, seed)?
            } else {
                Design::latin_hypercube(&names, axes, samples, seed)?
            }
        }
        other => bail!("invalid sweep.mode = \"{other}\": must be {MODES}"),
    };
    let largest = vary.values().map(largest).collect();
    Ok(Spec {
        case,
        varied,
        design,
        analysis,
        largest,
        rows_from,
    })
}

/// The largest value of a varied field's list or range (NaN when it has none).
fn largest(value: &Value) -> f64 {
    let of = |v: &Value| match v {
        Value::Integer(i) => *i as f64,
        Value::Float(f) => *f,
        _ => f64::NAN,
    };
    match value {
        Value::Array(values) => values.iter().map(of).fold(f64::NAN, f64::max),
        Value::Table(t) => ["from", "to"]
            .iter()
            .filter_map(|k| t.get(*k))
            .map(of)
            .fold(f64::NAN, f64::max),
        _ => f64::NAN,
    }
}

/// Finds `path` in the case: it must name a number the case writes.
fn lookup(case: &Table, path: &str) -> Result<Varied> {
    let keys: Vec<String> = path.split('.').map(str::to_string).collect();
    let mut table = case;
    for (i, key) in keys.iter().enumerate() {
        let here = keys[..=i].join(".");
        let Some(value) = table.get(key) else {
            let known = numeric_paths(case, "");
            bail!(
                "sweep.vary: unknown path \"{path}\": the case has no field {here} (numeric fields it has: {}); a field that takes a default must be written in the case to be varied",
                known.join(", ")
            );
        };
        match value {
            Value::Table(t) if i + 1 < keys.len() => table = t,
            Value::Integer(_) | Value::Float(_) if i + 1 == keys.len() => {
                return Ok(Varied {
                    path: path.to_string(),
                    keys,
                    integer: matches!(value, Value::Integer(_)),
                })
            }
            Value::Table(_) => bail!(
                "sweep.vary: \"{path}\" is a section of the case, not a number: name one of its numeric fields"
            ),
            other => bail!(
                "sweep.vary: \"{path}\" is not numeric: {here} is a {} ({other}) in the case; only numeric fields can vary",
                other.type_str()
            ),
        }
    }
    bail!("sweep.vary: the path \"{path}\" is empty")
}

/// Every numeric field of the case, as dotted paths.
fn numeric_paths(table: &Table, prefix: &str) -> Vec<String> {
    let mut out = Vec::new();
    for (key, value) in table {
        let path = format!("{prefix}{key}");
        match value {
            Value::Integer(_) | Value::Float(_) => out.push(path),
            Value::Table(t) => out.extend(numeric_paths(t, &format!("{path}."))),
            _ => {}
        }
    }
    out
}

/// A whole number >= 0 from `[sweep]`.
fn whole(sweep: &Table, key: &str, what: &str) -> Result<u64> {
    match sweep.get(key) {
        Some(Value::Integer(i)) if *i >= 0 => Ok(*i as u64),
        Some(other) => bail!("invalid sweep.{key} = {other}: must be {what}"),
        None => bail!("missing field sweep.{key}: give {what}"),
    }
}

fn number(value: &Value, field: &str) -> Result<f64> {
    match value {
        Value::Integer(i) => Ok(*i as f64),
        Value::Float(f) => Ok(*f),
        other => bail!("invalid {field} = {other}: must be a number"),
    }
}

fn list(name: &str, values: &[Value]) -> Result<Vec<f64>> {
    if values.is_empty() {
        bail!(
            "{name} = [] is an empty list: give the values to take, e.g. {name} = [0.3, 0.6], or a \
             range {{ from = 0.3, to = 0.6 }} (with count = ... in a grid)"
        );
    }
    values
        .iter()
        .enumerate()
        .map(|(i, v)| number(v, &format!("{name}[{i}]")))
        .collect()
}

/// `{ from, to, count, scale }`: the range, and the count if given.
fn range<'t>(name: &str, t: &'t Table) -> Result<(Range, Option<&'t Value>)> {
    for key in t.keys() {
        if !["from", "to", "count", "scale"].contains(&key.as_str()) {
            bail!(
                "unknown field {name}.{key}: a range takes from, to, scale and (in a grid) count"
            );
        }
    }
    let end = |key: &str| -> Result<f64> {
        let v = t
            .get(key)
            .ok_or_else(|| anyhow!("missing field {name}.{key}: a range needs from and to"))?;
        number(v, &format!("{name}.{key}"))
    };
    let scale = match t.get("scale") {
        None => Scale::Linear,
        Some(Value::String(s)) if s == "linear" => Scale::Linear,
        Some(Value::String(s)) if s == "log" => Scale::Log,
        Some(other) => bail!("invalid {name}.scale = {other}: must be \"linear\" or \"log\""),
    };
    let range = Range::new(name, end("from")?, end("to")?, scale)?;
    Ok((range, t.get("count")))
}

fn grid_axis(name: &str, value: &Value) -> Result<GridAxis> {
    match value {
        Value::Array(values) => Ok(GridAxis::List(list(name, values)?)),
        Value::Table(t) => {
            let (range, count) = range(name, t)?;
            let count = match count {
                Some(&Value::Integer(n)) if n >= 0 => n as usize,
                Some(other) => {
                    bail!("invalid {name}.count = {other}: must be a whole number >= 1")
                }
                None => bail!("missing field {name}.count: a grid range needs the number of values, both ends included"),
            };
            Ok(GridAxis::Steps(range, count))
        }
        other => bail!("invalid {name} = {other}: give a list of values [...] or a range {{ from = ..., to = ..., count = ... }}"),
    }
}

fn sampled_axis(name: &str, value: &Value) -> Result<SampledAxis> {
    match value {
        Value::Array(values) => Ok(SampledAxis::List(list(name, values)?)),
        Value::Table(t) => {
            let (range, count) = range(name, t)?;
            if count.is_some() {
                bail!("{name}.count is used only by mode = \"grid\": a random or latin-hypercube sweep draws `samples` values from the range");
            }
            Ok(SampledAxis::Range(range))
        }
        other => bail!(
            "invalid {name} = {other}: give a list of values [...] or a range {{ from = ..., to = ... }}"
        ),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    const CASE: &str = r#"
[material]
youngs_modulus = 200000.0
poisson_ratio = 0.3
[friction]
coefficient = 0.6
[profile]
kind = "hertz"
radius = 50.0
[cycle]
point1 = { normal = 1000.0, shear = -250.0 }
point2 = { normal = 1400.0, shear = 250.0 }
[solver]
cells = 200
"#;

    fn error(sweep: &str) -> String {
        match parse(&format!("{CASE}{sweep}")) {
            Ok(_) => panic!("accepted: {sweep}"),
            Err(e) => format!("{e:#}"),
        }
    }

    #[test]
    fn paths_keep_their_written_order_and_integer_fields_are_marked() {
        let spec = parse(&format!(
            "{CASE}[sweep]\nmode = \"grid\"\n[sweep.vary]\n\"profile.radius\" = [10, 20]\n\"friction.coefficient\" = [0.3]\n\"solver.cells\" = [100]\n"
        ))
        .expect("valid spec");
        let paths: Vec<_> = spec.varied.iter().map(|v| v.path.as_str()).collect();
        assert_eq!(
            paths,
            ["profile.radius", "friction.coefficient", "solver.cells"]
        );
        let ints: Vec<_> = spec.varied.iter().map(|v| v.integer).collect();
        assert_eq!(ints, [false, false, true]);
        assert!(!spec.case.contains_key("sweep"));
        assert_eq!(spec.design.rows(), 2);
    }

    #[test]
    fn bad_specs_name_the_problem() {
        let grid = "[sweep]\nmode = \"grid\"\n[sweep.vary]\n";
        for (vary, expected) in [
            (
                "\"profile.radus\" = [1.0]",
                "unknown path \"profile.radus\"",
            ),
            (
                "\"profile.kind\" = [1.0]",
                "\"profile.kind\" is not numeric",
            ),
            (
                "\"cycle.point1.bulk\" = [1.0]",
                "no field cycle.point1.bulk",
            ),
            ("\"cycle\" = [1.0]", "is a section of the case"),
            (
                "\"profile.radius\" = { from = 1.0, to = 2.0, count = 0 }",
                "sweep.vary.\"profile.radius\".count = 0",
            ),
            (
                "\"profile.radius\" = { from = 2.0, to = 1.0, count = 3 }",
                "from must not exceed to",
            ),
            (
                "\"profile.radius\" = { from = 0.0, to = 1.0, count = 3, scale = \"log\" }",
                "cannot reach or cross zero",
            ),
            (
                "\"cycle.point1.shear\" = { from = -1.0, to = 1.0, count = 3, scale = \"log\" }",
                "cannot reach or cross zero",
            ),
            (
                "\"profile.radius\" = { from = 1.0, to = 2.0 }",
                "missing field sweep.vary.\"profile.radius\".count",
            ),
            (
                "\"profile.radius\" = []",
                "sweep.vary.\"profile.radius\" = [] is an empty list",
            ),
            (
                "\"profile.radius\" = [\"big\"]",
                "sweep.vary.\"profile.radius\"[0]",
            ),
            (
                "\"profile.radius\" = { from = 1.0, to = 2.0, count = 2, step = 1 }",
                "unknown field sweep.vary.\"profile.radius\".step",
            ),
        ] {
            let message = error(&format!("{grid}{vary}\n"));
            assert!(message.contains(expected), "{vary}: {message}");
        }
        let random = "[sweep]\nmode = \"random\"\nsamples = 10\nseed = 1\n[sweep.vary]\n";
        let message = error(&format!(
            "{random}\"profile.radius\" = {{ from = 1.0, to = 2.0, count = 3 }}\n"
        ));
        assert!(
            message.contains("used only by mode = \"grid\""),
            "{message}"
        );
        let message = error(
            "[sweep]\nmode = \"random\"\nseed = 1\n[sweep.vary]\n\"profile.radius\" = [1.0]\n",
        );
        assert!(message.contains("missing field sweep.samples"), "{message}");
        let message =
            error("[sweep]\nmode = \"latin\"\n[sweep.vary]\n\"profile.radius\" = [1.0]\n");
        assert!(
            message.contains("invalid sweep.mode = \"latin\""),
            "{message}"
        );
        let message = error("[sweep]\nmode = \"grid\"\n[sweep.vary]\n");
        assert!(message.contains("sweep.vary is empty"), "{message}");
        assert!(error("").contains("missing section [sweep]"));
    }
}
