//! The stages of [`super::analyse`] and [`super::analyse_cycle`]: the steady cycle (from a march,
//! or from a cycle's recorded cell tractions), the grid, each parameter's maximum (with its
//! critical-distance values and life) and Ruiz on the surface.

use super::{
    critical_planes_over, fatemi_socie_life, swt_life, CriticalPlanes, FatigueConstants,
    FatigueGrid, Parameter, ParameterResult, Planes,
};
use crate::error::{Error, Result};
use crate::history::History;
use crate::labels::PerEdge;
use crate::march::{march, Fields, MarchOptions};
use crate::material::Material;
use crate::normal::Contact;
use crate::stress::{self, Stress, Traction};

/// A marched cycle as a grid of cells recorded it, increment by increment: what
/// [`super::analyse_cycle`] evaluates (the fatigue parameters of a worn cycle,
/// [`crate::march::Worn::record_tractions`]). Valid by construction: every increment has one
/// pressure and one shear traction per cell, and finite, ordered contact ends.
#[derive(Debug, Clone, PartialEq)]
pub struct CycleTractions {
    x: Vec<f64>,
    slip_range: Vec<f64>,
    increments: Vec<CellIncrement>,
}

/// One increment of a [`CycleTractions`].
#[derive(Debug, Clone, PartialEq)]
struct CellIncrement {
    ends: PerEdge<f64>,
    bulk: f64,
    pressure: Vec<f64>,
    traction: Vec<f64>,
}

impl CycleTractions {
    /// A cycle over cells centred at `x` (increasing) whose slip range over the cycle is
    /// `slip_range` (one per cell), with no increment yet.
    ///
    /// # Errors
    /// [`Error::LengthMismatch`] naming `slip_range`.
    pub fn new(x: Vec<f64>, slip_range: Vec<f64>) -> Result<Self> {
        same_length("slip_range", &slip_range, x.len())?;
        Ok(Self {
            x,
            slip_range,
            increments: Vec::new(),
        })
    }

    /// Adds the next increment: the contact `ends` `[b1, b2]` (its tractions are built as a
    /// march's, [`Traction::from_march_ends`]: square-root shaped next to the ends, linear
    /// between the cell centres inside), the bulk stress, and per cell the pressure (compressive
    /// positive) and the shear traction (`crate::march`'s sign).
    ///
    /// # Errors
    /// [`Error::LengthMismatch`] naming `pressure` or `traction`; [`Error::InvalidInput`] naming
    /// a contact end that is not finite or `b2 < b1`.
    pub fn push(
        &mut self,
        ends: [f64; 2],
        bulk: f64,
        pressure: Vec<f64>,
        traction: Vec<f64>,
    ) -> Result<()> {
        same_length("pressure", &pressure, self.x.len())?;
        same_length("traction", &traction, self.x.len())?;
        let ends = PerEdge {
            left: ends[0],
            right: ends[1],
        };
        // The check `Traction::from_march_ends` makes, here so that a bad end fails on entry.
        Traction::from_march_ends(ends, &fields(&self.x, &pressure, &traction))?;
        crate::error::physical("bulk", bulk)?;
        self.increments.push(CellIncrement {
            ends,
            bulk,
            pressure,
            traction,
        });
        Ok(())
    }

    /// Cell centres.
    pub fn x(&self) -> &[f64] {
        &self.x
    }

    /// The number of increments.
    pub fn len(&self) -> usize {
        self.increments.len()
    }

    /// No increment recorded.
    pub fn is_empty(&self) -> bool {
        self.increments.is_empty()
    }
}

fn same_length(field: &str, v: &[f64], cells: usize) -> Result<()> {
    if v.len() == cells {
        Ok(())
    } else {
        Err(Error::LengthMismatch {
            field: field.into(),
            length: v.len(),
            expected: cells,
            per: "one value per cell centre x",
        })
    }
}

/// A march's fields holding only what a traction is built from (a worn cycle's boundaries are
/// cell edges: no kinks).
fn fields<'a>(x: &'a [f64], pressure: &'a [f64], traction: &'a [f64]) -> Fields<'a> {
    Fields {
        x,
        pressure,
        traction,
        slip: &[],
        slip_increment: &[],
        kinks: &[],
    }
}

