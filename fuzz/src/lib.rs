//! Shared input types and result checks for the fuzz targets.
//!
//! A target passes when nothing panics. The checks here turn "an `Ok` result holds NaN or an
//! infinity where the library promises a finite value" into a panic too, so the fuzzer reports it.
//! What is promised: validated inputs are finite (LoadPoint, Material, Compliance, Friction);
//! contact half-widths are finite and > 0 (every function taking one rejects anything else);
//! pressures, intensities, stick and slip zones, criteria, energies and fields are finite;
//! `Criteria::full_stick_ratio` is documented as infinite when dP = 0 and is never NaN.

use arbitrary::{Arbitrary, Result, Unstructured};
use halfplane::asymptotic::AsymptoticSteady;
use halfplane::evolution::Evolution;
use halfplane::march::{Fields, MarchResult, StepReport};
use halfplane::{Contact, Friction, Material, Profile, SteadyState};
use std::path::{Path, PathBuf};
use std::sync::OnceLock;

/// Values that break numerical code.
pub const SPECIAL: [f64; 24] = [
    0.0,
    -0.0,
    1.0,
    -1.0,
    0.5,
    0.49,
    0.499_999_999_999_999_9,
    f64::NAN,
    f64::INFINITY,
    f64::NEG_INFINITY,
    f64::MIN_POSITIVE,
    5e-324,
    f64::MAX,
    f64::MIN,
    f64::EPSILON,
    1e-300,
    1e300,
    1e-150,
    1e150,
    64.0,
    64.000_000_000_001,
    1e-8,
    1e8,
    -1e-300,
];

/// A float: raw bits (any NaN payload, subnormals, infinities), a special value, or a
/// realistic magnitude `m * 10^e` with `|e| <= 12` (mostly positive, as most inputs must be).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Num(pub f64);

impl<'a> Arbitrary<'a> for Num {
    fn arbitrary(u: &mut Unstructured<'a>) -> Result<Self> {
        let tag: u8 = u.arbitrary()?;
        let v = match tag % 4 {
            0 => f64::from_bits(u.arbitrary()?),
            1 => SPECIAL[usize::from(u.arbitrary::<u8>()?) % SPECIAL.len()],
            _ => {
                let m: u16 = u.arbitrary()?;
                let e: i8 = u.arbitrary()?;
                let v = (1.0 + 9.0 * f64::from(m) / 65535.0) * 10f64.powi(i32::from(e % 13));
                if tag >= 0xC0 {
                    -v
                } else {
                    v
                }
            }
        };
        Ok(Num(v))
    }

    fn size_hint(_depth: usize) -> (usize, Option<usize>) {
        (1, Some(9))
    }
}

/// A profile as the library's constructors take it.
#[derive(Debug, Clone, Arbitrary)]
pub enum ProfileInput {
    Hertz(Num),
    FlatRounded(Num, Num),
    PowerLaw(Num, Num),
    /// Rows `(x, g)`; when `monotone`, x and g are running sums of the magnitudes from (0, 0),
    /// which the table validation accepts more often.
    Tabulated {
        monotone: bool,
        rows: Vec<(Num, Num)>,
        kinks: Vec<Num>,
    },
}

impl ProfileInput {
    /// The table rows as given or accumulated.
    pub fn table(monotone: bool, rows: &[(Num, Num)]) -> (Vec<f64>, Vec<f64>) {
        let rows = &rows[..rows.len().min(24)];
        if monotone {
            let (mut x, mut g) = (vec![0.0], vec![0.0]);
            for (dx, dg) in rows {
                x.push(x[x.len() - 1] + dx.0.abs());
                g.push(g[g.len() - 1] + dg.0.abs());
            }
            (x, g)
        } else {
            rows.iter().map(|(x, g)| (x.0, g.0)).unzip()
        }
    }

    /// The profile, or the library's error.
    pub fn build(&self) -> halfplane::Result<Profile> {
        match self {
            ProfileInput::Hertz(r) => Profile::hertz(r.0),
            ProfileInput::FlatRounded(b, r) => Profile::flat_rounded(b.0, r.0),
            ProfileInput::PowerLaw(c, k) => Profile::power_law(c.0, k.0),
            ProfileInput::Tabulated {
                monotone,
                rows,
                kinks,
            } => {
                let (x, g) = Self::table(*monotone, rows);
                let kinks = match (*monotone, kinks.first()) {
                    // Kinks at tabulated abscissae, picked by index, reach the kink code paths.
                    (true, Some(k)) if k.0.is_finite() => {
                        vec![x[(k.0.abs() as usize) % x.len()]]
                    }
                    _ => kinks.iter().take(4).map(|k| k.0).collect(),
                };
                Profile::tabulated(x, g, kinks)
            }
        }
    }
}

