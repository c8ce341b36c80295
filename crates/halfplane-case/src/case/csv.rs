//! The CSV tables a case refers to (profile tables, history rows) and `stress --at` points.

use anyhow::{anyhow, bail, Context, Result};
use std::io::BufRead;
use std::path::Path;

/// Reads a CSV whose header names `columns`, at most `max_rows` data rows; blank lines and lines
/// starting with `#` are skipped, a UTF-8 byte-order mark and CRLF line ends (a spreadsheet's
/// "CSV UTF-8") are accepted. Returns the values row after row (`columns.len()` per row) and
/// the file line of each row (for errors); `field` names the field that gave the path. Read
/// a line at a time: a file with too many rows is rejected without holding it.
pub fn read_csv(
    path: &Path,
    field: &str,
    columns: &[&str],
    max_rows: usize,
) -> Result<(Vec<f64>, Vec<usize>)> {
    let file = std::fs::File::open(path)
        .with_context(|| format!("cannot read {field} {}", path.display()))?;
    let mut reader = std::io::BufReader::new(file);
    let header_text = columns.join(",");
    let (mut values, mut numbers) = (Vec::new(), Vec::new());
    let mut header_seen = false;
    let mut line = String::new();
    for number in 1.. {
        line.clear();
        let read = reader
            .read_line(&mut line)
            .with_context(|| format!("cannot read {field} {}, line {number}", path.display()))?;
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
                bail!(
                    "{field} {}, line {number}: header is \"{text}\", expected \"{header_text}\"",
                    path.display()
                );
            }
            header_seen = true;
            continue;
        }
        if numbers.len() == max_rows {
            bail!(
                "{field} {}, line {number}: the table has more than {max_rows} rows, the most a run takes",
                path.display()
            );
        }
        let mut found = 0;
        for cell in text.split(',').map(str::trim) {
            found += 1;
            let Some(name) = columns.get(found - 1) else {
                continue;
            };
            let value = cell.parse::<f64>().map_err(|_| {
                anyhow!(
                    "{field} {}, line {number}: {name} = \"{cell}\" is not a number",
                    path.display()
                )
            })?;
            values.push(value);
        }
        if found != columns.len() {
            bail!(
                "{field} {}, line {number}: expected {} columns ({header_text}), found {found}",
                path.display(),
                columns.len()
            );
        }
        numbers.push(number);
    }
    if !header_seen {
        bail!(
            "{field} {} is empty: it needs a header {header_text} and rows",
            path.display()
        );
    }
    if numbers.is_empty() {
        bail!("{field} {} has a header but no rows", path.display());
    }
    Ok((values, numbers))
}
