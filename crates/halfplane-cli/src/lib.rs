//! The library half of the `halfplane` command: case-file resolution and report formatting.
//! The binary (`main.rs`) only parses arguments and calls these; keeping them in a library lets
//! the fuzz targets and tests drive the case-file parser and CSV readers directly.

pub mod case;
pub mod report;
