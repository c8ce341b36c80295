//! The case of a sweep, resolved once, and the case of each row: the template's values with the
//! varied numbers put in.
//!
//! Two routes give a row its case:
//! - **direct** (the varied fields are all among the material, the friction coefficient, the
//!   profile's numbers and the cycle's loads, and the analysis is `steady`): the resolved case is
//!   kept and only the parts a varied number feeds are rebuilt, with the same library constructors
//!   in the same order as the case reader (`case::parse`), so a row gets the same values and the
//!   same error as if its case file had been written out and read;
//! - **re-read** (anything else: history, solver, a march): the number is written into the case's
//!   TOML table, which is then read as a case file. This costs tens of microseconds a row, nothing
//!   beside a march.
//!
//! A test runs both routes on the same rows and compares them.

use super::spec::{Analysis, Spec, Varied};
use crate::case::{self, Case};
use crate::report::wear::WearRow;
use crate::report::Cell;
use anyhow::{bail, Result};
use halfplane::batch::{self, MarchSummary, SteadySummary};
use halfplane::crack::Verdict;
use halfplane::{Contact, Cycle, Friction, LoadPoint, Material, Profile, Shape, SteadyOptions};
use std::borrow::Cow;
use std::path::{Path, PathBuf};
use toml::{Table, Value};

/// A number the direct route can put in.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Slot {
    YoungsModulus,
    PoissonRatio,
    Friction,
    Radius,
    LeftRadius,
    RightRadius,
    FlatHalfWidth,
    Coefficient,
    Exponent,
    /// `cycle.point{1,2}.{normal, shear, bulk, moment}`: point 0 or 1, part 0 to 3.
    Load(usize, usize),
}

fn slot(keys: &[String]) -> Option<Slot> {
    let keys: Vec<&str> = keys.iter().map(String::as_str).collect();
    Some(match keys.as_slice() {
        ["material", "youngs_modulus"] => Slot::YoungsModulus,
        ["material", "poisson_ratio"] => Slot::PoissonRatio,
        ["friction", "coefficient"] => Slot::Friction,
        ["profile", "radius"] => Slot::Radius,
        ["profile", "left_radius"] => Slot::LeftRadius,
        ["profile", "right_radius"] => Slot::RightRadius,
        ["profile", "flat_half_width"] => Slot::FlatHalfWidth,
        ["profile", "coefficient"] => Slot::Coefficient,
        ["profile", "exponent"] => Slot::Exponent,
        ["cycle", point, part] => {
            let p = ["point1", "point2"].iter().position(|n| n == point)?;
            let q = ["normal", "shear", "bulk", "moment"]
                .iter()
                .position(|n| n == part)?;
            Slot::Load(p, q)
        }
        _ => return None,
    })
}

/// What one row computed: the summaries that succeeded and, if anything failed, why.
#[derive(Debug, Clone, PartialEq)]
pub struct Outcome {
    /// The steady state (absent when the case could not be built, the analysis failed, or a march
    /// sweep's case has no `[cycle]`).
    pub steady: Option<SteadySummary>,
    /// The march (march sweeps only; absent when it failed).
    pub march: Option<MarchSummary>,
    /// The crack's verdict (crack sweeps only; absent when it failed).
    pub crack: Option<CrackSummary>,
    /// The wear run's last checkpoint (wear sweeps only; absent when it failed).
    pub wear: Option<WearSummary>,
    /// Empty when the row succeeded; otherwise the error (in a march sweep, prefixed by the
    /// analysis that failed, `steady:` or `march:`, joined by `; `).
    pub error: String,
}

/// A crack analysis in the two values a crack-arrest map needs.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct CrackSummary {
    /// `arrests`, `propagates` or `no-growth`.
    pub verdict: Verdict,
    /// The arrest length when it arrests.
    pub arrest_length: Option<f64>,
}

/// A wear run (`halfplane wear`) in its last checkpoint, the cycle `[wear] cycles`, and the
/// cycles it marched.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct WearSummary {
    /// `wear.wear_volume` to `wear.displacement_amplitude`: the wear report's columns after `cycle`
    /// ([`WearRow::COLUMNS`]), `None` where the report leaves a cell empty (the stick ends in
    /// gross sliding).
    numbers: [Option<f64>; WEAR_NUMBERS],
    /// Cycles marched (the others were jumped over).
    pub simulated_cycles: usize,
}

