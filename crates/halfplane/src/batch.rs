//! Many independent analyses at once: the engine behind Python's `steady_batch` and the CLI's
//! `sweep`.
//!
//! Cases are solved on a rayon pool in chunks. With [`Batch::run`] each chunk's results are handed
//! to a sink, in row order, before the next chunk starts, so an output of any length is streamed
//! with at most one chunk in memory; with [`Batch::fill`] rows are solved straight into
//! preallocated output columns, each worker writing its own block of rows (nothing is copied on
//! the calling thread). Either way a caller's check between chunks (an interrupt, a full disk)
//! may stop the run. A case that fails is a row carrying its error, never an abort of the batch. Results do
//! not depend on the number of threads: every row is solved by the same sequential code.
//!
//! The library never reads the environment: a batch runs on the thread count its caller gives
//! ([`Batch::new`]) or on the caller's own rayon pool ([`Batch::in_pool`]). Front ends that let
//! users size the pool with [`THREADS_VARIABLE`] read it themselves and parse it with
//! [`threads_from_text`], so every front end refuses a bad value with the same error.

use crate::error::{Error, Result};
use crate::history::{History, Steady};
use crate::labels::{PerEdge, PerPoint};
use crate::march::{self, MarchOptions, MarchResult};
use crate::steady::{self, Regime, SteadyOptions, SteadyState};
use crate::{Contact, Cycle};
use rayon::prelude::*;
use std::ops::ControlFlow;
use std::sync::Arc;

mod fill;
pub mod row;
pub use fill::RowBlock;
pub use row::{ProfileKind, SteadyRow, STEADY_INPUT_COLUMNS};

/// The environment variable the front ends (the CLI's `sweep`, Python's `steady_batch`) read for
/// the thread count when none is given; parse its value with [`threads_from_text`].
pub const THREADS_VARIABLE: &str = "HALFPLANE_NUM_THREADS";

/// Rows solved between two calls of the sink when [`Batch::with_chunk_rows`] is not used: large
/// enough that scheduling costs nothing measurable, small enough that an interrupt is seen within
/// a fraction of a second and memory stays a few megabytes.
pub const DEFAULT_CHUNK_ROWS: usize = 16_384;

/// Largest thread count accepted (far above any machine; it bounds the pool's allocation).
pub const MAX_THREADS: usize = 4096;

/// How a batch is run: who solves the rows, and the chunk length.
#[derive(Debug, Clone)]
pub struct Batch {
    workers: Workers,
    chunk_rows: usize,
}

/// Who solves a batch's rows.
#[derive(Debug, Clone)]
enum Workers {
    /// A pool of this many threads started for each run (`None`: one per core).
    Threads(Option<usize>),
    /// The caller's pool.
    Pool(Arc<rayon::ThreadPool>),
}

impl Batch {
    /// A batch on `threads` workers, or on every core for `None` (one thread solves the rows on
    /// the calling thread, starting none).
    ///
    /// # Errors
    /// [`Error::InvalidCount`] for a thread count outside 1..=[`MAX_THREADS`].
    pub fn new(threads: Option<usize>) -> Result<Self> {
        let threads = match threads {
            Some(n) => Some(check_threads("threads", n as u64)?),
            None => None,
        };
        Ok(Self {
            workers: Workers::Threads(threads),
            chunk_rows: DEFAULT_CHUNK_ROWS,
        })
    }

    /// A batch on the caller's rayon pool, shared with whatever else the caller runs there (no
    /// pool is started per run).
    pub fn in_pool(pool: Arc<rayon::ThreadPool>) -> Self {
        Self {
            workers: Workers::Pool(pool),
            chunk_rows: DEFAULT_CHUNK_ROWS,
        }
    }

    /// The same batch with `rows` rows per chunk (1 to 2^24).
    ///
    /// # Errors
    /// [`Error::InvalidCount`] outside that range.
    pub fn with_chunk_rows(self, rows: usize) -> Result<Self> {
        const MAX_CHUNK: u64 = 1 << 24;
        if rows == 0 || rows as u64 > MAX_CHUNK {
            return Err(Error::InvalidCount {
                field: "chunk_rows".into(),
                value: rows as u64,
                min: 1,
                max: MAX_CHUNK,
            });
        }
        Ok(Self {
            chunk_rows: rows,
            ..self
        })
    }

    /// The thread count asked for (`None`: every core), or the caller's pool's.
    pub fn threads(&self) -> Option<usize> {
        match &self.workers {
            Workers::Threads(n) => *n,
            Workers::Pool(pool) => Some(pool.current_num_threads()),
        }
    }

    /// Rows per chunk.
    pub fn chunk_rows(&self) -> usize {
        self.chunk_rows
    }

