//! A panel's axes: data bounds with a margin, tick labels, and the chart frame (caption, mesh and
//! axis labels) shared by legend planning and drawing.

use super::draw_error;
use super::figure::Panel;
use super::font::FAMILY;
use crate::PlotError;
use plotters::coord::types::RangedCoordf64;
use plotters::coord::Shift;
use plotters::prelude::*;

/// Data bounds of a panel: a 5 % margin on each side, or, for a filled map (a panel with a colour
/// bar), the map's extent with only a 3 % margin above, so the surface and what lies on it show.
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
    let (margin, above) = match panel.color_bar {
        Some(_) => ((0.0, 0.0), (0.0, 0.03)),
        None => ((0.05, 0.05), (0.05, 0.05)),
    };
    let pad = |(lo, hi): (f64, f64), (below, above): (f64, f64)| {
        if !lo.is_finite() {
            return (0.0, 1.0);
        }
        let span = if hi > lo { hi - lo } else { lo.abs().max(1.0) };
        (lo - below * span, hi + above * span)
    };
    (pad(x, margin), pad(y, above))
}

/// The bounds widened so that a unit of x and of y have the same length on a plotting area of
/// `pixels` (width, height): x about its centre, y downwards (a map's top is the surface).
fn equal_aspect(
    ((x0, x1), (y0, y1)): ((f64, f64), (f64, f64)),
    (width, height): (i32, i32),
) -> ((f64, f64), (f64, f64)) {
    let (w, h) = (f64::from(width.max(1)), f64::from(height.max(1)));
    let (ux, uy) = ((x1 - x0) / w, (y1 - y0) / h);
    if ux > uy {
        ((x0, x1), (y1 - ux * h, y1))
    } else {
        let half = 0.5 * uy * w;
        let centre = 0.5 * (x0 + x1);
        ((centre - half, centre + half), (y0, y1))
    }
}

/// The plot height in pixels at which the panel's x and y scales are equal, for a plotting area
/// `width` pixels wide (`None` for a panel of free aspect).
pub(super) fn aspect_height(panel: &Panel, width: i32) -> Option<i32> {
    let ((x0, x1), (y0, y1)) = bounds(panel);
    (panel.equal_aspect && x1 > x0)
        .then(|| (f64::from(width) * (y1 - y0) / (x1 - x0)).round() as i32)
}

/// The width of the strip a colour bar takes to the right of its panel, in pixels.
pub(super) const BAR_STRIP: u32 = 120;

/// The panel's area split into the chart's and, when it has a colour bar, the bar's strip.
pub(super) fn split_bar<DB: DrawingBackend>(
    area: &DrawingArea<DB, Shift>,
    panel: &Panel,
) -> (DrawingArea<DB, Shift>, Option<DrawingArea<DB, Shift>>) {
    match panel.color_bar {
        Some(_) => {
            let width = area.dim_in_pixel().0 as i32;
            let (chart, bar) = area.split_horizontally(width - BAR_STRIP as i32);
            (chart, Some(bar))
        }
        None => (area.clone(), None),
    }
}

