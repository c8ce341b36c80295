//! Stresses in the body below the contact (`docs/stress.md`).
//!
//! The body is the half-plane `z >= 0` (z the depth) that carries the bulk tension `sigma`: the
//! specimen. Its surface carries the pressure `p` (compressive positive) and the shear traction
//! `q` that the other body exerts on it, positive in `+x`, the sense of positive Q: exactly the
//! traction [`crate::march`] reports. The stresses are tension positive, plane strain:
//!
//! - `sxx`, `szz`, `sxz` from the tractions by exact integration of the Flamant line-load
//!   solutions over a piecewise-linear representation ([`Traction`], closed form in `strip.rs`),
//!   plus `sigma` added to `sxx`;
//! - `syy = nu (sxx + szz)` (plane strain, with the bulk tension included).
//!
//! Piecewise-linear tractions through the march's cell values make the surface stress finite and
//! accurate; piecewise-constant ones (also available) have logarithmic peaks at every cell edge.
//! [`closed_form`] holds the independent references (Flamant, McEwen, Nowell-Hills).
//!
//! ```
//! use halfplane::stress::{self, closed_form::mcewen_pressure, Traction};
//! use halfplane::Material;
//!
//! // Hertzian pressure p0 sqrt(1 - x^2) on 2001 nodes, no shear.
//! let x: Vec<f64> = (0..=2000).map(|i| -1.0 + i as f64 / 1000.0).collect();
//! let p: Vec<f64> = x.iter().map(|x| (1.0 - x * x).max(0.0).sqrt()).collect();
//! let traction = Traction::piecewise_linear(&x, &p, &vec![0.0; x.len()])?;
//! let field = stress::field(&traction, 0.0, &Material::new(200_000.0, 0.3)?, &[0.0], &[0.5])?;
//! let exact = mcewen_pressure(1.0, 1.0, 0.0, 0.5);
//! assert!((field.szz[0] - exact[1]).abs() < 1e-5);
//! # Ok::<(), halfplane::Error>(())
//! ```

pub mod closed_form;
mod edge;
mod far;
mod fast;
mod marched;
mod shared;
mod strip;
mod traction;

pub use marched::{marched, MarchedTraction};
pub use shared::fields;
pub use traction::{Traction, MAX_NODES};

use crate::error::{physical, Error, Result, MAGNITUDE_LIMIT};
use crate::material::Material;
use far::FarField;
use std::sync::OnceLock;

/// The stress state at one point (tension positive).
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct Stress {
    /// `sxx`, along the surface (includes the bulk tension).
    pub sxx: f64,
    /// `szz`, normal to the surface.
    pub szz: f64,
    /// `syy = nu (sxx + szz)`, out of plane (plane strain).
    pub syy: f64,
    /// `sxz`, the in-plane shear.
    pub sxz: f64,
}

/// Stresses at a list of points, one value per point in each array, in the order given.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct StressField {
    /// `sxx` (includes the bulk tension).
    pub sxx: Vec<f64>,
    /// `szz`.
    pub szz: Vec<f64>,
    /// `syy = nu (sxx + szz)`.
    pub syy: Vec<f64>,
    /// `sxz`.
    pub sxz: Vec<f64>,
}

impl StressField {
    /// The state at point `i`.
    pub fn at(&self, i: usize) -> Stress {
        Stress {
            sxx: self.sxx[i],
            szz: self.szz[i],
            syy: self.syy[i],
            sxz: self.sxz[i],
        }
    }

    /// Number of points.
    pub fn len(&self) -> usize {
        self.sxx.len()
    }

    /// No points.
    pub fn is_empty(&self) -> bool {
        self.sxx.is_empty()
    }
}

/// Checks the points `(x[i], z[i])` a front end will ask for, before any work: one depth per
/// position, every `x` finite, every `z` finite and `>= 0` (points inside the other body are not
/// part of this problem). [`field`] checks the same itself.
///
/// # Errors
/// [`Error::LengthMismatch`] when `z` and `x` differ in length; [`Error::InvalidInput`] for the
/// first invalid point, its field naming the point by its 0-based index (`point 3: z`).
pub fn check_points(x: &[f64], z: &[f64]) -> Result<()> {
    if x.len() != z.len() {
        return Err(Error::LengthMismatch {
            field: "z".into(),
            length: z.len(),
            expected: x.len(),
            per: "one depth z per x",
        });
    }
    for (i, (&x, &z)) in x.iter().zip(z).enumerate() {
        check_point(i, x, z)?;
    }
    Ok(())
}

