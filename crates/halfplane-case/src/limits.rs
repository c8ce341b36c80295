//! Size limits: the time, output and memory a run would take, estimated before it starts, so that
//! a run that cannot finish on an ordinary machine is refused at once (naming the field that makes
//! it large, the estimate and the limit) instead of running for days or filling the disk.
//! `--no-size-limit` (Python: `no_size_limit=True`) skips the checks.
//!
//! The estimates are models fitted to measurements (BENCHMARKS.md, "Size limits"), not promises:
//! - a march costs [`MARCH_SECONDS_PER_UNIT`] per cell² x increment: the contact edges cross more
//!   cells per increment the finer the grid, each crossing a sub-step with an O(N log N) stick
//!   solve, and measured times grow like cells^2.0-2.4 x increments (reference cycle, 1000 to
//!   16000 cells); the constant is the quiet machine's, so the estimate errs towards running;
//! - a sweep row costs [`DIRECT_ROW_SECONDS`] or [`REREAD_ROW_SECONDS`] by its route, plus its
//!   march;
//! - output sizes are in `sweep::size` (sweeps) and [`check_fields_files`] (`march --fields`).

use halfplane::history::{History, Steady};
use halfplane::march::MarchOptions;
use std::fmt;

/// Seconds of one core per cell² x increment of a march (measured on a quiet machine: 5.0e-10 at
/// 1000 cells, 5.3e-10 at 8000).
pub const MARCH_SECONDS_PER_UNIT: f64 = 5e-10;
/// Seconds of one core per row of a steady sweep whose rows are rebuilt from the resolved case
/// (the direct route; measured 5.4 µs a row, Hertz, on a loaded machine).
pub const DIRECT_ROW_SECONDS: f64 = 1e-5;
/// Seconds of one core per row of a sweep whose rows re-read their case (measured 250 µs a row,
/// Hertz, on a loaded machine); a march sweep adds the march.
pub const REREAD_ROW_SECONDS: f64 = 3e-4;
/// The most core time a run may be estimated to take: 8 hours.
pub const TIME_LIMIT_SECONDS: f64 = 8.0 * 3600.0;
/// The most a run may write to files: 100 GB.
pub const OUTPUT_LIMIT_BYTES: f64 = 1e11;
/// The most memory a run's recorded fields may take: 4 GB.
pub const MEMORY_LIMIT_BYTES: f64 = 4e9;

/// What an estimate measures.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Quantity {
    /// Time on one core, in seconds.
    CoreTime,
    /// Bytes written to files.
    Output,
    /// Bytes of memory.
    Memory,
}

impl Quantity {
    fn limit(self) -> f64 {
        match self {
            Quantity::CoreTime => TIME_LIMIT_SECONDS,
            Quantity::Output => OUTPUT_LIMIT_BYTES,
            Quantity::Memory => MEMORY_LIMIT_BYTES,
        }
    }

    fn show(self, value: f64) -> String {
        match self {
            Quantity::CoreTime => duration(value),
            Quantity::Output | Quantity::Memory => bytes(value),
        }
    }
}

/// A run refused before it started: the field that makes it large (as the user wrote it), the
/// quantity, its estimate and how it was made, and the limit.
#[derive(Debug, Clone, PartialEq)]
pub struct TooLarge {
    /// The field or option, with its value as written (`--cells 1000000`, `sweep.samples = ...`).
    pub field: String,
    /// What was estimated.
    pub quantity: Quantity,
    /// The estimate (seconds or bytes).
    pub estimate: f64,
    /// The limit, in the same unit.
    pub limit: f64,
    /// How the estimate was made (the counts it multiplies).
    pub basis: String,
}

impl fmt::Display for TooLarge {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let what = match self.quantity {
            Quantity::CoreTime => "would take about",
            Quantity::Output => "would write about",
            Quantity::Memory => "would need about",
        };
        let unit = match self.quantity {
            Quantity::CoreTime => " of one core",
            Quantity::Output => "",
            Quantity::Memory => " of memory",
        };
        write!(
            f,
            "{}: the run {what} {}{unit} ({}), above the limit of {}",
            self.field,
            self.quantity.show(self.estimate),
            self.basis,
            self.quantity.show(self.limit)
        )
    }
}

impl std::error::Error for TooLarge {}

