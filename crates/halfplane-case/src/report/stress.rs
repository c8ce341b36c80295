//! The `stress` report: one row per point, columns `x,z,sxx,szz,syy,sxz` (a public interface),
//! stresses in the case's stress unit.

use super::{Cell, Column, Format, Style};
use crate::units::{Quantity, Units};
use serde::Serialize;

/// The stresses at one point.
#[derive(Debug, Clone, Copy, Serialize)]
pub struct StressRow {
    /// Position along the surface.
    pub x: f64,
    /// Depth into the body.
    pub z: f64,
    /// sxx (bulk tension included).
    pub sxx: f64,
    /// szz.
    pub szz: f64,
    /// syy = nu (sxx + szz).
    pub syy: f64,
    /// sxz.
    pub sxz: f64,
}

impl StressRow {
    /// The columns, in order.
    pub const COLUMNS: [Column<Self>; 6] = {
        use Quantity::{Length, Stress};
        use Style::Fixed;
        [
            Column::<Self>::new("x", Length, |r| Cell::Num(r.x)).table(12, Fixed(6)),
            Column::<Self>::new("z", Length, |r| Cell::Num(r.z)).table(12, Fixed(6)),
            Column::<Self>::new("sxx", Stress, |r| Cell::Num(r.sxx)).table(14, Fixed(4)),
            Column::<Self>::new("szz", Stress, |r| Cell::Num(r.szz)).table(14, Fixed(4)),
            Column::<Self>::new("syy", Stress, |r| Cell::Num(r.syy)).table(14, Fixed(4)),
            Column::<Self>::new("sxz", Stress, |r| Cell::Num(r.sxz)).table(14, Fixed(4)),
        ]
    };
}

/// The whole report (its JSON object).
#[derive(Debug, Serialize)]
pub struct StressReport {
    /// The increment used (1-based).
    pub step: usize,
    /// The load there: P, Q, sigma.
    pub normal: f64,
    /// Q.
    pub shear: f64,
    /// sigma (added to sxx).
    pub bulk: f64,
    /// Contact half-width.
    pub half_width: f64,
    /// M there (0 without a moment).
    pub moment: f64,
    /// The contact's ends b1 and b2 (`-a` and `a` when centred).
    pub contact_left: f64,
    /// b2.
    pub contact_right: f64,
    /// One row per point, in order.
    pub points: Vec<StressRow>,
    /// Unit names.
    pub units: Units,
}

impl StressReport {
    /// CSV: the header `x,z,sxx,szz,syy,sxz` and one line per point.
    pub fn csv(&self) -> String {
        super::csv(&StressRow::COLUMNS, &self.points)
    }

    /// A table: a line naming the increment, then the rows.
    pub fn table(&self) -> String {
        let contact = if self.contact_left == -self.contact_right {
            format!("a = {:.6}", self.half_width)
        } else {
            format!(
                "M = {}; contact [{:.6}, {:.6}]",
                self.moment, self.contact_left, self.contact_right
            )
        };
        format!(
            "stresses at step {} (P = {}, Q = {}, sigma = {}; {contact})\n{}",
            self.step,
            self.normal,
            self.shear,
            self.bulk,
            super::table(&StressRow::COLUMNS, &self.points, &self.units)
        )
    }

    /// JSON: the increment, its load and the rows under `points`.
    pub fn json(&self) -> serde_json::Result<String> {
        serde_json::to_string_pretty(self)
    }

    /// The report in `format` a piece at a time, for output written as the rows are computed:
    /// `self` holds the increment and no rows; the pieces, concatenated, are exactly what
    /// [`StressReport::csv`], [`StressReport::table`] or [`StressReport::json`] (with a final
    /// newline) give for the whole report.
    pub fn pieces(&self, format: Format) -> serde_json::Result<Pieces<'_>> {
        let (head, tail) = match format {
            Format::Csv => (self.csv(), String::new()),
            Format::Table => (self.table(), String::new()),
            Format::Json => {
                let empty = self.json()?;
                let at = empty.find(EMPTY_POINTS).unwrap_or(empty.len());
                let (head, tail) = empty.split_at(at);
                (
                    format!("{head}\"points\": ["),
                    format!("\n  ]{}\n", &tail[EMPTY_POINTS.len().min(tail.len())..]),
                )
            }
        };
        Ok(Pieces {
            report: self,
            format,
            head,
            tail,
            first: true,
        })
    }
}

/// The key of the rows in the JSON of a report without rows.
const EMPTY_POINTS: &str = "\"points\": []";

/// The pieces of a report written as its rows are computed ([`StressReport::pieces`]).
pub struct Pieces<'a> {
    report: &'a StressReport,
    format: Format,
    head: String,
    tail: String,
    first: bool,
}

impl Pieces<'_> {
    /// The text of the next `rows` (preceded by the report's head the first time).
    pub fn rows(&mut self, rows: &[StressRow]) -> serde_json::Result<String> {
        let first = std::mem::replace(&mut self.first, false);
        let mut o = if first {
            self.head.clone()
        } else {
            String::new()
        };
        match self.format {
            // Both repeat their headings for every call: keep only the rows.
            Format::Csv => o.push_str(after_lines(&super::csv(&StressRow::COLUMNS, rows), 1)),
            Format::Table => o.push_str(after_lines(
                &super::table(&StressRow::COLUMNS, rows, &self.report.units),
                2,
            )),
            Format::Json => {
                for (i, row) in rows.iter().enumerate() {
                    o.push_str(if first && i == 0 { "\n    " } else { ",\n    " });
                    o.push_str(&serde_json::to_string_pretty(row)?.replace('\n', "\n    "));
                }
            }
        }
        Ok(o)
    }

    /// The text after the last row.
    pub fn end(&self) -> &str {
        &self.tail
    }
}

/// `text` after its first `n` lines.
fn after_lines(text: &str, n: usize) -> &str {
    let mut rest = text;
    for _ in 0..n {
        rest = rest.split_once('\n').map_or("", |(_, r)| r);
    }
    rest
}

#[cfg(test)]
mod tests {
    use super::*;

    fn report(points: Vec<StressRow>) -> StressReport {
        StressReport {
            step: 7,
            normal: 1000.0,
            shear: -300.0,
            bulk: 60.0,
            half_width: 0.76,
            moment: 0.0,
            contact_left: -0.76,
            contact_right: 0.76,
            points,
            units: Units::default(),
        }
    }

    #[test]
    fn pieces_concatenate_to_the_whole_report_in_every_format() {
        let rows: Vec<StressRow> = (0..7)
            .map(|i| {
                let v = i as f64;
                StressRow {
                    x: v - 3.0,
                    z: 0.25 * v,
                    sxx: -100.0 * v + 0.5,
                    szz: -1e-12 * v,
                    syy: 3.0,
                    sxz: 1e20 * v,
                }
            })
            .collect();
        let whole = report(rows.clone());
        let empty = report(Vec::new());
        for format in [Format::Csv, Format::Table, Format::Json] {
            let expected = match format {
                Format::Csv => whole.csv(),
                Format::Table => whole.table(),
                Format::Json => whole.json().unwrap() + "\n",
            };
            let mut pieces = empty.pieces(format).unwrap();
            let mut got = String::new();
            for chunk in rows.chunks(3) {
                got.push_str(&pieces.rows(chunk).unwrap());
            }
            got.push_str(pieces.end());
            assert_eq!(got, expected, "{format:?}");
        }
    }
}
