//! The full 3-D critical-plane search (`[fatigue] planes = "3d"`, `docs/fatigue.md`): every
//! plane, normal `n = (cos t cos b, sin b, sin t cos b)` with the angle `t` in the x-z plane and the
//! tilt `b` towards `y`, using the out-of-plane stress `syy` of plane strain. The stress tensor has
//! `sxy = syz = 0`, so `y` is always a principal direction and the reflection `y -> -y` maps every
//! plane onto one with the same values: `t` in [0, 180) and `b` in [0, 90] cover them all.
//!
//! The sampled parameters (SWT, max-plane Fatemi-Socie, Findley) take the larger of the in-plane
//! search (`plane.rs`, so the 3-D value is never below it) and a 6-degree grid of `(t, b)` refined
//! by a pattern search to 0.05 degree. The plane of the largest shear range is found exactly.

use super::constants::FatigueConstants;
use super::plane::{self, half_turn, on_shear_plane, Critical, Elastic, OnPlane, PlaneParameters};
use crate::stress::Stress;

/// A plane's unit normal and two unit shear directions on it.
struct Frame {
    n: [f64; 3],
    m1: [f64; 3],
    m2: [f64; 3],
}

fn frame(angle: f64, tilt: f64) -> Frame {
    let (st, ct) = angle.to_radians().sin_cos();
    let (sb, cb) = tilt.to_radians().sin_cos();
    Frame {
        n: [ct * cb, sb, st * cb],
        m1: [-st, 0.0, ct],
        m2: [-ct * sb, cb, -st * sb],
    }
}

/// `(sigma . n)` for the plane-strain tensor `s` (`sxy = syz = 0`).
fn traction(s: &Stress, n: &[f64; 3]) -> [f64; 3] {
    [
        s.sxx * n[0] + s.sxz * n[2],
        s.syy * n[1],
        s.sxz * n[0] + s.szz * n[2],
    ]
}

fn dot(a: &[f64; 3], b: &[f64; 3]) -> f64 {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}

/// The plane `(angle, tilt)` over the history. `tau_a` is half the longest chord of the path of the
/// shear stress vector on the plane (the largest range of the shear resolved along any direction
/// of the plane), computed only when `shear` is true (else 0).
fn on_plane(history: &[Stress], e: Elastic, angle: f64, tilt: f64, shear: bool) -> OnPlane {
    let f = frame(angle, tilt);
    let (mut n_max, mut n_at) = (f64::NEG_INFINITY, 0);
    let (mut eps_lo, mut eps_hi) = (f64::INFINITY, f64::NEG_INFINITY);
    let mut path = Vec::with_capacity(if shear { history.len() } else { 0 });
    for (k, s) in history.iter().enumerate() {
        let t = traction(s, &f.n);
        let sn = dot(&t, &f.n);
        let eps = ((1.0 + e.poisson) * sn - e.poisson * (s.sxx + s.syy + s.szz)) / e.youngs;
        if sn > n_max {
            n_max = sn;
            n_at = k;
        }
        eps_lo = eps_lo.min(eps);
        eps_hi = eps_hi.max(eps);
        if shear {
            path.push([dot(&t, &f.m1), dot(&t, &f.m2)]);
        }
    }
    let mut longest: f64 = 0.0;
    for (i, a) in path.iter().enumerate() {
        for b in &path[i + 1..] {
            longest = longest.max((a[0] - b[0]).powi(2) + (a[1] - b[1]).powi(2));
        }
    }
    OnPlane {
        tau_a: 0.5 * longest.sqrt(),
        n_max,
        index: n_at,
        eps_range: eps_hi - eps_lo,
    }
}

/// The plane `(angle, tilt)` folded into `t` in [0, 180), `b` in [0, 90] (see the module notes).
fn fold(angle: f64, tilt: f64) -> (f64, f64) {
    let b = tilt.rem_euclid(360.0);
    let (angle, b) = if b > 180.0 {
        (angle, 360.0 - b)
    } else {
        (angle, b)
    };
    let (angle, b) = if b > 90.0 {
        (angle + 180.0, 180.0 - b)
    } else {
        (angle, b)
    };
    (half_turn(angle), b)
}

