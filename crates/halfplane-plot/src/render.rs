//! A small renderer: panels of named series drawn side by side, to SVG or PNG by file name.

use crate::PlotError;
use image::codecs::png::PngEncoder;
use image::{ColorType, ImageEncoder};
use plotters::coord::Shift;
use plotters::prelude::*;
use std::path::Path;
use std::sync::Once;

/// How a series is drawn.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Style {
    /// Solid line.
    Line,
    /// Dashed line.
    Dashed,
    /// Markers.
    Points,
    /// Disjoint segments: consecutive pairs of points.
    Segments,
}

/// A named data series; `pieces` are drawn separately (gaps between them) under one legend entry.
#[derive(Debug, Clone, PartialEq)]
pub struct Series {
    /// Legend text.
    pub name: String,
    /// Drawing style.
    pub style: Style,
    /// Index into the palette (series that belong together share it).
    pub color: usize,
    /// Continuous pieces of (x, y) points.
    pub pieces: Vec<Vec<(f64, f64)>>,
}

impl Series {
    /// One continuous piece.
    pub fn new(
        name: impl Into<String>,
        style: Style,
        color: usize,
        points: Vec<(f64, f64)>,
    ) -> Self {
        Self {
            name: name.into(),
            style,
            color,
            pieces: vec![points],
        }
    }
}

/// Where a panel's legend goes.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum Legend {
    /// Top right (default).
    #[default]
    UpperRight,
    /// Top left.
    UpperLeft,
    /// Bottom left.
    LowerLeft,
    /// Centre.
    Middle,
}

/// One chart.
#[derive(Debug, Clone, PartialEq)]
pub struct Panel {
    /// Legend placement.
    pub legend: Legend,
    /// Caption.
    pub title: String,
    /// x axis label, with units.
    pub x_label: String,
    /// y axis label, with units.
    pub y_label: String,
    /// The series.
    pub series: Vec<Series>,
}

/// A whole figure: a title and panels side by side.
#[derive(Debug, Clone, PartialEq)]
pub struct Figure {
    /// Title above the panels.
    pub title: String,
    /// Panels, left to right.
    pub panels: Vec<Panel>,
}

const COLORS: [RGBColor; 10] = [
    RGBColor(0, 90, 181),
    RGBColor(220, 50, 32),
    RGBColor(0, 140, 70),
    RGBColor(0, 0, 0),
    RGBColor(150, 70, 170),
    RGBColor(230, 140, 0),
    RGBColor(0, 160, 190),
    RGBColor(120, 120, 120),
    RGBColor(140, 90, 40),
    RGBColor(230, 90, 170),
];

static FONT: Once = Once::new();

/// plotters renders text only with registered fonts; the bundled DejaVu Sans is registered once.
fn register_font() {
    FONT.call_once(|| {
        // The bytes are a valid TrueType font (checked by the tests), so this cannot fail.
        let _ = plotters::style::register_font(
            "sans-serif",
            FontStyle::Normal,
            include_bytes!("../assets/DejaVuSans.ttf"),
        );
    });
}

fn draw_error<E: std::fmt::Debug>(e: E) -> PlotError {
    PlotError::Draw(format!("{e:?}"))
}