    /// Solves rows `0..rows` with `solve(row)` and hands each chunk's results, in row order, to
    /// `sink(first_row, results)`. The sink may return [`ControlFlow::Break`] to stop; the run then
    /// returns the break value without solving further chunks.
    ///
    /// # Errors
    /// [`Error::ThreadPool`] if the pool cannot be started.
    pub fn run<O, B>(
        &self,
        rows: usize,
        solve: impl Fn(usize) -> O + Sync,
        mut sink: impl FnMut(usize, Vec<O>) -> ControlFlow<B>,
    ) -> Result<Option<B>>
    where
        O: Send,
    {
        self.with_pool(|pool| {
            let mut first = 0;
            while first < rows {
                let end = rows.min(first.saturating_add(self.chunk_rows));
                let results: Vec<O> = match pool {
                    Some(pool) => {
                        pool.install(|| (first..end).into_par_iter().map(&solve).collect())
                    }
                    None => (first..end).map(&solve).collect(),
                };
                if let ControlFlow::Break(value) = sink(first, results) {
                    return Some(value);
                }
                first = end;
            }
            None
        })
    }
}

impl Batch {
    /// Runs `work` with the batch's pool: the caller's, a new one of the batch's size, or `None`
    /// for one thread: the rows are then solved on the calling thread, which saves starting a
    /// thread per call (milliseconds on a loaded machine, paid per task by a Dask worker with one
    /// thread).
    fn with_pool<T>(&self, work: impl FnOnce(Option<&rayon::ThreadPool>) -> T) -> Result<T> {
        let threads = match &self.workers {
            Workers::Pool(pool) => return Ok(work(Some(pool))),
            Workers::Threads(Some(1)) => return Ok(work(None)),
            Workers::Threads(Some(n)) => *n,
            Workers::Threads(None) => std::thread::available_parallelism().map_or(1, |n| n.get()),
        };
        let pool = rayon::ThreadPoolBuilder::new()
            .num_threads(threads)
            .build()
            .map_err(|e| Error::ThreadPool {
                message: e.to_string(),
            })?;
        Ok(work(Some(&pool)))
    }
}

fn check_threads(field: &str, n: u64) -> Result<usize> {
    if n == 0 || n > MAX_THREADS as u64 {
        return Err(Error::InvalidCount {
            field: field.into(),
            value: n,
            min: 1,
            max: MAX_THREADS as u64,
        });
    }
    Ok(n as usize)
}

/// A thread count as [`THREADS_VARIABLE`] holds it: blank means not given (`None`, every core).
/// Front ends pass the variable's value here (an unset variable is blank).
///
/// # Errors
/// [`Error::InvalidText`] for text that is not a whole number, [`Error::InvalidCount`] for a
/// count outside 1..=[`MAX_THREADS`]; both name [`THREADS_VARIABLE`].
pub fn threads_from_text(text: &str) -> Result<Option<usize>> {
    let text = text.trim();
    if text.is_empty() {
        return Ok(None);
    }
    match text.parse::<u64>() {
        Ok(n) => check_threads(THREADS_VARIABLE, n).map(Some),
        Err(_) => Err(Error::InvalidText {
            field: THREADS_VARIABLE.into(),
            value: text.into(),
            valid: "a whole number of threads from 1 to 4096",
        }),
    }
}

/// The columns of a steady summary row, in output order (a public interface: scripts depend on
/// these names). `error` is last: empty when the analysis succeeded.
pub const STEADY_COLUMNS: [&str; 10] = [
    "regime",
    "stick_left",
    "stick_right",
    "half_width_1",
    "half_width_2",
    "slip_left_1",
    "slip_left_2",
    "slip_right_1",
    "slip_right_2",
    "error",
];

/// How many numbers a steady summary has: [`STEADY_COLUMNS`] without `regime` and `error`.
pub const STEADY_NUMBERS: usize = STEADY_COLUMNS.len() - 2;

/// One case's steady state in the few numbers a design map needs. Points are as given (1, 2);
/// lengths in the case's length unit.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SteadySummary {
    regime: Regime,
    half_width: PerPoint<f64>,
    stick_zone: Option<(f64, f64)>,
    slip_zones: Option<PerEdge<PerPoint<f64>>>,
}

impl SteadySummary {
    /// The summary of an analysed state.
    pub fn of(state: &SteadyState) -> Self {
        Self {
            regime: state.regime,
            half_width: state.half_width,
            stick_zone: state.stick_zone.map(|z| (z.left, z.right)),
            slip_zones: state.slip_zones,
        }
    }

    /// The regime.
    pub fn regime(&self) -> Regime {
        self.regime
    }

