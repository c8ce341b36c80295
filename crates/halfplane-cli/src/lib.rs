//! The library half of the `halfplane` command, in layers: raw arguments ([`args`], parsed by
//! clap) are resolved into a validated configuration per command, which its module in
//! [`commands`] runs; [`report`] formats the results (one module and one row type per report),
//! [`case`] reads case files and [`units`] their unit names. The binary (`main.rs`) only parses,
//! dispatches and maps errors to the exit code; keeping the rest in a library lets the fuzz
//! targets and tests drive the case-file parser and the reports directly.

pub mod args;
pub mod case;
pub mod commands;
pub mod limits;
pub mod output;
pub mod progress;
pub mod report;
pub mod sweep;
pub mod units;
