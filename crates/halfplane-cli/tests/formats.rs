//! `--format` and its aliases, the steady CSV, `[units]`, and the per-figure options of `plot`.

mod common;
use common::*;

fn ok(args: &[&str]) -> String {
    let o = run(args);
    assert!(o.status.success(), "{args:?}: {}", stderr(&o));
    stdout(&o)
}

#[test]
fn format_and_its_aliases_print_the_same_bytes() {
    let (hertz, cycle) = (example("hertz.toml"), example("march-cycle.toml"));
    let cases: [(&[&str], &str, &str); 5] = [
        (&["steady", &hertz], "--json", "json"),
        (&["steady", &hertz], "--csv", "csv"),
        (&["evolve", &hertz, "--points", "3"], "--json", "json"),
        (&["evolve", &hertz, "--points", "3"], "--csv", "csv"),
        (&["march", &cycle, "--cells", "40"], "--csv", "csv"),
    ];
    for (base, alias, format) in cases {
        let a = ok(&[base, &[alias]].concat());
        let b = ok(&[base, &["--format", format]].concat());
        assert_eq!(a, b, "{base:?} {alias}");
    }
    let table = ok(&["steady", &hertz]);
    assert_eq!(table, ok(&["steady", &hertz, "--format", "table"]));
    for conflict in [
        ["--csv", "--json", ""],
        ["--json", "--format", "table"],
        ["--csv", "--format", "json"],
    ] {
        let args: Vec<&str> = ["evolve", &hertz]
            .into_iter()
            .chain(conflict)
            .filter(|a| !a.is_empty())
            .collect();
        let o = run(&args);
        assert_eq!(o.status.code(), Some(2), "{conflict:?}");
        assert!(stderr(&o).contains("cannot be used with"), "{}", stderr(&o));
    }
    let o = run(&["steady", &hertz, "--format", "xml"]);
    assert_eq!(o.status.code(), Some(2));
    for n in ["xml", "--format", "table", "csv", "json"] {
        assert!(stderr(&o).contains(n), "{n}: {}", stderr(&o));
    }
}

/// Flattens a JSON value into dotted paths of its non-null leaves.
fn leaves(prefix: &str, v: &serde_json::Value, out: &mut Vec<(String, serde_json::Value)>) {
    match v {
        serde_json::Value::Object(m) => {
            for (k, x) in m {
                let path = if prefix.is_empty() {
                    k.clone()
                } else {
                    format!("{prefix}.{k}")
                };
                leaves(&path, x, out);
            }
        }
        serde_json::Value::Null => {}
        _ => out.push((prefix.to_string(), v.clone())),
    }
}

#[test]
fn steady_csv_is_the_json_in_one_row_of_fixed_columns() {
    let mut header: Option<String> = None;
    for file in [
        "hertz.toml",
        "flat-rounded.toml",
        "tabulated.toml",
        "full-stick.toml",
        "gross-sliding.toml",
    ] {
        let case = example(file);
        let csv = ok(&["steady", &case, "--format", "csv"]);
        let lines: Vec<&str> = csv.lines().collect();
        assert_eq!(lines.len(), 2, "{file}: {csv}");
        // The same columns for every case, so rows concatenate.
        assert_eq!(
            header.get_or_insert(lines[0].to_string()),
            lines[0],
            "{file}"
        );
        let columns: Vec<&str> = lines[0].split(',').collect();
        let cells: Vec<&str> = lines[1].split(',').collect();
        assert_eq!(columns.len(), cells.len(), "{file}");
        let json: serde_json::Value =
            serde_json::from_str(&ok(&["steady", &case, "--json"])).unwrap();
        let mut found = Vec::new();
        leaves("", &json, &mut found);
        for (path, value) in &found {
            let i = columns
                .iter()
                .position(|c| c == path)
                .unwrap_or_else(|| panic!("{file}: JSON {path} has no CSV column"));
            let cell = cells[i];
            match value {
                serde_json::Value::Number(n) => {
                    // serde_json parses floats to within an ulp or two.
                    let (a, b) = (cell.parse::<f64>().unwrap(), n.as_f64().unwrap());
                    assert!(
                        (a - b).abs() <= 1e-15 * b.abs(),
                        "{file} {path}: {a} != {b}"
                    )
                }
                serde_json::Value::String(s) => assert_eq!(cell, s, "{file} {path}"),
                serde_json::Value::Bool(b) => assert_eq!(cell, &b.to_string(), "{file} {path}"),
                serde_json::Value::Array(a) => {
                    assert_eq!(cell.split_whitespace().count(), a.len(), "{file} {path}")
                }
                _ => panic!("{file} {path}: unexpected {value}"),
            }
        }
        // A column the JSON does not have (or has as null) is empty.
        for (c, cell) in columns.iter().zip(&cells) {
            if !found.iter().any(|(p, _)| p == c) {
                assert!(
                    cell.is_empty() || *c == "profile.kinks",
                    "{file} {c} = {cell}"
                );
            }
        }
    }
}

