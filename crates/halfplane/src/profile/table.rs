//! Tabulated profiles: validation of the `(x, g)` table and its kinks, the clamped cubic splines
//! split at the kinks, and the knot table of contact-law moments that brackets the inverse of
//! the contact law.

use super::pieces::{Piece, Pieces};
use super::{Profile, Shape, Slope};
use crate::error::{physical, Error, Result};
use crate::spline;

/// The most rows a tabulated profile may have. A table holds about 150 bytes per row (the table,
/// two spline pieces and the knot data), so 1,000,000 rows take about 150 MB, and every contact
/// evaluation walks the rows inside the contact; a finer table than that resolves nothing more.
pub const MAX_TABLE_ROWS: usize = 1_000_000;

/// Piece ends below this index all get their contact-law moment J1 in the knot table (at most
/// 512^2/2 piece integrals, about 3 ms); above it, only ends whose index has grown by at least
/// 1/[`KNOT_GROWTH`] since the last one kept. Tables of up to 513 rows thus keep a one-interval
/// bracket for the contact law (a 401-row solve takes 73 µs with it, 87 µs with the sparse
/// table).
const ALL_KNOTS_BELOW: usize = 512;
/// See [`ALL_KNOTS_BELOW`].
const KNOT_GROWTH: usize = 8;

impl Profile {
    /// Tabulated profile: `x` from 0, strictly increasing; `g` finite and non-decreasing; `kinks`
    /// a subset of `x` where the interpolant may have a corner or jump in g' (0 allowed: then
    /// g'(0+) is fitted from the data instead of set to 0 by symmetry). At least 3 rows and at
    /// most [`MAX_TABLE_ROWS`]. Such a table is mirrored: g(-x) = g(x).
    ///
    /// A table whose first x is negative is **two-sided**: it must extend beyond x = 0 (last
    /// x > 0), `g` must fall (non-increasing) down to its lowest row and rise (non-decreasing)
    /// after it, and it is used as given, with no mirroring: an asymmetric profile, solved only
    /// by the normal problem under P and a moment. Both end slopes of its splines are fitted
    /// from the data, and its kinks may be any rows but the last, of either sign.
    ///
    /// Setup takes time linear in the rows (about 0.2 s for 1,000,000 rows, BENCHMARKS.md).
    pub fn tabulated(x: Vec<f64>, g: Vec<f64>, kinks: Vec<f64>) -> Result<Self> {
        let table = |row: usize, problem: String| Error::InvalidTable { row, problem };
        if x.len().max(g.len()) > MAX_TABLE_ROWS {
            return Err(Error::TooManyRows {
                what: "tabulated profile",
                rows: x.len().max(g.len()),
                max: MAX_TABLE_ROWS,
            });
        }
        if x.len() != g.len() {
            return Err(Error::LengthMismatch {
                field: "g".into(),
                length: g.len(),
                expected: x.len(),
                per: "one gap g per x",
            });
        }
        if x.len() < 3 {
            return Err(table(
                x.len(),
                format!("needs at least 3 rows, found {}", x.len()),
            ));
        }
        for (i, (&xi, &gi)) in x.iter().zip(&g).enumerate() {
            if physical("x", xi).is_err() || physical("g", gi).is_err() {
                return Err(table(
                    i + 1,
                    format!(
                        "x = {xi}, g = {gi}: both must be finite numbers of magnitude at most 1e30"
                    ),
                ));
            }
        }
        if x[0] < 0.0 {
            return Self::two_sided(x, g, kinks);
        }
        if x[0] != 0.0 {
            return Err(table(
                1,
                format!(
                    "x = {}: the first row must be at x = 0 (the profile's centre; the table is mirrored) \
                     or below 0 (a two-sided table, used as given)",
                    x[0]
                ),
            ));
        }
        for i in 1..x.len() {
            if x[i] <= x[i - 1] {
                return Err(table(
                    i + 1,
                    format!(
                        "x = {} does not exceed the previous x = {}: x must be strictly increasing",
                        x[i],
                        x[i - 1]
                    ),
                ));
            }
            if g[i] < g[i - 1] {
                return Err(table(
                    i + 1,
                    format!(
                        "g = {} is below the previous g = {}: g must be non-decreasing in x",
                        g[i],
                        g[i - 1]
                    ),
                ));
            }
        }
        let (kinks, cuts) = kink_rows(&x, kinks)?;
        let kink_at_centre = kinks.first() == Some(&0.0);
        let pieces = spline_pieces(&x, &g, &cuts, !kink_at_centre);
        let mut breaks: Vec<f64> = kinks.clone();
        breaks.retain(|&k| k > 0.0);
        let mut slope = Pieces::symmetric(pieces, &breaks);
        // J1 at the piece end of index i costs O(i), so every end would cost O(n^2) (106 s for
        // 100,000 rows). The ends kept are all of the first ALL_KNOTS_BELOW, then ends at least
        // 1/KNOT_GROWTH further in index, and the last: the indices sum to below
        // (KNOT_GROWTH + 1) n + ALL_KNOTS_BELOW^2 / 2, and a bracket still spans at most 1/8 of
        // the contact's pieces, which the contact law's Newton iteration closes in a few steps.
        let ends: Vec<f64> = slope
            .pieces
            .iter()
            .filter(|p| p.end > 0.0)
            .map(|p| p.end)
            .collect();
        let mut next = 0;
        let mut knot_moments = Vec::new();
        for (i, &end) in ends.iter().enumerate() {
            if i >= next || i + 1 == ends.len() {
                knot_moments.push((end, slope.symmetric_moment(end)?.0));
                next = if i < ALL_KNOTS_BELOW {
                    i + 1
                } else {
                    i + i / KNOT_GROWTH
                };
            }
        }
        slope.knot_moments = knot_moments;
        Ok(Self {
            shape: Shape::Tabulated { x, g, kinks },
            slope: Slope::Pieces(slope),
            right_radius: None,
        })
    }

