//! End-to-end tests of `halfplane sweep`: a grid against the Hertz closed form, shards against
//! the whole sweep, seeds, a march sweep against `halfplane march`, a wear sweep against
//! `halfplane wear`, the Figure-5 spec against the library's slip map, and bad specs.

mod common;
use common::{example, run, scratch, stderr, REFERENCE_CASE, REFERENCE_CONTACT};
use halfplane::closed_form::{hertz_half_width, hertz_stick_zone};
use std::path::Path;

/// Runs a sweep of `spec` (text) into `out`, with extra arguments, and returns the output if it
/// is text (CSV); panics on failure.
fn sweep(dir: &Path, spec: &str, out: &str, extra: &[&str]) -> String {
    let spec_path = dir.join("spec.toml");
    std::fs::write(&spec_path, spec).unwrap();
    let out = dir.join(out);
    let mut args = vec![
        "sweep",
        spec_path.to_str().unwrap(),
        "-o",
        out.to_str().unwrap(),
    ];
    args.extend(extra);
    let o = run(&args);
    assert!(o.status.success(), "sweep {extra:?}: {}", stderr(&o));
    match out.extension().and_then(|e| e.to_str()) {
        Some("csv") => std::fs::read_to_string(&out).unwrap(),
        _ => String::new(),
    }
}

/// The rows of a CSV (header first) as cells; the sweep's errors hold no line breaks.
fn rows(csv: &str) -> Vec<Vec<String>> {
    let mut reader = csv::ReaderBuilder::new()
        .has_headers(false)
        .from_reader(csv.as_bytes());
    reader
        .records()
        .map(|r| r.unwrap().iter().map(str::to_string).collect())
        .collect()
}

fn num(cell: &str) -> f64 {
    cell.parse()
        .unwrap_or_else(|_| panic!("{cell:?} is not a number"))
}

#[test]
fn a_hertz_grid_matches_the_closed_form() {
    // Q2, f and R vary; point 1 (Q = -250, sigma = -20) is the smaller-Q end for every Q2 >= 0,
    // so dQ = Q2 + 250 and dsigma = sigma1 - sigma2 = -40. Closed forms (closed_form.rs, paper
    // eqs. (24), (28), (30)): a_i^2 = 2 P_i A R/pi, d^2 = (A R/pi)(P1 + P2 - dQ/f),
    // e = -A R dsigma/(8 f); stick zone [e - d, e + d]; slip zones a_i - m (left), a_i - n
    // (right). The sweep's numbers went through substitution, the steady analysis and CSV
    // formatting in full precision, so they must agree to rounding: 1e-12 relative to a.
    let spec = format!(
        "{REFERENCE_CASE}[sweep]\nmode = \"grid\"\n[sweep.vary]\n\"cycle.point2.shear\" = {{ from = 0.0, to = 800.0, count = 17 }}\n\"friction.coefficient\" = [0.3, 0.6, 0.9]\n\"profile.radius\" = {{ from = 10.0, to = 1000.0, count = 3, scale = \"log\" }}\n"
    );
    let dir = scratch("sweep-hertz");
    let table = rows(&sweep(&dir, &spec, "out.csv", &[]));
    assert_eq!(
        table[0].join(","),
        "cycle.point2.shear,friction.coefficient,profile.radius,regime,stick_left,stick_right,half_width_1,half_width_2,slip_left_1,slip_left_2,slip_right_1,slip_right_2,error"
    );
    assert_eq!(table.len(), 1 + 17 * 3 * 3);
    let a_compliance = 4.0 * (1.0 - 0.3f64 * 0.3) / 200_000.0;
    let (mut partial, mut sliding) = (0, 0);
    for row in &table[1..] {
        let (q2, f, r) = (num(&row[0]), num(&row[1]), num(&row[2]));
        let a = [1000.0, 1400.0].map(|p| hertz_half_width(a_compliance, r, p));
        let close = |cell: &str, want: f64, what: &str| {
            let got = num(cell);
            assert!(
                (got - want).abs() <= 1e-12 * a[1],
                "Q2 = {q2}, f = {f}, R = {r}: {what} {got} vs closed form {want}"
            );
        };
        match row[3].as_str() {
            "partial-slip" => {
                partial += 1;
                let (d, e) = hertz_stick_zone(a_compliance, r, f, 2400.0, q2 + 250.0, -40.0)
                    .expect("a stick zone in partial slip");
                close(&row[4], e - d, "stick_left");
                close(&row[5], e + d, "stick_right");
                close(&row[6], a[0], "half_width_1");
                close(&row[7], a[1], "half_width_2");
                for (k, ai) in a.iter().enumerate() {
                    close(&row[8 + k], ai - (d - e), "left slip zone a - m");
                    close(&row[10 + k], ai - (e + d), "right slip zone a - n");
                }
            }
            "full-stick" => {
                // Eq. (1) with a_max: (dQ + pi a2 |dsigma|/4)/dP <= f; the stick zone is the
                // smaller contact and nothing slips.
                let ratio = (q2 + 250.0 + std::f64::consts::PI * a[1] * 40.0 / 4.0) / 400.0;
                assert!(ratio <= f, "Q2 = {q2}, f = {f}: full stick needs eq. (1)");
                close(&row[4], -a[0], "stick_left");
                close(&row[5], a[0], "stick_right");
                assert!(
                    row[8..12].iter().all(|c| num(c) == 0.0),
                    "no slip in full stick"
                );
            }
            "gross-sliding" => {
                sliding += 1;
                assert!(
                    q2 >= f * 1400.0 || 250.0 >= f * 1000.0,
                    "Q2 = {q2}, f = {f}: slides"
                );
                assert!(
                    row[4].is_empty() && row[8].is_empty(),
                    "no stick zone when sliding"
                );
            }
            // Outside the analysis (slip reversal with this tension): a row with its error.
            "" => assert!(!row[12].is_empty(), "a failed row says why: {row:?}"),
            other => panic!("unexpected regime {other:?}"),
        }
    }
    assert!(
        partial >= 60 && sliding >= 10,
        "{partial} partial slip, {sliding} sliding"
    );
}

