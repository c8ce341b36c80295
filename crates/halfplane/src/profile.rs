//! Symmetric gap profiles g(x) and the integrals of their slope g'(x) that the normal and
//! tangential problems need.
//!
//! Everything downstream needs only integrals over a zone `[e - d, e + d]` in the variable
//! `xi = e + d cos(theta)`, which makes the square-root weights of the paper regular
//! (THEORY.md "Permanent stick zone"):
//!
//! - `J0(d, e) = integral_0^pi g'(e + d cos theta) dtheta`
//! - `J1(d, e) = integral_0^pi xi g'(xi) dtheta`
//!
//! and their partial derivatives. The contact law is `P(a) = J1(a, 0)/A`.
//!
//! Two routes compute them:
//! - **piecewise polynomial** (Hertz, flat-rounded, tabulated spline): g' is a polynomial of
//!   degree <= 2 on each piece, so every integral is a combination of the moments
//!   `integral cos^j theta dtheta` over the piece: exact to rounding, with kinks handled by
//!   construction;
//! - **power law** `g = B|x|^k`: Gauss-Jacobi quadrature with weight `|theta - theta0|^(k-1)` on
//!   each side of x = 0, which absorbs the algebraic singularity of g' there.

use crate::error::{physical, physical_positive, Error, Result};
use crate::quadrature::{gauss_legendre, Rule};
use crate::spline;
use std::f64::consts::PI;

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

/// The user-facing description of a profile, as constructed.
#[derive(Debug, Clone, PartialEq)]
pub enum Shape {
    /// Parabolic (Hertz) profile `g = x^2/(2R)`.
    Hertz {
        /// Relative radius of curvature R.
        radius: f64,
    },
    /// Flat punch with rounded edges: `g' = 0` for `|x| <= b`, `g' = sign(x)(|x| - b)/R` beyond.
    FlatRounded {
        /// Half-width b of the flat.
        flat_half_width: f64,
        /// Edge radius R.
        edge_radius: f64,
    },
    /// Power law `g = B|x|^k`, k >= 1.
    PowerLaw {
        /// B.
        coefficient: f64,
        /// k.
        exponent: f64,
    },
    /// Tabulated `g(x)` for x >= 0, extended symmetrically, interpolated by clamped cubic splines
    /// split at the stated kinks.
    Tabulated {
        /// Abscissae, from 0, strictly increasing.
        x: Vec<f64>,
        /// Gap values, non-decreasing.
        g: Vec<f64>,
        /// Abscissae (from `x`) where g' may have a corner or a jump.
        kinks: Vec<f64>,
    },
}

/// A validated symmetric profile, ready for integration.
#[derive(Debug, Clone, PartialEq)]
pub struct Profile {
    shape: Shape,
    slope: Slope,
}

#[derive(Debug, Clone, PartialEq)]
enum Slope {
    Pieces(Pieces),
    Power(PowerSlope),
}

/// J0, J1 and their partial derivatives with respect to d and e.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub(crate) struct StickIntegrals {
    pub j0: f64,
    pub j1: f64,
    pub j0_d: f64,
    pub j0_e: f64,
    pub j1_d: f64,
    pub j1_e: f64,
}

impl Profile {
    /// Hertz profile of relative radius `radius` > 0.
    pub fn hertz(radius: f64) -> Result<Self> {
        physical_positive("profile.radius", radius)?;
        let piece = Piece {
            start: 0.0,
            end: f64::INFINITY,
            origin: 0.0,
            coeffs: [0.0, 1.0 / radius, 0.0],
        };
        Ok(Self {
            shape: Shape::Hertz { radius },
            slope: Slope::Pieces(Pieces::symmetric(vec![piece], &[])),
        })
    }

