//! Per crack length over the steady cycle: `K_I` and `K_II` at every increment, their ranges, an
//! effective range, El Haddad's short-crack threshold and the verdict over the lengths.
//!
//! Definitions (`docs/crack.md`):
//! - `delta_k1 = max K_I - min K_I` with `K_I = 0` while the tip is closed, so only the open
//!   part of the cycle counts; `delta_k2 = max K_II - min K_II`.
//! - The effective range is, by choice, the maximum tangential stress criterion (Erdogan and
//!   Sih 1963) applied to the ranges, `K_eq = cos^3(t/2) dK_I - (3/2) cos(t/2) sin(t) dK_II` at
//!   `t = 2 atan((dK_I - sqrt(dK_I^2 + 8 dK_II^2))/(4 dK_II))`, or `sqrt(dK_I^2 + dK_II^2)`.
//! - El Haddad, Topper and Smith (1979): `dK_th(l) = dK_th sqrt(l/(l + l0))`,
//!   `l0 = (1/pi)(dK_th/(1.12 dsigma_0))^2`, from `[fatigue]` `threshold` and `endurance_range`.
//! - Verdict: `no-growth` when the range is at or below the threshold at the shortest length;
//!   otherwise `arrests` at the first length where it falls to or below the threshold again, or
//!   `propagates` if it never does.

use super::solve::{CrackSolver, TipFactors};
use super::Crack;
use crate::error::{Error, Result};
use crate::fatigue::{self, FatigueConstants, Parameter};
use crate::history::History;
use crate::march::MarchOptions;
use crate::normal::Contact;
use crate::stress::{self, MarchedTraction};

/// Longest crack, as a multiple of the largest contact half-width of the steady cycle: the
/// decoupled analysis needs the crack short beside the contact.
pub const MAX_LENGTH_RATIO: f64 = 1.0;

/// Where the crack's mouth is.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Position {
    /// At the leftmost position of the contact's left end over the steady cycle (`x = -a_max`,
    /// with `a_max` its largest half-width, without a moment on a symmetric profile).
    LeftEdge,
    /// At the rightmost position of its right end (`x = a_max` when centred).
    RightEdge,
    /// Of the two edges, the one with the larger effective range at the shortest length.
    LargerRange,
    /// At this `x`.
    At(f64),
}

/// The effective range's definition (module doc).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum EffectiveRange {
    /// Maximum tangential stress criterion on the ranges.
    #[default]
    Mts,
    /// `sqrt(dK_I^2 + dK_II^2)`.
    Quadratic,
}

/// What to analyse: the crack's position, angle, lengths and faces.
#[derive(Debug, Clone, PartialEq)]
pub struct CrackOptions {
    position: Position,
    angle: Angle,
    lengths: Vec<f64>,
    face_friction: f64,
    points: Option<usize>,
    effective: EffectiveRange,
}

/// The crack's angle: given, or the critical plane of an initiation parameter at the mouth.
#[derive(Debug, Clone, Copy, PartialEq)]
enum Angle {
    /// Radians from the surface normal.
    Given(f64),
    /// The plane of this critical-plane parameter at the mouth over the steady cycle.
    CriticalPlane(Parameter),
}

/// Most crack lengths in one analysis.
pub const MAX_LENGTHS: usize = 1000;

/// The parameters [`CrackOptions::with_critical_plane`] takes, by their report names.
pub const CRITICAL_PLANE_PARAMETERS: &str =
    "swt, fatemi_socie, findley, mwcm, fatemi_socie_max_plane or mcdiarmid (a parameter with a critical plane)";

