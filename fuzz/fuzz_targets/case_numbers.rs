//! The case-file parser on valid case files whose numbers (and counts, and table rows) are
//! mutated: every field is written as a TOML float, integer, nan or inf, or left out. The
//! resolved case is then analysed (steady, asymptotic, evolution) and short histories marched.
#![no_main]

use arbitrary::Arbitrary;
use halfplane_fuzz::{check_case, Num, ProfileInput};
use libfuzzer_sys::fuzz_target;
use std::fmt::Write;
use std::sync::OnceLock;

/// A TOML value for a numeric field.
#[derive(Debug, Arbitrary)]
enum Lit {
    Float(Num),
    Int(i64),
    Count(Count),
    Missing,
}

/// Counts around the limits: small ones, the increment limit (10^7) and overflowing products.
#[derive(Debug, Arbitrary)]
struct Count(u8);

const COUNTS: [i64; 14] = [
    0,
    1,
    2,
    3,
    5,
    8,
    20,
    -1,
    10_000_000,
    10_000_001,
    4_294_967_296,
    i64::MAX,
    i64::MIN,
    3_037_000_500,
];

impl Lit {
    /// `name = value` line, or nothing when missing.
    fn line(&self, name: &str) -> String {
        let value = match self {
            Lit::Float(Num(v)) if v.is_nan() => "nan".to_string(),
            Lit::Float(Num(v)) if v.is_infinite() => {
                if *v > 0.0 { "inf" } else { "-inf" }.to_string()
            }
            Lit::Float(Num(v)) => format!("{v:?}"),
            Lit::Int(i) => i.to_string(),
            Lit::Count(Count(c)) => COUNTS[usize::from(*c) % COUNTS.len()].to_string(),
            Lit::Missing => return String::new(),
        };
        format!("{name} = {value}\n")
    }

    /// `name = value, ` inside an inline table.
    fn inline(&self, name: &str) -> String {
        let l = self.line(name);
        if l.is_empty() {
            l
        } else {
            format!("{}, ", l.trim_end())
        }
    }
}

#[derive(Debug, Arbitrary)]
enum HistoryInput {
    None,
    Cycle {
        cycles: Lit,
        steps_per_half: Lit,
        proportional: bool,
        ramp_steps: Lit,
    },
    Harmonic {
        normal: [Lit; 3],
        shear: Option<[Lit; 3]>,
        bulk: Option<[Lit; 3]>,
        cycles: Lit,
        steps_per_cycle: Lit,
        ramp_steps: Lit,
    },
    File(Vec<[Num; 3]>),
}

#[derive(Debug, Arbitrary)]
struct Input {
    material: [Lit; 2],
    friction: Lit,
    profile: ProfileInput,
    kinds_swapped: bool,
    cycle: Option<[[Lit; 3]; 2]>,
    history: HistoryInput,
    cells: Lit,
    slip_tolerance: Lit,
}

fn dir() -> &'static std::path::Path {
    static DIR: OnceLock<std::path::PathBuf> = OnceLock::new();
    DIR.get_or_init(|| tempfile::tempdir().unwrap().keep())
}

fn csv(header: &str, rows: impl Iterator<Item = Vec<f64>>) -> String {
    let mut s = format!("{header}\n");
    for r in rows {
        let cells: Vec<String> = r.iter().map(|v| format!("{v:?}")).collect();
        s.push_str(&cells.join(","));
        s.push('\n');
    }
    s
}

fuzz_target!(|input: Input| {
    let dir = dir();
    let mut t = String::new();
    let _ = write!(
        t,
        "[material]\n{}{}\n[friction]\n{}\n[profile]\n",
        input.material[0].line("youngs_modulus"),
        input.material[1].line("poisson_ratio"),
        input.friction.line("coefficient")
    );
    let num = |v: &Num| Lit::Float(*v);
    match &input.profile {
        ProfileInput::Hertz(r) => {
            t += "kind = \"hertz\"\n";
            t += &num(r).line("radius");
        }
        ProfileInput::FlatRounded(b, r) => {
            // kinds_swapped: a field the kind does not use must be rejected, not ignored.
            t += if input.kinds_swapped {
                "kind = \"hertz\"\n"
            } else {
                "kind = \"flat-rounded\"\n"
            };
            t += &num(b).line("flat_half_width");
            t += &num(r).line("radius");
        }
        ProfileInput::PowerLaw(c, k) => {
            t += "kind = \"power-law\"\n";
            t += &num(c).line("coefficient");
            t += &num(k).line("exponent");
        }
        ProfileInput::Tabulated {
            monotone,
            rows,
            kinks,
        } => {
            let (x, g) = ProfileInput::table(*monotone, rows);
            let text = csv("x,g", x.iter().zip(&g).map(|(x, g)| vec![*x, *g]));
            std::fs::write(dir.join("profile.csv"), text).unwrap();
            t += "kind = \"tabulated\"\nfile = \"profile.csv\"\n";
            let kinks: Vec<String> = kinks
                .iter()
                .take(4)
                .map(|k| Lit::Float(*k).line("k").trim_end()["k = ".len()..].to_string())
                .collect();
            if !kinks.is_empty() {
                let _ = writeln!(t, "kinks = [{}]", kinks.join(", "));
            }
        }
    }
    if let Some(points) = &input.cycle {
        t += "[cycle]\n";
        for (name, p) in ["point1", "point2"].iter().zip(points) {
            let _ = writeln!(
                t,
                "{name} = {{ {}{}{}}}",
                p[0].inline("normal"),
                p[1].inline("shear"),
                p[2].inline("bulk")
            );
        }
        // Inline tables may not end with ", ".
        t = t.replace(", }", " }");
    }
    match &input.history {
        HistoryInput::None => {}
        HistoryInput::Cycle {
            cycles,
            steps_per_half,
            proportional,
            ramp_steps,
        } => {
            t += "[history]\nkind = \"cycle\"\n";
            t += &cycles.line("cycles");
            t += &steps_per_half.line("steps_per_half");
            if *proportional {
                t += "ramp = \"proportional\"\n";
            }
            t += &ramp_steps.line("ramp_steps");
        }
        HistoryInput::Harmonic {
            normal,
            shear,
            bulk,
            cycles,
            steps_per_cycle,
            ramp_steps,
        } => {
            t += "[history]\nkind = \"harmonic\"\n";
            t += &cycles.line("cycles");
            t += &steps_per_cycle.line("steps_per_cycle");
            t += &ramp_steps.line("ramp_steps");
            for (name, h) in [
                ("normal", Some(normal)),
                ("shear", shear.as_ref()),
                ("bulk", bulk.as_ref()),
            ] {
                if let Some(h) = h {
                    let _ = writeln!(
                        t,
                        "{name} = {{ {}{}{}}}",
                        h[0].inline("mean"),
                        h[1].inline("amplitude"),
                        h[2].inline("phase")
                    );
                }
            }
            t = t.replace(", }", " }");
        }
        HistoryInput::File(rows) => {
            let text = csv(
                "normal,shear,bulk",
                rows.iter()
                    .take(64)
                    .map(|r| r.iter().map(|v| v.0).collect()),
            );
            std::fs::write(dir.join("history.csv"), text).unwrap();
            t += "[history]\nfile = \"history.csv\"\n";
        }
    }
    let solver = input.cells.line("cells") + &input.slip_tolerance.line("slip_tolerance");
    if !solver.is_empty() {
        t += "[solver]\n";
        t += &solver;
    }
    if let Ok(case) = halfplane_case::case::parse(&t, dir) {
        check_case(&case, 64, 16);
    }
});
