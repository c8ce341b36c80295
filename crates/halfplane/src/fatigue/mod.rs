//! Fretting-fatigue initiation parameters over the steady cycle (`docs/fatigue.md`).
//!
//! [`analyse`] marches a cyclic history, takes the tractions of every increment of its last
//! cycle (the steady cycle), evaluates the stress history on a grid below the contact with
//! [`crate::stress`], and reports for each parameter its maximum, where `(x, z)`, on which plane
//! and at which increment: Smith-Watson-Topper, Fatemi-Socie and Findley on critical planes
//! (sampled every degree, refined to 0.05 degree), the Modified Wohler Curve Method on the plane of
//! the largest shear stress amplitude (found exactly), Crossland (invariant), and Ruiz's F1 and F2
//! on the surface. With `threshold` and `endurance_range` it adds the critical-distance values (point
//! method at `L/2`, line method over `2L`, both straight into the depth below the maximum), and
//! with the strain-life constants the cycles to initiation. Conventions are those of
//! [`crate::stress`]: `z >= 0` is the depth in the body carrying the bulk tension.

mod constants;
mod life;
mod plane;

pub use constants::FatigueConstants;
pub use life::{fatemi_socie_life, swt_life};
pub use plane::{mwcm_effective_shear, Critical};

use crate::error::{Error, Result};
use crate::history::History;
use crate::march::{march, MarchOptions};
use crate::material::Material;
use crate::normal::Contact;
use crate::stress::{self, Stress, Traction};
use plane::Elastic;

/// The critical-plane and invariant parameters at one point over a stress history.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct CriticalPlanes {
    /// Smith-Watson-Topper (always available).
    pub swt: Critical,
    /// Fatemi-Socie (needs `fatemi_socie_k` and `yield_stress`).
    pub fatemi_socie: Option<Critical>,
    /// Findley (needs `findley_k`).
    pub findley: Option<Critical>,
    /// Crossland's value and the index of the peak hydrostatic stress (needs `crossland_alpha`).
    pub crossland: Option<(f64, usize)>,
    /// The Modified Wohler Curve Method's effective shear stress on the plane of the largest
    /// shear stress amplitude (needs `axial_fatigue_limit` and `torsional_fatigue_limit`).
    pub mwcm: Option<Critical>,
}

/// The parameters at one point over `history` (the stress states of a cycle, at least one):
/// the critical-plane search of `plane.rs` and Crossland's invariant. Plane strain with the
/// elastic constants of `material`.
pub fn critical_planes(
    history: &[Stress],
    material: &Material,
    constants: &FatigueConstants,
) -> CriticalPlanes {
    let e = Elastic {
        youngs: material.youngs_modulus(),
        poisson: material.poisson_ratio(),
    };
    if history.is_empty() {
        let zero = Critical {
            value: 0.0,
            angle: 0.0,
            index: 0,
        };
        return CriticalPlanes {
            swt: zero,
            fatemi_socie: None,
            findley: None,
            crossland: None,
            mwcm: None,
        };
    }
    let p = plane::search(history, e, constants);
    CriticalPlanes {
        swt: p.swt,
        fatemi_socie: p.fatemi_socie,
        findley: p.findley,
        crossland: plane::crossland(history, constants),
        mwcm: p.mwcm,
    }
}

/// The grid the parameters are searched on: `nx` by `nz` points, x evenly from `-width` to
/// `width` and z evenly from 0 (the surface) to `depth`, both as multiples of the largest contact
/// half-width of the history.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct FatigueGrid {
    nx: usize,
    nz: usize,
    width: f64,
    depth: f64,
}

impl Default for FatigueGrid {
    fn default() -> Self {
        Self {
            nx: 100,
            nz: 50,
            width: 1.5,
            depth: 1.0,
        }
    }
}

/// Most grid points (the stress history of every point over the cycle is held: 32 bytes per
/// point and increment).
pub const MAX_GRID_POINTS: usize = 1_000_000;

