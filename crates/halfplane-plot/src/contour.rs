//! Contour lines of a field sampled on a rectangular grid (marching squares), filled contour
//! bands and their boundary lines ([`filled_contours`]), and the levels to draw: drawing geometry
//! only, no physics.

/// A scalar field on a grid below the surface: `values` row after row, `z` outer and `x` inner
/// (`z.len()` rows of `x.len()` values), `z` the depth.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct GridMap<'a> {
    /// The columns' x, increasing.
    pub x: &'a [f64],
    /// The rows' depth z, increasing.
    pub z: &'a [f64],
    /// The values, `z.len()` rows of `x.len()`.
    pub values: &'a [f64],
}

impl GridMap<'_> {
    /// Whether the grid is at least 2 by 2 and `values` has one value per grid point.
    pub fn is_consistent(&self) -> bool {
        self.x.len() >= 2
            && self.z.len() >= 2
            && self.x.len().checked_mul(self.z.len()) == Some(self.values.len())
    }

    /// The smallest and largest finite value (`None` when there is none).
    pub fn range(&self) -> Option<(f64, f64)> {
        let finite = self.values.iter().copied().filter(|v| v.is_finite());
        let (lo, hi) = finite.fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), v| {
            (lo.min(v), hi.max(v))
        });
        (lo <= hi).then_some((lo, hi))
    }
}

/// Evenly spaced "round" levels strictly between `lo` and `hi`: a step of 1, 2, 2.5 or 5 times a
/// power of ten giving at most `most` levels, and the number of decimals that step needs.
pub fn levels(lo: f64, hi: f64, most: usize) -> (Vec<f64>, usize) {
    if !(lo.is_finite() && hi.is_finite() && hi > lo) || most == 0 {
        return (Vec::new(), 0);
    }
    let raw = (hi - lo) / (most + 1) as f64;
    let power = 10f64.powf(raw.log10().floor());
    let step = [1.0, 2.0, 2.5, 5.0, 10.0]
        .iter()
        .map(|m| m * power)
        .find(|s| ((hi - lo) / s).ceil() - 1.0 <= most as f64)
        .unwrap_or(10.0 * power);
    let decimals = (-(step.log10().floor()) as i32 + i32::from((step / power - 2.5).abs() < 1e-9))
        .max(0) as usize;
    let first = (lo / step).floor() as i64 + 1;
    let levels = (first..)
        .map(|k| k as f64 * step)
        .take_while(|&l| l < hi)
        .filter(|&l| l > lo)
        .take(most)
        .map(|l| if l.abs() < 1e-9 * step { 0.0 } else { l })
        .collect();
    (levels, decimals)
}

/// The segments where the field `value(ix, iy)` on the grid `xs` × `ys` crosses `level`, as
/// pairs of points. Cells with a missing corner are skipped.
pub fn contour_segments(
    xs: &[f64],
    ys: &[f64],
    value: impl Fn(usize, usize) -> Option<f64>,
    level: f64,
) -> Vec<((f64, f64), (f64, f64))> {
    let mut out = Vec::new();
    for iy in 0..ys.len().saturating_sub(1) {
        for ix in 0..xs.len().saturating_sub(1) {
            // Corners counter-clockwise from (ix, iy).
            let at = [(ix, iy), (ix + 1, iy), (ix + 1, iy + 1), (ix, iy + 1)];
            let Some(v) = at
                .iter()
                .map(|&(i, j)| value(i, j))
                .collect::<Option<Vec<f64>>>()
            else {
                continue;
            };
            let p: Vec<(f64, f64)> = at.iter().map(|&(i, j)| (xs[i], ys[j])).collect();
            // The crossing on edge k (from corner k to k + 1), if the level separates its ends.
            let cross = |k: usize| -> Option<(f64, f64)> {
                let (a, b) = (v[k], v[(k + 1) % 4]);
                if (a < level) == (b < level) {
                    return None;
                }
                let t = (level - a) / (b - a);
                let (pa, pb) = (p[k], p[(k + 1) % 4]);
                Some((pa.0 + t * (pb.0 - pa.0), pa.1 + t * (pb.1 - pa.1)))
            };
            let crossings: Vec<(usize, (f64, f64))> =
                (0..4).filter_map(|k| cross(k).map(|c| (k, c))).collect();
            match crossings.len() {
                2 => out.push((crossings[0].1, crossings[1].1)),
                4 => {
                    // A saddle: the centre value decides which corners the level joins.
                    let centre = 0.25 * v.iter().sum::<f64>();
                    let c: Vec<(f64, f64)> = crossings.iter().map(|c| c.1).collect();
                    if (centre < level) == (v[0] < level) {
                        out.push((c[0], c[1]));
                        out.push((c[2], c[3]));
                    } else {
                        out.push((c[3], c[0]));
                        out.push((c[1], c[2]));
                    }
                }
                _ => {}
            }
        }
    }
    out
}