/// The wear report's columns a wear sweep records: all but `cycle`.
const WEAR_NUMBERS: usize = WearRow::COLUMNS.len() - 1;

impl WearSummary {
    /// The numbers of `wear.wear_volume` to `wear.displacement_amplitude`, in column order (the
    /// stick ends `None` in gross sliding).
    pub fn numbers(&self) -> [Option<f64>; WEAR_NUMBERS] {
        self.numbers
    }
}

/// The resolved case of a sweep and how each row's case is made from it.
#[derive(Debug, Clone)]
pub struct Template {
    table: Table,
    dir: PathBuf,
    varied: Vec<Varied>,
    analysis: Analysis,
    base: Case,
    /// The direct route's slots (one per varied field) and the case's cycle.
    direct: Option<(Vec<Slot>, Cycle)>,
}

impl Template {
    /// Resolves the spec's case (it must be a valid case on its own: the varied fields hold
    /// placeholder values) and checks that it has what the analysis needs.
    pub fn new(spec: &Spec, dir: &Path) -> Result<Self> {
        let text = toml::to_string(&spec.case)?;
        let base = case::parse(&text, dir)
            .map_err(|e| e.context("the spec without [sweep] must be a valid case"))?;
        match spec.analysis {
            Analysis::Steady if base.cycle.is_none() => bail!(
                "missing section [cycle]: a steady sweep analyses the case's cycle (for a march sweep set analysis = \"march\" in [sweep])"
            ),
            Analysis::March => {
                base.march_history()?;
            }
            Analysis::Crack => {
                base.crack()?;
                base.fatigue()?;
                base.history()?;
            }
            Analysis::Wear => {
                // Marches the ramp once, so a case `halfplane wear` would refuse (a history of
                // more than one cycle, no [wear]) is refused before the first row.
                base.worn_march(&base.wear()?, None)?;
            }
            _ => {}
        }
        let slots: Option<Vec<Slot>> = match spec.analysis {
            Analysis::Steady => spec.varied.iter().map(|v| slot(&v.keys)).collect(),
            Analysis::March | Analysis::Crack | Analysis::Wear => None,
        };
        let direct = slots.zip(base.cycle);
        Ok(Self {
            table: spec.case.clone(),
            dir: dir.to_path_buf(),
            varied: spec.varied.clone(),
            analysis: spec.analysis,
            base,
            direct,
        })
    }

    /// Forces the re-read route (for tests comparing the two).
    pub fn reread(mut self) -> Self {
        self.direct = None;
        self
    }

    /// Whether rows take the direct route.
    pub fn is_direct(&self) -> bool {
        self.direct.is_some()
    }

    /// Runs the analysis of the row whose varied fields take `values` (in the spec's order; an
    /// integer field's value must already be whole).
    pub fn solve(&self, values: &[f64]) -> Outcome {
        match &self.direct {
            Some((slots, cycle)) => {
                let result =
                    self.direct_case(slots, *cycle, values)
                        .and_then(|(contact, cycle)| {
                            batch::steady_summary(&contact, &cycle, &SteadyOptions::default())
                        });
                match result {
                    Ok(summary) => Outcome {
                        steady: Some(summary),
                        march: None,
                        crack: None,
                        wear: None,
                        error: String::new(),
                    },
                    Err(e) => failed(e.to_string()),
                }
            }
            None => match self.reread_case(values) {
                Ok(case) => self.analyse(&case),
                Err(e) => failed(format!("{e:#}")),
            },
        }
    }

