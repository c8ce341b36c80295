//! Fatigue constants of the specimen's material ([`FatigueConstants`]), each optional and each
//! validated on its own with an error naming its `[fatigue]` field.

use crate::error::{Error, Result};

/// Material constants for the initiation parameters and life curves (`docs/fatigue.md`). Every
/// field is optional: a parameter or life that needs a missing constant is not reported. Set
/// them with the `with_*` methods, which validate.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct FatigueConstants {
    pub(crate) fatigue_strength: Option<f64>,
    pub(crate) fatigue_strength_exponent: Option<f64>,
    pub(crate) fatigue_ductility: Option<f64>,
    pub(crate) fatigue_ductility_exponent: Option<f64>,
    pub(crate) shear_fatigue_strength: Option<f64>,
    pub(crate) shear_fatigue_ductility: Option<f64>,
    pub(crate) fatemi_socie_k: Option<f64>,
    pub(crate) findley_k: Option<f64>,
    pub(crate) crossland_alpha: Option<f64>,
    pub(crate) yield_stress: Option<f64>,
    pub(crate) threshold: Option<f64>,
    pub(crate) endurance_range: Option<f64>,
    /// `(axial_fatigue_limit, torsional_fatigue_limit)`: sigma_-1 and tau_-1, set together.
    pub(crate) fatigue_limits: Option<(f64, f64)>,
    /// `(mcdiarmid_shear_limit, ultimate_strength)`: t_A,B and sigma_u, set together.
    pub(crate) mcdiarmid: Option<(f64, f64)>,
}

fn check(field: &str, value: f64, ok: bool, valid: &'static str) -> Result<f64> {
    if value.is_finite() && ok {
        Ok(value)
    } else {
        Err(Error::InvalidInput {
            field: format!("fatigue.{field}"),
            value,
            valid,
        })
    }
}

const POSITIVE: &str = "a finite number from 1e-30 to 1e30";

fn positive(field: &str, v: f64) -> Result<f64> {
    check(field, v, (1e-30..=1e30).contains(&v), POSITIVE)
}

fn exponent(field: &str, v: f64) -> Result<f64> {
    check(
        field,
        v,
        v < 0.0 && v > -2.0,
        "a finite exponent with -2 < b < 0 (a Basquin or Coffin-Manson slope)",
    )
}

impl FatigueConstants {
    /// `fatigue_strength` sigma'_f > 0 (Basquin coefficient, stress).
    pub fn with_fatigue_strength(mut self, v: f64) -> Result<Self> {
        self.fatigue_strength = Some(positive("fatigue_strength", v)?);
        Ok(self)
    }
    /// `fatigue_strength_exponent` b, -2 < b < 0 (also used for shear, as b0 = b).
    pub fn with_fatigue_strength_exponent(mut self, v: f64) -> Result<Self> {
        self.fatigue_strength_exponent = Some(exponent("fatigue_strength_exponent", v)?);
        Ok(self)
    }
    /// `fatigue_ductility` eps'_f > 0 (Coffin-Manson coefficient).
    pub fn with_fatigue_ductility(mut self, v: f64) -> Result<Self> {
        self.fatigue_ductility = Some(positive("fatigue_ductility", v)?);
        Ok(self)
    }
    /// `fatigue_ductility_exponent` c, -2 < c < 0 (also used for shear, as c0 = c).
    pub fn with_fatigue_ductility_exponent(mut self, v: f64) -> Result<Self> {
        self.fatigue_ductility_exponent = Some(exponent("fatigue_ductility_exponent", v)?);
        Ok(self)
    }
    /// `shear_fatigue_strength` tau'_f > 0.
    pub fn with_shear_fatigue_strength(mut self, v: f64) -> Result<Self> {
        self.shear_fatigue_strength = Some(positive("shear_fatigue_strength", v)?);
        Ok(self)
    }
    /// `shear_fatigue_ductility` gamma'_f > 0.
    pub fn with_shear_fatigue_ductility(mut self, v: f64) -> Result<Self> {
        self.shear_fatigue_ductility = Some(positive("shear_fatigue_ductility", v)?);
        Ok(self)
    }
    /// `fatemi_socie_k`, 0 <= k <= 10 (typically 0.3 to 1).
    pub fn with_fatemi_socie_k(mut self, v: f64) -> Result<Self> {
        self.fatemi_socie_k = Some(check(
            "fatemi_socie_k",
            v,
            (0.0..=10.0).contains(&v),
            "a number from 0 to 10 (typically 0.3 to 1)",
        )?);
        Ok(self)
    }
    /// `findley_k`, 0 <= k <= 10 (typically 0.2 to 0.3).
    pub fn with_findley_k(mut self, v: f64) -> Result<Self> {
        self.findley_k = Some(check(
            "findley_k",
            v,
            (0.0..=10.0).contains(&v),
            "a number from 0 to 10 (typically 0.2 to 0.3)",
        )?);
        Ok(self)
    }
    /// `crossland_alpha`, 0 <= alpha <= 10: `sqrt(J2,a) + alpha sigma_H,max`.
    pub fn with_crossland_alpha(mut self, v: f64) -> Result<Self> {
        self.crossland_alpha = Some(check(
            "crossland_alpha",
            v,
            (0.0..=10.0).contains(&v),
            "a number from 0 to 10",
        )?);
        Ok(self)
    }
    /// `yield_stress` sigma_y > 0 (Fatemi-Socie's normalisation).
    pub fn with_yield_stress(mut self, v: f64) -> Result<Self> {
        self.yield_stress = Some(positive("yield_stress", v)?);
        Ok(self)
    }
    /// `threshold` Delta K_th > 0 (stress times square root of length).
    pub fn with_threshold(mut self, v: f64) -> Result<Self> {
        self.threshold = Some(positive("threshold", v)?);
        Ok(self)
    }
    /// `endurance_range` Delta sigma_0 > 0 (plain fatigue limit as a range).
    pub fn with_endurance_range(mut self, v: f64) -> Result<Self> {
        self.endurance_range = Some(positive("endurance_range", v)?);
        Ok(self)
    }

