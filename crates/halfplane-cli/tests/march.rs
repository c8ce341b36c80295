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
        ("no-kind", "[history]\ncycles = 2\n".into(), None, &["missing field history.kind", "\"sliding\""]),
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

/// `examples/march-steady.toml` with `[history] cycles` replaced (and `max_cycles` dropped for a
/// number).
fn steady_case_with(dir: &std::path::Path, cycles: &str, extra: &str) -> std::path::PathBuf {
    let text = std::fs::read_to_string(examples().join("march-steady.toml")).unwrap();
    let mut lines: Vec<String> = text
        .lines()
        .filter(|l| !l.starts_with("max_cycles") || cycles.contains("steady"))
        .map(|l| match l.starts_with("cycles = ") {
            true => format!("cycles = {cycles}\n{extra}"),
            false => l.to_string(),
        })
        .collect();
    lines.push(String::new());
    let path = dir.join(format!("case-{}.toml", cycles.replace('"', "")));
    std::fs::write(&path, lines.join("\n")).unwrap();
    path
}

fn march_json(path: &std::path::Path) -> serde_json::Value {
    let o = run(&["march", path.to_str().unwrap(), "--json"]);
    assert!(o.status.success(), "{}", stderr(&o));
    serde_json::from_slice(&o.stdout).unwrap()
}

#[test]
fn cycles_steady_marches_until_the_slip_ranges_repeat_and_says_how_many() {
    let dir = scratch("march-steady");
    let steady = march_json(&examples().join("march-steady.toml"));
    let cycles_run = steady["cycles_run"].as_u64().unwrap();
    assert_eq!(
        steady["cycles"].as_array().unwrap().len() as u64,
        cycles_run
    );
    assert_eq!(steady["steady_converged"], true);
    assert!(steady["steady_change"].as_f64().unwrap() <= 1e-10);
    // The same march with that number of cycles given: the same increments, and converged; one
    // cycle fewer has not converged (so the count is the first that meets the tolerance).
    let fixed = march_json(&steady_case_with(&dir, &cycles_run.to_string(), ""));
    assert_eq!(fixed["steps"], steady["steps"]);
    assert_eq!(fixed["steady_converged"], true);
    assert_eq!(fixed["cycles_run"], cycles_run);
    let fewer = march_json(&steady_case_with(&dir, &(cycles_run - 1).to_string(), ""));
    assert_eq!(fewer["steady_converged"], false);
    // The table says so.
    let o = run(&["march", example("march-steady.toml").as_str()]);
    let table = stdout(&o);
    assert!(
        table.contains(&format!(
            "{cycles_run} cycles of 40 (marched until the cycle repeated)"
        )) && table.contains("slip ranges: repeat"),
        "{table}"
    );
}

#[test]
fn steady_settings_are_checked_and_a_march_that_does_not_repeat_is_an_error() {
    let dir = scratch("march-steady-errors");
    let cases: [(&str, &str, &[&str]); 5] = [
        (
            "\"steady\"",
            "max_cycles = 1",
            &["history.max_cycles = 1", "from 2 to"],
        ),
        (
            "3",
            "max_cycles = 10",
            &[
                "history.max_cycles",
                "only with history.cycles = \"steady\"",
            ],
        ),
        (
            "\"stedy\"",
            "",
            &["history.cycles = \"stedy\"", "\"steady\""],
        ),
        (
            "\"steady\"",
            "steady_tolerance = 0.0",
            &["history.steady_tolerance = 0", "0 < t < 1"],
        ),
        // Three cycles are not enough for this case: the error names the last change.
        (
            "\"steady\"",
            "max_cycles = 3",
            &[
                "history.max_cycles = 3",
                "A f P",
                "history.steady_tolerance = 1e-10",
            ],
        ),
    ];
    for (cycles, extra, needles) in cases {
        let text = std::fs::read_to_string(examples().join("march-steady.toml")).unwrap();
        let text: String = text
            .lines()
            .filter(|l| !l.starts_with("max_cycles") && !l.starts_with("steady_tolerance"))
            .map(|l| match l.starts_with("cycles = ") {
                true => format!("cycles = {cycles}\n{extra}\n"),
                false => format!("{l}\n"),
            })
            .collect();
        let path = dir.join("case.toml");
        std::fs::write(&path, text).unwrap();
        let o = run(&["march", path.to_str().unwrap()]);
        assert_eq!(o.status.code(), Some(2), "{cycles} {extra}: {}", stdout(&o));
        let message = stderr(&o);
        for n in needles {
            assert!(message.contains(n), "{cycles} {extra}: {message}");
        }
    }
    // Commands that need a history's length up front say which commands run it.
    let o = run(&[
        "stress",
        example("march-steady.toml").as_str(),
        "--grid",
        "-1,1,3,0,1,2",
    ]);
    assert_eq!(o.status.code(), Some(2));
    assert!(
        stderr(&o).contains("history.cycles = \"steady\" is run by march"),
        "{}",
        stderr(&o)
    );
}

