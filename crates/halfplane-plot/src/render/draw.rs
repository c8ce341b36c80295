//! SVG drawing: the panels' series on their charts, and the legends where they were planned.

use super::axes::{chart, split_bar, Chart};
use super::figure::ColorBar;
use super::figure::{Figure, Series, Style};
use super::font::FAMILY;
use super::legend::{LegendPlan, Placement};
use super::palette::COLORS;
use super::{draw_error, LEGEND_FONT, PAD, ROW, SAMPLE};
use crate::PlotError;
use plotters::coord::Shift;
use plotters::prelude::*;
use plotters::style::text_anchor::{HPos, Pos, VPos};
use plotters::style::FontTransform;

/// The colour of contour lines over filled bands: black, partly transparent.
const CONTOUR: RGBAColor = RGBAColor(0, 0, 0, 0.45);
/// Width of the colour bar itself and its gap from the strip's left edge, in pixels.
const BAR: (i32, i32) = (18, 10);

/// The legend sample of a series at (x, y) (left end, vertical centre), `SAMPLE` pixels wide: a
/// line solid or dashed as the series is, a marker, or a vertical bar for segments.
fn sample<DB: DrawingBackend>(
    root: &DrawingArea<DB, Shift>,
    s: &Series,
    (x, y): (i32, i32),
) -> Result<(), PlotError>
where
    DB::ErrorType: 'static,
{
    let color = COLORS[s.color % COLORS.len()];
    let stroke = color.stroke_width(2);
    match s.style {
        Style::Line => root.draw(&PathElement::new(vec![(x, y), (x + SAMPLE, y)], stroke)),
        Style::Dashed => [(0, 8), (13, 21), (26, SAMPLE)]
            .into_iter()
            .try_for_each(|(a, b)| {
                root.draw(&PathElement::new(vec![(x + a, y), (x + b, y)], stroke))
            }),
        Style::Points | Style::Annotated => {
            root.draw(&Circle::new((x + SAMPLE / 2, y), 3, color.filled()))
        }
        Style::Contour => root.draw(&PathElement::new(
            vec![(x, y), (x + SAMPLE, y)],
            CONTOUR.stroke_width(1),
        )),
        Style::Segments => root.draw(&PathElement::new(
            vec![(x + SAMPLE / 2, y - 6), (x + SAMPLE / 2, y + 6)],
            stroke,
        )),
        Style::Filled((r, g, b)) | Style::Polygons((r, g, b)) => root
            .draw(&Rectangle::new(
                [(x + 4, y - 6), (x + SAMPLE - 4, y + 6)],
                RGBColor(r, g, b).filled(),
            ))
            .and_then(|()| {
                root.draw(&Rectangle::new(
                    [(x + 4, y - 6), (x + SAMPLE - 4, y + 6)],
                    BLACK.mix(0.4).stroke_width(1),
                ))
            }),
    }
    .map_err(draw_error)
}

