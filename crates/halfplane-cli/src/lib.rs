//! The library half of the `halfplane` command, in layers: raw arguments ([`args`], parsed by
//! clap) are resolved into a validated configuration per command, which its module in
//! [`commands`] runs. Case files, units, size limits and report rows are the `halfplane-case`
//! crate, shared with the Python package and re-exported here under the names the commands use.
//! The binary (`main.rs`) only parses, dispatches and maps errors to the exit code; keeping the
//! rest in a library lets the fuzz targets and tests drive the sweep directly.

pub mod args;
pub mod commands;
pub mod output;
pub mod progress;
pub mod sweep;

pub use halfplane_case::{case, limits, report, units};