/// Cattaneo-Mindlin as a case file: P = 1000 pressed in one increment, then Q = 0.5 f P in one,
/// on the reference contact (Hertz R = 50, E = 200 GPa, nu = 0.3, f = 0.6), 400 cells.
fn cattaneo_case(solver: &str) -> ScratchFile {
    case_with(
        "sub-cell",
        &format!("[history]\ndata = \"\"\"\nnormal,shear,bulk\n1000,0,0\n1000,300,0\n\"\"\"\n[solver]\ncells = 400\n{solver}"),
        None,
    )
}

/// The last increment's largest stick interval and its half-width error in cells against
/// Cattaneo-Mindlin's c = a sqrt(1 - Q/(f P)) (Johnson, Contact Mechanics, section 7.1), with the
/// Hertz half-width a = sqrt(8 P R (1 - nu^2) / (pi E)) of two equal bodies (plane strain).
fn cattaneo_stick_error(path: &std::path::Path) -> f64 {
    let v = march_json(path);
    let (p, q, f, r, e, nu) = (1000.0, 300.0, 0.6, 50.0, 200000.0, 0.3);
    let a = (8.0 * p * r * (1.0 - nu * nu) / (std::f64::consts::PI * e)).sqrt();
    let last = v["steps"].as_array().unwrap().last().unwrap();
    let reported = last["half_width"].as_f64().unwrap();
    assert!((reported - a).abs() < 1e-9 * a, "a = {reported}, Hertz {a}");
    let c = a * (1.0 - q / (f * p)).sqrt();
    let stick = last["largest_stick"].as_array().unwrap();
    let (left, right) = (stick[0].as_f64().unwrap(), stick[1].as_f64().unwrap());
    (left + c).abs().max((right - c).abs()) / v["cell_width"].as_f64().unwrap()
}

#[test]
fn solver_sub_cell_boundaries_puts_the_stick_zone_on_cattaneo_mindlin() {
    // Issue 20's target for located boundaries: within 0.05 cells (measured 0.0046). Cell-edge
    // boundaries are 0.58 cells off here, so the same case with the field false or absent
    // misses it: the field reaches the solver.
    let on = cattaneo_stick_error(&cattaneo_case("sub_cell_boundaries = true\n"));
    assert!(on < 0.05, "sub-cell stick edge off by {on} cells");
    let off = cattaneo_stick_error(&cattaneo_case("sub_cell_boundaries = false\n"));
    assert!(off > 0.1, "cell-edge stick edge off by only {off} cells");
    assert_eq!(
        off,
        cattaneo_stick_error(&cattaneo_case("")),
        "default is off"
    );
}

