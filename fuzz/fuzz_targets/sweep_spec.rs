//! Sweep specifications: arbitrary UTF-8, or a valid case with a `[sweep]` section whose mode,
//! samples, seed, analysis and varied paths (lists, possibly empty, and ranges with any count and
//! scale) are fuzzed, including absurd sizes. Checks that parsing, resolving the case and the size
//! estimate never panic; that a sweep too large to write (more rows than the output limit holds
//! at the fewest bytes a row can take) or to run (a march whose largest case alone exceeds the
//! time limit) is always refused by the estimate; and, for a small accepted sweep, that its rows
//! have finite values and solve without panicking.
#![no_main]

use arbitrary::Arbitrary;
use halfplane_case::limits;
use halfplane_cli::commands::sweep::OutputFormat;
use halfplane_cli::sweep::{size, spec, template::Template};
use halfplane_fuzz::{files_are_contained, fixture_dir, Num};
use libfuzzer_sys::fuzz_target;

const CASE: &str = r#"[material]
youngs_modulus = 200000.0
poisson_ratio = 0.3
[friction]
coefficient = 0.6
[profile]
kind = "hertz"
radius = 50.0
[cycle]
point1 = { normal = 1000.0, shear = -250.0, bulk = -20.0 }
point2 = { normal = 1400.0, shear = 250.0, bulk = 20.0 }
[history]
kind = "cycle"
cycles = 1
steps_per_half = 4
ramp_steps = 2
[solver]
cells = 16
"#;

/// Paths the case has (numbers and integers), one it lacks, one that is text, one a section.
const PATHS: [&str; 12] = [
    "material.youngs_modulus",
    "material.poisson_ratio",
    "friction.coefficient",
    "profile.radius",
    "cycle.point1.normal",
    "cycle.point2.shear",
    "solver.cells",
    "history.cycles",
    "history.steps_per_half",
    "profile.kind",
    "profile.radus",
    "cycle",
];

#[derive(Debug, Arbitrary)]
enum Axis {
    List(Vec<Num>),
    Range {
        from: Num,
        to: Num,
        count: Option<u64>,
        log: Option<bool>,
    },
}

#[derive(Debug, Arbitrary)]
struct Structured {
    mode: u8,
    samples: Option<u64>,
    seed: Option<u64>,
    march: bool,
    vary: Vec<(u8, Axis)>,
    parquet: bool,
}

#[derive(Debug, Arbitrary)]
enum Input {
    Text(String),
    Spec(Structured),
}

/// A float as TOML writes it (`nan`, `inf` included).
fn toml_num(v: f64) -> String {
    toml::Value::Float(v).to_string()
}

fn text(s: &Structured) -> String {
    let mut t = String::from(CASE);
    t.push_str("[sweep]\n");
    let mode = ["grid", "random", "latin-hypercube", "sobol"][usize::from(s.mode % 4)];
    t.push_str(&format!("mode = \"{mode}\"\n"));
    if let Some(n) = s.samples {
        // TOML integers are i64: larger samples are written as they are (a parse error).
        t.push_str(&format!("samples = {n}\n"));
    }
    if let Some(n) = s.seed {
        t.push_str(&format!("seed = {n}\n"));
    }
    if s.march {
        t.push_str("analysis = \"march\"\n");
    }
    t.push_str("[sweep.vary]\n");
    for (path, axis) in s.vary.iter().take(6) {
        let path = PATHS[usize::from(*path) % PATHS.len()];
        let value = match axis {
            Axis::List(values) => {
                let values: Vec<String> = values.iter().take(8).map(|v| toml_num(v.0)).collect();
                format!("[{}]", values.join(", "))
            }
            Axis::Range {
                from,
                to,
                count,
                log,
            } => {
                let mut r = format!("{{ from = {}, to = {}", toml_num(from.0), toml_num(to.0));
                if let Some(c) = count {
                    r.push_str(&format!(", count = {c}"));
                }
                match log {
                    Some(true) => r.push_str(", scale = \"log\""),
                    Some(false) => r.push_str(", scale = \"linear\""),
                    None => {}
                }
                r + " }"
            }
        };
        t.push_str(&format!("\"{path}\" = {value}\n"));
    }
    t
}

/// The fewest output bytes a row can take (Parquet numbers, one varied field).
fn min_row_bytes() -> f64 {
    11.0 * size::PARQUET_NUMBER_BYTES
}

fuzz_target!(|input: Input| {
    let (text, format) = match &input {
        Input::Text(t) => (t.clone(), OutputFormat::Csv),
        Input::Spec(s) => (
            text(s),
            match s.parquet {
                true => OutputFormat::Parquet,
                false => OutputFormat::Csv,
            },
        ),
    };
    let dir = fixture_dir();
    if !files_are_contained(&text, dir) {
        return;
    }
    let Ok(spec) = spec::parse(&text) else {
        return;
    };
    let rows = spec.design.rows();
    let template = Template::new(&spec, dir).ok();
    let run = size::Run {
        rows,
        shard: false,
        format,
        direct: template.as_ref().is_some_and(Template::is_direct),
    };
    let checked = size::check(&spec, dir, run);
    if rows as f64 * min_row_bytes() > limits::OUTPUT_LIMIT_BYTES {
        assert!(
            checked.is_err(),
            "{rows} rows accepted by the estimate: {text}"
        );
    }
    // A march sweep whose only whole-number field varied is solver.cells, up to a valid c: its
    // rows take at least c² x 10 increments (this case's history) at the calibrated cost.
    let integers: Vec<usize> = (0..spec.varied.len())
        .filter(|&j| spec.varied[j].integer)
        .collect();
    if let ([j], spec::Analysis::March) = (integers.as_slice(), spec.analysis) {
        let c = spec.largest[*j].round();
        if spec.varied[*j].path == "solver.cells" && (8.0..=1e6).contains(&c) {
            let seconds = rows as f64 * limits::march_seconds(c as usize, 10);
            if seconds > limits::TIME_LIMIT_SECONDS {
                assert!(checked.is_err(), "{seconds} s accepted: {text}");
            }
        }
    }
    // Every row's values are defined, also the last of an absurd design.
    let mut values = vec![0.0; spec.design.axes()];
    for row in [0, rows / 2, rows - 1] {
        spec.design.values(row, &mut values);
        assert!(
            values.iter().all(|v| v.is_finite()),
            "row {row}: {values:?}"
        );
    }
    let Some(template) = template else {
        return;
    };
    if let Err(e) = &checked {
        // A refusal names the field that sets the rows and the limit.
        let message = e.to_string();
        assert!(message.contains(&spec.rows_from), "{message}");
        return;
    }
    // A small accepted sweep runs: at most 4 rows, marches on at most 32 cells and short histories.
    if rows > 4 {
        return;
    }
    for row in 0..rows {
        spec.design.values(row, &mut values);
        for (v, varied) in values.iter_mut().zip(&spec.varied) {
            if varied.integer {
                *v = v.round();
                if varied.path == "solver.cells" && *v > 32.0 {
                    return;
                }
                if varied.path.starts_with("history.") && *v > 4.0 {
                    return;
                }
            }
        }
        let _ = template.solve(&values);
    }
});