const RANDOM: &str = "[sweep]\nmode = \"random\"\nsamples = 1000\nseed = 42\n[sweep.vary]\n\"cycle.point2.shear\" = { from = 0.0, to = 800.0 }\n\"profile.radius\" = { from = 10.0, to = 1000.0, scale = \"log\" }\n\"friction.coefficient\" = [0.3, 0.6]\n";

#[test]
fn shards_together_are_the_sweep_byte_for_byte() {
    let dir = scratch("sweep-shards");
    for mode in ["random", "latin-hypercube"] {
        let spec = format!("{REFERENCE_CASE}{}", RANDOM.replace("random", mode));
        let whole = sweep(&dir, &spec, "whole.csv", &["--threads", "2"]);
        let one_thread = sweep(&dir, &spec, "one.csv", &["--threads", "1"]);
        assert_eq!(
            whole, one_thread,
            "{mode}: the thread count changes nothing"
        );
        let mut lines = whole.split_inclusive('\n');
        let header = lines.next().unwrap();
        let body: String = lines.collect();
        let mut joined = String::new();
        for i in 1..=3 {
            let shard = sweep(
                &dir,
                &spec,
                &format!("shard{i}.csv"),
                &["--shard", &format!("{i}/3")],
            );
            let rest = shard
                .strip_prefix(header)
                .expect("every shard has the header");
            assert!(!rest.is_empty(), "{mode}: shard {i} of 3 is not empty");
            joined.push_str(rest);
        }
        assert_eq!(
            joined, body,
            "{mode}: the shards in order are the whole sweep"
        );
        assert_eq!(body.lines().count(), 1000);
    }
}

#[test]
fn a_seed_fixes_the_rows() {
    let dir = scratch("sweep-seed");
    let spec = format!("{REFERENCE_CASE}{RANDOM}");
    let first = sweep(&dir, &spec, "a.csv", &[]);
    let again = sweep(&dir, &spec, "b.csv", &[]);
    let other = sweep(&dir, &spec.replace("seed = 42", "seed = 43"), "c.csv", &[]);
    assert_eq!(first, again, "the same seed gives the same rows");
    let differ = first
        .lines()
        .zip(other.lines())
        .skip(1)
        .filter(|(a, b)| a != b)
        .count();
    assert!(
        differ > 990,
        "another seed gives other rows: {differ} of 1000 differ"
    );
    // Every row stays inside its ranges (log scale: 10 to 1000).
    for row in &rows(&first)[1..] {
        let (q, r) = (num(&row[0]), num(&row[1]));
        assert!(
            (0.0..=800.0).contains(&q) && (10.0..=1000.0).contains(&r),
            "{row:?}"
        );
        assert!(["0.3", "0.6"].contains(&row[2].as_str()));
    }
}

