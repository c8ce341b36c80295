//! Exact integrals of a piecewise-polynomial slope (Hertz, flat-rounded, tabulated spline): on
//! each piece g' is a polynomial of degree <= 2 in x, so J0, J1 and their derivatives are sums of
//! the moments `integral cos^j theta dtheta` over the piece, exact to rounding; jumps of g' add
//! their Leibniz terms to the derivatives.

use super::StickIntegrals;
use crate::error::{Error, Result};

/// `g'(x) = sum_j coeffs[j] (x - origin)^j` on `[start, end]`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(super) struct Piece {
    pub(super) start: f64,
    pub(super) end: f64,
    pub(super) origin: f64,
    pub(super) coeffs: [f64; 3],
}

impl Piece {
    pub(super) fn eval(&self, x: f64) -> f64 {
        let t = x - self.origin;
        self.coeffs[0] + t * (self.coeffs[1] + t * self.coeffs[2])
    }

    /// The piece's mirror image for the odd extension g'(-x) = -g'(x).
    pub(super) fn mirrored(&self) -> Piece {
        let [c0, c1, c2] = self.coeffs;
        Piece {
            start: -self.end,
            end: -self.start,
            origin: -self.origin,
            coeffs: [-c0, c1, -c2],
        }
    }
}

/// The pieces of a slope: one held inline (Hertz, built once per row of a batch, needs no
/// allocation) or any number on the heap. Reads as a slice either way.
#[derive(Debug, Clone)]
pub(super) enum PieceList {
    One([Piece; 1]),
    Many(Vec<Piece>),
}

impl std::ops::Deref for PieceList {
    type Target = [Piece];

    fn deref(&self) -> &[Piece] {
        match self {
            Self::One(piece) => piece,
            Self::Many(pieces) => pieces,
        }
    }
}

/// Equal when the pieces are, however they are held.
impl PartialEq for PieceList {
    fn eq(&self, other: &Self) -> bool {
        **self == **other
    }
}

/// g' as contiguous polynomial pieces over `[-extent, extent]` (odd slopes) or `[lower, upper]`
/// (two-sided), with the jumps of g' at breaks.
#[derive(Debug, Clone, PartialEq)]
pub(super) struct Pieces {
    pub(super) pieces: PieceList,
    /// `(x, g'(x+) - g'(x-))` for the breaks where g' jumps, over the whole line.
    pub(super) jumps: Vec<(f64, f64)>,
    /// The largest |x| where g' is defined on both sides (odd slopes); for a two-sided slope the
    /// larger of |lower| and upper.
    pub(super) extent: f64,
    /// `[lower, upper]`: where g' is defined (`[-extent, extent]` for odd slopes).
    pub(super) bounds: (f64, f64),
    /// Whether g' is odd (built by [`Pieces::symmetric`] or [`Pieces::whole_line`]): only then
    /// do the symmetric contact law's half-line integrals hold.
    pub(super) odd: bool,
    /// `(a, J1(a, 0))` at piece boundaries a > 0 of a finite table (all of a small table, a
    /// geometric selection of a large one, always the last): brackets the contact law's inverse.
    pub(super) knot_moments: Vec<(f64, f64)>,
    /// Whether g' is non-decreasing over the whole line (g convex), see [`Pieces::slope_never_falls`].
    pub(super) convex: bool,
}

impl Pieces {
    /// Builds the odd extension of pieces given for x >= 0 (starting at 0, contiguous). `breaks`
    /// (sorted) are the x > 0 where g' may jump; x = 0 is always checked.
    pub(super) fn symmetric(positive: Vec<Piece>, breaks: &[f64]) -> Self {
        let extent = positive.last().map_or(0.0, |p| p.end);
        let scale = positive
            .iter()
            .map(|p| {
                p.eval(p.start).abs().max(if p.end.is_finite() {
                    p.eval(p.end).abs()
                } else {
                    0.0
                })
            })
            .fold(0.0, f64::max);
        let mut jumps = Vec::new();
        let mut record = |x: f64, jump: f64| {
            if jump.abs() > 1e-13 * scale {
                jumps.push((x, jump));
            }
        };
        record(0.0, 2.0 * positive[0].eval(0.0));
        for w in positive.windows(2) {
            let x = w[0].end;
            if breaks.binary_search_by(|b| b.total_cmp(&x)).is_ok() {
                let jump = w[1].eval(x) - w[0].eval(x);
                record(x, jump);
                record(-x, jump);
            }
        }
        jumps.sort_by(|a, b| a.0.total_cmp(&b.0));
        let mut pieces: Vec<Piece> = positive.iter().rev().map(Piece::mirrored).collect();
        // Merge neighbours with the same formula (Hertz's two halves are one polynomial).
        for p in positive {
            match pieces.last_mut() {
                Some(last) if last.origin == p.origin && last.coeffs == p.coeffs => {
                    last.end = p.end
                }
                _ => pieces.push(p),
            }
        }
        let convex = Self::slope_never_falls(&pieces, scale);
        Self {
            pieces: PieceList::Many(pieces),
            jumps,
            extent,
            bounds: (-extent, extent),
            odd: true,
            knot_moments: Vec::new(),
            convex,
        }
    }

