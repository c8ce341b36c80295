//! SVG drawing: the panels' series on their charts, and the legends where they were planned.

use super::axes::chart;
use super::figure::{Figure, Series, Style};
use super::font::FAMILY;
use super::legend::{LegendPlan, Placement};
use super::palette::COLORS;
use super::{draw_error, LEGEND_FONT, PAD, ROW, SAMPLE};
use crate::PlotError;
use plotters::coord::Shift;
use plotters::prelude::*;
use plotters::style::text_anchor::{HPos, Pos, VPos};

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
        Style::Points => root.draw(&Circle::new((x + SAMPLE / 2, y), 3, color.filled())),
        Style::Segments => root.draw(&PathElement::new(
            vec![(x + SAMPLE / 2, y - 6), (x + SAMPLE / 2, y + 6)],
            stroke,
        )),
        Style::Filled((r, g, b)) => root
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
        let mut chart = chart(&top, panel)?;
        for s in &panel.series {
            let color = COLORS[s.color % COLORS.len()];
            let stroke = color.stroke_width(2);
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
                    Style::Segments => chart
                        .draw_series(
                            piece
                                .chunks_exact(2)
                                .map(|c| PathElement::new(vec![c[0], c[1]], stroke)),
                        )
                        .map(|_| ()),
                    Style::Filled((r, g, b)) => chart
                        .draw_series(
                            piece
                                .chunks_exact(2)
                                .map(|c| Rectangle::new([c[0], c[1]], RGBColor(r, g, b).filled())),
                        )
                        .map(|_| ()),
                }
                .map_err(draw_error)?;
            }
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
