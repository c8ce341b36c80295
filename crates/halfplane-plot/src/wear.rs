//! The wear figure ([`halfplane::wear`]): the wear depth and the pressure along x at the
//! checkpoints of a run, one curve per checkpoint, beside a checkpoint quantity against cycles.

use crate::format::number;
use crate::{Figure, Legend, LogAxes, Panel, PlotError, Series, Style, Units};
use halfplane::wear::{Checkpoint, WearResult};

/// The palette colours of the checkpoints' curves, in order: all but black, which marks the
/// stick zone.
const CHECKPOINT_COLORS: [usize; 9] = [0, 1, 2, 4, 5, 6, 8, 9, 7];

/// The most checkpoints whose depth and pressure are drawn (one colour each); of more, this many
/// spread evenly over the run, the first and the last among them.
pub const MAX_PROFILES: usize = CHECKPOINT_COLORS.len();

/// The palette colour of the stick zone's ends (black).
const STICK_COLOR: usize = 3;

/// The fraction of the worn region's width shown on either side of it.
const X_MARGIN: f64 = 0.1;

/// A quantity of every checkpoint, as the caller names and computes it, drawn against cycles.
#[derive(Debug, Clone, PartialEq)]
pub struct CheckpointQuantity {
    /// Its name, as the axis shows it (for example the report's column, `max_depth`).
    pub name: String,
    /// Its unit (empty for a pure number).
    pub unit: String,
    /// Its value at each checkpoint, in order; `None` where it has none (the stick zone's ends
    /// in gross sliding).
    pub values: Vec<Option<f64>>,
}

/// The wear figure of a run: the depth worn from both bodies and the pressure at the end of the
/// cycle along x at each checkpoint (at most [`MAX_PROFILES`]; x over the cells that are in
/// contact or worn at any of them, with a margin), the permanent stick zone of the last
/// checkpoint marked on the pressure, `quantity` against cycles on a logarithmic axis (its
/// values too when all are positive and they span more than a factor of 100, as wear volume
/// and depth do over decades of cycles), and the fretting loops of the checkpoints drawn (Q
/// against the bodies' relative displacement from the datum `loop_datum`).
///
/// # Errors
/// [`PlotError::Request`] when the run has no checkpoint, or `quantity` has not one value per
/// checkpoint or no finite value at all.
pub fn wear_figure(
    result: &WearResult,
    quantity: &CheckpointQuantity,
    loop_datum: f64,
    units: &Units,
) -> Result<Figure, PlotError> {
    let checkpoints = &result.checkpoints;
    let Some(last) = checkpoints.last() else {
        return Err(PlotError::Request(
            "the wear run has no checkpoint to draw".into(),
        ));
    };
    let shown = drawn(checkpoints.len());
    let cells = shown_cells(shown.iter().map(|&i| &checkpoints[i]));
    let along = |v: &[f64]| -> Vec<(f64, f64)> {
        cells
            .clone()
            .map(|i| (last.fields.x[i], v[i]))
            .collect::<Vec<_>>()
    };
    let (mut depth, mut pressure, mut loops) = (Vec::new(), Vec::new(), Vec::new());
    // The stick zone first, so that the pressure's peaks at its ends are drawn over it.
    if let Some([left, right]) = last.stick {
        let top = checkpoints
            .iter()
            .flat_map(|c| c.fields.pressure.iter().copied())
            .fold(0.0, f64::max);
        let span = if left == -right {
            format!("|x| ≤ {}", number(right))
        } else {
            format!("{} ≤ x ≤ {}", number(left), number(right))
        };
        pressure.push(Series {
            name: format!("stick zone {span} {} (cycle {})", units.length, last.cycle),
            style: Style::Dashed,
            color: STICK_COLOR,
            pieces: vec![
                vec![(left, 0.0), (left, top)],
                vec![(right, 0.0), (right, top)],
            ],
        });
    }
    // One legend for both panels, the depth's: the curves of a checkpoint share their colour.
    for (&i, &color) in shown.iter().zip(CHECKPOINT_COLORS.iter()) {
        let c = &checkpoints[i];
        depth.push(Series::new(
            format!("cycle {}", c.cycle),
            Style::Line,
            color,
            along(&c.fields.depth),
        ));
        pressure.push(Series::new(
            "",
            Style::Line,
            color,
            along(&c.fields.pressure),
        ));
        let points = c.fretting_loop.iter();
        loops.push(Series::new(
            "",
            Style::Line,
            color,
            points.map(|p| (p.relative_displacement, p.shear)).collect(),
        ));
    }
    let drawn_of = match shown.len() < checkpoints.len() {
        true => format!(" ({} of {} checkpoints)", shown.len(), checkpoints.len()),
        false => String::new(),
    };
    let x_label = format!("position x ({})", units.length);
    let mut depth_panel = Panel::new(
        format!("wear depth, both bodies{drawn_of}"),
        x_label.clone(),
        format!("depth h ({})", units.length),
        depth,
    );
    depth_panel.legend = Legend::Below;
    let mut pressure_panel = Panel::new(
        format!("pressure at the end of the cycle, colours as the depth's{drawn_of}"),
        x_label,
        format!("pressure p ({})", units.stress),
        pressure,
    );
    pressure_panel.legend = Legend::Below;
    let loop_panel = Panel::new(
        format!("fretting loops, colours as the depth's{drawn_of}"),
        format!(
            "relative displacement δ ({}), datum {} {}",
            units.length,
            number(loop_datum),
            units.length
        ),
        format!("shear load Q ({})", units.force_per_length),
        loops,
    );
    Ok(Figure {
        title: format!(
            "Fretting wear over {} cycles ({} marched, the others jumped)",
            last.cycle, result.simulated_cycles
        ),
        panels: vec![
            depth_panel,
            pressure_panel,
            quantity_panel(checkpoints, quantity)?,
            loop_panel,
        ],
    })
}