/// Filled contours of a field on the grid `xs` × `ys`: for each band between consecutive
/// `bounds` (increasing), the polygons where the field lies in it, and for each interior bound the
/// line where the field takes it (consecutive pairs of points), both from the same interpolation,
/// so the lines are the bands' edges.
///
/// Each cell is split into four triangles by its centre, given the mean of the corner values, and
/// the field is linear on each triangle (the centre split decides a saddle as marching squares
/// does). A band clips a triangle to a convex polygon (Sutherland & Hodgman 1974): the bands
/// tile every cell whose four corners have a value, with no staircase at cell edges. Values
/// below the first bound count to the first band and above the last to the last. Rows of cells
/// wholly in one band are merged into one rectangle. Cells with a missing corner are left out.
pub fn filled_contours(
    xs: &[f64],
    ys: &[f64],
    value: impl Fn(usize, usize) -> Option<f64>,
    bounds: &[f64],
) -> FilledContours {
    let count = bounds.len().saturating_sub(1);
    let mut out = FilledContours {
        bands: vec![Vec::new(); count],
        lines: vec![Vec::new(); count.saturating_sub(1)],
    };
    if count == 0 {
        return out;
    }
    let interior = &bounds[1..count];
    let band = |v: f64| interior.iter().filter(|&&l| v >= l).count();
    for iy in 0..ys.len().saturating_sub(1) {
        // A run of whole cells in one band along the row: (band, first x, last x).
        let mut run: Option<(usize, f64, f64)> = None;
        for ix in 0..xs.len().saturating_sub(1) {
            let at = [(ix, iy), (ix + 1, iy), (ix + 1, iy + 1), (ix, iy + 1)];
            let Some(v) = at
                .iter()
                .map(|&(i, j)| value(i, j))
                .collect::<Option<Vec<f64>>>()
            else {
                flush(&mut out, &mut run, ys[iy], ys[iy + 1]);
                continue;
            };
            let centre = 0.25 * v.iter().sum::<f64>();
            let b = band(centre);
            if v.iter().all(|&c| band(c) == b) {
                match &mut run {
                    Some((rb, _, x1)) if *rb == b => *x1 = xs[ix + 1],
                    _ => {
                        flush(&mut out, &mut run, ys[iy], ys[iy + 1]);
                        run = Some((b, xs[ix], xs[ix + 1]));
                    }
                }
                continue;
            }
            flush(&mut out, &mut run, ys[iy], ys[iy + 1]);
            let p: Vec<Vertex> = at
                .iter()
                .zip(&v)
                .map(|(&(i, j), &v)| (xs[i], ys[j], v))
                .collect();
            let c = (
                0.5 * (xs[ix] + xs[ix + 1]),
                0.5 * (ys[iy] + ys[iy + 1]),
                centre,
            );
            for k in 0..4 {
                let triangle = [p[k], p[(k + 1) % 4], c];
                let (lo, hi) = triangle.iter().fold((usize::MAX, 0), |(lo, hi), t| {
                    (lo.min(band(t.2)), hi.max(band(t.2)))
                });
                for b in lo..=hi {
                    let mut polygon = triangle.to_vec();
                    if b > 0 {
                        polygon = clip(&polygon, bounds[b], 1.0);
                    }
                    if b + 1 < count {
                        polygon = clip(&polygon, bounds[b + 1], -1.0);
                    }
                    // A level through a corner can leave a polygon of no area: not drawn.
                    if polygon.len() >= 3 && twice_area(&polygon) > 0.0 {
                        out.bands[b].push(polygon.iter().map(|q| (q.0, q.1)).collect());
                    }
                }
                for (l, &level) in interior.iter().enumerate() {
                    out.lines[l].extend(crossing(&triangle, level));
                }
            }
        }
        flush(&mut out, &mut run, ys[iy], ys[iy + 1]);
    }
    out
}

/// What [`filled_contours`] draws.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct FilledContours {
    /// For each band, its polygons (each a list of corners, not closed).
    pub bands: Vec<Vec<Vec<(f64, f64)>>>,
    /// For each interior bound, its line as disjoint segments (consecutive pairs of points).
    pub lines: Vec<Vec<(f64, f64)>>,
}

/// A corner of a triangle with the field's value there.
type Vertex = (f64, f64, f64);

/// Twice the signed area of a polygon (shoelace formula), positive counter-clockwise.
fn twice_area(p: &[Vertex]) -> f64 {
    (0..p.len())
        .map(|k| {
            let (a, b) = (p[k], p[(k + 1) % p.len()]);
            a.0 * b.1 - b.0 * a.1
        })
        .sum()
}