/// Checks one point: `x` finite, `z` finite and `>= 0`. `index` names the point in errors.
pub(crate) fn check_point(index: usize, x: f64, z: f64) -> Result<()> {
    // The common case without building the field names.
    if x.is_finite()
        && x.abs() <= MAGNITUDE_LIMIT
        && z.is_finite()
        && (0.0..=MAGNITUDE_LIMIT).contains(&z)
    {
        return Ok(());
    }
    physical(&format!("point {index}: x"), x)?;
    physical(&format!("point {index}: z"), z)?;
    if z < 0.0 {
        return Err(Error::InvalidInput {
            field: format!("point {index}: z"),
            value: z,
            valid: "a depth z >= 0 (the body is z >= 0; points in the other body are not computed)",
        });
    }
    Ok(())
}

/// The stress at `(x, z)` (`z >= 0`) under `traction` and the bulk tension `bulk`, plane strain
/// with the Poisson's ratio of `material` (conventions of this module): exactly the value
/// [`field`] gives for this point among any others.
/// Errors: a point that is not finite or has `z < 0`, or a surface point on a node where a
/// traction jumps (its stress is infinite).
pub fn at(traction: &Traction, bulk: f64, material: &Material, x: f64, z: f64) -> Result<Stress> {
    Ok(field(traction, bulk, material, &[x], &[z])?.at(0))
}

/// One point by the direct route: the closed form, or beyond [`far::FAR_RADII`] half-spans the
/// far field (`far`, built on the first far point and kept for the next).
fn point(
    t: &Traction,
    far: &mut Option<FarField>,
    bulk: f64,
    nu: f64,
    index: usize,
    x: f64,
    z: f64,
) -> Result<Stress> {
    // -0.0 is the surface: the logarithm's branch needs z = +0.
    let z = if z == 0.0 { 0.0 } else { z };
    if far.is_none() && far::is_far(t, x, z) {
        *far = FarField::new(t);
    }
    let [sxx, szz, sxz] = match far.as_ref().filter(|f| f.reaches(x, z)) {
        Some(f) => f.in_plane(x, z),
        None => strip::in_plane(t, x, z).ok_or_else(|| on_jump(index, x))?,
    };
    Ok(stress_from(sxx, szz, sxz, bulk, nu))
}

fn on_jump(index: usize, x: f64) -> Error {
    Error::InvalidInput {
        field: format!("point {index}: x"),
        value: x,
        valid: "a surface point away from a jump of the traction (the stress is infinite there)",
    }
}

/// The stress state from the traction's in-plane stresses, the bulk tension and plane strain.
fn stress_from(sxx: f64, szz: f64, sxz: f64, bulk: f64, nu: f64) -> Stress {
    // Adding +0.0 turns a signed zero into +0 (no "-0" in the output).
    let sxx = sxx + bulk + 0.0;
    Stress {
        sxx,
        szz: szz + 0.0,
        syy: nu * (sxx + szz) + 0.0,
        sxz: sxz + 0.0,
    }
}

/// Stresses at the points `(x[i], z[i])` under `traction` and the bulk tension `bulk`, in order
/// (see [`at`]). `x` and `z` must have the same length. Errors name the point by its 0-based index.
/// The same as [`Evaluator::field`] on a new evaluator.
///
/// A traction of many nodes is evaluated by a fast multipole method (`docs/stress.md`, "Fast
/// evaluation"): exact closed forms near each point, expansions far from it, agreeing with the
/// direct sum of [`field_direct`] to its rounding (1e-12 of `p0` at 16,000 cells). The route
/// depends on the traction only, never on the other points: a point's stresses alone, among
/// others or inside a grid of a million agree to 1e-13 of `p0` (the expansions' truncation and
/// rounding). Points beyond four half-spans of the loaded span take its far-field expansion in
/// every route, exact to rounding at any distance (`docs/stress.md`, "Far from the contact").
pub fn field(
    traction: &Traction,
    bulk: f64,
    material: &Material,
    x: &[f64],
    z: &[f64],
) -> Result<StressField> {
    Evaluator::new(traction, bulk, material)?.field(x, z)
}

