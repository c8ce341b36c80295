//! The crack figure ([`halfplane::crack`]): the stress intensity ranges against the crack length
//! with El Haddad's threshold on log-log axes, beside the stress map with the crack drawn on it.

use crate::contour::GridMap;
use crate::fields::stress_map_figure;
use crate::format::number;
use crate::{Figure, Legend, LogAxes, Panel, PlotError, Series, Style, Units};
use halfplane::crack::CrackResult;

/// The palette colour of the crack on the map (black, as the contact: it reads on every band).
const CRACK_COLOR: usize = 3;

/// `delta_k_eff`, `delta_k1`, `delta_k2` and the threshold against the length (both axes
/// logarithmic: values not above zero, such as a mode I range of zero while the tip stays
/// closed, are left out), with a vertical line at the arrest length when the crack arrests.
pub fn crack_growth_panel(result: &CrackResult, units: &Units) -> Panel {
    let k = format!("{} √{}", units.stress, units.length);
    let curve = |f: fn(&halfplane::crack::CrackRow) -> f64| -> Vec<(f64, f64)> {
        result.rows.iter().map(|r| (r.length, f(r))).collect()
    };
    let mut series = vec![
        Series::new("ΔK effective", Style::Line, 0, curve(|r| r.delta_k_eff)),
        Series::new("ΔK_I", Style::Line, 1, curve(|r| r.delta_k1)),
        Series::new("ΔK_II", Style::Line, 2, curve(|r| r.delta_k2)),
        Series::new(
            "threshold ΔK_th(l) (El Haddad)",
            Style::Dashed,
            3,
            curve(|r| r.threshold),
        ),
        Series::new("", Style::Points, 0, curve(|r| r.delta_k_eff)),
    ];
    if let Some(l) = result.arrest_length {
        let positive = result
            .rows
            .iter()
            .flat_map(|r| [r.delta_k_eff, r.delta_k1, r.delta_k2, r.threshold])
            .filter(|v| *v > 0.0);
        let (lo, hi) = positive.fold((f64::INFINITY, 0.0_f64), |(lo, hi), v| {
            (lo.min(v), hi.max(v))
        });
        if hi > 0.0 {
            series.push(Series::new(
                format!("arrests at l = {} {}", number(l), units.length),
                Style::Segments,
                4,
                vec![(l, lo), (l, hi)],
            ));
        }
    }
    let mut panel = Panel::new(
        format!("ΔK against crack length: {}", result.verdict.name()),
        format!("crack length l ({})", units.length),
        format!("stress intensity range ΔK ({k})"),
        series,
    );
    panel.log_axes = LogAxes::Both;
    panel.legend = Legend::Below;
    panel
}

/// The crack figure: [`crack_growth_panel`] beside the map of `sxx` (`map`, at increment `step`,
/// the contact's ends `contact` = `[b1, b2]` then; the contact's line is cut to the map's x) with
/// the longest crack drawn on it from its mouth.
pub fn crack_figure(
    result: &CrackResult,
    map: &GridMap,
    step: usize,
    contact: [f64; 2],
    units: &Units,
) -> Result<Figure, PlotError> {
    let mut stress = stress_map_figure(map, "σxx", step, contact, units)?;
    let mut panel = stress.panels.remove(0);
    // The map may show only part of the contact: its line is cut to the map.
    let (lo, hi) = (
        map.x.first().copied().unwrap_or(0.0),
        map.x.last().copied().unwrap_or(0.0),
    );
    for s in panel
        .series
        .iter_mut()
        .filter(|s| s.name.starts_with("contact"))
    {
        for p in s.pieces.iter_mut().flatten() {
            p.0 = p.0.clamp(lo, hi);
        }
    }
    let longest = result.rows.last().map_or(0.0, |r| r.length);
    let (s, c) = result.angle.to_radians().sin_cos();
    panel.series.push(Series::new(
        format!(
            "crack, l = {} {}, {}° from the normal",
            number(longest),
            units.length,
            number(result.angle)
        ),
        Style::Line,
        CRACK_COLOR,
        vec![
            (result.mouth, 0.0),
            (result.mouth + longest * s, -longest * c),
        ],
    ));
    panel.title = format!("σxx at increment {step} (tension positive) and the crack");
    Ok(Figure {
        title: format!(
            "Will the crack grow? Crack at x = {} {}: {}",
            number(result.mouth),
            units.length,
            result.verdict.name()
        ),
        panels: vec![crack_growth_panel(result, units), panel],
    })
}
