//! The `wear` report: one row per checkpoint (the CSV, the table and the JSON `checkpoints`),
//! and the fields of each checkpoint for `--fields`.

use super::{Cell, Column, Style};
use crate::units::{Quantity, Units};
use halfplane::wear::{Checkpoint, WearOptions};
use serde::Serialize;
use std::fmt::Write;

/// One checkpoint.
#[derive(Debug, Clone, Serialize)]
pub struct WearRow {
    cycle: u64,
    wear_volume: f64,
    max_depth: f64,
    energy_per_cycle: f64,
    dissipated_energy: f64,
    contact_left: f64,
    contact_right: f64,
    peak_pressure: f64,
    stick_left: Option<f64>,
    stick_right: Option<f64>,
    slip_amplitude_max: f64,
}

fn optional(x: Option<f64>) -> Cell {
    x.map_or(Cell::Missing, Cell::Num)
}

impl WearRow {
    /// The columns, in order (the stick columns empty in CSV, "-" in the table, null in JSON,
    /// in gross sliding).
    pub const COLUMNS: [Column<Self>; 11] = {
        use Quantity::{Area, Energy, Length, Stress};
        use Style::Sig;
        [
            Column::<Self>::new("cycle", Quantity::None, |r| Cell::Text(r.cycle.to_string()))
                .table(13, Style::Fixed(0)),
            Column::<Self>::new("wear_volume", Area, |r| Cell::Num(r.wear_volume))
                .titled("volume")
                .table(11, Sig(5)),
            Column::<Self>::new("max_depth", Length, |r| Cell::Num(r.max_depth))
                .titled("depth")
                .table(11, Sig(5)),
            Column::<Self>::new("energy_per_cycle", Energy, |r| {
                Cell::Num(r.energy_per_cycle)
            })
            .titled("E/cycle")
            .table(11, Sig(5)),
            Column::<Self>::new("dissipated_energy", Energy, |r| {
                Cell::Num(r.dissipated_energy)
            })
            .titled("E total")
            .table(11, Sig(5)),
            Column::<Self>::new("contact_left", Length, |r| Cell::Num(r.contact_left))
                .titled("b1")
                .table(9, Style::Fixed(4)),
            Column::<Self>::new("contact_right", Length, |r| Cell::Num(r.contact_right))
                .titled("b2")
                .table(9, Style::Fixed(4)),
            Column::<Self>::new("peak_pressure", Stress, |r| Cell::Num(r.peak_pressure))
                .titled("p max")
                .table(10, Sig(5)),
            Column::<Self>::new("stick_left", Length, |r| optional(r.stick_left))
                .titled("stick left")
                .table(11, Style::Fixed(4)),
            Column::<Self>::new("stick_right", Length, |r| optional(r.stick_right))
                .titled("stick right")
                .table(11, Style::Fixed(4)),
            Column::<Self>::new("slip_amplitude_max", Length, |r| {
                Cell::Num(r.slip_amplitude_max)
            })
            .titled("slip amp")
            .table(11, Sig(5)),
        ]
    };

    /// The row of a checkpoint.
    pub fn new(c: &Checkpoint) -> Self {
        Self {
            cycle: c.cycle,
            wear_volume: c.wear_volume,
            max_depth: c.max_depth,
            energy_per_cycle: c.energy_per_cycle,
            dissipated_energy: c.dissipated_energy,
            contact_left: c.contact[0],
            contact_right: c.contact[1],
            peak_pressure: c.peak_pressure,
            stick_left: c.stick.map(|s| s[0]),
            stick_right: c.stick.map(|s| s[1]),
            slip_amplitude_max: c.slip_amplitude_max,
        }
    }
}

/// The whole `wear` report (its JSON object).
#[derive(Debug, Serialize)]
pub struct WearReport {
    law: &'static str,
    coefficient: f64,
    share: f64,
    cycles: u64,
    max_depth_increment: f64,
    cells: usize,
    cell_width: f64,
    /// Cycles marched (the others were jumped over); null when the run stopped.
    simulated_cycles: Option<usize>,
    /// The elastic approach of the unworn contact (the jumps' depth bound is a fraction of it).
    elastic_approach: f64,
    checkpoints: Vec<WearRow>,
    /// Why the run stopped before its last cycle (the checkpoints are those reached); null
    /// when it ran to the end.
    stopped: Option<String>,
    units: Units,
}

