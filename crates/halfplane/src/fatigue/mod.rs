//! Fretting-fatigue initiation parameters over the steady cycle (`docs/fatigue.md`).
//!
//! [`analyse`] marches a cyclic history, takes the tractions of every increment of its last
//! cycle (the steady cycle), evaluates the stress history on a grid below the contact with
//! [`crate::stress`], and reports for each parameter its maximum, where `(x, z)`, on which plane
//! and at which increment: Smith-Watson-Topper, Findley and the max-plane Fatemi-Socie product on
//! critical planes (sampled every degree, refined to 0.05 degree; or over every plane with
//! [`Planes::Full3d`]), Fatemi-Socie as its authors define it, the Modified Wohler Curve Method
//! and McDiarmid on the plane of the largest shear range (found exactly), Crossland (invariant,
//! the minimum circumscribed ball of the deviatoric path), and Ruiz's F1 and F2 on the surface.
//! With `threshold` and `endurance_range` it adds the critical-distance values (point method at
//! `L/2`, line method over `2L`, both straight into the depth below the maximum), and with the
//! strain-life constants the cycles to initiation. Conventions are those of [`crate::stress`]:
//! `z >= 0` is the depth in the body carrying the bulk tension. [`analyse_cycle`] evaluates a
//! cycle recorded cell by cell instead ([`CycleTractions`]: a worn cycle of [`crate::wear`]).
//! Stages: `stages.rs` (the steady cycle, grid, maxima, Ruiz), `plane.rs` and `space.rs` (the
//! plane searches), `crossland.rs`.

mod constants;
mod crossland;
mod grid;
mod life;
mod plane;
mod result;
mod space;
mod stages;

pub use constants::FatigueConstants;
pub use grid::{FatigueGrid, Planes, MAX_GRID_POINTS};
pub use life::{fatemi_socie_life, swt_life};
pub use plane::{mcdiarmid_equivalent_shear, mwcm_effective_shear, Critical};
pub use result::{FatigueResult, Parameter, ParameterResult};
pub use stages::CycleTractions;

use crate::error::Result;
use crate::history::History;
use crate::march::MarchOptions;
use crate::material::Material;
use crate::normal::Contact;
use crate::stress::Stress;
use plane::Elastic;

/// The critical-plane and invariant parameters at one point over a stress history.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct CriticalPlanes {
    /// Smith-Watson-Topper (always available).
    pub swt: Critical,
    /// Fatemi-Socie as its authors define it, on the plane of the largest shear strain range
    /// (needs `fatemi_socie_k` and `yield_stress`).
    pub fatemi_socie: Option<Critical>,
    /// Findley (needs `findley_k`).
    pub findley: Option<Critical>,
    /// Crossland's value and the index of the peak hydrostatic stress (needs `crossland_alpha`).
    pub crossland: Option<(f64, usize)>,
    /// The Modified Wohler Curve Method's effective shear stress on the plane of the largest
    /// shear stress amplitude (needs `axial_fatigue_limit` and `torsional_fatigue_limit`).
    pub mwcm: Option<Critical>,
    /// The Fatemi-Socie product at its largest over the planes (same constants as
    /// `fatemi_socie`).
    pub fatemi_socie_max_plane: Option<Critical>,
    /// McDiarmid's equivalent shear stress on the plane of the largest shear stress amplitude
    /// (needs `mcdiarmid_shear_limit` and `ultimate_strength`).
    pub mcdiarmid: Option<Critical>,
}

/// The parameters at one point over `history` (the stress states of a cycle, at least one),
/// searching the planes containing `y`: [`critical_planes_over`] with [`Planes::InPlane`].
pub fn critical_planes(
    history: &[Stress],
    material: &Material,
    constants: &FatigueConstants,
) -> CriticalPlanes {
    critical_planes_over(history, material, constants, Planes::InPlane)
}

