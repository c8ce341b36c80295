//! End-to-end tests of `halfplane match`: the test case it writes runs through `steady` and
//! `march` and reproduces the prototype's edge state; bad requests exit 2 naming what is wrong.
//!
//! Tolerances: the exact equalities to 1e-8 and the asymptotic ones to 1e-10 (the library's
//! tests give the reasons); the loads pass through the TOML file in shortest round-trip form, so
//! the file adds no error.

mod common;
use common::*;
use serde_json::Value;
use std::path::Path;

fn json(args: &[&str]) -> Value {
    let o = run(args);
    assert!(o.status.success(), "{args:?}: {}", stderr(&o));
    serde_json::from_str(&stdout(&o)).expect("JSON")
}

fn at<'a>(v: &'a Value, path: &str) -> &'a Value {
    path.split('.').fold(v, |v, k| &v[k])
}

fn num(v: &Value, path: &str) -> f64 {
    at(v, path)
        .as_f64()
        .unwrap_or_else(|| panic!("{path} is not a number: {}", at(v, path)))
}

fn close(a: f64, b: f64, tol: f64) -> bool {
    (a - b).abs() <= tol * a.abs().max(b.abs())
}

fn path(p: &Path) -> &str {
    p.to_str().expect("UTF-8 path")
}

#[test]
fn exact_round_trip_the_test_case_runs_and_its_slip_zones_are_the_prototypes() {
    let dir = scratch("match-exact");
    let test = dir.join("TEST.toml");
    let proto = example("flat-rounded.toml");
    let report = json(&[
        "match",
        &proto,
        "--profile",
        "hertz",
        "--radius",
        "50",
        "--exact",
        "-o",
        path(&test),
        "--json",
    ]);
    assert_eq!(report["mode"], "exact");
    let p = json(&["steady", &proto, "--json"]);
    let t = json(&["steady", path(&test), "--json"]);
    assert_eq!(t["profile"]["kind"], "hertz");
    for key in ["slip_zones.left.at_point2", "slip_zones.right.at_point2"] {
        let (a, b) = (num(&p, key), num(&t, key));
        assert!(close(a, b, 1e-8), "{key}: prototype {a}, test {b}");
        assert!(
            close(num(&report, &format!("{key}.test")), b, 1e-12),
            "report {key}"
        );
    }
    for key in ["contact.normal_intensity_1", "contact.normal_intensity_2"] {
        assert!(close(num(&p, key), num(&t, key), 1e-8), "{key}");
    }
    for edge in ["left", "right"] {
        let mean = |v: &Value| {
            let k = |pt: &str| num(v, &format!("asymptotic.edges.{pt}.shear_intensity_{edge}"));
            0.5 * (k("at_point1") + k("at_point2"))
        };
        assert!(
            close(mean(&p), mean(&t), 1e-8),
            "mean K_T at the {edge} edge"
        );
    }
}

