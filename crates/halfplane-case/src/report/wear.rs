//! The `wear` report: one row per checkpoint (the CSV, the table and the JSON `checkpoints`),
//! the fatigue parameters of each checkpoint's cycle for `--fatigue`, and the fields of each
//! checkpoint for `--fields`.

use super::{Cell, Column, Style};
use crate::units::{Quantity, Units};
use halfplane::fatigue::{FatigueResult, Parameter};
use halfplane::wear::{Checkpoint, LoopPoint, WearOptions};
use serde::{Serialize, Serializer};
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
    displacement_amplitude: f64,
    /// `--fatigue`: each parameter's maximum over the checkpoint's cycle (absent without it).
    #[serde(skip_serializing_if = "Option::is_none")]
    fatigue: Option<CheckpointFatigue>,
}

/// A parameter's maximum over a checkpoint's cycle (`--fatigue`): the JSON object
/// `fatigue.<parameter>`, the CSV columns `fatigue.<parameter>.<field>`.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct FatigueMax {
    max: f64,
    x: f64,
    z: f64,
    /// The point method (with the critical distance only).
    #[serde(skip_serializing_if = "Option::is_none")]
    point_method: Option<f64>,
    /// The line method (with the critical distance only).
    #[serde(skip_serializing_if = "Option::is_none")]
    line_method: Option<f64>,
}

impl FatigueMax {
    /// `(field, value)` in column order, the critical-distance values when given.
    fn fields(&self) -> Vec<(&'static str, f64)> {
        let mut v = vec![("max", self.max), ("x", self.x), ("z", self.z)];
        v.extend(self.point_method.map(|m| ("point_method", m)));
        v.extend(self.line_method.map(|m| ("line_method", m)));
        v
    }
}

/// The parameters of a checkpoint, in the order of `halfplane fatigue`, keyed by its names.
#[derive(Debug, Clone, PartialEq)]
pub struct CheckpointFatigue(Vec<(&'static str, FatigueMax)>);

impl CheckpointFatigue {
    /// Each reported parameter's maximum of `result`.
    pub fn new(result: &FatigueResult) -> Self {
        Self(
            result
                .parameters
                .iter()
                .map(|p| {
                    let m = FatigueMax {
                        max: p.value,
                        x: p.x,
                        z: p.z,
                        point_method: p.point_method,
                        line_method: p.line_method,
                    };
                    (p.parameter.name(), m)
                })
                .collect(),
        )
    }
}

impl Serialize for CheckpointFatigue {
    fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        s.collect_map(self.0.iter().map(|(k, v)| (k, v)))
    }
}

fn optional(x: Option<f64>) -> Cell {
    x.map_or(Cell::Missing, Cell::Num)
}

impl WearRow {
    /// The columns, in order (the stick columns empty in CSV, "-" in the table, null in JSON,
    /// in gross sliding).
    pub const COLUMNS: [Column<Self>; 12] = {
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
            Column::<Self>::new("displacement_amplitude", Length, |r| {
                Cell::Num(r.displacement_amplitude)
            })
            .titled("disp amp")
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
            displacement_amplitude: c.displacement_amplitude,
            fatigue: None,
        }
    }

    /// With the fatigue parameters of the checkpoint's cycle.
    pub fn with_fatigue(self, fatigue: CheckpointFatigue) -> Self {
        Self {
            fatigue: Some(fatigue),
            ..self
        }
    }
}

/// One parameter at one checkpoint, for the table of `--fatigue`.
struct FatigueLine<'a> {
    cycle: u64,
    parameter: &'static str,
    at: &'a FatigueMax,
}