impl CrackOptions {
    /// Cracks at `position`, `angle_degrees` from the surface normal (strictly between -90 and
    /// 90), of the `lengths` given (each > 0, strictly ascending, 1 to [`MAX_LENGTHS`]), with
    /// faces of friction coefficient `face_friction >= 0`. [`default_points`] quadrature points,
    /// MTS range.
    pub fn new(
        position: Position,
        angle_degrees: f64,
        lengths: Vec<f64>,
        face_friction: f64,
    ) -> Result<Self> {
        if let Position::At(x) = position {
            crate::error::physical("crack.position", x)?;
        }
        let angle = angle_degrees.to_radians();
        Crack::new(0.0, angle, 1.0)?;
        if lengths.is_empty() || lengths.len() > MAX_LENGTHS {
            return Err(Error::InvalidCount {
                field: "crack.lengths (count)".into(),
                value: lengths.len() as u64,
                min: 1,
                max: MAX_LENGTHS as u64,
            });
        }
        for (i, &l) in lengths.iter().enumerate() {
            Crack::new(0.0, angle, l)?;
            if i > 0 && l <= lengths[i - 1] {
                return Err(Error::InvalidInput {
                    field: format!("crack.lengths[{i}]"),
                    value: l,
                    valid: "lengths in strictly ascending order",
                });
            }
        }
        if !(face_friction.is_finite() && (0.0..=1e6).contains(&face_friction)) {
            return Err(Error::InvalidInput {
                field: "crack.face_friction".into(),
                value: face_friction,
                valid: "a friction coefficient from 0 to 1e6",
            });
        }
        Ok(Self {
            position,
            angle: Angle::Given(angle),
            lengths,
            face_friction,
            points: None,
            effective: EffectiveRange::Mts,
        })
    }

    /// With the crack in the critical plane of `parameter` at the mouth (the issue's
    /// `angle = "critical-plane"`): the in-plane search of [`crate::fatigue::critical_planes`]
    /// over the mouth's surface stress through the steady cycle; the crack lies in that plane,
    /// running into the body. Errors: a parameter without a critical plane (Crossland, Ruiz).
    /// The analysis fails if the parameter's constants are missing or the plane is parallel to
    /// the surface.
    pub fn with_critical_plane(mut self, parameter: Parameter) -> Result<Self> {
        if matches!(
            parameter,
            Parameter::Crossland | Parameter::RuizF1 | Parameter::RuizF2
        ) {
            return Err(Error::InvalidText {
                field: "crack.initiation_parameter".into(),
                value: parameter.name().into(),
                valid: CRITICAL_PLANE_PARAMETERS,
            });
        }
        self.angle = Angle::CriticalPlane(parameter);
        Ok(self)
    }

    /// With `points` quadrature points per component (see [`super::MIN_POINTS`]).
    pub fn with_points(mut self, points: usize) -> Result<Self> {
        if !(super::MIN_POINTS..=super::MAX_POINTS).contains(&points) {
            return Err(Error::InvalidCount {
                field: "crack.points".into(),
                value: points as u64,
                min: super::MIN_POINTS as u64,
                max: super::MAX_POINTS as u64,
            });
        }
        self.points = Some(points);
        Ok(self)
    }

    /// With the effective range `effective`.
    pub fn with_effective(mut self, effective: EffectiveRange) -> Self {
        self.effective = effective;
        self
    }

    /// The lengths.
    pub fn lengths(&self) -> &[f64] {
        &self.lengths
    }
}

/// The quadrature points per component a crack at `angle_degrees` from the surface normal takes
/// unless told: 40 to 45 degrees, 80 to 60 degrees, 160 beyond. The crack's mouth makes a wedge of
/// `90 - |angle|` degrees with the surface, and the sharper it is the more slowly the solution
/// converges (`docs/convergence.md`): under remote tension these give `F_I` within 0.05% at 45
/// degrees, 0.4% at 60 and 0.5% at 75 of the 400-point values.
pub fn default_points(angle_degrees: f64) -> usize {
    match angle_degrees.abs() {
        a if a <= 45.0 => 40,
        a if a <= 60.0 => 80,
        _ => 160,
    }
}