impl FatigueGrid {
    /// A grid of `nx` by `nz` points (each 2 or more, at most [`MAX_GRID_POINTS`] in all) over
    /// `|x| <= width a_max`, `0 <= z <= depth a_max` (`width`, `depth` from 0.01 to 100).
    pub fn new(nx: usize, nz: usize, width: f64, depth: f64) -> Result<Self> {
        for (field, n) in [("fatigue.nx", nx), ("fatigue.nz", nz)] {
            if !(2..=MAX_GRID_POINTS).contains(&n) {
                return Err(Error::InvalidCount {
                    field: field.into(),
                    value: n as u64,
                    min: 2,
                    max: MAX_GRID_POINTS as u64,
                });
            }
        }
        if nx.saturating_mul(nz) > MAX_GRID_POINTS {
            return Err(Error::InvalidCount {
                field: "fatigue.nx * fatigue.nz".into(),
                value: nx.saturating_mul(nz) as u64,
                min: 4,
                max: MAX_GRID_POINTS as u64,
            });
        }
        for (field, v) in [("fatigue.width", width), ("fatigue.depth", depth)] {
            if !(v.is_finite() && (0.01..=100.0).contains(&v)) {
                return Err(Error::InvalidInput {
                    field: field.into(),
                    value: v,
                    valid: "a multiple of the largest contact half-width from 0.01 to 100",
                });
            }
        }
        Ok(Self {
            nx,
            nz,
            width,
            depth,
        })
    }
}

/// Which parameter a result is.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[non_exhaustive]
pub enum Parameter {
    /// Smith-Watson-Topper, `sigma_n,max d(eps_n)/2`.
    Swt,
    /// Fatemi-Socie, `(d(gamma)/2)(1 + k sigma_n,max/sigma_y)`.
    FatemiSocie,
    /// Findley, `tau_a + k sigma_n,max`.
    Findley,
    /// Crossland, `sqrt(J2,a) + alpha sigma_H,max`.
    Crossland,
    /// Ruiz F1 = max(tau delta) on the surface.
    RuizF1,
    /// Ruiz F2 = max(sigma_xx tau delta) on the surface.
    RuizF2,
    /// Modified Wohler Curve Method, `tau_a + kappa rho` on the plane of the largest `tau_a`.
    Mwcm,
}

impl Parameter {
    /// The name the reports print.
    pub fn name(self) -> &'static str {
        match self {
            Parameter::Swt => "swt",
            Parameter::FatemiSocie => "fatemi_socie",
            Parameter::Findley => "findley",
            Parameter::Crossland => "crossland",
            Parameter::RuizF1 => "ruiz_f1",
            Parameter::RuizF2 => "ruiz_f2",
            Parameter::Mwcm => "mwcm",
        }
    }
}

/// One parameter's maximum over the grid (or the surface, for Ruiz).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ParameterResult {
    /// Which parameter.
    pub parameter: Parameter,
    /// Its maximum.
    pub value: f64,
    /// Where: x.
    pub x: f64,
    /// Where: depth z.
    pub z: f64,
    /// The critical plane's normal angle in degrees from `+x` towards `+z` (critical-plane
    /// parameters only).
    pub angle: Option<f64>,
    /// The increment (1-based march step) of the peak normal stress on the critical plane
    /// (Crossland: hydrostatic stress; Ruiz: surface `sxx` for F2, traction for F1).
    pub step: usize,
    /// Point method: the parameter at depth `L/2` below `x` (needs the critical distance).
    pub point_method: Option<f64>,
    /// Line method: its mean over depths 0 to `2L` below `x`.
    pub line_method: Option<f64>,
    /// Cycles to initiation from the SWT or Fatemi-Socie curve, at the point-method value when
    /// the critical distance is known, else at the maximum; `None` without the constants or at
    /// run-out (beyond 5e19 cycles).
    pub cycles: Option<f64>,
}

/// The result of [`analyse`].
#[derive(Debug, Clone, PartialEq)]
pub struct FatigueResult {
    /// The critical distance `L`, when the constants give it.
    pub critical_distance: Option<f64>,
    /// The increments of the steady (last) cycle, 1-based.
    pub steps: Vec<usize>,
    /// One result per available parameter, in the order of [`Parameter`].
    pub parameters: Vec<ParameterResult>,
    /// The grid's x (one per column).
    pub grid_x: Vec<f64>,
    /// The grid's z (one per row).
    pub grid_z: Vec<f64>,
    /// SWT at every grid point, row after row (z outer, x inner).
    pub swt_map: Vec<f64>,
    /// Every grid parameter whose constants are given (SWT, Fatemi-Socie, Findley, Crossland,
    /// MWCM, in the order of [`Parameter`]) at every grid point, laid out as `swt_map`.
    pub maps: Vec<(Parameter, Vec<f64>)>,
    /// Cell centres in contact at some increment of the cycle (the surface profiles' x).
    pub surface_x: Vec<f64>,
    /// Largest surface `sxx` over the cycle at each of them.
    pub surface_sxx_max: Vec<f64>,
    /// `sxx_max |q|_max delta` at each of them (Ruiz F2's profile; delta the slip amplitude).
    pub ruiz_f2_profile: Vec<f64>,
    /// The surface `sxx` at each of them at every increment of the cycle: one row per entry of
    /// `steps`, one value per entry of `surface_x`.
    pub surface_sxx: Vec<Vec<f64>>,
}

