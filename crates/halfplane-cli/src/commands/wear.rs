//! `halfplane wear`: fretting wear of the case's contact over `[wear] cycles` load cycles.

use crate::args::{Format, WearArgs};
use crate::output::{emit, note};
use crate::progress::Progress;
use crate::report::wear::{fields_csv, loop_csv, WearReport};
use crate::units::Units;
use anyhow::{anyhow, bail, Result};
use halfplane::fatigue::{self, FatigueConstants, FatigueGrid, FatigueResult};
use halfplane::march::Worn;
use halfplane::wear::{self, Checkpoint, WearOptions, WornCycle};
use halfplane::Material;
use std::path::PathBuf;

/// `--fatigue`: what each checkpoint's cycle is evaluated with.
pub struct WearFatigue {
    /// The specimen's material.
    pub material: Material,
    /// `[fatigue]` constants.
    pub constants: FatigueConstants,
    /// `[fatigue]` grid, scaled on the unworn contact.
    pub grid: FatigueGrid,
    /// The parameters `[fatigue]` leaves out, one line each, for stderr.
    pub skipped: Vec<String>,
}

/// What `wear` runs on.
pub struct WearConfig {
    /// The march over the worn gap, its ramp done.
    pub worn: Worn,
    /// `[wear]`.
    pub options: WearOptions,
    /// `--fields DIR`: where to write each checkpoint's fields.
    pub fields: Option<PathBuf>,
    /// The unit names of `[units]`.
    pub units: Units,
    /// Table, CSV or JSON.
    pub format: Format,
    /// `--fatigue`.
    pub fatigue: Option<WearFatigue>,
}

impl WearConfig {
    /// Reads the case (with `[wear]` and a one-cycle or sliding `[history]`), applies `--cells`
    /// and marches the ramp.
    pub fn resolve(args: &WearArgs) -> Result<Self> {
        let case = crate::case::load(&args.case)?;
        let settings = case.wear()?;
        let fatigue = if args.fatigue {
            let f = case.fatigue()?;
            if f.constants == FatigueConstants::default() {
                bail!(
                    "--fatigue needs material constants in [fatigue], and {} gives none: add the \
                     constants of the parameters to report (fatigue.findley_k, \
                     fatigue.crossland_alpha, fatigue.fatemi_socie_k with fatigue.yield_stress, \
                     fatigue.axial_fatigue_limit with fatigue.torsional_fatigue_limit, \
                     fatigue.mcdiarmid_shear_limit with fatigue.ultimate_strength, the \
                     strain-life constants, fatigue.threshold with fatigue.endurance_range; \
                     docs/fatigue.md)",
                    args.case.display()
                );
            }
            Some(WearFatigue {
                material: case.contact.material(),
                constants: f.constants,
                grid: f.grid,
                skipped: f.skipped(),
            })
        } else {
            None
        };
        let mut worn = case.worn_march(&settings, args.cells)?;
        if fatigue.is_some() {
            worn.record_tractions();
        }
        Ok(Self {
            worn,
            options: settings.options,
            fields: args.fields.clone(),
            units: case.units,
            format: args.format.format(),
            fatigue,
        })
    }
}

/// Runs the wear loop (progress on stderr, one tick per checkpoint), writes each checkpoint's
/// fields as it is reached, evaluates the fatigue parameters of its cycle with `--fatigue`, and
/// prints the report. When the march fails part way, the report of the checkpoints reached is
/// printed before the error.
pub fn run(config: WearConfig) -> Result<()> {
    let WearConfig {
        mut worn,
        options,
        fields,
        units,
        format,
        fatigue,
    } = config;
    if let Some(f) = &fatigue {
        for line in &f.skipped {
            eprintln!("warning: {line}");
        }
    }
    let unworn = worn.unworn_contact();
    let mut parameters: Vec<FatigueResult> = Vec::new();
    let mut fatigue_error = None;
    if let Some(dir) = &fields {
        std::fs::create_dir_all(dir).map_err(|e| {
            anyhow!(
                "cannot create the --fields directory {}: {e}",
                dir.display()
            )
        })?;
    }
    let bar = Progress::new("wear", "checkpoints", options.checkpoints().len() as u64);
    let mut reached: Vec<Checkpoint> = Vec::new();
    let mut write_error = None;
    let (approach, datum) = (worn.elastic_approach(), worn.loop_datum());
    let outcome = wear::run(&mut worn, &options, |c| {
        bar.inc(1);
        if let (Some(dir), None) = (&fields, &write_error) {
            for (name, text) in [("checkpoint", fields_csv(c)), ("loop", loop_csv(c))] {
                let path = dir.join(format!("{name}_{}.csv", c.cycle));
                if let Err(e) = std::fs::write(&path, text) {
                    write_error.get_or_insert(anyhow!("cannot write {}: {e}", path.display()));
                }
            }
        }
        if let (Some(f), Some(cycle), None) = (&fatigue, &c.tractions, &fatigue_error) {
            match fatigue::analyse_cycle(&f.material, cycle, unworn, &f.constants, &f.grid) {
                Ok(r) => parameters.push(r),
                Err(e) => fatigue_error = Some(anyhow!("--fatigue at cycle {}: {e}", c.cycle)),
            }
        }
        let mut c = c.clone();
        c.tractions = None;
        reached.push(c);
    });
    bar.finish();
    if let Some(e) = write_error {
        return Err(e);
    }
    if let Some(e) = fatigue_error {
        return Err(e);
    }
    let (simulated, stopped) = match &outcome {
        Ok(r) => (Some(r.simulated_cycles), None),
        Err(e) => (None, Some(e.to_string())),
    };
    let mut report = WearReport::new(
        &reached, simulated, approach, datum, &options, &units, stopped,
    );
    if fatigue.is_some() {
        report = report.with_fatigue(&parameters);
    }
    if outcome.is_err() && !reached.is_empty() {
        note(&format!(
            "wear stopped after {} checkpoint(s); the report below holds them",
            reached.len()
        ));
    }
    if outcome.is_ok() || !reached.is_empty() {
        emit(&match format {
            Format::Table => report.table(),
            Format::Csv => report.csv(),
            Format::Json => report.json()? + "\n",
        })?;
    }
    outcome.map(|_| ())?;
    Ok(())
}
