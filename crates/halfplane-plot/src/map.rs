//! Design maps: a sweep's rows drawn over two of its varied inputs, coloured by a regime (one
//! colour per category) or by a number (filled contours with a colour bar).
//!
//! A regime map on a full grid over (x, y) is drawn as cells around each point (cell edges
//! half-way between neighbouring values): a category is not interpolated. A numeric map on a
//! full grid is drawn as filled contours between the points ([`crate::filled_contours`]: bands
//! interpolated within each cell, so no staircase at cell edges) with the contour lines on top;
//! rows without a value are grey cells. Scattered rows (a random or Latin-hypercube sweep) are
//! drawn as small squares in their band's colour, without contours.

use crate::shading::{filled_map, Shading};
use crate::{ColorBar, Figure, Legend, LogAxes, Panel, PlotError, Series, Style};

/// The colour of each row: a category (a regime name) or a number (absent where the row has no
/// value: gross sliding, or a failed case).
#[derive(Debug, Clone, PartialEq)]
pub enum MapColor {
    /// One name per row (an empty name is drawn as "error").
    Category(Vec<String>),
    /// One number per row.
    Numeric(Vec<Option<f64>>),
}

/// The data of a design map.
#[derive(Debug, Clone, PartialEq)]
pub struct DesignMap {
    /// The x axis label: what the varied path is, with its unit.
    pub x_label: String,
    /// The y axis label.
    pub y_label: String,
    /// What the colour shows, with its unit (the figure's title and the colour bar's label).
    pub color_label: String,
    /// (x, y) of each row.
    pub points: Vec<(f64, f64)>,
    /// The colour of each row.
    pub color: MapColor,
}

/// Colours of the regimes the library names, and of anything else.
const CATEGORY_COLORS: [(&str, (u8, u8, u8)); 4] = [
    ("full-stick", (0, 140, 70)),
    ("partial-slip", (86, 150, 220)),
    ("gross-sliding", (220, 50, 32)),
    ("error", (150, 150, 150)),
];
const OTHER_COLORS: [(u8, u8, u8); 4] =
    [(230, 140, 0), (150, 70, 170), (0, 160, 190), (140, 90, 40)];
/// Cells without a value in a numeric map.
const NO_VALUE: (u8, u8, u8) = (215, 215, 215);

/// The sorted distinct values of `v`.
fn distinct(v: impl Iterator<Item = f64>) -> Vec<f64> {
    let mut d: Vec<f64> = v.collect();
    d.sort_by(f64::total_cmp);
    d.dedup();
    d
}

/// Cell edges around sorted values: half-way between neighbours, and half a spacing beyond
/// the ends (a single value gets a unit-free width of 1% of its magnitude, or 1).
fn edges(values: &[f64]) -> Vec<f64> {
    let n = values.len();
    if n == 1 {
        let h = 0.01 * values[0].abs().max(1.0);
        return vec![values[0] - h, values[0] + h];
    }
    let mut e = Vec::with_capacity(n + 1);
    e.push(values[0] - 0.5 * (values[1] - values[0]));
    e.extend(values.windows(2).map(|w| 0.5 * (w[0] + w[1])));
    e.push(values[n - 1] + 0.5 * (values[n - 1] - values[n - 2]));
    e
}

/// A full grid: the distinct x and y values and, for each (iy, ix), the row there.
struct Grid {
    xs: Vec<f64>,
    ys: Vec<f64>,
    row: Vec<usize>,
}

fn grid(points: &[(f64, f64)]) -> Option<Grid> {
    let xs = distinct(points.iter().map(|p| p.0));
    let ys = distinct(points.iter().map(|p| p.1));
    if xs.len().checked_mul(ys.len())? != points.len() {
        return None;
    }
    let mut row = vec![usize::MAX; points.len()];
    for (i, &(x, y)) in points.iter().enumerate() {
        let ix = xs.binary_search_by(|v| v.total_cmp(&x)).ok()?;
        let iy = ys.binary_search_by(|v| v.total_cmp(&y)).ok()?;
        let slot = &mut row[iy * xs.len() + ix];
        if *slot != usize::MAX {
            return None;
        }
        *slot = i;
    }
    Some(Grid { xs, ys, row })
}

