//! Figures below and on the surface ([`halfplane::stress`], [`halfplane::fatigue`]): filled maps
//! of a stress component and of a fatigue parameter with a colour bar and the maximum marked, and
//! the surface profiles of `sxx` and Ruiz F2 over the cycle. Depth runs downwards: the y axis is
//! `-z`, drawn to the same scale as x.

use crate::contour::GridMap;
use crate::format::number;
use crate::shading::{filled_map, Shading};
use crate::{ColorBar, Figure, Legend, LogAxes, Panel, PlotError, Series, Style, Units};
use halfplane::fatigue::{FatigueResult, Parameter};

/// The palette colour of the marked maximum (black, with a white ring: it reads on every band).
const MAXIMUM_COLOR: usize = 3;

/// The filled map of `map` below the surface (plot y = −z) with its colour bar labelled
/// `label`; errors for a grid that is not one or a field with no finite value.
fn field_map(
    map: &GridMap,
    name: &str,
    label: String,
    shading: Shading,
) -> Result<(Vec<Series>, ColorBar), PlotError> {
    if !map.is_consistent() {
        return Err(PlotError::Request(format!(
            "a map needs at least 2 x 2 points and one value per point: {} x, {} z, {} values",
            map.x.len(),
            map.z.len(),
            map.values.len()
        )));
    }
    let Some(range) = map.range() else {
        return Err(PlotError::Request(format!(
            "{name} has no finite value to draw"
        )));
    };
    let nx = map.x.len();
    let value = |i: usize, j: usize| Some(map.values[j * nx + i]).filter(|v| v.is_finite());
    Ok(filled_map(
        (map.x, map.z),
        value,
        range,
        shading,
        label,
        |(x, z)| (x, -z),
    ))
}

/// The largest (`largest`) or smallest finite value of the map and where it is, `(x, z, value)`.
fn extreme(map: &GridMap, largest: bool) -> Option<(f64, f64, f64)> {
    let nx = map.x.len();
    let finite = map.values.iter().enumerate().filter(|(_, v)| v.is_finite());
    let found = if largest {
        finite.max_by(|a, b| a.1.total_cmp(b.1))
    } else {
        finite.min_by(|a, b| a.1.total_cmp(b.1))
    };
    found.map(|(k, &v)| (map.x[k % nx], map.z[k / nx], v))
}

/// The marker of an extreme `value` (with its unit, leading space included) at (x, z), its text
/// `"{what} {value} at (x, z) = ({x}, {z}) {length}{extra}"` written beside it.
fn marked(
    what: &str,
    (x, z, value): (f64, f64, f64),
    unit: &str,
    units: &Units,
    extra: &str,
) -> Series {
    Series::new(
        format!(
            "{what} {}{unit} at (x, z) = ({}, {}) {}{extra}",
            number(value),
            number(x),
            number(z),
            units.length
        ),
        Style::Annotated,
        MAXIMUM_COLOR,
        vec![(x, -z)],
    )
}

fn depth_label(units: &Units) -> String {
    format!("−z, depth below the surface ({})", units.length)
}

/// The filled map of one stress component below the contact at increment `step`, on a diverging
/// colour map centred on zero (tension red, compression blue) with its colour bar, the contact on
/// the surface and the largest and (when negative) the smallest value marked: `name` is the component as shown (for example
/// "σxx"), `half_width` the contact half-width at that increment. The values are the caller's,
/// in the stress unit; x and depth are drawn to the same scale.
pub fn stress_map_figure(
    map: &GridMap,
    name: &str,
    step: usize,
    contact: [f64; 2],
    units: &Units,
) -> Result<Figure, PlotError> {
    let label = format!("{name} ({})", units.stress);
    let (mut series, bar) = field_map(map, name, label, Shading::Diverging)?;
    let [left, right] = contact;
    series.push(Series::new(
        if left == -right {
            "contact −a ≤ x ≤ a"
        } else {
            "contact b1 ≤ x ≤ b2"
        },
        Style::Line,
        3,
        vec![(left, 0.0), (right, 0.0)],
    ));
    // Both extremes of a signed stress: the largest tension and the largest compression.
    let unit = format!(" {}", units.stress);
    if let Some(max) = extreme(map, true) {
        series.push(marked("max", max, &unit, units, ""));
    }
    if let Some(min) = extreme(map, false).filter(|m| m.2 < 0.0) {
        series.push(marked("min", min, &unit, units, ""));
    }
    Ok(Figure {
        title: format!("{name} below the contact at increment {step}"),
        panels: vec![Panel {
            legend: Legend::Below,
            color_bar: Some(bar),
            equal_aspect: true,
            log_axes: LogAxes::Neither,
            title: format!("{name} (tension positive)"),
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
    let label = match unit.trim() {
        "" => name.to_string(),
        u => format!("{name} ({u})"),
    };
    let (mut series, bar) = field_map(&map, name, label, Shading::Sequential)?;
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
    series.push(marked(
        "max",
        (best.x, best.z, best.value),
        &unit,
        units,
        &plane,
    ));
    Ok(Figure {
        title: format!(
            "{name} over the steady cycle (increments {} to {})",
            result.steps.first().copied().unwrap_or(0),
            result.steps.last().copied().unwrap_or(0)
        ),
        panels: vec![Panel {
            legend: Legend::Below,
            color_bar: Some(bar),
            equal_aspect: true,
            log_axes: LogAxes::Neither,
            title: format!("{name} ({})", parameter.name()),
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
    let f2_unit = format!("{}²·{}", units.stress, units.length);
    let mut f2 = vec![Series::new(
        "F2 = σxx,max |q|max δ",
        Style::Line,
        0,
        xy(&result.ruiz_f2_profile),
    )];
    if let Some(best) = result.parameter(Parameter::RuizF2) {
        f2.push(Series::new(
            format!(
                "maximum {} {} at x = {} {}",
                number(best.value),
                f2_unit,
                number(best.x),
                units.length
            ),
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
                color_bar: None,
                equal_aspect: false,
                log_axes: LogAxes::Neither,
                title: "surface σxx(x, 0)".into(),
                x_label: format!("position x ({})", units.length),
                y_label: format!("σxx ({})", units.stress),
                series: sxx,
            },
            Panel {
                legend: Legend::Auto,
                color_bar: None,
                equal_aspect: false,
                log_axes: LogAxes::Neither,
                title: "Ruiz F2 (δ the slip amplitude)".into(),
                x_label: format!("position x ({})", units.length),
                y_label: format!("F2 ({f2_unit})"),
                series: f2,
            },
        ],
    }
}