#[cfg(feature = "plot")] // only the figure tests use it
fn with_units(name: &str, units: &str) -> ScratchFile {
    let text = std::fs::read_to_string(examples().join("march-cycle.toml")).unwrap();
    let file = ScratchFile::new(scratch(name), "case.toml");
    std::fs::write(&*file, format!("{text}\n[units]\n{units}\n")).unwrap();
    file
}

#[cfg(feature = "plot")] // draws a figure
#[test]
fn units_label_tables_and_axes_but_not_keys() {
    let case = with_units("units", "force = \"kN\"\nlength = \"m\"\nstress = \"kPa\"");
    let case = case.to_str().unwrap();
    let table = ok(&["steady", case]);
    assert!(table.contains("1400.000000   kN/m\n"), "{table}");
    assert!(table.contains("d = 0.673650 m "), "{table}");
    let evolve = ok(&["evolve", case, "--points", "3"]);
    assert!(
        evolve
            .lines()
            .nth(2)
            .unwrap()
            .contains("kN/m        kPa          m"),
        "{evolve}"
    );
    let json: serde_json::Value = serde_json::from_str(&ok(&["evolve", case, "--json"])).unwrap();
    assert_eq!(json["units"]["force"], "kN");
    assert!(json["points"][0].get("half_width").is_some());
    let default_csv = ok(&["evolve", &example("march-cycle.toml"), "--csv"]);
    assert_eq!(ok(&["evolve", case, "--csv"]), default_csv);
    let march = ok(&["march", case, "--cells", "40"]);
    assert!(march.contains("kN m/m dissipated"), "{march}");
    let dir = scratch("units-svg");
    let svg = dir.join("load.svg");
    ok(&["plot", "load-space", case, "-o", svg.to_str().unwrap()]);
    let text = std::fs::read_to_string(&svg).unwrap();
    assert!(text.contains("(kN/m)"), "load-space axes do not show kN/m");
    for (units, needles) in [
        ("force = \"\"", &["units.force", "\"\"", "1 to 12"][..]),
        (
            "length = \"milli metre\"",
            &["units.length", "milli metre", "spaces"],
        ),
        ("stress = 5", &["stress"]),
        ("time = \"s\"", &["time"]),
    ] {
        let case = with_units("bad-units", units);
        let o = run(&["steady", case.to_str().unwrap()]);
        assert_eq!(o.status.code(), Some(2), "{units}");
        for n in needles {
            assert!(stderr(&o).contains(n), "{units}: {n} not in {}", stderr(&o));
        }
    }
}

