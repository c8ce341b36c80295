//! `halfplane plot design-map`: a sweep's output drawn over two of its varied paths, coloured by
//! regime or by any numeric column (with contours).

use crate::args::DesignMapArgs;
use crate::output::note;
use crate::sweep::read::{self, Values};
use anyhow::{anyhow, bail, Result};
use halfplane_plot::{DesignMap, MapColor};
use std::path::PathBuf;

/// Relative tolerance of `--where PATH=VALUE`: the sweep wrote the value in full, so only
/// rounding in a hand-typed value needs room.
const WHERE_TOLERANCE: f64 = 1e-9;

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

/// The colour of the rows `keep`: categories for `regime` (the one text column a sweep writes
/// for colouring), numbers for any other column. Text anywhere else is an error naming the
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
        .filter(|n| !matches!(*n, "regime" | "error"))
        .collect();
    if name == "error" {
        bail!(
            "--color error: column error of {file} holds text (each failed row's message), not numbers; --color takes regime or a numeric column ({})",
            numeric.join(", ")
        );
    }
    match &table.columns[2] {
        Values::Text(v) if name == "regime" => Ok(MapColor::Category(
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
                    "--color {name}: column {name} of {file} holds text, not numbers; --color takes regime or a numeric column ({})",
                    numeric.join(", ")
                ),
            }
        }
        Values::Number(_) if name == "regime" => bail!(
            "--color regime: column regime of {file} holds numbers, not regime names; this is not a sweep's output"
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
                x_label: args.x.clone(),
                y_label: args.y.clone(),
                color_label: args.color.clone(),
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
