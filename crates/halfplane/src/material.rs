//! Elastic constants and friction, validated when constructed.
//!
//! Plane strain, two elastically similar bodies (so the normal and tangential problems uncouple).
//! The named types keep Young's modulus `E`, the composite compliance `A` and friction `f` apart.

use crate::error::{physical_positive, Error, Result};

/// Young's modulus and Poisson's ratio of both (identical) bodies.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Material {
    youngs_modulus: f64,
    poisson_ratio: f64,
    /// `A = 4(1 - nu^2)/E`, computed once: a solve asks for it many times.
    compliance: f64,
}

impl Material {
    /// `youngs_modulus` E from 1e-30 to 1e30 (MPa in N-mm-MPa units;
    /// [`crate::error::MAGNITUDE_LIMIT`]); `poisson_ratio` 0 <= nu < 0.5.
    pub fn new(youngs_modulus: f64, poisson_ratio: f64) -> Result<Self> {
        physical_positive("material.youngs_modulus", youngs_modulus)?;
        if !(poisson_ratio.is_finite() && (0.0..0.5).contains(&poisson_ratio)) {
            return Err(Error::InvalidInput {
                field: "material.poisson_ratio".into(),
                value: poisson_ratio,
                valid: "a finite number with 0 <= nu < 0.5",
            });
        }
        Ok(Self {
            youngs_modulus,
            poisson_ratio,
            compliance: 4.0 * (1.0 - poisson_ratio * poisson_ratio) / youngs_modulus,
        })
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
    /// (paper, below eq. (3); docs/theory.md, "Conventions").
    pub fn compliance(&self) -> Compliance {
        Compliance(self.compliance)
    }
}

/// Composite compliance `A` (mm^2/N with E in MPa). Obtain it from [`Material::compliance`] or
/// [`Compliance::new`].
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Compliance(f64);

impl Compliance {
    /// A compliance given directly, from 1e-30 to 1e30 ([`crate::error::MAGNITUDE_LIMIT`]).
    pub fn new(value: f64) -> Result<Self> {
        physical_positive("compliance", value).map(Self)
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
    /// `coefficient` from 1e-30 to 1e30 ([`crate::error::MAGNITUDE_LIMIT`]).
    pub fn new(coefficient: f64) -> Result<Self> {
        physical_positive("friction.coefficient", coefficient).map(Self)
    }

    /// The value of f.
    pub fn value(self) -> f64 {
        self.0
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Fuzz finding (lib_steady): E = f64::MIN_POSITIVE was accepted and gave A = inf. Inputs
    /// are now bounded to magnitudes 1e-30..1e30 (MAGNITUDE_LIMIT), so A stays finite.
    #[test]
    fn modulus_outside_the_magnitude_range_is_rejected() {
        for bad in [f64::MIN_POSITIVE, 9.9e-31, 1.1e30, f64::MAX] {
            let e = Material::new(bad, 1e-11).unwrap_err();
            assert!(
                matches!(e, Error::InvalidInput { ref field, .. } if field == "material.youngs_modulus"),
                "E = {bad}: {e}"
            );
        }
        for good in [1e-30, 1e30] {
            let m = Material::new(good, 0.0).unwrap();
            assert!(m.compliance().value().is_finite() && m.compliance().value() > 0.0);
        }
    }
}
