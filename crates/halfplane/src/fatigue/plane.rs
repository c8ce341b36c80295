//! The critical-plane search at one point (`docs/fatigue.md`, "Critical planes"): planes normal to
//! the x-z plane, normal `n = (cos t, sin t)` with t from 0 to 180 degrees, sampled every degree
//! and refined to 0.05 degree around the best sample.
//!
//! On a plane: `sigma_n = (sxx + szz)/2 + (sxx - szz)/2 cos 2t + sxz sin 2t`,
//! `tau = -(sxx - szz)/2 sin 2t + sxz cos 2t`; elastic plane-strain strains
//! `eps_n = ((1 + nu) sigma_n - nu (sxx + syy + szz))/E` and `gamma = tau/G`.

use super::constants::FatigueConstants;
use crate::stress::Stress;

/// The maximum of a parameter over the planes: its value, the plane's normal angle (degrees from
/// `+x` towards `+z`, in [0, 180)), and the index in the history where the plane's normal stress
/// peaks.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Critical {
    /// The parameter's value.
    pub value: f64,
    /// Plane normal angle in degrees.
    pub angle: f64,
    /// Index (0-based) in the stress history of the peak normal stress on that plane.
    pub index: usize,
}

/// The critical-plane parameters at one point.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct PlaneParameters {
    pub swt: Critical,
    pub fatemi_socie: Option<Critical>,
    pub findley: Option<Critical>,
    pub mwcm: Option<Critical>,
}

/// Elastic constants the search needs.
#[derive(Debug, Clone, Copy)]
pub(crate) struct Elastic {
    pub youngs: f64,
    pub poisson: f64,
}

/// What one plane gives over the history.
#[derive(Debug, Clone, Copy)]
struct OnPlane {
    /// `[swt, fatemi_socie, findley]` (`None` without their constants).
    values: [Option<f64>; 3],
    /// Shear stress amplitude, half the range of `tau`.
    tau_a: f64,
    /// Largest normal stress.
    n_max: f64,
    /// Index of the largest normal stress.
    index: usize,
}

/// The plane at `angle` (degrees) over the history. Smith-Watson-Topper
/// `max(sigma_n,max, 0) d(eps_n)/2` (Smith, Watson and Topper, J. Materials 5, 1970); Fatemi-Socie
/// `(d(gamma)/2)(1 + k sigma_n,max/sigma_y)` (Fatemi and Socie, FFEMS 11, 1988); Findley
/// `tau_a + k sigma_n,max` (Findley, J. Eng. Ind. 81, 1959). The shear on these planes has one
/// component (in the x-z plane), so `tau_a` is exactly half its range.
fn on_plane(history: &[Stress], e: Elastic, c: &FatigueConstants, angle: f64) -> OnPlane {
    let (s2, c2) = (2.0 * angle.to_radians()).sin_cos();
    let (mut n_max, mut n_at) = (f64::NEG_INFINITY, 0);
    let (mut eps_lo, mut eps_hi) = (f64::INFINITY, f64::NEG_INFINITY);
    let (mut t_lo, mut t_hi) = (f64::INFINITY, f64::NEG_INFINITY);
    for (k, s) in history.iter().enumerate() {
        let mean = 0.5 * (s.sxx + s.szz);
        let half = 0.5 * (s.sxx - s.szz);
        let sn = mean + half * c2 + s.sxz * s2;
        let tau = -half * s2 + s.sxz * c2;
        let eps = ((1.0 + e.poisson) * sn - e.poisson * (s.sxx + s.syy + s.szz)) / e.youngs;
        if sn > n_max {
            n_max = sn;
            n_at = k;
        }
        eps_lo = eps_lo.min(eps);
        eps_hi = eps_hi.max(eps);
        t_lo = t_lo.min(tau);
        t_hi = t_hi.max(tau);
    }
    let shear_modulus = e.youngs / (2.0 * (1.0 + e.poisson));
    let swt = n_max.max(0.0) * 0.5 * (eps_hi - eps_lo);
    let tau_a = 0.5 * (t_hi - t_lo);
    let fs = match (c.fatemi_socie_k, c.yield_stress) {
        (Some(k), Some(sy)) => Some(tau_a / shear_modulus * (1.0 + k * n_max / sy)),
        _ => None,
    };
    let findley = c.findley_k.map(|k| tau_a + k * n_max);
    OnPlane {
        values: [Some(swt), fs, findley],
        tau_a,
        n_max,
        index: n_at,
    }
}

/// The Modified Wohler Curve Method's effective shear stress amplitude on a plane,
/// `tau_a + kappa rho`, `kappa = tau_-1 - sigma_-1/2`, `rho = sigma_n,max/tau_a` (L. Susmel and
/// P. Lazzarin, FFEMS 25, 2002; L. Susmel and D. Taylor, FFEMS 26, 2003: the fatigue limit is
/// reached when it equals `tau_-1`), with `rho` capped at `rho_lim = tau_-1/(2 tau_-1 - sigma_-1)`
/// (L. Susmel, *Multiaxial Notch Fatigue*, Woodhead 2009), so that `kappa rho <= tau_-1/2`: a
/// large tensile normal stress with a small shear amplitude does not reach the limit on its own.
/// With no shear amplitude at all `rho` is taken as `rho_lim` under tension and 0 otherwise.
/// Tension positive.
pub fn mwcm_effective_shear(tau_a: f64, n_max: f64, axial: f64, torsional: f64) -> f64 {
    let kappa = torsional - 0.5 * axial;
    if kappa <= 0.0 {
        return tau_a;
    }
    // kappa rho_lim = kappa tau_-1 / (2 kappa) = tau_-1/2.
    let cap = 0.5 * torsional;
    let term = if tau_a > 0.0 {
        (kappa * (n_max / tau_a)).min(cap)
    } else if n_max > 0.0 {
        cap
    } else {
        0.0
    };
    tau_a + term
}

