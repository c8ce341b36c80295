//! Contour lines of a field sampled on a rectangular grid (marching squares), and the levels to
//! draw: drawing geometry only, no physics.

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

/// The iso-line `value = level` of a field below the surface as disjoint segments (consecutive
/// pairs of points), in plot coordinates `(x, -z)` so that depth runs downwards. Cells with a
/// value that is not finite are skipped.
pub fn segments(map: &GridMap, level: f64) -> Vec<(f64, f64)> {
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

#[cfg(test)]
mod tests {
    use super::*;

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