pub(super) fn draw<DB: DrawingBackend>(
    figure: &Figure,
    plans: &[LegendPlan<'_>],
    strip: i32,
    root: DrawingArea<DB, Shift>,
) -> Result<(), PlotError>
where
    DB::ErrorType: 'static,
{
    root.fill(&WHITE).map_err(draw_error)?;
    let titled = root
        .titled(&figure.title, (FAMILY, 22))
        .map_err(draw_error)?;
    let areas = titled.split_evenly((1, figure.panels.len().max(1)));
    let text = TextStyle::from((FAMILY, LEGEND_FONT).into_font())
        .color(&BLACK)
        .pos(Pos::new(HPos::Left, VPos::Center));
    for ((area, panel), plan) in areas.iter().zip(&figure.panels).zip(plans) {
        let (top, strip_area) = area.split_vertically(area.dim_in_pixel().1 as i32 - strip);
        let (plot_area, bar_area) = split_bar(&top, panel);
        let mut chart = chart(&plot_area, panel)?;
        // Filled bands first, then lines and markers over them, annotations last.
        let order = |s: &&Series| match s.style {
            Style::Polygons(_) | Style::Filled(_) => 0,
            Style::Annotated => 2,
            _ => 1,
        };
        let mut series: Vec<&Series> = panel.series.iter().collect();
        series.sort_by_key(order);
        // The annotation labels drawn so far, so the next goes where none is.
        let mut placed = Vec::new();
        for s in series {
            if s.style == Style::Annotated {
                annotate(&root, &chart, s, &mut placed)?;
                continue;
            }
            series_on(&mut chart, s)?;
        }
        if let (Some(bar), Some(strip)) = (&panel.color_bar, &bar_area) {
            let (_, yr) = chart.plotting_area().get_pixel_range();
            color_bar(&root, strip, (yr.start, yr.end), bar)?;
        }
        // The legend is drawn in backend pixels on the whole canvas.
        let entry = |s: &Series, (x, y): (i32, i32)| -> Result<(), PlotError> {
            sample(&root, s, (x, y))?;
            root.draw(&Text::new(s.name.as_str(), (x + SAMPLE + PAD, y), &text))
                .map_err(draw_error)
        };
        match plan.place {
            Placement::Box((x, y), (w, h)) => {
                root.draw(&Rectangle::new(
                    [(x, y), (x + w, y + h)],
                    WHITE.mix(0.9).filled(),
                ))
                .map_err(draw_error)?;
                root.draw(&Rectangle::new(
                    [(x, y), (x + w, y + h)],
                    BLACK.mix(0.4).stroke_width(1),
                ))
                .map_err(draw_error)?;
                for (i, s) in plan.entries.iter().enumerate() {
                    entry(s, (x + PAD, y + PAD + ROW / 2 + i as i32 * ROW))?;
                }
            }
            Placement::Below { columns, width, .. } => {
                let (base_x, base_y) = strip_area.get_base_pixel();
                let (xr, _) = chart.plotting_area().get_pixel_range();
                let x0 = xr.start.max(base_x);
                for (i, s) in plan.entries.iter().enumerate() {
                    let (row, col) = (i as i32 / columns, i as i32 % columns);
                    entry(s, (x0 + col * width, base_y + PAD + ROW / 2 + row * ROW))?;
                }
            }
        }
    }
    root.present().map_err(draw_error)
}

/// One series (not an annotation) on the chart, in its style.
fn series_on<DB: DrawingBackend>(chart: &mut Chart<'_, DB>, s: &Series) -> Result<(), PlotError>
where
    DB::ErrorType: 'static,
{
    let color = COLORS[s.color % COLORS.len()];
    let stroke = color.stroke_width(2);
    if let Style::Polygons((r, g, b)) = s.style {
        // Each polygon filled and outlined in its colour, so that no hairline of the
        // background shows where neighbouring polygons meet once anti-aliased.
        let rgb = RGBColor(r, g, b);
        chart
            .draw_series(
                s.pieces
                    .iter()
                    .filter(|p| p.len() >= 3)
                    .map(|p| Polygon::new(p.clone(), rgb.filled())),
            )
            .map_err(draw_error)?;
        chart
            .draw_series(s.pieces.iter().filter(|p| p.len() >= 3).map(|p| {
                let mut ring = p.clone();
                ring.push(p[0]);
                PathElement::new(ring, rgb.stroke_width(1))
            }))
            .map_err(draw_error)?;
        return Ok(());
    }
    for piece in &s.pieces {
        let points = piece.iter().copied();
        match s.style {
            Style::Line => chart
                .draw_series(LineSeries::new(points, stroke))
                .map(|_| ()),
            Style::Dashed => chart
                .draw_series(DashedLineSeries::new(points, 8, 5, stroke))
                .map(|_| ()),
            Style::Points => chart
                .draw_series(points.map(|p| Circle::new(p, 3, color.filled())))
                .map(|_| ()),
            Style::Segments | Style::Contour => {
                let line = if s.style == Style::Contour {
                    CONTOUR.stroke_width(1)
                } else {
                    stroke
                };
                chart
                    .draw_series(
                        piece
                            .chunks_exact(2)
                            .map(|c| PathElement::new(vec![c[0], c[1]], line)),
                    )
                    .map(|_| ())
            }
            Style::Filled((r, g, b)) => chart
                .draw_series(
                    piece
                        .chunks_exact(2)
                        .map(|c| Rectangle::new([c[0], c[1]], RGBColor(r, g, b).filled())),
                )
                .map(|_| ()),
            Style::Polygons(_) | Style::Annotated => Ok(()),
        }
        .map_err(draw_error)?;
    }
    Ok(())
}

/// The series' markers, each with its name written near it on a white ground (so it reads over a
/// filled map) and joined to it by a thin line: below and to the right, or on another side or
/// further away where that has no room or an earlier label (`placed`) is there, so that the
/// neighbourhood of the marker stays visible. A marker outside the plotting area is not drawn.
fn annotate<DB: DrawingBackend>(
    root: &DrawingArea<DB, Shift>,
    chart: &Chart<'_, DB>,
    s: &Series,
    placed: &mut Vec<(i32, i32, i32, i32)>,
) -> Result<(), PlotError>
where
    DB::ErrorType: 'static,
{
    const OFFSET: (i32, i32) = (28, 22);
    let (xr, yr) = chart.plotting_area().get_pixel_range();
    let color = COLORS[s.color % COLORS.len()];
    let font = TextStyle::from((FAMILY, LEGEND_FONT).into_font()).color(&BLACK);
    let (w, h) = root
        .estimate_text_size(&s.name, &font)
        .map_err(draw_error)?;
    let (w, h) = (w as i32, h as i32);
    for p in s.pieces.iter().flatten() {
        let (px, py) = chart.backend_coord(p);
        if px < xr.start || px > xr.end || py < yr.start || py > yr.end {
            continue;
        }
        // Candidate places, nearest first: below or above, right or left, stepping away from
        // the marker; the first inside the plotting area that no earlier label covers.
        let fits = |(x, y): (i32, i32)| {
            x >= xr.start + PAD
                && x + w + PAD <= xr.end
                && y >= yr.start + PAD
                && y + h + PAD <= yr.end
                && !placed.iter().any(|&(x0, y0, x1, y1)| {
                    x - 3 <= x1 && x + w + 3 >= x0 && y - 2 <= y1 && y + h + 2 >= y0
                })
        };
        let candidates = (0..4).flat_map(|k| {
            let dy = OFFSET.1 + k * (h + 8);
            [
                (px + OFFSET.0, py + dy),
                (px - OFFSET.0 - w, py + dy),
                (px + OFFSET.0, py - dy - h),
                (px - OFFSET.0 - w, py - dy - h),
            ]
        });
        let (x, y) = candidates
            .clone()
            .find(|&c| fits(c))
            .unwrap_or((px + OFFSET.0, py + OFFSET.1));
        placed.push((x - 3, y - 2, x + w + 3, y + h + 2));
        let (ax, ay) = (
            if x > px { x - 3 } else { x + w + 3 },
            if y > py { y - 2 } else { y + h + 2 },
        );
        root.draw(&PathElement::new(
            vec![(px, py), (ax, ay)],
            BLACK.stroke_width(1),
        ))
        .map_err(draw_error)?;
        root.draw(&Rectangle::new(
            [(x - 3, y - 2), (x + w + 3, y + h + 2)],
            WHITE.mix(0.85).filled(),
        ))
        .map_err(draw_error)?;
        root.draw(&Rectangle::new(
            [(x - 3, y - 2), (x + w + 3, y + h + 2)],
            BLACK.mix(0.4).stroke_width(1),
        ))
        .map_err(draw_error)?;
        root.draw(&Text::new(
            s.name.as_str(),
            (x, y),
            font.pos(Pos::new(HPos::Left, VPos::Top)),
        ))
        .map_err(draw_error)?;
        root.draw(&Circle::new((px, py), 5, WHITE.filled()))
            .map_err(draw_error)?;
        root.draw(&Circle::new((px, py), 4, color.filled()))
            .map_err(draw_error)?;
    }
    Ok(())
}

/// A vertical colour bar in `strip`, spanning the plotting area's height `(top, bottom)` in
/// backend pixels: one rectangle per band from the first bound (bottom) to the last (top), the
/// labelled levels beside it (a label too close to the one below is left out) and the bar's label
/// along its right edge.
fn color_bar<DB: DrawingBackend>(
    root: &DrawingArea<DB, Shift>,
    strip: &DrawingArea<DB, Shift>,
    (top, bottom): (i32, i32),
    bar: &ColorBar,
) -> Result<(), PlotError>
where
    DB::ErrorType: 'static,
{
    let (lo, hi) = match (bar.bounds.first(), bar.bounds.last()) {
        (Some(&lo), Some(&hi)) if hi > lo => (lo, hi),
        _ => return Ok(()),
    };
    let (base_x, _) = strip.get_base_pixel();
    let (x0, x1) = (base_x + BAR.1, base_x + BAR.1 + BAR.0);
    let y = |v: f64| bottom - ((v - lo) / (hi - lo) * f64::from(bottom - top)).round() as i32;
    for (w, &(r, g, b)) in bar.bounds.windows(2).zip(&bar.colors) {
        root.draw(&Rectangle::new(
            [(x0, y(w[1])), (x1, y(w[0]))],
            RGBColor(r, g, b).filled(),
        ))
        .map_err(draw_error)?;
    }
    root.draw(&Rectangle::new(
        [(x0, top), (x1, bottom)],
        BLACK.stroke_width(1),
    ))
    .map_err(draw_error)?;
    let text = TextStyle::from((FAMILY, LEGEND_FONT).into_font())
        .color(&BLACK)
        .pos(Pos::new(HPos::Left, VPos::Center));
    let mut last: Option<i32> = None;
    let mut widest = 0;
    for (v, label) in &bar.ticks {
        if !(lo..=hi).contains(v) {
            continue;
        }
        let at = y(*v);
        root.draw(&PathElement::new(
            vec![(x1 - 4, at), (x1 + 4, at)],
            BLACK.stroke_width(1),
        ))
        .map_err(draw_error)?;
        if last.is_some_and(|l| (l - at).abs() < ROW - 4) {
            continue;
        }
        root.draw(&Text::new(label.as_str(), (x1 + 7, at), &text))
            .map_err(draw_error)?;
        let (w, _) = root.estimate_text_size(label, &text).map_err(draw_error)?;
        widest = widest.max(w as i32);
        last = Some(at);
    }
    let label = TextStyle::from((FAMILY, 15).into_font())
        .color(&BLACK)
        .transform(FontTransform::Rotate270)
        .pos(Pos::new(HPos::Center, VPos::Bottom));
    let right = (x1 + 7 + widest + 8 + 18).min(base_x + strip.dim_in_pixel().0 as i32 - 4);
    root.draw(&Text::new(
        bar.label.as_str(),
        (right, (top + bottom) / 2),
        &label,
    ))
    .map_err(draw_error)
}
