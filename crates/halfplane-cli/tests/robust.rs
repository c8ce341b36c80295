//! Every input ends in exit 0 or 2 with a message (issue 7, item 4): huge counts, closed pipes,
//! full disks, spreadsheet CSVs (byte-order mark, CRLF) and long tables.

mod common;
use common::*;
use std::process::{Command, Output, Stdio};

const BASE: &str = REFERENCE_CASE;

fn write_case(name: &str, text: &str) -> ScratchFile {
    let path = ScratchFile::new(scratch(name), "case.toml");
    std::fs::write(&*path, text).unwrap();
    path
}

/// The run failed with exit 2, no panic or abort, and a message holding every needle.
fn assert_clear_error(what: &str, o: &Output, needles: &[&str]) {
    let err = stderr(o);
    assert_eq!(
        o.status.code(),
        Some(2),
        "{what}: exit {:?}: {err}",
        o.status
    );
    assert!(!err.contains("panicked"), "{what}: panicked: {err}");
    for needle in needles {
        assert!(err.contains(needle), "{what}: no {needle:?} in: {err}");
    }
}

#[test]
fn huge_negative_and_fractional_counts_are_clear_errors_in_every_command() {
    let max = "10000000";
    let cases: &[(&str, &str, &[&str])] = &[
        (
            "steps-per-half",
            "kind = \"cycle\"\ncycles = 1\nsteps_per_half = 9223372036854775807\n",
            &["history.steps_per_half", "9223372036854775807", max],
        ),
        (
            "ramp-steps",
            "kind = \"cycle\"\ncycles = 1\nsteps_per_half = 10\nramp_steps = 18446744073709551615\n",
            &["history.ramp_steps", max],
        ),
        (
            "cycles",
            "kind = \"cycle\"\ncycles = 4611686018427387904\nsteps_per_half = 2\n",
            &["history.cycles", max],
        ),
        (
            "too-large-for-usize",
            "kind = \"cycle\"\ncycles = 1\nsteps_per_half = 99999999999999999999\n",
            &["history.steps_per_half", "99999999999999999999", max],
        ),
        (
            "negative",
            "kind = \"cycle\"\ncycles = -1\nsteps_per_half = 10\n",
            &["history.cycles", "-1", "whole number from 1 to"],
        ),
        (
            "fraction",
            "kind = \"cycle\"\ncycles = 1.5\nsteps_per_half = 10\n",
            &["history.cycles", "1.5", "whole number"],
        ),
        (
            "not-a-number",
            "kind = \"cycle\"\ncycles = \"three\"\nsteps_per_half = 10\n",
            &["history.cycles", "three", "whole number"],
        ),
        (
            "product",
            "kind = \"cycle\"\ncycles = 10000\nsteps_per_half = 10000\n",
            &["history.cycles", max],
        ),
        // 2^62 cycles of 4 steps: the product wraps to 0 in 64 bits, and used to run 20 steps.
        (
            "harmonic-wrap",
            "kind = \"harmonic\"\ncycles = 4611686018427387904\nsteps_per_cycle = 4\nnormal = { mean = 1000.0 }\n",
            &["history.cycles", max],
        ),
    ];
    for (name, history, needles) in cases {
        let path = write_case(name, &format!("{BASE}[history]\n{history}"));
        for command in ["steady", "evolve", "march"] {
            let o = run(&[command, path.to_str().unwrap()]);
            assert_clear_error(&format!("{name} ({command})"), &o, needles);
        }
    }
    // A whole number written as a float is that number.
    let path = write_case(
        "float-whole",
        &format!("{BASE}[history]\nkind = \"cycle\"\ncycles = 1.0\nsteps_per_half = 4e0\nramp_steps = 2\n[solver]\ncells = 1.6e1\n"),
    );
    let o = run(&["march", path.to_str().unwrap(), "--csv"]);
    assert!(o.status.success(), "{}", stderr(&o));
    assert_eq!(stdout(&o).lines().count(), 1 + 4 + 8);
}