    /// Flat punch with rounded edges: flat half-width `flat_half_width` >= 0 (0 gives Hertz),
    /// edge radius `edge_radius` > 0.
    pub fn flat_rounded(flat_half_width: f64, edge_radius: f64) -> Result<Self> {
        if !(flat_half_width >= 0.0 && physical("profile.flat_half_width", flat_half_width).is_ok())
        {
            return Err(Error::InvalidInput {
                field: "profile.flat_half_width".into(),
                value: flat_half_width,
                valid: "a finite number from 0 to 1e30",
            });
        }
        physical_positive("profile.radius", edge_radius)?;
        let b = flat_half_width;
        let mut pieces = Vec::new();
        if b > 0.0 {
            pieces.push(Piece {
                start: 0.0,
                end: b,
                origin: 0.0,
                coeffs: [0.0; 3],
            });
        }
        pieces.push(Piece {
            start: b,
            end: f64::INFINITY,
            origin: b,
            coeffs: [0.0, 1.0 / edge_radius, 0.0],
        });
        Ok(Self {
            shape: Shape::FlatRounded {
                flat_half_width,
                edge_radius,
            },
            slope: Slope::Pieces(Pieces::symmetric(pieces, &[])),
        })
    }

    /// Power law `g = coefficient |x|^exponent` with coefficient > 0 and exponent >= 1.
    pub fn power_law(coefficient: f64, exponent: f64) -> Result<Self> {
        physical_positive("profile.coefficient", coefficient)?;
        if !(exponent.is_finite() && (1.0..=64.0).contains(&exponent)) {
            return Err(Error::InvalidInput {
                field: "profile.exponent".into(),
                value: exponent,
                valid: "a finite number with 1 <= k <= 64",
            });
        }
        // R(t) in the integrand is analytic with its nearest singularity at t = 2, so the error
        // falls like 5.8^(-2n): 12 nodes are below rounding.
        let rule = Rule::jacobi(12, exponent - 1.0)?;
        Ok(Self {
            shape: Shape::PowerLaw {
                coefficient,
                exponent,
            },
            slope: Slope::Power(PowerSlope {
                coefficient,
                exponent,
                rule,
            }),
        })
    }

