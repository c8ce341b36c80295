//! Reports, one module per command (and per Python analysis). Each report has one row type whose column list drives the
//! table, the CSV and the JSON alike: a [`Column`] names the CSV/JSON key, the table heading, the
//! quantity (for the unit label) and the table format, and reads its cell from the row.

pub mod crack;
pub mod evolve;
pub mod fatigue;
pub mod march;
pub mod matching;
pub mod steady;
pub mod stress;
pub mod wear;

use crate::units::{Quantity, Units};
use std::fmt::Write;

/// How a report is written.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Format {
    /// A readable table.
    Table,
    /// Comma-separated values with a header row.
    Csv,
    /// One JSON object.
    Json,
}

/// One value of a row.
#[derive(Debug, Clone, PartialEq)]
pub enum Cell {
    /// A count or index.
    Int(usize),
    /// A number: CSV prints it in full (Rust's shortest round-trip form), the table rounded.
    Num(f64),
    /// A name, or a value already written out.
    Text(String),
    /// No value: empty in CSV, "-" in the table.
    Missing,
}

/// How the table writes a column's numbers.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Style {
    /// Fixed point with this many decimals.
    Fixed(usize),
    /// This many significant digits, written as people read them ([`significant`]).
    Sig(usize),
}

/// `x` to `digits` significant digits (at least 1): plain notation for 1e-3 <= |x| < 1e6 and for
/// 0 (`2.3615`, `486.70`, `0.0012340`), scientific outside it, where plain notation would need
/// runs of zeros (`3.1659e-4`, `1.2346e8`). The magnitude is taken after rounding, so 999.996 to
/// five digits is `1000.0`. Tables only: CSV and JSON keep every digit.
pub fn significant(x: f64, digits: usize) -> String {
    let decimals = digits.max(1) - 1;
    let sci = format!("{x:.decimals$e}");
    let exponent: i32 = match sci.split_once('e') {
        Some((_, e)) if x.is_finite() => e.parse().unwrap_or(0),
        _ => return sci,
    };
    if x == 0.0 || (-3..6).contains(&exponent) {
        let places = (decimals as i32 - exponent).max(0) as usize;
        format!("{x:.places$}")
    } else {
        sci
    }
}

/// Which outputs show a column.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Shown {
    /// Table and CSV.
    Both,
    /// Only the CSV.
    Csv,
    /// Only the table.
    Table,
}

/// One column of a report's rows.
pub struct Column<R> {
    /// The CSV header and JSON key.
    pub key: &'static str,
    /// The table heading.
    pub title: &'static str,
    /// What the numbers are, for the unit under the table heading.
    pub quantity: Quantity,
    /// Table width (0: as wide as the value, left-aligned, after two spaces).
    pub width: usize,
    /// Table number format.
    pub style: Style,
    /// Where the column appears.
    pub shown: Shown,
    /// The cell of a row.
    pub get: fn(&R) -> Cell,
}

impl<R> Column<R> {
    /// A column in the table and the CSV, titled by its key, as wide as its values.
    pub const fn new(key: &'static str, quantity: Quantity, get: fn(&R) -> Cell) -> Self {
        Self {
            key,
            title: key,
            quantity,
            width: 0,
            style: Style::Fixed(0),
            shown: Shown::Both,
            get,
        }
    }

    /// The table heading, when not the key.
    pub const fn titled(mut self, title: &'static str) -> Self {
        self.title = title;
        self
    }

    /// The table width and number format.
    pub const fn table(mut self, width: usize, style: Style) -> Self {
        self.width = width;
        self.style = style;
        self
    }

    /// Shown in one output only.
    pub const fn only(mut self, shown: Shown) -> Self {
        self.shown = shown;
        self
    }

    fn in_csv(&self) -> bool {
        self.shown != Shown::Table
    }

    fn in_table(&self) -> bool {
        self.shown != Shown::Csv
    }

    /// `text` placed in this column of the table, with the separator before it.
    fn place(&self, o: &mut String, first: bool, text: &str) {
        let w = self.width;
        let _ = match (first, w) {
            (_, 0) => write!(o, "  {text}"),
            (true, _) => write!(o, "{text:>w$}"),
            (false, _) => write!(o, " {text:>w$}"),
        };
    }
}