#[test]
fn a_sub_cell_boundaries_that_is_not_a_switch_exits_2_naming_the_field() {
    for (value, shown) in [("3", "= 3"), ("\"yes\"", "= \"yes\""), ("1.0", "= 1.0")] {
        let path = cattaneo_case(&format!("sub_cell_boundaries = {value}\n"));
        for command in ["march", "fatigue"] {
            let o = run(&[command, path.to_str().unwrap()]);
            let err = stderr(&o);
            assert_eq!(o.status.code(), Some(2), "{command} {value}: {err}");
            assert!(
                err.contains(&format!("solver.sub_cell_boundaries {shown}"))
                    && err.contains("true or false"),
                "{command} {value}: {err}"
            );
        }
    }
}

#[test]
fn relative_displacement_is_cattaneo_mindlins_at_the_stated_datum() {
    // Cattaneo-Mindlin (the case above): Q rises monotonically at constant P, so the bodies'
    // relative displacement is path-independent and the one-increment march gives the closed form
    // (`closed_form::cattaneo_mindlin_displacement`, from the traction by the log kernel). The
    // datum is ten Hertz half-widths. Tolerance 5e-5 of the value: the grid's error at 400 cells
    // (the library's loop test measures 2.3e-5 at that datum); the pressing increment moves
    // nothing (exactly zero). The CSV column carries the JSON's numbers.
    let case = cattaneo_case("");
    let v = march_json(&case);
    let contact = halfplane::reference::hertz();
    let compliance = contact.compliance().value();
    let a = halfplane::closed_form::hertz_half_width(compliance, 50.0, 1000.0);
    let datum = v["loop_datum"].as_f64().unwrap();
    assert!(
        (datum - 10.0 * a).abs() < 1e-9 * datum,
        "loop_datum {datum}, 10 a = {}",
        10.0 * a
    );
    let steps = v["steps"].as_array().unwrap();
    let delta: Vec<f64> = steps
        .iter()
        .map(|s| s["relative_displacement"].as_f64().unwrap())
        .collect();
    assert_eq!(
        delta[0], 0.0,
        "pressing alone moves the bodies apart tangentially"
    );
    let exact = halfplane::closed_form::cattaneo_mindlin_displacement(
        compliance, a, 0.6, 1000.0, 300.0, datum,
    );
    assert!(
        (delta[1] - exact).abs() < 5e-5 * exact.abs(),
        "relative displacement {} against Cattaneo-Mindlin's {exact}",
        delta[1]
    );
    let o = run(&["march", case.to_str().unwrap(), "--csv"]);
    assert!(o.status.success(), "{}", stderr(&o));
    let text = String::from_utf8(o.stdout).unwrap();
    let mut lines = text.lines();
    let header: Vec<&str> = lines.next().unwrap().split(',').collect();
    let column = header
        .iter()
        .position(|h| *h == "relative_displacement")
        .expect("a relative_displacement column");
    for (line, d) in lines.zip(&delta) {
        let cell: f64 = line.split(',').nth(column).unwrap().parse().unwrap();
        assert_eq!(cell, *d);
    }
}

#[test]
fn a_moment_arm_beyond_the_resolvable_exits_2_naming_the_row() {
    // M/P = 1e27 mm moves a Hertz contact of 0.76 mm where its ends and the grid's cells are the
    // same double: the march printed a grid "over [-1e27, 1e27] mm, cell width 0" and no energy.
    let case = case_with(
        "far-moment",
        "[history]\nkind = \"harmonic\"\nnormal = { mean = 1000.0, amplitude = 0.0 }\nshear = { mean = 0.0, amplitude = 300.0 }\nmoment = { mean = 1e30, amplitude = 0.0 }\ncycles = 1\nsteps_per_cycle = 20\n",
        None,
    );
    let o = run(&["march", case.to_str().unwrap()]);
    assert_eq!(o.status.code(), Some(2), "{}", stderr(&o));
    assert!(o.stdout.is_empty(), "no result printed");
    let e = stderr(&o);
    assert!(
        e.contains("history row 1.moment") && e.contains("1e5 contact half-widths"),
        "{e}"
    );
}
