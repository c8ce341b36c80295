//! How large a sweep is, estimated from its spec before the first row runs: the output it would
//! write and the core time it would take, each checked against `crate::limits`.
//!
//! A march sweep's rows are bounded by its largest case: the whole-number fields it varies
//! (`solver.cells`, `history.cycles`, steps) at the largest values they take, since cells and
//! increments only grow with them.
//!
//! A wear sweep's rows march an unknown number of cycles (the jumps are chosen as the run goes),
//! so its estimate assumes a bound on the cycles marched ([`wear_marched_cycles`]).

use super::spec::{Analysis, Spec};
use super::template::{number, set};
use crate::case::{self, Case};
use crate::commands::sweep::OutputFormat;
use crate::limits::{self, Quantity, TooLarge};
use std::path::Path;

/// Bytes of one number in a CSV row: the mean length of Rust's shortest round-trip form of
/// computed values, with the comma (measured on the example sweeps; see README "Size limits").
pub const CSV_NUMBER_BYTES: f64 = 20.0;
/// Bytes of one number in Parquet (a Float64; Snappy does not shrink computed values).
pub const PARQUET_NUMBER_BYTES: f64 = 8.0;

/// The field that sets the number of rows, as the spec writes it.
fn rows_field(spec: &Spec, rows: u64, shard: bool) -> String {
    match shard {
        true => format!("{rows} rows of this --shard, of {}", spec.rows_from),
        false => spec.rows_from.clone(),
    }
}

/// The estimated output bytes of `rows` rows.
pub fn output_bytes(spec: &Spec, rows: u64, format: OutputFormat) -> f64 {
    let mut numbers = spec.varied.len() + 10;
    match spec.analysis {
        Analysis::March => numbers += 5,
        Analysis::Crack => numbers += 2,
        Analysis::Wear => numbers += 11,
        Analysis::Steady => {}
    }
    let per = match format {
        OutputFormat::Csv => CSV_NUMBER_BYTES,
        OutputFormat::Parquet => PARQUET_NUMBER_BYTES,
    };
    rows as f64 * numbers as f64 * per
}

/// The core time of one row: building its case and the steady analysis, plus the march of the
/// largest case.
fn row_seconds(spec: &Spec, dir: &Path, direct: bool) -> f64 {
    if direct {
        return limits::DIRECT_ROW_SECONDS;
    }
    if spec.analysis == Analysis::Steady {
        return limits::REREAD_ROW_SECONDS;
    }
    let mut table = spec.case.clone();
    for (varied, &v) in spec.varied.iter().zip(&spec.largest) {
        if varied.integer && v.is_finite() {
            set(&mut table, &varied.keys, number(v.round(), true));
        }
    }
    // The largest case may be invalid (every such row then fails at once): fall back on the
    // spec's own case, which `Template::new` checked.
    let largest = toml::to_string(&table)
        .ok()
        .and_then(|t| case::parse(&t, dir).ok())
        .or_else(|| {
            toml::to_string(&spec.case)
                .ok()
                .and_then(|t| case::parse(&t, dir).ok())
        });
    if spec.analysis == Analysis::Wear {
        return limits::REREAD_ROW_SECONDS + largest.as_ref().and_then(wear_seconds).unwrap_or(0.0);
    }
    let march = largest
        .and_then(|c| {
            let history = c.history().ok()?;
            let increments = history.loads().len();
            let mut seconds = limits::march_seconds_with(&c.solver, increments);
            if spec.analysis == Analysis::Crack {
                let lengths = c.crack().ok()?.lengths().len();
                let per_cycle = history.cycles()?.steps_per_cycle();
                seconds += limits::crack_seconds(lengths, per_cycle);
            }
            Some(seconds)
        })
        .unwrap_or(0.0);
    limits::REREAD_ROW_SECONDS + march
}

/// The cycles a wear run marches per unit of `1 / max_depth_increment`, at most: 100, so 10 000
/// at the default bound 0.01. Measured: 78 cycles marched for the partial-slip example (1e6
/// cycles, 400 cells), 2886 for the 1e6-cycle gross-sliding one at the bound 0.02 (58 per unit),
/// 6587 for the 800-cell sliding comparison of docs/wear.md (BENCHMARKS.md, "Wear").
pub const WEAR_MARCHED_CYCLES_PER_UNIT: f64 = 100.0;

