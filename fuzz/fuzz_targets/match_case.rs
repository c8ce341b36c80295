//! `halfplane match` from a prototype case file to the test case it writes: a valid case file
//! whose numbers are fuzzed (material, friction, any analytic profile, the cycle, an optional
//! in-phase `[history]` carried over), and fuzzed test options (profile kind and geometry,
//! E, nu, f overrides, either mode), through the command's own path (`MatchConfig::from_case`,
//! `compute`, the table and JSON reports). On success: every compared value is finite, and the
//! test case text reads back (`case::parse`) to exactly the test cycle and contact the report
//! describes, whose steady analysis agrees with the report's regime.
#![no_main]

use arbitrary::Arbitrary;
use halfplane::steady::{self, SteadyOptions};
use halfplane_case::case;
use halfplane_case::matching::{compute, MatchConfig, TestOptions, TestProfile};
use halfplane_case::report::matching::MatchReportOut;
use halfplane_fuzz::{check_steady, Num};
use libfuzzer_sys::fuzz_target;
use std::fmt::Write;
use std::path::{Path, PathBuf};

#[derive(Debug, Arbitrary)]
enum ProtoProfile {
    Hertz(Num),
    FlatRounded(Num, Num),
    PowerLaw(Num, Num),
}

#[derive(Debug, Arbitrary)]
struct Input {
    youngs_modulus: Num,
    poisson_ratio: Num,
    friction: Num,
    profile: ProtoProfile,
    points: [[Num; 3]; 2],
    history: bool,
    test_kind: u8,
    radius: Option<Num>,
    flat_half_width: Option<Num>,
    coefficient: Option<Num>,
    exponent: Option<Num>,
    test_youngs_modulus: Option<Num>,
    test_poisson_ratio: Option<Num>,
    test_friction: Option<Num>,
    exact: bool,
}

/// A float as TOML writes it (nan and inf included), so every fuzzed value reaches the checks.
fn lit(v: Num) -> String {
    match v.0 {
        x if x.is_nan() => "nan".into(),
        x if x.is_infinite() => if x > 0.0 { "inf" } else { "-inf" }.into(),
        x => format!("{x:?}"),
    }
}

fn prototype_text(i: &Input) -> String {
    let mut o = String::new();
    let _ = writeln!(
        o,
        "[material]\nyoungs_modulus = {}\npoisson_ratio = {}\n[friction]\ncoefficient = {}\n[profile]",
        lit(i.youngs_modulus),
        lit(i.poisson_ratio),
        lit(i.friction)
    );
    let _ = match i.profile {
        ProtoProfile::Hertz(r) => writeln!(o, "kind = \"hertz\"\nradius = {}", lit(r)),
        ProtoProfile::FlatRounded(b, r) => writeln!(
            o,
            "kind = \"flat-rounded\"\nflat_half_width = {}\nradius = {}",
            lit(b),
            lit(r)
        ),
        ProtoProfile::PowerLaw(c, k) => writeln!(
            o,
            "kind = \"power-law\"\ncoefficient = {}\nexponent = {}",
            lit(c),
            lit(k)
        ),
    };
    let _ = writeln!(o, "[cycle]");
    for (name, p) in ["point1", "point2"].iter().zip(&i.points) {
        let _ = writeln!(
            o,
            "{name} = {{ normal = {}, shear = {}, bulk = {} }}",
            lit(p[0]),
            lit(p[1]),
            lit(p[2])
        );
    }
    if i.history {
        o.push_str("[history]\nkind = \"cycle\"\ncycles = 1\nsteps_per_half = 4\nramp_steps = 2\n");
    }
    o
}

fn finite(what: &str, v: f64, context: &dyn std::fmt::Debug) {
    assert!(v.is_finite(), "{what} = {v} is not finite in {context:?}");
}

fuzz_target!(|input: Input| {
    let text = prototype_text(&input);
    let dir = Path::new(".");
    let Ok(prototype) = case::parse(&text, dir) else {
        return;
    };
    let test = TestOptions {
        profile: [
            TestProfile::Hertz,
            TestProfile::FlatRounded,
            TestProfile::PowerLaw,
        ][usize::from(input.test_kind % 3)],
        radius: input.radius.map(|v| v.0),
        flat_half_width: input.flat_half_width.map(|v| v.0),
        coefficient: input.coefficient.map(|v| v.0),
        exponent: input.exponent.map(|v| v.0),
        youngs_modulus: input.test_youngs_modulus.map(|v| v.0),
        poisson_ratio: input.test_poisson_ratio.map(|v| v.0),
        friction: input.test_friction.map(|v| v.0),
        exact: input.exact,
    };
    let Ok(config) = MatchConfig::from_case(
        prototype,
        &text,
        PathBuf::from("prototype.toml"),
        &test,
        PathBuf::from("test.toml"),
    ) else {
        return;
    };
    let matched = match compute(&config) {
        Ok(m) => m,
        Err(e) => {
            assert!(!format!("{e:#}").is_empty());
            return;
        }
    };
    let r = &matched.report;
    for side in [&r.prototype, &r.test] {
        check_steady(&side.steady);
        for p in [&side.edges.first, &side.edges.second] {
            finite("K_N", p.normal_intensity, &input);
            finite("a", p.half_width, &input);
        }
    }
    for c in [
        &r.normal_intensity.first,
        &r.normal_intensity.second,
        &r.edge_motion,
    ] {
        finite("prototype value", c.prototype, &input);
        finite("test value", c.test, &input);
    }
    // The reports render (the table and the JSON the command prints).
    let out = MatchReportOut::new(r, &config, &matched.notes);
    assert!(!out.table().is_empty());
    out.json().expect("the report serialises");
    // The written test case reads back to exactly the test the report describes.
    let back = case::parse(&matched.test_case, dir).unwrap_or_else(|e| {
        panic!(
            "the test case does not read back: {e:#}\n{}",
            matched.test_case
        )
    });
    let cycle = back.cycle().expect("the test case has a [cycle]");
    assert_eq!(
        cycle.as_given(),
        r.test.cycle.as_given(),
        "{}",
        matched.test_case
    );
    assert_eq!(back.contact, r.test.contact, "{}", matched.test_case);
    let again = steady::analyse(&back.contact, &cycle, &SteadyOptions::default())
        .expect("the test case's steady analysis succeeds as in the report");
    assert_eq!(again.regime, r.test.steady.regime);
});
