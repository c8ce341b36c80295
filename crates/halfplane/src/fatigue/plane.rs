//! The critical-plane search at one point (`docs/fatigue.md`, "Critical planes"), in-plane:
//! planes normal to the x-z plane, normal `n = (cos t, 0, sin t)` with t from 0 to 180 degrees,
//! sampled every degree and refined to 0.05 degree around the best sample; the plane of the
//! largest shear range found exactly. The 3-D search is in `space.rs`.
//!
//! On a plane: `sigma_n = (sxx + szz)/2 + (sxx - szz)/2 cos 2t + sxz sin 2t`,
//! `tau = -(sxx - szz)/2 sin 2t + sxz cos 2t`; elastic strains
//! `eps_n = ((1 + nu) sigma_n - nu (sxx + syy + szz))/E` and `gamma = tau/G`.

use super::constants::FatigueConstants;
use crate::stress::Stress;

/// The maximum of a parameter over the planes: its value, the plane's normal (angle in the x-z
/// plane and tilt towards `y`), and the index in the history where the plane's normal stress
/// peaks.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Critical {
    /// The parameter's value.
    pub value: f64,
    /// Plane normal angle in degrees from `+x` towards `+z`, in [0, 180): the normal is
    /// `(cos angle cos tilt, sin tilt, sin angle cos tilt)`.
    pub angle: f64,
    /// Tilt of the normal out of the x-z plane towards `+y`, degrees in [0, 90] (0 for every
    /// in-plane search).
    pub tilt: f64,
    /// Index (0-based) in the stress history of the peak normal stress on that plane.
    pub index: usize,
}

/// The critical-plane parameters at one point.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct PlaneParameters {
    pub swt: Critical,
    pub fatemi_socie: Option<Critical>,
    pub fatemi_socie_max_plane: Option<Critical>,
    pub findley: Option<Critical>,
    pub mwcm: Option<Critical>,
    pub mcdiarmid: Option<Critical>,
}

/// Elastic constants the search needs.
#[derive(Debug, Clone, Copy)]
pub(crate) struct Elastic {
    pub youngs: f64,
    pub poisson: f64,
}

impl Elastic {
    pub fn shear_modulus(self) -> f64 {
        self.youngs / (2.0 * (1.0 + self.poisson))
    }
}

/// What one plane gives over the history.
#[derive(Debug, Clone, Copy)]
pub(crate) struct OnPlane {
    /// Shear stress amplitude: half the longest chord of the path of the shear stress vector on
    /// the plane (half the range of its one component for planes containing `y`).
    pub tau_a: f64,
    /// Largest normal stress.
    pub n_max: f64,
    /// Index of the largest normal stress.
    pub index: usize,
    /// Range of the normal strain.
    pub eps_range: f64,
}

impl OnPlane {
    /// `[swt, fatemi_socie, findley]` on this plane (`None` without their constants):
    /// Smith-Watson-Topper `max(sigma_n,max, 0) d(eps_n)/2` (Smith, Watson and Topper, J. Materials
    /// 5, 1970); Fatemi-Socie `(d(gamma)/2)(1 + k sigma_n,max/sigma_y)` with
    /// `d(gamma)/2 = tau_a/G` (Fatemi and Socie, FFEMS 11, 1988, eq. 2); Findley
    /// `tau_a + k sigma_n,max` (Findley, J. Eng. Ind. 81, 1959). Tension positive.
    pub fn values(&self, e: Elastic, c: &FatigueConstants) -> [Option<f64>; 3] {
        [
            Some(self.n_max.max(0.0) * 0.5 * self.eps_range),
            self.fatemi_socie(e, c),
            c.findley_k.map(|k| self.tau_a + k * self.n_max),
        ]
    }

    /// Fatemi-Socie on this plane (see [`OnPlane::values`]).
    pub fn fatemi_socie(&self, e: Elastic, c: &FatigueConstants) -> Option<f64> {
        let (k, sy) = (c.fatemi_socie_k?, c.yield_stress?);
        Some(self.tau_a / e.shear_modulus() * (1.0 + k * self.n_max / sy))
    }
}

