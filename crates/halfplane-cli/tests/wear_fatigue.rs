//! End-to-end tests of `halfplane wear --fatigue`: the `[fatigue]` parameters of each
//! checkpoint's cycle on the partial-slip example as its slip annuli wear out of contact, the
//! CSV's columns after the checkpoint's own, and exit 2 without constants.

mod common;
use common::*;

const COLUMNS: &str = "cycle,wear_volume,max_depth,energy_per_cycle,dissipated_energy,contact_left,contact_right,peak_pressure,stick_left,stick_right,slip_amplitude_max,displacement_amplitude";

/// Findley, Crossland and the critical distance (L = (160/700)^2/pi = 0.0166 mm) on a 61 x 31
/// grid over +-1.5 a and 1.0 a deep.
const FATIGUE: &str = "
[fatigue]
findley_k = 0.25
crossland_alpha = 0.4
threshold = 160.0
endurance_range = 700.0
nx = 61
nz = 31
";

/// The partial-slip example with `[fatigue]`, `from` replaced by `to` in its text.
fn case(dir: &Scratch, from: &str, to: &str) -> String {
    let base = std::fs::read_to_string(examples().join("wear-partial-slip.toml")).unwrap();
    assert!(base.contains(from), "{from}");
    let path = dir.join("case.toml");
    std::fs::write(&path, base.replacen(from, to, 1) + FATIGUE).unwrap();
    path.to_str().unwrap().to_string()
}

fn num(v: &serde_json::Value) -> f64 {
    v.as_f64().unwrap_or_else(|| panic!("a number: {v}"))
}

/// Hertz, P = 1000 N/mm, f = 0.6, Q = +-300 N/mm: a = 0.7611 mm, Cattaneo's stick zone
/// c = a sqrt(1 - Q/fP) = 0.5382 mm. Unworn, every parameter peaks on the surface at a contact
/// edge (the trailing edge of the cycle's extreme); worn for 1e6 cycles, the annuli are out of
/// contact, nothing slips (Ruiz's F1 = max q delta falls to nothing), and the load is carried
/// by the stick zone, whose worn steps raise the pressure at its edges (the peak Ciavarella and
/// Hills describe; singular on this model's sharp steps, so its size grows with cells:
/// docs/wear.md), and SWT moves there, above its unworn value: in partial slip this wear does not
/// protect the contact. Measured at 400 cells: SWT 1.94 at x = 0.755 unworn, 5.45 at 0.561 after
/// 1e6 cycles (examples/fatigue.toml's 60 x 30 grid), so the factor 1.5 asserted is far inside.
#[test]
fn swt_moves_to_the_stick_zone_edge_as_the_annuli_wear() {
    let dir = scratch("wear-fatigue");
    let path = case(&dir, "checkpoints = 7 ", "checkpoints = [1, 1000, 100000] ");
    let o = run(&["wear", &path, "--fatigue", "--json"]);
    assert!(o.status.success(), "{}", stderr(&o));
    let v: serde_json::Value = serde_json::from_str(&stdout(&o)).unwrap();
    let points = v["checkpoints"].as_array().unwrap();
    assert_eq!(points.len(), 4, "1, 1000, 1e5 and the last cycle, 1e6");
    let (a, c) = (0.7611, 0.5382);
    let grid_step = 2.0 * 1.5 * a / 60.0;
    let cell = num(&v["cell_width"]);
    for p in points {
        let f = p["fatigue"]
            .as_object()
            .expect("a fatigue object per checkpoint");
        // The parser sorts the keys (serde_json without preserve_order): the set is checked.
        let names: Vec<&str> = f.keys().map(String::as_str).collect();
        assert_eq!(
            names,
            ["crossland", "findley", "ruiz_f1", "ruiz_f2", "swt"],
            "those [fatigue] allows"
        );
        for name in ["swt", "findley", "crossland"] {
            let m = &f[name];
            for key in ["max", "x", "z", "point_method", "line_method"] {
                assert!(m[key].is_f64(), "{name}.{key}: {m}");
            }
            assert!(num(&m["point_method"]) < num(&m["max"]), "{name}: {m}");
        }
        assert!(f["ruiz_f1"]["point_method"].is_null());
    }
    let swt = |p: &serde_json::Value| p["fatigue"]["swt"].clone();
    let (first, last) = (&points[0], &points[3]);
    assert!(
        (num(&swt(first)["x"]).abs() - a).abs() < grid_step,
        "{first}"
    );
    assert_eq!(num(&swt(first)["z"]), 0.0);
    assert!(
        (num(&swt(last)["x"]).abs() - c).abs() < grid_step + cell,
        "{}",
        swt(last)
    );
    assert!(num(&swt(last)["max"]) > 1.5 * num(&swt(first)["max"]));
    let f1 = |p: &serde_json::Value| num(&p["fatigue"]["ruiz_f1"]["max"]);
    assert!(
        f1(last) < 1e-2 * f1(first),
        "{} against {}",
        f1(last),
        f1(first)
    );
}

/// The CSV keeps its 11 columns first, then `fatigue.<parameter>.<field>`; without `--fatigue`
/// neither CSV nor JSON says anything of fatigue.
#[test]
fn csv_columns_follow_the_checkpoint_columns() {
    let dir = scratch("wear-fatigue-csv");
    let path = case(&dir, "cycles = 1000000", "cycles = 10");
    let o = run(&["wear", &path, "--fatigue", "--csv"]);
    assert!(o.status.success(), "{}", stderr(&o));
    let out = stdout(&o);
    let header = out.lines().next().unwrap();
    let mut extra = Vec::new();
    for p in ["swt", "findley", "crossland"] {
        for f in ["max", "x", "z", "point_method", "line_method"] {
            extra.push(format!("fatigue.{p}.{f}"));
        }
    }
    for p in ["ruiz_f1", "ruiz_f2"] {
        for f in ["max", "x", "z"] {
            extra.push(format!("fatigue.{p}.{f}"));
        }
    }
    assert_eq!(header, format!("{COLUMNS},{}", extra.join(",")));
    let width = header.split(',').count();
    for row in out.lines().skip(1) {
        assert_eq!(row.split(',').count(), width, "{row}");
    }
    let o = run(&["wear", &path, "--csv"]);
    assert_eq!(stdout(&o).lines().next(), Some(COLUMNS));
    let o = run(&["wear", &path, "--json"]);
    assert!(!stdout(&o).contains("fatigue"), "{}", stdout(&o));
}

/// `--fatigue` on a case whose `[fatigue]` gives no constant (absent, or only its grid) exits 2
/// naming what to add, before any cycle.
#[test]
fn fatigue_without_constants_exits_2_naming_them() {
    let dir = scratch("wear-fatigue-bad");
    let bare = dir.join("bare.toml");
    std::fs::copy(examples().join("wear-partial-slip.toml"), &bare).unwrap();
    let grid_only = dir.join("grid.toml");
    let text = std::fs::read_to_string(&bare).unwrap() + "\n[fatigue]\nnx = 41\n";
    std::fs::write(&grid_only, text).unwrap();
    for path in [&bare, &grid_only] {
        let o = run(&["wear", path.to_str().unwrap(), "--fatigue"]);
        assert_eq!(o.status.code(), Some(2), "{}", stdout(&o));
        let e = stderr(&o);
        assert!(
            e.contains("--fatigue needs material constants in [fatigue]")
                && e.contains("fatigue.findley_k"),
            "{e}"
        );
        assert!(stdout(&o).is_empty(), "{}", stdout(&o));
        assert!(!e.contains("panicked"), "{e}");
    }
}