/// A traction prepared for the stresses at many points asked for in as many calls as wanted
/// (a front end writing its output in chunks): the fast method's tree and the far field are
/// built once. Every call gives what [`field`] gives for the same points.
pub struct Evaluator<'a> {
    traction: &'a Traction,
    bulk: f64,
    material: Material,
    tree: Option<fast::Tree<'a>>,
    far: OnceLock<Option<FarField>>,
}

impl<'a> Evaluator<'a> {
    /// The evaluator of `traction` under the bulk tension `bulk` (plane strain with the Poisson's
    /// ratio of `material`). Errors: a bulk tension that is not finite or too large.
    pub fn new(traction: &'a Traction, bulk: f64, material: &Material) -> Result<Self> {
        physical("bulk tension", bulk)?;
        let tree = if traction.nodes.len() >= FAST_MIN_NODES {
            fast::Tree::new(traction)
        } else {
            None
        };
        Ok(Self {
            traction,
            bulk,
            material: *material,
            tree,
            far: OnceLock::new(),
        })
    }

    /// Stresses at the points `(x[i], z[i])`, in order, exactly as [`field`] gives them. Errors
    /// name the point by its 0-based index in `x`.
    pub fn field(&self, x: &[f64], z: &[f64]) -> Result<StressField> {
        check_request(self.bulk, x, z)?;
        let (t, bulk) = (self.traction, self.bulk);
        let Some(tree) = &self.tree else {
            return field_direct(t, bulk, &self.material, x, z);
        };
        let far = if x.iter().zip(z).any(|(&x, &z)| far::is_far(t, x, z)) {
            self.far.get_or_init(|| FarField::new(t)).as_ref()
        } else {
            None
        };
        let nu = self.material.poisson_ratio();
        let in_plane = tree.in_plane(x, z, far).map_err(|i| on_jump(i, x[i]))?;
        let mut out = StressField {
            sxx: Vec::with_capacity(x.len()),
            szz: Vec::with_capacity(x.len()),
            syy: Vec::with_capacity(x.len()),
            sxz: Vec::with_capacity(x.len()),
        };
        for [sxx, szz, sxz] in in_plane {
            push(&mut out, stress_from(sxx, szz, sxz, bulk, nu));
        }
        Ok(out)
    }
}

/// Tractions with at least this many nodes are evaluated by the fast method whatever the number of
/// points, so that a point's stresses never depend on the other points of a request: the direct
/// sum's rounding grows with the nodes (1e-12 of `p0` at 16,000 cells, 4 half-spans away) while
/// the expansions stay within 1e-14 (`docs/stress.md`, "Fast evaluation"). Below it the direct sum
/// is both cheaper and exact to rounding.
const FAST_MIN_NODES: usize = 32;

/// [`field`] by the direct sum over every node for every point: the reference the fast method
/// is checked against, `O(points x nodes)`.
pub fn field_direct(
    traction: &Traction,
    bulk: f64,
    material: &Material,
    x: &[f64],
    z: &[f64],
) -> Result<StressField> {
    check_request(bulk, x, z)?;
    let nu = material.poisson_ratio();
    let mut out = StressField {
        sxx: Vec::with_capacity(x.len()),
        szz: Vec::with_capacity(x.len()),
        syy: Vec::with_capacity(x.len()),
        sxz: Vec::with_capacity(x.len()),
    };
    let mut far = None;
    for (i, (&x, &z)) in x.iter().zip(z).enumerate() {
        push(&mut out, point(traction, &mut far, bulk, nu, i, x, z)?);
    }
    Ok(out)
}

fn push(out: &mut StressField, s: Stress) {
    out.sxx.push(s.sxx);
    out.szz.push(s.szz);
    out.syy.push(s.syy);
    out.sxz.push(s.sxz);
}

fn check_request(bulk: f64, x: &[f64], z: &[f64]) -> Result<()> {
    if x.len() == z.len() {
        physical("bulk tension", bulk)?;
    }
    check_points(x, z)
}