#[test]
fn asymptotic_round_trip_matches_k_n_and_k_t_through_the_written_file() {
    let dir = scratch("match-asym");
    let test = dir.join("TEST.toml");
    let proto = example("flat-rounded.toml");
    let o = run(&[
        "match",
        &proto,
        "--profile",
        "power-law",
        "--coefficient",
        "1e-2",
        "--exponent",
        "2.5",
        "-o",
        path(&test),
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    assert!(stdout(&o).contains("K_T left at point1"), "{}", stdout(&o));
    assert!(stderr(&o).contains("wrote"), "{}", stderr(&o));
    let p = json(&["steady", &proto, "--json"]);
    let t = json(&["steady", path(&test), "--json"]);
    assert_eq!(t["profile"]["kind"], "power-law");
    for pt in ["at_point1", "at_point2"] {
        for edge in ["left", "right"] {
            let key = format!("asymptotic.edges.{pt}.shear_intensity_{edge}");
            assert!(close(num(&p, &key), num(&t, &key), 1e-10), "{key}");
        }
    }
    for key in ["contact.normal_intensity_1", "contact.normal_intensity_2"] {
        assert!(close(num(&p, key), num(&t, key), 1e-10), "{key}");
    }
}

#[test]
fn a_hertz_prototype_onto_its_own_geometry_writes_its_own_loads() {
    let dir = scratch("match-self");
    let test = dir.join("TEST.toml");
    let proto = example("hertz.toml");
    let r = json(&[
        "match",
        &proto,
        "--profile",
        "hertz",
        "--radius",
        "50",
        "-o",
        path(&test),
        "--json",
    ]);
    for pt in ["at_point1", "at_point2"] {
        for q in ["normal", "shear", "bulk"] {
            let key = format!("points.{pt}.{q}");
            let (a, b) = (num(&r["prototype"], &key), num(&r["test"], &key));
            assert!(close(a, b, 1e-10), "{key}: {a} != {b}");
        }
    }
    assert_eq!(r["warnings"], Value::Array(vec![]));
}

#[test]
fn a_cycle_history_is_carried_over_and_the_test_marches() {
    let dir = scratch("match-history");
    let test = dir.join("TEST.toml");
    let o = run(&[
        "match",
        &example("march-cycle.toml"),
        "--profile",
        "flat-rounded",
        "--flat-half-width",
        "0.3",
        "--radius",
        "50",
        "-o",
        path(&test),
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    let text = std::fs::read_to_string(&test).unwrap();
    assert!(
        text.contains("kind = \"cycle\"") && text.contains("cells = 400"),
        "{text}"
    );
    let m = run(&["march", path(&test), "--cells", "40"]);
    assert!(m.status.success(), "{}", stderr(&m));
}

#[test]
fn a_harmonic_history_is_mapped_row_by_row_into_a_csv_beside_the_test() {
    let dir = scratch("match-harmonic");
    let harmonic = std::fs::read_to_string(example("march-harmonic.toml")).unwrap();
    let proto = dir.join("proto.toml");
    std::fs::write(&proto, format!("{harmonic}\n[cycle]\npoint1 = {{ normal = 1000.0, shear = -250.0, bulk = -20.0 }}\npoint2 = {{ normal = 1400.0, shear = 250.0, bulk = 20.0 }}\n")).unwrap();
    let test = dir.join("TEST.toml");
    let o = run(&[
        "match",
        path(&proto),
        "--profile",
        "hertz",
        "--radius",
        "50",
        "-o",
        path(&test),
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    let csv = std::fs::read_to_string(dir.join("TEST-history.csv")).unwrap();
    // Header, 20 ramp rows and 3 cycles of 120.
    assert_eq!(
        csv.lines().count(),
        1 + 20 + 360,
        "rows of the mapped history"
    );
    let m = run(&["march", path(&test), "--cells", "40"]);
    assert!(m.status.success(), "{}", stderr(&m));
}

#[test]
fn bad_requests_exit_2_naming_what_is_wrong() {
    let dir = scratch("match-bad");
    let out = dir.join("TEST.toml");
    let proto = example("flat-rounded.toml");
    let cases: &[(&[&str], &str)] = &[
        (&["--profile", "hertz"], "missing --radius"),
        (
            &["--profile", "hertz", "--radius", "50", "--exponent", "3"],
            "--exponent is not used by --profile hertz",
        ),
        (
            &["--profile", "hertz", "--radius", "-1"],
            "invalid --radius = -1",
        ),
        (
            &[
                "--profile",
                "hertz",
                "--radius",
                "50",
                "--poisson-ratio",
                "0.5",
            ],
            "invalid --poisson-ratio = 0.5",
        ),
        (
            &["--profile", "hertz", "--radius", "50", "--friction", "0"],
            "invalid --friction = 0",
        ),
        (
            &[
                "--profile",
                "power-law",
                "--coefficient",
                "1e-2",
                "--exponent",
                "1.5",
            ],
            "no solution bracketed",
        ),
        (
            &["--profile", "hertz", "--radius", "50", "--friction", "0.2"],
            "gross-sliding constraint",
        ),
        (
            &["--profile", "hertz", "--radius", "100", "--exact"],
            "stick-zone-outside-contact constraint",
        ),
        (
            &["--profile", "tabulated"],
            "possible values: hertz, flat-rounded, power-law",
        ),
    ];
    for (args, expected) in cases {
        let mut all = vec!["match", proto.as_str()];
        all.extend_from_slice(args);
        all.extend_from_slice(&["-o", path(&out)]);
        let o = run(&all);
        assert_eq!(o.status.code(), Some(2), "{args:?}");
        assert!(stderr(&o).contains(expected), "{args:?}: {}", stderr(&o));
        assert!(!out.exists(), "{args:?} wrote a test case");
    }
    let no_cycle = dir.join("no-cycle.toml");
    std::fs::write(&no_cycle, REFERENCE_CONTACT).unwrap();
    let o = run(&[
        "match",
        path(&no_cycle),
        "--profile",
        "hertz",
        "--radius",
        "50",
        "-o",
        path(&out),
    ]);
    assert_eq!(o.status.code(), Some(2));
    assert!(
        stderr(&o).contains("missing section [cycle]"),
        "{}",
        stderr(&o)
    );
}

#[cfg(feature = "plot")] // draws a figure
#[test]
fn plot_match_draws_both_load_spaces() {
    let dir = scratch("match-plot");
    let svg = dir.join("match.svg");
    let o = run(&[
        "plot",
        "match",
        &example("flat-rounded.toml"),
        "--profile",
        "hertz",
        "--radius",
        "50",
        "-o",
        path(&svg),
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    let text = std::fs::read_to_string(&svg).unwrap();
    assert!(text.contains("prototype: flat, rounded edges") && text.contains("test: Hertz"));
}

/// A failed match's hint offers the other mode: in --exact it offered "--exact" again.
#[test]
fn a_failed_match_hints_at_the_other_mode() {
    let dir = scratch("match-hint");
    let out = dir.join("TEST.toml");
    let proto = example("flat-rounded.toml");
    let hint = |args: &[&str]| {
        let mut all = vec!["match", proto.as_str(), "--profile", "hertz"];
        all.extend_from_slice(args);
        all.extend_from_slice(&["-o", path(&out)]);
        let o = run(&all);
        assert_eq!(o.status.code(), Some(2), "{args:?}");
        let text = stderr(&o);
        let line = text
            .lines()
            .find(|l| l.starts_with("hint: "))
            .map(str::to_string);
        line.unwrap_or_else(|| panic!("{args:?}: no hint in {text}"))
    };
    let exact = hint(&["--radius", "100", "--exact"]);
    assert!(
        exact.contains("without --exact") && !exact.contains("(--exact)"),
        "{exact}"
    );
    let asymptotic = hint(&["--radius", "50", "--friction", "0.2"]);
    assert!(asymptotic.contains("exact match (--exact)"), "{asymptotic}");
}