#[cfg(feature = "plot")] // draws a figure
#[test]
fn figure_options_belong_to_their_figure() {
    let hertz = example("hertz.toml");
    let dir = scratch("figure-options");
    let svg = dir.join("x.svg");
    let svg = svg.to_str().unwrap();
    // Options another figure takes are usage errors naming the option.
    let wrong: [(&str, &[&str]); 5] = [
        ("load-space", &["--frictions", "0.1"]),
        ("load-space", &["--steps", "3"]),
        ("load-space", &["--march"]),
        ("slip-map", &["--points", "5"]),
        ("march-zones", &["--steps", "3"]),
    ];
    for (figure, extra) in wrong {
        let o = run(&[&["plot", figure, hertz.as_str(), "-o", svg][..], extra].concat());
        assert_eq!(o.status.code(), Some(2), "{figure} {extra:?}");
        assert!(stderr(&o).contains(extra[0]), "{figure}: {}", stderr(&o));
    }
    let o = run(&["plot", "evolution", &hertz, "-o", svg, "--cells", "50"]);
    assert_eq!(o.status.code(), Some(2));
    assert!(stderr(&o).contains("--march"), "{}", stderr(&o));
    // Lists take the forms the help shows: spaces or commas.
    let read = || std::fs::read_to_string(svg).unwrap();
    ok(&[
        "plot",
        "slip-map",
        &hertz,
        "-o",
        svg,
        "--frictions",
        "0.3",
        "0.6",
        "--ratios",
        "1",
        "1.2",
    ]);
    let spaced = read();
    ok(&[
        "plot",
        "slip-map",
        &hertz,
        "-o",
        svg,
        "--frictions",
        "0.3,0.6",
        "--ratios",
        "1,1.2",
    ]);
    assert_eq!(spaced, read());
    assert!(spaced.contains("f = 0.3") && spaced.contains("P2/P1 = 1.2"));
    let history = example("march-history.toml");
    let o = run(&[
        "plot",
        "march-fields",
        &history,
        "-o",
        svg,
        "--steps",
        "10",
        "999",
        "--cells",
        "40",
    ]);
    assert!(stderr(&o).contains("--steps value 999"), "{}", stderr(&o));
    let help = ok(&["plot", "slip-map", "--help"]);
    assert!(
        help.contains("--frictions") && !help.contains("--steps"),
        "{help}"
    );
}

/// Without the `plot` feature (the README's first command builds so, for speed) every other
/// command works and `plot` says how to get figures.
#[cfg(not(feature = "plot"))]
#[test]
fn plot_without_the_feature_says_how_to_enable_it() {
    let o = run(&["plot", "load-space", &example("hertz.toml"), "-o", "x.png"]);
    assert_eq!(o.status.code(), Some(2));
    assert!(stderr(&o).contains("--features plot"), "{}", stderr(&o));
    assert!(!std::path::Path::new("x.png").exists());
}

/// Tables print numbers as people read them: the fatigue table printed `2.3615e0`, `4.8670e2`;
/// every number from 1e-3 to 1e6 is now in plain notation, and the CSV keeps every digit.
#[test]
fn tables_use_exponents_only_outside_the_readable_range() {
    let case = example("fatigue.toml");
    let table = ok(&["fatigue", &case]);
    let csv = ok(&["fatigue", &case, "--csv"]);
    let mut checked = 0;
    for line in table.lines().skip(3) {
        // The significant-digit columns: value, point_method, line_method, cycles.
        let words: Vec<&str> = line.split_whitespace().collect();
        for word in [1, 6, 7, 8].map(|k| words[k]) {
            if let Ok(v) = word.parse::<f64>() {
                let readable = v == 0.0 || (1e-3..1e6).contains(&v.abs());
                assert_eq!(word.contains('e'), !readable, "{word} in {line}");
                checked += 1;
            }
        }
    }
    assert!(checked >= 12, "{table}");
    let swt = csv
        .lines()
        .find(|l| l.starts_with("swt,"))
        .expect("swt row");
    let value: f64 = swt.split(',').nth(1).unwrap().parse().unwrap();
    assert!((1.0..10.0).contains(&value), "{swt}");
    let shown = format!("{value:.4}");
    assert!(table.contains(&format!(" {shown} ")), "{shown} in\n{table}");
    assert!(
        swt.split(',').nth(1).unwrap().len() > 10,
        "CSV keeps every digit: {swt}"
    );
}