    /// Builds a slope from contiguous pieces over the whole range they cover, with no symmetry
    /// (two-sided tables, flat-rounded pads with unequal radii). `breaks` (sorted) are the x
    /// where g' may jump.
    pub(super) fn two_sided(pieces: Vec<Piece>, breaks: &[f64]) -> Self {
        let lower = pieces.first().map_or(0.0, |p| p.start);
        let upper = pieces.last().map_or(0.0, |p| p.end);
        let scale = pieces
            .iter()
            .map(|p| {
                let at = |x: f64| if x.is_finite() { p.eval(x).abs() } else { 0.0 };
                at(p.start).max(at(p.end))
            })
            .fold(0.0, f64::max);
        let jumps = pieces
            .windows(2)
            .map(|w| (w[0].end, w[1].eval(w[0].end) - w[0].eval(w[0].end)))
            .filter(|&(x, jump)| {
                breaks.binary_search_by(|b| b.total_cmp(&x)).is_ok() && jump.abs() > 1e-13 * scale
            })
            .collect();
        let convex = Self::slope_never_falls(&pieces, scale);
        Self {
            pieces: PieceList::Many(pieces),
            jumps,
            extent: lower.abs().max(upper.abs()),
            bounds: (lower, upper),
            odd: false,
            knot_moments: Vec::new(),
            convex,
        }
    }

    /// Whether g' is non-decreasing along the contiguous `pieces` (of g' scale `scale`): g'' (linear
    /// on a piece) is non-negative at both ends of every piece and g' does not fall where pieces
    /// meet. A fall of g' by at most 1e-12 of its scale counts as none: a spline fitted to a convex
    /// table can be off by rounding.
    fn slope_never_falls(pieces: &[Piece], scale: f64) -> bool {
        let tolerance = 1e-12 * scale;
        let within = pieces.iter().all(|p| {
            let curvature = |x: f64| p.coeffs[1] + 2.0 * p.coeffs[2] * (x - p.origin);
            if p.end.is_finite() && p.start.is_finite() {
                let length = p.end - p.start;
                curvature(p.start) * length >= -tolerance && curvature(p.end) * length >= -tolerance
            } else {
                // Only the analytic profiles have unbounded pieces: linear g', slope coeffs[1].
                p.coeffs[2] == 0.0 && p.coeffs[1] >= 0.0
            }
        });
        within
            && pieces
                .windows(2)
                .all(|w| w[1].eval(w[0].end) - w[0].eval(w[0].end) >= -tolerance)
    }

    /// One odd piece given for x >= 0 that holds on the whole line (Hertz: g' = x/R): exactly
    /// what [`Pieces::symmetric`] builds from `vec![piece]` when the piece starts at 0, ends at
    /// infinity and its odd extension is the same polynomial (its mirror image merged with it: no
    /// jump at 0), without the general route's merging or any allocation.
    pub(super) fn whole_line(piece: Piece) -> Self {
        let whole = Piece {
            end: piece.end,
            ..piece.mirrored()
        };
        Self {
            pieces: PieceList::One([whole]),
            jumps: Vec::new(),
            extent: piece.end,
            bounds: (-piece.end, piece.end),
            odd: true,
            knot_moments: Vec::new(),
            convex: Self::slope_never_falls(&[whole], 0.0),
        }
    }

    pub(super) fn check_extent(&self, what: &'static str, needed: f64) -> Result<()> {
        if needed > self.extent {
            Err(Error::BeyondTable {
                what,
                needed,
                table_end: self.extent,
            })
        } else {
            Ok(())
        }
    }

    /// [`Pieces::check_extent`] for the interval `[lo, hi]`: odd slopes check `max(|lo|, |hi|)`
    /// against the extent (the historical message), two-sided ones check both bounds.
    pub(super) fn check_span(&self, what: &'static str, lo: f64, hi: f64) -> Result<()> {
        if self.odd {
            return self.check_extent(what, lo.abs().max(hi.abs()));
        }
        let (lower, upper) = self.bounds;
        if lo < lower || hi > upper {
            Err(Error::OutsideProfile {
                what,
                needed: [lo, hi],
                defined: [lower, upper],
            })
        } else {
            Ok(())
        }
    }

