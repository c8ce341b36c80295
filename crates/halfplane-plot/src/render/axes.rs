//! A panel's axes: data bounds with a margin, tick labels, and the chart frame (caption, mesh and
//! axis labels) shared by legend planning and drawing.

use super::draw_error;
use super::figure::Panel;
use super::font::FAMILY;
use crate::PlotError;
use plotters::coord::types::RangedCoordf64;
use plotters::coord::Shift;
use plotters::prelude::*;

/// Data bounds of a panel with a 5 % margin.
fn bounds(panel: &Panel) -> ((f64, f64), (f64, f64)) {
    let mut x = (f64::INFINITY, f64::NEG_INFINITY);
    let mut y = (f64::INFINITY, f64::NEG_INFINITY);
    for s in &panel.series {
        for &(px, py) in s.pieces.iter().flatten() {
            if px.is_finite() && py.is_finite() {
                x = (x.0.min(px), x.1.max(px));
                y = (y.0.min(py), y.1.max(py));
            }
        }
    }
    let pad = |(lo, hi): (f64, f64)| {
        if !lo.is_finite() {
            return (0.0, 1.0);
        }
        let span = if hi > lo { hi - lo } else { lo.abs().max(1.0) };
        (lo - 0.05 * span, hi + 0.05 * span)
    };
    (pad(x), pad(y))
}

/// Tick labels of an axis from `lo` to `hi`: as many decimals as the tick spacing needs (none for
/// integer ticks: "50", not "50.0"), and never "-0".
fn tick_formatter(lo: f64, hi: f64) -> impl Fn(&f64) -> String {
    let ticks = RangedCoordf64::from(lo..hi).key_points(TICKS);
    let step = ticks
        .windows(2)
        .map(|w| w[1] - w[0])
        .fold(f64::INFINITY, f64::min);
    let decimals = (0..=12)
        .find(|&d| {
            ticks.iter().all(|&t| {
                let shown: f64 = format!("{t:.d$}").parse().unwrap_or(f64::NAN);
                (shown - t).abs() <= 1e-6 * step.clamp(f64::MIN_POSITIVE, 1.0)
            })
        })
        .unwrap_or(6);
    move |v| {
        let s = format!("{v:.decimals$}");
        if s.trim_start_matches('-')
            .chars()
            .all(|c| c == '0' || c == '.')
        {
            s.trim_start_matches('-').to_string()
        } else {
            s.replace('-', "−")
        }
    }
}

/// Number of tick labels asked for on each axis.
const TICKS: usize = 11;

pub(super) type Chart<'a, DB> = ChartContext<'a, DB, Cartesian2d<RangedCoordf64, RangedCoordf64>>;

/// The chart of a panel on `area`, with its axes drawn (the same geometry in planning and drawing).
pub(super) fn chart<'a, DB: DrawingBackend>(
    area: &'a DrawingArea<DB, Shift>,
    panel: &Panel,
) -> Result<Chart<'a, DB>, PlotError>
where
    DB::ErrorType: 'static,
{
    let ((x0, x1), (y0, y1)) = bounds(panel);
    let mut chart = ChartBuilder::on(area)
        .caption(&panel.title, (FAMILY, 17))
        .margin(12)
        .x_label_area_size(45)
        .y_label_area_size(70)
        .build_cartesian_2d(x0..x1, y0..y1)
        .map_err(draw_error)?;
    let (fx, fy) = (tick_formatter(x0, x1), tick_formatter(y0, y1));
    chart
        .configure_mesh()
        .x_labels(TICKS)
        .y_labels(TICKS)
        .x_label_formatter(&fx)
        .y_label_formatter(&fy)
        .x_desc(&panel.x_label)
        .y_desc(&panel.y_label)
        .axis_desc_style((FAMILY, 15))
        .label_style((FAMILY, 13))
        .light_line_style(WHITE.mix(0.0))
        .draw()
        .map_err(draw_error)?;
    Ok(chart)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn ticks_show_the_decimals_their_spacing_needs_and_no_negative_zero() {
        let f = tick_formatter(-5.0, 105.0);
        assert_eq!(f(&50.0), "50");
        assert_eq!(f(&0.0), "0");
        let f = tick_formatter(-1.05, 1.05);
        assert_eq!(f(&-0.0), "0.0");
        assert_eq!(f(&-1e-17), "0.0");
        assert_eq!(f(&-0.5), "−0.5");
        let f = tick_formatter(-0.0007, 0.0014);
        assert_eq!(f(&0.0005), "0.0005");
        assert_eq!(f(&-0.0), "0.0000");
    }
}
