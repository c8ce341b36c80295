//! The `[fatigue]` section: the material constants of the initiation parameters and the grid
//! they are searched on (`docs/fatigue.md`). Each constant is validated by the library's setter,
//! whose error names the field as the file spells it.

use super::count::{count_in, RawCount};
use anyhow::{anyhow, bail, Result};
use halfplane::fatigue::{FatigueConstants, FatigueGrid, Parameter, Planes, MAX_GRID_POINTS};
use serde::Deserialize;

/// `[fatigue]` as the case file gives it.
#[derive(Debug, Default, Deserialize)]
#[serde(deny_unknown_fields)]
struct RawFatigue {
    fatigue_strength: Option<f64>,
    fatigue_strength_exponent: Option<f64>,
    fatigue_ductility: Option<f64>,
    fatigue_ductility_exponent: Option<f64>,
    shear_fatigue_strength: Option<f64>,
    shear_fatigue_ductility: Option<f64>,
    fatemi_socie_k: Option<f64>,
    findley_k: Option<f64>,
    crossland_alpha: Option<f64>,
    yield_stress: Option<f64>,
    threshold: Option<f64>,
    endurance_range: Option<f64>,
    axial_fatigue_limit: Option<f64>,
    torsional_fatigue_limit: Option<f64>,
    mcdiarmid_shear_limit: Option<f64>,
    ultimate_strength: Option<f64>,
    planes: Option<String>,
    nx: Option<RawCount>,
    nz: Option<RawCount>,
    width: Option<f64>,
    depth: Option<f64>,
}

/// `[fatigue]` resolved: what `fatigue` and the fatigue figures run with.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct FatigueSettings {
    /// The material constants (a parameter whose constants are missing is not reported).
    pub constants: FatigueConstants,
    /// The grid below the contact.
    pub grid: FatigueGrid,
}

/// Resolves `[fatigue]` (absent: no constants, the default grid).
pub(super) fn resolve(table: Option<&toml::Table>) -> Result<FatigueSettings> {
    let raw: RawFatigue = match table {
        Some(t) => t
            .clone()
            .try_into()
            .map_err(|e| anyhow!("in section [fatigue]: {}", e.to_string().trim_end()))?,
        None => RawFatigue::default(),
    };
    let mut c = FatigueConstants::default();
    type Setter = fn(FatigueConstants, f64) -> halfplane::Result<FatigueConstants>;
    let fields: [(Option<f64>, Setter); 12] = [
        (
            raw.fatigue_strength,
            FatigueConstants::with_fatigue_strength,
        ),
        (
            raw.fatigue_strength_exponent,
            FatigueConstants::with_fatigue_strength_exponent,
        ),
        (
            raw.fatigue_ductility,
            FatigueConstants::with_fatigue_ductility,
        ),
        (
            raw.fatigue_ductility_exponent,
            FatigueConstants::with_fatigue_ductility_exponent,
        ),
        (
            raw.shear_fatigue_strength,
            FatigueConstants::with_shear_fatigue_strength,
        ),
        (
            raw.shear_fatigue_ductility,
            FatigueConstants::with_shear_fatigue_ductility,
        ),
        (raw.fatemi_socie_k, FatigueConstants::with_fatemi_socie_k),
        (raw.findley_k, FatigueConstants::with_findley_k),
        (raw.crossland_alpha, FatigueConstants::with_crossland_alpha),
        (raw.yield_stress, FatigueConstants::with_yield_stress),
        (raw.threshold, FatigueConstants::with_threshold),
        (raw.endurance_range, FatigueConstants::with_endurance_range),
    ];
    for (value, set) in fields {
        if let Some(v) = value {
            c = set(c, v)?;
        }
    }
    c = match (raw.axial_fatigue_limit, raw.torsional_fatigue_limit) {
        (Some(axial), Some(torsional)) => c.with_fatigue_limits(axial, torsional)?,
        (None, None) => c,
        (Some(_), None) => bail!("missing field fatigue.torsional_fatigue_limit: the Modified Wohler Curve Method needs it with axial_fatigue_limit (give tau_-1, the fully reversed torsional fatigue limit as an amplitude)"),
        (None, Some(_)) => bail!("missing field fatigue.axial_fatigue_limit: the Modified Wohler Curve Method needs it with torsional_fatigue_limit (give sigma_-1, the fully reversed axial fatigue limit as an amplitude)"),
    };
    c = match (raw.mcdiarmid_shear_limit, raw.ultimate_strength) {
        (Some(t), Some(u)) => c.with_mcdiarmid(t, u)?,
        (None, None) => c,
        (Some(_), None) => bail!("missing field fatigue.ultimate_strength: McDiarmid's criterion needs it with mcdiarmid_shear_limit (give sigma_u, the ultimate tensile strength)"),
        (None, Some(_)) => bail!("missing field fatigue.mcdiarmid_shear_limit: McDiarmid's criterion needs it with ultimate_strength (give t_A,B, the fully reversed shear fatigue limit of the crack case as an amplitude)"),
    };
    let planes = match &raw.planes {
        Some(name) => Planes::from_name(name)?,
        None => Planes::InPlane,
    };
    let count = |v: &Option<RawCount>, field: &str, default: usize| match v {
        Some(v) => count_in(v, field, 2, MAX_GRID_POINTS),
        None => Ok(default),
    };
    let grid = FatigueGrid::new(
        count(&raw.nx, "fatigue.nx", 100)?,
        count(&raw.nz, "fatigue.nz", 50)?,
        raw.width.unwrap_or(1.5),
        raw.depth.unwrap_or(1.0),
    )?
    .with_planes(planes);
    Ok(FatigueSettings { constants: c, grid })
}

impl FatigueSettings {
    /// One line per parameter that the constants leave out, naming it and the `[fatigue]` fields it
    /// lacks (what `fatigue` warns about on stderr rather than dropping the row silently).
    pub fn skipped(&self) -> Vec<String> {
        let constants = &self.constants;
        Parameter::ALL
            .iter()
            .filter_map(|&p| {
                let missing = constants.missing_for(p);
                (!missing.is_empty()).then(|| {
                    let fields: Vec<String> =
                        missing.iter().map(|m| format!("fatigue.{m}")).collect();
                    format!(
                        "{} not reported: [fatigue] does not give {}",
                        p.name(),
                        fields.join(" and ")
                    )
                })
            })
            .collect()
    }
}
