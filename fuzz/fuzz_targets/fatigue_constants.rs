//! `[fatigue]` constants and grids: every field of the section written as a TOML float, integer,
//! string or left out (and `planes` as any text), resolved through the case parser; the resolved
//! constants then drive the critical-plane search (in-plane and 3-D) and Crossland on a short
//! arbitrary stress history. Promised: no panic; every value reported is finite, every plane
//! angle in [0, 180) and tilt in [0, 90]; Crossland's ball radius (alpha = 0) lies between half
//! the longest chord of the deviatoric path and 2 sqrt(3/8) times it (Jung's bound in 3-D).
#![no_main]

use arbitrary::Arbitrary;
use halfplane::fatigue::{self, CriticalPlanes, FatigueConstants, Planes};
use halfplane::stress::Stress;
use halfplane::Material;
use halfplane_fuzz::{fixture_dir, Num};
use libfuzzer_sys::fuzz_target;

/// A TOML value for a field.
#[derive(Debug, Arbitrary)]
enum Lit {
    Float(Num),
    Int(i64),
    Text(String),
    Missing,
}

impl Lit {
    fn line(&self, name: &str) -> String {
        let value = match self {
            Lit::Float(Num(v)) if v.is_nan() => "nan".to_string(),
            Lit::Float(Num(v)) if v.is_infinite() => if *v > 0.0 { "inf" } else { "-inf" }.into(),
            Lit::Float(Num(v)) => format!("{v:?}"),
            Lit::Int(i) => i.to_string(),
            Lit::Text(s) => format!("{s:?}"),
            Lit::Missing => return String::new(),
        };
        format!("{name} = {value}\n")
    }
}

const FIELDS: [&str; 21] = [
    "fatigue_strength",
    "fatigue_strength_exponent",
    "fatigue_ductility",
    "fatigue_ductility_exponent",
    "shear_fatigue_strength",
    "shear_fatigue_ductility",
    "fatemi_socie_k",
    "findley_k",
    "crossland_alpha",
    "yield_stress",
    "threshold",
    "endurance_range",
    "axial_fatigue_limit",
    "torsional_fatigue_limit",
    "mcdiarmid_shear_limit",
    "ultimate_strength",
    "planes",
    "nx",
    "nz",
    "width",
    "depth",
];

#[derive(Debug, Arbitrary)]
struct Input {
    fields: [Lit; 21],
    /// `planes` as one of the valid names (when the field above is not text).
    full_3d: bool,
    history: Vec<[Num; 4]>,
}

const CASE: &str = "[material]\nyoungs_modulus = 200000.0\npoisson_ratio = 0.3\n\
[friction]\ncoefficient = 0.6\n[profile]\nkind = \"hertz\"\nradius = 50.0\n\
[cycle]\npoint1 = { normal = 1000.0, shear = -300.0, bulk = -60.0 }\n\
point2 = { normal = 1000.0, shear = 300.0, bulk = 60.0 }\n\
[history]\nkind = \"cycle\"\ncycles = 2\nsteps_per_half = 4\n";

fn check(p: &CriticalPlanes, n: usize, what: &str) {
    let planes = [
        Some(p.swt),
        p.fatemi_socie,
        p.fatemi_socie_max_plane,
        p.findley,
        p.mwcm,
        p.mcdiarmid,
    ];
    for c in planes.into_iter().flatten() {
        assert!(c.value.is_finite(), "{what}: {c:?}");
        assert!((0.0..180.0).contains(&c.angle), "{what}: {c:?}");
        assert!((0.0..=90.0).contains(&c.tilt), "{what}: {c:?}");
        assert!(c.index < n.max(1), "{what}: {c:?}");
    }
    if let Some((v, i)) = p.crossland {
        assert!(
            v.is_finite() && i < n.max(1),
            "{what}: crossland {v} at {i}"
        );
    }
}

fuzz_target!(|input: Input| {
    let mut text = String::from(CASE);
    text += "[fatigue]\n";
    for (lit, name) in input.fields.iter().zip(FIELDS) {
        match (name, lit) {
            ("planes", Lit::Float(_) | Lit::Int(_)) => {
                text += if input.full_3d {
                    "planes = \"3d\"\n"
                } else {
                    "planes = \"in-plane\"\n"
                }
            }
            _ => text += &lit.line(name),
        }
    }
    let Ok(case) = halfplane_case::case::parse(&text, fixture_dir()) else {
        return;
    };
    let settings = match case.fatigue() {
        Ok(s) => s,
        Err(e) => {
            assert!(!e.to_string().is_empty());
            return;
        }
    };
    for line in settings.skipped() {
        assert!(
            line.contains(" not reported: [fatigue] does not give fatigue."),
            "{line}"
        );
    }
    // The stresses the library produces are bounded by its input range (1e30).
    let history: Vec<Stress> = input
        .history
        .iter()
        .take(8)
        .map(|s| Stress {
            sxx: s[0].0,
            szz: s[1].0,
            syy: s[2].0,
            sxz: s[3].0,
        })
        .collect();
    if history.iter().any(|s| {
        [s.sxx, s.szz, s.syy, s.sxz]
            .iter()
            .any(|v| !(v.abs() <= 1e30))
    }) {
        return;
    }
    let m = case.contact.material();
    let n = history.len();
    for planes in [Planes::InPlane, Planes::Full3d] {
        let p = fatigue::critical_planes_over(&history, &m, &settings.constants, planes);
        check(&p, n, planes.name());
    }
    // Crossland with alpha = 0: the ball radius against the half chord and Jung's bound.
    let alone = FatigueConstants::default()
        .with_crossland_alpha(0.0)
        .unwrap();
    let radius = fatigue::critical_planes(&history, &Material::new(2e5, 0.3).unwrap(), &alone)
        .crossland
        .map_or(0.0, |c| c.0);
    let dev = |s: &Stress| {
        [
            0.5 * (s.sxx - s.szz),
            s.sxz,
            (2.0 * s.syy - s.sxx - s.szz) / (2.0 * 3f64.sqrt()),
        ]
    };
    let mut chord: f64 = 0.0;
    for a in &history {
        for b in &history {
            let (u, v) = (dev(a), dev(b));
            chord = chord.max(
                ((u[0] - v[0]).powi(2) + (u[1] - v[1]).powi(2) + (u[2] - v[2]).powi(2)).sqrt(),
            );
        }
    }
    let half = 0.5 * chord;
    let slack = 1e-9 * half + 1e-300;
    assert!(
        radius >= half - slack && radius <= 2.0 * (3.0f64 / 8.0).sqrt() * half + slack,
        "ball {radius} vs half chord {half} for {history:?}"
    );
});
