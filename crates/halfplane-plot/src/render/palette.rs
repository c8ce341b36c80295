//! The colours series are drawn in, by palette index.

use plotters::style::RGBColor;

pub(super) const COLORS: [RGBColor; 10] = [
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
