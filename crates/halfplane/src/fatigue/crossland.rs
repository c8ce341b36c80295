//! Crossland's invariant criterion with the amplitude of `sqrt(J2)` as the radius of the minimum
//! circumscribed ball of the deviatoric stress path (`docs/fatigue.md`, "Crossland").
//!
//! The deviatoric stress lives in a 5-dimensional space in which the Euclidean norm is
//! `sqrt(J2)`; in plane strain its `sxy` and `syz` coordinates vanish, so the path lies in the
//! 3-dimensional subspace with orthonormal coordinates `((sxx - szz)/2, sxz,
//! (2 syy - sxx - szz)/(2 sqrt(3)))` (the sum of their squares is `J2`), and the minimum ball of
//! the path in 5-D is the one in that subspace (its centre lies in the convex hull of the path).

use super::constants::FatigueConstants;
use crate::stress::Stress;

/// The dimension of the deviatoric subspace a plane-strain path spans.
const D: usize = 3;

/// The deviatoric stress of `s` in orthonormal coordinates whose Euclidean norm is `sqrt(J2)`,
/// `J2 = ((sxx - syy)^2 + (syy - szz)^2 + (szz - sxx)^2)/6 + sxz^2` (no `sxy`, `syz`).
pub(crate) fn deviatoric(s: &Stress) -> [f64; D] {
    [
        0.5 * (s.sxx - s.szz),
        s.sxz,
        (2.0 * s.syy - s.sxx - s.szz) / (2.0 * 3f64.sqrt()),
    ]
}

/// A ball: centre and squared radius.
#[derive(Debug, Clone, Copy)]
struct Ball {
    centre: [f64; D],
    radius2: f64,
}

fn dist2(a: &[f64; D], b: &[f64; D]) -> f64 {
    a.iter().zip(b).map(|(x, y)| (x - y) * (x - y)).sum()
}

/// The smallest ball with the points of `boundary` (at most `D + 1`) on its surface: its centre
/// is `p0 + x` with `x` in the span of `v_i = p_i - p0` and `x.v_i = |v_i|^2 / 2` (equal distance
/// to `p0` and `p_i`). The `v_i` are orthonormalised by modified Gram-Schmidt (twice, for
/// orthogonality to rounding), which makes the system lower-triangular; a point whose residual
/// off the span of the earlier ones is at most `dependent` (a length) is affinely dependent on
/// them, lies on their sphere up to rounding (Welzl only adds a point found outside), and is
/// dropped instead of becoming a near-zero pivot that would throw the centre off.
fn ball_through(boundary: &[[f64; D]], dependent: f64) -> Ball {
    let Some(p0) = boundary.first() else {
        return Ball {
            centre: [0.0; D],
            radius2: -1.0,
        };
    };
    let dot = |a: &[f64; D], b: &[f64; D]| a.iter().zip(b).map(|(x, y)| x * y).sum::<f64>();
    let mut basis: Vec<[f64; D]> = Vec::with_capacity(D);
    let mut y: Vec<f64> = Vec::with_capacity(D);
    for p in &boundary[1..] {
        let v: [f64; D] = std::array::from_fn(|d| p[d] - p0[d]);
        let mut r = v;
        for _ in 0..2 {
            for e in &basis {
                let c = dot(&r, e);
                r.iter_mut().zip(e).for_each(|(x, e)| *x -= c * e);
            }
        }
        let norm = dot(&r, &r).sqrt();
        if norm <= dependent || basis.len() == D {
            continue;
        }
        let known: f64 = basis.iter().zip(&y).map(|(e, yj)| dot(&v, e) * yj).sum();
        y.push((0.5 * dot(&v, &v) - known) / norm);
        basis.push(r.map(|x| x / norm));
    }
    let centre: [f64; D] =
        std::array::from_fn(|d| p0[d] + basis.iter().zip(&y).map(|(e, yj)| yj * e[d]).sum::<f64>());
    Ball {
        centre,
        radius2: dist2(&centre, p0),
    }
}

