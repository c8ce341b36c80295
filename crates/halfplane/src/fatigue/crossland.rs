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

/// The smallest ball with every point of `boundary` (affinely independent, at most `D + 1`) on
/// its surface: its centre is `p0 + sum_i l_i (p_i - p0)` in their affine hull, with
/// `2 (p_i - p0).(p_j - p0) l_j = |p_i - p0|^2` (Gaussian elimination with partial pivoting; a
/// pivot below `1e-13` of the largest entry is a degenerate set, whose direction is left out:
/// the caller's final covering check absorbs it).
fn ball_through(boundary: &[[f64; D]]) -> Ball {
    let Some(p0) = boundary.first() else {
        return Ball {
            centre: [0.0; D],
            radius2: -1.0,
        };
    };
    let k = boundary.len() - 1;
    let v: Vec<[f64; D]> = boundary[1..]
        .iter()
        .map(|p| std::array::from_fn(|d| p[d] - p0[d]))
        .collect();
    let dot = |a: &[f64; D], b: &[f64; D]| a.iter().zip(b).map(|(x, y)| x * y).sum::<f64>();
    let mut m: Vec<Vec<f64>> = (0..k)
        .map(|i| {
            let mut row: Vec<f64> = (0..k).map(|j| 2.0 * dot(&v[i], &v[j])).collect();
            row.push(dot(&v[i], &v[i]));
            row
        })
        .collect();
    let scale = m
        .iter()
        .flat_map(|r| r.iter())
        .fold(0.0f64, |a, x| a.max(x.abs()));
    let mut l = vec![0.0; k];
    let mut pivots = vec![None; k];
    for col in 0..k {
        let Some(p) = (col..k).max_by(|&a, &b| m[a][col].abs().total_cmp(&m[b][col].abs())) else {
            break;
        };
        if m[p][col].abs() <= 1e-13 * scale {
            continue;
        }
        m.swap(col, p);
        pivots[col] = Some(col);
        let pivot = m[col].clone();
        for (r, row) in m.iter_mut().enumerate() {
            if r != col {
                let f = row[col] / pivot[col];
                for (x, p) in row[col..].iter_mut().zip(&pivot[col..]) {
                    *x -= f * p;
                }
            }
        }
    }
    for (i, p) in pivots.iter().enumerate() {
        if p.is_some() {
            l[i] = m[i][k] / m[i][i];
        }
    }
    let centre: [f64; D] =
        std::array::from_fn(|d| p0[d] + (0..k).map(|i| l[i] * v[i][d]).sum::<f64>());
    Ball {
        centre,
        radius2: dist2(&centre, p0),
    }
}

/// Welzl's algorithm with the move-to-front heuristic (E. Welzl, "Smallest enclosing disks (balls
/// and ellipsoids)", LNCS 555, 1991; B. Gartner, "Fast and robust smallest enclosing balls", ESA
/// 1999): the minimum ball of `points[..n]` with `boundary` on its surface.
fn welzl(points: &mut [[f64; D]], n: usize, boundary: &mut Vec<[f64; D]>, tol2: f64) -> Ball {
    let mut ball = ball_through(boundary);
    if boundary.len() == D + 1 {
        return ball;
    }
    for i in 0..n {
        if dist2(&ball.centre, &points[i]) > ball.radius2 + tol2 {
            boundary.push(points[i]);
            ball = welzl(points, i, boundary, tol2);
            boundary.pop();
            points[..=i].rotate_right(1);
        }
    }
    ball
}

/// The radius of the minimum circumscribed ball of `points`: exact up to rounding; a point
/// counts as inside when its squared distance exceeds the squared radius by at most `1e-24`
/// of the squared extent of the set (a relative tolerance of `1e-12` on distances), and the
/// returned radius is the largest distance from the centre found, so the ball always covers
/// every point.
pub(crate) fn min_ball_radius(points: &[[f64; D]]) -> f64 {
    if points.is_empty() {
        return 0.0;
    }
    let extent2 = points
        .iter()
        .map(|p| dist2(p, &points[0]))
        .fold(0.0, f64::max);
    let mut work = points.to_vec();
    let n = work.len();
    let ball = welzl(
        &mut work,
        n,
        &mut Vec::with_capacity(D + 1),
        1e-24 * extent2,
    );
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