    /// The [`STEADY_NUMBERS`] numbers of [`STEADY_COLUMNS`] after `regime` and before `error`: stick zone ends
    /// (NaN in gross sliding), half-widths at points 1 and 2, slip zones left 1, 2, right 1, 2
    /// (NaN in gross sliding, 0 in full stick).
    pub fn numbers(&self) -> [f64; STEADY_NUMBERS] {
        let (left, right) = self.stick_zone.unwrap_or((f64::NAN, f64::NAN));
        let nan = PerPoint {
            first: f64::NAN,
            second: f64::NAN,
        };
        let slip = self.slip_zones.unwrap_or(PerEdge {
            left: nan,
            right: nan,
        });
        [
            left,
            right,
            self.half_width.first,
            self.half_width.second,
            slip.left.first,
            slip.left.second,
            slip.right.first,
            slip.right.second,
        ]
    }
}

/// The steady analysis of one case, summarised ([`steady::analyse`] then [`SteadySummary::of`]).
///
/// # Errors
/// Every error of [`steady::analyse`].
pub fn steady_summary(
    contact: &Contact,
    cycle: &Cycle,
    options: &SteadyOptions,
) -> Result<SteadySummary> {
    steady::analyse(contact, cycle, options).map(|state| SteadySummary::of(&state))
}

/// The columns a march adds to a summary row, in output order (a public interface). The names are
/// those of the `march` command's cycle table and JSON (`energy`, `max_slip_amplitude`,
/// `shakedown_cycle`); the final stick interval is `final_stick_left`/`final_stick_right`, since
/// `stick_left`/`stick_right` already name the steady state's zone in [`STEADY_COLUMNS`];
/// `cycles_run`, `steady_change` and `steady_converged` are the `march` JSON's.
pub const MARCH_COLUMNS: [&str; 8] = [
    "energy",
    "max_slip_amplitude",
    "shakedown_cycle",
    "final_stick_left",
    "final_stick_right",
    "cycles_run",
    "steady_change",
    "steady_converged",
];

/// One marched history in the few numbers a design map needs.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct MarchSummary {
    energy: Option<f64>,
    max_slip_amplitude: Option<f64>,
    shakedown_cycle: Option<usize>,
    final_stick: Option<[f64; 2]>,
    cycles_run: usize,
    steady_change: Option<f64>,
    steady_converged: Option<bool>,
}

impl MarchSummary {
    /// The summary of a marched history: the last cycle's energy and largest slip amplitude (the
    /// steady cycle's, once shaken down; `None` for a history without cycles), the shakedown
    /// cycle, the largest stick interval at the last increment (`None` when nothing sticks),
    /// the cycles run and the change of the slip ranges in the last, judged by `steady`'s
    /// tolerance.
    pub fn of(result: &MarchResult, steady: &Steady) -> Self {
        let last = result.cycles.last();
        Self {
            energy: last.map(|c| c.energy),
            max_slip_amplitude: last.map(|c| c.max_slip_amplitude()),
            shakedown_cycle: result.shakedown_cycle,
            final_stick: result.steps.last().and_then(|s| s.largest_stick()),
            cycles_run: result.cycles.len(),
            steady_change: result.steady_change,
            steady_converged: result.steady_change.map(|c| steady.is_met(c)),
        }
    }

    /// Cycles marched.
    pub fn cycles_run(&self) -> usize {
        self.cycles_run
    }

    /// The largest change of a cell's slip range between the last two cycles, a fraction of
    /// `A f P_max` (`None` with fewer than two cycles).
    pub fn steady_change(&self) -> Option<f64> {
        self.steady_change
    }

    /// Whether that change is within the steady tolerance (`None` with fewer than two cycles).
    pub fn steady_converged(&self) -> Option<bool> {
        self.steady_converged
    }

    /// Energy dissipated in the last cycle (per unit thickness).
    pub fn energy(&self) -> Option<f64> {
        self.energy
    }

    /// Largest slip amplitude along x in the last cycle (half the peak-to-peak slip).
    pub fn max_slip_amplitude(&self) -> Option<f64> {
        self.max_slip_amplitude
    }

    /// The first cycle that the next one repeats, if any.
    pub fn shakedown_cycle(&self) -> Option<usize> {
        self.shakedown_cycle
    }

    /// The largest stick interval `[left, right]` at the last increment.
    pub fn final_stick(&self) -> Option<[f64; 2]> {
        self.final_stick
    }
}