/// How many times the march model's cost a gross-sliding cycle takes: 10 (measured 15 ms a cycle
/// at 400 cells, 10 increments per half, against the model's 1.6 ms: Q reverses through a
/// Mindlin reversal in which the slip zones sweep the whole contact).
pub const SLIDING_COST_FACTOR: f64 = 10.0;

/// The cycles a wear run with `options` is assumed to march: every cycle, or
/// [`WEAR_MARCHED_CYCLES_PER_UNIT`] / `max_depth_increment` plus one per checkpoint (jumps end on
/// each), whichever is fewer. A bound, not a prediction: a settled partial-slip contact marches
/// a hundred times fewer.
pub fn wear_marched_cycles(options: &halfplane::wear::WearOptions) -> f64 {
    let bound = WEAR_MARCHED_CYCLES_PER_UNIT / options.max_depth_increment()
        + options.checkpoints().len() as f64;
    (options.cycles() as f64).min(bound)
}

/// The core time of one wear row: the ramp, then [`wear_marched_cycles`] cycles, each at the
/// march model's cost of its increments (times [`SLIDING_COST_FACTOR`] in gross sliding).
fn wear_seconds(c: &Case) -> Option<f64> {
    let settings = c.wear().ok()?;
    let (ramp, per_cycle, factor) = match &c.sliding {
        // Q rises and falls over 2 x steps_per_half increments each way, with a slide at each end.
        Some(s) => (s.ramp_steps, 4 * s.steps_per_half + 2, SLIDING_COST_FACTOR),
        None => {
            let cycles = c.history().ok()?.cycles()?;
            (cycles.first_step(), cycles.steps_per_cycle(), 1.0)
        }
    };
    let cycle = limits::march_seconds_with(&c.solver, per_cycle) * factor;
    Some(
        limits::march_seconds_with(&c.solver, ramp)
            + wear_marched_cycles(&settings.options) * cycle,
    )
}

/// Where a sweep's rows go, and how its rows are solved.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Run {
    /// Rows of this run (the shard's).
    pub rows: u64,
    /// Whether `--shard` picked them.
    pub shard: bool,
    /// The output format.
    pub format: OutputFormat,
    /// Whether the rows take the template's direct route.
    pub direct: bool,
}

/// Refuses a sweep whose output or core time is estimated above the limits; `dir` is the spec's
/// directory (for the case's CSV tables).
pub fn check(spec: &Spec, dir: &Path, run: Run) -> Result<(), TooLarge> {
    let Run {
        rows,
        shard,
        format,
        direct,
    } = run;
    let field = rows_field(spec, rows, shard);
    let kind = match format {
        OutputFormat::Csv => format!("{CSV_NUMBER_BYTES} bytes per CSV number"),
        OutputFormat::Parquet => format!("{PARQUET_NUMBER_BYTES} bytes per Parquet number"),
    };
    limits::check(
        field.clone(),
        Quantity::Output,
        output_bytes(spec, rows, format),
        format!("{} rows at {kind}", limits::sci(rows as f64)),
    )?;
    let per_row = row_seconds(spec, dir, direct);
    let basis = match spec.analysis {
        Analysis::Steady => format!("{} rows at {} s each", limits::sci(rows as f64), per_row),
        Analysis::March | Analysis::Crack => format!(
            "{} rows at {} each, the march of the largest case at {} s per cell² x increment",
            limits::sci(rows as f64),
            limits::duration(per_row),
            limits::MARCH_SECONDS_PER_UNIT
        ),
        Analysis::Wear => format!(
            "{} rows at {} each: the largest case's ramp and at most {} / max_depth_increment cycles \
             marched (all of [wear] cycles when fewer), at {:e} s per cell² x increment",
            limits::sci(rows as f64),
            limits::duration(per_row),
            WEAR_MARCHED_CYCLES_PER_UNIT,
            limits::MARCH_SECONDS_PER_UNIT
        ),
    };
    limits::check(field, Quantity::CoreTime, rows as f64 * per_row, basis)
}