#[test]
fn a_march_sweep_adds_the_march_columns_and_matches_the_march_command() {
    // Small: 60 cells, 2 cycles of 2 x 10 increments, two friction coefficients.
    let case = format!(
        "{REFERENCE_CASE}[history]\nkind = \"cycle\"\ncycles = 2\nsteps_per_half = 10\nramp_steps = 5\n[solver]\ncells = 60\n"
    );
    let dir = scratch("sweep-march");
    let spec = format!(
        "{case}[sweep]\nmode = \"grid\"\nanalysis = \"march\"\n[sweep.vary]\n\"friction.coefficient\" = [0.6, 0.9]\n"
    );
    let table = rows(&sweep(&dir, &spec, "march.csv", &[]));
    assert_eq!(
        table[0][10..].join(","),
        "error,energy,max_slip_amplitude,shakedown_cycle,final_stick_left,final_stick_right,\
         cycles_run,steady_change,steady_converged"
    );
    for (row, f) in table[1..].iter().zip(["0.6", "0.9"]) {
        assert_eq!(row[0], f);
        assert_eq!(row[1], "partial-slip");
        assert!(row[10].is_empty(), "f = {f}: {}", row[10]);
        let case_path = dir.join(format!("case-{f}.toml"));
        std::fs::write(
            &case_path,
            case.replace("coefficient = 0.6", &format!("coefficient = {f}")),
        )
        .unwrap();
        let o = run(&["march", case_path.to_str().unwrap(), "--json"]);
        assert!(o.status.success(), "{}", stderr(&o));
        let json: serde_json::Value = serde_json::from_slice(&o.stdout).unwrap();
        let last = json["cycles"].as_array().unwrap().last().unwrap().clone();
        let step = json["steps"].as_array().unwrap().last().unwrap().clone();
        // The same march by the same code; the JSON's numbers are read back by serde_json's
        // fast float parser, which may miss the last bit: 1e-14 relative.
        let same = |cell: &str, json: &serde_json::Value, what: &str| {
            let (got, want) = (num(cell), json.as_f64().unwrap());
            assert!(
                (got - want).abs() <= 1e-14 * want.abs(),
                "{what}: {got} vs {want}"
            );
        };
        same(&row[11], &last["energy"], "energy");
        same(&row[12], &last["max_slip_amplitude"], "max_slip_amplitude");
        let shakedown = json["shakedown_cycle"].as_u64().map(|k| k.to_string());
        assert_eq!(Some(row[13].clone()).filter(|s| !s.is_empty()), shakedown);
        let stick = step["largest_stick"].as_array().unwrap();
        same(&row[14], &stick[0], "final_stick_left");
        same(&row[15], &stick[1], "final_stick_right");
        assert!(num(&row[11]) > 0.0, "partial slip dissipates");
        assert_eq!(row[16], "2");
        same(&row[17], &json["steady_change"], "steady_change");
        assert_eq!(row[18], json["steady_converged"].to_string());
    }
}

#[test]
fn a_crack_sweep_records_verdict_and_arrest_length_as_the_crack_command() {
    // A crack-arrest map over the threshold (the crack example, coarsened): the rows take both
    // verdicts, and each equals `halfplane crack --json` on the row's case written out.
    let base = std::fs::read_to_string(example("crack.toml"))
        .unwrap()
        .replace("cells = 400", "cells = 200")
        .replace("steps_per_half = 30", "steps_per_half = 20")
        .replace("count = 20", "count = 8");
    let dir = scratch("sweep-crack");
    let spec = format!(
        "{base}[sweep]\nmode = \"grid\"\nanalysis = \"crack\"\n[sweep.vary]\n\"fatigue.threshold\" = [100.0, 260.0]\n"
    );
    let table = rows(&sweep(&dir, &spec, "crack.csv", &[]));
    assert_eq!(
        table[0][10..].join(","),
        "error,crack.verdict,crack.arrest_length"
    );
    let mut verdicts = Vec::new();
    for row in &table[1..] {
        assert!(row[10].is_empty(), "{}", row[10]);
        let case_path = dir.join(format!("case-{}.toml", row[0]));
        let threshold = format!("threshold = {}", row[0]);
        std::fs::write(
            &case_path,
            base.replacen("threshold = 160.0", &threshold, 1),
        )
        .unwrap();
        let o = run(&["crack", case_path.to_str().unwrap(), "--json"]);
        assert!(o.status.success(), "{}", stderr(&o));
        let json: serde_json::Value = serde_json::from_slice(&o.stdout).unwrap();
        assert_eq!(row[11], json["verdict"].as_str().unwrap());
        match json["arrest_length"].as_f64() {
            Some(l) => assert!((num(&row[12]) - l).abs() <= 1e-14 * l, "{} {l}", row[12]),
            None => assert!(row[12].is_empty(), "{}", row[12]),
        }
        verdicts.push(row[11].clone());
    }
    assert_eq!(verdicts, ["propagates", "arrests"]);
}

/// The number `key` holds in pretty-printed JSON `text` (its first occurrence), as written: read
/// with Rust's exact parser rather than serde_json's fast one, so a value compares bit for bit.
/// `None` for `null`.
fn json_number(text: &str, key: &str) -> Option<f64> {
    let at = text
        .find(&format!("\"{key}\": "))
        .unwrap_or_else(|| panic!("no {key} in {text}"));
    let value = text[at + key.len() + 4..]
        .split([',', '\n', '}'])
        .next()
        .unwrap()
        .trim();
    (value != "null").then(|| num(value))
}

