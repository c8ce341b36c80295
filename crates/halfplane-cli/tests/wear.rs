//! End-to-end tests of `halfplane wear`: the public columns, JSON keys and field files on the
//! bundled examples, a run that stops part way (exit 2 after its checkpoints), and bad `[wear]`
//! and sliding-history input (exit 2 naming the field, the value and what is valid).

mod common;
use common::*;

const COLUMNS: &str = "cycle,wear_volume,max_depth,energy_per_cycle,dissipated_energy,contact_left,contact_right,peak_pressure,stick_left,stick_right,slip_amplitude_max,displacement_amplitude";

fn json(args: &[&str]) -> serde_json::Value {
    let o = run(args);
    assert!(o.status.success(), "{}", stderr(&o));
    serde_json::from_str(&stdout(&o)).expect("wear --json prints one JSON object")
}

fn num(v: &serde_json::Value, key: &str) -> f64 {
    v[key]
        .as_f64()
        .unwrap_or_else(|| panic!("{key} is a number: {v}"))
}

/// Partial slip (Hertz, f = 0.6, Q = +-0.5 f P): Cattaneo's stick zone |x| < a sqrt(1 - Q/fP)
/// = 0.5382 mm never slips, so it never wears, and after 1e6 cycles the worn slip annuli have
/// left it carrying the load nearly alone, with almost no slip and no energy.
#[test]
fn partial_slip_wears_onto_the_stick_zone() {
    let v = json(&["wear", &example("wear-partial-slip.toml"), "--json"]);
    for key in [
        "law",
        "coefficient",
        "share",
        "cycles",
        "max_depth_increment",
        "cells",
        "cell_width",
        "simulated_cycles",
        "elastic_approach",
        "checkpoints",
        "stopped",
        "units",
    ] {
        assert!(v.get(key).is_some(), "the report has {key}: {v}");
    }
    assert_eq!(v["law"], "archard");
    assert!(v["stopped"].is_null());
    let cycles: Vec<u64> = v["checkpoints"]
        .as_array()
        .unwrap()
        .iter()
        .map(|c| c["cycle"].as_u64().unwrap())
        .collect();
    assert_eq!(cycles, [1, 10, 100, 1000, 10_000, 100_000, 1_000_000]);
    // Cycle jumping: a million cycles from a few thousand marched (the stability bound holds
    // the jumps to a few hundred cycles while the annuli carry load: docs/wear.md).
    let marched = v["simulated_cycles"].as_u64().unwrap();
    assert!((7..5000).contains(&marched), "{marched} cycles marched");
    let width = num(&v, "cell_width");
    let c = 0.7611 * 0.5f64.sqrt();
    let points = v["checkpoints"].as_array().unwrap();
    for p in points {
        // The stick zone is Cattaneo's to a cell at every checkpoint (its cells never slip).
        assert!((num(p, "stick_left") + c).abs() < width, "{p}");
        assert!((num(p, "stick_right") - c).abs() < width, "{p}");
    }
    let (first, last) = (&points[0], &points[6]);
    // Unworn: Hertz's a = 0.7611 mm and p0 = 836.4 MPa, to half a cell and 0.1%.
    assert!(
        (num(first, "contact_right") - 0.7611).abs() < width,
        "{first}"
    );
    assert!(
        (num(first, "peak_pressure") / 836.4 - 1.0).abs() < 1e-3,
        "{first}"
    );
    // The annuli wear out of contact asymptotically (docs/wear.md): 1e-3 of the first
    // cycle's energy is left at most, and the load on the stick zone alone peaks its pressure
    // at the worn steps (singular there: the peak grows with cells, 2463 MPa at 200).
    assert!(num(last, "energy_per_cycle") < 1e-3 * num(first, "energy_per_cycle"));
    assert!(num(last, "contact_left") > -0.7611 && num(last, "contact_right") < 0.7611);
    assert!(num(last, "peak_pressure") > 2.0 * 836.4, "{last}");
    for w in points.windows(2) {
        assert!(num(&w[1], "wear_volume") > num(&w[0], "wear_volume"));
        assert!(num(&w[1], "dissipated_energy") > num(&w[0], "dissipated_energy"));
    }
}

