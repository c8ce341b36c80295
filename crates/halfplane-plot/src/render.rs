//! A small renderer: panels of named series drawn side by side. plotters lays the figure out and
//! writes SVG; a PNG is that SVG rendered by resvg, so both formats show the same text layout.
//! Both use only the bundled DejaVu Sans (no system font library).

use crate::PlotError;
use plotters::coord::types::RangedCoordf64;
use plotters::coord::Shift;
use plotters::prelude::*;
use plotters::style::text_anchor::{HPos, Pos, VPos};
use std::path::Path;
use std::sync::{Arc, Once, OnceLock};

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
    /// Legend text (empty: no legend entry).
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
    /// The first corner of the plotting area (upper right, upper left, lower right, lower left)
    /// that no data crosses; below the panel when every corner has data (default).
    #[default]
    Auto,
    /// Below the panel, outside the plotting area.
    Below,
    /// Top right, whatever is drawn there.
    UpperRight,
    /// Top left, whatever is drawn there.
    UpperLeft,
    /// Bottom right, whatever is drawn there.
    LowerRight,
    /// Bottom left, whatever is drawn there.
    LowerLeft,
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

/// The colour, as RGB, that a series with `color` index draws in (for example to find its strokes
/// in an SVG).
pub fn palette(color: usize) -> (u8, u8, u8) {
    let RGBColor(r, g, b) = COLORS[color % COLORS.len()];
    (r, g, b)
}

/// The bundled font.
const DEJAVU: &[u8] = include_bytes!("../assets/DejaVuSans.ttf");
/// The private name under which plotters knows the bundled font: plotters' font table is
/// process-wide, so a common name such as "sans-serif" would replace an embedding application's.
const FAMILY: &str = "halfplane-dejavu";
/// What the written SVG asks for instead of the private name.
const SVG_FAMILY: &str = "DejaVu Sans, sans-serif";

/// Width of one panel and height of a figure without a legend strip, in pixels.
const PANEL_WIDTH: u32 = 640;
const HEIGHT: u32 = 520;
/// Legend geometry, in pixels.
const LEGEND_FONT: u32 = 13;
const ROW: i32 = 18;
const SAMPLE: i32 = 30;
const PAD: i32 = 6;
const INSET: i32 = 8;

static FONT: Once = Once::new();

/// plotters measures text only with registered fonts; the bundled font is registered once, under
/// a private family name.
fn register_font() {
    FONT.call_once(|| {
        // The bytes are a valid TrueType font (checked by the tests), so this cannot fail.
        let _ = plotters::style::register_font(FAMILY, FontStyle::Normal, DEJAVU);
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
    let width = (PANEL_WIDTH * figure.panels.len().max(1) as u32).min(1920);
    let plan = plan(figure, (width, HEIGHT))?;
    let strip = plan
        .iter()
        .filter_map(|p| match p.place {
            Placement::Below { rows, .. } => Some(rows * ROW + 2 * PAD),
            Placement::Box(..) => None,
        })
        .max()
        .unwrap_or(0);
    let size = (width, HEIGHT + strip as u32);
    let mut svg = String::new();
    {
        let root = SVGBackend::with_string(&mut svg, size).into_drawing_area();
        draw(figure, &plan, strip, root)?;
    }
    let svg = svg.replace(
        &format!("font-family=\"{FAMILY}\""),
        &format!("font-family=\"{SVG_FAMILY}\""),
    );
    Ok((svg, size))
}

/// The SVG rendered to PNG by resvg, with the bundled font only.
fn render_png(svg: &str, (width, height): (u32, u32)) -> Result<Vec<u8>, PlotError> {
    use resvg::{tiny_skia, usvg};
    static FONTS: OnceLock<Arc<usvg::fontdb::Database>> = OnceLock::new();
    let fontdb = FONTS.get_or_init(|| {
        let mut db = usvg::fontdb::Database::new();
        db.load_font_data(DEJAVU.to_vec());
        db.set_sans_serif_family("DejaVu Sans");
        Arc::new(db)
    });
    let options = usvg::Options {
        font_family: "DejaVu Sans".into(),
        fontdb: fontdb.clone(),
        ..Default::default()
    };
    let tree = usvg::Tree::from_str(svg, &options).map_err(draw_error)?;
    let mut pixmap = tiny_skia::Pixmap::new(width, height)
        .ok_or_else(|| PlotError::Draw(format!("cannot make a {width}x{height} image")))?;
    pixmap.fill(tiny_skia::Color::WHITE);
    resvg::render(&tree, tiny_skia::Transform::default(), &mut pixmap.as_mut());
    pixmap.encode_png().map_err(draw_error)
}

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

type Chart<'a, DB> = ChartContext<'a, DB, Cartesian2d<RangedCoordf64, RangedCoordf64>>;

/// The chart of a panel on `area`, with its axes drawn (the same geometry in planning and drawing).
fn chart<'a, DB: DrawingBackend>(
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

/// Where a panel's legend is drawn.
#[derive(Debug, Clone, Copy)]
enum Placement {
    /// A framed box with its top-left corner at this backend pixel, of this size.
    Box((i32, i32), (i32, i32)),
    /// In the strip below the panel: rows and columns of entries, each column this wide.
    Below { rows: i32, columns: i32, width: i32 },
}

/// A panel's legend: its entries and where they go.
struct LegendPlan<'f> {
    entries: Vec<&'f Series>,
    place: Placement,
}

/// Decides every panel's legend placement on a throwaway drawing of the same geometry, by mapping
/// the data to pixels and looking for a corner that no line, segment or marker crosses.
fn plan(figure: &Figure, size: (u32, u32)) -> Result<Vec<LegendPlan<'_>>, PlotError> {
    let mut scratch = String::new();
    let root = SVGBackend::with_string(&mut scratch, size).into_drawing_area();
    let root = root
        .titled(&figure.title, (FAMILY, 22))
        .map_err(draw_error)?;
    let areas = root.split_evenly((1, figure.panels.len().max(1)));
    let font = TextStyle::from((FAMILY, LEGEND_FONT).into_font());
    let mut plans = Vec::new();
    for (area, panel) in areas.iter().zip(&figure.panels) {
        let entries: Vec<&Series> = panel.series.iter().filter(|s| !s.name.is_empty()).collect();
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
        let chart = chart(area, panel)?;
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
                        Style::Points => pts.iter().any(|&p| crosses(p, p, rect, 4.0)),
                        Style::Segments => {
                            pts.chunks_exact(2).any(|c| crosses(c[0], c[1], rect, 2.0))
                        }
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
        plans.push(LegendPlan { entries, place });
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
    }
    .map_err(draw_error)
}

