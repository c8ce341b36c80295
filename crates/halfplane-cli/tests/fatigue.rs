//! End-to-end tests of `halfplane fatigue`: the rows and columns on the bundled example, and bad
//! `[fatigue]` input (exit 2 naming the field).

mod common;
use common::*;

#[test]
fn example_reports_every_parameter_with_the_trailing_edge_critical() {
    let o = run(&["fatigue", &example("fatigue.toml"), "--csv"]);
    assert!(o.status.success(), "{}", stderr(&o));
    let out = stdout(&o);
    let mut lines = out.lines();
    assert_eq!(
        lines.next().unwrap(),
        "parameter,value,x,z,plane,step,point_method,line_method,cycles,tilt"
    );
    let rows: Vec<Vec<&str>> = lines.map(|l| l.split(',').collect()).collect();
    let names: Vec<&str> = rows.iter().map(|r| r[0]).collect();
    assert_eq!(
        names,
        [
            "swt",
            "fatemi_socie",
            "findley",
            "crossland",
            "ruiz_f1",
            "ruiz_f2",
            "mwcm",
            "fatemi_socie_max_plane",
            "mcdiarmid"
        ]
    );
    // A progress line appears on a loaded machine (every 5 s of running); warnings would not
    // start so.
    let err = stderr(&o);
    let warnings: Vec<&str> = err
        .lines()
        .filter(|l| !l.starts_with("fatigue: running"))
        .collect();
    assert!(
        warnings.is_empty(),
        "every constant is given: nothing to warn about: {warnings:?}"
    );
    // Positive Q and sigma together: the trailing edge x = -a (a = 0.761 mm) is critical.
    let x: f64 = rows[0][2].parse().unwrap();
    assert!((x + 0.761).abs() < 0.03, "SWT maximum at x = {x}");
    let cycles: f64 = rows[0][8].parse().unwrap();
    assert!(cycles > 1.0, "{cycles}");
    let o = run(&["fatigue", &example("fatigue.toml"), "--json"]);
    let v: serde_json::Value = serde_json::from_str(&stdout(&o)).unwrap();
    assert!(v["critical_distance"].as_f64().unwrap() > 0.0);
    let parameters = v["parameters"].as_array().unwrap();
    assert_eq!(parameters.len(), 9);
    // The MWCM row: its plane and its value, an effective shear stress in MPa.
    let mwcm = &parameters[6];
    assert_eq!(mwcm["parameter"], "mwcm");
    assert!(mwcm["plane"].as_f64().is_some() && mwcm["value"].as_f64().unwrap() > 0.0);
    assert!((mwcm["x"].as_f64().unwrap() + 0.761).abs() < 0.03, "{mwcm}");
}

#[test]
fn bad_fatigue_input_exits_2_naming_the_field() {
    let dir = scratch("fatigue-bad");
    let base = std::fs::read_to_string(examples().join("fatigue.toml")).unwrap();
    let cases = [
        ("findley_k = 0.25", "findley_k = -1.0", "fatigue.findley_k"),
        ("nx = 60", "nx = 1", "fatigue.nx"),
        ("nz = 30", "nz = -3", "invalid fatigue.nz = -3"),
        (
            "torsional_fatigue_limit = 220.0",
            "torsional_fatigue_limit = 100.0",
            "fatigue.torsional_fatigue_limit = 100",
        ),
        (
            "axial_fatigue_limit = 350.0",
            "",
            "missing field fatigue.axial_fatigue_limit",
        ),
        ("nz = 30", "nz = 2.5", "invalid fatigue.nz = 2.5"),
        (
            "yield_stress = 900.0",
            "yield_strength = 900.0",
            "yield_strength",
        ),
        ("kind = \"cycle\"\n", "file = \"h.csv\"\n", "cyclic history"),
        (
            "nx = 60",
            "nx = 60\nplanes = \"3D\"",
            "invalid fatigue.planes = \"3D\": must be \"in-plane\" (the default: planes containing y) or \"3d\"",
        ),
        (
            "ultimate_strength = 1200.0",
            "ultimate_strength = 200.0",
            "fatigue.mcdiarmid_shear_limit = 220",
        ),
        (
            "ultimate_strength = 1200.0",
            "",
            "missing field fatigue.ultimate_strength",
        ),
    ];
    std::fs::write(dir.join("h.csv"), "normal,shear,bulk\n1000,0,0\n").unwrap();
    for (from, to, message) in cases {
        let mut text = base.replace(from, to);
        if from.starts_with("kind") {
            text = text.replace(
                "cycles = 2\nsteps_per_half = 30\nramp = \"normal-first\"\nramp_steps = 10\n",
                "",
            );
        }
        let path = dir.join("case.toml");
        std::fs::write(&path, text).unwrap();
        let o = run(&["fatigue", path.to_str().unwrap()]);
        assert_eq!(o.status.code(), Some(2), "{to}");
        assert!(stderr(&o).contains(message), "{to}: {}", stderr(&o));
    }
}

