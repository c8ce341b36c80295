//! The stress and fatigue figures hold the library's numbers: filled bands covering the grid,
//! contour lines where the field takes their level, a colour bar over the data's range, the
//! maximum where the analysis put it, the surface profiles as computed; bad requests are errors.

use halfplane::fatigue::{self, FatigueConstants, FatigueGrid, Parameter};
use halfplane::history::{History, Ramp};
use halfplane::march::MarchOptions;
use halfplane::{reference, LoadPoint};
use halfplane_plot::*;

/// The area of a polygon (shoelace formula), unsigned.
fn area(p: &[(f64, f64)]) -> f64 {
    0.5 * (0..p.len())
        .map(|k| {
            let (a, b) = (p[k], p[(k + 1) % p.len()]);
            a.0 * b.1 - b.0 * a.1
        })
        .sum::<f64>()
        .abs()
}

fn styled(f: &Figure, style: fn(&Style) -> bool) -> Vec<&Series> {
    f.panels[0]
        .series
        .iter()
        .filter(|s| style(&s.style))
        .collect()
}

#[test]
fn stress_map_bands_cover_the_grid_and_its_lines_lie_on_the_bar_levels() {
    // sxx = 100 x - 50 z (linear, so the interpolation within each cell is exact).
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
    let f = stress_map_figure(&map, "σxx", 7, [-0.8, 0.8], &Units::default()).unwrap();
    let panel = &f.panels[0];
    assert!(panel.equal_aspect, "x and depth to the same scale");
    // The colour bar spans the data, -150 (x = -1, z = 1) to 100 (x = 1, z = 0), with the
    // levels every 25 (at most ten) labelled in plain notation.
    let bar = panel.color_bar.as_ref().unwrap();
    assert_eq!(bar.label, "σxx (MPa)");
    let bounds: Vec<f64> = (-6..=4).map(|k| 25.0 * k as f64).collect();
    assert_eq!(bar.bounds, bounds);
    let labels: Vec<&str> = bar.ticks.iter().map(|t| t.1.as_str()).collect();
    assert_eq!(
        labels,
        ["−125", "−100", "−75", "−50", "−25", "0", "25", "50", "75"]
    );
    // Diverging and centred on zero: blue below zero, red above.
    let (first, last) = (bar.colors[0], bar.colors[9]);
    assert!(first.2 > first.0 && last.0 > last.2);
    // The bands tile the 2 x 1 grid (to rounding, 1e-12 of it), each polygon inside its band.
    let bands = styled(&f, |s| matches!(s, Style::Polygons(_)));
    let total: f64 = bands.iter().flat_map(|s| &s.pieces).map(|p| area(p)).sum();
    assert!((total - 2.0).abs() < 1e-12, "covered {total}");
    for s in &bands {
        let Style::Polygons(rgb) = s.style else {
            unreachable!()
        };
        let b = bar.colors.iter().position(|&c| c == rgb).unwrap();
        for &(px, py) in s.pieces.iter().flatten() {
            let v = 100.0 * px + 50.0 * py;
            assert!(v >= bar.bounds[b] - 1e-9 && v <= bar.bounds[b + 1] + 1e-9);
        }
    }
    // Every contour point lies on a level (the plot's y is -z).
    let lines = styled(&f, |s| *s == Style::Contour);
    assert_eq!(lines.len(), 1);
    for &(px, py) in lines[0].pieces.iter().flatten() {
        let v = 100.0 * px + 50.0 * py;
        assert!(
            bar.ticks.iter().any(|(l, _)| (v - l).abs() < 1e-9),
            "({px}, {py}) has {v}, on no level"
        );
    }
    // The maximum, 100 at x = 1 on the surface, and the minimum, -150 at x = -1 at the bottom,
    // are marked with their values.
    let marks = styled(&f, |s| *s == Style::Annotated);
    assert_eq!(marks.len(), 2);
    assert_eq!(marks[0].pieces[0], vec![(1.0, 0.0)]);
    assert!(marks[0]
        .name
        .starts_with("max 100 MPa at (x, z) = (1, 0) mm"));
    assert_eq!(marks[1].pieces[0], vec![(-1.0, -1.0)]);
    assert!(marks[1]
        .name
        .starts_with("min −150 MPa at (x, z) = (−1, 1) mm"));
    let contact = panel
        .series
        .iter()
        .find(|s| s.name.starts_with("contact"))
        .unwrap();
    assert_eq!(contact.pieces[0], vec![(-0.8, 0.0), (0.8, 0.0)]);
    let (svg, (width, height)) = render_svg(&f).unwrap();
    assert!(svg.contains("σxx (MPa)") && svg.contains("max 100 MPa"));
    // Equal aspect: a 2 x 1.03 map (3 % above the surface) on a 900-pixel-wide panel is much
    // wider than tall.
    assert!(width > 2 * height - 200, "{width} x {height}");
    // One value short: an error, not a panic.
    let short = GridMap {
        values: &values[1..],
        ..map
    };
    assert!(matches!(
        stress_map_figure(&short, "σxx", 7, [-0.8, 0.8], &Units::default()),
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
            .find(|s| s.style == Style::Annotated)
            .unwrap();
        assert_eq!(marked.pieces[0], vec![(best.x, -best.z)]);
        assert!(marked.name.contains(&format!("max {}", number(best.value))));
        let map = result.map(parameter).unwrap();
        let (lo, hi) = map
            .iter()
            .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), &v| {
                (a.min(v), b.max(v))
            });
        assert_eq!(hi, best.value, "the map's maximum is the reported one");
        let bar = f.panels[0].color_bar.as_ref().unwrap();
        assert_eq!(
            bar.bounds[0], lo,
            "the colour bar starts at the map's minimum"
        );
        assert_eq!(
            bar.bounds[bar.bounds.len() - 1],
            hi,
            "and ends at its maximum"
        );
        assert!(bar.ticks.iter().all(|(l, _)| *l > lo && *l < hi));
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
