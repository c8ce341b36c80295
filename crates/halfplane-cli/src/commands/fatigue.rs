//! `halfplane fatigue`: initiation parameters over the steady (last) cycle of the history, with
//! the material constants of `[fatigue]` (`docs/fatigue.md`).

use crate::args::{FatigueArgs, Format};
use crate::output::emit;
use crate::report::fatigue::FatigueReport;
use crate::units::Units;
use anyhow::{anyhow, Result};
use halfplane::fatigue::{self, FatigueConstants, FatigueGrid};
use halfplane::history::History;
use halfplane::march::MarchOptions;
use halfplane::Contact;
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
    nx: Option<usize>,
    nz: Option<usize>,
    width: Option<f64>,
    depth: Option<f64>,
}

/// What `fatigue` runs on.
#[derive(Debug, Clone)]
pub struct FatigueConfig {
    /// The contact.
    pub contact: Contact,
    /// The (cyclic) history.
    pub history: History,
    /// `[solver]` with `--cells` applied.
    pub options: MarchOptions,
    /// `[fatigue]` constants.
    pub constants: FatigueConstants,
    /// `[fatigue]` grid.
    pub grid: FatigueGrid,
    /// Unit names.
    pub units: Units,
    /// Table, CSV or JSON.
    pub format: Format,
}

impl FatigueConfig {
    /// Reads the case and resolves `[fatigue]`.
    pub fn resolve(args: &FatigueArgs) -> Result<Self> {
        let case = crate::case::load(&args.case)?;
        let raw: RawFatigue = match &case.fatigue {
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
        let grid = FatigueGrid::new(
            raw.nx.unwrap_or(100),
            raw.nz.unwrap_or(50),
            raw.width.unwrap_or(1.5),
            raw.depth.unwrap_or(1.0),
        )?;
        Ok(Self {
            history: case.history()?,
            options: case.solver_with_cells(args.cells)?,
            contact: case.contact,
            constants: c,
            grid,
            units: case.units,
            format: args.format.format(),
        })
    }
}

/// Runs the analysis and prints the report.
pub fn run(config: &FatigueConfig) -> Result<()> {
    let result = fatigue::analyse(
        &config.contact,
        &config.history,
        &config.options,
        &config.constants,
        &config.grid,
    )?;
    let report = FatigueReport::new(&result, &config.units);
    emit(&match config.format {
        Format::Table => report.table(),
        Format::Csv => report.csv(),
        Format::Json => report.json()? + "\n",
    })
}
