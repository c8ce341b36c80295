//! # halfplane
//!
//! Frictional contact of elastically similar bodies idealised as half-planes, under varying
//! normal load P, shear load Q and bulk tension sigma (plane strain, Coulomb friction).
//!
//! The sign conventions are those of `docs/theory.md`: point 1 of a cycle is the end with
//! the smaller Q, `dQ = Q2 - Q1 >= 0`, `dsigma = sigma1 - sigma2`, and bulk tension adds to the
//! shear at the left edge. Every function that implements a formula cites the paper's equation
//! label (Andresen, Hills, Barber & Vazquez) or its reference.
//!
//! ```
//! use halfplane::{steady, Contact, Cycle, Friction, LoadPoint, Material, Profile, SteadyOptions};
//!
//! let contact = Contact::new(Profile::hertz(50.0)?, Material::new(200_000.0, 0.3)?, Friction::new(0.6)?);
//! let cycle = Cycle::new(
//!     LoadPoint::new("point1", 1000.0, -250.0, -20.0)?,
//!     LoadPoint::new("point2", 1400.0, 250.0, 20.0)?,
//! );
//! let state = steady::analyse(&contact, &cycle, &SteadyOptions::default())?;
//! let zone = state.stick_zone.unwrap();
//! assert!((zone.right - 0.68123).abs() < 1e-5); // the reference cycle's checked value
//! # Ok::<(), halfplane::Error>(())
//! ```
//!
//! Modules, one per concept: [`batch`] (many cases on every core, streamed), [`design`] (grid,
//! random and Latin-hypercube sweep designs, reproducible row by row), [`profile`] (gap profiles and their integrals), [`normal`] (the
//! normal problem, [`Contact`]), [`normal_moment`] (the normal problem under P and a moment, any
//! profile, [`NormalContact`]), [`steady`] (regime and permanent stick zone), [`asymptotic`]
//! (edge description), [`matching`] (prototype-to-test matching), [`evolution`] (stick zone
//! along the cycle), [`slip_map`] (the slip-zone map of the paper's Figure 5), [`record`]
//! (recorders for the marching solver), [`stress`] (stresses below the contact), [`fatigue`]
//! (initiation parameters over the steady cycle), [`crack`] (will a crack grow: stress
//! intensity factors and the short-crack threshold), [`closed_form`]
//! (reference solutions), [`load`] and [`material`] (validated inputs), [`labels`] (edges, points and halves,
//! and pairs indexed by them), [`reference`](mod@reference) (the reference cycle of `docs/theory.md`), [`error`].

pub mod asymptotic;
#[cfg(feature = "parallel")]
pub mod batch;
pub mod closed_form;
pub mod crack;
pub mod design;
pub mod error;
pub mod evolution;
pub mod fatigue;
pub mod history;
pub mod labels;
pub mod load;
pub mod matching;
pub mod material;
pub mod normal;
pub mod normal_moment;
pub mod profile;
mod quadrature;
pub mod record;
pub mod reference;
mod roots;
pub mod slip_map;
mod spline;
pub mod steady;
pub mod stress;
pub mod wear;
pub mod written;

pub use error::{Error, Result};
pub use labels::{Edge, GivenPoint, Half, PerEdge, PerPoint};
pub use load::{Cycle, LoadPoint};
pub use material::{Compliance, Friction, Material};
pub use normal::Contact;
pub use normal_moment::NormalContact;
pub use profile::{Profile, Shape};
pub use steady::{Regime, SteadyOptions, SteadyState, StickZone};

/// The README's Rust example, compiled and run as a doctest.
#[cfg(doctest)]
#[doc = include_str!("../../../README.md")]
struct ReadmeDoctests;
pub mod march;