/// The indices of the checkpoints drawn, of `n`: all of them up to [`MAX_PROFILES`], else that
/// many spread evenly, the first and the last among them.
fn drawn(n: usize) -> Vec<usize> {
    if n <= MAX_PROFILES {
        return (0..n).collect();
    }
    (0..MAX_PROFILES)
        .map(|k| ((k * (n - 1)) as f64 / (MAX_PROFILES - 1) as f64).round() as usize)
        .collect()
}

/// The cells drawn along x: those in contact or worn at any of `checkpoints`, widened by
/// [`X_MARGIN`] of their width on either side (the whole grid when none is).
fn shown_cells<'a>(
    checkpoints: impl Iterator<Item = &'a Checkpoint> + Clone,
) -> std::ops::Range<usize> {
    let Some(first) = checkpoints.clone().next() else {
        return 0..0;
    };
    let x = &first.fields.x;
    let active = |i: usize| {
        checkpoints
            .clone()
            .any(|c| c.fields.pressure[i] > 0.0 || c.fields.depth[i] > 0.0)
    };
    let (Some(lo), Some(hi)) = (
        (0..x.len()).find(|&i| active(i)),
        (0..x.len()).rfind(|&i| active(i)),
    ) else {
        return 0..x.len();
    };
    let margin = X_MARGIN * (x[hi] - x[lo]);
    let start = x.partition_point(|&v| v < x[lo] - margin);
    let end = x.partition_point(|&v| v <= x[hi] + margin);
    start..end
}

/// `quantity` against cycles: x logarithmic, y too when every value is positive and they span
/// more than a factor of 100.
fn quantity_panel(
    checkpoints: &[Checkpoint],
    quantity: &CheckpointQuantity,
) -> Result<Panel, PlotError> {
    let name = &quantity.name;
    if quantity.values.len() != checkpoints.len() {
        return Err(PlotError::Request(format!(
            "{name}: {} values for {} checkpoints",
            quantity.values.len(),
            checkpoints.len()
        )));
    }
    let points: Vec<(f64, f64)> = checkpoints
        .iter()
        .zip(&quantity.values)
        .filter_map(|(c, v)| v.filter(|v| v.is_finite()).map(|v| (c.cycle as f64, v)))
        .collect();
    if points.is_empty() {
        return Err(PlotError::Request(format!(
            "{name} has no value at any checkpoint"
        )));
    }
    let (lo, hi) = points
        .iter()
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), p| {
            (lo.min(p.1), hi.max(p.1))
        });
    let y_label = match quantity.unit.as_str() {
        "" => name.clone(),
        unit => format!("{name} ({unit})"),
    };
    let mut panel = Panel::new(
        format!("{name} at the checkpoints"),
        "cycle",
        y_label,
        vec![
            Series::new("", Style::Line, 0, points.clone()),
            Series::new("", Style::Points, 0, points),
        ],
    );
    panel.log_axes = match lo > 0.0 && hi > 100.0 * lo {
        true => LogAxes::Both,
        false => LogAxes::X,
    };
    Ok(panel)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn at_most_max_profiles_are_drawn_first_and_last_among_them() {
        assert_eq!(drawn(3), [0, 1, 2]);
        let d = drawn(25);
        assert_eq!(d.len(), MAX_PROFILES);
        assert_eq!((d[0], d[MAX_PROFILES - 1]), (0, 24));
        assert!(d.windows(2).all(|w| w[0] < w[1]));
    }
}