#[test]
fn a_wear_sweep_records_the_last_checkpoint_as_the_wear_command() {
    // The partial-slip example over 1000 cycles on 200 cells, a 2 x 2 grid over the wear
    // coefficient and the cycle's Q: each row's wear columns equal the last checkpoint of
    // `halfplane wear --json` on the row's case written out, bit for bit (the same code on the
    // same case; both outputs print the shortest round-trip form). A negative coefficient fails
    // the wear run alone: its rows keep the steady columns and carry the error.
    let base = std::fs::read_to_string(example("wear-partial-slip.toml"))
        .unwrap()
        .replace("cycles = 1000000", "cycles = 1000")
        .replace("checkpoints = 7 ", "checkpoints = 4 ")
        .replace("cells = 400", "cells = 200");
    assert!(base.contains("cycles = 1000\n") && base.contains("cells = 200"));
    let dir = scratch("sweep-wear");
    let spec = format!(
        "{base}[sweep]\nmode = \"grid\"\nanalysis = \"wear\"\n[sweep.vary]\n\"wear.coefficient\" = [3e-8, 1e-7, -1e-8]\n\"cycle.point2.shear\" = [200.0, 300.0]\n"
    );
    let table = rows(&sweep(&dir, &spec, "wear.csv", &[]));
    let names = [
        "wear_volume",
        "max_depth",
        "energy_per_cycle",
        "dissipated_energy",
        "contact_left",
        "contact_right",
        "peak_pressure",
        "stick_left",
        "stick_right",
        "slip_amplitude_max",
        "displacement_amplitude",
    ];
    assert_eq!(
        table[0][11..].join(","),
        "error,wear.wear_volume,wear.max_depth,wear.energy_per_cycle,wear.dissipated_energy,\
         wear.contact_left,wear.contact_right,wear.peak_pressure,wear.stick_left,wear.stick_right,\
         wear.slip_amplitude_max,wear.displacement_amplitude,wear.simulated_cycles"
    );
    assert_eq!(table.len(), 7);
    let mut volumes = Vec::new();
    for row in &table[1..] {
        let (k, q) = (&row[0], &row[1]);
        assert_eq!(row[2], "partial-slip", "k = {k}, Q2 = {q}");
        if num(k) < 0.0 {
            assert!(
                row[11].starts_with("wear: invalid wear.coefficient = -1e-8"),
                "{}",
                row[11]
            );
            assert!(row[12..].iter().all(String::is_empty), "{row:?}");
            continue;
        }
        assert!(row[11].is_empty(), "k = {k}, Q2 = {q}: {}", row[11]);
        let case_path = dir.join(format!("case-{k}-{q}.toml"));
        let case = base
            .replace("coefficient = 3e-8", &format!("coefficient = {:?}", num(k)))
            .replace(
                "point2 = { normal = 1000.0, shear = 300.0",
                &format!("point2 = {{ normal = 1000.0, shear = {:?}", num(q)),
            );
        std::fs::write(&case_path, case).unwrap();
        let o = run(&["wear", case_path.to_str().unwrap(), "--json"]);
        assert!(o.status.success(), "{}", stderr(&o));
        let json = String::from_utf8(o.stdout).unwrap();
        let parsed: serde_json::Value = serde_json::from_str(&json).unwrap();
        let checkpoints = parsed["checkpoints"].as_array().unwrap();
        assert_eq!(checkpoints.len(), 4);
        assert_eq!(checkpoints.last().unwrap()["cycle"], 1000);
        // The last checkpoint's object is the text after the last "cycle".
        let last = &json[json.rfind("\"cycle\": ").unwrap()..];
        for (name, cell) in names.iter().zip(&row[12..23]) {
            let want = json_number(last, name);
            let got = Some(cell).filter(|c| !c.is_empty()).map(|c| num(c));
            assert_eq!(got, want, "k = {k}, Q2 = {q}: {name}");
        }
        assert_eq!(row[23], parsed["simulated_cycles"].to_string());
        assert!(num(&row[12]) > 0.0, "k = {k}, Q2 = {q}: partial slip wears");
        volumes.push(num(&row[12]));
    }
    // Rows are in grid order (the first path slowest): a larger k wears more at either Q.
    assert!(
        volumes[2] > volumes[0] && volumes[3] > volumes[1],
        "{volumes:?}"
    );
}

#[cfg(feature = "parquet")]
#[test]
fn a_wear_sweep_writes_the_same_rows_to_parquet_as_to_csv() {
    use halfplane_cli::sweep::read::{read, Values};
    use halfplane_cli::sweep::WEAR_COLUMNS;
    // Solved rows and failed ones (k < 0): every wear column read back from Parquet equals the
    // CSV's (numbers exactly, empty cells as nulls), wear.simulated_cycles included (UInt64).
    let base = std::fs::read_to_string(example("wear-partial-slip.toml"))
        .unwrap()
        .replace("cycles = 1000000", "cycles = 100")
        .replace("cells = 400", "cells = 100");
    let dir = scratch("sweep-wear-parquet");
    let spec = format!(
        "{base}[sweep]\nmode = \"grid\"\nanalysis = \"wear\"\n[sweep.vary]\n\"wear.coefficient\" = [-1e-8, 3e-8, 1e-7]\n"
    );
    sweep(&dir, &spec, "out.csv", &[]);
    sweep(&dir, &spec, "out.parquet", &[]);
    let mut columns = vec!["wear.coefficient", "error"];
    columns.extend(WEAR_COLUMNS);
    let csv = read(&dir.join("out.csv"), &columns).unwrap();
    let parquet = read(&dir.join("out.parquet"), &columns).unwrap();
    assert_eq!(csv.rows, 3);
    assert_eq!(csv.names, parquet.names);
    for (k, name) in columns.iter().enumerate() {
        match (&csv.columns[k], &parquet.columns[k]) {
            (Values::Number(a), Values::Number(b)) => {
                assert_eq!(a, b, "{name}");
                if k >= 2 {
                    assert!(
                        a[0].is_none() && a[1..].iter().all(Option::is_some),
                        "{name}: {a:?}"
                    );
                }
            }
            (Values::Text(a), Values::Text(b)) => assert_eq!(a, b, "{name}"),
            (a, b) => panic!("{name}: {a:?} vs {b:?}"),
        }
    }
}

