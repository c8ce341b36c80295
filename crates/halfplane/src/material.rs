//! Elastic constants and friction, validated when constructed.
//!
//! Plane strain, two elastically similar bodies (so the normal and tangential problems uncouple).
//! The named types keep Young's modulus `E`, the composite compliance `A` and friction `f` apart.

use crate::error::{positive, Error, Result};

/// Young's modulus and Poisson's ratio of both (identical) bodies.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Material {
    youngs_modulus: f64,
    poisson_ratio: f64,
}

impl Material {
    /// `youngs_modulus` E > 0 (MPa in N-mm-MPa units); `poisson_ratio` 0 <= nu < 0.5.
    pub fn new(youngs_modulus: f64, poisson_ratio: f64) -> Result<Self> {
        positive("material.youngs_modulus", youngs_modulus)?;
        if !(poisson_ratio.is_finite() && (0.0..0.5).contains(&poisson_ratio)) {
            return Err(Error::InvalidInput {
                field: "material.poisson_ratio".into(),
                value: poisson_ratio,
                valid: "a finite number with 0 <= nu < 0.5",
            });
        }
        let material = Self {
            youngs_modulus,
            poisson_ratio,
        };
        // E below about 4/f64::MAX (subnormal-range moduli) passes the checks above but makes
        // A = 4(1 - nu^2)/E overflow to infinity, which every half-width then inherits.
        if !material.compliance().0.is_finite() {
            return Err(Error::InvalidInput {
                field: "material.youngs_modulus".into(),
                value: youngs_modulus,
                valid: "a finite number > 0 large enough that A = 4(1 - nu^2)/E is finite",
            });
        }
        Ok(material)
    }

    /// Young's modulus E.
    pub fn youngs_modulus(&self) -> f64 {
        self.youngs_modulus
    }

    /// Poisson's ratio nu.
    pub fn poisson_ratio(&self) -> f64 {
        self.poisson_ratio
    }

    /// Composite compliance of the two half-planes in plane strain, `A = 4(1 - nu^2)/E`
    /// (paper, below eq. `gap_function`; THEORY.md "Symbols and units").
    pub fn compliance(&self) -> Compliance {
        Compliance(4.0 * (1.0 - self.poisson_ratio * self.poisson_ratio) / self.youngs_modulus)
    }
}

/// Composite compliance `A` (mm^2/N with E in MPa). Obtain it from [`Material::compliance`] or
/// [`Compliance::new`].
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Compliance(f64);

impl Compliance {
    /// A compliance given directly; must be finite and > 0.
    pub fn new(value: f64) -> Result<Self> {
        positive("compliance", value).map(Self)
    }

    /// The value of A.
    pub fn value(self) -> f64 {
        self.0
    }
}

/// Coulomb friction coefficient `f > 0`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Friction(f64);

impl Friction {
    /// `coefficient` must be finite and > 0.
    pub fn new(coefficient: f64) -> Result<Self> {
        positive("friction.coefficient", coefficient).map(Self)
    }

    /// The value of f.
    pub fn value(self) -> f64 {
        self.0
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Fuzz finding (lib_steady): E = f64::MIN_POSITIVE was accepted and gave A = inf.
    #[test]
    fn modulus_whose_compliance_overflows_is_rejected() {
        let e = Material::new(f64::MIN_POSITIVE, 1e-11).unwrap_err();
        assert!(
            matches!(e, Error::InvalidInput { ref field, .. } if field == "material.youngs_modulus")
        );
        // The smallest modulus with a finite compliance is still accepted.
        let m = Material::new(4.0 / f64::MAX * 1.000_001, 0.0).unwrap();
        assert!(m.compliance().value().is_finite());
    }
}