#[test]
fn csv_columns_and_field_files() {
    let dir = scratch("wear-fields");
    let case = dir.join("case.toml");
    let base = std::fs::read_to_string(examples().join("wear-partial-slip.toml")).unwrap();
    let short = base
        .replace("cycles = 1000000", "cycles = 1000")
        .replace("checkpoints = 7 ", "checkpoints = [1, 1000]");
    assert_ne!(short, base);
    std::fs::write(&case, short).unwrap();
    let fields = dir.join("fields");
    let o = run(&[
        "wear",
        case.to_str().unwrap(),
        "--csv",
        "--fields",
        fields.to_str().unwrap(),
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    let out = stdout(&o);
    let mut lines = out.lines();
    assert_eq!(lines.next(), Some(COLUMNS));
    let rows: Vec<&str> = lines.collect();
    assert_eq!(rows.len(), 2);
    assert!(rows[1].starts_with("1000,"), "{}", rows[1]);
    for cycle in [1, 1000] {
        let text = std::fs::read_to_string(fields.join(format!("checkpoint_{cycle}.csv")))
            .expect("one field file per checkpoint");
        let mut lines = text.lines();
        assert_eq!(
            lines.next(),
            Some("x,depth,depth_pad,depth_specimen,pressure,traction,slip_range")
        );
        let cells: Vec<Vec<f64>> = lines
            .map(|l| l.split(',').map(|v| v.parse().unwrap()).collect())
            .collect();
        assert_eq!(cells.len(), 400);
        for r in &cells {
            // share = 0.5: the pad and the specimen each lose half of the depth.
            assert!((r[2] - 0.5 * r[1]).abs() <= 1e-15 * r[1].abs().max(1e-30));
            assert!((r[2] + r[3] - r[1]).abs() <= 1e-15 * r[1].abs().max(1e-30));
            // Inside Cattaneo's stick zone nothing slips, so nothing wears.
            if r[0].abs() < 0.53 {
                assert_eq!(r[1], 0.0, "worn inside the stick zone: {r:?}");
            }
        }
        assert!(cells.iter().any(|r| r[1] > 0.0), "the slip annuli wear");
    }
}

/// A scar that outgrows a narrow grid stops the run with exit 2, naming the cycle and
/// `wear.span`, after printing the checkpoints it reached (gross sliding: stick columns null).
#[test]
fn a_scar_leaving_the_grid_stops_after_its_checkpoints() {
    let dir = scratch("wear-stops");
    let case = dir.join("case.toml");
    let base = std::fs::read_to_string(examples().join("wear-sliding.toml")).unwrap();
    let narrow = base.replacen("span = 6.0", "span = 1.2", 1);
    assert_ne!(narrow, base);
    std::fs::write(&case, narrow).unwrap();
    let o = run(&["wear", case.to_str().unwrap(), "--json"]);
    assert_eq!(o.status.code(), Some(2), "{}", stderr(&o));
    let e = stderr(&o);
    assert!(
        e.contains("wear stopped at cycle") && e.contains("wear.span"),
        "{e}"
    );
    assert!(!e.contains("panicked"), "{e}");
    let v: serde_json::Value = serde_json::from_str(&stdout(&o)).unwrap();
    assert!(v["stopped"].as_str().unwrap().contains("wear.span"));
    assert!(v["simulated_cycles"].is_null());
    let points = v["checkpoints"].as_array().unwrap();
    assert!(
        !points.is_empty() && points.len() < 6,
        "{} checkpoints",
        points.len()
    );
    for p in points {
        assert!(
            p["stick_left"].is_null() && p["stick_right"].is_null(),
            "{p}"
        );
        // Sliding 0.02 mm each way at Q = f P = 600 N/mm dissipates at least 24 N mm/mm.
        assert!(num(p, "energy_per_cycle") > 24.0, "{p}");
    }
}

#[test]
fn bad_wear_input_exits_2_naming_the_field() {
    let dir = scratch("wear-bad");
    let partial = std::fs::read_to_string(examples().join("wear-partial-slip.toml")).unwrap();
    let sliding = std::fs::read_to_string(examples().join("wear-sliding.toml")).unwrap();
    let cases = [
        (
            &partial,
            "coefficient = 3e-8",
            "coefficient = 0.0",
            "wear.coefficient",
        ),
        (
            &partial,
            "coefficient = 3e-8",
            "coefficient = -1e-8",
            "wear.coefficient = -1e-8",
        ),
        (&partial, "share = 0.5", "share = 1.5", "wear.share = 1.5"),
        (
            &partial,
            "cycles = 1000000",
            "cycles = 0",
            "wear.cycles = 0",
        ),
        (
            &partial,
            "checkpoints = 7 ",
            "checkpoints = [10, 5] ",
            "wear.checkpoints[1] = 5",
        ),
        (
            &partial,
            "law = \"archard\"",
            "law = \"archerd\"",
            "wear.law",
        ),
        (
            &partial,
            "share = 0.5",
            "shares = 0.5",
            "unknown field wear.shares",
        ),
        (
            &partial,
            "\n[wear]\n",
            "\n[wearing]\n",
            "unknown field `wearing`",
        ),
        (&sliding, "span = 6.0", "span = 0.5", "wear.span = 0.5"),
        (
            &sliding,
            "amplitude = 0.02",
            "amplitude = inf",
            "history.amplitude = inf",
        ),
        (
            &sliding,
            "amplitude = 0.02",
            "amplitude = nan",
            "history.amplitude = NaN",
        ),
        (
            &sliding,
            "amplitude = 0.02",
            "amplitude = 0.0",
            "history.amplitude = 0",
        ),
    ];
    for (base, from, to, expect) in cases {
        assert!(base.contains(from), "{from}");
        let path = dir.join("case.toml");
        std::fs::write(&path, base.replacen(from, to, 1)).unwrap();
        let o = run(&["wear", path.to_str().unwrap()]);
        assert_eq!(o.status.code(), Some(2), "{to}: {}", stdout(&o));
        let e = stderr(&o);
        assert!(e.contains(expect), "{to}: {e}");
        assert!(!e.contains("panicked"), "{e}");
    }
}