/// Tick labels of an axis from `lo` to `hi`: as many decimals as the tick spacing needs (none for
/// integer ticks: "50", not "50.0"), never "-0", and scientific notation only for ticks finer
/// than 1e-4 or beyond 1e7.
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
    // Ticks finer than 1e-4 or beyond 1e7 in scientific notation ("1.5e-7"), as crate::number.
    let largest = ticks.iter().fold(0.0_f64, |m, t| m.max(t.abs()));
    let scientific = decimals > 4 || largest >= 1e7;
    move |v| {
        if scientific {
            return crate::number(if v.abs() < 1e-9 * step { 0.0 } else { *v });
        }
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

pub(super) type Chart<'a, DB> = ChartContext<'a, DB, Cartesian2d<Axis, Axis>>;

/// An axis: linear in the values drawn, with plotters' ticks, or (a log panel, whose values are
/// base-10 logarithms) with ticks at the logarithms of 1, 2 and 5 times the powers of ten.
#[derive(Clone)]
pub(super) struct Axis {
    linear: RangedCoordf64,
    log: bool,
}

impl Ranged for Axis {
    type FormatOption = plotters::coord::ranged1d::DefaultFormatting;
    type ValueType = f64;

    fn map(&self, value: &f64, limit: (i32, i32)) -> i32 {
        self.linear.map(value, limit)
    }

    fn key_points<Hint: plotters::coord::ranged1d::KeyPointHint>(&self, hint: Hint) -> Vec<f64> {
        if !self.log {
            return self.linear.key_points(hint);
        }
        if hint.weight().allow_light_points() {
            return Vec::new(); // no light grid between the labelled ticks
        }
        let range = self.linear.range();
        log_ticks(range.start, range.end)
    }

    fn range(&self) -> std::ops::Range<f64> {
        self.linear.range()
    }
}

/// The base-10 logarithms within `[lo, hi]` of 1, 2 and 5 times the powers of ten (only the
/// powers when the range spans more than four decades, every digit when it spans less than one).
fn log_ticks(lo: f64, hi: f64) -> Vec<f64> {
    let span = hi - lo;
    let mantissas: &[f64] = if span > 4.0 {
        &[1.0]
    } else if span < 1.0 {
        &[1.0, 2.0, 3.0, 4.0, 5.0, 6.0, 7.0, 8.0, 9.0]
    } else {
        &[1.0, 2.0, 5.0]
    };
    let mut out = Vec::new();
    for decade in (lo.floor() as i32)..=(hi.ceil() as i32) {
        for m in mantissas {
            let t = m.log10() + f64::from(decade);
            if t >= lo - 1e-12 && t <= hi + 1e-12 {
                out.push(t);
            }
        }
    }
    out
}

/// The label of a log panel's tick `t` (a base-10 logarithm): the value `10^t` written plainly,
/// to the digits the tick has (`0.002`, `50`, `200`).
fn log_label(t: &f64) -> String {
    crate::number((10f64.powf(*t) * 1e9).round() / 1e9 * (1.0 + 0.0))
        .trim_end_matches(".0")
        .to_string()
}

/// The chart frame: caption, margin and the axes' label areas (the same in measuring, planning
/// and drawing).
fn frame<'a, 'b, DB: DrawingBackend>(
    area: &'a DrawingArea<DB, Shift>,
    caption: &'b str,
) -> ChartBuilder<'a, 'b, DB> {
    let mut builder = ChartBuilder::on(area);
    if !caption.is_empty() {
        builder.caption(caption, (FAMILY, 17));
    }
    builder
        .margin(12)
        .x_label_area_size(45)
        .y_label_area_size(70);
    builder
}

/// The size in pixels of the plotting area a panel gets on an area of `size` pixels.
pub(super) fn plot_pixels(size: (u32, u32), panel: &Panel) -> Result<(i32, i32), PlotError> {
    let mut scratch = String::new();
    let root = SVGBackend::with_string(&mut scratch, size).into_drawing_area();
    let chart = frame(&root, &panel.title)
        .build_cartesian_2d(0.0..1.0, 0.0..1.0)
        .map_err(draw_error)?;
    let (xr, yr) = chart.plotting_area().get_pixel_range();
    Ok((xr.end - xr.start, yr.end - yr.start))
}

/// The chart of a panel on `area` (without the colour bar's strip), with its axes drawn (the
/// same geometry in planning and drawing).
pub(super) fn chart<'a, DB: DrawingBackend>(
    area: &'a DrawingArea<DB, Shift>,
    panel: &Panel,
) -> Result<Chart<'a, DB>, PlotError>
where
    DB::ErrorType: 'static,
{
    let mut range = bounds(panel);
    if panel.equal_aspect {
        range = equal_aspect(range, plot_pixels(area.dim_in_pixel(), panel)?);
    }
    let ((x0, x1), (y0, y1)) = range;
    let (log_x, log_y) = (panel.log_axes.x(), panel.log_axes.y());
    let axis = |lo: f64, hi: f64, log: bool| Axis {
        linear: RangedCoordf64::from(lo..hi),
        log,
    };
    let mut chart = frame(area, &panel.title)
        .build_cartesian_2d(axis(x0, x1, log_x), axis(y0, y1, log_y))
        .map_err(draw_error)?;
    let (lx, ly) = (tick_formatter(x0, x1), tick_formatter(y0, y1));
    let fx = |v: &f64| if log_x { log_label(v) } else { lx(v) };
    let fy = |v: &f64| if log_y { log_label(v) } else { ly(v) };
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
        .bold_line_style(BLACK.mix(if panel.color_bar.is_some() { 0.0 } else { 0.2 }))
        .draw()
        .map_err(draw_error)?;
    Ok(chart)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn equal_aspect_widens_the_short_side_only() {
        // 3 by 1 units on 600 by 300 pixels: x needs 200 px per unit, y gets 300; y widens
        // downwards to 1.5 units, keeping its top (the surface).
        let ((x0, x1), (y0, y1)) = equal_aspect(((-1.5, 1.5), (-1.0, 0.0)), (600, 300));
        assert_eq!((x0, x1), (-1.5, 1.5));
        assert!((y0 + 1.5).abs() < 1e-12 && y1 == 0.0);
        // The other way round: x widens about its centre.
        let ((x0, x1), (y0, y1)) = equal_aspect(((0.0, 1.0), (0.0, 1.0)), (600, 300));
        assert!((x0 + 0.5).abs() < 1e-12 && (x1 - 1.5).abs() < 1e-12);
        assert_eq!((y0, y1), (0.0, 1.0));
    }

    #[test]
    fn log_ticks_at_one_two_five_and_plain_labels() {
        // 0.0015 to 0.35: 0.002, 0.005, 0.01, ..., 0.2 (the logarithms), labelled plainly.
        let t = log_ticks(0.0015f64.log10(), 0.35f64.log10());
        let labels: Vec<String> = t.iter().map(log_label).collect();
        assert_eq!(
            labels,
            ["0.002", "0.005", "0.01", "0.02", "0.05", "0.1", "0.2"]
        );
        // Less than a decade: every digit.
        let t = log_ticks(45f64.log10(), 310f64.log10());
        let labels: Vec<String> = t.iter().map(log_label).collect();
        assert_eq!(labels, ["50", "60", "70", "80", "90", "100", "200", "300"]);
    }

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
        // Slip of a fraction of a micrometre: scientific, not 0.00000015.
        let f = tick_formatter(0.0, 4e-7);
        assert_eq!(f(&1.5e-7), "1.5e-7");
        assert_eq!(f(&0.0), "0");
        let f = tick_formatter(0.0, 2e7);
        assert_eq!(f(&1.2e7), "1.2e7");
        let f = tick_formatter(0.0, 15000.0);
        assert_eq!(f(&12000.0), "12000");
    }
}
