//! The `march` report: one row per increment, one per cycle, and a summary table.

use super::{Cell, Column, Shown, Style};
use crate::units::{Quantity, Units};
use halfplane::history::{History, Steady};
use halfplane::march::MarchResult;
use serde::Serialize;
use std::fmt::Write;

/// One increment: a CSV line, an element of the JSON `steps`, and (for the listed increments) a
/// line of the summary table.
#[derive(Debug, Clone, Serialize)]
pub struct MarchStepRow<'a> {
    step: usize,
    normal: f64,
    shear: f64,
    bulk: f64,
    half_width: f64,
    moment: f64,
    contact_left: f64,
    contact_right: f64,
    stick_intervals: &'a [[f64; 2]],
    largest_stick: Option<[f64; 2]>,
    energy_increment: f64,
    energy: f64,
    /// The bodies' relative tangential displacement, datum the report's `loop_datum`.
    relative_displacement: f64,
    /// Solver passes: in the CSV only (the JSON never had it).
    #[serde(skip)]
    passes: usize,
}

type StepColumn<'a> = Column<MarchStepRow<'a>>;

fn stick(r: &MarchStepRow, side: usize) -> Cell {
    r.largest_stick
        .map_or(Cell::Missing, |s| Cell::Num(s[side]))
}

impl<'a> MarchStepRow<'a> {
    /// The columns of the CSV and the summary table, in order. The stick columns hold the largest
    /// stick interval (empty in CSV, "-" in the table, when none), `stick_intervals` every
    /// interval as `left:right`, space-separated, and `runs` (table only) how many there are.
    pub const COLUMNS: [StepColumn<'a>; 16] = {
        use Quantity::{Energy, ForcePerLength, Length, Stress};
        use Style::Fixed;
        [
            Column::<Self>::new("step", Quantity::None, |r| Cell::Int(r.step)).table(6, Fixed(0)),
            Column::<Self>::new("normal", ForcePerLength, |r| Cell::Num(r.normal))
                .table(11, Fixed(4)),
            Column::<Self>::new("shear", ForcePerLength, |r| Cell::Num(r.shear))
                .table(11, Fixed(4)),
            Column::<Self>::new("bulk", Stress, |r| Cell::Num(r.bulk)).table(10, Fixed(4)),
            Column::<Self>::new("half_width", Length, |r| Cell::Num(r.half_width))
                .titled("a")
                .table(10, Fixed(6)),
            Column::<Self>::new("stick_left", Length, |r| stick(r, 0)).table(11, Fixed(6)),
            Column::<Self>::new("stick_right", Length, |r| stick(r, 1)).table(11, Fixed(6)),
            Column::<Self>::new("stick_intervals", Length, |r| {
                let text: Vec<String> = r
                    .stick_intervals
                    .iter()
                    .map(|[l, r]| format!("{l}:{r}"))
                    .collect();
                Cell::Text(text.join(" "))
            })
            .only(Shown::Csv),
            Column::<Self>::new("energy_increment", Energy, |r| {
                Cell::Num(r.energy_increment)
            })
            .only(Shown::Csv),
            Column::<Self>::new("energy", Energy, |r| Cell::Num(r.energy)).only(Shown::Csv),
            Column::<Self>::new("passes", Quantity::None, |r| Cell::Int(r.passes)).only(Shown::Csv),
            Column::<Self>::new("moment", Quantity::Moment, |r| Cell::Num(r.moment))
                .only(Shown::Csv),
            Column::<Self>::new("contact_left", Length, |r| Cell::Num(r.contact_left))
                .only(Shown::Csv),
            Column::<Self>::new("contact_right", Length, |r| Cell::Num(r.contact_right))
                .only(Shown::Csv),
            Column::<Self>::new("relative_displacement", Length, |r| {
                Cell::Num(r.relative_displacement)
            })
            .only(Shown::Csv),
            Column::<Self>::new("runs", Quantity::None, |r| {
                Cell::Int(r.stick_intervals.len())
            })
            .table(5, Fixed(0))
            .only(Shown::Table),
        ]
    };
}