    pub(super) fn index(&self, x: f64) -> usize {
        self.pieces
            .partition_point(|p| p.end < x)
            .min(self.pieces.len() - 1)
    }

    pub(super) fn slope(&self, x: f64) -> f64 {
        self.pieces[self.index(x)].eval(x)
    }

    /// Exact J0, J1 and derivatives: on each piece the integrands are polynomials in cos(theta),
    /// integrated by the moments `M_j = integral cos^j theta dtheta`.
    pub(super) fn integrals(&self, d: f64, e: f64) -> Result<StickIntegrals> {
        self.integrals_over::<true>(d, e, false)
    }

    /// `J1(a, 0)` and `dJ1/da` from the x >= 0 half alone (the integrand is even there).
    pub(super) fn symmetric_moment(&self, a: f64) -> Result<(f64, f64)> {
        if !self.odd {
            return Err(Error::AsymmetricProfile {
                what: "symmetric contact law P(a)",
            });
        }
        let s = self.integrals_over::<false>(a, 0.0, true)?;
        Ok((2.0 * s.j1, 2.0 * s.j1_d))
    }

    /// With `from_centre`, only theta in [0, pi/2] (x >= 0 when e = 0) is integrated. Without
    /// `ALL`, only J1 and dJ1/dd are accumulated (what the contact law needs).
    fn integrals_over<const ALL: bool>(
        &self,
        d: f64,
        e: f64,
        from_centre: bool,
    ) -> Result<StickIntegrals> {
        let (lo, hi) = (e - d, e + d);
        self.check_span("contact or stick zone", lo, hi)?;
        // cos, sin and theta of the point xi, computed from distances to the zone ends so that
        // theta stays accurate near 0 and pi.
        let angle = |x: f64| {
            if x >= hi {
                return (1.0, 0.0);
            }
            if x <= lo {
                return (-1.0, 0.0);
            }
            let c = ((x - e) / d).clamp(-1.0, 1.0);
            (c, ((hi - x) * (x - lo)).sqrt() / d)
        };
        let mut out = StickIntegrals::default();
        let start = if from_centre { e } else { lo };
        let first = self.pieces.partition_point(|p| p.end <= start);
        // Pieces ascend in x, so theta descends: each piece's upper end is the next one's lower.
        let (mut cb, mut sb) = if from_centre { (0.0, 1.0) } else { (-1.0, 0.0) };
        for p in &self.pieces[first..] {
            if p.start >= hi {
                break;
            }
            let (ca, sa) = angle(p.end);
            let mut m = [0.0; 5];
            m[0] = angle_between(ca, sa, cb, sb);
            m[1] = sb - sa;
            m[2] = 0.5 * (cb * sb - ca * sa) + 0.5 * m[0];
            m[3] = (cb * cb * sb - ca * ca * sa) / 3.0 + 2.0 / 3.0 * m[1];
            m[4] = 0.25 * (cb * cb * cb * sb - ca * ca * ca * sa) + 0.75 * m[2];
            (cb, sb) = (ca, sa);
            let [q0, q1, q2] = p.coeffs;
            let u = e - p.origin;
            // g'(xi) and g''(xi) as polynomials in c = cos(theta).
            let g = [q0 + u * (q1 + u * q2), d * (q1 + 2.0 * u * q2), d * d * q2];
            let gx = [q1 + 2.0 * u * q2, 2.0 * q2 * d];
            let xg = [e * g[0], e * g[1] + d * g[0], e * g[2] + d * g[1], d * g[2]];
            let h = [
                g[0] + e * gx[0],
                g[1] + e * gx[1] + d * gx[0],
                g[2] + d * gx[1],
            ];
            out.j1 += xg[0] * m[0] + xg[1] * m[1] + xg[2] * m[2] + xg[3] * m[3];
            out.j1_d += h[0] * m[1] + h[1] * m[2] + h[2] * m[3];
            if ALL {
                out.j0 += g[0] * m[0] + g[1] * m[1] + g[2] * m[2];
                out.j0_e += gx[0] * m[0] + gx[1] * m[1];
                out.j0_d += gx[0] * m[1] + gx[1] * m[2];
                out.j1_e += h[0] * m[0] + h[1] * m[1] + h[2] * m[2];
            }
        }
        // Leibniz terms where g' jumps inside the zone: d(theta_k)/de = 1/(d sin), d/dd = cos/(d sin).
        for &(x, jump) in &self.jumps {
            if x > start && x < hi {
                let (c, s) = angle(x);
                let k = jump / (d * s);
                out.j0_e += k;
                out.j0_d += k * c;
                out.j1_e += x * k;
                out.j1_d += x * k * c;
            }
        }
        Ok(out)
    }
}

