//! A small renderer: panels of named series drawn side by side. plotters lays the figure out and
//! writes SVG; a PNG is that SVG rendered by resvg, so both formats show the same text layout.
//! Both use only the bundled DejaVu Sans (no system font library).
//!
//! This module owns the entry points ([`write()`], [`render_svg()`]) and the figure geometry; the
//! rooms below own one concept each: [`figure`] the data model, [`palette`](mod@palette) the
//! colours, [`font`] the bundled font, [`axes`] bounds, ticks and the chart frame, [`legend`] legend
//! placement, [`draw`](mod@draw) the SVG drawing and [`png`] the PNG rendering.

mod axes;
mod draw;
mod figure;
mod font;
mod legend;
mod palette;
mod png;

pub use figure::{ColorBar, Figure, Legend, LogAxes, Panel, Series, Style};
pub use palette::palette;

use crate::PlotError;
use draw::draw;
use font::{register_font, FAMILY, SVG_FAMILY};
use legend::{plan, Placement};
use plotters::prelude::*;
use png::render_png;
use std::path::Path;

/// Width of one panel and height of a figure without a legend strip, in pixels.
const PANEL_WIDTH: u32 = 640;
const HEIGHT: u32 = 520;
/// Width of a panel of equal aspect (a cross-section, wider than deep), in pixels.
const MAP_WIDTH: u32 = 900;
/// The heights an equal-aspect figure may take (beyond, the map is widened instead), in pixels.
const MAP_HEIGHTS: (i32, i32) = (300, 1000);
/// Legend geometry, in pixels.
const LEGEND_FONT: u32 = 13;
const ROW: i32 = 18;
const SAMPLE: i32 = 30;
const PAD: i32 = 6;
const INSET: i32 = 8;

fn draw_error<E: std::fmt::Debug>(e: E) -> PlotError {
    PlotError::Draw(format!("{e:?}"))
}

/// Writes `figure` to `path`: SVG for `.svg`, PNG for `.png`.
pub fn write(figure: &Figure, path: &Path) -> Result<(), PlotError> {
    let ext = path
        .extension()
        .and_then(|e| e.to_str())
        .map(str::to_ascii_lowercase);
    let png = match ext.as_deref() {
        Some("svg") => false,
        Some("png") => true,
        _ => {
            return Err(PlotError::Format {
                path: path.display().to_string(),
            })
        }
    };
    let (svg, size) = render_svg(figure)?;
    let bytes = if png {
        render_png(&svg, size)?
    } else {
        svg.into_bytes()
    };
    std::fs::write(path, bytes).map_err(|e| PlotError::Io {
        path: path.display().to_string(),
        message: e.to_string(),
    })
}

/// The figure as an SVG document, and its size in pixels.
pub fn render_svg(figure: &Figure) -> Result<(String, (u32, u32)), PlotError> {
    register_font();
    let logged = logarithms(figure);
    let figure = logged.as_ref().unwrap_or(figure);
    let panel_width = figure
        .panels
        .iter()
        .map(|p| {
            let base = if p.equal_aspect {
                MAP_WIDTH
            } else {
                PANEL_WIDTH
            };
            base + p.color_bar.as_ref().map_or(0, |_| axes::BAR_STRIP)
        })
        .max()
        .unwrap_or(PANEL_WIDTH);
    let width = (panel_width * figure.panels.len().max(1) as u32).min(1920);
    let mut height = HEIGHT;
    let mut plans = plan(figure, (width, height))?;
    // An equal-aspect map gets the height its shape needs (the legend plan is redone for it).
    if let Some(change) = plans.iter().filter_map(|p| p.aspect_change).max() {
        let wanted = (HEIGHT as i32 + change).clamp(MAP_HEIGHTS.0, MAP_HEIGHTS.1);
        height = wanted as u32;
        plans = plan(figure, (width, height))?;
    }
    let strip = plans
        .iter()
        .filter_map(|p| match p.place {
            Placement::Below { rows, .. } => Some(rows * ROW + 2 * PAD),
            Placement::Box(..) => None,
        })
        .max()
        .unwrap_or(0);
    let size = (width, height + strip as u32);
    let mut svg = String::new();
    {
        let root = SVGBackend::with_string(&mut svg, size).into_drawing_area();
        draw(figure, &plans, strip, root)?;
    }
    let svg = svg.replace(
        &format!("font-family=\"{FAMILY}\""),
        &format!("font-family=\"{SVG_FAMILY}\""),
    );
    Ok((svg, size))
}

/// The figure with the coordinates on its log axes replaced by their base-10 logarithms (values
/// not above zero become NaN, which the bounds and the drawing leave out); `None` without log
/// axes.
fn logarithms(figure: &Figure) -> Option<Figure> {
    if figure.panels.iter().all(|p| p.log_axes == LogAxes::Neither) {
        return None;
    }
    let log = |v: f64| if v > 0.0 { v.log10() } else { f64::NAN };
    let mut out = figure.clone();
    for panel in &mut out.panels {
        let (x, y) = (panel.log_axes.x(), panel.log_axes.y());
        for s in &mut panel.series {
            for p in s.pieces.iter_mut().flatten() {
                if x {
                    p.0 = log(p.0);
                }
                if y {
                    p.1 = log(p.1);
                }
            }
        }
    }
    Some(out)
}