/// One crack length over the steady cycle.
#[derive(Debug, Clone, PartialEq)]
pub struct CrackRow {
    /// Crack length.
    pub length: f64,
    /// Largest and smallest `K_I` (never negative).
    pub k1_max: f64,
    /// See `k1_max`.
    pub k1_min: f64,
    /// Largest and smallest `K_II`.
    pub k2_max: f64,
    /// See `k2_max`.
    pub k2_min: f64,
    /// `k1_max - k1_min`.
    pub delta_k1: f64,
    /// `k2_max - k2_min`.
    pub delta_k2: f64,
    /// The effective range of the options.
    pub delta_k_eff: f64,
    /// El Haddad's threshold at this length.
    pub threshold: f64,
    /// `K_I`, `K_II` at every increment of the steady cycle.
    pub increments: Vec<TipFactors>,
}

/// The verdict over the lengths (module doc).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Verdict {
    /// Grows, then stops.
    Arrests,
    /// Above the threshold at every length.
    Propagates,
    /// At or below the threshold from the shortest length.
    NoGrowth,
}

impl Verdict {
    /// The public name (`arrests`, `propagates`, `no-growth`).
    pub fn name(self) -> &'static str {
        match self {
            Verdict::Arrests => "arrests",
            Verdict::Propagates => "propagates",
            Verdict::NoGrowth => "no-growth",
        }
    }

    /// The verdict of `rows` (ascending lengths) and the arrest length if it arrests.
    pub fn of(rows: &[CrackRow]) -> (Self, Option<f64>) {
        let above = |r: &CrackRow| r.delta_k_eff > r.threshold;
        match rows.first() {
            Some(r) if above(r) => match rows.iter().find(|r| !above(r)) {
                Some(r) => (Verdict::Arrests, Some(r.length)),
                None => (Verdict::Propagates, None),
            },
            _ => (Verdict::NoGrowth, None),
        }
    }
}

/// The analysis.
#[derive(Debug, Clone, PartialEq)]
pub struct CrackResult {
    /// One row per length, ascending.
    pub rows: Vec<CrackRow>,
    /// The verdict.
    pub verdict: Verdict,
    /// The arrest length when the verdict is `Arrests`.
    pub arrest_length: Option<f64>,
    /// The mouth's `x`.
    pub mouth: f64,
    /// The angle from the surface normal, degrees.
    pub angle: f64,
    /// The largest contact half-width of the steady cycle.
    pub half_width: f64,
    /// The increments of the steady cycle (1-based).
    pub steps: Vec<usize>,
}

/// El Haddad's intrinsic length `l0 = (1/pi)(dK_th/(1.12 dsigma_0))^2` (El Haddad, Topper and
/// Smith 1979, with the free-surface factor 1.12).
pub fn el_haddad_length(threshold: f64, endurance_range: f64) -> f64 {
    (threshold / (1.12 * endurance_range)).powi(2) / std::f64::consts::PI
}

/// El Haddad's threshold `dK_th sqrt(l/(l + l0))` at length `l`.
pub fn threshold(threshold: f64, l0: f64, l: f64) -> f64 {
    threshold * (l / (l + l0)).sqrt()
}

/// The maximum tangential stress equivalent of `(k1 >= 0, k2)` (Erdogan and Sih 1963): the
/// opening factor on the plane of the largest hoop stress.
pub fn mts_equivalent(k1: f64, k2: f64) -> f64 {
    if k2 == 0.0 {
        return k1;
    }
    let t = 2.0 * ((k1 - (k1 * k1 + 8.0 * k2 * k2).sqrt()) / (4.0 * k2)).atan();
    let c = (0.5 * t).cos();
    c * c * c * k1 - 1.5 * c * t.sin() * k2
}

