//! The figures hold the expected series (from the library's own numbers) and are written as valid
//! SVG and PNG; bad requests are clear errors.

use halfplane::evolution::evolve;
use halfplane::history::{History, Ramp};
use halfplane::march::{march, MarchOptions};
use halfplane::{reference, Contact, Cycle, SteadyOptions};
use halfplane_plot::*;

/// The reference cycle of docs/theory.md ([`halfplane::reference`]).
fn contact() -> Contact {
    reference::hertz()
}

fn cycle() -> Cycle {
    reference::cycle()
}

fn units() -> Units {
    Units::default()
}

fn names(f: &Figure) -> Vec<String> {
    f.panels
        .iter()
        .flat_map(|p| p.series.iter().map(|s| s.name.clone()))
        .filter(|n| !n.is_empty())
        .collect()
}

/// A `<polyline>` of the SVG: stroke colour, stroke width and number of points.
#[derive(Debug, PartialEq)]
struct Polyline {
    stroke: String,
    width: String,
    points: usize,
}

fn attribute<'a>(element: &'a str, name: &str) -> &'a str {
    let key = format!(" {name}=\"");
    let start = element
        .find(&key)
        .unwrap_or_else(|| panic!("no {name} in {element}"))
        + key.len();
    let len = element[start..].find('"').unwrap();
    &element[start..start + len]
}

fn elements<'a>(svg: &'a str, tag: &str) -> Vec<&'a str> {
    svg.match_indices(&format!("<{tag} "))
        .map(|(i, _)| &svg[i..i + svg[i..].find("/>").unwrap()])
        .collect()
}

/// The contents of the SVG's `<text>` elements.
fn texts(svg: &str) -> Vec<&str> {
    svg.split("<text ")
        .skip(1)
        .map(|t| {
            let body = &t[t.find('>').unwrap() + 1..];
            body[..body.find("</text>").unwrap()].trim()
        })
        .collect()
}

fn polylines(svg: &str) -> Vec<Polyline> {
    elements(svg, "polyline")
        .into_iter()
        .map(|e| Polyline {
            stroke: attribute(e, "stroke").to_string(),
            width: attribute(e, "stroke-width").to_string(),
            points: attribute(e, "points").split_whitespace().count(),
        })
        .collect()
}

fn hex(color: usize) -> String {
    let (r, g, b) = palette(color);
    format!("#{r:02X}{g:02X}{b:02X}")
}

/// Renders the figure as SVG and checks that every legend name and axis title is in it, and that
/// every series is drawn with its data: each solid piece as a polyline of its colour with exactly
/// as many points as the piece, each dashed piece as dashes of its colour, each marker and each
/// segment of its colour. (The axes alone are 2-point polylines of width 1, so an empty figure
/// fails.)
fn check_svg(f: &Figure) -> String {
    let (svg, _) = render_svg(f).unwrap();
    check_drawn(f, &svg);
    svg
}