impl FatigueLine<'_> {
    const COLUMNS: [Column<Self>; 7] = {
        use Quantity::{Length, None};
        use Style::{Fixed, Sig};
        [
            Column::<Self>::new("cycle", None, |r| Cell::Text(r.cycle.to_string()))
                .table(13, Fixed(0)),
            Column::<Self>::new("parameter", None, |r| Cell::Text(r.parameter.into()))
                .table(22, Fixed(0)),
            Column::<Self>::new("max", None, |r| Cell::Num(r.at.max)).table(13, Sig(5)),
            Column::<Self>::new("x", Length, |r| Cell::Num(r.at.x)).table(11, Fixed(5)),
            Column::<Self>::new("z", Length, |r| Cell::Num(r.at.z)).table(11, Fixed(5)),
            Column::<Self>::new("point_method", None, |r| optional(r.at.point_method))
                .table(13, Sig(5)),
            Column::<Self>::new("line_method", None, |r| optional(r.at.line_method))
                .table(13, Sig(5)),
        ]
    };
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
    /// The datum of the fretting loop's relative displacement (a length).
    loop_datum: f64,
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
        loop_datum: f64,
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
            loop_datum,
            checkpoints: checkpoints.iter().map(WearRow::new).collect(),
            stopped,
            units: units.clone(),
        }
    }

    /// The fatigue parameters of each checkpoint (`--fatigue`), one result per checkpoint, in
    /// order.
    pub fn with_fatigue(mut self, results: &[FatigueResult]) -> Self {
        let rows = std::mem::take(&mut self.checkpoints);
        self.checkpoints = rows
            .into_iter()
            .zip(results)
            .map(|(row, r)| row.with_fatigue(CheckpointFatigue::new(r)))
            .collect();
        self
    }

    /// The `--fatigue` CSV columns: `fatigue.<parameter>.<field>` for every parameter and field
    /// some checkpoint has, parameters in the order of `halfplane fatigue`.
    fn fatigue_columns(&self) -> Vec<(&'static str, &'static str)> {
        let mut columns: Vec<(&'static str, &'static str)> = Vec::new();
        for p in Parameter::ALL {
            let name = p.name();
            for field in ["max", "x", "z", "point_method", "line_method"] {
                let given = self.checkpoints.iter().any(|r| {
                    r.fatigue.as_ref().is_some_and(|f| {
                        f.0.iter()
                            .any(|(k, m)| *k == name && m.fields().iter().any(|(g, _)| *g == field))
                    })
                });
                if given {
                    columns.push((name, field));
                }
            }
        }
        columns
    }

    /// The `--fatigue` columns, `fatigue.<parameter>.<field>`, each with its value at every
    /// checkpoint (`None` where a checkpoint has none): the CSV's extra columns, Python's too.
    pub fn fatigue_table(&self) -> Vec<(String, Vec<Option<f64>>)> {
        self.fatigue_columns()
            .into_iter()
            .map(|(name, field)| {
                let values = self
                    .checkpoints
                    .iter()
                    .map(|row| {
                        let f = row.fatigue.as_ref()?;
                        let (_, m) = f.0.iter().find(|(k, _)| *k == name)?;
                        m.fields()
                            .into_iter()
                            .find(|(g, _)| *g == field)
                            .map(|(_, v)| v)
                    })
                    .collect();
                (format!("fatigue.{name}.{field}"), values)
            })
            .collect()
    }

    /// One CSV row per checkpoint; with `--fatigue`, the columns `fatigue.<parameter>.<field>`
    /// after the others.
    pub fn csv(&self) -> String {
        let text = super::csv(&WearRow::COLUMNS, &self.checkpoints);
        let columns = self.fatigue_table();
        if columns.is_empty() {
            return text;
        }
        let mut o = String::new();
        let mut lines = text.lines();
        o.push_str(lines.next().unwrap_or_default());
        for (name, _) in &columns {
            let _ = write!(o, ",{name}");
        }
        o.push('\n');
        for (k, line) in lines.enumerate() {
            o.push_str(line);
            for (_, values) in &columns {
                o.push(',');
                if let Some(v) = values[k] {
                    let _ = write!(o, "{v}");
                }
            }
            o.push('\n');
        }
        o
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
            "wear: {} law, coefficient {:e} 1/{}, pad share {}, {} cycles ({} marched, jumps adding at most {} of the elastic approach {} {} and kept stable)",
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
        o += &super::table(&WearRow::COLUMNS, &self.checkpoints, &self.units);
        let lines: Vec<FatigueLine> = self
            .checkpoints
            .iter()
            .filter_map(|r| r.fatigue.as_ref().map(|f| (r.cycle, f)))
            .flat_map(|(cycle, f)| {
                f.0.iter().map(move |(parameter, at)| FatigueLine {
                    cycle,
                    parameter,
                    at,
                })
            })
            .collect();
        if !lines.is_empty() {
            o += "\nfatigue over each checkpoint's cycle (maxima over the [fatigue] grid of the unworn contact):\n";
            o += &super::table(&FatigueLine::COLUMNS, &lines, &self.units);
        }
        o
    }
}

/// A loop point's value in one column.
pub type LoopValue = fn(&LoopPoint) -> f64;

/// The fretting loop's columns (`--fields`' `loop_<cycle>.csv`), each with its value at a point:
/// `shear` (Q) and `relative_displacement`.
pub const LOOP_COLUMNS: [(&str, LoopValue); 2] = [
    ("shear", |p| p.shear),
    ("relative_displacement", |p| p.relative_displacement),
];

