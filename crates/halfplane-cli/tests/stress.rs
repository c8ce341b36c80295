//! End-to-end tests of `halfplane stress`: the columns, the order of the points, the grid, the
//! sign conventions against the Nowell-Hills closed form, and bad input (exit 2 naming the field).

mod common;
use common::*;
use halfplane::stress::closed_form::NowellHills;
use std::path::Path;

/// A Nowell-Hills case in `dir`: P to 1000 N/mm in 20 rows, then Q to 300 and sigma to 100
/// together in 40.
fn nowell_hills_case(dir: &Path) -> String {
    let mut rows = String::from("normal,shear,bulk\n");
    for i in 1..=20 {
        rows.push_str(&format!("{},0,0\n", 50 * i));
    }
    for i in 1..=40 {
        let t = i as f64 / 40.0;
        rows.push_str(&format!("1000,{},{}\n", 300.0 * t, 100.0 * t));
    }
    std::fs::write(dir.join("history.csv"), rows).unwrap();
    let case = dir.join("case.toml");
    std::fs::write(
        &case,
        format!("{REFERENCE_CONTACT}[history]\nfile = \"history.csv\"\n"),
    )
    .unwrap();
    case.to_str().unwrap().to_string()
}

fn parse_csv(text: &str) -> (String, Vec<Vec<f64>>) {
    let mut lines = text.lines();
    let header = lines.next().unwrap().to_string();
    let rows = lines
        .map(|l| l.split(',').map(|v| v.parse().unwrap()).collect())
        .collect();
    (header, rows)
}

#[test]
fn points_in_order_with_the_stated_columns_match_the_nowell_hills_field() {
    let dir = scratch("stress-nh");
    let case = nowell_hills_case(&dir);
    let a = (2.0 * 1000.0 * 4.0 * (1.0 - 0.09) / 200_000.0 * 50.0 / std::f64::consts::PI).sqrt();
    let points = [
        (0.3 * a, 0.2 * a),
        (-a, 0.0),
        (-0.5 * a, 0.5 * a),
        (1.4 * a, 0.1 * a),
    ];
    let mut text = String::from("x,z\n");
    for (x, z) in points {
        text.push_str(&format!("{x},{z}\n"));
    }
    let at = dir.join("points.csv");
    std::fs::write(&at, text).unwrap();
    let o = run(&[
        "stress",
        &case,
        "--at",
        at.to_str().unwrap(),
        "--csv",
        "--cells",
        "1600",
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    let (header, rows) = parse_csv(&stdout(&o));
    assert_eq!(header, "x,z,sxx,szz,syy,sxz");
    assert_eq!(rows.len(), points.len());
    let nh = NowellHills::hertz(a, 0.6, 1000.0, 300.0, 100.0);
    let p0 = nh.peak_pressure;
    for (row, (x, z)) in rows.iter().zip(points) {
        assert_eq!((row[0], row[1]), (x, z), "points are echoed in order");
        let e = nh.stress(x, z);
        // Below the surface the library test measures 3.6e-5 p0 at 1600 cells; at the trailing
        // edge 6.3e-4 p0.
        let tol = if z == 0.0 { 1.5e-3 } else { 1e-4 } * p0;
        for (got, want, name) in [
            (row[2], e[0], "sxx"),
            (row[3], e[1], "szz"),
            (row[5], e[2], "sxz"),
        ] {
            assert!(
                (got - want).abs() < tol,
                "{name} at ({x}, {z}): {got} vs Nowell-Hills {want} (sign conventions of stress)"
            );
        }
        assert!(
            (row[4] - 0.3 * (row[2] + row[3])).abs() < 1e-9 * p0,
            "plane strain syy"
        );
    }
}

#[test]
fn grid_runs_along_x_one_depth_after_another_and_json_names_the_increment() {
    let case = example("march-cycle.toml");
    let o = run(&[
        "stress",
        &case,
        "--grid",
        "-1,1,5,0,0.4,3",
        "--csv",
        "--step",
        "150",
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    let (_, rows) = parse_csv(&stdout(&o));
    assert_eq!(rows.len(), 15);
    for (k, r) in rows.iter().enumerate() {
        let (i, j) = (k % 5, k / 5);
        assert!(
            (r[0] - (-1.0 + 0.5 * i as f64)).abs() < 1e-12 && (r[1] - 0.2 * j as f64).abs() < 1e-12
        );
    }
    let o = run(&[
        "stress",
        &case,
        "--grid",
        "0,0,1,0.1,0.1,1",
        "--json",
        "--step",
        "150",
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    let v: serde_json::Value = serde_json::from_str(&stdout(&o)).unwrap();
    assert_eq!(v["step"], 150);
    assert_eq!(v["points"].as_array().unwrap().len(), 1);
    for key in ["x", "z", "sxx", "szz", "syy", "sxz"] {
        assert!(v["points"][0][key].is_number(), "{key}");
    }
    assert_eq!(v["units"]["stress"], "MPa");
    // The table names the increment and the units.
    let o = run(&[
        "stress",
        &case,
        "--grid",
        "0,0,1,0.1,0.1,1",
        "--step",
        "150",
    ]);
    assert!(stdout(&o).starts_with("stresses at step 150") && stdout(&o).contains("MPa"));
}

#[test]
fn bad_input_exits_2_naming_the_field() {
    let case = example("march-cycle.toml");
    let dir = scratch("stress-bad");
    let write = |name: &str, text: &str| {
        let p = dir.join(name);
        std::fs::write(&p, text).unwrap();
        p.to_str().unwrap().to_string()
    };
    let header = write("header.csv", "x,y\n0,1\n");
    let negative = write("negative.csv", "x,z\n0,0.1\n0,-0.5\n");
    let text = write("text.csv", "x,z\n0,deep\n");
    let cases: [(&[&str], &str); 7] = [
        (&["--at", &header], "expected \"x,z\""),
        (&["--at", &negative], "line 3: invalid point 1: z = -0.5"),
        (&["--at", &text], "z = \"deep\" is not a number"),
        (&["--grid", "0,1,2,0,1"], "six numbers"),
        (&["--grid", "0,1,2.5,0,1,2"], "NX = 2.5"),
        (&["--grid", "0,1,2,0,1,2", "--step", "301"], "--step 301"),
        (&[], "--at"),
    ];
    for (args, message) in cases {
        let mut all = vec!["stress", case.as_str()];
        all.extend_from_slice(args);
        let o = run(&all);
        assert_eq!(o.status.code(), Some(2), "{args:?}");
        assert!(stderr(&o).contains(message), "{args:?}: {}", stderr(&o));
    }
}
