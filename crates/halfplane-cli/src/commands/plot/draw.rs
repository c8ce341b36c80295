//! Drawing a resolved `plot` configuration: the marches, stress and fatigue fields a figure
//! needs, computed here, then handed to the plot crate.

use super::{FigureConfig, PlotConfig, MAP_POINTS};
use crate::args::Component;
use crate::output::note;
use crate::report::wear::WearRow;
use crate::report::Cell;
use anyhow::{anyhow, Result};
use halfplane::fatigue;
use halfplane::history::History;
use halfplane::march::{self, MarchOptions};
use halfplane::wear::Checkpoint;
use halfplane::{stress, Contact};
use halfplane_plot::{CheckpointQuantity, FieldRecorder, GridMap, MarchedCycle, Units};

/// The stress map: march to the increment, evaluate the component on a grid over
/// `+/-1.5 a` and down to `a` (`a` the half-width there) and draw it as a filled map.
fn stress_map(
    contact: &Contact,
    history: &History,
    options: &MarchOptions,
    step: usize,
    component: Component,
    units: &Units,
) -> Result<halfplane_plot::Figure> {
    let state = stress::marched(contact, history, options, &[step])?
        .into_iter()
        .next()
        .ok_or_else(|| anyhow!("the march did not reach step {step}"))?;
    let (x, z, field) = map_field(contact, &state)?;
    let (values, name) = match component {
        Component::Sxx => (field.sxx, "σxx"),
        Component::Szz => (field.szz, "σzz"),
        Component::Syy => (field.syy, "σyy"),
        Component::Sxz => (field.sxz, "σxz"),
    };
    let map = GridMap {
        x: &x,
        z: &z,
        values: &values,
    };
    Ok(halfplane_plot::stress_map_figure(
        &map,
        name,
        step,
        [state.ends.left, state.ends.right],
        units,
    )?)
}

/// The stresses of a marched increment on the map's grid over `+/-1.5 a` about the contact's
/// centre and down to `a` (`a` the half-width then): the grid's x and z and the field row after
/// row (z outer).
fn map_field(
    contact: &Contact,
    state: &stress::MarchedTraction,
) -> Result<(Vec<f64>, Vec<f64>, stress::StressField)> {
    // Centred on the contact, which a moment moves off x = 0.
    let a = state.half_width;
    let centre = 0.5 * (state.ends.left + state.ends.right);
    grid_field(contact, state, centre, 1.5 * a, a)
}

/// The stresses of a marched increment on the map's grid: `x` from `centre - half` to
/// `centre + half`, `z` from 0 to `depth`; the grid's x and z and the field row after row.
fn grid_field(
    contact: &Contact,
    state: &stress::MarchedTraction,
    centre: f64,
    half: f64,
    depth: f64,
) -> Result<(Vec<f64>, Vec<f64>, stress::StressField)> {
    let (nx, nz) = MAP_POINTS;
    let x: Vec<f64> = (0..nx)
        .map(|i| centre + half * (-1.0 + 2.0 * i as f64 / (nx - 1) as f64))
        .collect();
    let z: Vec<f64> = (0..nz)
        .map(|j| depth * j as f64 / (nz - 1) as f64)
        .collect();
    let (px, pz): (Vec<f64>, Vec<f64>) = z
        .iter()
        .flat_map(|&z| x.iter().map(move |&x| (x, z)))
        .unzip();
    let field = stress::field(
        &state.traction,
        state.load.bulk(),
        &contact.material(),
        &px,
        &pz,
    )?;
    Ok((x, z, field))
}

/// The crack figure: the analysis of `halfplane crack`, and the `sxx` map at the increment where
/// the longest crack opens most (the first of the cycle when it never opens).
fn crack_figure(
    contact: &Contact,
    history: &History,
    options: &MarchOptions,
    constants: &halfplane::fatigue::FatigueConstants,
    crack: &halfplane::crack::CrackOptions,
    units: &Units,
) -> Result<halfplane_plot::Figure> {
    let result = halfplane::crack::analyse(contact, history, options, constants, crack)?;
    let longest = result
        .rows
        .last()
        .ok_or_else(|| anyhow!("the crack analysis gave no rows"))?;
    let peak = longest
        .increments
        .iter()
        .enumerate()
        .max_by(|a, b| a.1.k1.total_cmp(&b.1.k1))
        .map_or(0, |(i, _)| i);
    let step = result.steps[peak];
    let state = stress::marched(contact, history, options, &[step])?
        .into_iter()
        .next()
        .ok_or_else(|| anyhow!("the march did not reach step {step}"))?;
    // The map around the crack: 1.5 crack lengths to either side of the mouth and below it (at
    // least a fifth of the contact half-width), so that the stress the crack crosses shows.
    let span = 1.5 * longest.length.max(0.2 * state.half_width);
    let (x, z, field) = grid_field(contact, &state, result.mouth, span, span)?;
    let map = GridMap {
        x: &x,
        z: &z,
        values: &field.sxx,
    };
    Ok(halfplane_plot::crack_figure(
        &result,
        &map,
        step,
        [state.ends.left, state.ends.right],
        units,
    )?)
}

