//! `halfplane plot design-map`: a sweep's output drawn over two of its varied paths, coloured by
//! regime or by any numeric column (filled contours), axes labelled in words with units.

use crate::args::DesignMapArgs;
use crate::output::note;
use crate::sweep::read::{self, Values};
use anyhow::{anyhow, bail, Result};
use halfplane_plot::{DesignMap, MapColor};
use std::path::PathBuf;

/// Relative tolerance of `--where PATH=VALUE`: the sweep wrote the value in full, so only
/// rounding in a hand-typed value needs room.
const WHERE_TOLERANCE: f64 = 1e-9;

/// The unit names the map's labels show: a sweep's output does not record the case's `[units]`,
/// so the labels name the defaults (N, mm, MPa).
const FORCE_PER_LENGTH: &str = "N/mm";
const LENGTH: &str = "mm";
const STRESS: &str = "MPa";

/// What a sweep's column is, in words with its unit, for an axis or colour-bar label: the varied
/// paths a sweep takes (`cycle.point2.shear`: "shear load Q at point 2 (N/mm)") and the columns
/// it writes (`slip_right_1`: "right slip zone at point 1 (mm)"). A column not in the table is
/// shown by its name.
pub fn describe(column: &str) -> String {
    let with = |name: &str, unit: &str| match unit {
        "" => name.to_string(),
        u => format!("{name} ({u})"),
    };
    let per_point = |name: &str, n: &str, unit: &str| with(&format!("{name} at point {n}"), unit);
    let keys: Vec<&str> = column.split('.').collect();
    match keys.as_slice() {
        ["cycle", point, part] if point.starts_with("point") => {
            let n = &point["point".len()..];
            match *part {
                "normal" => per_point("normal load P", n, FORCE_PER_LENGTH),
                "shear" => per_point("shear load Q", n, FORCE_PER_LENGTH),
                "bulk" => per_point("bulk stress σ", n, STRESS),
                _ => column.to_string(),
            }
        }
        ["material", "youngs_modulus"] => with("Young's modulus E", STRESS),
        ["material", "poisson_ratio"] => with("Poisson's ratio ν", ""),
        ["friction", "coefficient"] => with("friction coefficient f", ""),
        ["profile", "radius"] => with("radius R", LENGTH),
        ["profile", "flat_half_width"] => with("flat half-width b", LENGTH),
        ["profile", "coefficient"] => with("power-law coefficient B", ""),
        ["profile", "exponent"] => with("power-law exponent k", ""),
        ["regime"] => "regime".into(),
        ["crack", "verdict"] => "crack verdict".into(),
        ["crack", "arrest_length"] => with("crack arrest length", LENGTH),
        ["wear", "coefficient"] => with("wear coefficient", &format!("1/{STRESS}")),
        ["wear", "wear_volume"] => with("wear volume per unit thickness", &format!("{LENGTH}²")),
        ["wear", "max_depth"] => with("largest wear depth", LENGTH),
        ["wear", "energy_per_cycle"] => with(
            "energy dissipated in the last cycle",
            &format!("N {LENGTH}/{LENGTH}"),
        ),
        ["wear", "dissipated_energy"] => with("energy dissipated", &format!("N {LENGTH}/{LENGTH}")),
        ["wear", "contact_left"] => with("worn contact left end", LENGTH),
        ["wear", "contact_right"] => with("worn contact right end", LENGTH),
        ["wear", "peak_pressure"] => with("worn peak pressure", STRESS),
        ["wear", "stick_left"] => with("worn stick zone left end", LENGTH),
        ["wear", "stick_right"] => with("worn stick zone right end", LENGTH),
        ["wear", "slip_amplitude_max"] => with("worn largest slip amplitude", LENGTH),
        ["wear", "simulated_cycles"] => "wear cycles marched".into(),
        ["stick_left"] => with("stick zone left end", LENGTH),
        ["stick_right"] => with("stick zone right end", LENGTH),
        ["final_stick_left"] => with("final stick zone left end", LENGTH),
        ["final_stick_right"] => with("final stick zone right end", LENGTH),
        ["max_slip_amplitude"] => with("largest slip amplitude", LENGTH),
        ["energy"] => with(
            "energy dissipated in the last cycle",
            &format!("N {LENGTH}/{LENGTH}"),
        ),
        ["shakedown_cycle"] => "shakedown cycle".into(),
        ["cycles_run"] => "cycles run".into(),
        ["steady_change"] => "change of the slip ranges in the last cycle".into(),
        ["steady_converged"] => "steady state reached (1 yes, 0 no)".into(),
        [one] => {
            let (name, n) = match one.rsplit_once('_') {
                Some((name, n @ ("1" | "2"))) => (name, n),
                _ => return column.to_string(),
            };
            match name {
                "half_width" => per_point("contact half-width a", n, LENGTH),
                "slip_left" => per_point("left slip zone", n, LENGTH),
                "slip_right" => per_point("right slip zone", n, LENGTH),
                _ => column.to_string(),
            }
        }
        _ => column.to_string(),
    }
}

