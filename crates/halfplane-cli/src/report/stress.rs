//! The `stress` report: one row per point, columns `x,z,sxx,szz,syy,sxz` (a public interface),
//! stresses in the case's stress unit.

use super::{Cell, Column, Style};
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
        format!(
            "stresses at step {} (P = {}, Q = {}, sigma = {}; a = {:.6})\n{}",
            self.step,
            self.normal,
            self.shear,
            self.bulk,
            self.half_width,
            super::table(&StressRow::COLUMNS, &self.points, &self.units)
        )
    }

    /// JSON: the increment, its load and the rows under `points`.
    pub fn json(&self) -> serde_json::Result<String> {
        serde_json::to_string_pretty(self)
    }
}