#[test]
fn out_of_range_cells_are_clear_errors() {
    let history = "[history]\nkind = \"cycle\"\ncycles = 1\nsteps_per_half = 2\n";
    for (name, cells, needles) in [
        ("float", "1e10", &["solver.cells", "whole number"][..]),
        ("huge", "10000000000", &["solver.cells", "10000000000"]),
        ("negative", "-5", &["solver.cells", "-5"]),
        ("fraction", "100.5", &["solver.cells", "100.5"]),
        ("i64-max", "9223372036854775807", &["solver.cells"]),
    ] {
        let path = write_case(
            &format!("cells-{name}"),
            &format!("{BASE}{history}[solver]\ncells = {cells}\n"),
        );
        let o = run(&["march", path.to_str().unwrap()]);
        assert_clear_error(&format!("cells = {cells}"), &o, needles);
    }
    let path = write_case("cells-flag", &format!("{BASE}{history}"));
    let o = run(&["march", path.to_str().unwrap(), "--cells", "10000000000"]);
    assert_clear_error("--cells", &o, &["cells", "10000000000"]);
}

#[cfg(feature = "plot")] // draws a figure
#[test]
fn huge_evolve_points_are_a_clear_error_with_the_maximum() {
    let hertz = example("hertz.toml");
    for points in ["100000000000", "18446744073709551615"] {
        let o = run(&["evolve", &hertz, "--points", points]);
        assert_clear_error(
            &format!("--points {points}"),
            &o,
            &["points", points, "100000"],
        );
        let o = run(&[
            "plot",
            "evolution",
            &hertz,
            "-o",
            "x.svg",
            "--points",
            points,
        ]);
        assert_clear_error(
            &format!("plot --points {points}"),
            &o,
            &["points", "100000"],
        );
    }
}

/// Runs with stdout a pipe whose reader has gone away before anything is written.
fn run_into_closed_pipe(args: &[&str]) -> Output {
    let mut child = Command::new(env!("CARGO_BIN_EXE_halfplane"))
        .args(args)
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .expect("run halfplane");
    drop(child.stdout.take());
    child.wait_with_output().expect("wait")
}

/// Every output route of every command.
fn output_routes() -> Vec<Vec<String>> {
    let (hertz, cycle) = (example("hertz.toml"), example("march-cycle.toml"));
    let args: [&[&str]; 9] = [
        &["steady", &hertz],
        &["steady", &hertz, "--json"],
        &["steady", &hertz, "--format", "csv"],
        &["evolve", &hertz],
        &["evolve", &hertz, "--csv"],
        &["evolve", &hertz, "--json"],
        &["march", &cycle, "--cells", "50"],
        &["march", &cycle, "--cells", "50", "--csv"],
        &["march", &cycle, "--cells", "50", "--json"],
    ];
    args.iter()
        .map(|a| a.iter().map(|s| s.to_string()).collect())
        .collect()
}

#[test]
fn a_closed_pipe_ends_quietly_with_exit_0() {
    for args in output_routes() {
        let args: Vec<&str> = args.iter().map(String::as_str).collect();
        let o = run_into_closed_pipe(&args);
        assert_eq!(o.status.code(), Some(0), "{args:?}: {}", stderr(&o));
        assert!(o.stderr.is_empty(), "{args:?}: {}", stderr(&o));
    }
}

