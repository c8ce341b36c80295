//! Legend placement: which entries a panel's legend has and where it goes, a free corner of the
//! plotting area or the strip below the panel.

use super::axes::{aspect_height, chart, plot_pixels, split_bar};
use super::figure::{Figure, Legend, Series, Style};
use super::font::FAMILY;
use super::{draw_error, INSET, LEGEND_FONT, PAD, ROW, SAMPLE};
use crate::PlotError;
use plotters::prelude::*;

/// Where a panel's legend is drawn.
#[derive(Debug, Clone, Copy)]
pub(super) enum Placement {
    /// A framed box with its top-left corner at this backend pixel, of this size.
    Box((i32, i32), (i32, i32)),
    /// In the strip below the panel: rows and columns of entries, each column this wide.
    Below { rows: i32, columns: i32, width: i32 },
}

/// A panel's legend: its entries and where they go.
pub(super) struct LegendPlan<'f> {
    pub(super) entries: Vec<&'f Series>,
    pub(super) place: Placement,
    /// How much taller (or, negative, shorter) the plotting area must be for equal x and y
    /// scales, in pixels (`None`: free aspect).
    pub(super) aspect_change: Option<i32>,
}

/// Decides every panel's legend placement on a throwaway drawing of the same geometry, by mapping
/// the data to pixels and looking for a corner that no line, segment or marker crosses.
pub(super) fn plan(figure: &Figure, size: (u32, u32)) -> Result<Vec<LegendPlan<'_>>, PlotError> {
    let mut scratch = String::new();
    let root = SVGBackend::with_string(&mut scratch, size).into_drawing_area();
    let root = root
        .titled(&figure.title, (FAMILY, 22))
        .map_err(draw_error)?;
    let areas = root.split_evenly((1, figure.panels.len().max(1)));
    let font = TextStyle::from((FAMILY, LEGEND_FONT).into_font());
    let mut plans = Vec::new();
    for (area, panel) in areas.iter().zip(&figure.panels) {
        let entries: Vec<&Series> = panel
            .series
            .iter()
            .filter(|s| !s.name.is_empty() && !matches!(s.style, Style::Annotated))
            .collect();
        let text_width = entries
            .iter()
            .map(|s| {
                area.estimate_text_size(&s.name, &font)
                    .map(|(w, _)| w as i32)
            })
            .collect::<Result<Vec<_>, _>>()
            .map_err(draw_error)?
            .into_iter()
            .max()
            .unwrap_or(0);
        let entry_width = SAMPLE + PAD + text_width;
        let box_size = (entry_width + 2 * PAD, entries.len() as i32 * ROW + 2 * PAD);
        let (plot_area, _) = split_bar(area, panel);
        let (width, height) = plot_pixels(plot_area.dim_in_pixel(), panel)?;
        let aspect_change = aspect_height(panel, width).map(|h| h - height);
        let chart = chart(&plot_area, panel)?;
        let (xr, yr) = chart.plotting_area().get_pixel_range();
        let corner = |c: Legend| -> (i32, i32) {
            let x = match c {
                Legend::UpperLeft | Legend::LowerLeft => xr.start + INSET,
                _ => xr.end - INSET - box_size.0,
            };
            let y = match c {
                Legend::LowerLeft | Legend::LowerRight => yr.end - INSET - box_size.1,
                _ => yr.start + INSET,
            };
            (x, y)
        };
        let free = |at: (i32, i32)| {
            let rect = (
                at.0 as f64 - 3.0,
                at.1 as f64 - 3.0,
                (at.0 + box_size.0) as f64 + 3.0,
                (at.1 + box_size.1) as f64 + 3.0,
            );
            let px = |p: &(f64, f64)| {
                let (x, y) = chart.backend_coord(p);
                (x as f64, y as f64)
            };
            !panel.series.iter().any(|s| {
                s.pieces.iter().any(|piece| {
                    let pts: Vec<(f64, f64)> = piece.iter().map(px).collect();
                    match s.style {
                        Style::Points | Style::Annotated => {
                            pts.iter().any(|&p| crosses(p, p, rect, 4.0))
                        }
                        Style::Polygons(_) => {
                            let (mut x0, mut y0) = (f64::INFINITY, f64::INFINITY);
                            let (mut x1, mut y1) = (f64::NEG_INFINITY, f64::NEG_INFINITY);
                            for p in &pts {
                                (x0, y0, x1, y1) =
                                    (x0.min(p.0), y0.min(p.1), x1.max(p.0), y1.max(p.1));
                            }
                            x0 <= rect.2 && x1 >= rect.0 && y0 <= rect.3 && y1 >= rect.1
                        }
                        Style::Segments | Style::Contour => {
                            pts.chunks_exact(2).any(|c| crosses(c[0], c[1], rect, 2.0))
                        }
                        Style::Filled(_) => pts.chunks_exact(2).any(|c| {
                            let (x0, x1) = (c[0].0.min(c[1].0), c[0].0.max(c[1].0));
                            let (y0, y1) = (c[0].1.min(c[1].1), c[0].1.max(c[1].1));
                            x0 <= rect.2 && x1 >= rect.0 && y0 <= rect.3 && y1 >= rect.1
                        }),
                        Style::Line | Style::Dashed => match pts.len() {
                            1 => crosses(pts[0], pts[0], rect, 2.0),
                            _ => pts.windows(2).any(|w| crosses(w[0], w[1], rect, 2.0)),
                        },
                    }
                })
            })
        };
        let below = || {
            let width = entry_width + 3 * PAD;
            let columns = ((xr.end - xr.start) / width).clamp(1, entries.len().max(1) as i32);
            let rows = (entries.len() as i32 + columns - 1) / columns;
            Placement::Below {
                rows,
                columns,
                width,
            }
        };
        let place = match panel.legend {
            _ if entries.is_empty() => Placement::Below {
                rows: 0,
                columns: 1,
                width: 0,
            },
            Legend::Below => below(),
            Legend::Auto => [
                Legend::UpperRight,
                Legend::UpperLeft,
                Legend::LowerRight,
                Legend::LowerLeft,
            ]
            .into_iter()
            .map(corner)
            .find(|&at| free(at))
            .map_or_else(below, |at| Placement::Box(at, box_size)),
            c => Placement::Box(corner(c), box_size),
        };
        plans.push(LegendPlan {
            entries,
            place,
            aspect_change,
        });
    }
    Ok(plans)
}

