//! End-to-end tests of `halfplane march`.

mod common;
use common::*;

#[test]
fn csv_rows_follow_the_history_and_end_on_the_steady_stick_zone() {
    let case = examples().join("march-cycle.toml");
    let o = run(&["march", case.to_str().unwrap(), "--csv"]);
    assert!(o.status.success(), "{}", stderr(&o));
    let out = stdout(&o);
    let mut lines = out.lines();
    assert!(lines
        .next()
        .unwrap()
        .starts_with("step,normal,shear,bulk,half_width,stick_left,stick_right"));
    let rows: Vec<Vec<&str>> = lines.map(|l| l.split(',').collect()).collect();
    assert_eq!(rows.len(), 300, "30 ramp + 3 cycles of 90 increments");
    let last = &rows[299];
    // 400 cells over a2 = 0.90059: a cell is 0.0045; the reference stick zone [-0.66607, 0.68123].
    let (l, r): (f64, f64) = (last[5].parse().unwrap(), last[6].parse().unwrap());
    assert!(
        (l + 0.66607).abs() < 0.0045 && (r - 0.68123).abs() < 0.0045,
        "[{l}, {r}]"
    );
    assert!(
        o.stderr.is_empty(),
        "no progress bar when stderr is not a terminal: {}",
        stderr(&o)
    );
}

#[test]
fn json_reports_cycles_and_shakedown() {
    let case = examples().join("march-harmonic.toml");
    let o = run(&["march", case.to_str().unwrap(), "--json", "--cells", "200"]);
    assert!(o.status.success(), "{}", stderr(&o));
    let v: serde_json::Value = serde_json::from_str(&stdout(&o)).unwrap();
    assert_eq!(v["cells"], 200);
    assert_eq!(v["cycles"].as_array().unwrap().len(), 3);
    assert_eq!(v["steps"].as_array().unwrap().len(), 380);
    // Out of phase, the first cycle differs from the steady cycle that follows.
    assert_eq!(v["shakedown_cycle"], 2);
    let e: Vec<f64> = v["cycles"]
        .as_array()
        .unwrap()
        .iter()
        .map(|c| c["energy"].as_f64().unwrap())
        .collect();
    assert!(e[0] > e[1] && (e[1] - e[2]).abs() < 1e-3 * e[1], "{e:?}");
}

#[test]
fn fields_directory_holds_every_increment_and_the_slip_amplitude() {
    let dir = scratch("fields");
    let case = examples().join("march-history.toml");
    let o = run(&[
        "march",
        case.to_str().unwrap(),
        "--fields",
        dir.to_str().unwrap(),
        "--cells",
        "100",
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    let first = std::fs::read_to_string(dir.join("step_00001.csv")).unwrap();
    assert!(first.starts_with("x,pressure,traction,slip,slip_increment\n"));
    assert_eq!(first.lines().count(), 101);
    assert!(dir.join("step_00050.csv").exists() && !dir.join("step_00051.csv").exists());
    // The file history has no cycles, so no slip-amplitude file.
    assert!(!dir.join("slip_amplitude.csv").exists());
    let dir = scratch("fields-cycle");
    let case = examples().join("march-cycle.toml");
    let o = run(&[
        "march",
        case.to_str().unwrap(),
        "--fields",
        dir.to_str().unwrap(),
        "--cells",
        "50",
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    let amp = std::fs::read_to_string(dir.join("slip_amplitude.csv")).unwrap();
    assert!(amp.starts_with("x,cycle_1,cycle_2,cycle_3\n"));
}

const BASE: &str = REFERENCE_CONTACT;

fn case_with(name: &str, history: &str, csv: Option<&str>) -> ScratchFile {
    let dir = scratch(name);
    if let Some(c) = csv {
        std::fs::write(dir.join("h.csv"), c).unwrap();
    }
    let path = ScratchFile::new(dir, "case.toml");
    std::fs::write(&*path, format!("{BASE}{history}")).unwrap();
    path
}

#[test]
fn bad_histories_and_solver_settings_are_clear_errors() {
    let file = "[history]\nfile = \"h.csv\"\n";
    let cases: Vec<(&str, String, Option<&str>, &[&str])> = vec![
        ("no-history", String::new(), None, &["[history]"]),
        (
            "slip-tolerance",
            format!("{file}[solver]\nslip_tolerance = 0.0\n"),
            Some("normal,shear,bulk\n1000,0,0\n"),
            &["solver.slip_tolerance", "0 < t < 1"],
        ),
        ("zero-cells", format!("{file}[solver]\ncells = 0\n"), Some("normal,shear,bulk\n1000,0,0\n"), &["solver.cells", "from 8 to"]),
        ("nan-row", file.into(), Some("normal,shear,bulk\n1000,0,0\nnan,0,0\n"), &["line 3", "normal", "finite"]),
        ("p-zero", file.into(), Some("normal,shear,bulk\n1000,0,0\n0,0,0\n"), &["line 3", "normal", "from 1e-30 to 1e30"]),
        ("empty", file.into(), Some(""), &["empty"]),
        ("header-only", file.into(), Some("normal,shear,bulk\n"), &["no rows"]),
        ("columns", file.into(), Some("normal,shear,bulk\n1000,0\n"), &["line 2", "3 columns"]),
        ("text", file.into(), Some("normal,shear,bulk\n1000,x,0\n"), &["line 2", "shear", "not a number"]),
        ("slides", file.into(), Some("normal,shear,bulk\n1000,0,0\n1000,300,0\n1000,650,0\n"), &["step 3", "slides"]),
        ("missing-file", "[history]\nfile = \"absent.csv\"\n".into(), None, &["history.file", "absent.csv"]),
        ("kind", "[history]\nkind = \"sawtooth\"\n".into(), None, &["history.kind", "\"cycle\""]),
        ("cycle-without-points", "[history]\nkind = \"cycle\"\ncycles = 2\nsteps_per_half = 10\n".into(), None, &["[cycle]"]),
        ("harmonic-p", "[history]\nkind = \"harmonic\"\ncycles = 1\nsteps_per_cycle = 10\nnormal = { mean = 100.0, amplitude = 200.0 }\n".into(), None, &["history.normal.amplitude", "P stays > 0"]),
    ];
    for (name, history, csv, needles) in cases {
        let path = case_with(name, &history, csv);
        let o = run(&["march", path.to_str().unwrap()]);
        let err = stderr(&o);
        assert!(!o.status.success(), "{name} should fail: {}", stdout(&o));
        assert!(!err.contains("panicked"), "{name}: {err}");
        for needle in needles {
            assert!(
                err.contains(needle),
                "{name}: error does not mention {needle:?}: {err}"
            );
        }
    }
    let path = case_with("cells-flag", file, Some("normal,shear,bulk\n1000,0,0\n"));
    let o = run(&["march", path.to_str().unwrap(), "--cells", "3"]);
    assert!(
        !o.status.success() && stderr(&o).contains("--cells = 3"),
        "{}",
        stderr(&o)
    );
    let o = run(&[
        "march",
        path.to_str().unwrap(),
        "--fields",
        "/proc/halfplane-cannot-write",
    ]);
    assert!(
        !o.status.success() && stderr(&o).contains("--fields"),
        "{}",
        stderr(&o)
    );
}