/// Checks an estimate against its limit.
pub fn check(
    field: String,
    quantity: Quantity,
    estimate: f64,
    basis: String,
) -> Result<(), TooLarge> {
    let limit = quantity.limit();
    if estimate > limit {
        return Err(TooLarge {
            field,
            quantity,
            estimate,
            limit,
            basis,
        });
    }
    Ok(())
}

/// The work of a march in cell² x increments.
pub fn march_units(cells: usize, increments: usize) -> f64 {
    (cells as f64).powi(2) * increments as f64
}

/// Seconds of one core per crack length and increment of the steady cycle (`halfplane crack`:
/// measured 0.2 ms at f = 0 and 0.35 ms at f = 0.3, 40 points per component; BENCHMARKS.md).
pub const CRACK_SECONDS_PER_UNIT: f64 = 4e-4;

/// The core time a crack analysis over `lengths` lengths and `increments` increments per cycle is
/// estimated to take (the march aside).
pub fn crack_seconds(lengths: usize, increments: usize) -> f64 {
    CRACK_SECONDS_PER_UNIT * lengths as f64 * increments as f64
}

/// The core time a march is estimated to take.
pub fn march_seconds(cells: usize, increments: usize) -> f64 {
    march_units(cells, increments) * MARCH_SECONDS_PER_UNIT
}

/// How many times the cell-level march's cost a march with `sub_cell_boundaries` may take: 14,
/// the largest measured (the reference cycle at 400 cells, every increment with two boundaries
/// to locate; Cattaneo 2-4 times; BENCHMARKS.md, "Stick-slip boundaries inside their cells").
pub const SUB_CELL_COST_FACTOR: f64 = 14.0;

/// [`march_seconds`] for a march with `options`: times [`SUB_CELL_COST_FACTOR`] when its
/// stick-slip boundaries are located inside their cells.
pub fn march_seconds_with(options: &MarchOptions, increments: usize) -> f64 {
    let factor = if options.sub_cell() {
        SUB_CELL_COST_FACTOR
    } else {
        1.0
    };
    march_seconds(options.cells(), increments) * factor
}

/// The increments a march will solve at most: the history's, or for a march until the cycle
/// repeats (`history.cycles = "steady"`), its ramp and `max_cycles` cycles.
pub fn planned_increments(history: &History, until_steady: Option<&Steady>) -> usize {
    match (until_steady, history.cycles()) {
        (Some(steady), Some(c)) => c
            .first_step()
            .saturating_add(steady.max_cycles().saturating_mul(c.steps_per_cycle())),
        _ => history.loads().len(),
    }
}

/// Refuses a march estimated to take longer than [`TIME_LIMIT_SECONDS`]; `cells_field` names where
/// the cell count came from as the user wrote it (`--cells 1000000`, `cells=1000000`, or
/// `solver.cells = 400`).
pub fn check_march(
    increments: usize,
    options: &MarchOptions,
    cells_field: &str,
) -> Result<(), TooLarge> {
    let cells = options.cells();
    check(
        format!("{cells_field} with {increments} increments of [history]"),
        Quantity::CoreTime,
        march_seconds_with(options, increments),
        format!(
            "cells² x increments = {} at {MARCH_SECONDS_PER_UNIT:e} s each{}",
            sci(march_units(cells, increments)),
            if options.sub_cell() {
                format!(", x {SUB_CELL_COST_FACTOR} for solver.sub_cell_boundaries")
            } else {
                String::new()
            }
        ),
    )
}

/// [`check_march`] for a command that marches the case's whole history before it computes
/// (`stress`, `fatigue`, `crack`), unless `no_size_limit`; `cells` is `--cells` as given.
pub fn check_case_march(
    history: &History,
    options: &MarchOptions,
    cells: Option<usize>,
    no_size_limit: bool,
) -> Result<(), TooLarge> {
    if no_size_limit {
        return Ok(());
    }
    check_march(history.loads().len(), options, &cells_field(cells, options))
}

/// Where the command line's cell count came from, as the user wrote it: `--cells N` when given,
/// else the case's `solver.cells = N`.
pub fn cells_field(cells: Option<usize>, options: &MarchOptions) -> String {
    match cells {
        Some(n) => format!("--cells {n}"),
        None => format!("solver.cells = {}", options.cells()),
    }
}

/// Refuses recorded fields (four f64 per cell and increment) above [`MEMORY_LIMIT_BYTES`].
pub fn check_fields_memory(
    increments: usize,
    options: &MarchOptions,
    cells_field: &str,
) -> Result<(), TooLarge> {
    let cells = options.cells();
    check(
        format!("{cells_field} with fields recorded at {increments} increments"),
        Quantity::Memory,
        32.0 * cells as f64 * increments as f64,
        "4 fields x 8 bytes x cells x increments".into(),
    )
}