#[test]
fn a_parameter_left_out_for_a_missing_constant_is_named_on_stderr() {
    // Failed before the fix: the fatemi_socie rows vanished with exit 0 and nothing on stderr.
    let dir = scratch("fatigue-missing");
    let base = std::fs::read_to_string(examples().join("fatigue.toml")).unwrap();
    let text = base
        .replace("fatemi_socie_k = 0.5", "")
        .replace("mcdiarmid_shear_limit = 220.0", "")
        .replace("ultimate_strength = 1200.0", "")
        .replace("nx = 60", "nx = 8")
        .replace("nz = 30", "nz = 4");
    let path = dir.join("case.toml");
    std::fs::write(&path, text).unwrap();
    let o = run(&["fatigue", path.to_str().unwrap(), "--csv"]);
    assert!(o.status.success(), "{}", stderr(&o));
    let err = stderr(&o);
    let lines: Vec<&str> = err.lines().collect();
    assert_eq!(
        lines,
        [
            "warning: fatemi_socie not reported: [fatigue] does not give fatigue.fatemi_socie_k",
            "warning: fatemi_socie_max_plane not reported: [fatigue] does not give fatigue.fatemi_socie_k",
            "warning: mcdiarmid not reported: [fatigue] does not give fatigue.mcdiarmid_shear_limit and fatigue.ultimate_strength",
        ]
    );
    let out = stdout(&o);
    assert!(
        !out.contains("fatemi_socie") && !out.contains("mcdiarmid"),
        "{out}"
    );
    // Asked for explicitly, a parameter without its constants is an error naming them.
    let png = dir.join("map.png");
    let o = run(&[
        "plot",
        "fatigue-map",
        path.to_str().unwrap(),
        "--parameter",
        "mcdiarmid",
        "-o",
        png.to_str().unwrap(),
    ]);
    assert_eq!(o.status.code(), Some(2));
    assert!(
        stderr(&o).contains("fatigue.mcdiarmid_shear_limit"),
        "{}",
        stderr(&o)
    );
}

#[test]
fn planes_3d_reports_tilted_planes_never_below_the_in_plane_ones() {
    let dir = scratch("fatigue-3d");
    let base = std::fs::read_to_string(examples().join("fatigue.toml")).unwrap();
    let small = base
        .replace("nx = 60", "nx = 12")
        .replace("nz = 30", "nz = 6");
    let values = |text: &str| -> Vec<(String, f64, f64)> {
        let path = dir.join("case.toml");
        std::fs::write(&path, text).unwrap();
        let o = run(&["fatigue", path.to_str().unwrap(), "--csv"]);
        assert!(o.status.success(), "{}", stderr(&o));
        stdout(&o)
            .lines()
            .skip(1)
            .map(|l| {
                let r: Vec<&str> = l.split(',').collect();
                (
                    r[0].to_string(),
                    r[1].parse().unwrap(),
                    r[9].parse().unwrap_or(f64::NAN),
                )
            })
            .collect()
    };
    let in_plane = values(&small);
    let full = values(&small.replace("nx = 12", "nx = 12\nplanes = \"3d\""));
    // The sampled parameters take the larger of both searches; the ones on the plane of the
    // largest shear range need not grow (a tilted plane can carry less normal stress).
    for ((name, a, tilt_a), (_, b, tilt_b)) in in_plane.iter().zip(&full) {
        if [
            "swt",
            "fatemi_socie_max_plane",
            "findley",
            "crossland",
            "ruiz_f1",
            "ruiz_f2",
        ]
        .contains(&name.as_str())
        {
            assert!(*b >= a - 1e-12 * a.abs(), "{name}: 3d {b} vs in-plane {a}");
        }
        if !tilt_a.is_nan() {
            assert_eq!(*tilt_a, 0.0, "{name}");
            assert!((0.0..=90.0).contains(tilt_b), "{name}: {tilt_b}");
        }
    }
}
