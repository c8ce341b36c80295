//! The `crack` report: one row per crack length, columns
//! `length,k1_max,k1_min,k2_max,k2_min,delta_k1,delta_k2,delta_k_eff,threshold` (names fixed by
//! issue 21: a public interface). K in stress times the square root of the case's length.

use super::{Cell, Column, Style};
use crate::units::{Quantity, Units};
use halfplane::crack::{CrackResult, CrackRow as Row};
use serde::Serialize;

/// One crack length.
#[derive(Debug, Clone, Serialize)]
pub struct CrackRow {
    length: f64,
    k1_max: f64,
    k1_min: f64,
    k2_max: f64,
    k2_min: f64,
    delta_k1: f64,
    delta_k2: f64,
    delta_k_eff: f64,
    threshold: f64,
}

impl From<&Row> for CrackRow {
    fn from(r: &Row) -> Self {
        Self {
            length: r.length,
            k1_max: r.k1_max,
            k1_min: r.k1_min,
            k2_max: r.k2_max,
            k2_min: r.k2_min,
            delta_k1: r.delta_k1,
            delta_k2: r.delta_k2,
            delta_k_eff: r.delta_k_eff,
            threshold: r.threshold,
        }
    }
}

impl CrackRow {
    /// The columns, in order.
    pub const COLUMNS: [Column<Self>; 9] = {
        use Quantity::{Intensity, Length};
        use Style::Fixed;
        [
            Column::<Self>::new("length", Length, |r| Cell::Num(r.length)).table(11, Style::Sig(5)),
            Column::<Self>::new("k1_max", Intensity, |r| Cell::Num(r.k1_max)).table(10, Fixed(3)),
            Column::<Self>::new("k1_min", Intensity, |r| Cell::Num(r.k1_min)).table(10, Fixed(3)),
            Column::<Self>::new("k2_max", Intensity, |r| Cell::Num(r.k2_max)).table(10, Fixed(3)),
            Column::<Self>::new("k2_min", Intensity, |r| Cell::Num(r.k2_min)).table(10, Fixed(3)),
            Column::<Self>::new("delta_k1", Intensity, |r| Cell::Num(r.delta_k1))
                .table(10, Fixed(3)),
            Column::<Self>::new("delta_k2", Intensity, |r| Cell::Num(r.delta_k2))
                .table(10, Fixed(3)),
            Column::<Self>::new("delta_k_eff", Intensity, |r| Cell::Num(r.delta_k_eff))
                .table(11, Fixed(3)),
            Column::<Self>::new("threshold", Intensity, |r| Cell::Num(r.threshold))
                .table(10, Fixed(3)),
        ]
    };
}

/// The whole report (its JSON object).
#[derive(Debug, Serialize)]
pub struct CrackReport {
    rows: Vec<CrackRow>,
    verdict: &'static str,
    arrest_length: Option<f64>,
    position: f64,
    angle: f64,
    half_width: f64,
    first_step: usize,
    last_step: usize,
    units: Units,
    /// The unit of K, e.g. "MPa sqrt(mm)".
    intensity_unit: String,
}

impl CrackReport {
    /// The report of an analysis.
    pub fn new(result: &CrackResult, units: &Units) -> Self {
        Self {
            rows: result.rows.iter().map(CrackRow::from).collect(),
            verdict: result.verdict.name(),
            arrest_length: result.arrest_length,
            position: result.mouth,
            angle: result.angle,
            half_width: result.half_width,
            first_step: result.steps.first().copied().unwrap_or(0),
            last_step: result.steps.last().copied().unwrap_or(0),
            units: units.clone(),
            intensity_unit: format!("{} sqrt({})", units.stress, units.length),
        }
    }

    /// CSV: one line per length.
    pub fn csv(&self) -> String {
        super::csv(&CrackRow::COLUMNS, &self.rows)
    }

    /// A table, after lines naming the crack, the cycle and the verdict.
    pub fn table(&self) -> String {
        let arrest = self.arrest_length.map_or(String::new(), |l| {
            format!(" at length {l:.6} {}", self.units.length)
        });
        format!(
            "crack at x = {:.6} {}, {:.2} degrees from the surface normal; steady cycle: steps {} to {}\nverdict: {}{arrest}\n{}",
            self.position,
            self.units.length,
            self.angle,
            self.first_step,
            self.last_step,
            self.verdict,
            super::table(&CrackRow::COLUMNS, &self.rows, &self.units)
        )
    }

    /// JSON.
    pub fn json(&self) -> serde_json::Result<String> {
        serde_json::to_string_pretty(self)
    }
}
