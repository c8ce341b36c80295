//! The stress and fatigue figures hold the library's numbers: contour lines where the field takes
//! their level, the maximum where the analysis put it, the surface profiles as computed; bad
//! requests are errors.

use halfplane::fatigue::{self, FatigueConstants, FatigueGrid, Parameter};
use halfplane::history::{History, Ramp};
use halfplane::march::MarchOptions;
use halfplane::{reference, LoadPoint};
use halfplane_plot::*;

/// The level a contour series is drawn at, read back from its name "... = {level} unit".
fn level(s: &Series) -> f64 {
    let text = s.name.split(" = ").nth(1).unwrap().replace('−', "-");
    text.split_whitespace().next().unwrap().parse().unwrap()
}

fn contour_series(f: &Figure) -> Vec<&Series> {
    f.panels[0]
        .series
        .iter()
        .filter(|s| s.style == Style::Segments)
        .collect()
}

#[test]
fn stress_map_contours_lie_where_the_field_takes_their_level() {
    // sxx = 100 x - 50 z (linear, so interpolation along cell edges is exact).
    let x: Vec<f64> = (0..21).map(|i| -1.0 + 0.1 * i as f64).collect();
    let z: Vec<f64> = (0..11).map(|j| 0.1 * j as f64).collect();
    let values: Vec<f64> = z
        .iter()
        .flat_map(|z| x.iter().map(move |x| 100.0 * x - 50.0 * z))
        .collect();
    let map = GridMap {
        x: &x,
        z: &z,
        values: &values,
    };
    let f = stress_map_figure(&map, "σxx", 7, 0.8, &Units::default()).unwrap();
    let lines = contour_series(&f);
    assert_eq!(lines.len(), 4, "levels -100, -50, 0, 50");
    for s in &lines {
        let l = level(s);
        assert!((-150.0..100.0).contains(&l));
        for &(px, py) in s.pieces.iter().flatten() {
            // The plot's y is -z.
            let v = 100.0 * px + 50.0 * py;
            assert!(
                (v - l).abs() < 1e-9,
                "{}: point ({px}, {py}) has {v}",
                s.name
            );
        }
    }
    let contact = f.panels[0]
        .series
        .iter()
        .find(|s| s.name.starts_with("contact"))
        .unwrap();
    assert_eq!(contact.pieces[0], vec![(-0.8, 0.0), (0.8, 0.0)]);
    render_svg(&f).unwrap();
    // One value short: an error, not a panic.
    let short = GridMap {
        values: &values[1..],
        ..map
    };
    assert!(matches!(
        stress_map_figure(&short, "σxx", 7, 0.8, &Units::default()),
        Err(PlotError::Request(_))
    ));
}

#[test]
fn fatigue_figures_show_the_analysis_maximum_and_profiles() {
    let history = History::in_phase(
        LoadPoint::new("point1", 1000.0, -300.0, -60.0).unwrap(),
        LoadPoint::new("point2", 1000.0, 300.0, 60.0).unwrap(),
        2,
        10,
        Ramp::NormalFirst,
        5,
    )
    .unwrap();
    let constants = FatigueConstants::default()
        .with_findley_k(0.25)
        .and_then(|c| c.with_threshold(160.0))
        .and_then(|c| c.with_endurance_range(700.0))
        .unwrap();
    let result = fatigue::analyse(
        &reference::hertz(),
        &history,
        &MarchOptions::default().with_cells(100).unwrap(),
        &constants,
        &FatigueGrid::new(25, 9, 1.5, 0.5).unwrap(),
    )
    .unwrap();
    let units = Units::default();
    for parameter in [Parameter::Swt, Parameter::Findley] {
        let f = fatigue_map_figure(&result, parameter, &units).unwrap();
        let best = result.parameter(parameter).unwrap();
        let marked = f.panels[0]
            .series
            .iter()
            .find(|s| s.style == Style::Points)
            .unwrap();
        assert_eq!(marked.pieces[0], vec![(best.x, -best.z)]);
        assert!(marked.name.contains(&format!("{:.4e}", best.value)));
        let map = result.map(parameter).unwrap();
        let (lo, hi) = map
            .iter()
            .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), &v| {
                (a.min(v), b.max(v))
            });
        assert_eq!(hi, best.value, "the map's maximum is the reported one");
        let lines = contour_series(&f);
        assert!(!lines.is_empty());
        for s in lines {
            assert!(level(s) > lo && level(s) < hi, "{} outside the map", s.name);
        }
        render_svg(&f).unwrap();
    }
    // Not evaluated: Crossland without its constant, and Ruiz (a surface value, no map).
    for parameter in [Parameter::Crossland, Parameter::RuizF2] {
        assert!(matches!(
            fatigue_map_figure(&result, parameter, &units),
            Err(PlotError::Request(_))
        ));
    }
    let f = surface_profiles_figure(&result, &units);
    let xy = |v: &[f64]| -> Vec<(f64, f64)> {
        result
            .surface_x
            .iter()
            .copied()
            .zip(v.iter().copied())
            .collect()
    };
    let sxx = &f.panels[0].series;
    // 20 increments in the cycle: the quarters are the 5th, 10th, 15th and 20th.
    for (s, k) in sxx.iter().zip([4, 9, 14, 19]) {
        assert!(s
            .name
            .starts_with(&format!("increment {} ", result.steps[k])));
        assert_eq!(s.pieces[0], xy(&result.surface_sxx[k]));
    }
    assert_eq!(sxx[4].pieces[0], xy(&result.surface_sxx_max));
    assert_eq!(f.panels[1].series[0].pieces[0], xy(&result.ruiz_f2_profile));
    let f2 = result.parameter(Parameter::RuizF2).unwrap();
    assert_eq!(f.panels[1].series[1].pieces[0], vec![(f2.x, f2.value)]);
    // The largest sxx over the cycle is the largest of the increments' rows.
    for (i, m) in result.surface_sxx_max.iter().enumerate() {
        let rows = result
            .surface_sxx
            .iter()
            .map(|r| r[i])
            .fold(f64::MIN, f64::max);
        assert_eq!(*m, rows);
    }
    render_svg(&f).unwrap();
}
