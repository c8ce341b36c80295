//! Will the crack grow? A straight surface-breaking crack below the contact, its stress
//! intensity factors over the steady cycle with crack-face contact and friction, and the
//! short-crack threshold (`docs/crack.md`).
//!
//! The crack starts at the surface point `(mouth, 0)` and runs at `angle` from the surface normal
//! (positive towards `+x`) for `length`: its points are `(mouth + s sin(angle), s cos(angle))`,
//! `0 <= s <= length`, in the coordinates of [`crate::stress`] (`z >= 0` the depth). Along it,
//! `e_s = (sin, cos)` points from the mouth to the tip and `n = (cos, -sin)` (for a crack normal
//! to the surface, `n = +x`). `K_I` is the opening mode; `K_II = lim sqrt(2 pi r) tau` with
//! `tau = e_s . sigma . n` on the crack line ahead of the tip, so a crack normal to the surface
//! has `K_II > 0` when `sxz > 0` would act there.
//!
//! The crack and the contact are decoupled, as usual in this literature (Nowell and Hills; Hills,
//! Kelly, Dai and Korsunsky 1996): the uncracked stress of [`crate::stress`] under the marched
//! tractions loads the crack, and the crack does not change the contact tractions. That holds
//! while the crack is short compared with the contact and does not reach into it.
//!
//! Stages: `kernel.rs` (the half-plane dislocation kernel), `quadrature.rs` (the Gauss-Jacobi
//! rule), `solve.rs` (assembly and the open crack), `contact.rs` (faces in contact with friction,
//! incrementally over the cycle), `growth.rs` (ranges, threshold, verdict, the driver). Two
//! references check them: `reference.rs` (published factors, a weight function) and `graded.rs`
//! (the open crack solved a second way, on panels graded towards the mouth).

mod contact;
pub mod graded;
mod growth;
mod kernel;
mod quadrature;
pub mod reference;
mod solve;

pub use contact::{FaceState, IncrementSolution};
pub use growth::{
    analyse, default_points, el_haddad_length, mts_equivalent, threshold, CrackOptions,
    CrackResult, CrackRow, EffectiveRange, Position, Verdict, CRITICAL_PLANE_PARAMETERS,
    MAX_LENGTHS, MAX_LENGTH_RATIO,
};
pub use reference::EDGE_CRACK_FACTOR;
pub use solve::{CrackSolver, TipFactors, MAX_POINTS, MIN_POINTS};

use crate::error::{physical, Error, Result};

/// A straight surface-breaking crack (module doc for the geometry).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Crack {
    mouth: f64,
    angle: f64,
    length: f64,
}

impl Crack {
    /// The crack from `(mouth, 0)` at `angle` radians from the surface normal (strictly between
    /// -pi/2 and pi/2), of `length` from 1e-30 to 1e30. Errors name `crack.position`,
    /// `crack.angle` (in degrees) or `crack.lengths`.
    pub fn new(mouth: f64, angle: f64, length: f64) -> Result<Self> {
        physical("crack.position", mouth)?;
        let degrees = angle.to_degrees();
        if !(degrees.is_finite() && degrees > -90.0 && degrees < 90.0) {
            return Err(Error::InvalidInput {
                field: "crack.angle".into(),
                value: degrees,
                valid: "an angle in degrees strictly between -90 and 90 (from the surface normal)",
            });
        }
        if !(length.is_finite() && (1e-30..=1e30).contains(&length)) {
            return Err(Error::InvalidInput {
                field: "crack.lengths".into(),
                value: length,
                valid: "a crack length from 1e-30 to 1e30",
            });
        }
        Ok(Self {
            mouth,
            angle,
            length,
        })
    }

    /// The mouth's `x`.
    pub fn mouth(&self) -> f64 {
        self.mouth
    }

    /// The angle from the surface normal, radians.
    pub fn angle(&self) -> f64 {
        self.angle
    }

    /// The length.
    pub fn length(&self) -> f64 {
        self.length
    }

    /// The tip `(x, z)`.
    pub fn tip(&self) -> (f64, f64) {
        let (s, c) = self.angle.sin_cos();
        (self.mouth + self.length * s, self.length * c)
    }

    /// `(e1, e2)`: `e1 = e_s` and `e2 = -n` in `(x, z)` (a quarter turn from `e1` towards `+z`
    /// from `+x`, the frame of the kernel).
    fn frame(&self) -> ([f64; 2], [f64; 2]) {
        let (s, c) = self.angle.sin_cos();
        ([s, c], [-c, s])
    }
}