    /// `axial_fatigue_limit` sigma_-1 and `torsional_fatigue_limit` tau_-1: the fully reversed
    /// (R = -1) uniaxial and torsional fatigue limits as amplitudes, both > 0 with
    /// `0.5 <= tau_-1/sigma_-1 <= 1`, for the Modified Wohler Curve Method. The lower bound is
    /// Tresca's ratio, where the method's mean-stress slope `kappa = tau_-1 - sigma_-1/2` vanishes
    /// (below it the slope would reward tension); the upper bound, a torsional limit above the
    /// axial one, is not seen in metals.
    pub fn with_fatigue_limits(mut self, axial: f64, torsional: f64) -> Result<Self> {
        let axial = positive("axial_fatigue_limit", axial)?;
        let torsional = positive("torsional_fatigue_limit", torsional)?;
        let ratio = torsional / axial;
        check(
            "torsional_fatigue_limit",
            torsional,
            (0.5..=1.0).contains(&ratio),
            "from 0.5 to 1 times fatigue.axial_fatigue_limit (the torsional fatigue limit tau_-1 of \
             a metal lies between Tresca's sigma_-1/2 and sigma_-1)",
        )?;
        self.fatigue_limits = Some((axial, torsional));
        Ok(self)
    }

    /// `mcdiarmid_shear_limit` t_A,B and `ultimate_strength` sigma_u for McDiarmid's criterion
    /// (McDiarmid, FFEMS 14, 1991): t_A,B the fully reversed shear fatigue limit (amplitude) for
    /// the crack case of the planes searched (case A: shear along the surface; case B: shear
    /// driving the crack into the depth, as on the in-plane planes of a fretting contact), both
    /// > 0 with `t_A,B < sigma_u` (a fatigue limit below the static strength).
    pub fn with_mcdiarmid(mut self, shear_limit: f64, ultimate: f64) -> Result<Self> {
        let shear_limit = positive("mcdiarmid_shear_limit", shear_limit)?;
        let ultimate = positive("ultimate_strength", ultimate)?;
        check(
            "mcdiarmid_shear_limit",
            shear_limit,
            shear_limit < ultimate,
            "below fatigue.ultimate_strength (the shear fatigue limit t_A,B of a metal lies below \
             its ultimate tensile strength sigma_u)",
        )?;
        self.mcdiarmid = Some((shear_limit, ultimate));
        Ok(self)
    }

    /// The `[fatigue]` fields `parameter` needs that are not given (empty: it is evaluated).
    pub fn missing_for(&self, parameter: super::Parameter) -> Vec<&'static str> {
        use super::Parameter as P;
        let limits = self.fatigue_limits.is_some();
        let mcdiarmid = self.mcdiarmid.is_some();
        let needs: &[(&'static str, bool)] = match parameter {
            P::FatemiSocie | P::FatemiSocieMaxPlane => &[
                ("fatemi_socie_k", self.fatemi_socie_k.is_some()),
                ("yield_stress", self.yield_stress.is_some()),
            ],
            P::Findley => &[("findley_k", self.findley_k.is_some())],
            P::Crossland => &[("crossland_alpha", self.crossland_alpha.is_some())],
            P::Mwcm => &[
                ("axial_fatigue_limit", limits),
                ("torsional_fatigue_limit", limits),
            ],
            P::McDiarmid => &[
                ("mcdiarmid_shear_limit", mcdiarmid),
                ("ultimate_strength", mcdiarmid),
            ],
            _ => &[],
        };
        needs
            .iter()
            .filter(|(_, given)| !given)
            .map(|(name, _)| *name)
            .collect()
    }

    /// The critical distance `L = (1/pi)(Delta K_th/Delta sigma_0)^2` (El Haddad, Topper and
    /// Smith 1979; Taylor, *The Theory of Critical Distances*, 2007), when both are given.
    pub fn critical_distance(&self) -> Option<f64> {
        let (k, s) = (self.threshold?, self.endurance_range?);
        Some((k / s).powi(2) / std::f64::consts::PI)
    }
}
