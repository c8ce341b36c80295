//! # halfplane
//!
//! Frictional contact of elastically similar bodies idealised as half-planes, under varying
//! normal load P, shear load Q and bulk tension sigma. See `THEORY.md` in the project for the sign
//! conventions.

pub mod error;
pub mod load;
pub mod material;
pub mod profile;
mod quadrature;
mod spline;

pub use error::{Error, Result};
pub use load::{Cycle, LoadPoint};
pub use material::{Compliance, Friction, Material};
pub use profile::{Profile, Shape};
pub mod closed_form;
pub mod normal;
pub mod steady;

pub use normal::Contact;
pub use steady::{analyse, Regime, SteadyOptions, SteadyState, StickZone};
pub mod asymptotic;
pub mod evolution;