/// The 3-D plane of the largest shear stress range, exactly: between two states the largest
/// resolved shear range over all planes and directions is half the spread of the principal
/// values of their difference (Mohr), on the plane bisecting its extreme principal directions.
/// With `y` principal that spread is `max(2r, |dyy - m| + r)` for the x-z block's mean `m` and
/// radius `r`: when `2r` wins the plane contains `y` (the in-plane result); otherwise it is tilted
/// 45 degrees from `y` towards the in-plane principal direction farther from `dyy`, and its twin
/// is its mirror in `y` (the same values).
fn max_shear_plane(history: &[Stress], e: Elastic) -> (f64, f64, OnPlane) {
    let (mut spread, mut tilted) = (0.0, None);
    for (i, a) in history.iter().enumerate() {
        for b in &history[i + 1..] {
            let (dxx, dzz, dxz, dyy) = (a.sxx - b.sxx, a.szz - b.szz, a.sxz - b.sxz, a.syy - b.syy);
            let (m, h) = (0.5 * (dxx + dzz), 0.5 * (dxx - dzz));
            let r = h.hypot(dxz);
            let out = (dyy - m).abs() + r;
            if (2.0 * r).max(out) > spread {
                spread = (2.0 * r).max(out);
                // The in-plane principal direction of m + r is at 0.5 atan2(dxz, h); the one of
                // m - r is 90 degrees away.
                let first = 0.5 * dxz.atan2(h).to_degrees();
                tilted = (out > 2.0 * r).then_some(if dyy < m { first } else { first + 90.0 });
            }
        }
    }
    match tilted {
        Some(t) => {
            let (angle, tilt) = fold(t, 45.0);
            (angle, tilt, on_plane(history, e, angle, tilt, true))
        }
        None => {
            let (angle, p) = plane::max_shear_plane(history, e);
            (angle, 0.0, p)
        }
    }
}

/// Searches every plane for each parameter's maximum (see the module notes).
pub(crate) fn search(history: &[Stress], e: Elastic, c: &FatigueConstants) -> PlaneParameters {
    let in_plane = plane::search(history, e, c);
    let mut best = [
        Some(in_plane.swt),
        in_plane.fatemi_socie_max_plane,
        in_plane.findley,
    ];
    let (s_angle, s_tilt, s_plane) = max_shear_plane(history, e);
    // No plane's shear amplitude exceeds the largest one, so a plane whose values cannot beat the
    // best so far even with it is not given the (quadratic) shear-path chord.
    let tau_max = s_plane.tau_a;
    let consider = |angle: f64, tilt: f64, best: &mut [Option<Critical>; 3]| {
        let (angle, tilt) = fold(angle, tilt);
        let normal = on_plane(history, e, angle, tilt, false);
        let bound = OnPlane {
            tau_a: tau_max,
            ..normal
        };
        let promising = bound.values(e, c)[1..]
            .iter()
            .zip(&best[1..])
            .any(|(v, b)| matches!((v, b), (Some(v), Some(b)) if v.max(0.0) > b.value));
        let plane = if promising {
            on_plane(history, e, angle, tilt, true)
        } else {
            normal
        };
        for (j, (b, v)) in best.iter_mut().zip(plane.values(e, c)).enumerate() {
            if let Some(v) = v {
                if (j == 0 || promising) && b.is_none_or(|b| v > b.value) {
                    *b = Some(Critical {
                        value: v,
                        angle,
                        tilt,
                        index: plane.index,
                    });
                }
            }
        }
    };
    for i in 0..30 {
        for j in 0..=15 {
            consider(6.0 * i as f64, 6.0 * j as f64, &mut best);
        }
    }
    // Pattern search around each parameter's best plane, halving the step down to 0.05 degree.
    for p in 0..3 {
        let Some(mut at) = best[p] else { continue };
        let mut step = 3.0;
        while step >= 0.05 {
            let mut local = best;
            for (da, db) in [(1.0, 0.0), (-1.0, 0.0), (0.0, 1.0), (0.0, -1.0)] {
                consider(at.angle + da * step, at.tilt + db * step, &mut local);
            }
            match local[p] {
                Some(l) if l.value > at.value => (at, best[p]) = (l, Some(l)),
                _ => step *= 0.5,
            }
        }
    }
    let [fatemi_socie, mwcm, mcdiarmid] = on_shear_plane(&s_plane, s_angle, s_tilt, e, c);
    PlaneParameters {
        swt: best[0].unwrap_or(in_plane.swt),
        fatemi_socie,
        fatemi_socie_max_plane: best[1],
        findley: best[2],
        mwcm,
        mcdiarmid,
    }
}
