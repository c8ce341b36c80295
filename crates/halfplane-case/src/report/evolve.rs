//! The `evolve` report: one row per point of each half-cycle.

use super::{Cell, Column, Shown, Style};
use crate::units::{Quantity, Units};
use halfplane::evolution::{Evolution, EvolutionWarning};
use serde::Serialize;

/// One point of the evolution: a table line, a CSV line and an element of the JSON `points`.
#[derive(Debug, Clone, Serialize)]
pub struct EvolveRow {
    half: u8,
    fraction: f64,
    normal: f64,
    shear: f64,
    bulk: f64,
    half_width: f64,
    stick_left: f64,
    stick_right: f64,
    asymptotic_stick_left: f64,
    asymptotic_stick_right: f64,
    state: &'static str,
    moment: f64,
    contact_left: f64,
    contact_right: f64,
}

/// A column of lengths (a, stick and asymptotic boundaries), to 6 decimals.
const fn length(key: &'static str, width: usize, get: fn(&EvolveRow) -> Cell) -> Column<EvolveRow> {
    Column::new(key, Quantity::Length, get).table(width, Style::Fixed(6))
}

/// A column of loads, to 4 decimals.
const fn load(
    key: &'static str,
    q: Quantity,
    width: usize,
    get: fn(&EvolveRow) -> Cell,
) -> Column<EvolveRow> {
    Column::new(key, q, get).table(width, Style::Fixed(4))
}

impl EvolveRow {
    /// The columns of every format, in order (the CSV header is their keys).
    pub const COLUMNS: [Column<Self>; 14] = [
        Column::<Self>::new("half", Quantity::None, |r| Cell::Int(r.half.into()))
            .table(4, Style::Fixed(0)),
        load("fraction", Quantity::None, 8, |r| Cell::Num(r.fraction)),
        load("normal", Quantity::ForcePerLength, 11, |r| {
            Cell::Num(r.normal)
        }),
        load("shear", Quantity::ForcePerLength, 11, |r| {
            Cell::Num(r.shear)
        }),
        load("bulk", Quantity::Stress, 10, |r| Cell::Num(r.bulk)),
        length("half_width", 10, |r| Cell::Num(r.half_width)).titled("a"),
        length("stick_left", 11, |r| Cell::Num(r.stick_left)),
        length("stick_right", 11, |r| Cell::Num(r.stick_right)),
        length("asymptotic_stick_left", 11, |r| {
            Cell::Num(r.asymptotic_stick_left)
        })
        .titled("asym_left"),
        length("asymptotic_stick_right", 11, |r| {
            Cell::Num(r.asymptotic_stick_right)
        })
        .titled("asym_right"),
        Column::<Self>::new("state", Quantity::None, |r| Cell::Text(r.state.into())),
        Column::<Self>::new("moment", Quantity::Moment, |r| Cell::Num(r.moment)).only(Shown::Csv),
        Column::<Self>::new("contact_left", Quantity::Length, |r| {
            Cell::Num(r.contact_left)
        })
        .only(Shown::Csv),
        Column::<Self>::new("contact_right", Quantity::Length, |r| {
            Cell::Num(r.contact_right)
        })
        .only(Shown::Csv),
    ];
}

/// The whole `evolve` report (its JSON object).
#[derive(Debug, Serialize)]
pub struct EvolveReport {
    regime: &'static str,
    points: Vec<EvolveRow>,
    warnings: Vec<String>,
    units: Units,
}

impl EvolveReport {
    /// The report of an evolution, with the unit names for the table.
    pub fn new(ev: &Evolution, units: &Units) -> Self {
        Self {
            regime: ev.regime.as_str(),
            points: ev
                .points
                .iter()
                .map(|p| EvolveRow {
                    half: p.half.number(),
                    fraction: p.fraction,
                    normal: p.load.normal(),
                    shear: p.load.shear(),
                    bulk: p.load.bulk(),
                    half_width: p.half_width,
                    stick_left: p.stick_zone.left,
                    stick_right: p.stick_zone.right,
                    asymptotic_stick_left: p.asymptotic_stick_zone.left,
                    asymptotic_stick_right: p.asymptotic_stick_zone.right,
                    state: p.state.as_str(),
                    moment: p.load.moment(),
                    contact_left: p.contact.end(halfplane::Edge::Left),
                    contact_right: p.contact.end(halfplane::Edge::Right),
                })
                .collect(),
            warnings: warnings(ev),
            units: units.clone(),
        }
    }

    /// CSV, one row per point.
    pub fn csv(&self) -> String {
        super::csv(&EvolveRow::COLUMNS, &self.points)
    }

    /// A readable table: the regime, then one line per point.
    pub fn table(&self) -> String {
        format!(
            "regime {}\n{}",
            self.regime,
            super::table(&EvolveRow::COLUMNS, &self.points, &self.units)
        )
    }

    /// One JSON object.
    pub fn json(&self) -> serde_json::Result<String> {
        serde_json::to_string_pretty(self)
    }

    /// Warnings in words, for stderr.
    pub fn warnings(&self) -> &[String] {
        &self.warnings
    }
}

/// Warnings in words, for stderr and the JSON.
fn warnings(ev: &Evolution) -> Vec<String> {
    ev.warnings
        .iter()
        .map(|w| match w {
            EvolutionWarning::NonMonotoneSlip { half, edge, fraction } => format!(
                "warning: half {half}: the {} stick boundary moves outwards at fraction {fraction:.4}; slip zones do not grow monotonically, so the exact partial-path result does not hold there (use `halfplane march`)",
                edge.name()
            ),
            EvolutionWarning::OneEdgeSlip { half, count } => format!(
                "warning: half {half}: {count} point(s) slip at one edge only; their slipping boundary is from the two-edge relation and only approximate (use `halfplane march` for exact values)"
            ),
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_json_keys_are_the_columns() {
        let row = EvolveRow {
            half: 1,
            fraction: 0.0,
            normal: 1.0,
            shear: 0.0,
            bulk: 0.0,
            half_width: 1.0,
            stick_left: -1.0,
            stick_right: 1.0,
            asymptotic_stick_left: -1.0,
            asymptotic_stick_right: 1.0,
            state: "full-stick",
            moment: 0.0,
            contact_left: -1.0,
            contact_right: 1.0,
        };
        let mut columns: Vec<String> = EvolveRow::COLUMNS.iter().map(|c| c.key.into()).collect();
        columns.sort();
        assert_eq!(super::super::tests::json_keys(&row), columns);
    }
}
