//! The two tables a case can hold, a tabulated profile (`x,g`) and a history's rows
//! (`normal,shear,bulk`), each given as a CSV file (`file = "..."`, relative to the case file) or
//! as the CSV text itself (`data = """..."""`): the same columns and the same reader, so both
//! forms give the same numbers. Errors name the table as the case gives it and its line.

use super::csv::{read_csv, read_csv_with, Table};
use anyhow::{anyhow, bail, Result};
use halfplane::history::History;
use halfplane::written::Written;
use halfplane::Profile;
use std::path::Path;

/// The table of `section` from its `file` or `data` field (at most one of them), or None when
/// it has neither. `dir` is where a relative path starts.
pub(super) fn source<'a>(
    section: &'a str,
    file: Option<&str>,
    data: Option<&'a str>,
    dir: &Path,
) -> Result<Option<Table<'a>>> {
    match (file, data) {
        (Some(_), Some(_)) => bail!(
            "{section}.file and {section}.data are both given: give one, the CSV file's path or \
             its text"
        ),
        (Some(file), None) => Ok(Some(Table::File {
            field: format!("{section}.file"),
            path: dir.join(file),
        })),
        (None, Some(text)) => Ok(Some(Table::Data { section, text })),
        (None, None) => Ok(None),
    }
}

/// A history from its table of rows `normal,shear,bulk` or `normal,shear,bulk,moment` (one
/// increment each; the moment is 0 without its column).
pub(super) fn history_rows(table: &Table) -> Result<History> {
    let (chosen, values, lines) = read_csv_with(
        table,
        &[
            &["normal", "shear", "bulk"],
            &["normal", "shear", "bulk", "moment"],
        ],
        halfplane::history::MAX_INCREMENTS,
    )?;
    let rows: Vec<[f64; 4]> = if chosen == 0 {
        values
            .chunks_exact(3)
            .map(|r| [r[0], r[1], r[2], 0.0])
            .collect()
    } else {
        values
            .chunks_exact(4)
            .map(|r| [r[0], r[1], r[2], r[3]])
            .collect()
    };
    History::from_moment_rows(&rows).map_err(|e| match e {
        halfplane::Error::InvalidRow {
            row,
            column,
            value,
            valid,
            ..
        } => {
            let line = lines.get(row.wrapping_sub(1)).copied().unwrap_or(0);
            anyhow!(
                "{table}, line {line}: {column} = {}: must be {valid}",
                Written(value)
            )
        }
        other => anyhow!("{table}: {other}"),
    })
}

/// A tabulated profile from its table `x,g` (x >= 0 mirrored, or two-sided) and its kinks.
pub(super) fn profile_table(table: &Table, kinks: Vec<f64>) -> Result<Profile> {
    let (values, lines) = read_csv(table, &["x", "g"], halfplane::profile::MAX_TABLE_ROWS)?;
    let (x, g) = values.chunks_exact(2).map(|r| (r[0], r[1])).unzip();
    Profile::tabulated(x, g, kinks).map_err(|e| match e {
        halfplane::Error::InvalidTable { row, problem } if row >= 1 && row <= lines.len() => {
            anyhow!("{table}, line {}: {problem}", lines[row - 1])
        }
        other => anyhow!("{table}: {other}"),
    })
}