/// The fretting loop of a checkpoint's cycle as CSV ([`LOOP_COLUMNS`]), at the cycle's start and
/// after every increment and slide.
pub fn loop_csv(c: &Checkpoint) -> String {
    let names: Vec<&str> = LOOP_COLUMNS.iter().map(|(name, _)| *name).collect();
    let mut o = names.join(",") + "\n";
    for p in &c.fretting_loop {
        let values: Vec<String> = LOOP_COLUMNS.iter().map(|(_, v)| v(p).to_string()).collect();
        o += &values.join(",");
        o.push('\n');
    }
    o
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
            displacement_amplitude: 2e-3,
            fatigue: None,
        };
        let text = crate::report::csv(&WearRow::COLUMNS, std::slice::from_ref(&row));
        let (header, line) = text.split_once('\n').expect("a header line and a row");
        let mut csv: Vec<String> = header.split(',').map(str::to_string).collect();
        csv.sort();
        assert_eq!(csv, json_keys(&row));
        assert_eq!(
            line,
            "10,0.000001,0.000002,0.1,1,-0.5,0.5,800,,,0.001,0.002\n"
        );
    }

    /// `--fatigue`: the CSV's extra columns after the 12 of the checkpoint are the JSON's
    /// `fatigue` object flattened (`fatigue.<parameter>.<field>`), the critical-distance values
    /// where given, and the table lists each parameter at each checkpoint.
    #[test]
    fn fatigue_columns_follow_the_checkpoint_and_name_the_json_fields() {
        let at = |max: f64, l: Option<f64>| FatigueMax {
            max,
            x: -0.76,
            z: 0.0,
            point_method: l,
            line_method: l,
        };
        let fatigue = CheckpointFatigue(vec![
            ("swt", at(2.6, Some(1.5))),
            ("ruiz_f1", at(0.13, None)),
        ]);
        let row = WearRow {
            cycle: 1,
            wear_volume: 1e-6,
            max_depth: 2e-6,
            energy_per_cycle: 0.1,
            dissipated_energy: 0.1,
            contact_left: -0.76,
            contact_right: 0.76,
            peak_pressure: 836.0,
            stick_left: Some(-0.5),
            stick_right: Some(0.5),
            slip_amplitude_max: 1e-3,
            displacement_amplitude: 2e-3,
            fatigue: None,
        }
        .with_fatigue(fatigue);
        let report = WearReport {
            law: "archard",
            coefficient: 3e-8,
            share: 0.5,
            cycles: 1,
            max_depth_increment: 0.01,
            cells: 400,
            cell_width: 0.0077,
            simulated_cycles: Some(1),
            elastic_approach: 0.0058,
            loop_datum: 7.6,
            checkpoints: vec![row.clone()],
            stopped: None,
            units: Units::default(),
        };
        let text = report.csv();
        let (header, line) = text.split_once('\n').unwrap();
        let plain = crate::report::csv(&WearRow::COLUMNS, std::slice::from_ref(&row));
        let (plain_header, plain_line) = plain.split_once('\n').unwrap();
        let extra = "fatigue.swt.max,fatigue.swt.x,fatigue.swt.z,fatigue.swt.point_method,\
                     fatigue.swt.line_method,fatigue.ruiz_f1.max,fatigue.ruiz_f1.x,fatigue.ruiz_f1.z";
        assert_eq!(header, format!("{plain_header},{extra}"));
        assert_eq!(
            line,
            format!(
                "{},2.6,-0.76,0,1.5,1.5,0.13,-0.76,0\n",
                plain_line.trim_end()
            )
        );
        let v = serde_json::to_value(&row).unwrap();
        let mut keys: Vec<String> = Vec::new();
        for (k, v) in v.as_object().unwrap() {
            match v.as_object() {
                Some(params) => {
                    for (p, fields) in params {
                        for f in fields.as_object().unwrap().keys() {
                            keys.push(format!("{k}.{p}.{f}"));
                        }
                    }
                }
                None => keys.push(k.clone()),
            }
        }
        keys.sort();
        let mut csv: Vec<String> = header.split(',').map(str::to_string).collect();
        csv.sort();
        assert_eq!(csv, keys);
        let table = report.table();
        assert!(
            table.contains("fatigue over each checkpoint's cycle"),
            "{table}"
        );
        assert!(table.lines().any(|l| l.contains("ruiz_f1")), "{table}");
    }
}
