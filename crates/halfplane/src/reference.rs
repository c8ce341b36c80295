//! The reference cycle of `docs/theory.md` ("The reference cycle"), used by tests, benches,
//! examples and docs, so that its numbers are written once.
//!
//! Hertz, `R = 50` mm, `E = 200` GPa, `nu = 0.3`, `f = 0.6`; point 1 = (P, Q, sigma) =
//! (1000 N/mm, -250 N/mm, -20 MPa), point 2 = (1400, 250, 20). An independent time-marching
//! program gives, to five figures, the contact half-widths [`CHECKED_HALF_WIDTHS`] and the
//! permanent stick zone [`CHECKED_STICK_ZONE`]. The flat punch with rounded edges `b = 0.3`,
//! `R = 50` ([`flat_rounded`], and sampled as a table by [`flat_rounded_table`]) is the
//! non-Hertz companion used alongside it.
//!
//! ```
//! use halfplane::{reference, steady, SteadyOptions};
//!
//! let state = steady::analyse(&reference::hertz(), &reference::cycle(), &SteadyOptions::default())?;
//! let zone = state.stick_zone.unwrap();
//! let [left, right] = reference::CHECKED_STICK_ZONE;
//! assert!((zone.left - left).abs() < 1e-5 && (zone.right - right).abs() < 1e-5);
//! # Ok::<(), halfplane::Error>(())
//! ```

use crate::error::Result;
use crate::load::{Cycle, LoadPoint};
use crate::material::{Friction, Material};
use crate::normal::Contact;
use crate::profile::Profile;

/// Young's modulus E of both bodies (MPa).
pub const YOUNGS_MODULUS: f64 = 200_000.0;
/// Poisson's ratio nu of both bodies.
pub const POISSONS_RATIO: f64 = 0.3;
/// Coulomb friction coefficient f.
pub const FRICTION: f64 = 0.6;
/// Hertz radius R, also the edge radius of the flat-rounded punch (mm).
pub const RADIUS: f64 = 50.0;
/// Flat half-width b of the flat-rounded punch (mm).
pub const FLAT_HALF_WIDTH: f64 = 0.3;
/// Point 1 as (P, Q, sigma): (N/mm, N/mm, MPa).
pub const POINT1: [f64; 3] = [1000.0, -250.0, -20.0];
/// Point 2 as (P, Q, sigma).
pub const POINT2: [f64; 3] = [1400.0, 250.0, 20.0];
/// Hertz contact half-widths `[a1, a2]` at the two points (mm), to the five figures quoted.
pub const CHECKED_HALF_WIDTHS: [f64; 2] = [0.76113, 0.90059];
/// Hertz permanent stick zone `[-m, n]` (mm), to the five figures quoted.
pub const CHECKED_STICK_ZONE: [f64; 2] = [-0.66607, 0.68123];

/// The material: E = 200000, nu = 0.3.
pub fn material() -> Material {
    Material::new(YOUNGS_MODULUS, POISSONS_RATIO).expect("the reference material is valid")
}

/// The friction: f = 0.6.
pub fn friction() -> Friction {
    Friction::new(FRICTION).expect("the reference friction is valid")
}

/// `profile` with the reference material and friction.
pub fn contact(profile: Profile) -> Contact {
    Contact::new(profile, material(), friction())
}

/// The reference contact: Hertz, R = 50.
pub fn hertz() -> Contact {
    contact(Profile::hertz(RADIUS).expect("the reference radius is valid"))
}

/// The flat punch with rounded edges b = 0.3, R = 50, with the reference material and friction.
pub fn flat_rounded() -> Contact {
    contact(Profile::flat_rounded(FLAT_HALF_WIDTH, RADIUS).expect("the reference punch is valid"))
}

/// Point 1, named `point1` in errors.
pub fn point1() -> LoadPoint {
    let [p, q, s] = POINT1;
    LoadPoint::new("point1", p, q, s).expect("the reference point 1 is valid")
}

/// Point 2, named `point2` in errors.
pub fn point2() -> LoadPoint {
    let [p, q, s] = POINT2;
    LoadPoint::new("point2", p, q, s).expect("the reference point 2 is valid")
}

/// The in-phase cycle between [`point1`] and [`point2`], in that order.
pub fn cycle() -> Cycle {
    Cycle::new(point1(), point2())
}

/// The flat-rounded punch b = 0.3, R = 50 sampled at `rows` evenly spaced x in [0, 2], the kink
/// at 0.3 stated: `g = 0` for `x <= 0.3`, `(x - 0.3)^2/100` beyond. The clamped spline
/// reproduces it exactly (a quadratic on each side of the kink). `rows - 1` must be a multiple
/// of 20 so that 0.3 is a row (41 is the bundled example's table); otherwise the kink is refused.
pub fn flat_rounded_table(rows: usize) -> Result<Profile> {
    let x: Vec<f64> = (0..rows)
        .map(|i| 2.0 * i as f64 / (rows - 1) as f64)
        .collect();
    let g = x
        .iter()
        .map(|&x| {
            if x <= FLAT_HALF_WIDTH {
                0.0
            } else {
                (x - FLAT_HALF_WIDTH).powi(2) / (2.0 * RADIUS)
            }
        })
        .collect();
    Profile::tabulated(x, g, vec![FLAT_HALF_WIDTH])
}