/// Computes the figure, writes it and says where on stderr. The figures that march or integrate
/// say they are running every progress interval, like the commands that do (`fatigue`).
pub fn run(config: &PlotConfig) -> Result<()> {
    let fig = crate::progress::while_running("plot", || figure(config))?;
    halfplane_plot::write(&fig, &config.output)?;
    note(&format!("wrote {}", config.output.display()));
    Ok(())
}

/// The figure's data computed and laid out.
fn figure(config: &PlotConfig) -> Result<halfplane_plot::Figure> {
    let (contact, units) = (&config.contact, &config.units);
    Ok(match &config.figure {
        FigureConfig::LoadSpace { cycle } => {
            halfplane_plot::load_space_figure(contact, cycle, units)?
        }
        FigureConfig::SlipMap(map) => halfplane_plot::slip_map_figure(contact, map, units)?,
        FigureConfig::Evolution {
            cycle,
            points,
            overlay,
        } => {
            let ev = crate::commands::evolve::evolve(contact, cycle, *points)?;
            let marched = match overlay {
                Some((history, options)) => {
                    let result = march::march(contact, history, options, |_, _| {})?;
                    let marched = MarchedCycle::last_cycle(&result, history).ok_or_else(|| {
                        anyhow!(
                            "the marching overlay needs a cyclic history ([history] kind = \"cycle\")"
                        )
                    })?;
                    Some(marched)
                }
                None => None,
            };
            halfplane_plot::evolution_figure(&ev, marched.as_ref(), units)
        }
        FigureConfig::MarchFields {
            history,
            options,
            steps,
        } => {
            let mut recorder = FieldRecorder {
                steps: steps.clone(),
                kept: Vec::new(),
            };
            let f = contact.friction().value();
            march::march(contact, history, options, |r, fields| {
                recorder.observe(r.step, fields, f)
            })?;
            halfplane_plot::march_fields_figure(&recorder.kept, units)
        }
        FigureConfig::MarchZones { history, options } => {
            let result = march::march(contact, history, options, |_, _| {})?;
            halfplane_plot::march_zones_figure(&result, units)
        }
        FigureConfig::Match { cycle, test, mode } => {
            let report = halfplane::matching::match_cycle(contact, cycle, test, *mode)?;
            halfplane_plot::match_figure(&report, units)?
        }
        FigureConfig::StressMap {
            history,
            options,
            step,
            component,
        } => stress_map(contact, history, options, *step, *component, units)?,
        FigureConfig::Fatigue {
            history,
            options,
            settings,
            parameter,
        } => {
            let result = fatigue::analyse(
                contact,
                history,
                options,
                &settings.constants,
                &settings.grid,
            )?;
            match parameter {
                Some(p) => halfplane_plot::fatigue_map_figure(&result, *p, units)?,
                None => halfplane_plot::surface_profiles_figure(&result, units),
            }
        }
        FigureConfig::Crack {
            history,
            options,
            constants,
            crack,
        } => crack_figure(contact, history, options, constants, crack, units)?,
        FigureConfig::Wear {
            case,
            settings,
            cells,
            quantity,
        } => {
            let mut worn = case.worn_march(settings, *cells)?;
            let result = halfplane::wear::run(&mut worn, &settings.options, |_| {})?;
            let quantity = checkpoint_quantity(&result.checkpoints, quantity, &case.units)?;
            halfplane_plot::wear_figure(&result, &quantity, worn.loop_datum(), units)?
        }
    })
}

/// The column `name` of the `wear` report at every checkpoint, with its unit: the numbers its
/// CSV prints (`None` where it prints nothing).
fn checkpoint_quantity(
    checkpoints: &[Checkpoint],
    name: &str,
    units: &crate::units::Units,
) -> Result<CheckpointQuantity> {
    let column = WearRow::COLUMNS
        .iter()
        .find(|c| c.key == name)
        .ok_or_else(|| anyhow!("invalid --quantity {name}: not a column of the wear report"))?;
    let values = checkpoints
        .iter()
        .map(|c| match (column.get)(&WearRow::new(c)) {
            Cell::Num(v) => Some(v),
            _ => None,
        })
        .collect();
    Ok(CheckpointQuantity {
        name: name.to_string(),
        unit: units.of(column.quantity),
        values,
    })
}