/// Bytes `march --fields` writes per cell and increment: a line of five numbers (measured 66 on
/// the reference cycle; rounded up).
pub const FIELD_LINE_BYTES: f64 = 80.0;

/// Refuses `--fields` files ([`FIELD_LINE_BYTES`] per cell and increment) above
/// [`OUTPUT_LIMIT_BYTES`].
pub fn check_fields_files(
    increments: usize,
    options: &MarchOptions,
    cells_field: &str,
) -> Result<(), TooLarge> {
    let cells = options.cells();
    check(
        format!("--fields with {cells_field} and {increments} increments"),
        Quantity::Output,
        FIELD_LINE_BYTES * cells as f64 * increments as f64,
        format!("{FIELD_LINE_BYTES} bytes x cells x increments"),
    )
}

/// A count in a form people read: whole below 1e6, else with an exponent.
pub fn sci(v: f64) -> String {
    if v < 1e6 {
        format!("{v:.0}")
    } else {
        format!("{v:.1e}")
    }
}

/// Seconds as seconds, minutes, hours, days or years: the largest unit that makes at least 2.
pub fn duration(s: f64) -> String {
    const UNITS: [(f64, &str); 4] = [
        (365.25 * 86400.0, "years"),
        (86400.0, "days"),
        (3600.0, "hours"),
        (60.0, "minutes"),
    ];
    for (size, name) in UNITS {
        if s >= 2.0 * size {
            let v = s / size;
            return if v >= 1e6 {
                format!("{} {name}", sci(v))
            } else {
                format!("{v:.1} {name}")
            };
        }
    }
    format!("{s:.1} s")
}

/// Bytes in decimal units (kB, MB, GB, TB, PB).
pub fn bytes(b: f64) -> String {
    const UNITS: [(f64, &str); 5] = [
        (1e15, "PB"),
        (1e12, "TB"),
        (1e9, "GB"),
        (1e6, "MB"),
        (1e3, "kB"),
    ];
    for (size, name) in UNITS {
        if b >= size {
            let v = b / size;
            return if v >= 1e6 {
                format!("{} {name}", sci(v))
            } else {
                format!("{v:.1} {name}")
            };
        }
    }
    format!("{b:.0} bytes")
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn sizes_read_as_people_write_them() {
        assert_eq!(duration(12.34), "12.3 s");
        assert_eq!(duration(5400.0), "90.0 minutes");
        assert_eq!(duration(1.5e5), "41.7 hours");
        assert_eq!(duration(3e5), "3.5 days");
        assert_eq!(bytes(1.5e14), "150.0 TB");
        assert_eq!(bytes(999.0), "999 bytes");
        assert_eq!(sci(3e14), "3.0e14");
    }

    #[test]
    fn a_limit_is_inclusive_and_the_error_names_everything() {
        let at = check("f".into(), Quantity::Output, OUTPUT_LIMIT_BYTES, "b".into());
        assert_eq!(at, Ok(()));
        let over = check(
            "sweep.samples = 7".into(),
            Quantity::Output,
            2e11,
            "basis".into(),
        )
        .expect_err("above the limit");
        let text = over.to_string();
        for part in ["sweep.samples = 7", "200.0 GB", "basis", "100.0 GB"] {
            assert!(text.contains(part), "{text}");
        }
    }

    #[test]
    fn located_boundaries_raise_the_march_estimate() {
        // 4000 cells and 400 000 increments: 3200 s of the cell-level march, under the 8 h
        // limit, and 14 times that, over it.
        let off = MarchOptions::default().with_cells(4000).unwrap();
        let on = off.with_sub_cell_boundaries(true).unwrap();
        let n = 400_000;
        assert_eq!(march_seconds_with(&off, n), march_seconds(4000, n));
        assert_eq!(
            march_seconds_with(&on, n),
            SUB_CELL_COST_FACTOR * march_seconds(4000, n)
        );
        assert!(check_march(n, &off, "solver.cells = 4000").is_ok());
        let e = check_march(n, &on, "solver.cells = 4000").expect_err("14 x 3200 s");
        assert!(e.to_string().contains("solver.sub_cell_boundaries"), "{e}");
    }
}