/// Welzl's algorithm with the move-to-front heuristic (E. Welzl, "Smallest enclosing disks (balls
/// and ellipsoids)", LNCS 555, 1991; B. Gartner, "Fast and robust smallest enclosing balls", ESA
/// 1999): the minimum ball of `points[..n]` with `boundary` on its surface.
fn welzl(points: &mut [[f64; D]], n: usize, boundary: &mut Vec<[f64; D]>, tol: &Tolerance) -> Ball {
    let mut ball = ball_through(boundary, tol.dependent);
    if boundary.len() == D + 1 {
        return ball;
    }
    for i in 0..n {
        if dist2(&ball.centre, &points[i]) > ball.radius2 + tol.outside2 {
            boundary.push(points[i]);
            ball = welzl(points, i, boundary, tol);
            boundary.pop();
            points[..=i].rotate_right(1);
        }
    }
    ball
}

/// The tolerances of [`welzl`], relative to the extent `L` of the set (the largest distance
/// from its first point; the diameter is between `L` and `2 L`).
struct Tolerance {
    /// A point is outside when its squared distance from the centre exceeds the squared radius
    /// by more than `1e-12 L^2`, so by more than about `1e-12 L` in distance (`d^2 - r^2 =
    /// (d - r)(d + r)`): well above the rounding of the squared distances (`1e-16 L^2`), so that a
    /// point on the sphere is never taken as outside, which would make a dependent boundary.
    outside2: f64,
    /// A boundary point within `1e-10 L` of the affine hull of the earlier ones is dependent on
    /// them ([`ball_through`]): `1e-10` leaves a margin of six orders above the rounding of the
    /// orthogonalised residual (`1e-16 L`), whose inverse scales the centre's error.
    dependent: f64,
}

/// The radius of the minimum circumscribed ball of `points`, to `1e-12` of the extent of the
/// set (the tolerances of [`Tolerance`]); the returned radius is the largest distance from the
/// centre found, so the ball always covers every point.
pub(crate) fn min_ball_radius(points: &[[f64; D]]) -> f64 {
    if points.is_empty() {
        return 0.0;
    }
    let extent2 = points
        .iter()
        .map(|p| dist2(p, &points[0]))
        .fold(0.0, f64::max);
    let tol = Tolerance {
        outside2: 1e-12 * extent2,
        dependent: 1e-10 * extent2.sqrt(),
    };
    let mut work = points.to_vec();
    let n = work.len();
    let ball = welzl(&mut work, n, &mut Vec::with_capacity(D + 1), &tol);
    points
        .iter()
        .map(|p| dist2(&ball.centre, p))
        .fold(0.0, f64::max)
        .sqrt()
}

/// Crossland's `sqrt(J2,a) + alpha sigma_H,max` (Crossland, Proc. Int. Conf. Fatigue of Metals,
/// 1956), with `sqrt(J2,a)` the radius of the minimum circumscribed ball of the deviatoric stress
/// path (Papadopoulos et al., FFEMS 20, 1997; Dang Van's and Crossland's amplitude for
/// non-proportional paths), which for a proportional path is half its length and otherwise never
/// less than half its longest chord. Tension positive. `None` without `crossland_alpha`; else the
/// value and the index of the peak hydrostatic stress.
pub(crate) fn crossland(history: &[Stress], c: &FatigueConstants) -> Option<(f64, usize)> {
    let alpha = c.crossland_alpha?;
    let path: Vec<[f64; D]> = history.iter().map(deviatoric).collect();
    let (mut h_max, mut at) = (f64::NEG_INFINITY, 0);
    for (k, s) in history.iter().enumerate() {
        let h = (s.sxx + s.syy + s.szz) / 3.0;
        if h > h_max {
            h_max = h;
            at = k;
        }
    }
    Some((min_ball_radius(&path) + alpha * h_max, at))
}

