//! The CSV tables a case refers to or holds (profile tables, history rows) and `stress --at`
//! points.

use anyhow::{anyhow, bail, Context, Result};
use std::borrow::Cow;
use std::collections::VecDeque;
use std::fmt;
use std::io::{self, Read};
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

/// Reads a CSV whose header names `columns`, at most `max_rows` data rows, with the `csv` crate;
/// blank lines and lines starting with `#` are skipped, a UTF-8
/// byte-order mark and CRLF line ends (a spreadsheet's "CSV UTF-8") are accepted. Returns the
/// values row after row (`columns.len()` per row) and the line of each row (1-based, for
/// errors, which name the table, the line, the column and the value). Read a record at a time: a
/// file with too many rows is rejected without holding it.
pub fn read_csv(
    table: &Table,
    columns: &[&str],
    max_rows: usize,
) -> Result<(Vec<f64>, Vec<usize>)> {
    read_csv_with(table, &[columns], max_rows).map(|(_, values, lines)| (values, lines))
}

/// [`read_csv`] for a table whose header may name any one of `headers` (for example a history
/// with or without its `moment` column): also returns which one it named.
pub fn read_csv_with(
    table: &Table,
    headers: &[&[&str]],
    max_rows: usize,
) -> Result<(usize, Vec<f64>, Vec<usize>)> {
    match table {
        Table::File { path, .. } => {
            let file = std::fs::File::open(path).with_context(|| format!("cannot read {table}"))?;
            read_lines(file, table, headers, max_rows)
        }
        Table::Data { text, .. } => read_lines(text.as_bytes(), table, headers, max_rows),
    }
}

fn read_lines(
    reader: impl Read,
    table: &Table,
    headers: &[&[&str]],
    max_rows: usize,
) -> Result<(usize, Vec<f64>, Vec<usize>)> {
    let mut columns: &[&str] = headers[0];
    let mut chosen = 0;
    let mut header_text = columns.join(",");
    // The csv crate splits the lines into cells and skips empty lines; cells are trimmed here
    // (without the copy the crate's trimming makes of every record), and comments and lines of
    // spaces skipped. Lines end at '\n' (a CRLF's '\r' is trimmed with the last cell). Quotes
    // are plain characters, so that a quote in a comment cannot swallow the lines after it (cells
    // are numbers). A row's number of cells is checked here, to name the line.
    let mut reader = csv::ReaderBuilder::new()
        .has_headers(false)
        .flexible(true)
        .terminator(csv::Terminator::Any(b'\n'))
        .quoting(false)
        .from_reader(LineEnds::new(LineLimit::new(reader, "a table of numbers")));
    let (mut values, mut numbers) = (Vec::new(), Vec::new());
    let mut header_seen = false;
    let mut record = csv::ByteRecord::new();
    loop {
        let more = reader
            .read_byte_record(&mut record)
            .with_context(|| format!("cannot read {table}"))?;
        if !more {
            break;
        }
        let end = reader.position().byte();
        let line = reader.get_mut().line_ending_at(end);
        // A cell as text, trimmed (borrowed unless it is not UTF-8: then shown with U+FFFD).
        let cell = |i: usize| {
            let bytes = &record[i];
            // A spreadsheet's "CSV UTF-8" starts with a byte-order mark.
            let bytes = match (header_seen, i) {
                (false, 0) => bytes.strip_prefix(b"\xef\xbb\xbf").unwrap_or(bytes),
                _ => bytes,
            };
            let bytes = bytes.trim_ascii();
            std::str::from_utf8(bytes)
                .map_or_else(|_| String::from_utf8_lossy(bytes), Cow::Borrowed)
        };
        // A line of spaces, or a comment.
        let first = cell(0);
        if record.len() == 1 && first.is_empty() || first.starts_with('#') {
            continue;
        }
        if !header_seen {
            let names: Vec<String> = (0..record.len())
                .map(|i| cell(i).to_ascii_lowercase())
                .collect();
            let Some(found) = headers.iter().position(|h| names == *h) else {
                let text = (0..record.len()).map(cell).collect::<Vec<_>>().join(",");
                let expected = headers
                    .iter()
                    .map(|h| format!("\"{}\"", h.join(",")))
                    .collect::<Vec<_>>()
                    .join(" or ");
                bail!("{table}, line {line}: header is \"{text}\", expected {expected}");
            };
            (chosen, columns) = (found, headers[found]);
            header_text = columns.join(",");
            header_seen = true;
            continue;
        }
        if numbers.len() == max_rows {
            bail!(
                "{table}, line {line}: the table has more than {max_rows} rows, the most a run takes"
            );
        }
        if record.len() != columns.len() {
            bail!(
                "{table}, line {line}: expected {} columns ({header_text}), found {}",
                columns.len(),
                record.len()
            );
        }
        for (i, name) in columns.iter().enumerate() {
            let text = cell(i);
            let value = text.parse::<f64>().map_err(|_| {
                anyhow!("{table}, line {line}: {name} = \"{text}\" is not a number")
            })?;
            values.push(value);
        }
        numbers.push(line);
    }
    if !header_seen {
        bail!("{table} is empty: it needs a header {header_text} and rows");
    }
    if numbers.is_empty() {
        bail!("{table} has a header but no rows");
    }
    Ok((chosen, values, numbers))
}

