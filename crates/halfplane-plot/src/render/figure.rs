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
    /// Filled polygons in this colour (RGB), whatever the palette index: each piece is one
    /// polygon's corners (a band of a filled contour map).
    Polygons((u8, u8, u8)),
    /// Thin dark contour lines: disjoint segments (consecutive pairs of points), drawn over
    /// filled bands.
    Contour,
    /// A marker with the series' name written beside it in the plotting area (not in the
    /// legend), placed where it stays inside: a value marked on a map.
    Annotated,
}

/// A colour bar beside a panel: the bands of a filled map, their colours and the labelled levels.
#[derive(Debug, Clone, PartialEq)]
pub struct ColorBar {
    /// What the colours show, with its unit (written along the bar).
    pub label: String,
    /// The bands' edges, increasing: the data's smallest value, the levels, its largest value.
    pub bounds: Vec<f64>,
    /// One colour per band (RGB), `bounds.len() - 1` of them.
    pub colors: Vec<(u8, u8, u8)>,
    /// The labelled values (the levels) and their labels.
    pub ticks: Vec<(f64, String)>,
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

/// Which of a panel's axes are logarithmic. On a logarithmic axis the series' points are given
/// as they are and drawn at their base-10 logarithms (points not above zero are left out), with
/// ticks at 1, 2 and 5 times the powers of ten.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum LogAxes {
    /// Both linear (default).
    #[default]
    Neither,
    /// x logarithmic, y linear (a quantity against cycles).
    X,
    /// Both logarithmic.
    Both,
}

impl LogAxes {
    /// Whether x is logarithmic.
    pub fn x(self) -> bool {
        self != Self::Neither
    }

    /// Whether y is logarithmic.
    pub fn y(self) -> bool {
        self == Self::Both
    }
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
    /// The colour bar of a filled map, drawn to the right of the plotting area.
    pub color_bar: Option<ColorBar>,
    /// Whether a unit of x and of y are the same length on the page (a map of a cross-section).
    pub equal_aspect: bool,
    /// Which axes are logarithmic.
    pub log_axes: LogAxes,
}

impl Panel {
    /// A panel of these series with the legend placed automatically, no colour bar and free
    /// aspect.
    pub fn new(
        title: impl Into<String>,
        x_label: impl Into<String>,
        y_label: impl Into<String>,
        series: Vec<Series>,
    ) -> Self {
        Self {
            legend: Legend::Auto,
            title: title.into(),
            x_label: x_label.into(),
            y_label: y_label.into(),
            series,
            color_bar: None,
            equal_aspect: false,
            log_axes: LogAxes::Neither,
        }
    }
}

/// A whole figure: a title and panels side by side.
#[derive(Debug, Clone, PartialEq)]
pub struct Figure {
    /// Title above the panels.
    pub title: String,
    /// Panels, left to right.
    pub panels: Vec<Panel>,
}