#[cfg(feature = "plot")] // draws a figure
#[test]
fn a_full_disk_is_exit_2_with_a_message() {
    let full = || std::fs::File::create("/dev/full").expect("/dev/full");
    for args in output_routes() {
        let o = Command::new(env!("CARGO_BIN_EXE_halfplane"))
            .args(&args)
            .stdout(full())
            .output()
            .unwrap();
        assert_clear_error(&format!("{args:?}"), &o, &["stdout", "No space left"]);
    }
    let o = Command::new(env!("CARGO_BIN_EXE_halfplane"))
        .arg("--help")
        .stdout(full())
        .output()
        .unwrap();
    assert_clear_error("--help", &o, &["stdout", "No space left"]);
    let o = run_into_closed_pipe(&["--help"]);
    assert!(o.status.success() && o.stderr.is_empty(), "{}", stderr(&o));
    // A usage error is exit 2 (clap's convention, and this project's).
    assert_eq!(run(&["steady"]).status.code(), Some(2));
    // A full stderr loses the message but not the exit code.
    let o = Command::new(env!("CARGO_BIN_EXE_halfplane"))
        .args(["steady", "/nonexistent/case.toml"])
        .stderr(full())
        .output()
        .unwrap();
    assert_eq!(o.status.code(), Some(2));
    // `plot` reports the file it wrote on stderr; a full stderr does not make that a failure.
    let dir = scratch("stderr-full");
    let o = Command::new(env!("CARGO_BIN_EXE_halfplane"))
        .args(["plot", "load-space", &example("hertz.toml"), "-o"])
        .arg(dir.join("f.svg"))
        .stderr(full())
        .output()
        .unwrap();
    assert_eq!(o.status.code(), Some(0), "plot with a full stderr");
}

#[cfg(feature = "plot")] // only the figure tests use it
#[cfg(unix)]
fn link_to_dev_full(path: &std::path::Path) {
    std::os::unix::fs::symlink("/dev/full", path).unwrap();
}

#[cfg(unix)]
#[cfg(feature = "plot")] // draws a figure
#[test]
fn fields_and_plots_on_a_full_disk_are_exit_2_naming_the_file() {
    let cycle = example("march-cycle.toml");
    for file in ["step_00001.csv", "step_00300.csv", "slip_amplitude.csv"] {
        let dir = scratch(&format!("full-{file}"));
        link_to_dev_full(&dir.join(file));
        let o = run(&[
            "march",
            &cycle,
            "--cells",
            "20",
            "--fields",
            dir.to_str().unwrap(),
        ]);
        assert_clear_error(file, &o, &[file, "No space left"]);
    }
    let dir = scratch("full-plot");
    for (figure, file) in [("load-space", "f.svg"), ("load-space", "f.png")] {
        let path = dir.join(file);
        link_to_dev_full(&path);
        let o = run(&[
            "plot",
            figure,
            &example("hertz.toml"),
            "-o",
            path.to_str().unwrap(),
        ]);
        assert_clear_error(file, &o, &[file, "No space left"]);
    }
}

#[cfg(feature = "plot")] // draws a figure
#[test]
fn march_fields_takes_at_most_20_steps() {
    let steps: Vec<String> = (1..=21).map(|k| k.to_string()).collect();
    let out = scratch("many-steps").join("f.svg");
    let o = run(&[
        "plot",
        "march-fields",
        &example("march-cycle.toml"),
        "-o",
        out.to_str().unwrap(),
        "--steps",
        &steps.join(","),
    ]);
    assert_clear_error("--steps", &o, &["--steps", "21 values", "20"]);
}

fn tabulated_case(name: &str, table: &[u8], case_prefix: &[u8], eol: &str) -> ScratchFile {
    let dir = scratch(name);
    std::fs::write(dir.join("p.csv"), table).unwrap();
    let text = BASE
        .replace(
            "kind = \"hertz\"\nradius = 50.0",
            "kind = \"tabulated\"\nfile = \"p.csv\"\nkinks = [0.3]",
        )
        .replace('\n', eol);
    let path = ScratchFile::new(dir, "case.toml");
    std::fs::write(&*path, [case_prefix, text.as_bytes()].concat()).unwrap();
    path
}