#[cfg(feature = "plot")] // draws a figure
#[test]
fn a_crack_arrest_map_colours_the_verdicts() {
    // A crack sweep over two paths drawn by its verdict (categories, as regimes) and its arrest
    // length (a number; rows that do not arrest have none).
    let base = std::fs::read_to_string(example("crack.toml"))
        .unwrap()
        .replace("cells = 400", "cells = 100")
        .replace("steps_per_half = 30", "steps_per_half = 10")
        .replace("count = 20", "count = 6");
    let dir = scratch("sweep-crack-map");
    let spec = format!(
        "{base}[sweep]\nmode = \"grid\"\nanalysis = \"crack\"\n[sweep.vary]\n\"fatigue.threshold\" = [100.0, 260.0]\n\"crack.face_friction\" = [0.0, 0.5]\n"
    );
    sweep(&dir, &spec, "map.csv", &[]);
    let csv = dir.join("map.csv");
    let svg = dir.join("map.svg");
    let args = |color: &str| {
        vec![
            "plot".to_string(),
            "design-map".into(),
            csv.to_str().unwrap().into(),
            "-o".into(),
            svg.to_str().unwrap().into(),
            "--x".into(),
            "fatigue.threshold".into(),
            "--y".into(),
            "crack.face_friction".into(),
            "--color".into(),
            color.into(),
        ]
    };
    let a = args("crack.verdict");
    let o = run(&a.iter().map(String::as_str).collect::<Vec<_>>());
    assert!(o.status.success(), "{}", stderr(&o));
    let text = std::fs::read_to_string(&svg).unwrap();
    assert!(
        text.contains("propagates") && text.contains("arrests"),
        "legend"
    );
    let a = args("crack.arrest_length");
    let o = run(&a.iter().map(String::as_str).collect::<Vec<_>>());
    assert!(o.status.success(), "{}", stderr(&o));
    assert!(std::fs::read_to_string(&svg)
        .unwrap()
        .contains("crack arrest length (mm)"));
}

#[test]
fn a_march_sweep_runs_cycles_steady_as_the_march_command_does() {
    // cycles = "steady": each row marches until its cycle repeats and says how many it took.
    let case = format!(
        "{REFERENCE_CASE}[history]\nkind = \"cycle\"\ncycles = \"steady\"\nsteps_per_half = 10\nramp_steps = 5\n[solver]\ncells = 60\n"
    );
    let dir = scratch("sweep-march-steady");
    let spec = format!(
        "{case}[sweep]\nmode = \"grid\"\nanalysis = \"march\"\n[sweep.vary]\n\"friction.coefficient\" = [0.6, 0.9]\n"
    );
    let table = rows(&sweep(&dir, &spec, "march.csv", &[]));
    for (row, f) in table[1..].iter().zip(["0.6", "0.9"]) {
        assert!(row[10].is_empty(), "f = {f}: {}", row[10]);
        let case_path = dir.join(format!("case-{f}.toml"));
        std::fs::write(
            &case_path,
            case.replace("coefficient = 0.6", &format!("coefficient = {f}")),
        )
        .unwrap();
        let o = run(&["march", case_path.to_str().unwrap(), "--json"]);
        assert!(o.status.success(), "{}", stderr(&o));
        let json: serde_json::Value = serde_json::from_slice(&o.stdout).unwrap();
        assert_eq!(row[16], json["cycles_run"].to_string());
        assert_eq!(row[18], "true");
        assert_eq!(json["steady_converged"], true);
        let (got, want) = (num(&row[17]), json["steady_change"].as_f64().unwrap());
        assert!((got - want).abs() <= 1e-14 * want.abs(), "{got} vs {want}");
    }
}