/// Ends a run of whole cells between rows `y0` and `y1`: one rectangle in its band.
fn flush(out: &mut FilledContours, run: &mut Option<(usize, f64, f64)>, y0: f64, y1: f64) {
    if let Some((b, x0, x1)) = run.take() {
        out.bands[b].push(vec![(x0, y0), (x1, y0), (x1, y1), (x0, y1)]);
    }
}

/// The part of the convex polygon where `side * (v - level) >= 0` (Sutherland-Hodgman against
/// one half-plane, the field linear along each edge).
fn clip(polygon: &[Vertex], level: f64, side: f64) -> Vec<Vertex> {
    let inside = |p: &Vertex| side * (p.2 - level) >= 0.0;
    let mut out = Vec::with_capacity(polygon.len() + 2);
    for (k, a) in polygon.iter().enumerate() {
        let b = &polygon[(k + 1) % polygon.len()];
        if inside(a) {
            out.push(*a);
        }
        if inside(a) != inside(b) {
            let t = (level - a.2) / (b.2 - a.2);
            out.push((a.0 + t * (b.0 - a.0), a.1 + t * (b.1 - a.1), level));
        }
    }
    out
}

/// The segment where the field, linear on the triangle, takes `level` (none when it does not
/// cross: a level touching a corner only, or lying on a whole edge, draws nothing here).
fn crossing(triangle: &[Vertex; 3], level: f64) -> Vec<(f64, f64)> {
    let mut ends = Vec::with_capacity(2);
    for k in 0..3 {
        let (a, b) = (triangle[k], triangle[(k + 1) % 3]);
        if (a.2 < level) != (b.2 < level) {
            let t = (level - a.2) / (b.2 - a.2);
            ends.push((a.0 + t * (b.0 - a.0), a.1 + t * (b.1 - a.1)));
        }
    }
    if ends.len() == 2 {
        ends
    } else {
        Vec::new()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The iso-line `value = level` of a field below the surface as disjoint segments (consecutive
    /// pairs of points), in plot coordinates `(x, -z)` so that depth runs downwards. Cells with a
    /// value that is not finite are skipped.
    fn segments(map: &GridMap, level: f64) -> Vec<(f64, f64)> {
        if !map.is_consistent() {
            return Vec::new();
        }
        let nx = map.x.len();
        let value = |i: usize, j: usize| Some(map.values[j * nx + i]).filter(|v| v.is_finite());
        contour_segments(map.x, map.z, value, level)
            .into_iter()
            .flat_map(|((x0, z0), (x1, z1))| [(x0, -z0), (x1, -z1)])
            .collect()
    }

    #[test]
    fn contours_of_a_plane_lie_on_its_level_line() {
        // v = x + 2y on a 5 x 4 grid: marching squares with linear interpolation is exact for a
        // linear field, so every segment end lies on x + 2y = level to rounding (1e-12).
        let xs = [0.0, 1.0, 2.0, 3.0, 4.0];
        let ys = [0.0, 0.5, 1.5, 3.0];
        let value = |i: usize, j: usize| Some(xs[i] + 2.0 * ys[j]);
        let segments = contour_segments(&xs, &ys, value, 3.3);
        assert!(!segments.is_empty());
        for (a, b) in segments {
            for p in [a, b] {
                assert!(
                    (p.0 + 2.0 * p.1 - 3.3).abs() < 1e-12,
                    "{p:?} off the level line"
                );
            }
        }
    }

    /// The area of a polygon (shoelace formula), positive counter-clockwise.
    fn area(p: &[(f64, f64)]) -> f64 {
        0.5 * (0..p.len())
            .map(|k| {
                let (a, b) = (p[k], p[(k + 1) % p.len()]);
                a.0 * b.1 - b.0 * a.1
            })
            .sum::<f64>()
    }

    #[test]
    fn filled_bands_tile_the_grid_and_hold_their_values() {
        // A saddle-free but curved field v = x^2 + 3 y on an uneven 7 x 5 grid, bounds from its
        // minimum to its maximum: the bands' polygons cover the grid's area exactly (to rounding,
        // 1e-12 of it) without overlap (every polygon counter-clockwise, areas summing to the
        // total), and each polygon's corners take values inside its band on the triangle
        // interpolation (checked through the linear field v = x + 2y, for which it is exact).
        let xs = [0.0, 0.3, 0.5, 1.0, 1.6, 2.0, 2.5];
        let ys = [0.0, 0.2, 0.7, 0.9, 1.5];
        let curved = |i: usize, j: usize| Some(xs[i] * xs[i] + 3.0 * ys[j]);
        let bounds = [0.0, 1.0, 2.0, 2.5, 4.0, 6.25 + 4.5];
        let filled = filled_contours(&xs, &ys, curved, &bounds);
        let total: f64 = filled.bands.iter().flatten().map(|p| area(p)).sum();
        assert!((total - 2.5 * 1.5).abs() < 1e-12, "covered {total}");
        assert!(filled.bands.iter().flatten().all(|p| area(p) > 0.0));
        assert_eq!(filled.lines.len(), 4);
        let linear = |i: usize, j: usize| Some(xs[i] + 2.0 * ys[j]);
        let bounds = [0.0, 1.0, 2.5, 4.0, 5.5];
        let filled = filled_contours(&xs, &ys, linear, &bounds);
        for (b, polygons) in filled.bands.iter().enumerate() {
            assert!(!polygons.is_empty(), "band {b} is drawn");
            for &(x, y) in polygons.iter().flatten() {
                let v = x + 2.0 * y;
                assert!(
                    v >= bounds[b] - 1e-12 && v <= bounds[b + 1] + 1e-12,
                    "({x}, {y}) = {v} outside band {b}"
                );
            }
        }
        for (l, line) in filled.lines.iter().enumerate() {
            assert!(!line.is_empty() && line.len().is_multiple_of(2));
            for &(x, y) in line {
                assert!((x + 2.0 * y - bounds[l + 1]).abs() < 1e-12);
            }
        }
        // A missing corner leaves its four cells out.
        let holed = |i: usize, j: usize| ((i, j) != (3, 2)).then(|| xs[i] + 2.0 * ys[j]);
        let filled = filled_contours(&xs, &ys, holed, &bounds);
        let total: f64 = filled.bands.iter().flatten().map(|p| area(p)).sum();
        assert!((total - (2.5 * 1.5 - (1.6 - 0.5) * (0.9 - 0.2))).abs() < 1e-12);
    }

    #[test]
    fn levels_are_round_and_inside_the_range() {
        let same = |a: &[f64], b: &[f64]| {
            a.len() == b.len() && a.iter().zip(b).all(|(a, b)| (a - b).abs() < 1e-12)
        };
        let (l, d) = levels(0.0, 1.0, 9);
        let tenths: Vec<f64> = (1..=9).map(|k| k as f64 / 10.0).collect();
        assert!(same(&l, &tenths) && d == 1, "{l:?}, {d}");
        let (l, d) = levels(-330.0, 470.0, 9);
        let hundreds = [-300.0, -200.0, -100.0, 0.0, 100.0, 200.0, 300.0, 400.0];
        assert!(same(&l, &hundreds) && d == 0, "{l:?}, {d}");
        let (l, d) = levels(0.0, 1.0, 3);
        assert!(same(&l, &[0.25, 0.5, 0.75]) && d == 2, "{l:?}, {d}");
        let (l, d) = levels(0.0, 0.011, 9);
        assert_eq!(d, 3);
        assert!(l.len() <= 9 && l.iter().all(|&v| v > 0.0 && v < 0.011));
        assert_eq!(levels(1.0, 1.0, 9).0, Vec::<f64>::new());
    }

    #[test]
    fn a_linear_field_gives_straight_iso_lines_where_they_belong() {
        // v = x + 2z on a 5 x 4 grid: the line v = 1.5 runs from (1.5, 0) to (0, 0.75).
        let x = [0.0, 0.5, 1.0, 1.5, 2.0];
        let z = [0.0, 0.5, 1.0, 1.5];
        let values: Vec<f64> = z
            .iter()
            .flat_map(|z| x.iter().map(move |x| x + 2.0 * z))
            .collect();
        let map = GridMap {
            x: &x,
            z: &z,
            values: &values,
        };
        let s = segments(&map, 1.5);
        assert!(!s.is_empty() && s.len().is_multiple_of(2));
        for &(px, py) in &s {
            assert!(
                (px - 2.0 * py - 1.5).abs() < 1e-12,
                "({px}, {py}) off the line"
            );
        }
    }

    #[test]
    fn a_saddle_gives_two_segments_and_bad_values_are_skipped() {
        let (x, z) = ([0.0, 1.0], [0.0, 1.0]);
        let values = [1.0, 0.0, 1.0, 0.0];
        let map = GridMap {
            x: &x,
            z: &z,
            values: &values,
        };
        assert_eq!(segments(&map, 0.5).len(), 2, "not a saddle: one segment");
        let values = [1.0, 0.0, 0.0, 1.0];
        let saddle = GridMap {
            values: &values,
            ..map
        };
        assert_eq!(segments(&saddle, 0.5).len(), 4);
        let values = [1.0, f64::NAN, 0.0, 1.0];
        let bad = GridMap {
            values: &values,
            ..map
        };
        assert!(segments(&bad, 0.5).is_empty());
    }
}