    /// The row's contact and cycle, rebuilt from the resolved case where a varied number feeds
    /// them: material, friction, profile, then the points, as `case::parse` builds them.
    fn direct_case(
        &self,
        slots: &[Slot],
        cycle: Cycle,
        values: &[f64],
    ) -> halfplane::Result<(Cow<'_, Contact>, Cycle)> {
        let base = &self.base.contact;
        let (mut e, mut nu) = (
            base.material().youngs_modulus(),
            base.material().poisson_ratio(),
        );
        let mut f = base.friction().value();
        let mut shape = base.profile().shape().clone();
        // A flat-rounded pad's two radii (equal unless written as left_radius/right_radius).
        let mut radii = base.profile().edge_radii();
        let (p1, p2) = cycle.as_given();
        let mut loads = [p1, p2].map(|p| [p.normal(), p.shear(), p.bulk(), p.moment()]);
        let (mut material, mut friction, mut profile, mut points) = (false, false, false, false);
        for (slot, &v) in slots.iter().zip(values) {
            match (slot, &mut shape) {
                (Slot::YoungsModulus, _) => (e, material) = (v, true),
                (Slot::PoissonRatio, _) => (nu, material) = (v, true),
                (Slot::Friction, _) => (f, friction) = (v, true),
                (Slot::Radius, Shape::Hertz { radius })
                | (
                    Slot::Radius,
                    Shape::FlatRounded {
                        edge_radius: radius,
                        ..
                    },
                ) => {
                    (*radius, profile) = (v, true);
                    radii = radii.map(|_| (v, v));
                }
                (Slot::LeftRadius, Shape::FlatRounded { .. }) => {
                    (radii, profile) = (radii.map(|(_, r)| (v, r)), true)
                }
                (Slot::RightRadius, Shape::FlatRounded { .. }) => {
                    (radii, profile) = (radii.map(|(l, _)| (l, v)), true)
                }
                (
                    Slot::FlatHalfWidth,
                    Shape::FlatRounded {
                        flat_half_width, ..
                    },
                ) => (*flat_half_width, profile) = (v, true),
                (Slot::Coefficient, Shape::PowerLaw { coefficient, .. }) => {
                    (*coefficient, profile) = (v, true)
                }
                (Slot::Exponent, Shape::PowerLaw { exponent, .. }) => {
                    (*exponent, profile) = (v, true)
                }
                (Slot::Load(p, q), _) => (loads[*p][*q], points) = (v, true),
                // The case reader rejects a profile field its kind does not use, so the
                // template's case (already read) has none.
                _ => {}
            }
        }
        let two_radii = !base.profile().is_symmetric()
            || slots
                .iter()
                .any(|s| matches!(s, Slot::LeftRadius | Slot::RightRadius));
        let contact = if material || friction || profile {
            let material = match material {
                true => Material::new(e, nu)?,
                false => base.material(),
            };
            let friction = match friction {
                true => Friction::new(f)?,
                false => base.friction(),
            };
            let profile = match (profile, shape) {
                (true, Shape::Hertz { radius }) => Profile::hertz(radius)?,
                (
                    true,
                    Shape::FlatRounded {
                        flat_half_width, ..
                    },
                ) => match radii {
                    // As the case reader: two radii when the case writes two (so varies them).
                    Some((left, right)) if two_radii => {
                        Profile::flat_rounded_asymmetric(flat_half_width, left, right)?
                    }
                    Some((radius, _)) => Profile::flat_rounded(flat_half_width, radius)?,
                    None => base.profile().clone(),
                },
                (
                    true,
                    Shape::PowerLaw {
                        coefficient,
                        exponent,
                    },
                ) => Profile::power_law(coefficient, exponent)?,
                _ => base.profile().clone(),
            };
            Cow::Owned(Contact::new(profile, material, friction))
        } else {
            Cow::Borrowed(base)
        };
        let cycle = match points {
            true => {
                let [a, b] = loads;
                Cycle::new(
                    LoadPoint::new("cycle.point1", a[0], a[1], a[2])?
                        .with_moment("cycle.point1", a[3])?,
                    LoadPoint::new("cycle.point2", b[0], b[1], b[2])?
                        .with_moment("cycle.point2", b[3])?,
                )
            }
            false => cycle,
        };
        Ok((contact, cycle))
    }

    /// The row's case, read from the case table with the varied numbers written in.
    fn reread_case(&self, values: &[f64]) -> Result<Case> {
        let mut table = self.table.clone();
        for (varied, &v) in self.varied.iter().zip(values) {
            set(&mut table, &varied.keys, number(v, varied.integer));
        }
        case::parse(&toml::to_string(&table)?, &self.dir)
    }