/// One cycle: a line of the cycle table and an element of the JSON `cycles`.
#[derive(Debug, Clone, Serialize)]
pub struct MarchCycleRow {
    index: usize,
    energy: f64,
    max_slip_amplitude: f64,
}

impl MarchCycleRow {
    /// The columns of the cycle table.
    pub const COLUMNS: [Column<Self>; 3] = [
        Column::<Self>::new("index", Quantity::None, |r| Cell::Int(r.index))
            .titled("cycle")
            .table(6, Style::Fixed(0)),
        Column::<Self>::new("energy", Quantity::Energy, |r| Cell::Num(r.energy))
            .table(14, Style::Sig(7)),
        Column::<Self>::new("max_slip_amplitude", Quantity::Length, |r| {
            Cell::Num(r.max_slip_amplitude)
        })
        .titled("max slip amplitude")
        .table(20, Style::Sig(7)),
    ];
}

/// The whole `march` report (its JSON object).
#[derive(Debug, Serialize)]
pub struct MarchReport<'a> {
    cells: usize,
    cell_width: f64,
    /// The datum of the steps' `relative_displacement` ([`MarchResult::loop_datum`]).
    loop_datum: f64,
    steps: Vec<MarchStepRow<'a>>,
    cycles: Vec<MarchCycleRow>,
    shakedown_cycle: Option<usize>,
    /// Cycles marched (all of the history's, or those a march until steady took).
    cycles_run: usize,
    /// The largest change of a cell's slip range between the last two cycles, a fraction of
    /// `A f P_max` (null with fewer than two cycles).
    steady_change: Option<f64>,
    /// Whether that change is within `history.steady_tolerance` (null with fewer than two
    /// cycles).
    steady_converged: Option<bool>,
    /// The tolerance it was compared with (table only).
    #[serde(skip)]
    steady_tolerance: f64,
    /// Marched until the cycle repeated (table only).
    #[serde(skip)]
    until_steady: bool,
    units: Units,
}

impl<'a> MarchReport<'a> {
    /// The report of a marched history, with the unit names for the table; `steady` holds the
    /// tolerance `steady_converged` is decided by, and `until_steady` says whether the march ran
    /// until its cycle repeated (`history.cycles = "steady"`).
    pub fn new(
        result: &'a MarchResult,
        units: &Units,
        steady: &Steady,
        until_steady: bool,
    ) -> Self {
        Self {
            cells: result.x.len(),
            // A march has at least 8 cells (the solver rejects fewer).
            cell_width: result.x[1] - result.x[0],
            loop_datum: result.loop_datum(),
            steps: result
                .steps
                .iter()
                .zip(result.relative_displacements())
                .map(|(s, relative_displacement)| MarchStepRow {
                    step: s.step,
                    normal: s.load.normal(),
                    shear: s.load.shear(),
                    bulk: s.load.bulk(),
                    half_width: s.half_width,
                    moment: s.load.moment(),
                    contact_left: s.ends.left,
                    contact_right: s.ends.right,
                    stick_intervals: &s.stick_intervals,
                    largest_stick: s.largest_stick(),
                    energy_increment: s.energy_increment,
                    energy: s.energy,
                    relative_displacement,
                    passes: s.passes,
                })
                .collect(),
            cycles: result
                .cycles
                .iter()
                .map(|c| MarchCycleRow {
                    index: c.index,
                    energy: c.energy,
                    max_slip_amplitude: c.max_slip_amplitude(),
                })
                .collect(),
            shakedown_cycle: result.shakedown_cycle,
            cycles_run: result.cycles.len(),
            steady_change: result.steady_change,
            steady_converged: result.steady_change.map(|c| steady.is_met(c)),
            steady_tolerance: steady.tolerance(),
            until_steady,
            units: units.clone(),
        }
    }