/// The steady cycle: its increments' tractions and what Ruiz needs.
pub(super) struct SteadyCycle {
    /// The increments of the cycle, 1-based.
    pub steps: Vec<usize>,
    /// Per increment: its step, bulk stress and traction.
    states: Vec<(usize, f64, Traction)>,
    /// Per cell, the largest `|q|` over the cycle.
    q_max: Vec<f64>,
    /// Cell centres.
    cells: Vec<f64>,
    /// Per cell, half its slip range over the cycle.
    slip_amplitude: Vec<f64>,
    /// The largest contact half-width of the history: half the span of every contact it reaches
    /// (the half-width at the largest P without a moment on a symmetric profile).
    pub a_max: f64,
    /// The middle of that span (0 without a moment on a symmetric profile): the grid is centred
    /// there.
    pub centre: f64,
    /// The material.
    pub material: Material,
}

impl SteadyCycle {
    /// Marches `history` (which must have cycles), keeping its last cycle.
    pub fn march(contact: &Contact, history: &History, options: &MarchOptions) -> Result<Self> {
        let structure = history.cycles().ok_or(Error::NoCycle {
            what: "fatigue analysis",
        })?;
        let spc = structure.steps_per_cycle();
        let start = structure.first_step() + (structure.count() - 1) * spc;
        let p_max = history
            .loads()
            .iter()
            .map(|p| p.normal())
            .fold(0.0, f64::max);
        let centred =
            contact.profile().is_symmetric() && history.loads().iter().all(|p| p.moment() == 0.0);
        let mut states: Vec<(usize, f64, Traction)> = Vec::with_capacity(spc);
        let mut q_max: Vec<f64> = Vec::new();
        let mut failure = None;
        let (mut lower, mut upper) = (f64::INFINITY, f64::NEG_INFINITY);
        let result = march(contact, history, options, |r, f| {
            lower = lower.min(r.ends.left);
            upper = upper.max(r.ends.right);
            if r.step > start && failure.is_none() {
                match Traction::from_march_ends(r.ends, f) {
                    Ok(t) => states.push((r.step, r.load.bulk(), t)),
                    Err(e) => failure = Some(e),
                }
                track_q_max(&mut q_max, f.traction);
            }
        })?;
        if let Some(e) = failure {
            return Err(e);
        }
        let (a_max, centre) = if centred {
            (contact.half_width(p_max)?, 0.0)
        } else {
            (0.5 * (upper - lower), 0.5 * (upper + lower))
        };
        let slip_amplitude = result
            .cycles
            .last()
            .map(|c| c.slip_range.iter().map(|r| 0.5 * r).collect())
            .unwrap_or_else(|| vec![0.0; result.x.len()]);
        Ok(Self {
            steps: (start + 1..=start + spc).collect(),
            states,
            q_max,
            cells: result.x,
            slip_amplitude,
            a_max,
            centre,
            material: contact.material,
        })
    }

    /// The recorded `cycle`, its increments numbered from 1, the grid scaled on the contact
    /// `[b1, b2]` given.
    pub fn recorded(cycle: &CycleTractions, material: Material, contact: [f64; 2]) -> Result<Self> {
        let mut states = Vec::with_capacity(cycle.len());
        let mut q_max = Vec::new();
        for (k, i) in cycle.increments.iter().enumerate() {
            let t = Traction::from_march_ends(i.ends, &fields(&cycle.x, &i.pressure, &i.traction))?;
            states.push((k + 1, i.bulk, t));
            track_q_max(&mut q_max, &i.traction);
        }
        Ok(Self {
            steps: (1..=cycle.len()).collect(),
            states,
            q_max,
            cells: cycle.x.clone(),
            slip_amplitude: cycle.slip_range.iter().map(|r| 0.5 * r).collect(),
            a_max: 0.5 * (contact[1] - contact[0]),
            centre: 0.5 * (contact[0] + contact[1]),
            material,
        })
    }

    /// The stress history over the cycle at each point `(x[i], z[i])`.
    pub fn histories(&self, x: &[f64], z: &[f64]) -> Result<Vec<Vec<Stress>>> {
        let mut h = vec![Vec::with_capacity(self.states.len()); x.len()];
        for (_, bulk, t) in &self.states {
            let f = stress::field(t, *bulk, &self.material, x, z)?;
            for (i, h) in h.iter_mut().enumerate() {
                h.push(f.at(i));
            }
        }
        Ok(h)
    }

    fn step(&self, index: usize) -> usize {
        self.steps[index.min(self.steps.len() - 1)]
    }
}