/// Marches `history` (which must have cycles), takes the tractions of every increment of its
/// last cycle and analyses the crack of `crack` at each length. Errors: no cycle; `[fatigue]`
/// without `threshold` or `endurance_range`; a length above [`MAX_LENGTH_RATIO`] times the
/// largest contact half-width; a critical-plane angle without its parameter's constants or
/// parallel to the surface; an active set that does not settle; any error of the march.
pub fn analyse(
    contact: &Contact,
    history: &History,
    options: &MarchOptions,
    constants: &FatigueConstants,
    crack: &CrackOptions,
) -> Result<CrackResult> {
    let structure = history.cycles().ok_or(Error::NoCycle {
        what: "crack analysis",
    })?;
    let (Some(dk_th), Some(ds0)) = (constants.threshold, constants.endurance_range) else {
        return Err(Error::MissingConstants {
            what: "crack analysis",
            fields: "fatigue.threshold and fatigue.endurance_range",
        });
    };
    let spc = structure.steps_per_cycle();
    let start = structure.first_step() + (structure.count() - 1) * spc;
    let steps: Vec<usize> = (start + 1..=start + spc).collect();
    let states = stress::marched(contact, history, options, &steps)?;
    let a_max = states.iter().map(|s| s.half_width).fold(0.0, f64::max);
    // The contact's outermost ends over the cycle: -a_max and a_max when centred; under a
    // moment the ends move on their own.
    let left_end = states
        .iter()
        .map(|s| s.ends.left)
        .fold(f64::INFINITY, f64::min);
    let right_end = states
        .iter()
        .map(|s| s.ends.right)
        .fold(f64::NEG_INFINITY, f64::max);
    let longest = *crack.lengths.last().unwrap_or(&0.0);
    if longest > MAX_LENGTH_RATIO * a_max {
        return Err(Error::InvalidInput {
            field: "crack.lengths".into(),
            value: longest,
            valid: "crack lengths at most the largest contact half-width of the steady cycle \
                    (the crack is taken as not disturbing the contact)",
        });
    }
    let l0 = el_haddad_length(dk_th, ds0);
    let run = |mouth: f64, lengths: &[f64]| -> Result<(f64, Vec<CrackRow>)> {
        let angle = match crack.angle {
            Angle::Given(angle) => angle,
            Angle::CriticalPlane(p) => critical_plane_angle(mouth, p, contact, &states, constants)?,
        };
        let points = crack
            .points
            .unwrap_or_else(|| default_points(angle.to_degrees()));
        let mut rows = length_rows(mouth, angle, points, lengths, contact, &states, crack)?;
        for row in &mut rows {
            row.threshold = threshold(dk_th, l0, row.length);
        }
        Ok((angle, rows))
    };
    let mouth = match crack.position {
        Position::LeftEdge => left_end,
        Position::RightEdge => right_end,
        Position::At(x) => x,
        Position::LargerRange => {
            let first = &crack.lengths[..1];
            let left = run(left_end, first)?.1[0].delta_k_eff;
            let right = run(right_end, first)?.1[0].delta_k_eff;
            if right > left {
                right_end
            } else {
                left_end
            }
        }
    };
    let (angle, rows) = run(mouth, &crack.lengths)?;
    let (verdict, arrest_length) = Verdict::of(&rows);
    Ok(CrackResult {
        rows,
        verdict,
        arrest_length,
        mouth,
        angle: angle.to_degrees(),
        half_width: a_max,
        steps,
    })
}

/// The crack angle (radians from the surface normal, positive towards `+x`) in the critical plane
/// of `parameter` at the surface point `(mouth, 0)` over the kept increments. The plane's normal
/// makes `alpha` with `+x` (towards `+z`); the crack runs along the plane into the body, so its
/// angle is `-alpha` folded into (-90, 90] degrees.
fn critical_plane_angle(
    mouth: f64,
    parameter: Parameter,
    contact: &Contact,
    states: &[MarchedTraction],
    constants: &FatigueConstants,
) -> Result<f64> {
    let increments: Vec<(&stress::Traction, f64)> = states
        .iter()
        .map(|st| (&st.traction, st.load.bulk()))
        .collect();
    let history: Vec<stress::Stress> =
        stress::fields(&increments, &contact.material, &[mouth], &[0.0])?
            .iter()
            .map(|f| f.at(0))
            .collect();
    let planes = fatigue::critical_planes(&history, &contact.material, constants);
    let critical = match parameter {
        Parameter::Swt => Some(planes.swt),
        Parameter::FatemiSocie => planes.fatemi_socie,
        Parameter::Findley => planes.findley,
        Parameter::Mwcm => planes.mwcm,
        Parameter::FatemiSocieMaxPlane => planes.fatemi_socie_max_plane,
        Parameter::McDiarmid => planes.mcdiarmid,
        _ => None,
    }
    .ok_or(Error::MissingConstants {
        what: "critical-plane crack angle",
        fields: "the [fatigue] constants of crack.initiation_parameter",
    })?;
    let alpha = critical.angle;
    let degrees = if alpha > 90.0 { 180.0 - alpha } else { -alpha };
    if degrees.abs() >= 90.0 - 1e-9 {
        return Err(Error::InvalidInput {
            field: "crack.angle".into(),
            value: degrees,
            valid: "a critical plane that cuts into the body (this one is parallel to the \
                    surface at the mouth): give the angle in degrees instead",
        });
    }
    Ok(degrees.to_radians())
}