fn check_drawn(f: &Figure, svg: &str) {
    assert!(
        svg.starts_with("<svg") && svg.trim_end().ends_with("</svg>"),
        "not an SVG document"
    );
    for n in names(f) {
        let escaped = n
            .replace('&', "&amp;")
            .replace('<', "&lt;")
            .replace('>', "&gt;");
        assert!(svg.contains(&escaped), "legend entry {n:?} missing");
    }
    for p in &f.panels {
        assert!(
            svg.contains(&p.x_label) && svg.contains(&p.y_label),
            "axis titles missing"
        );
    }
    let mut lines = polylines(svg);
    let circles = elements(svg, "circle");
    for s in f.panels.iter().flat_map(|p| &p.series) {
        let color = hex(s.color);
        let pieces = s.pieces.iter().filter(|p| !p.is_empty());
        let count = |points: usize| {
            lines
                .iter()
                .filter(|l| l.stroke == color && l.width == "2" && l.points == points)
                .count()
        };
        match s.style {
            Style::Line => {
                for piece in pieces {
                    let i = lines
                        .iter()
                        .position(|l| {
                            l.stroke == color && l.width == "2" && l.points == piece.len()
                        })
                        .unwrap_or_else(|| {
                            panic!("{:?}: no polyline of {} points", s.name, piece.len())
                        });
                    lines.remove(i);
                }
            }
            Style::Dashed => {
                let n = pieces.count();
                assert!(count(2) >= 2 * n, "{:?}: too few dashes", s.name);
            }
            Style::Points => {
                let n: usize = s.pieces.iter().map(Vec::len).sum();
                let drawn = circles
                    .iter()
                    .filter(|c| attribute(c, "fill") == color)
                    .count();
                assert!(drawn >= n, "{:?}: {drawn} markers for {n} points", s.name);
            }
            Style::Segments => {
                let n: usize = s.pieces.iter().map(|p| p.len() / 2).sum();
                assert!(count(2) >= n, "{:?}: too few segments", s.name);
            }
            Style::Filled((r, g, b)) => {
                let fill = format!("#{r:02X}{g:02X}{b:02X}");
                let n: usize = s.pieces.iter().map(|p| p.len() / 2).sum();
                let drawn = elements(svg, "rect")
                    .iter()
                    .filter(|c| attribute(c, "fill") == fill)
                    .count();
                assert!(drawn >= n, "{:?}: {drawn} cells for {n}", s.name);
            }
            Style::Polygons((r, g, b)) => {
                let fill = format!("#{r:02X}{g:02X}{b:02X}");
                let n = s.pieces.iter().filter(|p| p.len() >= 3).count();
                let drawn = elements(svg, "polygon")
                    .iter()
                    .filter(|c| attribute(c, "fill") == fill)
                    .count();
                assert!(drawn >= n, "{fill}: {drawn} polygons for {n}");
            }
            Style::Contour => {
                let n: usize = s.pieces.iter().map(|p| p.len() / 2).sum();
                let drawn = lines
                    .iter()
                    .filter(|l| l.stroke == "#000000" && l.width == "1" && l.points == 2)
                    .count();
                assert!(drawn >= n, "{drawn} contour segments for {n}");
            }
            Style::Annotated => {
                let n: usize = s.pieces.iter().map(Vec::len).sum();
                let drawn = circles
                    .iter()
                    .filter(|c| attribute(c, "fill") == color)
                    .count();
                assert!(drawn >= n, "{:?}: {drawn} markers for {n} points", s.name);
            }
        }
    }
}

#[test]
fn a_figure_without_its_data_fails_the_drawn_data_check() {
    let f = load_space_figure(&contact(), &cycle(), &units()).unwrap();
    check_svg(&f);
    // The same panels, titles and legends with every series emptied: the axes and legend samples
    // are still drawn, but no series' data.
    let mut empty = f.clone();
    for s in empty.panels.iter_mut().flat_map(|p| &mut p.series) {
        s.pieces = vec![Vec::new()];
    }
    let (svg, _) = render_svg(&empty).unwrap();
    assert!(std::panic::catch_unwind(|| check_drawn(&f, &svg)).is_err());
}

