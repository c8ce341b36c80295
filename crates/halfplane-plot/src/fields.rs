//! Figures below and on the surface ([`halfplane::stress`], [`halfplane::fatigue`]): contour maps
//! of a stress component and of a fatigue parameter with its critical point, and the surface
//! profiles of `sxx` and Ruiz F2 over the cycle. Depth runs downwards: the y axis is `-z`.

use crate::contour::{levels, segments, GridMap};
use crate::{Figure, Legend, Panel, PlotError, Series, Style, Units};
use halfplane::fatigue::{FatigueResult, Parameter};

/// The palette colours of the contour levels, lowest first: every colour but black (3), which
/// marks the contact and the line method's line, red (1), which marks the maximum, and grey (7),
/// which outlines the grid.
const LEVEL_COLORS: [usize; 7] = [0, 6, 2, 8, 5, 4, 9];

/// The contour lines of `map`, one series per level named `"{label} = {level}{unit}"`.
fn contours(map: &GridMap, label: &str, unit: &str) -> Result<Vec<Series>, PlotError> {
    if !map.is_consistent() {
        return Err(PlotError::Request(format!(
            "a map needs at least 2 x 2 points and one value per point: {} x, {} z, {} values",
            map.x.len(),
            map.z.len(),
            map.values.len()
        )));
    }
    let Some((lo, hi)) = map.range() else {
        return Err(PlotError::Request(format!(
            "{label} has no finite value to draw"
        )));
    };
    let (levels, decimals) = levels(lo, hi, LEVEL_COLORS.len());
    let mut series: Vec<Series> = levels
        .iter()
        .zip(LEVEL_COLORS)
        .map(|(&level, color)| Series {
            name: format!("{label} = {level:.decimals$}{unit}").replace('-', "−"),
            style: Style::Segments,
            color,
            pieces: vec![segments(map, level)],
        })
        .filter(|s| s.pieces[0].len() >= 2)
        .collect();
    // The grid's outline, so the figure spans all of it (not only where lines run).
    let (x0, x1) = (map.x[0], map.x[map.x.len() - 1]);
    let (z0, z1) = (map.z[0], map.z[map.z.len() - 1]);
    series.push(Series::new(
        "evaluation grid",
        Style::Dashed,
        7,
        vec![(x0, -z0), (x1, -z0), (x1, -z1), (x0, -z1), (x0, -z0)],
    ));
    Ok(series)
}

fn depth_label(units: &Units) -> String {
    format!("−z, depth below the surface ({})", units.length)
}

/// The contour map of one stress component below the contact at increment `step`: `name` is the
/// component as shown (for example "σxx"), `half_width` the contact half-width at that increment
/// (the contact is drawn on the surface). The values are the caller's, in the stress unit.
pub fn stress_map_figure(
    map: &GridMap,
    name: &str,
    step: usize,
    half_width: f64,
    units: &Units,
) -> Result<Figure, PlotError> {
    let mut series = contours(map, name, &format!(" {}", units.stress))?;
    series.push(Series::new(
        "contact −a ≤ x ≤ a",
        Style::Line,
        3,
        vec![(-half_width, 0.0), (half_width, 0.0)],
    ));
    Ok(Figure {
        title: format!("{name} below the contact at increment {step}"),
        panels: vec![Panel {
            legend: Legend::Below,
            title: format!("contours of {name} (tension positive)"),
            x_label: format!("position x ({})", units.length),
            y_label: depth_label(units),
            series,
        }],
    })
}

/// How a parameter is named on a figure, and whether it is a stress (else dimensionless or, for
/// SWT and Ruiz, the product units the report uses).
fn display(parameter: Parameter) -> &'static str {
    match parameter {
        Parameter::Swt => "SWT",
        Parameter::FatemiSocie => "Fatemi-Socie",
        Parameter::Findley => "Findley",
        Parameter::Crossland => "Crossland",
        Parameter::RuizF1 => "Ruiz F1",
        Parameter::RuizF2 => "Ruiz F2",
        Parameter::Mwcm => "MWCM",
        Parameter::FatemiSocieMaxPlane => "Fatemi-Socie (max. plane)",
        Parameter::McDiarmid => "McDiarmid",
        _ => "parameter",
    }
}