#[cfg(test)]
mod tests {
    use super::{deviatoric, dist2, min_ball_radius, D};
    use crate::stress::Stress;

    type P = [f64; D];

    fn sub(a: &P, b: &P) -> P {
        std::array::from_fn(|d| a[d] - b[d])
    }
    fn dot(a: &P, b: &P) -> f64 {
        a.iter().zip(b).map(|(x, y)| x * y).sum()
    }
    fn cross(a: &P, b: &P) -> P {
        [
            a[1] * b[2] - a[2] * b[1],
            a[2] * b[0] - a[0] * b[2],
            a[0] * b[1] - a[1] * b[0],
        ]
    }

    /// The centres of the balls spanned by subsets of at most `D + 1` points, by closed forms
    /// independent of the Gram solve: the point, the midpoint, the circumcentre of a triangle
    /// `a + (|u|^2 v x w + |v|^2 w x u) / (2 |w|^2)` with `w = u x v`, and the circumcentre of a
    /// tetrahedron by Cramer's rule on `2 (p_i - a).x = |p_i - a|^2`. Degenerate subsets (a
    /// zero cross product or determinant) span no ball and are skipped.
    fn candidate_centres(p: &[P]) -> Vec<P> {
        let n = p.len();
        let mut out = p.to_vec();
        for i in 0..n {
            for j in i + 1..n {
                out.push(std::array::from_fn(|d| 0.5 * (p[i][d] + p[j][d])));
                for k in j + 1..n {
                    let (u, v) = (sub(&p[j], &p[i]), sub(&p[k], &p[i]));
                    let w = cross(&u, &v);
                    let w2 = dot(&w, &w);
                    if w2 > 0.0 {
                        let (a, b) = (cross(&v, &w), cross(&w, &u));
                        out.push(std::array::from_fn(|d| {
                            p[i][d] + (dot(&u, &u) * a[d] + dot(&v, &v) * b[d]) / (2.0 * w2)
                        }));
                    }
                    for l in k + 1..n {
                        let t = sub(&p[l], &p[i]);
                        let det = dot(&u, &cross(&v, &t));
                        if det != 0.0 {
                            let rhs = [dot(&u, &u) / 2.0, dot(&v, &v) / 2.0, dot(&t, &t) / 2.0];
                            // Rows u, v, t; x = (rhs_0 (v x t) + rhs_1 (t x u) + rhs_2 (u x v)) / det.
                            let (vt, tu, uv) = (cross(&v, &t), cross(&t, &u), cross(&u, &v));
                            out.push(std::array::from_fn(|d| {
                                p[i][d] + (rhs[0] * vt[d] + rhs[1] * tu[d] + rhs[2] * uv[d]) / det
                            }));
                        }
                    }
                }
            }
        }
        out
    }

    /// Brute force: the smallest covering radius over the candidate centres. Every candidate
    /// covers with its own farthest distance, so this is an upper bound on the minimum radius,
    /// equal to it up to rounding because the minimum ball is spanned by at most `D + 1` points.
    fn brute_force(p: &[P]) -> f64 {
        candidate_centres(p)
            .iter()
            .map(|c| p.iter().map(|q| dist2(c, q)).fold(0.0, f64::max))
            .fold(f64::INFINITY, f64::min)
            .sqrt()
    }