/// What `design-map` draws and where.
#[derive(Debug, Clone)]
pub struct DesignMapConfig {
    /// The map's data.
    pub map: DesignMap,
    /// The output file (.svg or .png).
    pub output: PathBuf,
}

fn filter(text: &str) -> Result<(String, f64)> {
    let (path, value) = text.split_once('=').ok_or_else(|| {
        anyhow!(
            "invalid --where {text:?}: must be PATH=VALUE, e.g. --where friction.coefficient=0.3"
        )
    })?;
    let value: f64 = value.trim().parse().map_err(|_| {
        anyhow!(
            "invalid --where {text:?}: the value {:?} is not a number",
            value.trim()
        )
    })?;
    Ok((path.trim().to_string(), value))
}

/// The text columns a sweep writes for colouring: drawn as categories.
const CATEGORIES: [&str; 2] = ["regime", "crack.verdict"];

/// The colour of the rows `keep`: categories for `regime` and `crack.verdict` (the text columns
/// a sweep writes for colouring), numbers for any other column. Text anywhere else is an error naming the
/// column (the `error` column, or a cell a sweep never writes), since drawing it as categories
/// or skipping it would give a map that looks valid; rows without a value (failed cases, the
/// stick zone in gross sliding) are drawn as "no value", and stderr says how many.
fn color(args: &DesignMapArgs, table: &read::SweepTable, keep: &[usize]) -> Result<MapColor> {
    let name = &args.color;
    let file = args.sweep.display();
    let numeric: Vec<&str> = table
        .names
        .iter()
        .map(String::as_str)
        .filter(|n| *n != "error" && !CATEGORIES.contains(n))
        .collect();
    if name == "error" {
        bail!(
            "--color error: column error of {file} holds text (each failed row's message), not numbers; --color takes regime, crack.verdict or a numeric column ({})",
            numeric.join(", ")
        );
    }
    match &table.columns[2] {
        Values::Text(v) if CATEGORIES.contains(&name.as_str()) => Ok(MapColor::Category(
            keep.iter().map(|&i| v[i].clone()).collect(),
        )),
        Values::Text(v) => {
            let text = |c: &&String| !c.trim().is_empty() && c.trim().parse::<f64>().is_err();
            let numbers = v.iter().filter(|c| c.trim().parse::<f64>().is_ok()).count();
            match v.iter().position(|c| text(&c)) {
                Some(row) if numbers > 0 => bail!(
                    "--color {name}: row {} of {file} has {:?} in column {name}, which is not a number; a sweep writes only numbers or empty cells there",
                    row + 1,
                    v[row]
                ),
                _ => bail!(
                    "--color {name}: column {name} of {file} holds text, not numbers; --color takes regime, crack.verdict or a numeric column ({})",
                    numeric.join(", ")
                ),
            }
        }
        Values::Number(_) if CATEGORIES.contains(&name.as_str()) => bail!(
            "--color {name}: column {name} of {file} holds numbers, not names; this is not a sweep's output"
        ),
        Values::Number(v) => {
            let values: Vec<Option<f64>> = keep.iter().map(|&i| v[i]).collect();
            let empty: Vec<usize> = keep.iter().copied().filter(|&i| v[i].is_none()).collect();
            if let Some(first) = empty.first() {
                note(&format!(
                    "warning: {} of {} rows drawn have no value of {name} (failed cases, or no stick zone in gross sliding; see the error and regime columns), first row {}: drawn grey as \"no value\"",
                    empty.len(),
                    keep.len(),
                    first + 1
                ));
            }
            if values.iter().all(Option::is_none) {
                bail!("--color {name}: no row drawn has a value of {name} in {file}");
            }
            Ok(MapColor::Numeric(values))
        }
    }
}