    /// The analyses of a case read for the row.
    fn analyse(&self, case: &Case) -> Outcome {
        let options = SteadyOptions::default();
        let steady = case
            .cycle
            .map(|cycle| batch::steady_summary(&case.contact, &cycle, &options));
        match self.analysis {
            Analysis::Steady => match steady {
                Some(Ok(summary)) => Outcome {
                    steady: Some(summary),
                    march: None,
                    crack: None,
                    wear: None,
                    error: String::new(),
                },
                Some(Err(e)) => failed(e.to_string()),
                // Template::new requires [cycle] of a steady sweep, and rows keep the sections.
                None => failed("missing section [cycle]".into()),
            },
            Analysis::March => {
                let mut errors = Vec::new();
                let steady = kept(steady, &mut errors);
                let march = case.march_history().and_then(|(history, until)| {
                    Ok(batch::march_summary(
                        &case.contact,
                        &history,
                        &case.solver,
                        &case.steady(),
                        until.is_some(),
                    )?)
                });
                let march = match march {
                    Ok(m) => Some(m),
                    Err(e) => {
                        errors.push(format!("march: {e:#}"));
                        None
                    }
                };
                Outcome {
                    steady,
                    march,
                    crack: None,
                    wear: None,
                    error: errors.join("; "),
                }
            }
            Analysis::Crack => {
                let mut errors = Vec::new();
                let steady = kept(steady, &mut errors);
                let crack = crack_summary(case);
                let crack = match crack {
                    Ok(c) => Some(c),
                    Err(e) => {
                        errors.push(format!("crack: {e:#}"));
                        None
                    }
                };
                Outcome {
                    steady,
                    march: None,
                    crack,
                    wear: None,
                    error: errors.join("; "),
                }
            }
            Analysis::Wear => {
                let mut errors = Vec::new();
                let steady = kept(steady, &mut errors);
                let wear = match wear_summary(case) {
                    Ok(w) => Some(w),
                    Err(e) => {
                        errors.push(format!("wear: {e:#}"));
                        None
                    }
                };
                Outcome {
                    steady,
                    march: None,
                    crack: None,
                    wear,
                    error: errors.join("; "),
                }
            }
        }
    }
}

/// The steady summary of a march or crack row, its error (if any) added to `errors` as
/// `steady: ...`.
fn kept(
    steady: Option<halfplane::Result<SteadySummary>>,
    errors: &mut Vec<String>,
) -> Option<SteadySummary> {
    match steady? {
        Ok(s) => Some(s),
        Err(e) => {
            errors.push(format!("steady: {e}"));
            None
        }
    }
}

/// `halfplane crack` on a case read for the row: its verdict and arrest length.
fn crack_summary(case: &Case) -> Result<CrackSummary> {
    let options = case.crack()?;
    let constants = case.fatigue()?.constants;
    let history = case.history()?;
    let result =
        halfplane::crack::analyse(&case.contact, &history, &case.solver, &constants, &options)?;
    Ok(CrackSummary {
        verdict: result.verdict,
        arrest_length: result.arrest_length,
    })
}

/// `halfplane wear` on a case read for the row: its last checkpoint and the cycles it marched.
/// A run that stops part way is the row's error (its earlier checkpoints are not recorded).
fn wear_summary(case: &Case) -> Result<WearSummary> {
    let settings = case.wear()?;
    let mut worn = case.worn_march(&settings, None)?;
    let result = halfplane::wear::run(&mut worn, &settings.options, |_| {})?;
    let last = result
        .checkpoints
        .last()
        .ok_or_else(|| anyhow::anyhow!("the wear run reached no checkpoint"))?;
    // The numbers `halfplane wear` reports for the checkpoint, read through its own columns.
    let row = WearRow::new(last);
    let numbers = std::array::from_fn(|k| match (WearRow::COLUMNS[k + 1].get)(&row) {
        Cell::Num(v) => Some(v),
        _ => None,
    });
    Ok(WearSummary {
        numbers,
        simulated_cycles: result.simulated_cycles,
    })
}

fn failed(error: String) -> Outcome {
    Outcome {
        steady: None,
        march: None,
        crack: None,
        wear: None,
        error,
    }
}

/// The TOML value of a varied number: an integer where the case writes one.
pub(super) fn number(v: f64, integer: bool) -> Value {
    if integer && v.abs() < 9e18 {
        Value::Integer(v as i64)
    } else {
        Value::Float(v)
    }
}