    /// The ball must cover (by construction of the returned radius), lie between half the
    /// diameter and Jung's bound `sqrt(D / (2 (D + 1)))` times it, and be no larger than the brute
    /// force within `1e-9` of the diameter: rounding in the closed forms of nearly degenerate
    /// subsets (a near-zero determinant) costs more than the `1e-12` of a well-posed solve.
    fn check(p: &[P], what: &str) {
        let r = min_ball_radius(p);
        let diameter = p
            .iter()
            .flat_map(|a| p.iter().map(move |b| dist2(a, b)))
            .fold(0.0, f64::max)
            .sqrt();
        let jung = (D as f64 / (2.0 * (D as f64 + 1.0))).sqrt() * diameter;
        let slack = 1e-12 * diameter;
        assert!(
            r >= 0.5 * diameter - slack && r <= jung + slack,
            "{what}: ball {r} vs diameter {diameter} (Jung {jung}) for {p:?}"
        );
        let best = brute_force(p);
        assert!(
            r <= best + 1e-9 * diameter && best <= r + 1e-9 * diameter,
            "{what}: ball {r} vs brute force {best} for {p:?}"
        );
    }

    /// A small deterministic generator (SplitMix64) so that the paths are reproducible.
    struct Rng(u64);
    impl Rng {
        fn unit(&mut self) -> f64 {
            self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
            let mut z = self.0;
            z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
            z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
            ((z ^ (z >> 31)) >> 11) as f64 / (1u64 << 53) as f64 * 2.0 - 1.0
        }
        fn point(&mut self, scale: f64) -> P {
            std::array::from_fn(|_| scale * self.unit())
        }
    }

    #[test]
    fn degenerate_paths_give_the_minimum_covering_ball() {
        let mut rng = Rng(7);
        for case in 0..6000 {
            let n = 2 + case % 7;
            let scale = 10f64.powi((case % 9) as i32 - 4);
            let origin = rng.point(scale * 10.0);
            let (e1, e2) = (rng.point(1.0), rng.point(1.0));
            let kind = case % 6;
            let mut p: Vec<P> = (0..n)
                .map(|_| {
                    let (s, t) = (rng.unit(), rng.unit());
                    let eps = 10f64.powi(-(4 + (case % 11) as i32));
                    let off = rng.point(eps);
                    match kind {
                        // Collinear and nearly collinear.
                        0 => std::array::from_fn(|d| origin[d] + scale * s * e1[d]),
                        1 => std::array::from_fn(|d| origin[d] + scale * (s * e1[d] + off[d])),
                        // Coplanar (a 2-D affine subspace of 3-D) and nearly coplanar.
                        2 => std::array::from_fn(|d| origin[d] + scale * (s * e1[d] + t * e2[d])),
                        3 => std::array::from_fn(|d| {
                            origin[d] + scale * (s * e1[d] + t * e2[d] + off[d])
                        }),
                        4 => std::array::from_fn(|d| origin[d] + scale * (s * e1[d] + off[d] * t)),
                        // A lattice: many ties (cospherical subsets), as in the fuzzed path.
                        _ => std::array::from_fn(|_| scale * (2.0 * rng.unit()).round() * 0.5),
                    }
                })
                .collect();
            // Repeated points: copies of the first and of a random one, some nudged by rounding.
            for k in 0..case % 6 {
                let q = p[k % p.len()];
                p.push(if k % 2 == 0 {
                    q
                } else {
                    q.map(|x| x * (1.0 + 1e-16))
                });
            }
            check(&p, &format!("case {case} kind {kind}"));
        }
    }

    /// The path `fatigue_constants` found (three identical states, two nearly collinear with
    /// them): the returned ball was 3.84 against a half chord of 1.97, above Jung's bound.
    #[test]
    fn the_fuzzed_path_gives_the_minimum_covering_ball() {
        let s = |sxx, szz, syy, sxz| Stress { sxx, szz, syy, sxz };
        let path = [
            s(-1.0, -1.0, -1.0, -1.0),
            s(-1.0, -1.0, -1.0, -1.0),
            s(-1.0, -6.823529411764706, 1e-8, 1e-8),
            s(1e-8, 1e-8, 1e-8, 1e-300),
            s(-1.0, -1.0, -1.0, -1.0),
            s(-1.0, 3.885332901e-313, 0.0, 0.0),
        ];
        let p: Vec<P> = path.iter().map(deviatoric).collect();
        check(&p, "fuzzed path");
    }
}