/// The cell rectangle (opposite corners) of each row, and whether the rows form a grid.
fn cells(points: &[(f64, f64)]) -> (Vec<[(f64, f64); 2]>, Option<Grid>) {
    if let Some(g) = grid(points) {
        let (ex, ey) = (edges(&g.xs), edges(&g.ys));
        let mut rect = vec![[(0.0, 0.0); 2]; points.len()];
        for iy in 0..g.ys.len() {
            for ix in 0..g.xs.len() {
                rect[g.row[iy * g.xs.len() + ix]] = [(ex[ix], ey[iy]), (ex[ix + 1], ey[iy + 1])];
            }
        }
        return (rect, Some(g));
    }
    // Scattered rows: squares of 1/100 of each axis's span.
    let span = |v: Vec<f64>| match (v.first(), v.last()) {
        (Some(a), Some(b)) if b > a => 0.005 * (b - a),
        (Some(a), _) => 0.005 * a.abs().max(1.0),
        _ => 1.0,
    };
    let hx = span(distinct(points.iter().map(|p| p.0)));
    let hy = span(distinct(points.iter().map(|p| p.1)));
    let rect = points
        .iter()
        .map(|&(x, y)| [(x - hx, y - hy), (x + hx, y + hy)])
        .collect();
    (rect, None)
}

fn filled(name: String, rgb: (u8, u8, u8), rects: Vec<[(f64, f64); 2]>) -> Series {
    Series {
        name,
        style: Style::Filled(rgb),
        color: 0,
        pieces: vec![rects.into_iter().flatten().collect()],
    }
}

/// The design map: one panel, cells coloured by category or by band, contours for a numeric
/// colour on a grid. The legend (below the panel) names each category or band.
///
/// # Errors
/// [`PlotError::Request`] when there are no rows, the colour has another length than the
/// points, or a coordinate is not finite.
pub fn design_map_figure(map: &DesignMap) -> Result<Figure, PlotError> {
    let n = map.points.len();
    let len = match &map.color {
        MapColor::Category(c) => c.len(),
        MapColor::Numeric(c) => c.len(),
    };
    if n == 0 || len != n {
        return Err(PlotError::Request(format!(
            "a design map needs rows with a colour each: {n} points, {len} colours"
        )));
    }
    if let Some(p) = map
        .points
        .iter()
        .find(|p| !(p.0.is_finite() && p.1.is_finite()))
    {
        return Err(PlotError::Request(format!(
            "a design map needs finite coordinates: found ({}, {})",
            p.0, p.1
        )));
    }
    let (rects, grid) = cells(&map.points);
    let mut series = Vec::new();
    let mut title = map.color_label.clone();
    let mut color_bar = None;
    match &map.color {
        MapColor::Category(names) => {
            let mut seen: Vec<&str> = Vec::new();
            for name in names {
                let name = if name.is_empty() {
                    "error"
                } else {
                    name.as_str()
                };
                if !seen.contains(&name) {
                    seen.push(name);
                }
            }
            // Regimes in the library's order, then anything else as first seen.
            seen.sort_by_key(|s| {
                CATEGORY_COLORS
                    .iter()
                    .position(|c| c.0 == *s)
                    .unwrap_or(CATEGORY_COLORS.len())
            });
            let mut other = OTHER_COLORS.iter().cycle();
            for category in seen {
                let rgb = CATEGORY_COLORS
                    .iter()
                    .find(|c| c.0 == category)
                    .map(|c| c.1)
                    .or_else(|| other.next().copied())
                    .unwrap_or(NO_VALUE);
                let mine = names
                    .iter()
                    .zip(&rects)
                    .filter(|(s, _)| {
                        s.as_str() == category || (s.is_empty() && category == "error")
                    })
                    .map(|(_, r)| *r)
                    .collect();
                series.push(filled(category.to_string(), rgb, mine));
            }
        }
        MapColor::Numeric(values) => {
            let finite = values.iter().flatten().copied().filter(|v| v.is_finite());
            let (lo, hi) = finite.fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), v| {
                (a.min(v), b.max(v))
            });
            if lo.is_finite() {
                let bar = numeric(map, values, &rects, grid.as_ref(), (lo, hi), &mut series);
                color_bar = Some(bar);
            }
            let missing: Vec<[(f64, f64); 2]> = values
                .iter()
                .zip(&rects)
                .filter(|(v, _)| !v.is_some_and(f64::is_finite))
                .map(|(_, r)| *r)
                .collect();
            if !missing.is_empty() {
                series.push(filled("no value".into(), NO_VALUE, missing));
            }
            if grid.is_none() {
                title.push_str(" (scattered rows: no contours)");
            }
        }
    }
    Ok(Figure {
        title,
        panels: vec![Panel {
            legend: Legend::Below,
            color_bar,
            equal_aspect: false,
            log_axes: LogAxes::Neither,
            title: String::new(),
            x_label: map.x_label.clone(),
            y_label: map.y_label.clone(),
            series,
        }],
    })
}