    /// The two-sided table of [`Profile::tabulated`] (first x < 0), its rows already checked to
    /// be finite and as many in x as in g: x strictly increasing to beyond 0, g falling to its
    /// lowest row and rising after it.
    fn two_sided(x: Vec<f64>, g: Vec<f64>, kinks: Vec<f64>) -> Result<Self> {
        let table = |row: usize, problem: String| Error::InvalidTable { row, problem };
        let n = x.len();
        if x[n - 1] <= 0.0 {
            return Err(table(
                n,
                format!(
                    "x = {}: a table starting below 0 (two-sided) must extend beyond x = 0",
                    x[n - 1]
                ),
            ));
        }
        let lowest = (0..n).fold(0, |best, i| if g[i] < g[best] { i } else { best });
        for i in 1..n {
            if x[i] <= x[i - 1] {
                return Err(table(
                    i + 1,
                    format!(
                        "x = {} does not exceed the previous x = {}: x must be strictly increasing",
                        x[i],
                        x[i - 1]
                    ),
                ));
            }
            let (falls, rises) = (g[i] < g[i - 1], g[i] > g[i - 1]);
            if (i <= lowest && rises) || (i > lowest && falls) {
                return Err(table(
                    i + 1,
                    format!(
                        "g = {} after g = {}: a two-sided table's g must fall to its lowest value \
                         (row {}) and rise after it",
                        g[i],
                        g[i - 1],
                        lowest + 1
                    ),
                ));
            }
        }
        let (kinks, cuts) = kink_rows(&x, kinks)?;
        let pieces = spline_pieces(&x, &g, &cuts, false);
        let slope = Pieces::two_sided(pieces, &kinks);
        Ok(Self {
            shape: Shape::Tabulated { x, g, kinks },
            slope: Slope::Pieces(slope),
            right_radius: None,
        })
    }
}

/// The kinks matched to rows (sorted, one per row) and the row indices where the table is cut
/// into spline segments (the first row, each kink row but the first, the last row).
fn kink_rows(x: &[f64], mut kinks: Vec<f64>) -> Result<(Vec<f64>, Vec<usize>)> {
    kinks.sort_by(f64::total_cmp);
    kinks.dedup();
    let mut cuts = vec![0usize];
    // Kinks are matched to a row within 1e-9 of the table's length (decimal inputs such as 0.3
    // need not be bit-equal to a computed abscissa); a one-sided table's length is its last x.
    let tol = 1e-9 * x[x.len() - 1].max(-x[0]);
    for k in kinks.iter_mut() {
        let k_given = *k;
        // x is increasing: the first row within tol is found by bisection, O(log n) per kink.
        let first = x.partition_point(|&xi| xi < k_given - tol);
        let within = x.get(first).filter(|&&xi| (xi - k_given).abs() <= tol);
        match within.map(|_| first) {
            Some(i) if i + 1 < x.len() => {
                *k = x[i];
                if i > 0 {
                    cuts.push(i);
                }
            }
            _ => {
                return Err(Error::InvalidInput {
                    field: "profile.kinks".into(),
                    value: k_given,
                    valid: "one of the tabulated x values, below the last one",
                })
            }
        }
    }
    // Two kinks given within the tolerance of one row are one kink (a repeated cut would leave a
    // one-point segment, which has no spline).
    kinks.dedup();
    cuts.dedup();
    cuts.push(x.len() - 1);
    Ok((kinks, cuts))
}