    /// The increments' rows (their values through [`MarchStepRow::COLUMNS`]).
    pub fn step_rows(&self) -> &[MarchStepRow<'a>] {
        &self.steps
    }

    /// One CSV row per increment.
    pub fn csv(&self) -> String {
        super::csv(&MarchStepRow::COLUMNS, &self.steps)
    }

    /// One JSON object.
    pub fn json(&self) -> serde_json::Result<String> {
        serde_json::to_string_pretty(self)
    }

    /// A readable summary: the grid, the history, the cycles and the increments at the ramp end
    /// and each quarter of the last cycle (every increment for a history from a file).
    pub fn table(&self, result: &MarchResult, history: &History, tolerance: f64) -> String {
        let mut o = String::new();
        let (n, w) = (self.cells, self.cell_width);
        let span = result.x[n - 1] + 0.5 * w;
        let len = &self.units.length;
        let _ = writeln!(
            o,
            "grid         {n} cells over [-{span:.6}, {span:.6}] {len}, cell width {w:.6} {len}"
        );
        let _ = match history.cycles() {
            Some(c) => writeln!(
                o,
                "history      {} increments: {} of ramp, {} cycles of {}{}",
                self.steps.len(),
                c.first_step(),
                self.cycles_run,
                c.steps_per_cycle(),
                if self.until_steady {
                    " (marched until the cycle repeated)"
                } else {
                    ""
                }
            ),
            None => writeln!(
                o,
                "history      {} increments from the file",
                history.loads().len()
            ),
        };
        if let Some(last) = self.steps.last() {
            let _ = writeln!(
                o,
                "energy       {} {} dissipated in all",
                super::significant(last.energy, 7),
                self.units.of(Quantity::Energy)
            );
        }
        if !self.cycles.is_empty() {
            o.push('\n');
            o.push_str(&super::table(
                &MarchCycleRow::COLUMNS,
                &self.cycles,
                &self.units,
            ));
            let _ = match self.shakedown_cycle {
                Some(k) => writeln!(
                    o,
                    "steady cycle: from cycle {k} (cycle {} repeats it within {tolerance})",
                    k + 1
                ),
                None => writeln!(
                    o,
                    "steady cycle: not reached (no two consecutive cycles agree within {tolerance})"
                ),
            };
            if let (Some(change), Some(met)) = (self.steady_change, self.steady_converged) {
                let t = self.steady_tolerance;
                let _ = match met {
                    // The change itself is in the JSON: once converged it is often rounding.
                    true => writeln!(
                        o,
                        "slip ranges: repeat (no cell's changed by more than history.steady_tolerance = {t:e} x A f P in the last cycle)"
                    ),
                    false => writeln!(
                        o,
                        "slip ranges: still changing ({change:.2e} A f P in the last cycle > history.steady_tolerance = {t:e}): more cycles would move them; cycles = \"steady\" marches until they repeat"
                    ),
                };
            }
        }
        // With cycles, the ramp end and the end of every quarter of the last cycle (five steps,
        // so the search below is constant time); a file history lists every step. (Searching a
        // list of every step once per step made this quadratic: 1.1 s for 100,000 increments.)
        let ends: Option<Vec<usize>> = history.cycles().map(|c| {
            let last = c.first_step() + (self.cycles_run.max(1) - 1) * c.steps_per_cycle();
            let mut v = vec![c.first_step()];
            v.extend((1..=4).map(|q| last + q * c.steps_per_cycle() / 4));
            v
        });
        let listed = |step: usize| ends.as_ref().is_none_or(|e| e.contains(&step));
        let rows: Vec<MarchStepRow> = self
            .steps
            .iter()
            .filter(|s| listed(s.step))
            .cloned()
            .collect();
        o.push('\n');
        o.push_str(&super::table(&MarchStepRow::COLUMNS, &rows, &self.units));
        o
    }
}