/// Every length over the kept increments (thresholds left at 0 for the caller). The uncracked
/// stress is evaluated at the collocation points of all lengths under every increment in one
/// call ([`stress::fields`]: the logarithms of a point and a cell are taken once for the cycle).
fn length_rows(
    mouth: f64,
    angle: f64,
    points: usize,
    lengths: &[f64],
    contact: &Contact,
    states: &[MarchedTraction],
    options: &CrackOptions,
) -> Result<Vec<CrackRow>> {
    let solvers = lengths
        .iter()
        .map(|&l| {
            let c = Crack::new(mouth, angle, l)?;
            CrackSolver::new(&c, &contact.material, points)
        })
        .collect::<Result<Vec<_>>>()?;
    let x: Vec<f64> = solvers.iter().flat_map(|s| s.x().iter().copied()).collect();
    let z: Vec<f64> = solvers.iter().flat_map(|s| s.z().iter().copied()).collect();
    let mut loads: Vec<Vec<(Vec<f64>, Vec<f64>)>> =
        vec![Vec::with_capacity(states.len()); solvers.len()];
    let increments: Vec<(&stress::Traction, f64)> = states
        .iter()
        .map(|st| (&st.traction, st.load.bulk()))
        .collect();
    for f in stress::fields(&increments, &contact.material, &x, &z)? {
        let mut i = 0;
        for (solver, l) in solvers.iter().zip(&mut loads) {
            let (normal, shear): (Vec<f64>, Vec<f64>) = (i..i + solver.x().len())
                .map(|j| solver.resolve(f.sxx[j], f.szz[j], f.sxz[j]))
                .unzip();
            i += solver.x().len();
            l.push((normal, shear));
        }
    }
    solvers
        .iter()
        .zip(&loads)
        .map(|(solver, l)| {
            let solutions = solver.cycle(l, options.face_friction)?;
            let increments = solutions.iter().map(|s| s.factors).collect();
            Ok(row_of(
                solver.crack().length(),
                increments,
                options.effective,
            ))
        })
        .collect()
}

/// The ranges of one length's increments.
pub(crate) fn row_of(
    length: f64,
    increments: Vec<TipFactors>,
    effective: EffectiveRange,
) -> CrackRow {
    let fold = |f: fn(&TipFactors) -> f64| {
        increments
            .iter()
            .map(f)
            .fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), v| {
                (lo.min(v), hi.max(v))
            })
    };
    let (k1_min, k1_max) = fold(|k| k.k1);
    let (k2_min, k2_max) = fold(|k| k.k2);
    let (delta_k1, delta_k2) = (k1_max - k1_min, k2_max - k2_min);
    let delta_k_eff = match effective {
        EffectiveRange::Mts => mts_equivalent(delta_k1, delta_k2),
        EffectiveRange::Quadratic => delta_k1.hypot(delta_k2),
    };
    CrackRow {
        length,
        k1_max,
        k1_min,
        k2_max,
        k2_min,
        delta_k1,
        delta_k2,
        delta_k_eff,
        threshold: 0.0,
        increments,
    }
}
