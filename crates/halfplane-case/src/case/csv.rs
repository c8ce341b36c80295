//! The CSV tables a case refers to or holds (profile tables, history rows) and `stress --at`
//! points.

use anyhow::{anyhow, bail, Context, Result};
use std::fmt;
use std::io::BufRead;
use std::path::PathBuf;

/// A CSV table: a file, or text given in the case itself (`data = """..."""`).
#[derive(Debug, Clone)]
pub enum Table<'a> {
    /// A file, named in errors by the field or option that gave it (`profile.file`, `--at`).
    File {
        /// The field or option that gave the path.
        field: String,
        /// The file.
        path: PathBuf,
    },
    /// The table's text, given as `{section}.data`; its lines count from the header's.
    Data {
        /// The case-file section holding it (`profile`, `history`).
        section: &'a str,
        /// The CSV text.
        text: &'a str,
    },
}

/// The table as errors name it: `profile.file path/to.csv` or `profile.data`.
impl fmt::Display for Table<'_> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Table::File { field, path } => write!(f, "{field} {}", path.display()),
            Table::Data { section, .. } => write!(f, "{section}.data"),
        }
    }
}

/// Reads a CSV whose header names `columns`, at most `max_rows` data rows; blank lines and lines starting with `#` are skipped, a UTF-8
/// byte-order mark and CRLF line ends (a spreadsheet's "CSV UTF-8") are accepted. Returns the
/// values row after row (`columns.len()` per row) and the line of each row (1-based, for
/// errors, which name the table, the line, the column and the value). Read a line at a time: a
/// file with too many rows is rejected without holding it.
pub fn read_csv(
    table: &Table,
    columns: &[&str],
    max_rows: usize,
) -> Result<(Vec<f64>, Vec<usize>)> {
    match table {
        Table::File { path, .. } => {
            let file = std::fs::File::open(path).with_context(|| format!("cannot read {table}"))?;
            read_lines(std::io::BufReader::new(file), table, columns, max_rows)
        }
        Table::Data { text, .. } => read_lines(text.as_bytes(), table, columns, max_rows),
    }
}

fn read_lines(
    mut reader: impl BufRead,
    table: &Table,
    columns: &[&str],
    max_rows: usize,
) -> Result<(Vec<f64>, Vec<usize>)> {
    let header_text = columns.join(",");
    let (mut values, mut numbers) = (Vec::new(), Vec::new());
    let mut header_seen = false;
    let mut line = String::new();
    for number in 1.. {
        line.clear();
        let read = reader
            .read_line(&mut line)
            .with_context(|| format!("cannot read {table}, line {number}"))?;
        if read == 0 {
            break;
        }
        let text = if number == 1 {
            line.strip_prefix('\u{feff}').unwrap_or(&line)
        } else {
            &line
        };
        // trim() also removes the '\r' of a CRLF line end.
        let text = text.trim();
        if text.is_empty() || text.starts_with('#') {
            continue;
        }
        if !header_seen {
            let names: Vec<String> = text
                .split(',')
                .map(|s| s.trim().to_ascii_lowercase())
                .collect();
            if names != columns {
                bail!("{table}, line {number}: header is \"{text}\", expected \"{header_text}\"");
            }
            header_seen = true;
            continue;
        }
        if numbers.len() == max_rows {
            bail!(
                "{table}, line {number}: the table has more than {max_rows} rows, the most a run takes"
            );
        }
        let mut found = 0;
        for cell in text.split(',').map(str::trim) {
            found += 1;
            let Some(name) = columns.get(found - 1) else {
                continue;
            };
            let value = cell.parse::<f64>().map_err(|_| {
                anyhow!("{table}, line {number}: {name} = \"{cell}\" is not a number")
            })?;
            values.push(value);
        }
        if found != columns.len() {
            bail!(
                "{table}, line {number}: expected {} columns ({header_text}), found {found}",
                columns.len()
            );
        }
        numbers.push(number);
    }
    if !header_seen {
        bail!("{table} is empty: it needs a header {header_text} and rows");
    }
    if numbers.is_empty() {
        bail!("{table} has a header but no rows");
    }
    Ok((values, numbers))
}