fn draw<DB: DrawingBackend>(
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

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_font_is_registered_under_a_private_name_only() {
        let figure = Figure {
            title: "t".into(),
            panels: vec![],
        };
        render_svg(&figure).unwrap();
        let ours = TextStyle::from((FAMILY, 12).into_font());
        assert!(ours.font.box_size("0.5").is_ok(), "bundled font usable");
        // An application's "sans-serif" (here: none registered) is left alone.
        let theirs = TextStyle::from(("sans-serif", 12).into_font());
        assert!(theirs.font.box_size("0.5").is_err());
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
    }

    #[test]
    fn segments_crossing_a_box_are_found() {
        let rect = (10.0, 10.0, 20.0, 20.0);
        assert!(crosses((0.0, 0.0), (30.0, 30.0), rect, 0.0));
        assert!(crosses((15.0, 15.0), (15.0, 15.0), rect, 0.0));
        assert!(!crosses((0.0, 30.0), (8.0, 0.0), rect, 0.0));
        assert!(crosses((0.0, 15.0), (9.0, 15.0), rect, 2.0));
    }

    #[test]
    fn the_png_is_the_svg_rendered_with_text_and_data() {
        let figure = Figure {
            title: "Title 0.5".into(),
            panels: vec![Panel {
                legend: Legend::Auto,
                title: "panel".into(),
                x_label: "x".into(),
                y_label: "y".into(),
                series: vec![Series::new(
                    "line",
                    Style::Line,
                    1,
                    vec![(0.0, 0.0), (1.0, 1.0)],
                )],
            }],
        };
        let (svg, size) = render_svg(&figure).unwrap();
        let png = render_png(&svg, size).unwrap();
        let image = resvg::tiny_skia::Pixmap::decode_png(&png).unwrap();
        assert_eq!((image.width(), image.height()), size);
        let (r, g, b) = palette(1);
        let red = image
            .pixels()
            .iter()
            .filter(|p| (p.red(), p.green(), p.blue()) == (r, g, b))
            .count();
        assert!(red > 100, "the data line is drawn: {red} pixels");
        // The title's text is rendered: dark pixels in the top band.
        let dark_top = image.pixels()[..(size.0 * 25) as usize]
            .iter()
            .filter(|p| p.red() < 100)
            .count();
        assert!(dark_top > 50, "title text rendered: {dark_top} dark pixels");
    }
}