/// The numeric colour of the rows with a value: filled contours on a grid of at least 2 x 2
/// points, else each row's cell in its band's colour; pushed to `series`, and the colour bar.
fn numeric(
    map: &DesignMap,
    values: &[Option<f64>],
    rects: &[[(f64, f64); 2]],
    grid: Option<&Grid>,
    range: (f64, f64),
    series: &mut Vec<Series>,
) -> ColorBar {
    let label = map.color_label.clone();
    let (xs, ys): (&[f64], &[f64]) = match grid {
        Some(g) if g.xs.len() >= 2 && g.ys.len() >= 2 => (&g.xs, &g.ys),
        _ => (&[], &[]),
    };
    let value = |ix: usize, iy: usize| {
        grid.and_then(|g| values[g.row[iy * g.xs.len() + ix]])
            .filter(|v| v.is_finite())
    };
    let (bands, bar) = filled_map((xs, ys), value, range, Shading::Sequential, label, |p| p);
    if xs.is_empty() {
        // No cells to interpolate in: each row's own cell in its band's colour.
        let band = |v: f64| bar.ticks.iter().filter(|(l, _)| v >= *l).count();
        for (b, &rgb) in bar.colors.iter().enumerate() {
            let mine: Vec<[(f64, f64); 2]> = values
                .iter()
                .zip(rects)
                .filter(|(v, _)| v.is_some_and(|v| v.is_finite() && band(v) == b))
                .map(|(_, r)| *r)
                .collect();
            if !mine.is_empty() {
                series.push(filled(String::new(), rgb, mine));
            }
        }
    } else {
        series.extend(bands);
    }
    bar
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_grid_gets_cells_and_a_regime_map_one_series_per_regime() {
        let points: Vec<(f64, f64)> = (0..3)
            .flat_map(|i| (0..2).map(move |j| (i as f64, 10.0 * j as f64)))
            .collect();
        let names = [
            "full-stick",
            "partial-slip",
            "partial-slip",
            "",
            "gross-sliding",
            "partial-slip",
        ];
        let map = DesignMap {
            x_label: "x".into(),
            y_label: "y".into(),
            color_label: "regime".into(),
            points,
            color: MapColor::Category(names.iter().map(|s| s.to_string()).collect()),
        };
        let f = design_map_figure(&map).expect("draws");
        let s = &f.panels[0].series;
        let got: Vec<(&str, usize)> = s
            .iter()
            .map(|s| (s.name.as_str(), s.pieces[0].len() / 2))
            .collect();
        assert_eq!(
            got,
            [
                ("full-stick", 1),
                ("partial-slip", 3),
                ("gross-sliding", 1),
                ("error", 1)
            ]
        );
        // Cells tile the grid: x edges at -0.5, 0.5, 1.5, 2.5.
        assert_eq!(s[0].pieces[0], vec![(-0.5, -5.0), (0.5, 5.0)]);
    }
}
