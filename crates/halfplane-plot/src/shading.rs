//! Filled maps: colour maps (viridis for a magnitude, a diverging red-blue centred on zero for a
//! signed stress) and the bands, contour lines and colour bar of a field on a grid.

use crate::contour::{filled_contours, levels};
use crate::format::level_labels;
use crate::{ColorBar, Series, Style};

/// The viridis colour map at five stops (van der Walt & Smith, matplotlib 2.0), interpolated
/// linearly: perceptually ordered and readable in grey and by colour-blind readers.
const VIRIDIS: [(f64, f64, f64); 5] = [
    (68.0, 1.0, 84.0),
    (59.0, 82.0, 139.0),
    (33.0, 145.0, 140.0),
    (94.0, 201.0, 98.0),
    (253.0, 231.0, 37.0),
];

/// ColorBrewer's diverging RdBu at eleven classes (Harrower & Brewer 2003), blue (negative) to
/// red (positive) through a near-white middle, interpolated linearly.
const RED_BLUE: [(f64, f64, f64); 11] = [
    (5.0, 48.0, 97.0),
    (33.0, 102.0, 172.0),
    (67.0, 147.0, 195.0),
    (146.0, 197.0, 222.0),
    (209.0, 229.0, 240.0),
    (247.0, 247.0, 247.0),
    (253.0, 219.0, 199.0),
    (244.0, 165.0, 130.0),
    (214.0, 96.0, 77.0),
    (178.0, 24.0, 43.0),
    (103.0, 0.0, 31.0),
];

/// The colour at fraction `t` (0 to 1) of a colour map given by evenly spaced stops.
fn along(stops: &[(f64, f64, f64)], t: f64) -> (u8, u8, u8) {
    let t = t.clamp(0.0, 1.0) * (stops.len() - 1) as f64;
    let i = (t.floor() as usize).min(stops.len() - 2);
    let f = t - i as f64;
    let (a, b) = (stops[i], stops[i + 1]);
    let mix = |p: f64, q: f64| (p + (q - p) * f).round() as u8;
    (mix(a.0, b.0), mix(a.1, b.1), mix(a.2, b.2))
}

/// The colour at fraction `t` (0 to 1) of the viridis map.
pub fn sequential(t: f64) -> (u8, u8, u8) {
    along(&VIRIDIS, t)
}

/// The colour of `v` on the diverging map centred on zero, with `±reach` at its ends: white at
/// zero, blue below, red above.
pub fn diverging(v: f64, reach: f64) -> (u8, u8, u8) {
    let t = if reach > 0.0 {
        0.5 + 0.5 * v / reach
    } else {
        0.5
    };
    along(&RED_BLUE, t)
}

/// How a filled map is coloured.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum Shading {
    /// Viridis from the smallest value to the largest.
    Sequential,
    /// Red-blue centred on zero (a signed stress).
    Diverging,
}

/// The most levels a filled map is cut at.
const MAP_LEVELS: usize = 10;

/// A filled map of `value` on the grid `xs` × `ys` whose finite values span `lo` to `hi`: one
/// [`Style::Polygons`] series per band (unnamed: the colour bar tells them apart), the levels as
/// [`Style::Contour`] lines, and the colour bar, labelled `label`, spanning `lo` to `hi` with the
/// levels labelled. `to_plot` maps a grid point to plot coordinates (a depth runs downwards).
pub(crate) fn filled_map(
    (xs, ys): (&[f64], &[f64]),
    value: impl Fn(usize, usize) -> Option<f64>,
    (lo, hi): (f64, f64),
    shading: Shading,
    label: String,
    to_plot: impl Fn((f64, f64)) -> (f64, f64),
) -> (Vec<Series>, ColorBar) {
    let (levels, decimals) = levels(lo, hi, MAP_LEVELS);
    let bounds: Vec<f64> = std::iter::once(lo)
        .chain(levels.iter().copied())
        .chain(std::iter::once(hi))
        .collect();
    let reach = lo.abs().max(hi.abs());
    let bands = bounds.len() - 1;
    let colors: Vec<(u8, u8, u8)> = bounds
        .windows(2)
        .enumerate()
        .map(|(b, w)| match shading {
            Shading::Diverging => diverging(0.5 * (w[0] + w[1]), reach),
            Shading::Sequential if bands > 1 => sequential(b as f64 / (bands - 1) as f64),
            Shading::Sequential => sequential(0.5),
        })
        .collect();
    let filled = filled_contours(xs, ys, value, &bounds);
    let mut series: Vec<Series> = filled
        .bands
        .into_iter()
        .zip(&colors)
        .map(|(polygons, &rgb)| Series {
            name: String::new(),
            style: Style::Polygons(rgb),
            color: 0,
            pieces: polygons
                .into_iter()
                .map(|p| p.into_iter().map(&to_plot).collect())
                .collect(),
        })
        .collect();
    let lines: Vec<(f64, f64)> = filled.lines.into_iter().flatten().map(&to_plot).collect();
    if !lines.is_empty() {
        series.push(Series::new("", Style::Contour, 3, lines));
    }
    let ticks = levels
        .iter()
        .copied()
        .zip(level_labels(&levels, decimals))
        .collect();
    let bar = ColorBar {
        label,
        bounds,
        colors,
        ticks,
    };
    (series, bar)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_diverging_map_is_white_at_zero_and_symmetric_in_lightness() {
        assert_eq!(diverging(0.0, 300.0), (247, 247, 247));
        assert_eq!(diverging(-300.0, 300.0), (5, 48, 97));
        assert_eq!(diverging(300.0, 300.0), (103, 0, 31));
        // Beyond the reach: the ends.
        assert_eq!(diverging(900.0, 300.0), (103, 0, 31));
        assert_eq!(sequential(0.0), (68, 1, 84));
        assert_eq!(sequential(1.0), (253, 231, 37));
    }

    #[test]
    fn a_filled_map_has_a_band_per_colour_and_a_bar_over_the_data_range() {
        // v = x - 2y on a 5 x 3 grid from -4 to 4: the bar spans exactly that range, with one
        // colour per band and the levels as ticks, and every band is drawn.
        let xs = [0.0, 1.0, 2.0, 3.0, 4.0];
        let ys = [0.0, 1.0, 2.0];
        let value = |i: usize, j: usize| Some(xs[i] - 2.0 * ys[j]);
        let (series, bar) = filled_map(
            (&xs, &ys),
            value,
            (-4.0, 4.0),
            Shading::Diverging,
            "v (MPa)".into(),
            |p| p,
        );
        assert_eq!(bar.bounds.first(), Some(&-4.0));
        assert_eq!(bar.bounds.last(), Some(&4.0));
        assert_eq!(bar.colors.len(), bar.bounds.len() - 1);
        assert_eq!(bar.ticks.len(), bar.bounds.len() - 2);
        assert!(bar.ticks.iter().any(|(v, l)| *v == 0.0 && l == "0"));
        let bands = series
            .iter()
            .filter(|s| matches!(s.style, Style::Polygons(_)))
            .count();
        assert_eq!(bands, bar.colors.len());
        // Centred on zero: the bands either side of zero mirror each other's colours in a
        // symmetric range.
        let n = bar.colors.len();
        let mirrored = |c: (u8, u8, u8)| c.0 as i32 - c.2 as i32;
        assert!(mirrored(bar.colors[0]) < 0 && mirrored(bar.colors[n - 1]) > 0);
    }
}