#[test]
fn load_space_holds_the_trajectory_friction_lines_and_edge_paths() {
    let f = load_space_figure(&contact(), &cycle(), &units()).unwrap();
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
    check_svg(&f);
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
    let f = slip_map_figure(&contact(), &map, &units()).unwrap();
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
    check_svg(&f);
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
    let f = evolution_figure(&ev, Some(&marched), &units());
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
    let svg = check_svg(&f);
    assert!(svg.contains("stick boundary (time marching)"));
    // Without the overlay the marching series is absent.
    assert!(!names(&evolution_figure(&ev, None, &units()))
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
    let fields = march_fields_figure(&recorder.kept, &units());
    assert_eq!(fields.panels[0].series[0].pieces[0].len(), 100);
    check_svg(&fields);
    let zones = march_zones_figure(&result, &units());
    let bars = &zones.panels[0].series[1];
    assert_eq!(
        bars.pieces[0].len(),
        2 * result
            .steps
            .iter()
            .map(|s| s.stick_intervals.len())
            .sum::<usize>()
    );
    check_svg(&zones);
    let dir = tempfile::tempdir().unwrap();
    let png = dir.path().join("zones.png");
    write(&zones, &png).unwrap();
    let bytes = std::fs::read(&png).unwrap();
    assert_eq!(&bytes[..8], b"\x89PNG\r\n\x1a\n", "PNG signature");
    let width = u32::from_be_bytes(bytes[16..20].try_into().unwrap());
    let height = u32::from_be_bytes(bytes[20..24].try_into().unwrap());
    // The PNG is the SVG rendered: the same size.
    let (_, size) = render_svg(&zones).unwrap();
    assert_eq!((width, height), size);
    assert_eq!(width, 640);
    assert!(bytes.len() > 10_000, "a PNG with content");
}

#[test]
fn axis_labels_carry_the_units_given() {
    let units = Units {
        force_per_length: "kN/m".into(),
        length: "m".into(),
        stress: "kPa".into(),
    };
    let f = load_space_figure(&contact(), &cycle(), &units).unwrap();
    assert_eq!(f.panels[0].x_label, "normal load P (kN/m)");
    assert_eq!(f.panels[1].y_label, "equivalent shear S (kN/m)");
    let fields = march_fields_figure(&[], &units);
    assert_eq!(fields.panels[0].y_label, "traction q (kPa)");
    assert_eq!(fields.panels[1].y_label, "slip (m)");
    assert_eq!(fields.panels[1].x_label, "position x (m)");
    let svg = check_svg(&f);
    assert!(!svg.contains("N/mm"), "a default unit left in the labels");
}

#[test]
fn tick_labels_have_the_decimals_the_spacing_needs() {
    let f = load_space_figure(&contact(), &cycle(), &units()).unwrap();
    let (svg, _) = render_svg(&f).unwrap();
    let labels = texts(&svg);
    // Loads in hundreds: integer ticks, a true minus sign, and zero without a sign.
    for want in ["0", "200", "1000", "−600"] {
        assert!(labels.contains(&want), "{want} not among {labels:?}");
    }
    for bad in ["200.0", "-0", "−0", "-0.0"] {
        assert!(!labels.contains(&bad), "{bad} among the tick labels");
    }
    // The slip map's axes run from 0 to about 1: one decimal.
    let map = SlipMap {
        normal: 1000.0,
        frictions: vec![0.6],
        ratios: vec![1.0],
        tensions: vec![0.0],
        samples: 10,
    };
    let (svg, _) = render_svg(&slip_map_figure(&contact(), &map, &units()).unwrap()).unwrap();
    let labels = texts(&svg);
    assert!(labels.contains(&"0.5"), "no 0.5 tick among {labels:?}");
}

#[test]
fn bad_requests_are_clear_errors() {
    let f = load_space_figure(&contact(), &cycle(), &units()).unwrap();
    let dir = tempfile::tempdir().unwrap();
    let jpg = dir.path().join("figure.jpg");
    let err = write(&f, &jpg).unwrap_err();
    assert!(err.to_string().contains(".svg or .png"), "{err}");
    assert!(!jpg.exists(), "no file is left for a refused format");
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
    // A history without cycles has no last cycle to overlay.
    assert_eq!(MarchedCycle::last_cycle(&result, &history), None);
}

#[test]
fn match_figure_draws_both_sides_with_the_reports_edge_shears() {
    use halfplane::matching::{match_cycle, Mode};
    let report = match_cycle(
        &reference::flat_rounded(),
        &cycle(),
        &contact(),
        Mode::Exact,
    )
    .unwrap();
    let f = match_figure(&report, &units()).unwrap();
    assert_eq!(f.panels.len(), 2, "prototype and test side by side");
    for (panel, side) in f.panels.iter().zip([&report.prototype, &report.test]) {
        // The P-S paths of both edges run from S at the first point to S at the second, as the
        // report's edge description gives them (eq. (33)).
        for (name, edge) in [
            ("S left", halfplane::Edge::Left),
            ("S right", halfplane::Edge::Right),
        ] {
            let s = panel
                .series
                .iter()
                .find(|s| s.name.starts_with(name))
                .unwrap();
            let path = &s.pieces[0];
            let ends = [path[0], path[path.len() - 1]];
            let loads = side.cycle.as_given();
            let given = [(loads.0, side.edges.first), (loads.1, side.edges.second)];
            for ((p, sh), (load, e)) in ends.iter().zip(given) {
                assert_eq!(
                    *p,
                    load.normal(),
                    "{}: {name} starts and ends at the points' P",
                    panel.title
                );
                assert!(
                    (sh - e.equivalent_shear[edge]).abs() < 1e-9,
                    "{}: {name}",
                    panel.title
                );
            }
        }
    }
    check_svg(&f);
}

#[test]
fn a_design_map_fills_its_grid_between_the_points_and_greys_the_rows_without_a_value() {
    use halfplane_plot::{design_map_figure, DesignMap, MapColor};
    // v = x y on a 20 x 10 grid, with the last two columns missing (as gross sliding would be).
    let points: Vec<(f64, f64)> = (0..20)
        .flat_map(|i| (0..10).map(move |j| (i as f64, 0.1 * j as f64)))
        .collect();
    let values: Vec<Option<f64>> = points
        .iter()
        .map(|&(x, y)| (x < 18.0).then_some(x * y))
        .collect();
    let map = DesignMap {
        x_label: "shear load Q at point 2 (N/mm)".into(),
        y_label: "friction coefficient f".into(),
        color_label: "right slip zone at point 1 (mm)".into(),
        points,
        color: MapColor::Numeric(values),
    };
    let f = design_map_figure(&map).unwrap();
    let svg = check_svg(&f);
    let panel = &f.panels[0];
    // The filled bands cover the 18 columns with values, between the points: 17 x 0.9 (to
    // rounding, 1e-9 of it), with no staircase (they are not the rows' cells).
    let area = |p: &[(f64, f64)]| {
        0.5 * (0..p.len())
            .map(|k| {
                let (a, b) = (p[k], p[(k + 1) % p.len()]);
                a.0 * b.1 - b.0 * a.1
            })
            .sum::<f64>()
            .abs()
    };
    let filled: f64 = panel
        .series
        .iter()
        .filter(|s| matches!(s.style, Style::Polygons(_)))
        .flat_map(|s| &s.pieces)
        .map(|p| area(p))
        .sum();
    assert!((filled - 17.0 * 0.9).abs() < 1e-9, "filled {filled}");
    // The colour bar spans the data: 0 to 17 x 0.9.
    let bar = panel.color_bar.as_ref().unwrap();
    assert_eq!(bar.bounds[0], 0.0);
    assert!((bar.bounds[bar.bounds.len() - 1] - 17.0 * 0.9).abs() < 1e-12);
    // The bar is drawn: its label, every level's label as a text of its own, and one rectangle
    // per band in the band's colour.
    let labels = texts(&svg);
    assert!(
        labels.contains(&bar.label.as_str()),
        "colour bar label drawn"
    );
    for (_, label) in &bar.ticks {
        assert!(
            labels.contains(&label.as_str()),
            "level {label} not labelled"
        );
    }
    let rects = elements(&svg, "rect");
    for &(r, g, b) in &bar.colors {
        let fill = format!("#{r:02X}{g:02X}{b:02X}");
        assert!(
            rects.iter().any(|e| attribute(e, "fill") == fill),
            "band {fill} missing from the bar"
        );
    }
    let missing = panel.series.iter().find(|s| s.name == "no value").unwrap();
    assert_eq!(
        missing.pieces[0].len() / 2,
        20,
        "two columns of ten have no value"
    );
    assert!(svg.contains("shear load Q at point 2 (N/mm)"));
}

#[test]
fn annotations_of_nearby_markers_do_not_cover_each_other() {
    // Two marked values a few pixels apart on the surface of a map (as the largest tension and
    // compression of a stress can be): their labels go to different places, not one on the
    // other (they overlapped before the labels were placed apart).
    let mut panel = Panel::new(
        "",
        "x (mm)",
        "y (mm)",
        vec![
            Series::new("", Style::Line, 3, vec![(0.0, -1.0), (1.0, 0.0)]),
            Series::new("max 780.5 MPa", Style::Annotated, 3, vec![(0.2, 0.0)]),
            Series::new("min −843.5 MPa", Style::Annotated, 3, vec![(0.25, 0.0)]),
        ],
    );
    panel.legend = Legend::Below;
    let f = Figure {
        title: "t".into(),
        panels: vec![panel],
    };
    let svg = check_svg(&f);
    let at = |label: &str| {
        let start = svg.find(&format!(">\n{label}")).unwrap_or_else(|| {
            svg.find(&format!(">{label}"))
                .unwrap_or_else(|| panic!("{label} not drawn"))
        });
        let element = &svg[svg[..start].rfind("<text").unwrap()..start];
        let number = |name: &str| attribute(element, name).parse::<i32>().unwrap();
        (number("x"), number("y"))
    };
    let (a, b) = (at("max 780.5 MPa"), at("min −843.5 MPa"));
    // Labels are 13-px text: apart by a line's height, or side by side without overlap.
    assert!(
        (a.1 - b.1).abs() >= 16 || (a.0 - b.0).abs() >= 120,
        "labels at {a:?} and {b:?}"
    );
}
