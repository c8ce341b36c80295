//! The case-and-report layer between the `halfplane` library and its front ends (the command and
//! the Python package): [`case`] reads case files (TOML) and their CSV tables into validated
//! library values, [`units`] names their units, [`report`] turns results into rows with public
//! column names (table, CSV, JSON), [`limits`] refuses runs too large to finish, and [`stress`] and
//! [`matching`] hold the computations both front ends run. Nothing here parses a command line,
//! draws or prints: the front ends do, so that both give the same numbers and messages by
//! construction.

pub mod case;
pub mod limits;
pub mod matching;
pub mod report;
pub mod stress;
pub mod units;