impl WearReport {
    /// The report of the `checkpoints` a wear run with `options` reached: all of them with
    /// `simulated_cycles` when it ended, those before `stopped` (the error) otherwise.
    pub fn new(
        checkpoints: &[Checkpoint],
        simulated_cycles: Option<usize>,
        elastic_approach: f64,
        options: &WearOptions,
        units: &Units,
        stopped: Option<String>,
    ) -> Self {
        let x = checkpoints.first().map(|c| &c.fields.x);
        Self {
            law: options.law().as_str(),
            coefficient: options.coefficient(),
            share: options.share(),
            cycles: options.cycles(),
            max_depth_increment: options.max_depth_increment(),
            cells: x.map_or(0, |x| x.len()),
            cell_width: x.map_or(0.0, |x| x[1] - x[0]),
            simulated_cycles,
            elastic_approach,
            checkpoints: checkpoints.iter().map(WearRow::new).collect(),
            stopped,
            units: units.clone(),
        }
    }

    /// One CSV row per checkpoint.
    pub fn csv(&self) -> String {
        super::csv(&WearRow::COLUMNS, &self.checkpoints)
    }

    /// One JSON object.
    pub fn json(&self) -> serde_json::Result<String> {
        serde_json::to_string_pretty(self)
    }

    /// A readable summary: the law and the run, then the checkpoints.
    pub fn table(&self) -> String {
        let mut o = String::new();
        let _ = writeln!(
            o,
            "wear: {} law, coefficient {:e} 1/{}, pad share {}, {} cycles ({} marched, jumps adding at most {} of the elastic approach {} {})",
            self.law,
            self.coefficient,
            self.units.stress,
            self.share,
            self.cycles,
            self.simulated_cycles
                .map_or_else(|| "stopped: some".into(), |n| n.to_string()),
            self.max_depth_increment,
            super::significant(self.elastic_approach, 5),
            self.units.length,
        );
        let _ = writeln!(
            o,
            "grid: {} cells of {} {}\n",
            self.cells,
            super::significant(self.cell_width, 5),
            self.units.length
        );
        o + &super::table(&WearRow::COLUMNS, &self.checkpoints, &self.units)
    }
}

/// The fields of a checkpoint as CSV: x, depth (both bodies), depth_pad, depth_specimen,
/// pressure and traction at the end of the cycle, slip_range over it.
pub fn fields_csv(c: &Checkpoint) -> String {
    let f = &c.fields;
    let mut o = String::from("x,depth,depth_pad,depth_specimen,pressure,traction,slip_range\n");
    for i in 0..f.x.len() {
        let _ = writeln!(
            o,
            "{},{},{},{},{},{},{}",
            f.x[i],
            f.depth[i],
            f.depth_pad[i],
            f.depth_specimen[i],
            f.pressure[i],
            f.traction[i],
            f.slip_range[i]
        );
    }
    o
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::report::tests::json_keys;

    #[test]
    fn csv_and_json_name_the_same_fields() {
        let row = WearRow {
            cycle: 10,
            wear_volume: 1e-6,
            max_depth: 2e-6,
            energy_per_cycle: 0.1,
            dissipated_energy: 1.0,
            contact_left: -0.5,
            contact_right: 0.5,
            peak_pressure: 800.0,
            stick_left: None,
            stick_right: None,
            slip_amplitude_max: 1e-3,
        };
        let text = crate::report::csv(&WearRow::COLUMNS, std::slice::from_ref(&row));
        let (header, line) = text.split_once('\n').expect("a header line and a row");
        let mut csv: Vec<String> = header.split(',').map(str::to_string).collect();
        csv.sort();
        assert_eq!(csv, json_keys(&row));
        assert_eq!(line, "10,0.000001,0.000002,0.1,1,-0.5,0.5,800,,,0.001\n");
    }
}