/// Each cell's largest `|q|` so far, `traction` the next increment's.
fn track_q_max(q_max: &mut Vec<f64>, traction: &[f64]) {
    q_max.resize(traction.len(), 0.0);
    for (m, q) in q_max.iter_mut().zip(traction) {
        *m = m.max(q.abs());
    }
}

/// The grid's axes and its points, row after row (z outer, x inner).
pub(super) struct GridPoints {
    pub grid_x: Vec<f64>,
    pub grid_z: Vec<f64>,
    pub px: Vec<f64>,
    pub pz: Vec<f64>,
}

impl GridPoints {
    pub fn new(grid: &FatigueGrid, a_max: f64, centre: f64) -> Self {
        let grid_x: Vec<f64> = (0..grid.nx)
            .map(|i| centre + a_max * grid.width * (-1.0 + 2.0 * i as f64 / (grid.nx - 1) as f64))
            .collect();
        let grid_z: Vec<f64> = (0..grid.nz)
            .map(|j| a_max * grid.depth * j as f64 / (grid.nz - 1) as f64)
            .collect();
        let (px, pz) = grid_z
            .iter()
            .flat_map(|&z| grid_x.iter().map(move |&x| (x, z)))
            .unzip();
        Self {
            grid_x,
            grid_z,
            px,
            pz,
        }
    }
}

/// A parameter's value at a point, its plane (angle, tilt) and the index of its peak.
type Picked = (f64, Option<(f64, f64)>, usize);

/// `parameter` from the parameters at one point (`None`: not evaluated, or Ruiz).
fn pick(p: &CriticalPlanes, parameter: Parameter) -> Option<Picked> {
    let plane = |c: super::Critical| (c.value, Some((c.angle, c.tilt)), c.index);
    match parameter {
        Parameter::Swt => Some(plane(p.swt)),
        Parameter::FatemiSocie => p.fatemi_socie.map(plane),
        Parameter::FatemiSocieMaxPlane => p.fatemi_socie_max_plane.map(plane),
        Parameter::Findley => p.findley.map(plane),
        Parameter::Crossland => p.crossland.map(|(v, i)| (v, None, i)),
        Parameter::Mwcm => p.mwcm.map(plane),
        Parameter::McDiarmid => p.mcdiarmid.map(plane),
        Parameter::RuizF1 | Parameter::RuizF2 => None,
    }
}

/// Every evaluated parameter's map over the grid, in the order of [`Parameter`].
pub(super) fn maps(planes: &[CriticalPlanes]) -> Vec<(Parameter, Vec<f64>)> {
    Parameter::ALL
        .iter()
        .filter_map(|&parameter| {
            let map: Option<Vec<f64>> = planes
                .iter()
                .map(|p| pick(p, parameter).map(|v| v.0))
                .collect();
            map.map(|m| (parameter, m))
        })
        .collect()
}

/// Each grid parameter's maximum, with its point and line methods and its life.
pub(super) fn maxima(
    cycle: &SteadyCycle,
    points: &GridPoints,
    planes: &[CriticalPlanes],
    constants: &FatigueConstants,
    search: Planes,
) -> Result<Vec<ParameterResult>> {
    let material = cycle.material;
    let shear_modulus = material.youngs_modulus() / (2.0 * (1.0 + material.poisson_ratio()));
    let mut parameters = Vec::new();
    for parameter in Parameter::ALL {
        let Some((k, (value, plane, index))) = planes
            .iter()
            .enumerate()
            .filter_map(|(k, p)| pick(p, parameter).map(|v| (k, v)))
            .max_by(|a, b| a.1 .0.total_cmp(&b.1 .0))
        else {
            continue;
        };
        let (x, z) = (points.px[k], points.pz[k]);
        let (point_method, line_method) = match constants.critical_distance() {
            Some(l) => {
                let (p, m) = critical_distance_values(cycle, constants, search, parameter, x, l)?;
                (Some(p), Some(m))
            }
            None => (None, None),
        };
        let basis = point_method.unwrap_or(value);
        let cycles = match parameter {
            Parameter::Swt => swt_life(basis, material.youngs_modulus(), constants),
            Parameter::FatemiSocie | Parameter::FatemiSocieMaxPlane => {
                fatemi_socie_life(basis, shear_modulus, constants)
            }
            _ => None,
        };
        parameters.push(ParameterResult {
            parameter,
            value,
            x,
            z,
            angle: plane.map(|p| p.0),
            tilt: plane.map(|p| p.1),
            step: cycle.step(index),
            point_method,
            line_method,
            cycles,
        });
    }
    Ok(parameters)
}