#[test]
fn spreadsheet_csv_with_a_byte_order_mark_and_crlf_is_read() {
    let table = std::fs::read_to_string(examples().join("tabulated-profile.csv")).unwrap();
    let reference = run(&["steady", &example("tabulated.toml"), "--json"]);
    assert!(reference.status.success(), "{}", stderr(&reference));
    let bom = "\u{feff}";
    for (name, csv, prefix, eol) in [
        ("bom", format!("{bom}{table}"), "", "\n"),
        ("crlf", table.replace('\n', "\r\n"), "", "\n"),
        (
            "bom-crlf",
            format!("{bom}{}", table.replace('\n', "\r\n")),
            "",
            "\n",
        ),
        ("toml-bom-crlf", table.clone(), bom, "\r\n"),
    ] {
        let path = tabulated_case(name, csv.as_bytes(), prefix.as_bytes(), eol);
        let o = run(&["steady", path.to_str().unwrap(), "--json"]);
        assert!(o.status.success(), "{name}: {}", stderr(&o));
        assert_eq!(stdout(&o), stdout(&reference), "{name}");
    }
    // A history saved the same way.
    let history = std::fs::read_to_string(examples().join("march-history.csv")).unwrap();
    let reference = run(&[
        "march",
        &example("march-history.toml"),
        "--csv",
        "--cells",
        "20",
    ]);
    assert!(reference.status.success(), "{}", stderr(&reference));
    let dir = scratch("history-bom");
    std::fs::write(
        dir.join("h.csv"),
        format!("{bom}{}", history.replace('\n', "\r\n")),
    )
    .unwrap();
    let case = std::fs::read_to_string(examples().join("march-history.toml"))
        .unwrap()
        .replace("march-history.csv", "h.csv");
    std::fs::write(dir.join("case.toml"), format!("{bom}{case}")).unwrap();
    let o = run(&[
        "march",
        dir.join("case.toml").to_str().unwrap(),
        "--csv",
        "--cells",
        "20",
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    assert_eq!(stdout(&o), stdout(&reference));
}

/// The flat-rounded punch b = 0.3, R = 50 sampled at `rows` evenly spaced x from 0 to 2.
fn flat_rounded_table(rows: usize) -> String {
    let mut t = String::from("x,g\n");
    for i in 0..rows {
        let x = 2.0 * i as f64 / (rows - 1) as f64;
        let g = if x <= 0.3 {
            0.0
        } else {
            (x - 0.3).powi(2) / 100.0
        };
        t.push_str(&format!("{x},{g}\n"));
    }
    t
}

#[test]
fn a_long_profile_table_gives_the_flat_rounded_answer() {
    // 1e5 rows took 106 s before (quadratic setup). Its speed now is a benchmark figure
    // (BENCHMARKS.md); here the long table must still give the closed-form profile's answer.
    // The kink must sit on a row: 0.3 = 2 i/(rows - 1).
    let rows = 100_001;
    let path = tabulated_case("long-table", flat_rounded_table(rows).as_bytes(), b"", "\n");
    let o = run(&["steady", path.to_str().unwrap(), "--json"]);
    assert!(o.status.success(), "{}", stderr(&o));
    let v: serde_json::Value = serde_json::from_str(&stdout(&o)).unwrap();
    let reference = run(&["steady", &example("flat-rounded.toml"), "--json"]);
    let r: serde_json::Value = serde_json::from_str(&stdout(&reference)).unwrap();
    for field in ["left", "right"] {
        let (a, b) = (
            v["stick_zone"][field].as_f64().unwrap(),
            r["stick_zone"][field].as_f64().unwrap(),
        );
        assert!((a - b).abs() < 1e-9, "{field}: {a} vs {b}");
    }
}

#[test]
fn too_many_profile_rows_are_a_clear_error() {
    // One row past the stated maximum of 1,000,000, rejected while reading.
    let mut t = String::from("x,g\n");
    for i in 0..1_000_001u32 {
        t.push_str(&format!("{i},0\n"));
    }
    let path = tabulated_case("too-many-rows", t.as_bytes(), b"", "\n");
    let o = run(&["steady", path.to_str().unwrap()]);
    assert_clear_error("rows", &o, &["profile.file", "1000000"]);
}

/// A file that is not a table (a binary file, or /dev/zero, with no line ends) is rejected at
/// its first overlong line: the reader held the whole line, growing without bound on an endless
/// file, and echoed all of it in the message.
#[test]
fn an_overlong_line_is_a_clear_error_not_unbounded_memory() {
    let line = "0".repeat(2 << 20);
    let path = tabulated_case("long-line", format!("x,g\n{line}").as_bytes(), b"", "\n");
    let o = run(&["steady", path.to_str().unwrap()]);
    assert_clear_error("line", &o, &["profile.file", "line 2", "longer than"]);
    assert!(
        stderr(&o).len() < 2000,
        "the message is short: {}",
        stderr(&o).len()
    );
}

/// The same for a sweep's output read by `plot design-map`.
#[test]
fn an_overlong_line_in_a_sweep_output_is_a_clear_error() {
    let dir = scratch("long-sweep-line");
    let table = dir.join("sweep.csv");
    std::fs::write(&table, format!("a,b,regime\n{}", "0".repeat(2 << 20))).unwrap();
    let png = dir.join("map.png");
    let o = run(&[
        "plot",
        "design-map",
        table.to_str().unwrap(),
        "--x",
        "a",
        "--y",
        "b",
        "-o",
        png.to_str().unwrap(),
    ]);
    assert_clear_error("sweep line", &o, &["sweep.csv", "line 2", "longer than"]);
}

/// A case file or sweep spec that is not text (a binary file, /dev/zero) is rejected at its
/// first NUL byte, which TOML never allows: the whole file was read first, without bound on an
/// endless one.
#[test]
fn a_binary_case_file_or_spec_is_a_clear_error() {
    let dir = scratch("binary-case");
    let binary = dir.join("case.toml");
    std::fs::write(&binary, b"[material]\n\0\x01\x02").unwrap();
    let binary = binary.to_str().unwrap();
    let out = dir.join("out.csv");
    let mut runs = vec![
        vec!["steady", binary],
        vec!["sweep", binary, "-o", out.to_str().unwrap()],
    ];
    if cfg!(target_os = "linux") {
        runs.push(vec!["steady", "/dev/zero"]);
        runs.push(vec!["sweep", "/dev/zero", "-o", out.to_str().unwrap()]);
    }
    for args in runs {
        let o = run(&args);
        assert_clear_error(&args.join(" "), &o, &["not a text file", args[1]]);
    }
}

#[test]
fn the_march_summary_lists_every_increment_of_a_long_history() {
    // The summary used to search the list of rows once per row (100,000 increments: 68 s in
    // debug, 1.1 s in release); its speed now is a benchmark figure (BENCHMARKS.md). Here every
    // increment of a long history must be listed.
    let dir = scratch("long-history");
    let mut h = String::from("normal,shear,bulk\n");
    for i in 0..20_000 {
        h.push_str(&format!(
            "1000,{},0\n",
            100.0 * ((i % 40) as f64 / 20.0 - 1.0)
        ));
    }
    std::fs::write(dir.join("h.csv"), h).unwrap();
    let case = format!("{BASE}[history]\nfile = \"h.csv\"\n[solver]\ncells = 8\n");
    std::fs::write(dir.join("case.toml"), case).unwrap();
    let o = run(&["march", dir.join("case.toml").to_str().unwrap()]);
    assert!(o.status.success(), "{}", stderr(&o));
    assert!(stdout(&o).lines().count() > 20_000);
}

/// An edge radius 1e12 times the flat: the contact is Hertz-like and 1e5 mm wide, its stick zone
/// would leave it (as Hertz's does at such radii), and the stick-zone equations find no root.
/// That is exit 2 with the number of iterations taken and the hint to march, not a bare failure.
#[test]
fn stick_zone_equations_without_a_root_point_to_the_march() {
    let text = std::fs::read_to_string(example("flat-rounded.toml"))
        .unwrap()
        .replace("radius = 50.0", "radius = 1e12");
    let case = write_case("no-root", &text);
    let o = run(&["steady", case.to_str().unwrap()]);
    assert_clear_error(
        "steady, edge radius 1e12",
        &o,
        &[
            "stick-zone equations did not converge in",
            "halfplane march",
        ],
    );
}