/// Whether the segment a-b, widened by `halo` pixels, meets the rectangle (x0, y0, x1, y1).
fn crosses(a: (f64, f64), b: (f64, f64), rect: (f64, f64, f64, f64), halo: f64) -> bool {
    let (x0, y0, x1, y1) = (rect.0 - halo, rect.1 - halo, rect.2 + halo, rect.3 + halo);
    // Liang-Barsky clipping of the segment against the rectangle.
    let (dx, dy) = (b.0 - a.0, b.1 - a.1);
    let (mut t0, mut t1) = (0.0_f64, 1.0_f64);
    for (p, q) in [
        (-dx, a.0 - x0),
        (dx, x1 - a.0),
        (-dy, a.1 - y0),
        (dy, y1 - a.1),
    ] {
        if p == 0.0 {
            if q < 0.0 {
                return false;
            }
        } else {
            let r = q / p;
            if p < 0.0 {
                t0 = t0.max(r);
            } else {
                t1 = t1.min(r);
            }
        }
    }
    t0 <= t1
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn segments_crossing_a_box_are_found() {
        let rect = (10.0, 10.0, 20.0, 20.0);
        assert!(crosses((0.0, 0.0), (30.0, 30.0), rect, 0.0));
        assert!(crosses((15.0, 15.0), (15.0, 15.0), rect, 0.0));
        assert!(!crosses((0.0, 30.0), (8.0, 0.0), rect, 0.0));
        assert!(crosses((0.0, 15.0), (9.0, 15.0), rect, 2.0));
    }
}
