//! The figures hold the expected series (from the library's own numbers) and are written as valid
//! SVG and PNG; bad requests are clear errors.

use halfplane::evolution::evolve;
use halfplane::history::{History, Ramp};
use halfplane::march::{march, MarchOptions};
use halfplane::{Contact, Cycle, Friction, LoadPoint, Material, Profile, SteadyOptions};
use halfplane_plot::*;
use std::path::PathBuf;

fn contact() -> Contact {
    Contact::new(
        Profile::hertz(50.0).unwrap(),
        Material::new(200_000.0, 0.3).unwrap(),
        Friction::new(0.6).unwrap(),
    )
}

fn cycle() -> Cycle {
    Cycle::new(
        LoadPoint::new("p1", 1000.0, -250.0, -20.0).unwrap(),
        LoadPoint::new("p2", 1400.0, 250.0, 20.0).unwrap(),
    )
}

fn out(name: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("halfplane-plot-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    dir.join(name)
}

fn names(f: &Figure) -> Vec<String> {
    f.panels
        .iter()
        .flat_map(|p| p.series.iter().map(|s| s.name.clone()))
        .filter(|n| !n.is_empty())
        .collect()
}

/// Writes the figure as SVG and checks that every legend name and one polyline per line series is
/// in the file.
fn check_svg(f: &Figure, name: &str) -> String {
    let path = out(name);
    write(f, &path).unwrap();
    let svg = std::fs::read_to_string(&path).unwrap();
    assert!(
        svg.starts_with("<svg") && svg.trim_end().ends_with("</svg>"),
        "not an SVG document"
    );
    for n in names(f) {
        let escaped = n
            .replace('&', "&amp;")
            .replace('<', "&lt;")
            .replace('>', "&gt;");
        assert!(
            svg.contains(&escaped),
            "legend entry {n:?} missing from {name}"
        );
    }
    for p in &f.panels {
        assert!(
            svg.contains(&p.x_label) && svg.contains(&p.y_label),
            "axis titles missing"
        );
    }
    let lines = f
        .panels
        .iter()
        .flat_map(|p| &p.series)
        .filter(|s| s.style == Style::Line)
        .map(|s| s.pieces.len())
        .sum::<usize>();
    assert!(
        svg.matches("<polyline").count() >= lines,
        "{name}: fewer polylines than line pieces"
    );
    svg
}

#[test]
fn load_space_holds_the_trajectory_friction_lines_and_edge_paths() {
    let f = load_space_figure(&contact(), &cycle()).unwrap();
    let n = names(&f);
    for want in [
        "trajectory",
        "point 1",
        "point 2",
        "friction lines ±fP",
        "left edge S = Q + πaσ/4",
        "right edge S = Q − πaσ/4",
    ] {
        assert!(n.iter().any(|x| x == want), "{want} missing: {n:?}");
    }
    // Points 1 and 2 are drawn where the load is; the edges' S start at Q -/+ pi a1 sigma1/4.
    let pq = &f.panels[0];
    let p1 = pq.series.iter().find(|s| s.name == "point 1").unwrap();
    assert_eq!(p1.pieces[0], vec![(1000.0, -250.0)]);
    let left = f.panels[1]
        .series
        .iter()
        .find(|s| s.name.starts_with("left"))
        .unwrap();
    let a1 = contact().half_width(1000.0).unwrap();
    let s1 = -250.0 + std::f64::consts::PI * a1 * (-20.0) / 4.0;
    assert!(
        (left.pieces[0][0].1 - s1).abs() < 1e-9,
        "{} vs {s1}",
        left.pieces[0][0].1
    );
    check_svg(&f, "load.svg");
}

#[test]
fn slip_map_curves_are_the_steady_analysis() {
    let map = SlipMap {
        normal: 1000.0,
        frictions: vec![0.3, 0.6],
        ratios: vec![1.0, 1.5],
        tensions: vec![0.0, 0.02],
        samples: 20,
    };
    let f = slip_map_figure(&contact(), &map).unwrap();
    assert_eq!(f.panels.len(), 2);
    assert_eq!(f.panels[0].title, "f = 0.3");
    assert_eq!(f.panels[0].series.len(), 4);
    // Spot check against steady::analyse: P2/P1 = 1, no tension, x = 0.5 at f = 0.6 is
    // Mindlin's steady slip zone, (a - a(P_K))/a with P_K = P0 (1 - x/2).
    let s = &f.panels[1].series[0];
    let (x, y) = s.pieces[0]
        .iter()
        .copied()
        .find(|p| (p.0 - 0.5).abs() < 1e-12)
        .unwrap();
    let c = contact();
    let a = c.half_width(1000.0).unwrap();
    let mindlin = (a - c.half_width(1000.0 * (1.0 - x / 2.0)).unwrap()) / a;
    assert!((y - mindlin).abs() < 1e-12, "{y} vs {mindlin}");
    // The paper's observations: more tension lengthens the slip zone, a larger P2/P1 shortens it.
    let at = |series: &Series, x: f64| {
        series
            .pieces
            .iter()
            .flatten()
            .find(|p| (p.0 - x).abs() < 1e-12)
            .map(|p| p.1)
            .unwrap()
    };
    let panel = &f.panels[1].series;
    assert!(at(&panel[1], 0.9) > at(&panel[0], 0.9));
    assert!(at(&panel[2], 0.9) < at(&panel[0], 0.9));
    check_svg(&f, "map.svg");
}

#[test]
fn evolution_overlays_exact_asymptotic_and_marched_stick_zones() {
    let c = contact();
    let ev = evolve(&c, &cycle(), 9, &SteadyOptions::default()).unwrap();
    let (p1, p2) = cycle().as_given();
    let history = History::in_phase(p1, p2, 2, 20, Ramp::NormalFirst, 10).unwrap();
    let result = march(
        &c,
        &history,
        &MarchOptions::default().with_cells(200).unwrap(),
        |_, _| {},
    )
    .unwrap();
    let marched = MarchedCycle::last_cycle(&result, &history).unwrap();
    assert_eq!(marched.points.len(), 40);
    let f = evolution_figure(&ev, Some(&marched));
    let exact = f.panels[1]
        .series
        .iter()
        .find(|s| s.name == "stick boundary (exact)")
        .unwrap();
    // The exact right boundary at t = 1 (point 2) is the permanent zone's n.
    let right_end = exact.pieces[0]
        .iter()
        .find(|p| (p.0 - 1.0).abs() < 1e-12)
        .unwrap()
        .1;
    assert!((right_end - 0.68123).abs() < 1e-5, "{right_end}");
    // The marched boundary at the end of half 1 is within a cell (1.8/200 mm) of it.
    let marched_right = f.panels[1].series[0].pieces[0]
        .iter()
        .find(|p| (p.0 - 1.0).abs() < 1e-12)
        .unwrap()
        .1;
    assert!(
        (marched_right - right_end).abs() < 2.0 * 0.9006 / 200.0,
        "{marched_right}"
    );
    let svg = check_svg(&f, "evolution.svg");
    assert!(svg.contains("stick boundary (time marching)"));
    // Without the overlay the marching series is absent.
    assert!(!names(&evolution_figure(&ev, None))
        .iter()
        .any(|n| n.contains("marching")));
}

#[test]
fn march_figures_hold_fields_and_zones_and_png_is_valid() {
    let c = contact();
    let (p1, p2) = cycle().as_given();
    let history = History::in_phase(p1, p2, 1, 10, Ramp::Proportional, 5).unwrap();
    let mut recorder = FieldRecorder {
        steps: vec![10, 25],
        kept: Vec::new(),
    };
    let result = march(
        &c,
        &history,
        &MarchOptions::default().with_cells(100).unwrap(),
        |r, f| recorder.observe(r.step, f, 0.6),
    )
    .unwrap();
    assert_eq!(
        recorder.kept.iter().map(|k| k.step).collect::<Vec<_>>(),
        vec![10, 25]
    );
    let fields = march_fields_figure(&recorder.kept);
    assert_eq!(fields.panels[0].series[0].pieces[0].len(), 100);
    check_svg(&fields, "fields.svg");
    let zones = march_zones_figure(&result);
    let bars = &zones.panels[0].series[1];
    assert_eq!(
        bars.pieces[0].len(),
        2 * result
            .steps
            .iter()
            .map(|s| s.stick_intervals.len())
            .sum::<usize>()
    );
    check_svg(&zones, "zones.svg");
    let png = out("zones.png");
    write(&zones, &png).unwrap();
    let bytes = std::fs::read(&png).unwrap();
    assert_eq!(&bytes[..8], b"\x89PNG\r\n\x1a\n", "PNG signature");
    let width = u32::from_be_bytes(bytes[16..20].try_into().unwrap());
    let height = u32::from_be_bytes(bytes[20..24].try_into().unwrap());
    assert_eq!((width, height), (640, 520));
    assert!(bytes.len() > 10_000, "a PNG with content");
}

#[test]
fn bad_requests_are_clear_errors() {
    let f = load_space_figure(&contact(), &cycle()).unwrap();
    let err = write(&f, &out("figure.jpg")).unwrap_err();
    assert!(err.to_string().contains(".svg or .png"), "{err}");
    let err = write(&f, std::path::Path::new("/nonexistent-dir/figure.svg")).unwrap_err();
    assert!(
        err.to_string()
            .contains("cannot write /nonexistent-dir/figure.svg"),
        "{err}"
    );
    let history = History::from_rows(&[[1000.0, 0.0, 0.0]]).unwrap();
    let result = march(
        &contact(),
        &history,
        &MarchOptions::default().with_cells(20).unwrap(),
        |_, _| {},
    )
    .unwrap();
    let err = MarchedCycle::last_cycle(&result, &history).unwrap_err();
    assert!(err.to_string().contains("cyclic history"), "{err}");
}
