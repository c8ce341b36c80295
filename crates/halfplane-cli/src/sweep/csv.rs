//! CSV output of a sweep: one header line, then one line per row. Numbers are written in full
//! (Rust's shortest round-trip form); a value the row does not have is an empty cell, never NaN.

use super::spec::Analysis;
use super::template::Outcome;
use super::{Layout, RowSink};
use anyhow::{anyhow, Context, Result};
use halfplane::batch::{MARCH_COLUMNS, STEADY_NUMBERS};
use std::fmt::Write as _;
use std::fs::File;
use std::io::{BufWriter, Write};
use std::path::{Path, PathBuf};

/// Writes a sweep's rows to `PATH.part`, renamed to `PATH` when the sweep completes, so a file
/// under the final name is always whole.
#[derive(Debug)]
pub struct CsvSink {
    out: BufWriter<File>,
    part: PathBuf,
    path: PathBuf,
}

/// The name written to until the output is complete.
pub fn part_path(path: &Path) -> PathBuf {
    let mut name = path.as_os_str().to_owned();
    name.push(".part");
    PathBuf::from(name)
}

impl CsvSink {
    /// Creates the output and writes the header.
    pub fn create(path: &Path, layout: &Layout) -> Result<Self> {
        let part = part_path(path);
        let file =
            File::create(&part).with_context(|| format!("cannot create {}", part.display()))?;
        let mut sink = Self {
            out: BufWriter::with_capacity(1 << 20, file),
            part,
            path: path.to_path_buf(),
        };
        let mut header = String::new();
        for (i, name) in layout.columns().iter().enumerate() {
            if i > 0 {
                header.push(',');
            }
            text(&mut header, name);
        }
        header.push('\n');
        sink.put(header.as_bytes())?;
        Ok(sink)
    }

    fn put(&mut self, bytes: &[u8]) -> Result<()> {
        self.out
            .write_all(bytes)
            .map_err(|e| anyhow!("cannot write {}: {e}", self.part.display()))
    }
}

impl RowSink for CsvSink {
    type Item = String;

    fn encode(layout: &Layout, values: &[f64], outcome: Outcome) -> String {
        line(layout, values, &outcome)
    }

    fn write(&mut self, rows: Vec<String>) -> Result<()> {
        for row in rows {
            self.put(row.as_bytes())?;
        }
        Ok(())
    }

    fn finish(mut self) -> Result<()> {
        self.out
            .flush()
            .map_err(|e| anyhow!("cannot write {}: {e}", self.part.display()))?;
        std::fs::rename(&self.part, &self.path).with_context(|| {
            format!(
                "cannot rename {} to {}",
                self.part.display(),
                self.path.display()
            )
        })
    }
}

/// A number in full, or nothing when it is not finite (a value the row does not have).
fn num(s: &mut String, v: f64) {
    if v.is_finite() {
        let _ = write!(s, "{v}");
    }
}

/// A text cell, quoted when it holds a comma, a quote or a line break.
fn text(s: &mut String, t: &str) {
    if t.contains([',', '"', '\n', '\r']) {
        s.push('"');
        s.push_str(&t.replace('"', "\"\""));
        s.push('"');
    } else {
        s.push_str(t);
    }
}

/// One row as a CSV line (with its line end).
pub fn line(layout: &Layout, values: &[f64], outcome: &Outcome) -> String {
    let mut s = String::with_capacity(64 + 24 * (values.len() + 13) + outcome.error.len());
    for &v in values {
        num(&mut s, v);
        s.push(',');
    }
    match &outcome.steady {
        Some(summary) => {
            s.push_str(summary.regime().as_str());
            for v in summary.numbers() {
                s.push(',');
                num(&mut s, v);
            }
        }
        None => s.push_str(&",".repeat(STEADY_NUMBERS)),
    }
    s.push(',');
    text(&mut s, &outcome.error);
    if layout.analysis == Analysis::March {
        match &outcome.march {
            Some(m) => {
                let stick = m.final_stick();
                for v in [m.energy(), m.max_slip_amplitude()] {
                    s.push(',');
                    num(&mut s, v.unwrap_or(f64::NAN));
                }
                s.push(',');
                if let Some(k) = m.shakedown_cycle() {
                    let _ = write!(s, "{k}");
                }
                for v in [stick.map(|z| z[0]), stick.map(|z| z[1])] {
                    s.push(',');
                    num(&mut s, v.unwrap_or(f64::NAN));
                }
                let _ = write!(s, ",{},", m.cycles_run());
                num(&mut s, m.steady_change().unwrap_or(f64::NAN));
                s.push(',');
                if let Some(met) = m.steady_converged() {
                    let _ = write!(s, "{met}");
                }
            }
            None => s.push_str(&",".repeat(MARCH_COLUMNS.len())),
        }
    }
    if layout.analysis == Analysis::Crack {
        s.push(',');
        if let Some(c) = &outcome.crack {
            s.push_str(c.verdict.name());
            s.push(',');
            num(&mut s, c.arrest_length.unwrap_or(f64::NAN));
        } else {
            s.push(',');
        }
    }
    if layout.analysis == Analysis::Wear {
        match &outcome.wear {
            Some(w) => {
                for v in w.numbers() {
                    s.push(',');
                    num(&mut s, v.unwrap_or(f64::NAN));
                }
                let _ = write!(s, ",{}", w.simulated_cycles);
            }
            None => s.push_str(&",".repeat(super::WEAR_COLUMNS.len())),
        }
    }
    s.push('\n');
    s
}