/// CSV of `rows`: a header of the keys, then one line per row.
pub fn csv<R>(columns: &[Column<R>], rows: &[R]) -> String {
    let columns: Vec<&Column<R>> = columns.iter().filter(|c| c.in_csv()).collect();
    let mut o = columns.iter().map(|c| c.key).collect::<Vec<_>>().join(",");
    o.push('\n');
    for r in rows {
        for (i, c) in columns.iter().enumerate() {
            if i > 0 {
                o.push(',');
            }
            let _ = match (c.get)(r) {
                Cell::Int(n) => write!(o, "{n}"),
                Cell::Num(x) => write!(o, "{x}"),
                Cell::Text(t) => write!(o, "{t}"),
                Cell::Missing => Ok(()),
            };
        }
        o.push('\n');
    }
    o
}

/// A table of `rows`: the headings, a line of their units, then one line per row.
pub fn table<R>(columns: &[Column<R>], rows: &[R], units: &Units) -> String {
    let columns: Vec<&Column<R>> = columns.iter().filter(|c| c.in_table()).collect();
    let mut o = String::new();
    let line = |o: &mut String, text: &dyn Fn(&Column<R>) -> String| {
        let mut l = String::new();
        for (i, c) in columns.iter().enumerate() {
            c.place(&mut l, i == 0, &text(c));
        }
        o.push_str(l.trim_end());
        o.push('\n');
    };
    line(&mut o, &|c| c.title.to_string());
    line(&mut o, &|c| units.of(c.quantity));
    for r in rows {
        line(&mut o, &|c| match ((c.get)(r), c.style) {
            (Cell::Int(n), _) => n.to_string(),
            (Cell::Num(x), Style::Fixed(p)) => format!("{x:.p$}"),
            (Cell::Num(x), Style::Sig(p)) => significant(x, p),
            (Cell::Text(t), _) => t,
            (Cell::Missing, _) => "-".into(),
        });
    }
    o
}

#[cfg(test)]
pub(crate) mod tests {
    use super::*;
    use serde::Serialize;

    /// The JSON keys of a serialized row, in order.
    pub(crate) fn json_keys<T: Serialize>(row: &T) -> Vec<String> {
        // serde_json keeps insertion order only with its preserve_order feature, so the keys are
        // compared as sets by the callers' sorting.
        let v = serde_json::to_value(row).unwrap();
        let mut keys: Vec<String> = v.as_object().unwrap().keys().cloned().collect();
        keys.sort();
        keys
    }

    struct Row(usize, f64, Option<f64>, &'static str);

    const COLUMNS: [Column<Row>; 4] = [
        Column::<Row>::new("n", Quantity::None, |r| Cell::Int(r.0)).table(3, Style::Fixed(0)),
        Column::<Row>::new("x", Quantity::Length, |r| Cell::Num(r.1)).table(8, Style::Fixed(3)),
        Column::<Row>::new("y", Quantity::Stress, |r| {
            r.2.map_or(Cell::Missing, Cell::Num)
        })
        .only(Shown::Csv),
        Column::<Row>::new("name", Quantity::None, |r| Cell::Text(r.3.into())),
    ];

    #[test]
    fn significant_digits_are_plain_in_the_readable_range_and_scientific_outside() {
        // The cases (were 2.3615e0, 4.8670e2, 4.3087e2), both ends of the plain range,
        // rounding that carries into the next power of ten, signs, zero and non-finite values.
        let cases: [(f64, usize, &str); 14] = [
            (2.36149, 5, "2.3615"),
            (486.7012, 5, "486.70"),
            (430.8712, 5, "430.87"),
            (1.0e-3, 5, "0.0010000"),
            (9.99994e-4, 5, "9.9999e-4"),
            (999_994.0, 5, "999994"),
            (999_996.0, 5, "1.0000e6"),
            (999.996, 5, "1000.0"),
            (-0.0398152, 7, "-0.03981520"),
            (3.1659351e-4, 7, "3.165935e-4"),
            (1.25e12, 3, "1.25e12"),
            (0.0, 5, "0.0000"),
            (7.0, 1, "7"),
            (f64::INFINITY, 5, "inf"),
        ];
        for (x, digits, expected) in cases {
            assert_eq!(significant(x, digits), expected, "{x} to {digits} digits");
        }
    }

    #[test]
    fn one_column_list_gives_the_table_and_the_csv() {
        let rows = [Row(1, 0.5, Some(2.0), "a"), Row(12, -1.25, None, "bc")];
        assert_eq!(
            csv(&COLUMNS, &rows),
            "n,x,y,name\n1,0.5,2,a\n12,-1.25,,bc\n"
        );
        assert_eq!(
            table(&COLUMNS, &rows, &Units::default()),
            "  n        x  name\n          mm\n  1    0.500  a\n 12   -1.250  bc\n"
        );
    }
}