/// Writes `value` at `keys` (which the spec checked exist in the table).
pub(super) fn set(table: &mut Table, keys: &[String], value: Value) {
    let Some((last, parents)) = keys.split_last() else {
        return;
    };
    let mut t = table;
    for key in parents {
        match t.get_mut(key) {
            Some(Value::Table(inner)) => t = inner,
            _ => return,
        }
    }
    t.insert(last.clone(), value);
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::sweep::spec;

    #[test]
    fn wear_columns_are_the_wear_reports_after_cycle() {
        // The numbers come from the report's columns by position: the names must line up.
        let report: Vec<String> = WearRow::COLUMNS[1..]
            .iter()
            .map(|c| format!("wear.{}", c.key))
            .collect();
        assert_eq!(report, crate::sweep::WEAR_COLUMNS[..WEAR_NUMBERS]);
        assert_eq!(
            crate::sweep::WEAR_COLUMNS[WEAR_NUMBERS..],
            ["wear.simulated_cycles"]
        );
    }

    /// A random sweep over every number the direct route puts in, over ranges that include
    /// invalid values (negative radius, Poisson's ratio above 0.5, negative P) and gross sliding.
    fn spec(profile: &str, vary_profile: &str) -> Spec {
        let text = format!(
            r#"[material]
youngs_modulus = 200000.0
poisson_ratio = 0.3
[friction]
coefficient = 0.6
[profile]
{profile}
[cycle]
point1 = {{ normal = 1000.0, shear = -250.0, bulk = -20.0 }}
point2 = {{ normal = 1400.0, shear = 250.0, bulk = 20.0, moment = 0.0 }}
[sweep]
mode = "random"
samples = 300
seed = 11
[sweep.vary]
"material.youngs_modulus" = {{ from = 1e5, to = 3e5 }}
"material.poisson_ratio" = {{ from = 0.2, to = 0.55 }}
"friction.coefficient" = {{ from = 0.2, to = 0.9 }}
{vary_profile}
"cycle.point1.normal" = {{ from = -100.0, to = 2000.0 }}
"cycle.point2.shear" = {{ from = 0.0, to = 900.0 }}
"cycle.point1.bulk" = [-30.0, 0.0, 30.0]
"#
        );
        spec::parse(&text).expect("valid spec")
    }

    #[test]
    fn the_direct_route_agrees_with_reading_each_case() {
        let cases = [
            (
                "kind = \"hertz\"\nradius = 50.0",
                "\"profile.radius\" = { from = -10.0, to = 100.0 }",
            ),
            (
                "kind = \"flat-rounded\"\nflat_half_width = 0.3\nradius = 50.0",
                "\"profile.flat_half_width\" = { from = -0.1, to = 0.6 }\n\"profile.radius\" = { from = 10.0, to = 100.0, scale = \"log\" }",
            ),
            (
                "kind = \"power-law\"\ncoefficient = 0.01\nexponent = 2.5",
                "\"profile.coefficient\" = { from = 0.001, to = 0.1, scale = \"log\" }\n\"profile.exponent\" = { from = 0.5, to = 4.0 }",
            ),
            (
                "kind = \"flat-rounded\"\nflat_half_width = 0.3\nleft_radius = 40.0\nright_radius = 60.0",
                "\"profile.left_radius\" = { from = -5.0, to = 80.0 }\n\"profile.right_radius\" = { from = 20.0, to = 90.0 }\n\"cycle.point2.moment\" = { from = -400.0, to = 400.0 }",
            ),
        ];
        for (profile, vary) in cases {
            let spec = spec(profile, vary);
            let direct = Template::new(&spec, Path::new(".")).expect("valid template");
            assert!(direct.is_direct(), "{profile}: every path is a direct one");
            let reread = direct.clone().reread();
            let (mut failed, mut solved) = (0, 0);
            let mut values = vec![0.0; spec.design.axes()];
            for row in 0..spec.design.rows() {
                spec.design.values(row, &mut values);
                let (a, b) = (direct.solve(&values), reread.solve(&values));
                assert_eq!(a, b, "{profile}, row {row}: {values:?}");
                if a.error.is_empty() {
                    solved += 1;
                } else {
                    failed += 1;
                }
            }
            // Both kinds of row occur, so both the values and the errors were compared.
            assert!(
                solved > 30 && failed > 30,
                "{profile}: {solved} solved, {failed} failed"
            );
        }
    }
}