/// Searches the planes for each parameter's maximum over `history` (at least one state). SWT,
/// Fatemi-Socie and Findley take the plane where they are largest; the MWCM takes the plane of
/// the largest shear stress amplitude, and of two such planes (`t` and `t + 90`, equal for
/// proportional paths) the one with the larger normal stress (Susmel and Lazzarin 2002), and
/// reports its effective shear stress there.
pub(crate) fn search(history: &[Stress], e: Elastic, c: &FatigueConstants) -> PlaneParameters {
    let mut best: [Option<Critical>; 3] = [None; 3];
    let consider = |angle: f64, best: &mut [Option<Critical>; 3]| {
        let plane = on_plane(history, e, c, angle);
        for (b, v) in best.iter_mut().zip(plane.values) {
            if let Some(v) = v {
                if b.is_none_or(|b| v > b.value) {
                    *b = Some(Critical {
                        value: v,
                        angle,
                        index: plane.index,
                    });
                }
            }
        }
    };
    for d in 0..180 {
        consider(d as f64, &mut best);
    }
    // Refine each parameter around its best sample, to 0.05 degree.
    for p in 0..3 {
        if let Some(b) = best[p] {
            let mut local = best;
            for k in -20..=20 {
                let angle = (b.angle + 0.05 * k as f64).rem_euclid(180.0);
                consider(angle, &mut local);
            }
            best[p] = local[p];
        }
    }
    PlaneParameters {
        swt: best[0].unwrap_or(Critical {
            value: 0.0,
            angle: 0.0,
            index: 0,
        }),
        fatemi_socie: best[1],
        findley: best[2],
        mwcm: c
            .fatigue_limits
            .map(|(axial, torsional)| mwcm(history, e, c, axial, torsional)),
    }
}

/// The MWCM's plane and value (see [`search`]). The plane of the largest shear stress amplitude
/// is found exactly rather than by sampling (near it the normal stress varies to first order in
/// the angle, so a sampled plane would carry that error into `rho`): the largest range of `tau`
/// over all planes is the longest chord of the path of `((sxx - szz)/2, sxz)`, since on the plane
/// at `t` two states differ in shear by `-d sin 2t + e cos 2t` (`d`, `e` their differences in
/// those components), largest, at `sqrt(d^2 + e^2)`, where `2t = atan2(-d, e)`. Of that plane and
/// its twin at `t + 90` (the same amplitude) the one with the larger normal stress is taken.
fn mwcm(
    history: &[Stress],
    e: Elastic,
    c: &FatigueConstants,
    axial: f64,
    torsional: f64,
) -> Critical {
    let (mut longest, mut d, mut f) = (0.0, 0.0, 0.0);
    for (i, a) in history.iter().enumerate() {
        for b in &history[i + 1..] {
            let dd = 0.5 * ((a.sxx - a.szz) - (b.sxx - b.szz));
            let de = a.sxz - b.sxz;
            let l = dd * dd + de * de;
            if l > longest {
                (longest, d, f) = (l, dd, de);
            }
        }
    }
    let angle = (0.5 * f64::atan2(-d, f).to_degrees()).rem_euclid(180.0);
    let twin = (angle + 90.0).rem_euclid(180.0);
    let (p, q) = (
        on_plane(history, e, c, angle),
        on_plane(history, e, c, twin),
    );
    let (angle, p) = if q.n_max > p.n_max {
        (twin, q)
    } else {
        (angle, p)
    };
    Critical {
        value: mwcm_effective_shear(p.tau_a, p.n_max, axial, torsional),
        angle,
        index: p.index,
    }
}

/// Crossland's `sqrt(J2,a) + alpha sigma_H,max` (Crossland, Proc. Int. Conf. Fatigue of Metals,
/// 1956), with the amplitude of `sqrt(J2)` taken as half the longest chord of the deviatoric path
/// (exact for proportional paths, conservative otherwise). `None` without `crossland_alpha`.
pub(crate) fn crossland(history: &[Stress], c: &FatigueConstants) -> Option<(f64, usize)> {
    let alpha = c.crossland_alpha?;
    let dev = |s: &Stress| {
        let m = (s.sxx + s.syy + s.szz) / 3.0;
        [s.sxx - m, s.syy - m, s.szz - m, s.sxz]
    };
    let devs: Vec<[f64; 4]> = history.iter().map(dev).collect();
    let mut chord: f64 = 0.0;
    for i in 0..devs.len() {
        for j in i + 1..devs.len() {
            let (a, b) = (devs[i], devs[j]);
            let d = [a[0] - b[0], a[1] - b[1], a[2] - b[2], a[3] - b[3]];
            let j2 = 0.5 * (d[0] * d[0] + d[1] * d[1] + d[2] * d[2]) + d[3] * d[3];
            chord = chord.max(j2);
        }
    }
    let (mut h_max, mut at) = (f64::NEG_INFINITY, 0);
    for (k, s) in history.iter().enumerate() {
        let h = (s.sxx + s.syy + s.szz) / 3.0;
        if h > h_max {
            h_max = h;
            at = k;
        }
    }
    Some((0.5 * chord.sqrt() + alpha * h_max, at))
}
