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

/// The iso-line `value = level` as disjoint segments (consecutive pairs of points), in plot
/// coordinates `(x, -z)` so that depth runs downwards. Cells with a value that is not finite are
/// skipped; a saddle cell is resolved by the mean of its corners.
pub fn segments(map: &GridMap, level: f64) -> Vec<(f64, f64)> {
    let (nx, nz) = (map.x.len(), map.z.len());
    let mut out = Vec::new();
    if !map.is_consistent() {
        return out;
    }
    let at = |i: usize, j: usize| map.values[j * nx + i];
    for j in 0..nz - 1 {
        for i in 0..nx - 1 {
            // Corners counter-clockwise from (i, j): (i, j), (i+1, j), (i+1, j+1), (i, j+1).
            let corner = [(i, j), (i + 1, j), (i + 1, j + 1), (i, j + 1)];
            let v = corner.map(|(a, b)| at(a, b));
            if v.iter().any(|v| !v.is_finite()) {
                continue;
            }
            let above = v.map(|v| v >= level);
            // Edge k joins corner k and corner k + 1.
            let cross = |k: usize| -> Option<(f64, f64)> {
                let l = (k + 1) % 4;
                if above[k] == above[l] {
                    return None;
                }
                let t = (level - v[k]) / (v[l] - v[k]);
                let (a, b) = (corner[k], corner[l]);
                let x = map.x[a.0] + t * (map.x[b.0] - map.x[a.0]);
                let z = map.z[a.1] + t * (map.z[b.1] - map.z[a.1]);
                Some((x, -z))
            };
            let points: Vec<(usize, (f64, f64))> =
                (0..4).filter_map(|k| cross(k).map(|p| (k, p))).collect();
            match points.len() {
                2 => out.extend([points[0].1, points[1].1]),
                4 => {
                    // A saddle: cut off the two corners on the other side from the centre. The
                    // corner k lies between edges k - 1 and k.
                    let centre = 0.25 * v.iter().sum::<f64>() >= level;
                    for k in (0..4).filter(|&k| above[k] != centre) {
                        out.extend([points[(k + 3) % 4].1, points[k].1]);
                    }
                }
                _ => {}
            }
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

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
