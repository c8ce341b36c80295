//! The `fatigue` report: one row per parameter, columns
//! `parameter,value,x,z,plane,step,point_method,line_method,cycles,tilt` (a public interface;
//! `tilt` was added with the 3-D plane search, at the end so that no column moves).

use super::{Cell, Column, Style};
use crate::units::{Quantity, Units};
use halfplane::fatigue::{FatigueResult, ParameterResult};
use serde::Serialize;

/// One parameter's maximum.
#[derive(Debug, Clone, Serialize)]
pub struct FatigueRow {
    parameter: &'static str,
    value: f64,
    x: f64,
    z: f64,
    plane: Option<f64>,
    step: usize,
    point_method: Option<f64>,
    line_method: Option<f64>,
    cycles: Option<f64>,
    tilt: Option<f64>,
}

impl From<&ParameterResult> for FatigueRow {
    fn from(p: &ParameterResult) -> Self {
        Self {
            parameter: p.parameter.name(),
            value: p.value,
            x: p.x,
            z: p.z,
            plane: p.angle,
            step: p.step,
            point_method: p.point_method,
            line_method: p.line_method,
            cycles: p.cycles,
            tilt: p.tilt,
        }
    }
}

fn opt(v: Option<f64>) -> Cell {
    v.map_or(Cell::Missing, Cell::Num)
}

impl FatigueRow {
    /// The columns, in order (`plane` in degrees from +x towards +z, `tilt` of the plane's
    /// normal towards +y in degrees, 0 unless `[fatigue] planes = "3d"`).
    pub const COLUMNS: [Column<Self>; 10] = {
        use Quantity::{Length, None};
        use Style::Sig;
        [
            Column::<Self>::new("parameter", None, |r| Cell::Text(r.parameter.into()))
                .table(22, Style::Fixed(0)),
            Column::<Self>::new("value", None, |r| Cell::Num(r.value)).table(13, Sig(5)),
            Column::<Self>::new("x", Length, |r| Cell::Num(r.x)).table(11, Style::Fixed(5)),
            Column::<Self>::new("z", Length, |r| Cell::Num(r.z)).table(11, Style::Fixed(5)),
            Column::<Self>::new("plane", None, |r| opt(r.plane)).table(7, Style::Fixed(2)),
            Column::<Self>::new("step", None, |r| Cell::Int(r.step)).table(6, Style::Fixed(0)),
            Column::<Self>::new("point_method", None, |r| opt(r.point_method)).table(13, Sig(5)),
            Column::<Self>::new("line_method", None, |r| opt(r.line_method)).table(13, Sig(5)),
            Column::<Self>::new("cycles", None, |r| opt(r.cycles)).table(11, Sig(4)),
            Column::<Self>::new("tilt", None, |r| opt(r.tilt)).table(6, Style::Fixed(2)),
        ]
    };
}

/// The whole report (its JSON object).
#[derive(Debug, Serialize)]
pub struct FatigueReport {
    critical_distance: Option<f64>,
    first_step: usize,
    last_step: usize,
    parameters: Vec<FatigueRow>,
    units: Units,
}

impl FatigueReport {
    /// The report of an analysis.
    pub fn new(result: &FatigueResult, units: &Units) -> Self {
        Self {
            critical_distance: result.critical_distance,
            first_step: result.steps.first().copied().unwrap_or(0),
            last_step: result.steps.last().copied().unwrap_or(0),
            parameters: result.parameters.iter().map(FatigueRow::from).collect(),
            units: units.clone(),
        }
    }

    /// CSV: one line per parameter.
    pub fn csv(&self) -> String {
        super::csv(&FatigueRow::COLUMNS, &self.parameters)
    }

    /// A table, after a line naming the cycle and the critical distance.
    pub fn table(&self) -> String {
        let l = self.critical_distance.map_or("not given".to_string(), |l| {
            format!("{l:.6} {}", self.units.length)
        });
        format!(
            "steady cycle: steps {} to {}; critical distance L: {l}\n{}",
            self.first_step,
            self.last_step,
            super::table(&FatigueRow::COLUMNS, &self.parameters, &self.units)
        )
    }

    /// JSON.
    pub fn json(&self) -> serde_json::Result<String> {
        serde_json::to_string_pretty(self)
    }
}