/// A reader that notes where the lines it passes on end, so that a record's line is known from
/// where the record ends: the csv crate's own line numbers leave out blank lines. Only the line
/// ends not yet matched to a record are kept (those in the csv reader's buffer).
struct LineEnds<R> {
    inner: R,
    /// Bytes passed on so far.
    offset: u64,
    /// Offsets of the '\n's passed on and not yet counted.
    ends: VecDeque<u64>,
    /// '\n's counted so far.
    counted: usize,
}

impl<R> LineEnds<R> {
    fn new(inner: R) -> Self {
        Self {
            inner,
            offset: 0,
            ends: VecDeque::new(),
            counted: 0,
        }
    }

    /// The line (1-based) of the record whose last byte (its '\n', or the last byte of a file
    /// without a final line end) is at `end - 1`.
    fn line_ending_at(&mut self, end: u64) -> usize {
        let mut terminated = false;
        while let Some(&at) = self.ends.front().filter(|&&at| at < end) {
            terminated = at + 1 == end;
            self.ends.pop_front();
            self.counted += 1;
        }
        if terminated {
            self.counted
        } else {
            self.counted + 1
        }
    }
}

impl<R: Read> Read for LineEnds<R> {
    fn read(&mut self, buf: &mut [u8]) -> io::Result<usize> {
        let n = self.inner.read(buf)?;
        let start = self.offset;
        self.ends.extend(
            buf[..n]
                .iter()
                .enumerate()
                .filter(|(_, b)| **b == b'\n')
                .map(|(i, _)| start + i as u64),
        );
        self.offset += n as u64;
        Ok(n)
    }
}

/// The longest line read from a table: a row is a few numbers (a sweep's output, some 100 and a
/// message), so a longer line means the file is not a table (a binary file, or an endless one with
/// no line ends, which the CSV reader would otherwise hold whole in memory).
pub const MAX_LINE_BYTES: u64 = 1 << 20;

/// A reader that fails on a line longer than [`MAX_LINE_BYTES`], naming the line and saying
/// what the file is not (`not`, e.g. "a table of numbers").
pub struct LineLimit<R> {
    inner: R,
    not: &'static str,
    /// Line ends passed on so far.
    lines: usize,
    /// Bytes passed on since the last line end.
    since_end: u64,
}

impl<R> LineLimit<R> {
    /// `inner`, read a line of at most [`MAX_LINE_BYTES`] at a time.
    pub fn new(inner: R, not: &'static str) -> Self {
        Self {
            inner,
            not,
            lines: 0,
            since_end: 0,
        }
    }
}

impl<R: Read> Read for LineLimit<R> {
    fn read(&mut self, buf: &mut [u8]) -> io::Result<usize> {
        let n = self.inner.read(buf)?;
        let read = &buf[..n];
        match read.iter().rposition(|&b| b == b'\n') {
            Some(last) => {
                self.lines += read.iter().filter(|&&b| b == b'\n').count();
                self.since_end = (n - last - 1) as u64;
            }
            None => self.since_end += n as u64,
        }
        if self.since_end > MAX_LINE_BYTES {
            return Err(io::Error::new(
                io::ErrorKind::InvalidData,
                format!(
                    "line {} is longer than {MAX_LINE_BYTES} bytes: not {}",
                    self.lines + 1,
                    self.not
                ),
            ));
        }
        Ok(n)
    }
}