    /// Tabulated profile: `x` from 0, strictly increasing; `g` finite and non-decreasing; `kinks`
    /// a subset of `x` where the interpolant may have a corner or jump in g' (0 allowed: then
    /// g'(0+) is fitted from the data instead of set to 0 by symmetry). At least 3 rows and at
    /// most [`MAX_TABLE_ROWS`].
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
            return Err(table(
                0,
                format!("{} x values but {} g values", x.len(), g.len()),
            ));
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
        if x[0] != 0.0 {
            return Err(table(
                1,
                format!(
                    "x = {}: the first row must be at x = 0 (the profile's centre)",
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
        let mut kinks = kinks;
        kinks.sort_by(f64::total_cmp);
        kinks.dedup();
        let mut cuts = vec![0usize];
        for k in kinks.iter_mut() {
            let k_given = *k;
            // Kinks are matched to a row within 1e-9 of the table's length (decimal inputs such
            // as 0.3 need not be bit-equal to a computed abscissa).
            // x is increasing: the first row within tol is found by bisection, O(log n) per kink.
            let tol = 1e-9 * x[x.len() - 1];
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
        // Two kinks given within the tolerance of one row are one kink (a repeated cut would
        // leave a one-point segment, which has no spline).
        kinks.dedup();
        cuts.dedup();
        cuts.push(x.len() - 1);
        let kink_at_centre = kinks.first() == Some(&0.0);
        let mut pieces = Vec::new();
        for (s, w) in cuts.windows(2).enumerate() {
            let (xs, gs) = (&x[w[0]..=w[1]], &g[w[0]..=w[1]]);
            // The end slope uses the last four points only: copying the whole segment reversed
            // would cost O(rows) per segment.
            let rev = |v: &[f64]| v.iter().rev().take(4).copied().collect::<Vec<_>>();
            let s0 = if s == 0 && !kink_at_centre {
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
        })
    }

    /// The profile as constructed.
    pub fn shape(&self) -> &Shape {
        &self.shape
    }

    /// Largest |x| where the profile is defined (infinite for analytic profiles).
    pub fn extent(&self) -> f64 {
        match &self.slope {
            Slope::Pieces(p) => p.extent,
            Slope::Power(_) => f64::INFINITY,
        }
    }

    /// Points x >= 0 where g' is not smooth (g'' jumps, or g' itself jumps); the profile is
    /// symmetric, so -x is one too.
    pub fn kinks(&self) -> Vec<f64> {
        match &self.shape {
            Shape::Hertz { .. } => vec![],
            Shape::FlatRounded {
                flat_half_width, ..
            } => {
                if *flat_half_width > 0.0 {
                    vec![*flat_half_width]
                } else {
                    vec![]
                }
            }
            Shape::PowerLaw { exponent, .. } => {
                let smooth = exponent.fract() == 0.0 && (*exponent as i64) % 2 == 0;
                if smooth {
                    vec![]
                } else {
                    vec![0.0]
                }
            }
            Shape::Tabulated { kinks, .. } => kinks.clone(),
        }
    }

    /// Profile slope `g'(x)` (odd in x). Errors beyond a tabulated profile's last row.
    pub fn slope(&self, x: f64) -> Result<f64> {
        match &self.slope {
            Slope::Pieces(p) => {
                p.check_extent("profile evaluation", x.abs())?;
                Ok(p.slope(x))
            }
            Slope::Power(p) => Ok(p.slope(x)),
        }
    }

    /// For piecewise-polynomial slopes, the regular part of the pressure integral in closed form:
    /// `integral_0^pi (g'(a cos t) - g'(x))/(a cos t - x) dt` (see [`crate::Contact::pressure`]).
    /// On a piece with `g' = q0 + q1 u + q2 u^2`, `u = xi - o`, the divided difference by the
    /// piece's own formula continued to x is `q1 + q2 (x - 2 o) + q2 xi`, integrated by the moments
    /// `M0 = dt`, `M1 = d(sin t)`; the remainder `(c - g'(x))` multiplies
    /// `integral dt/(a cos t - x) = ln|(k + tan(t/2))/(k - tan(t/2))|/sqrt(a^2 - x^2)`,
    /// `k = sqrt((a - x)/(a + x))`. `None` for the power law.
    pub(crate) fn pressure_integral(&self, a: f64, x: f64) -> Option<f64> {
        let Slope::Pieces(p) = &self.slope else {
            return None;
        };
        let gx = p.slope(x);
        let root = ((a - x) * (a + x)).sqrt();
        let k = ((a - x) / (a + x)).sqrt();
        let log_kernel = |c: f64, s: f64| {
            // tan(t/2) = s/(1 + c); at t = pi the kernel is 0.
            if c <= -1.0 {
                0.0
            } else {
                let u = s / (1.0 + c);
                ((k + u) / (k - u)).abs().ln() / root
            }
        };
        let angle = |xi: f64| {
            let c = (xi / a).clamp(-1.0, 1.0);
            (c, ((a - xi).max(0.0) * (a + xi).max(0.0)).sqrt() / a)
        };
        let first = p.pieces.partition_point(|q| q.end <= -a);
        let mut sum = 0.0;
        let (mut cb, mut sb) = (-1.0, 0.0);
        for q in &p.pieces[first..] {
            if q.start >= a {
                break;
            }
            let (ca, sa) = if q.end >= a { (1.0, 0.0) } else { angle(q.end) };
            let m0 = angle_between(ca, sa, cb, sb);
            let m1 = sb - sa;
            let [_, q1, q2] = q.coeffs;
            sum += (q1 + q2 * (x - 2.0 * q.origin)) * m0 + q2 * a * m1;
            let continued = q.eval(x);
            if !(q.start <= x && x <= q.end) && continued != gx {
                sum += (continued - gx) * (log_kernel(cb, sb) - log_kernel(ca, sa));
            }
            (cb, sb) = (ca, sa);
        }
        Some(sum)
    }

    /// Every x in `(lo, hi)` where the slope formula changes: piece boundaries (spline knots and
    /// kinks) or x = 0 for the power law.
    pub(crate) fn breaks_within(&self, lo: f64, hi: f64) -> Vec<f64> {
        match &self.slope {
            Slope::Pieces(p) => p
                .pieces
                .iter()
                .map(|q| q.start)
                .filter(|&x| x > lo && x < hi)
                .collect(),
            Slope::Power(_) => [0.0].into_iter().filter(|&x| x > lo && x < hi).collect(),
        }
    }

    /// For a tabulated profile: the knot interval `(lo, J1(lo)), (hi, J1(hi))` holding the half-width
    /// whose symmetric moment is `target`, or `Err(last knot)` when the table is too short.
    /// `None` for analytic profiles.
    pub(crate) fn moment_bracket(
        &self,
        target: f64,
    ) -> Option<std::result::Result<[(f64, f64); 2], f64>> {
        let Slope::Pieces(p) = &self.slope else {
            return None;
        };
        let table = &p.knot_moments;
        let last = *table.last()?;
        let i = table.partition_point(|&(_, m)| m < target);
        Some(if i == table.len() {
            Err(last.0 * (target / last.1).sqrt())
        } else {
            Ok([if i == 0 { (0.0, 0.0) } else { table[i - 1] }, table[i]])
        })
    }

    /// The slope formula of the smooth piece containing `inside`, continued analytically to `at`
    /// (`None` where no continuation exists: a non-integer power law across x = 0).
    pub(crate) fn slope_branch(&self, inside: f64, at: f64) -> Option<f64> {
        match &self.slope {
            Slope::Pieces(p) => Some(p.pieces[p.index(inside)].eval(at)),
            Slope::Power(p) => (inside.signum() == at.signum()).then(|| p.slope(at)),
        }
    }

    /// `J1(a, 0) = integral_0^pi a cos(t) g'(a cos t) dt` and its derivative in a: the contact law
    /// is `P = J1/A` (THEORY.md "Normal problem").
    pub(crate) fn symmetric_moment(&self, a: f64) -> Result<(f64, f64)> {
        match &self.slope {
            Slope::Pieces(p) => p.symmetric_moment(a),
            Slope::Power(p) => {
                // integral_0^pi |cos t|^k dt = 2 W_k, W_k = (sqrt(pi)/2) Gamma((k+1)/2)/Gamma(k/2+1).
                let k = p.exponent;
                let wallis =
                    0.5 * PI.sqrt() * libm::tgamma(0.5 * (k + 1.0)) / libm::tgamma(0.5 * k + 1.0);
                let j1 = 2.0 * p.coefficient * k * wallis * a.powf(k);
                Ok((j1, k * j1 / a))
            }
        }
    }

    /// J0, J1 and derivatives over the zone `[e - d, e + d]`.
    pub(crate) fn stick_integrals(&self, d: f64, e: f64) -> Result<StickIntegrals> {
        match &self.slope {
            Slope::Pieces(p) => p.integrals(d, e),
            Slope::Power(p) => Ok(p.integrals(d, e)),
        }
    }
}

/// `g'(x) = sum_j coeffs[j] (x - origin)^j` on `[start, end]`.
#[derive(Debug, Clone, Copy, PartialEq)]
struct Piece {
    start: f64,
    end: f64,
    origin: f64,
    coeffs: [f64; 3],
}

impl Piece {
    fn eval(&self, x: f64) -> f64 {
        let t = x - self.origin;
        self.coeffs[0] + t * (self.coeffs[1] + t * self.coeffs[2])
    }

    /// The piece's mirror image for the odd extension g'(-x) = -g'(x).
    fn mirrored(&self) -> Piece {
        let [c0, c1, c2] = self.coeffs;
        Piece {
            start: -self.end,
            end: -self.start,
            origin: -self.origin,
            coeffs: [-c0, c1, -c2],
        }
    }
}

/// g' as contiguous polynomial pieces over `[-extent, extent]`, with the jumps of g' at breaks.
#[derive(Debug, Clone, PartialEq)]
struct Pieces {
    pieces: Vec<Piece>,
    /// `(x, g'(x+) - g'(x-))` for the breaks where g' jumps, over the whole line.
    jumps: Vec<(f64, f64)>,
    extent: f64,
    /// `(a, J1(a, 0))` at piece boundaries a > 0 of a finite table (all of a small table, a
    /// geometric selection of a large one, always the last): brackets the contact law's inverse.
    knot_moments: Vec<(f64, f64)>,
}

impl Pieces {
    /// Builds the odd extension of pieces given for x >= 0 (starting at 0, contiguous). `breaks`
    /// (sorted) are the x > 0 where g' may jump; x = 0 is always checked.
    fn symmetric(positive: Vec<Piece>, breaks: &[f64]) -> Self {
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
        Self {
            pieces,
            jumps,
            extent,
            knot_moments: Vec::new(),
        }
    }

    fn check_extent(&self, what: &'static str, needed: f64) -> Result<()> {
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

    fn index(&self, x: f64) -> usize {
        self.pieces
            .partition_point(|p| p.end < x)
            .min(self.pieces.len() - 1)
    }

    fn slope(&self, x: f64) -> f64 {
        self.pieces[self.index(x)].eval(x)
    }

    /// Exact J0, J1 and derivatives: on each piece the integrands are polynomials in cos(theta),
    /// integrated by the moments `M_j = integral cos^j theta dtheta`.
    fn integrals(&self, d: f64, e: f64) -> Result<StickIntegrals> {
        self.integrals_over::<true>(d, e, false)
    }

    /// `J1(a, 0)` and `dJ1/da` from the x >= 0 half alone (the integrand is even there).
    fn symmetric_moment(&self, a: f64) -> Result<(f64, f64)> {
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
        self.check_extent("contact or stick zone", lo.abs().max(hi.abs()))?;
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
fn angle_between(ca: f64, sa: f64, cb: f64, sb: f64) -> f64 {
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

/// Power-law slope `g' = B k |x|^(k-1) sign(x)` with a Gauss-Jacobi rule for weight t^(k-1).
#[derive(Debug, Clone, PartialEq)]
struct PowerSlope {
    coefficient: f64,
    exponent: f64,
    rule: Rule,
}

impl PowerSlope {
    fn slope(&self, x: f64) -> f64 {
        self.coefficient * self.exponent * x.abs().powf(self.exponent - 1.0) * x.signum()
    }

    /// J0 and J1 only (no derivatives).
    fn values(&self, d: f64, e: f64) -> (f64, f64) {
        let (b, k) = (self.coefficient, self.exponent);
        if e.abs() >= d {
            // x = 0 is outside the zone: the integrands are smooth.
            let [j0, j1] = gauss_legendre(0.0, PI, |t| {
                let xi = e + d * t.cos();
                let s = self.slope(xi);
                [s, xi * s]
            });
            return (j0, j1);
        }
        // theta0: where xi = e + d cos(theta0) = 0. On each side, with theta = theta0 -/+ L t,
        // |xi| = 2 d sin((theta + theta0)/2) sin(L t / 2) = L t R(t), R smooth and positive.
        let theta0 = ((d - e) * (d + e)).sqrt().atan2(-e);
        let mut j0 = 0.0;
        let mut j1 = 0.0;
        for (length, sign) in [(theta0, 1.0), (PI - theta0, -1.0)] {
            let mut s0 = 0.0;
            let mut s1 = 0.0;
            for (t, w) in self.rule.nodes.iter().zip(&self.rule.weights) {
                let theta = theta0 - sign * length * t;
                // |xi| = L t R(t); xi from one cosine loses at most ~1e-14 relative at the
                // node nearest theta0 (t ~ 0.01), whose weight is small.
                let r = (e + d * theta.cos()).abs() / (length * t);
                let rk1 = r.powf(k - 1.0);
                s0 += w * rk1;
                s1 += w * t * rk1 * r;
            }
            j0 += sign * b * k * length.powf(k) * s0;
            j1 += b * k * length.powf(k + 1.0) * s1;
        }
        (j0, j1)
    }

    /// Values and Jacobian. Because `xi g''(xi) = (k-1) g'(xi)` and the integrals are homogeneous
    /// (J0 of degree k-1, J1 of degree k in (d, e)), `dJ1/de = k J0`,
    /// `d dJ0/dd + e dJ0/de = (k-1) J0` and `d dJ1/dd + e dJ1/de = k J1`: only `dJ0/de` needs a
    /// (forward) difference, step 1e-7 d. Newton needs only an approximate Jacobian; the
    /// solution's accuracy is set by the values.
    fn integrals(&self, d: f64, e: f64) -> StickIntegrals {
        let k = self.exponent;
        let h = 1e-7 * d;
        let (j0, j1) = self.values(d, e);
        let j0_e = (self.values(d, e + h).0 - j0) / h;
        let j1_e = k * j0;
        StickIntegrals {
            j0,
            j1,
            j0_d: ((k - 1.0) * j0 - e * j0_e) / d,
            j0_e,
            j1_d: (k * j1 - e * j1_e) / d,
            j1_e,
        }
    }
}

#[cfg(test)]
mod tests {
    /// Fuzz finding (lib_steady): an edge radius of 5e-324 was accepted; 1/R = inf made the
    /// moments NaN (P(a) = NaN for a flat-rounded punch with b = 1, a = 2). Radii are now bounded
    /// to 1e-30..1e30 (MAGNITUDE_LIMIT).
    #[test]
    fn radius_outside_the_magnitude_range_is_rejected() {
        for r in [5e-324, 1e-310, 9.9e-31, 1.1e30] {
            assert!(super::Profile::hertz(r).is_err(), "R = {r}");
            assert!(super::Profile::flat_rounded(1.0, r).is_err(), "R = {r}");
        }
        assert!(super::Profile::hertz(1e-30).is_ok() && super::Profile::hertz(1e30).is_ok());
    }

    use super::*;

    /// Independent check of the exact piecewise route: composite Gauss-Legendre in theta on the
    /// pointwise slope, 64 panels between consecutive kink angles (so each panel is smooth).
    fn brute(profile: &Profile, d: f64, e: f64) -> (f64, f64) {
        let mut cuts = vec![0.0, PI];
        for k in profile.kinks() {
            for x in [k, -k] {
                let c = (x - e) / d;
                if c.abs() < 1.0 {
                    cuts.push(c.acos());
                }
            }
        }
        cuts.sort_by(f64::total_cmp);
        let mut j = [0.0; 2];
        let n = 64;
        for w in cuts.windows(2) {
            for i in 0..n {
                let a = w[0] + (w[1] - w[0]) * i as f64 / n as f64;
                let b = w[0] + (w[1] - w[0]) * (i + 1) as f64 / n as f64;
                let [u, v] = gauss_legendre(a, b, |t| {
                    let xi = e + d * t.cos();
                    let s = profile.slope(xi).unwrap();
                    [s, xi * s]
                });
                j[0] += u;
                j[1] += v;
            }
        }
        (j[0], j[1])
    }

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

    /// The flat-rounded punch b = 0.3, R = 50 sampled at `rows` evenly spaced x in [0, 2]; the
    /// clamped spline reproduces it exactly (a quadratic on each side of the kink at 0.3).
    fn flat_rounded_table(rows: usize) -> Profile {
        let x: Vec<f64> = (0..rows)
            .map(|i| 2.0 * i as f64 / (rows - 1) as f64)
            .collect();
        let g = x
            .iter()
            .map(|&x| {
                if x <= 0.3 {
                    0.0
                } else {
                    (x - 0.3).powi(2) / 100.0
                }
            })
            .collect();
        Profile::tabulated(x, g, vec![0.3]).unwrap()
    }

    #[test]
    fn a_long_table_is_set_up_in_linear_time_with_exact_brackets() {
        // 100,000 rows took 106 s in release when every knot's J1 was computed (O(n^2)); in
        // linear time they take well under a second even in debug.
        let start = std::time::Instant::now();
        let table = flat_rounded_table(100_001);
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
        let table = flat_rounded_table(41);
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

    #[test]
    fn power_law_integrals_match_brute_force() {
        // k = 2.5 has g' ~ |x|^1.5 at 0, so the brute-force panels next to x = 0 converge only
        // algebraically (~1e-12 with 64 panels); the Jacobi rule must agree to 1e-11.
        let profile = Profile::power_law(0.01, 2.5).unwrap();
        for (d, e) in [(0.8, 0.0), (0.8, 0.05), (0.7, -0.1)] {
            let s = profile.stick_integrals(d, e).unwrap();
            let (j0, j1) = brute(&profile, d, e);
            assert!((s.j0 - j0).abs() < 1e-11, "J0: {} vs {j0}", s.j0);
            assert!((s.j1 - j1).abs() < 1e-11, "J1: {} vs {j1}", s.j1);
        }
    }
}