/// The point method (the parameter at depth `L/2` below `x`) and the line method (its mean over
/// `0 <= z <= 2L`, Simpson's rule on 33 points).
fn critical_distance_values(
    cycle: &SteadyCycle,
    constants: &FatigueConstants,
    search: Planes,
    parameter: Parameter,
    x: f64,
    l: f64,
) -> Result<(f64, f64)> {
    const LINE: usize = 33;
    let mut lz: Vec<f64> = (0..LINE)
        .map(|j| 2.0 * l * j as f64 / (LINE - 1) as f64)
        .collect();
    lz.push(0.5 * l);
    let lx = vec![x; lz.len()];
    let values: Vec<f64> = cycle
        .histories(&lx, &lz)?
        .iter()
        .map(|h| {
            let p = critical_planes_over(h, &cycle.material, constants, search);
            pick(&p, parameter).map_or(0.0, |v| v.0)
        })
        .collect();
    let mut sum = values[0] + values[LINE - 1];
    for (j, v) in values.iter().enumerate().take(LINE - 1).skip(1) {
        sum += if j % 2 == 1 { 4.0 } else { 2.0 } * v;
    }
    Ok((values[LINE], sum / (3.0 * (LINE - 1) as f64)))
}

/// Ruiz's parameters and the surface profiles.
pub(super) struct Surface {
    pub parameters: Vec<ParameterResult>,
    pub x: Vec<f64>,
    pub sxx_max: Vec<f64>,
    pub f2_profile: Vec<f64>,
    pub sxx: Vec<Vec<f64>>,
}

/// Ruiz on the surface (Ruiz, Boddington and Chen, Exp. Mech. 24, 1984; Nowell and Hills, Wear
/// 136, 1990), at the cell centres in contact at some increment: `F1 = max(tau delta)`,
/// `F2 = max(sxx tau delta)`, `tau` the largest `|q|` over the cycle, `delta` half the
/// peak-to-peak slip of the cycle, `sxx` the largest surface `sxx` over the cycle.
pub(super) fn ruiz(cycle: &SteadyCycle) -> Result<Surface> {
    let (cells, slip_amplitude) = (&cycle.cells, &cycle.slip_amplitude);
    let spc = cycle.steps.len();
    let inside: Vec<usize> = (0..cells.len())
        .filter(|&i| (cells[i] - cycle.centre).abs() < cycle.a_max)
        .collect();
    let x: Vec<f64> = inside.iter().map(|&i| cells[i]).collect();
    let surface = cycle.histories(&x, &vec![0.0; x.len()])?;
    let sxx = (0..spc)
        .map(|k| {
            surface
                .iter()
                .map(|h| h.get(k).map_or(0.0, |s| s.sxx))
                .collect()
        })
        .collect();
    let mut sxx_max = Vec::with_capacity(inside.len());
    let mut f2_profile = Vec::with_capacity(inside.len());
    let mut f1 = (f64::NEG_INFINITY, 0usize);
    let mut f2 = (f64::NEG_INFINITY, 0usize, 0usize);
    for (j, &i) in inside.iter().enumerate() {
        let (peak_at, peak) = surface[j]
            .iter()
            .enumerate()
            .map(|(k, s)| (k, s.sxx))
            .max_by(|a, b| a.1.total_cmp(&b.1))
            .unwrap_or((0, 0.0));
        let td = cycle.q_max.get(i).copied().unwrap_or(0.0) * slip_amplitude[i];
        sxx_max.push(peak);
        f2_profile.push(peak * td);
        if td > f1.0 {
            f1 = (td, j);
        }
        if peak * td > f2.0 {
            f2 = (peak * td, j, peak_at);
        }
    }
    let mut parameters = Vec::new();
    if !inside.is_empty() {
        for (parameter, value, j, k) in [
            (Parameter::RuizF1, f1.0, f1.1, spc - 1),
            (Parameter::RuizF2, f2.0, f2.1, f2.2),
        ] {
            parameters.push(ParameterResult {
                parameter,
                value,
                x: x[j],
                z: 0.0,
                angle: None,
                tilt: None,
                step: cycle.step(k),
                point_method: None,
                line_method: None,
                cycles: None,
            });
        }
    }
    Ok(Surface {
        parameters,
        x,
        sxx_max,
        f2_profile,
        sxx,
    })
}