/// Writes `figure` to `path`: SVG for `.svg`, PNG for `.png`.
pub fn write(figure: &Figure, path: &Path) -> Result<(), PlotError> {
    let ext = path
        .extension()
        .and_then(|e| e.to_str())
        .map(str::to_ascii_lowercase);
    let width = 640 * figure.panels.len().max(1) as u32;
    let size = (width.min(1920), 520);
    let io_error = |e: std::io::Error| PlotError::Io {
        path: path.display().to_string(),
        message: e.to_string(),
    };
    let format_error = || PlotError::Format {
        path: path.display().to_string(),
    };
    if !matches!(ext.as_deref(), Some("svg" | "png")) {
        return Err(format_error());
    }
    // Fail early, with the path, when the file cannot be created.
    std::fs::File::create(path).map_err(io_error)?;
    register_font();
    // The figure is drawn in memory and written here, so that a failed write (a full disk) is
    // reported: the backends' own file writers drop buffered errors.
    let bytes = match ext.as_deref() {
        Some("svg") => {
            let mut svg = String::new();
            draw(
                figure,
                SVGBackend::with_string(&mut svg, size).into_drawing_area(),
            )?;
            svg.into_bytes()
        }
        Some("png") => {
            let mut rgb = vec![0u8; 3 * size.0 as usize * size.1 as usize];
            draw(
                figure,
                BitMapBackend::with_buffer(&mut rgb, size).into_drawing_area(),
            )?;
            let mut png = Vec::new();
            PngEncoder::new(&mut png)
                .write_image(&rgb, size.0, size.1, ColorType::Rgb8)
                .map_err(draw_error)?;
            png
        }
        _ => return Err(format_error()),
    };
    std::fs::write(path, bytes).map_err(io_error)
}

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

fn draw<DB: DrawingBackend>(figure: &Figure, root: DrawingArea<DB, Shift>) -> Result<(), PlotError>
where
    DB::ErrorType: 'static,
{
    root.fill(&WHITE).map_err(draw_error)?;
    let root = root
        .titled(&figure.title, ("sans-serif", 22))
        .map_err(draw_error)?;
    let areas = root.split_evenly((1, figure.panels.len().max(1)));
    for (area, panel) in areas.iter().zip(&figure.panels) {
        let ((x0, x1), (y0, y1)) = bounds(panel);
        let mut chart = ChartBuilder::on(area)
            .caption(&panel.title, ("sans-serif", 17))
            .margin(12)
            .x_label_area_size(45)
            .y_label_area_size(70)
            .build_cartesian_2d(x0..x1, y0..y1)
            .map_err(draw_error)?;
        chart
            .configure_mesh()
            .x_desc(&panel.x_label)
            .y_desc(&panel.y_label)
            .axis_desc_style(("sans-serif", 15))
            .label_style(("sans-serif", 13))
            .light_line_style(WHITE.mix(0.0))
            .draw()
            .map_err(draw_error)?;
        for s in &panel.series {
            let color = COLORS[s.color % COLORS.len()];
            let stroke = color.stroke_width(2);
            let mut labelled = false;
            for piece in &s.pieces {
                let points = piece.iter().copied();
                let anno = match s.style {
                    Style::Line => chart
                        .draw_series(LineSeries::new(points, stroke))
                        .map_err(draw_error)?,
                    Style::Dashed => chart
                        .draw_series(DashedLineSeries::new(points, 8, 5, stroke))
                        .map_err(draw_error)?,
                    Style::Points => chart
                        .draw_series(points.map(|p| Circle::new(p, 2, color.filled())))
                        .map_err(draw_error)?,
                    Style::Segments => chart
                        .draw_series(
                            piece
                                .chunks_exact(2)
                                .map(|c| PathElement::new(vec![c[0], c[1]], stroke)),
                        )
                        .map_err(draw_error)?,
                };
                if !labelled && !s.name.is_empty() {
                    labelled = true;
                    let style = s.style;
                    anno.label(s.name.as_str())
                        .legend(move |(x, y)| match style {
                            Style::Points => Circle::new((x + 10, y), 3, color.filled()).into_dyn(),
                            _ => PathElement::new(vec![(x, y), (x + 20, y)], stroke).into_dyn(),
                        });
                }
            }
        }
        chart
            .configure_series_labels()
            .label_font(("sans-serif", 13))
            .background_style(WHITE.mix(0.85))
            .border_style(BLACK.mix(0.4))
            .position(match panel.legend {
                Legend::UpperRight => SeriesLabelPosition::UpperRight,
                Legend::UpperLeft => SeriesLabelPosition::UpperLeft,
                Legend::LowerLeft => SeriesLabelPosition::LowerLeft,
                Legend::Middle => SeriesLabelPosition::MiddleMiddle,
            })
            .draw()
            .map_err(draw_error)?;
    }
    root.present().map_err(draw_error)
}