/// The parameters at one point over `history`: the critical-plane search of `plane.rs` (or of
/// `space.rs` for [`Planes::Full3d`]) and Crossland's invariant. Elastic strains with the
/// constants of `material`; an empty history gives zeros.
pub fn critical_planes_over(
    history: &[Stress],
    material: &Material,
    constants: &FatigueConstants,
    planes: Planes,
) -> CriticalPlanes {
    let e = Elastic {
        youngs: material.youngs_modulus(),
        poisson: material.poisson_ratio(),
    };
    if history.is_empty() {
        let zero = Critical {
            value: 0.0,
            angle: 0.0,
            tilt: 0.0,
            index: 0,
        };
        return CriticalPlanes {
            swt: zero,
            fatemi_socie: None,
            findley: None,
            crossland: None,
            mwcm: None,
            fatemi_socie_max_plane: None,
            mcdiarmid: None,
        };
    }
    let p = match planes {
        Planes::InPlane => plane::search(history, e, constants),
        Planes::Full3d => space::search(history, e, constants),
    };
    CriticalPlanes {
        swt: p.swt,
        fatemi_socie: p.fatemi_socie,
        findley: p.findley,
        crossland: crossland::crossland(history, constants),
        mwcm: p.mwcm,
        fatemi_socie_max_plane: p.fatemi_socie_max_plane,
        mcdiarmid: p.mcdiarmid,
    }
}

/// Marches `history` (which must have cycles) and evaluates the parameters over its last cycle:
/// the march, the grid, each parameter's maximum with its critical-distance values and life,
/// and Ruiz on the surface (the stages of `stages.rs`).
pub fn analyse(
    contact: &Contact,
    history: &History,
    options: &MarchOptions,
    constants: &FatigueConstants,
    grid: &FatigueGrid,
) -> Result<FatigueResult> {
    let cycle = stages::SteadyCycle::march(contact, history, options)?;
    evaluate(&cycle, constants, grid)
}

/// The parameters over a cycle recorded cell by cell (a worn cycle of [`crate::wear`], whose
/// gap no profile describes), as [`analyse`] evaluates a march's last cycle: the same stages,
/// each increment's tractions built as a march's ([`crate::stress::Traction::from_march_ends`]),
/// the grid spanning `grid.width` and `grid.depth` times the half-width of `contact` `[b1, b2]`
/// about its centre (the wear command passes the unworn contact, so that every checkpoint is
/// evaluated on the same points), the increments numbered from 1 in `step`.
///
/// # Errors
/// [`crate::Error::NoCycle`] for a cycle without increments; [`crate::Error::InvalidInput`]
/// naming `contact` when its ends are not finite with `b1 < b2`; the stress field's errors.
pub fn analyse_cycle(
    material: &Material,
    cycle: &CycleTractions,
    contact: [f64; 2],
    constants: &FatigueConstants,
    grid: &FatigueGrid,
) -> Result<FatigueResult> {
    if cycle.is_empty() {
        return Err(crate::Error::NoCycle {
            what: "fatigue analysis",
        });
    }
    if !(contact[0].is_finite() && contact[1].is_finite() && contact[0] < contact[1]) {
        return Err(crate::Error::InvalidInput {
            field: "contact".into(),
            value: contact[1] - contact[0],
            valid: "finite contact ends b1 < b2 (the grid is scaled on their half-width)",
        });
    }
    let cycle = stages::SteadyCycle::recorded(cycle, *material, contact)?;
    evaluate(&cycle, constants, grid)
}

/// The stages after the steady cycle: the grid, the parameters at each point, their maxima,
/// Ruiz.
fn evaluate(
    cycle: &stages::SteadyCycle,
    constants: &FatigueConstants,
    grid: &FatigueGrid,
) -> Result<FatigueResult> {
    let points = stages::GridPoints::new(grid, cycle.a_max, cycle.centre);
    let planes: Vec<CriticalPlanes> = cycle
        .histories(&points.px, &points.pz)?
        .iter()
        .map(|h| critical_planes_over(h, &cycle.material, constants, grid.planes))
        .collect();
    let swt_map = planes.iter().map(|p| p.swt.value).collect();
    let maps = stages::maps(&planes);
    let mut parameters = stages::maxima(cycle, &points, &planes, constants, grid.planes)?;
    let surface = stages::ruiz(cycle)?;
    parameters.extend(surface.parameters);
    parameters.sort_by_key(|p| p.parameter as u8);
    Ok(FatigueResult {
        critical_distance: constants.critical_distance(),
        steps: cycle.steps.clone(),
        parameters,
        grid_x: points.grid_x,
        grid_z: points.grid_z,
        swt_map,
        maps,
        surface_x: surface.x,
        surface_sxx_max: surface.sxx_max,
        ruiz_f2_profile: surface.f2_profile,
        surface_sxx: surface.sxx,
    })
}