/// The clamped cubic splines of the segments between consecutive `cuts`, as slope pieces. The
/// first segment's start slope is 0 (the mirrored table's centre) when `flat_start`, otherwise
/// fitted from the data like every other end.
fn spline_pieces(x: &[f64], g: &[f64], cuts: &[usize], flat_start: bool) -> Vec<Piece> {
    let mut pieces = Vec::new();
    for (s, w) in cuts.windows(2).enumerate() {
        let (xs, gs) = (&x[w[0]..=w[1]], &g[w[0]..=w[1]]);
        // The end slope uses the last four points only: copying the whole segment reversed
        // would cost O(rows) per segment.
        let rev = |v: &[f64]| v.iter().rev().take(4).copied().collect::<Vec<_>>();
        let s0 = if s == 0 && flat_start {
            0.0
        } else {
            spline::end_slope(xs, gs)
        };
        let s1 = spline::end_slope(&rev(xs), &rev(gs));
        pieces.extend(spline::clamped(xs, gs, s0, s1).into_iter().map(|iv| Piece {
            start: iv.x0,
            end: iv.x1,
            origin: iv.x0,
            coeffs: iv.slope,
        }));
    }
    pieces
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::reference;

    #[test]
    fn a_long_table_is_set_up_in_linear_time_with_exact_brackets() {
        // 100,000 rows took 106 s in release when every knot's J1 was computed (O(n^2)); in
        // linear time they take well under a second even in debug.
        let start = std::time::Instant::now();
        let table = reference::flat_rounded_table(100_001).unwrap();
        let took = start.elapsed();
        assert!(took.as_secs() < 10, "setup took {took:?}");
        let Slope::Pieces(p) = &table.slope else {
            unreachable!("a table is piecewise")
        };
        assert!(
            p.knot_moments.len() < 600,
            "{} knots kept",
            p.knot_moments.len()
        );
        assert_eq!(p.knot_moments.last().map(|k| k.0), Some(2.0));
        // The integrals match the analytic profile's, and the sparse knot table still brackets
        // the contact law's inverse.
        let exact = Profile::flat_rounded(0.3, 50.0).unwrap();
        for a in [0.31, 0.35, 0.9, 1.7, 1.99] {
            let (j1, _) = table.symmetric_moment(a).unwrap();
            let (want, _) = exact.symmetric_moment(a).unwrap();
            assert!(
                (j1 - want).abs() <= 1e-10 * want,
                "J1({a}) = {j1}, want {want}"
            );
            let [(lo, m_lo), (hi, m_hi)] = table.moment_bracket(j1).unwrap().unwrap();
            assert!(
                lo <= a && a <= hi && m_lo <= j1 && j1 <= m_hi,
                "{a}: [{lo}, {hi}]"
            );
        }
    }

    #[test]
    fn small_tables_keep_every_knot() {
        let table = reference::flat_rounded_table(41).unwrap();
        let Slope::Pieces(p) = &table.slope else {
            unreachable!("a table is piecewise")
        };
        assert_eq!(p.knot_moments.len(), 40);
    }

    #[test]
    fn kinks_on_one_row_are_one_kink_and_too_many_rows_are_an_error() {
        let x = vec![0.0, 0.25, 0.5, 0.75, 1.0];
        let g = vec![0.0, 0.0, 0.0, 0.01, 0.04];
        let p = Profile::tabulated(x.clone(), g.clone(), vec![0.5, 0.5 + 1e-12, 0.5 - 1e-12]);
        assert_eq!(p.map(|p| p.kinks()), Ok(vec![0.5]));
        let n = MAX_TABLE_ROWS + 1;
        let long = Profile::tabulated(vec![0.0; n], vec![0.0; n], vec![]);
        assert_eq!(
            long,
            Err(Error::TooManyRows {
                what: "tabulated profile",
                rows: n,
                max: MAX_TABLE_ROWS
            })
        );
    }
}
