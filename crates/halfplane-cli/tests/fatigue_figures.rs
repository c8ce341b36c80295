//! End-to-end tests of the stress and fatigue figures (`plot stress-map`, `plot fatigue-map`,
//! `plot surface-profiles`): each is written with its series, and bad input exits 2 naming the
//! field or option.
#![cfg(feature = "plot")]

mod common;
use common::*;

#[test]
fn stress_and_fatigue_figures_are_written_with_their_series() {
    let dir = scratch("fatigue-figures");
    let case = example("fatigue.toml");
    let cases: [(&str, &[&str], &[&str]); 5] = [
        (
            "stress-map",
            &["--step", "110"],
            &[
                "σxx below the contact at increment 110",
                "contact −a ≤ x ≤ a",
                "σxx (MPa)",
                "max ",
            ],
        ),
        (
            "stress-map",
            &["--component", "sxz"],
            &["σxz below the contact at increment 140", "σxz (MPa)"],
        ),
        (
            "fatigue-map",
            &[],
            &[
                "SWT over the steady cycle (increments 81 to 140)",
                "max ",
                "line method: 0 ≤ z ≤ 2L",
            ],
        ),
        (
            "fatigue-map",
            &["--parameter", "mwcm"],
            &["MWCM (mwcm)", "MWCM (MPa)", "plane "],
        ),
        (
            "surface-profiles",
            &[],
            &[
                "surface σxx(x, 0)",
                "increment 110 (1/2 of the cycle)",
                "largest over the cycle",
                "F2 = σxx,max |q|max δ",
            ],
        ),
    ];
    for (figure, extra, needles) in cases {
        let out = dir.join(format!("{figure}.svg"));
        let mut args = vec!["plot", figure, &case, "-o", out.to_str().unwrap()];
        args.extend_from_slice(extra);
        args.extend_from_slice(&["--cells", "100"]);
        let o = run(&args);
        assert_eq!(o.status.code(), Some(0), "{args:?}: {}", stderr(&o));
        let svg = std::fs::read_to_string(&out).unwrap();
        for n in needles {
            assert!(svg.contains(n), "{figure} {extra:?}: {n:?} not in the SVG");
        }
    }
    let png = dir.join("map.png");
    let o = run(&[
        "plot",
        "stress-map",
        &case,
        "-o",
        png.to_str().unwrap(),
        "--cells",
        "100",
    ]);
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    assert!(std::fs::read(&png).unwrap().starts_with(b"\x89PNG"));
}

#[test]
fn bad_figure_input_exits_2_naming_the_field() {
    let dir = scratch("fatigue-figures-bad");
    let base = std::fs::read_to_string(examples().join("fatigue.toml")).unwrap();
    let write = |name: &str, text: String| {
        let path = dir.join(name);
        std::fs::write(&path, text).unwrap();
        path.to_str().unwrap().to_string()
    };
    let no_findley = write("no-findley.toml", base.replace("findley_k = 0.25", ""));
    let no_limit = write(
        "no-limit.toml",
        base.replace("torsional_fatigue_limit = 220.0", ""),
    );
    let bad_grid = write("bad-grid.toml", base.replace("nx = 60", "nx = 1"));
    let out = dir.join("x.svg");
    let out = out.to_str().unwrap();
    let (case, file_history) = (example("fatigue.toml"), example("march-history.toml"));
    let cases: [(&[&str], &str); 8] = [
        (
            &["stress-map", &case, "--step", "0"],
            "invalid --step 0: the history has increments 1 to 140",
        ),
        (
            &["stress-map", &case, "--step", "141"],
            "invalid --step 141",
        ),
        (&["stress-map", &case, "--component", "sxy"], "--component"),
        (
            &["fatigue-map", &no_findley, "--parameter", "findley"],
            "--parameter findley needs fatigue.findley_k",
        ),
        (
            &["fatigue-map", &no_limit, "--parameter", "mwcm"],
            "fatigue.torsional_fatigue_limit",
        ),
        (
            &["fatigue-map", &case, "--parameter", "ruiz_f2"],
            "--parameter",
        ),
        (&["surface-profiles", &bad_grid], "fatigue.nx = 1"),
        (&["surface-profiles", &file_history], "cyclic history"),
    ];
    for (args, message) in cases {
        let mut all = vec!["plot"];
        all.extend_from_slice(args);
        all.extend_from_slice(&["-o", out]);
        let o = run(&all);
        let err = stderr(&o);
        assert_eq!(o.status.code(), Some(2), "{all:?}: {err}");
        assert!(err.contains(message), "{all:?}: {err:?} lacks {message:?}");
        assert!(!err.contains("panicked"), "{all:?}: {err}");
    }
}
