//! `halfplane sweep`: one analysis per row of a design over any numeric fields of a case.
//!
//! A spec is a case file plus a `[sweep]` section ([`spec`]). Its case is resolved once
//! ([`template`]); each row puts its numbers in and runs the steady analysis (or a march). Rows
//! are solved on every core by the library's batch engine and handed over in order, chunk by
//! chunk, to a writer ([`csv`], or Parquet with the `parquet` feature, on by default), so output of any length
//! is streamed. Column names are a public interface: the varied paths as written, then
//! [`STEADY_COLUMNS`], then (march sweeps) [`MARCH_COLUMNS`], (crack sweeps) [`CRACK_COLUMNS`]
//! or (wear sweeps) [`WEAR_COLUMNS`].

pub mod csv;
#[cfg(feature = "parquet")]
pub mod parquet;
pub mod part;
pub mod read;
pub mod size;
pub mod spec;
pub mod template;

use anyhow::Result;
use halfplane::batch::{MARCH_COLUMNS, STEADY_COLUMNS};
use spec::{Analysis, Varied};
use template::Outcome;

/// The shape of a sweep's rows: the varied paths and the analysis.
#[derive(Debug, Clone, PartialEq)]
pub struct Layout {
    /// The varied fields, in the spec's order.
    pub varied: Vec<Varied>,
    /// What each row ran.
    pub analysis: Analysis,
}

impl Layout {
    /// Every column name, in order.
    pub fn columns(&self) -> Vec<String> {
        let mut out: Vec<String> = self.varied.iter().map(|v| v.path.clone()).collect();
        out.extend(STEADY_COLUMNS.iter().map(|c| c.to_string()));
        match self.analysis {
            Analysis::March => out.extend(MARCH_COLUMNS.iter().map(|c| c.to_string())),
            Analysis::Crack => out.extend(CRACK_COLUMNS.iter().map(|c| c.to_string())),
            Analysis::Wear => out.extend(WEAR_COLUMNS.iter().map(|c| c.to_string())),
            Analysis::Steady => {}
        }
        out
    }
}

/// The columns a crack sweep adds: the verdict (`arrests`, `propagates`, `no-growth`) and the
/// arrest length (empty unless the crack arrests), as `halfplane crack --json` names them.
pub const CRACK_COLUMNS: [&str; 2] = ["crack.verdict", "crack.arrest_length"];

/// The columns a wear sweep adds: the last checkpoint's quantities (the cycle `[wear] cycles`)
/// as `halfplane wear --json` names them (the stick ends empty in gross sliding), and the cycles
/// marched.
pub const WEAR_COLUMNS: [&str; 12] = [
    "wear.wear_volume",
    "wear.max_depth",
    "wear.energy_per_cycle",
    "wear.dissipated_energy",
    "wear.contact_left",
    "wear.contact_right",
    "wear.peak_pressure",
    "wear.stick_left",
    "wear.stick_right",
    "wear.slip_amplitude_max",
    "wear.displacement_amplitude",
    "wear.simulated_cycles",
];

/// Where a sweep's rows go: each row is encoded on a worker thread ([`RowSink::encode`]), and
/// the encoded rows of a chunk are written in row order ([`RowSink::write`]).
pub trait RowSink {
    /// A row ready to write.
    type Item: Send;
    /// Encodes one row (called on the worker threads, so it must not depend on the sink's state).
    fn encode(layout: &Layout, values: &[f64], outcome: Outcome) -> Self::Item;
    /// Writes a chunk of rows, in order.
    fn write(&mut self, rows: Vec<Self::Item>) -> Result<()>;
    /// Completes the output (flushes, closes, and moves it to its final name).
    fn finish(self) -> Result<()>;
}