fn finite(what: &str, v: f64, context: &dyn std::fmt::Debug) {
    assert!(v.is_finite(), "{what} = {v} is not finite in {context:?}");
}

/// The contact built from fuzzed constants, checked, or `None` when the library rejects any of
/// them (a typed error is a pass).
pub fn fuzzed_contact(
    youngs_modulus: Num,
    poisson_ratio: Num,
    friction: Num,
    profile: &ProfileInput,
) -> Option<Contact> {
    let contact = Contact::new(
        profile.build().ok()?,
        Material::new(youngs_modulus.0, poisson_ratio.0).ok()?,
        Friction::new(friction.0).ok()?,
    );
    check_contact(&contact);
    Some(contact)
}

/// A contact half-width returned as `Ok`: finite and > 0.
pub fn check_half_width(a: f64, context: &dyn std::fmt::Debug) {
    assert!(
        a.is_finite() && a > 0.0,
        "half-width {a} is not finite and > 0 in {context:?}"
    );
}

/// The validated parts of a contact are finite, and so is the compliance derived from them.
pub fn check_contact(c: &Contact) {
    finite("E", c.material().youngs_modulus(), c);
    finite("nu", c.material().poisson_ratio(), c);
    finite("f", c.friction().value(), c);
    let a = c.compliance().value();
    assert!(
        a.is_finite() && a > 0.0,
        "compliance A = {a} is not finite and > 0 for {:?}",
        c.material()
    );
}

/// Every number of a steady analysis is finite (`full_stick_ratio` may be +inf when dP = 0).
pub fn check_steady(s: &SteadyState) {
    for &a in &s.half_width {
        check_half_width(a, s);
    }
    let c = &s.criteria;
    finite("friction", c.friction, s);
    // FINDINGS.md F4 (fixed by the 1e-30..1e30 input range): only full_stick_ratio may be
    // infinite, and only when dP = 0.
    for r in c.shear_ratio.iter().chain([&c.bulk_term]) {
        finite("criterion", *r, s);
        assert!(*r >= 0.0, "criterion ratio {r} in {s:?}");
    }
    assert!(
        c.full_stick_ratio >= 0.0,
        "full-stick ratio {} in {s:?}",
        c.full_stick_ratio
    );
    if let Some(z) = s.stick_zone {
        finite("stick zone left", z.left, s);
        finite("stick zone right", z.right, s);
        assert!(z.left <= z.right, "stick zone {z:?} reversed in {s:?}");
    }
    if let Some(z) = s.slip_zones {
        for v in z.left.iter().chain(&z.right) {
            finite("slip zone", *v, s);
        }
    }
}

/// True when `|Q| < f P` at both ends (FINDINGS.md F6, fixed: `asymptotic::steady` now returns
/// `GrossSliding` otherwise).
pub fn sticks_at_both_ends(contact: &Contact, cycle: &halfplane::Cycle) -> bool {
    let f = contact.friction().value();
    [cycle.low(), cycle.high()]
        .iter()
        .all(|p| p.shear().abs() < f * p.normal())
}

/// Every number of the asymptotic description is finite.
pub fn check_asymptotic(a: &AsymptoticSteady) {
    for e in &a.edges {
        check_half_width(e.half_width, a);
        finite("K_N", e.normal_intensity, a);
        for v in e.shear_intensity.iter().chain(&e.equivalent_shear) {
            finite("edge value", *v, a);
        }
    }
    for v in a
        .stick_load
        .iter()
        .chain([&a.stick_zone.left, &a.stick_zone.right])
    {
        finite("asymptotic value", *v, a);
    }
    // FINDINGS.md F5 (fixed by the input range: f K_N can no longer underflow).
    for v in a.slip_zones.iter().flatten() {
        finite("asymptotic slip zone", *v, a);
    }
}

/// Every point of an evolution is finite.
pub fn check_evolution(e: &Evolution) {
    for p in &e.points {
        check_half_width(p.half_width, p);
        for v in [p.fraction, p.stick_zone.left, p.stick_zone.right] {
            finite("evolution value", v, p);
        }
        for v in [p.asymptotic_stick_zone.left, p.asymptotic_stick_zone.right] {
            finite("asymptotic evolution value", v, p);
        }
    }
}

