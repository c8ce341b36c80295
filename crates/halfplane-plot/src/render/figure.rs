//! The figure model: a [`Figure`] of [`Panel`]s, each with [`Series`] drawn in a [`Style`] and a
//! [`Legend`] placement. Plain data, built by the callers and read by the renderer.

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
    /// Filled rectangles in this colour (RGB), whatever the palette index: consecutive pairs of
    /// points are opposite corners (cells of a map).
    Filled((u8, u8, u8)),
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