/// A march through `history`, summarised ([`march::march`], or [`march::march_steady`] when
/// `until_steady`, then [`MarchSummary::of`] with `steady`'s tolerance).
///
/// # Errors
/// Every error of [`march::march`] or [`march::march_steady`].
pub fn march_summary(
    contact: &Contact,
    history: &History,
    options: &MarchOptions,
    steady: &Steady,
    until_steady: bool,
) -> Result<MarchSummary> {
    let result = match until_steady {
        true => march::march_steady(contact, history, steady, options, |_, _| {}),
        false => march::march(contact, history, options, |_, _| {}),
    }?;
    Ok(MarchSummary::of(&result, steady))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::reference;

    #[test]
    fn rows_come_back_in_order_whatever_the_threads_and_chunks() {
        let expected: Vec<u64> = (0..1000u64).map(|i| i * i).collect();
        for (threads, chunk) in [(1, 7), (2, 1000), (3, 64), (8, 1)] {
            let batch = Batch::new(Some(threads))
                .and_then(|b| b.with_chunk_rows(chunk))
                .expect("valid batch");
            let mut got = Vec::new();
            let stopped = batch
                .run(
                    1000,
                    |i| (i as u64) * (i as u64),
                    |first, part| {
                        assert_eq!(first, got.len(), "chunks arrive in row order");
                        got.extend(part);
                        ControlFlow::<()>::Continue(())
                    },
                )
                .expect("pool starts");
            assert_eq!(stopped, None);
            assert_eq!(got, expected, "{threads} threads, chunks of {chunk}");
        }
    }

    #[test]
    fn the_sink_stops_the_run_between_chunks() {
        let batch = Batch::new(Some(2))
            .and_then(|b| b.with_chunk_rows(10))
            .expect("valid");
        let mut seen = 0;
        let stopped = batch
            .run(
                100,
                |i| i,
                |_, part| {
                    seen += part.len();
                    if seen >= 30 {
                        ControlFlow::Break(seen)
                    } else {
                        ControlFlow::Continue(())
                    }
                },
            )
            .expect("pool starts");
        assert_eq!(stopped, Some(30), "three chunks solved, then stopped");
    }

    #[test]
    fn bad_thread_counts_name_the_field() {
        for n in [0, MAX_THREADS + 1] {
            match Batch::new(Some(n)) {
                Err(Error::InvalidCount { field, value, .. }) => {
                    assert_eq!((field.as_str(), value), ("threads", n as u64))
                }
                other => panic!("threads = {n} accepted: {other:?}"),
            }
        }
        assert!(matches!(
            threads_from_text("many"),
            Err(Error::InvalidText { field, .. }) if field == THREADS_VARIABLE
        ));
        assert!(matches!(
            threads_from_text("0"),
            Err(Error::InvalidCount { .. })
        ));
        assert_eq!(threads_from_text(" 3 ").ok(), Some(Some(3)));
        assert_eq!(threads_from_text("").ok(), Some(None));
        assert!(Batch::new(Some(1))
            .and_then(|b| b.with_chunk_rows(0))
            .is_err());
    }

    #[test]
    fn a_march_summary_carries_the_last_cycle_and_increment() {
        let (first, second) = reference::cycle().as_given();
        let history = crate::history::History::in_phase(
            first,
            second,
            2,
            20,
            crate::history::Ramp::NormalFirst,
            10,
        )
        .expect("valid history");
        let options = MarchOptions::default()
            .with_cells(100)
            .expect("valid cells");
        let contact = reference::hertz();
        let result = march::march(&contact, &history, &options, |_, _| {}).expect("marches");
        let steady = Steady::default();
        let summary = march_summary(&contact, &history, &options, &steady, false).expect("marches");
        let last = result.cycles.last().expect("a cyclic history");
        assert_eq!(summary.energy(), Some(last.energy));
        assert_eq!(
            summary.max_slip_amplitude(),
            Some(last.max_slip_amplitude())
        );
        assert_eq!(summary.shakedown_cycle(), result.shakedown_cycle);
        assert_eq!(summary.cycles_run(), 2);
        assert_eq!(summary.steady_change(), result.steady_change);
        assert_eq!(
            summary.steady_converged(),
            result.steady_change.map(|c| c <= steady.tolerance())
        );
        assert_eq!(
            summary.final_stick(),
            result.steps.last().and_then(|s| s.largest_stick())
        );
        assert!(
            summary.energy().is_some_and(|e| e > 0.0),
            "partial slip dissipates"
        );
    }

    #[test]
    fn a_summary_carries_the_steady_state_numbers() {
        let (contact, cycle) = (reference::hertz(), reference::cycle());
        let state = steady::analyse(&contact, &cycle, &SteadyOptions::default()).expect("solves");
        let summary = steady_summary(&contact, &cycle, &SteadyOptions::default()).expect("solves");
        let zone = state.stick_zone.expect("partial slip");
        let slip = state.slip_zones.expect("partial slip");
        assert_eq!(summary.regime(), Regime::PartialSlip);
        assert_eq!(
            summary.numbers(),
            [
                zone.left,
                zone.right,
                state.half_width.first,
                state.half_width.second,
                slip.left.first,
                slip.left.second,
                slip.right.first,
                slip.right.second,
            ]
        );
        assert_eq!(
            STEADY_COLUMNS.len(),
            summary.numbers().len() + 2,
            "regime and error"
        );
    }
}