/// One marched increment: report and fields finite.
pub fn check_step(r: &StepReport, f: &Fields) {
    finite("energy", r.energy, r);
    finite("energy increment", r.energy_increment, r);
    assert!(
        r.half_width.is_finite() && r.half_width >= 0.0,
        "half-width {} in {r:?}",
        r.half_width
    );
    for s in &r.stick_intervals {
        finite("stick interval", s[0], r);
        finite("stick interval", s[1], r);
    }
    for field in [f.x, f.pressure, f.traction, f.slip, f.slip_increment] {
        for &v in field {
            finite("field value", v, r);
        }
    }
}

/// A whole march result: grid and per-cycle values finite.
pub fn check_march(m: &MarchResult) {
    for &x in &m.x {
        finite("cell centre", x, &m.steps.len());
    }
    for c in &m.cycles {
        finite("cycle energy", c.energy, c);
        for &v in &c.slip_range {
            finite("slip range", v, c);
        }
    }
}

/// A per-process directory holding the bundled example CSV files, for case files that refer to
/// `history.csv` and `profile.csv`.
pub fn fixture_dir() -> &'static Path {
    static DIR: OnceLock<PathBuf> = OnceLock::new();
    DIR.get_or_init(|| {
        let dir = tempfile::Builder::new()
            .prefix("halfplane-fuzz")
            .tempdir()
            .expect("temp dir")
            .keep();
        std::fs::write(
            dir.join("history.csv"),
            include_str!("../../examples/march-history.csv"),
        )
        .unwrap();
        std::fs::write(
            dir.join("profile.csv"),
            include_str!("../../examples/tabulated-profile.csv"),
        )
        .unwrap();
        dir
    })
}

/// True when every `file = ...` of the case text stays inside `dir` (or does not exist), so a
/// fuzzed case never reads a device, a FIFO or a large system file (reading those would hang or
/// exhaust memory, which is the CLI's limit handling, not the parser's robustness).
pub fn files_are_contained(text: &str, dir: &Path) -> bool {
    let Ok(table) = toml::from_str::<toml::Table>(text) else {
        return true; // the parser rejects the text before reading anything
    };
    let inside = |v: Option<&toml::Value>| match v {
        Some(toml::Value::String(s)) => {
            let path = dir.join(s);
            match path.canonicalize() {
                Ok(p) => p.starts_with(dir.canonicalize().unwrap()) && p.is_file(),
                Err(_) => !path.exists() && !path.is_symlink(),
            }
        }
        _ => true,
    };
    ["profile", "history"]
        .iter()
        .all(|s| inside(table.get(*s).and_then(|t| t.get("file"))))
}

/// Checks a resolved case and runs the cheap analyses on it: the steady state, the asymptotic
/// description and a 3-point evolution of its cycle, and the finiteness of its history. Marches
/// only short histories, on at most `max_cells` cells, so each run stays fast.
pub fn check_case(case: &halfplane_case::case::Case, max_rows: usize, max_cells: usize) {
    use halfplane::steady::analyse;
    use halfplane::{asymptotic, evolution, march, SteadyOptions};
    check_contact(&case.contact);
    if let Some(cycle) = case.cycle {
        let options = SteadyOptions::default();
        if let Ok(s) = analyse(&case.contact, &cycle, &options) {
            check_steady(&s);
        }
        if let Ok(a) = asymptotic::steady(&case.contact, &cycle) {
            if sticks_at_both_ends(&case.contact, &cycle) {
                check_asymptotic(&a);
            }
        }
        if let Ok(e) = evolution::evolve(&case.contact, &cycle, 3, &options) {
            check_evolution(&e);
        }
    }
    if let Ok(history) = case.history() {
        for p in history.loads() {
            assert!(
                p.normal().is_finite() && p.normal() > 0.0,
                "history load {p:?}"
            );
            finite("history shear", p.shear(), p);
            finite("history bulk", p.bulk(), p);
        }
        if history.loads().len() <= max_rows {
            let cells = case.solver.cells().min(max_cells);
            let Ok(options) = case.solver.with_cells(cells) else {
                return;
            };
            if let Ok(m) = march::march(&case.contact, &history, &options, check_step) {
                check_march(&m);
            }
        }
    }
}