/// The map of `parameter` over the fatigue grid of `result` with its maximum marked (and, when
/// the critical distance is known, the line below it over which the line method averages).
/// Errors: a parameter that was not evaluated (no map: its constants are missing, or Ruiz, which
/// lives on the surface).
pub fn fatigue_map_figure(
    result: &FatigueResult,
    parameter: Parameter,
    units: &Units,
) -> Result<Figure, PlotError> {
    let name = display(parameter);
    let (Some(values), Some(best)) = (result.map(parameter), result.parameter(parameter)) else {
        return Err(PlotError::Request(format!(
            "{} was not evaluated on the grid (its constants are missing, or it is a surface value)",
            parameter.name()
        )));
    };
    let map = GridMap {
        x: &result.grid_x,
        z: &result.grid_z,
        values,
    };
    let unit = match parameter {
        Parameter::Findley | Parameter::Crossland | Parameter::Mwcm | Parameter::McDiarmid => {
            format!(" {}", units.stress)
        }
        _ => String::new(),
    };
    let mut series = contours(&map, name, &unit)?;
    if let Some(l) = result.critical_distance {
        series.push(Series::new(
            "line method: 0 ≤ z ≤ 2L",
            Style::Line,
            3,
            vec![(best.x, 0.0), (best.x, -2.0 * l)],
        ));
    }
    let plane = best
        .angle
        .map_or(String::new(), |a| format!(", plane {a:.1}°"));
    series.push(Series::new(
        format!(
            "maximum {:.4e} at x = {:.4}, z = {:.4}{plane}",
            best.value, best.x, best.z
        ),
        Style::Points,
        1,
        vec![(best.x, -best.z)],
    ));
    Ok(Figure {
        title: format!(
            "{name} over the steady cycle (increments {} to {})",
            result.steps.first().copied().unwrap_or(0),
            result.steps.last().copied().unwrap_or(0)
        ),
        panels: vec![Panel {
            legend: Legend::Below,
            title: format!("contours of {name} ({})", parameter.name()),
            x_label: format!("position x ({})", units.length),
            y_label: depth_label(units),
            series,
        }],
    })
}

/// The surface profiles of the steady cycle: `sxx(x, 0)` at a quarter, half, three quarters and
/// the end of the cycle with its largest value over the cycle dashed, and Ruiz F2
/// `sxx,max |q|max delta` with its maximum marked, at the cell centres in contact.
pub fn surface_profiles_figure(result: &FatigueResult, units: &Units) -> Figure {
    let x = &result.surface_x;
    let xy = |v: &[f64]| x.iter().copied().zip(v.iter().copied()).collect::<Vec<_>>();
    let n = result.surface_sxx.len();
    let mut sxx = Vec::new();
    for (color, (q, when)) in [(1, "1/4"), (2, "1/2"), (3, "3/4"), (4, "end")]
        .into_iter()
        .enumerate()
    {
        let k = (q * n / 4).saturating_sub(1);
        if let (Some(row), Some(step)) = (result.surface_sxx.get(k), result.steps.get(k)) {
            sxx.push(Series::new(
                format!("increment {step} ({when} of the cycle)"),
                Style::Line,
                color,
                xy(row),
            ));
        }
    }
    sxx.push(Series::new(
        "largest over the cycle",
        Style::Dashed,
        3,
        xy(&result.surface_sxx_max),
    ));
    let mut f2 = vec![Series::new(
        "F2 = σxx,max |q|max δ",
        Style::Line,
        0,
        xy(&result.ruiz_f2_profile),
    )];
    if let Some(best) = result.parameter(Parameter::RuizF2) {
        f2.push(Series::new(
            format!("maximum {:.4e} at x = {:.4}", best.value, best.x),
            Style::Points,
            1,
            vec![(best.x, best.value)],
        ));
    }
    Figure {
        title: "Surface over the steady cycle".into(),
        panels: vec![
            Panel {
                legend: Legend::Auto,
                title: "surface σxx(x, 0)".into(),
                x_label: format!("position x ({})", units.length),
                y_label: format!("σxx ({})", units.stress),
                series: sxx,
            },
            Panel {
                legend: Legend::Auto,
                title: "Ruiz F2 (δ the slip amplitude)".into(),
                x_label: format!("position x ({})", units.length),
                y_label: format!("F2 ({}·{}·{})", units.stress, units.stress, units.length),
                series: f2,
            },
        ],
    }
}