/// The plane at `angle` (degrees, normal in the x-z plane) over the history. The shear on these
/// planes has one component (in the x-z plane: `syx = syz = 0`), so `tau_a` is exactly half its
/// range.
pub(crate) fn on_plane(history: &[Stress], e: Elastic, angle: f64) -> OnPlane {
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
    OnPlane {
        tau_a: 0.5 * (t_hi - t_lo),
        n_max,
        index: n_at,
        eps_range: eps_hi - eps_lo,
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

/// McDiarmid's equivalent shear stress amplitude on a plane, `tau_a + t_AB sigma_n,max/(2 sigma_u)`
/// (D. L. McDiarmid, FFEMS 14, 1991, eq. 6, "A general criterion for high cycle multiaxial
/// fatigue failure"; FFEMS 17, 1994): the criterion `tau_a/t_AB + sigma_n,max/(2 sigma_u) = 1`
/// multiplied by `t_AB`, so the fatigue limit is reached when it equals `t_AB`, the shear fatigue
/// strength for the crack case (A or B) of the plane. Tension positive.
pub fn mcdiarmid_equivalent_shear(tau_a: f64, n_max: f64, shear_limit: f64, ultimate: f64) -> f64 {
    tau_a + shear_limit * n_max / (2.0 * ultimate)
}

/// The parameters evaluated on the plane of the largest shear range (`plane`, its angle and tilt
/// in degrees): Fatemi-Socie as its authors define it, the MWCM and McDiarmid.
pub(crate) fn on_shear_plane(
    plane: &OnPlane,
    angle: f64,
    tilt: f64,
    e: Elastic,
    c: &FatigueConstants,
) -> [Option<Critical>; 3] {
    let critical = |value: f64| Critical {
        value,
        angle,
        tilt,
        index: plane.index,
    };
    [
        plane.fatemi_socie(e, c).map(critical),
        c.fatigue_limits
            .map(|(a, t)| critical(mwcm_effective_shear(plane.tau_a, plane.n_max, a, t))),
        c.mcdiarmid
            .map(|(t, u)| critical(mcdiarmid_equivalent_shear(plane.tau_a, plane.n_max, t, u))),
    ]
}

/// Searches the planes containing `y` for each parameter's maximum over `history` (at least one
/// state). SWT, the max-plane Fatemi-Socie and Findley take the plane where they are largest;
/// Fatemi-Socie, the MWCM and McDiarmid are evaluated on the plane of the largest shear stress
/// range ([`max_shear_plane`]).
pub(crate) fn search(history: &[Stress], e: Elastic, c: &FatigueConstants) -> PlaneParameters {
    let mut best: [Option<Critical>; 3] = [None; 3];
    let consider = |angle: f64, best: &mut [Option<Critical>; 3]| {
        let plane = on_plane(history, e, angle);
        for (b, v) in best.iter_mut().zip(plane.values(e, c)) {
            if let Some(v) = v {
                if b.is_none_or(|b| v > b.value) {
                    *b = Some(Critical {
                        value: v,
                        angle,
                        tilt: 0.0,
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
                let angle = half_turn(b.angle + 0.05 * k as f64);
                consider(angle, &mut local);
            }
            best[p] = local[p];
        }
    }
    let (angle, plane) = max_shear_plane(history, e);
    let [fatemi_socie, mwcm, mcdiarmid] = on_shear_plane(&plane, angle, 0.0, e, c);
    PlaneParameters {
        swt: best[0].unwrap_or(Critical {
            value: 0.0,
            angle: 0.0,
            tilt: 0.0,
            index: 0,
        }),
        fatemi_socie,
        fatemi_socie_max_plane: best[1],
        findley: best[2],
        mwcm,
        mcdiarmid,
    }
}

/// The in-plane plane of the largest shear stress range (and so, elastically, of the largest
/// shear strain range), found exactly rather than by sampling (near it the normal stress varies
/// to first order in the angle, so a sampled plane would carry that error into the parameters):
/// the largest range of `tau` over the planes is the longest chord of the path of
/// `((sxx - szz)/2, sxz)`, since on the plane at `t` two states differ in shear by
/// `-d sin 2t + e cos 2t` (`d`, `e` their differences in those components), largest, at
/// `sqrt(d^2 + e^2)`, where `2t = atan2(-d, e)`. Of that plane and its twin at `t + 90` (the same
/// shear range) the one with the larger normal stress is taken (Susmel and Lazzarin 2002; the
/// larger, so the more damaging, value for every criterion evaluated there).
pub(crate) fn max_shear_plane(history: &[Stress], e: Elastic) -> (f64, OnPlane) {
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
    let angle = half_turn(0.5 * f64::atan2(-d, f).to_degrees());
    let twin = half_turn(angle + 90.0);
    let (p, q) = (on_plane(history, e, angle), on_plane(history, e, twin));
    if q.n_max > p.n_max {
        (twin, q)
    } else {
        (angle, p)
    }
}

/// `degrees` folded into [0, 180). `rem_euclid` alone returns 180.0 itself for a negative angle
/// within rounding of 0 (-1e-17 + 180 rounds to 180), which names no plane of the range.
pub(super) fn half_turn(degrees: f64) -> f64 {
    let folded = degrees.rem_euclid(180.0);
    if folded < 180.0 {
        folded
    } else {
        0.0
    }
}

#[cfg(test)]
mod tests {
    use super::half_turn;

    #[test]
    fn plane_angles_stay_below_a_half_turn() {
        // The fuzz target `fatigue_constants` found a plane reported at 180.0: rem_euclid of an
        // angle a rounding step below 0 rounds up to the modulus itself.
        assert_eq!((-1e-17_f64).rem_euclid(180.0), 180.0);
        for (given, folded) in [
            (-1e-17, 0.0),
            (0.0, 0.0),
            (180.0, 0.0),
            (-90.0, 90.0),
            (270.0, 90.0),
        ] {
            assert_eq!(half_turn(given), folded, "{given}");
        }
        for k in -1000..1000 {
            let a = half_turn(k as f64 * 0.37 - 1e-15);
            assert!((0.0..180.0).contains(&a), "{a}");
        }
    }
}