impl FatigueResult {
    /// The map of `parameter` over the grid (row after row, z outer), when it was evaluated.
    pub fn map(&self, parameter: Parameter) -> Option<&[f64]> {
        self.maps
            .iter()
            .find(|(p, _)| *p == parameter)
            .map(|(_, m)| m.as_slice())
    }

    /// The result of `parameter`, when it was evaluated.
    pub fn parameter(&self, parameter: Parameter) -> Option<&ParameterResult> {
        self.parameters.iter().find(|p| p.parameter == parameter)
    }
}

/// Marches `history` (which must have cycles) and evaluates the parameters over its last cycle.
pub fn analyse(
    contact: &Contact,
    history: &History,
    options: &MarchOptions,
    constants: &FatigueConstants,
    grid: &FatigueGrid,
) -> Result<FatigueResult> {
    let structure = history.cycles().ok_or(Error::NoCycle {
        what: "fatigue analysis",
    })?;
    let spc = structure.steps_per_cycle();
    let start = structure.first_step() + (structure.count() - 1) * spc;
    let steps: Vec<usize> = (start + 1..=start + spc).collect();
    let p_max = history
        .loads()
        .iter()
        .map(|p| p.normal())
        .fold(0.0, f64::max);
    let a_max = contact.half_width(p_max)?;
    let material = contact.material;

    // The march: the last cycle's tractions, and per cell the largest |q|.
    let mut states: Vec<(usize, f64, Traction)> = Vec::with_capacity(spc);
    let mut q_max: Vec<f64> = Vec::new();
    let mut failure = None;
    let result = march(contact, history, options, |r, f| {
        if r.step > start && failure.is_none() {
            match Traction::from_march(r.half_width, f) {
                Ok(t) => states.push((r.step, r.load.bulk(), t)),
                Err(e) => failure = Some(e),
            }
            q_max.resize(f.x.len(), 0.0);
            for (m, q) in q_max.iter_mut().zip(f.traction) {
                *m = m.max(q.abs());
            }
        }
    })?;
    if let Some(e) = failure {
        return Err(e);
    }
    let histories = |x: &[f64], z: &[f64]| -> Result<Vec<Vec<Stress>>> {
        let mut h = vec![Vec::with_capacity(spc); x.len()];
        for (_, bulk, t) in &states {
            let f = stress::field(t, *bulk, &material, x, z)?;
            for (i, h) in h.iter_mut().enumerate() {
                h.push(f.at(i));
            }
        }
        Ok(h)
    };

    // The grid.
    let grid_x: Vec<f64> = (0..grid.nx)
        .map(|i| a_max * grid.width * (-1.0 + 2.0 * i as f64 / (grid.nx - 1) as f64))
        .collect();
    let grid_z: Vec<f64> = (0..grid.nz)
        .map(|j| a_max * grid.depth * j as f64 / (grid.nz - 1) as f64)
        .collect();
    let (px, pz): (Vec<f64>, Vec<f64>) = grid_z
        .iter()
        .flat_map(|&z| grid_x.iter().map(move |&x| (x, z)))
        .unzip();
    let at_points = histories(&px, &pz)?;
    let planes: Vec<CriticalPlanes> = at_points
        .iter()
        .map(|h| critical_planes(h, &material, constants))
        .collect();
    let swt_map = planes.iter().map(|p| p.swt.value).collect();

    let critical_distance = constants.critical_distance();
    let shear_modulus = material.youngs_modulus() / (2.0 * (1.0 + material.poisson_ratio()));
    type Pick = fn(&CriticalPlanes) -> Option<(f64, Option<f64>, usize)>;
    let picks: [(Parameter, Pick); 5] = [
        (Parameter::Swt, |p| {
            Some((p.swt.value, Some(p.swt.angle), p.swt.index))
        }),
        (Parameter::FatemiSocie, |p| {
            p.fatemi_socie.map(|c| (c.value, Some(c.angle), c.index))
        }),
        (Parameter::Findley, |p| {
            p.findley.map(|c| (c.value, Some(c.angle), c.index))
        }),
        (Parameter::Crossland, |p| {
            p.crossland.map(|(v, i)| (v, None, i))
        }),
        (Parameter::Mwcm, |p| {
            p.mwcm.map(|c| (c.value, Some(c.angle), c.index))
        }),
    ];
    let mut maps = Vec::new();
    for (parameter, pick) in picks {
        let map: Option<Vec<f64>> = planes.iter().map(|p| pick(p).map(|v| v.0)).collect();
        if let Some(map) = map {
            maps.push((parameter, map));
        }
    }
    let mut parameters = Vec::new();
    for (parameter, pick) in picks {
        let Some((k, (value, angle, index))) = planes
            .iter()
            .enumerate()
            .filter_map(|(k, p)| pick(p).map(|v| (k, v)))
            .max_by(|a, b| a.1 .0.total_cmp(&b.1 .0))
        else {
            continue;
        };
        let (x, z) = (px[k], pz[k]);
        let (point_method, line_method) = match critical_distance {
            Some(l) => {
                const LINE: usize = 33;
                let mut lz: Vec<f64> = (0..LINE)
                    .map(|j| 2.0 * l * j as f64 / (LINE - 1) as f64)
                    .collect();
                lz.push(0.5 * l);
                let lx = vec![x; lz.len()];
                let values: Vec<f64> = histories(&lx, &lz)?
                    .iter()
                    .map(|h| pick(&critical_planes(h, &material, constants)).map_or(0.0, |v| v.0))
                    .collect();
                // Simpson's rule over [0, 2L], divided by 2L.
                let mut sum = values[0] + values[LINE - 1];
                for (j, v) in values.iter().enumerate().take(LINE - 1).skip(1) {
                    sum += if j % 2 == 1 { 4.0 } else { 2.0 } * v;
                }
                (Some(values[LINE]), Some(sum / (3.0 * (LINE - 1) as f64)))
            }
            None => (None, None),
        };
        let basis = point_method.unwrap_or(value);
        let cycles = match parameter {
            Parameter::Swt => swt_life(basis, material.youngs_modulus(), constants),
            Parameter::FatemiSocie => fatemi_socie_life(basis, shear_modulus, constants),
            _ => None,
        };
        parameters.push(ParameterResult {
            parameter,
            value,
            x,
            z,
            angle,
            step: steps[index.min(spc - 1)],
            point_method,
            line_method,
            cycles,
        });
    }

    // Ruiz on the surface, at the cell centres in contact at some increment.
    let slip_amplitude: Vec<f64> = result
        .cycles
        .last()
        .map(|c| c.slip_range.iter().map(|r| 0.5 * r).collect())
        .unwrap_or_else(|| vec![0.0; result.x.len()]);
    let inside: Vec<usize> = (0..result.x.len())
        .filter(|&i| result.x[i].abs() < a_max)
        .collect();
    let surface_x: Vec<f64> = inside.iter().map(|&i| result.x[i]).collect();
    let surface = histories(&surface_x, &vec![0.0; surface_x.len()])?;
    let surface_sxx = (0..spc)
        .map(|k| {
            surface
                .iter()
                .map(|h| h.get(k).map_or(0.0, |s| s.sxx))
                .collect()
        })
        .collect();
    let mut surface_sxx_max = Vec::with_capacity(inside.len());
    let mut ruiz_f2_profile = Vec::with_capacity(inside.len());
    let mut f1 = (f64::NEG_INFINITY, 0usize);
    let mut f2 = (f64::NEG_INFINITY, 0usize, 0usize);
    for (j, &i) in inside.iter().enumerate() {
        let (peak_at, peak) = surface[j]
            .iter()
            .enumerate()
            .map(|(k, s)| (k, s.sxx))
            .max_by(|a, b| a.1.total_cmp(&b.1))
            .unwrap_or((0, 0.0));
        let td = q_max.get(i).copied().unwrap_or(0.0) * slip_amplitude[i];
        surface_sxx_max.push(peak);
        ruiz_f2_profile.push(peak * td);
        if td > f1.0 {
            f1 = (td, j);
        }
        if peak * td > f2.0 {
            f2 = (peak * td, j, peak_at);
        }
    }
    if !inside.is_empty() {
        for (parameter, value, j, k) in [
            (Parameter::RuizF1, f1.0, f1.1, spc - 1),
            (Parameter::RuizF2, f2.0, f2.1, f2.2),
        ] {
            parameters.push(ParameterResult {
                parameter,
                value,
                x: surface_x[j],
                z: 0.0,
                angle: None,
                step: steps[k.min(spc - 1)],
                point_method: None,
                line_method: None,
                cycles: None,
            });
        }
    }
    // The order of `Parameter` (the MWCM, added later, after Ruiz).
    parameters.sort_by_key(|p| p.parameter as u8);
    Ok(FatigueResult {
        critical_distance,
        steps,
        parameters,
        grid_x,
        grid_z,
        swt_map,
        maps,
        surface_x,
        surface_sxx_max,
        ruiz_f2_profile,
        surface_sxx,
    })
}