/// `theta_b - theta_a` (in [0, pi]) from the cosines and sines of the two angles. Pieces of a fine
/// table subtend small angles, where the odd series of atan is exact to rounding and several times
/// cheaper than `atan2`.
pub(super) fn angle_between(ca: f64, sa: f64, cb: f64, sb: f64) -> f64 {
    let y = sb * ca - cb * sa;
    let x = cb * ca + sb * sa;
    if x > 0.0 && y.abs() <= 0.1 * x {
        // atan z = z (1 - z^2 (1/3 - z^2 (1/5 - ...))), nine terms; the first omitted one,
        // z^19/19, is below 1e-19 |z| for |z| <= 0.1.
        let z = y / x;
        let z2 = z * z;
        const INVERSE_ODD: [f64; 9] = [
            1.0,
            1.0 / 3.0,
            1.0 / 5.0,
            1.0 / 7.0,
            1.0 / 9.0,
            1.0 / 11.0,
            1.0 / 13.0,
            1.0 / 15.0,
            1.0 / 17.0,
        ];
        z * INVERSE_ODD.iter().rev().fold(0.0, |sum, c| c - z2 * sum)
    } else {
        y.atan2(x)
    }
}

#[cfg(test)]
mod tests {
    use super::super::{brute, Profile};
    use super::*;

    #[test]
    fn exact_piecewise_integrals_match_brute_force_quadrature() {
        // Both routes are exact to rounding on smooth panels: tolerance 1e-13 absolute
        // (the integrals are O(0.1)).
        let profile = Profile::flat_rounded(0.5, 10.0).unwrap();
        for (d, e) in [(0.8, 0.0), (0.8, 0.05), (0.7, -0.1), (0.3, 0.0)] {
            let s = profile.stick_integrals(d, e).unwrap();
            let (j0, j1) = brute(&profile, d, e);
            assert!((s.j0 - j0).abs() < 1e-13, "J0({d},{e}): {} vs {j0}", s.j0);
            assert!((s.j1 - j1).abs() < 1e-13, "J1({d},{e}): {} vs {j1}", s.j1);
        }
    }

    #[test]
    fn analytic_derivatives_match_finite_differences() {
        // Central differences with h = 1e-6 have error ~h^2 * J''' ~ 1e-10 plus rounding 1e-10.
        let profiles = [
            Profile::flat_rounded(0.5, 10.0).unwrap(),
            Profile::tabulated(
                vec![0.0, 0.2, 0.5, 1.0, 1.5],
                vec![0.0, 0.0, 0.0, 0.03, 0.1],
                vec![0.5],
            )
            .unwrap(),
        ];
        for p in &profiles {
            let (d, e) = (0.8, 0.07);
            let s = p.stick_integrals(d, e).unwrap();
            let h = 1e-6;
            let f = |d, e| p.stick_integrals(d, e).unwrap();
            let dd =
                |g: fn(&StickIntegrals) -> f64| (g(&f(d + h, e)) - g(&f(d - h, e))) / (2.0 * h);
            let de =
                |g: fn(&StickIntegrals) -> f64| (g(&f(d, e + h)) - g(&f(d, e - h))) / (2.0 * h);
            for (analytic, numeric, name) in [
                (s.j0_d, dd(|s| s.j0), "dJ0/dd"),
                (s.j0_e, de(|s| s.j0), "dJ0/de"),
                (s.j1_d, dd(|s| s.j1), "dJ1/dd"),
                (s.j1_e, de(|s| s.j1), "dJ1/de"),
            ] {
                assert!(
                    (analytic - numeric).abs() < 1e-7 * (1.0 + numeric.abs()),
                    "{name}: {analytic} vs {numeric} for {:?}",
                    p.shape()
                );
            }
        }
    }

    #[test]
    fn angle_between_matches_atan2_on_both_paths() {
        // Series path (small angles) and atan2 path agree with the difference of atan2 values.
        for (ta, tb) in [
            (0.3, 0.31),
            (1.0, 1.05),
            (0.2, 0.2001),
            (0.0, 2.5),
            (1.0, 3.1),
            (0.5, 0.59),
        ] {
            let got = angle_between(f64::cos(ta), f64::sin(ta), f64::cos(tb), f64::sin(tb));
            assert!(
                (got - (tb - ta)).abs() < 2e-16,
                "({ta}, {tb}): {got} vs {}",
                tb - ta
            );
        }
    }
}