impl DesignMapConfig {
    /// Reads the columns the map needs and keeps the rows `--where` selects.
    pub fn resolve(args: &DesignMapArgs) -> Result<Self> {
        let filters = args
            .filter
            .iter()
            .map(|f| filter(f))
            .collect::<Result<Vec<_>>>()?;
        if args.x == args.y {
            bail!(
                "--x and --y both name {:?}: a map needs two different columns (the varied paths)",
                args.x
            );
        }
        let mut wanted = vec![args.x.as_str(), args.y.as_str(), args.color.as_str()];
        wanted.extend(filters.iter().map(|f| f.0.as_str()));
        let table = read::read(&args.sweep, &wanted)?;
        let numbers = |k: usize| -> Result<&Vec<Option<f64>>> {
            match &table.columns[k] {
                Values::Number(v) => Ok(v),
                Values::Text(_) => bail!(
                    "column {} of {} is not numeric: --x, --y and --where need numeric columns (the varied paths: {})",
                    wanted[k],
                    args.sweep.display(),
                    table.varied.join(", ")
                ),
            }
        };
        let (xs, ys) = (numbers(0)?, numbers(1)?);
        let wheres = (0..filters.len())
            .map(|k| numbers(3 + k))
            .collect::<Result<Vec<_>>>()?;
        let keep: Vec<usize> = (0..table.rows)
            .filter(|&i| {
                filters.iter().zip(&wheres).all(|((_, want), col)| {
                    col[i]
                        .is_some_and(|v| (v - want).abs() <= WHERE_TOLERANCE * want.abs().max(1.0))
                })
            })
            .collect();
        if keep.is_empty() {
            bail!(
                "no rows to draw in {}{}",
                args.sweep.display(),
                if filters.is_empty() {
                    ""
                } else {
                    " after --where"
                }
            );
        }
        let mut points = Vec::with_capacity(keep.len());
        for &i in &keep {
            match (xs[i], ys[i]) {
                (Some(x), Some(y)) => points.push((x, y)),
                _ => bail!(
                    "row {} of {} has no value of {} or {}",
                    i + 1,
                    args.sweep.display(),
                    args.x,
                    args.y
                ),
            }
        }
        let mut sorted = points.clone();
        sorted.sort_by(|a, b| a.0.total_cmp(&b.0).then(a.1.total_cmp(&b.1)));
        if sorted.windows(2).any(|w| w[0] == w[1]) {
            let others: Vec<&str> = table
                .varied
                .iter()
                .map(String::as_str)
                .filter(|p| *p != args.x && *p != args.y && !filters.iter().any(|f| f.0 == *p))
                .collect();
            bail!(
                "several rows share the same ({}, {}): the sweep also varies {}; pick one value of each with --where PATH=VALUE",
                args.x,
                args.y,
                if others.is_empty() { "nothing else (the output repeats rows)".to_string() } else { others.join(", ") }
            );
        }
        let color = color(args, &table, &keep)?;
        Ok(Self {
            map: DesignMap {
                x_label: describe(&args.x),
                y_label: describe(&args.y),
                color_label: describe(&args.color),
                points,
                color,
            },
            output: args.output.clone(),
        })
    }
}

/// Draws the map and says where on stderr.
pub fn run(config: &DesignMapConfig) -> Result<()> {
    let figure = halfplane_plot::design_map_figure(&config.map)?;
    halfplane_plot::write(&figure, &config.output)?;
    note(&format!("wrote {}", config.output.display()));
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn columns_are_described_in_words_with_their_units() {
        for (column, want) in [
            ("cycle.point2.shear", "shear load Q at point 2 (N/mm)"),
            ("cycle.point1.normal", "normal load P at point 1 (N/mm)"),
            ("cycle.point1.bulk", "bulk stress σ at point 1 (MPa)"),
            ("friction.coefficient", "friction coefficient f"),
            ("profile.radius", "radius R (mm)"),
            ("material.youngs_modulus", "Young's modulus E (MPa)"),
            ("slip_right_1", "right slip zone at point 1 (mm)"),
            ("half_width_2", "contact half-width a at point 2 (mm)"),
            ("energy", "energy dissipated in the last cycle (N mm/mm)"),
            ("regime", "regime"),
            ("wear.coefficient", "wear coefficient (1/MPa)"),
            ("wear.wear_volume", "wear volume per unit thickness (mm²)"),
            ("wear.stick_left", "worn stick zone left end (mm)"),
            // Not in the table: the name as given.
            ("solver.cells", "solver.cells"),
            ("slip_right_3", "slip_right_3"),
        ] {
            assert_eq!(describe(column), want, "{column}");
        }
    }
}