#[test]
fn the_figure_5_spec_gives_the_library_slip_map() {
    // examples/sweep-fig5.toml shifts the Figure-5 cycle to Q1 = 0; its slip_right_1 must equal
    // the library's Figure-5 value (slip_map::right_slip_zone) of the centred cycle
    // (Q = -dQ/2 .. dQ/2), to rounding: 1e-12 of a.
    use halfplane::slip_map::right_slip_zone;
    use halfplane::{Cycle, LoadPoint};
    let dir = scratch("sweep-fig5");
    let out = dir.join("fig5.csv");
    let o = run(&[
        "sweep",
        &example("sweep-fig5.toml"),
        "-o",
        out.to_str().unwrap(),
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    let table = rows(&std::fs::read_to_string(&out).unwrap());
    let contact = halfplane::reference::hertz();
    assert!(table.len() > 500);
    for row in table[1..].iter().step_by(7) {
        let (dq, p2) = (num(&row[0]), num(&row[1]));
        let cycle = Cycle::new(
            LoadPoint::new("point1", 1000.0, -0.5 * dq, 0.0).unwrap(),
            LoadPoint::new("point2", p2, 0.5 * dq, 0.0).unwrap(),
        );
        let want = right_slip_zone(&contact, &cycle).expect("Figure 5 draws every point here");
        let got = num(&row[9]);
        assert!(
            (got - want).abs() < 1e-12,
            "dQ = {dq}, P2 = {p2}: {got} vs {want}"
        );
    }
}

#[test]
fn bad_specs_are_errors_that_name_the_problem() {
    let dir = scratch("sweep-bad");
    let spec_path = dir.join("spec.toml");
    let out = dir.join("out.csv");
    let grid = "[sweep]\nmode = \"grid\"\n[sweep.vary]\n";
    for (vary, expected) in [
        (
            "\"profile.radios\" = [1.0]",
            "unknown path \"profile.radios\"",
        ),
        (
            "\"profile.kind\" = [1.0]",
            "\"profile.kind\" is not numeric",
        ),
        (
            "\"profile.radius\" = { from = 1.0, to = 2.0, count = 0 }",
            "count = 0: must be a whole number from 1",
        ),
        (
            "\"profile.radius\" = { from = 2.0, to = 1.0, count = 3 }",
            "from must not exceed to",
        ),
        (
            "\"cycle.point2.shear\" = { from = 0.0, to = 10.0, count = 3, scale = \"log\" }",
            "cannot reach or cross zero",
        ),
        (
            "\"cycle.point1.shear\" = { from = -10.0, to = -1.0, count = 3, scale = \"log\" }",
            "cannot reach or cross zero",
        ),
    ] {
        std::fs::write(&spec_path, format!("{REFERENCE_CASE}{grid}{vary}\n")).unwrap();
        let o = run(&[
            "sweep",
            spec_path.to_str().unwrap(),
            "-o",
            out.to_str().unwrap(),
        ]);
        assert_eq!(o.status.code(), Some(2), "{vary}");
        assert!(stderr(&o).contains(expected), "{vary}: {}", stderr(&o));
        assert!(!out.exists(), "no output for a bad spec");
    }
    // A steady sweep needs [cycle]; the output's name says its format.
    std::fs::write(
        &spec_path,
        format!("{REFERENCE_CONTACT}{grid}\"profile.radius\" = [1.0]\n"),
    )
    .unwrap();
    let o = run(&[
        "sweep",
        spec_path.to_str().unwrap(),
        "-o",
        out.to_str().unwrap(),
    ]);
    assert!(
        stderr(&o).contains("missing section [cycle]"),
        "{}",
        stderr(&o)
    );
    let o = run(&["sweep", &example("sweep-fig5.toml"), "-o", "out.txt"]);
    assert!(
        stderr(&o).contains("must end in .csv or .parquet"),
        "{}",
        stderr(&o)
    );
    for shard in ["0/3", "4/3", "1/0", "x"] {
        let o = run(&[
            "sweep",
            &example("sweep-fig5.toml"),
            "-o",
            out.to_str().unwrap(),
            "--shard",
            shard,
        ]);
        assert_eq!(o.status.code(), Some(2));
        assert!(
            stderr(&o).contains("must be I/N with 1 <= I <= N"),
            "{shard}: {}",
            stderr(&o)
        );
    }
}

#[test]
fn failed_rows_carry_their_error_and_the_rest_is_solved() {
    // R from -50 to 50: negative radii fail in the library's constructor, the rest solve.
    let dir = scratch("sweep-failed");
    let spec = format!(
        "{REFERENCE_CASE}[sweep]\nmode = \"grid\"\n[sweep.vary]\n\"profile.radius\" = {{ from = -50.0, to = 50.0, count = 5 }}\n"
    );
    let table = rows(&sweep(&dir, &spec, "out.csv", &[]));
    let errors: Vec<&str> = table[1..].iter().map(|r| r[10].as_str()).collect();
    assert!(
        errors[0].contains("invalid profile.radius = -50"),
        "{errors:?}"
    );
    assert!(
        errors[1].contains("invalid profile.radius = -25"),
        "{errors:?}"
    );
    assert!(
        errors[2].contains("invalid profile.radius = 0"),
        "{errors:?}"
    );
    assert!(errors[3].is_empty() && errors[4].is_empty());
    assert_eq!(table[5][1], "partial-slip");
}

#[cfg(not(feature = "parquet"))]
#[test]
fn parquet_output_without_the_feature_says_how_to_enable_it() {
    let o = run(&["sweep", &example("sweep-fig5.toml"), "-o", "out.parquet"]);
    assert_eq!(o.status.code(), Some(2));
    assert!(stderr(&o).contains("--features parquet"), "{}", stderr(&o));
}

#[cfg(feature = "parquet")]
#[test]
fn parquet_holds_the_same_rows_as_the_csv() {
    use halfplane_cli::sweep::read::{read, Values};
    // A grid with failed rows (R <= 0), gross sliding (large Q2) and a march-free steady sweep:
    // every column read back from Parquet equals the CSV's (numbers exactly, empty cells as
    // nulls, text as written).
    let dir = scratch("sweep-parquet");
    let spec = format!(
        "{REFERENCE_CASE}[sweep]\nmode = \"grid\"\n[sweep.vary]\n\"profile.radius\" = {{ from = -50.0, to = 100.0, count = 7 }}\n\"cycle.point2.shear\" = [0.0, 250.0, 900.0]\n"
    );
    sweep(&dir, &spec, "out.csv", &[]);
    sweep(&dir, &spec, "out.parquet", &[]);
    let columns = [
        "profile.radius",
        "cycle.point2.shear",
        "regime",
        "stick_left",
        "stick_right",
        "half_width_1",
        "half_width_2",
        "slip_left_1",
        "slip_left_2",
        "slip_right_1",
        "slip_right_2",
        "error",
    ];
    let csv = read(&dir.join("out.csv"), &columns).unwrap();
    let parquet = read(&dir.join("out.parquet"), &columns).unwrap();
    assert_eq!(csv.rows, 21);
    assert_eq!(csv.names, parquet.names);
    for (k, name) in columns.iter().enumerate() {
        match (&csv.columns[k], &parquet.columns[k]) {
            (Values::Number(a), Values::Number(b)) => assert_eq!(a, b, "{name}"),
            (Values::Text(a), Values::Text(b)) => assert_eq!(a, b, "{name}"),
            (a, b) => panic!("{name}: {a:?} vs {b:?}"),
        }
    }
    assert!(
        matches!(&csv.columns[11], Values::Text(e) if e.iter().any(|e| e.contains("profile.radius")))
    );
}

#[cfg(feature = "plot")] // draws a figure
#[test]
fn design_map_draws_a_sweep_and_names_what_it_cannot_draw() {
    let dir = scratch("sweep-map");
    let spec = format!(
        "{REFERENCE_CASE}[sweep]\nmode = \"grid\"\n[sweep.vary]\n\"cycle.point2.shear\" = {{ from = 0.0, to = 800.0, count = 9 }}\n\"profile.radius\" = [20.0, 50.0, 100.0]\n\"friction.coefficient\" = [0.3, 0.6]\n"
    );
    sweep(&dir, &spec, "out.csv", &[]);
    let csv = dir.join("out.csv");
    let svg = dir.join("map.svg");
    let map = |extra: &[&str]| {
        let mut args = vec![
            "plot",
            "design-map",
            csv.to_str().unwrap(),
            "--x",
            "cycle.point2.shear",
            "--y",
            "profile.radius",
            "-o",
            svg.to_str().unwrap(),
        ];
        args.extend(extra);
        run(&args)
    };
    // f varies too: rows repeat over (x, y) until --where picks one f.
    let o = map(&[]);
    assert_eq!(o.status.code(), Some(2));
    assert!(
        stderr(&o).contains("also varies friction.coefficient") && stderr(&o).contains("--where"),
        "{}",
        stderr(&o)
    );
    for color in ["regime", "slip_right_1"] {
        let o = map(&["--where", "friction.coefficient=0.6", "--color", color]);
        assert!(o.status.success(), "{color}: {}", stderr(&o));
        let text = std::fs::read_to_string(&svg).unwrap();
        // Axes and colour bar in words with units, not the dotted paths.
        assert!(text.contains("shear load Q at point 2 (N/mm)") && text.contains("radius R (mm)"));
        assert!(
            text.contains("partial-slip") || text.contains("right slip zone at point 1 (mm)"),
            "{color}"
        );
    }
    let o = map(&[
        "--where",
        "friction.coefficient=0.6",
        "--color",
        "slip_rigth_1",
    ]);
    assert_eq!(o.status.code(), Some(2));
    assert!(
        stderr(&o).contains("no column \"slip_rigth_1\""),
        "{}",
        stderr(&o)
    );
    let o = map(&["--where", "friction.coefficient=0.45"]);
    assert!(stderr(&o).contains("no rows to draw"), "{}", stderr(&o));
}

/// `design-map` never draws a map that only looks valid: a text colour column (the `error`
/// column drew an all-grey map with exit 0) and a text cell in a numeric column (read as a
/// category per number) are errors naming the column; rows without a value (failed or sliding
/// cases) are drawn as "no value" with a warning on stderr saying how many; the same column for
/// --x and --y is named as such (it was reported as rows needing --where).
#[cfg(feature = "plot")] // draws a figure
#[test]
fn design_map_refuses_text_colours_and_says_what_it_draws_without_a_value() {
    let dir = scratch("sweep-map-text");
    let spec = format!(
        "{REFERENCE_CASE}[sweep]\nmode = \"grid\"\n[sweep.vary]\n\"cycle.point2.shear\" = {{ from = 0.0, to = 800.0, count = 9 }}\n\"profile.radius\" = [20.0, 50.0, 100.0]\n"
    );
    let csv_text = sweep(&dir, &spec, "out.csv", &[]);
    let csv = dir.join("out.csv");
    let svg = dir.join("map.svg");
    let map = |file: &Path, x: &str, y: &str, color: &str| {
        run(&[
            "plot",
            "design-map",
            file.to_str().unwrap(),
            "--x",
            x,
            "--y",
            y,
            "--color",
            color,
            "-o",
            svg.to_str().unwrap(),
        ])
    };
    let (x, y) = ("cycle.point2.shear", "profile.radius");
    let o = map(&csv, x, y, "error");
    assert_eq!(o.status.code(), Some(2), "{}", stderr(&o));
    assert!(
        stderr(&o).contains("--color error: column error") && stderr(&o).contains("holds text"),
        "{}",
        stderr(&o)
    );
    // Gross sliding at the largest shear ranges leaves slip_right_1 empty on some rows.
    let table = rows(&csv_text);
    let column = table[0].iter().position(|c| c == "slip_right_1").unwrap();
    let empty = table[1..].iter().filter(|r| r[column].is_empty()).count();
    assert!(empty > 0 && empty < table.len() - 1, "{empty} empty rows");
    let o = map(&csv, x, y, "slip_right_1");
    assert!(o.status.success(), "{}", stderr(&o));
    assert!(
        stderr(&o).contains(&format!(
            "warning: {empty} of {} rows drawn have no value of slip_right_1",
            table.len() - 1
        )),
        "{}",
        stderr(&o)
    );
    // One cell of a numeric column replaced by text: named by row and column.
    let mut edited = table.clone();
    let row = edited
        .iter()
        .position(|r| !r[column].is_empty() && r[column] != "slip_right_1");
    let row = row.unwrap();
    edited[row][column] = "oops".into();
    let bad = dir.join("edited.csv");
    let mut writer = csv::Writer::from_path(&bad).unwrap();
    edited.iter().for_each(|r| writer.write_record(r).unwrap());
    writer.flush().unwrap();
    let o = map(&bad, x, y, "slip_right_1");
    assert_eq!(o.status.code(), Some(2), "{}", stderr(&o));
    assert!(
        stderr(&o).contains(&format!("row {row} of"))
            && stderr(&o).contains("\"oops\" in column slip_right_1"),
        "{}",
        stderr(&o)
    );
    let o = map(&csv, x, x, "regime");
    assert_eq!(o.status.code(), Some(2));
    assert!(
        stderr(&o).contains("--x and --y both name \"cycle.point2.shear\"")
            && !stderr(&o).contains("--where"),
        "{}",
        stderr(&o)
    );
}

/// The command reads `HALFPLANE_NUM_THREADS` itself (the library no longer does) and refuses a bad
/// value with the error it gave before, exit 2; `--threads` takes precedence over it.
#[test]
fn the_threads_variable_is_read_by_the_command() {
    let dir = scratch("sweep-threads-variable");
    let spec_path = dir.join("spec.toml");
    let spec = format!(
        "{REFERENCE_CASE}[sweep]\nmode = \"grid\"\n[sweep.vary]\n\"friction.coefficient\" = [0.5, 0.6]\n"
    );
    std::fs::write(&spec_path, spec).unwrap();
    let out = dir.join("out.csv");
    let sweep_with = |value: &str, extra: &[&str]| {
        let mut command = std::process::Command::new(env!("CARGO_BIN_EXE_halfplane"));
        command
            .args([
                "sweep",
                spec_path.to_str().unwrap(),
                "-o",
                out.to_str().unwrap(),
            ])
            .args(extra)
            .env("HALFPLANE_NUM_THREADS", value);
        command.output().expect("run halfplane")
    };
    for (value, expected) in [
        (
            "lots",
            "invalid HALFPLANE_NUM_THREADS = \"lots\": must be a whole number of threads from 1 to 4096",
        ),
        (
            "0",
            "invalid HALFPLANE_NUM_THREADS = 0: must be a whole number from 1 to 4096",
        ),
    ] {
        let o = sweep_with(value, &[]);
        assert_eq!(o.status.code(), Some(2), "{value}: {}", stderr(&o));
        assert!(stderr(&o).contains(expected), "{value}: {}", stderr(&o));
    }
    let o = sweep_with("lots", &["--threads", "2"]);
    assert!(o.status.success(), "--threads wins: {}", stderr(&o));
    let o = sweep_with("1", &[]);
    assert!(o.status.success(), "{}", stderr(&o));
    assert_eq!(rows(&std::fs::read_to_string(&out).unwrap()).len(), 3);
}
