//! Load histories for the time-marching solver: explicit rows, an in-phase cycle between two
//! points, or harmonic components (out-of-phase loading, elliptical trajectories).
//!
//! Every history starts from zero load (nothing in contact); its first point is reached in one
//! increment, so generated histories begin with a ramp.

use crate::error::{physical, physical_positive, Error, Result};
use crate::load::LoadPoint;
use std::f64::consts::PI;

/// The most increments a history may have. A history is held in memory with one report per
/// increment (about 100 bytes each, plus the stick intervals), so 10 million increments take a
/// few GB; and at 400 cells a march takes about 0.1 ms per increment, so longer runs would take
/// hours. Longer studies are split into several runs.
pub const MAX_INCREMENTS: usize = 10_000_000;

/// When a march through a cyclic history may stop: once the cycle repeats (`history.cycles =
/// "steady"` in a case file), rather than after a number of cycles fixed in advance.
///
/// The cycle repeats when no cell's peak-to-peak slip range over a cycle differs from the
/// previous cycle's by more than `tolerance` times `A f P_max` (the compliance, the friction
/// coefficient and the largest normal load of the history: the scale of slip that
/// `solver.slip_tolerance` also uses). The default, 1e-10, is the default slip-labelling
/// threshold: a cell whose slip still shakes down by more than that in a cycle could still be
/// labelled slipping in it, so stopping earlier could misplace the reported stick zone (on the
/// case of `docs/convergence.md`, "The steady cycle", a tolerance relative to the largest slip
/// range would need to be below 1e-7 to tell the shaking-down cells apart).
///
/// Valid by construction: `max_cycles` from 2 (two cycles are compared) to
/// [`Steady::MAX_CYCLES`], `tolerance` with 0 < t < 1.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Steady {
    max_cycles: usize,
    tolerance: f64,
}

impl Default for Steady {
    fn default() -> Self {
        Self {
            max_cycles: Self::DEFAULT_MAX_CYCLES,
            tolerance: Self::DEFAULT_TOLERANCE,
        }
    }
}

impl Steady {
    /// The default most cycles: a shakedown by 10x per cycle reaches the default tolerance in
    /// about ten, and 1000 cycles of 100 increments take seconds at 400 cells.
    pub const DEFAULT_MAX_CYCLES: usize = 1000;
    /// The most cycles a steady march may be allowed; the increments are also limited by
    /// [`MAX_INCREMENTS`].
    pub const MAX_CYCLES: usize = MAX_INCREMENTS / 2;
    /// The default tolerance, a fraction of `A f P_max` (the default slip-labelling threshold).
    pub const DEFAULT_TOLERANCE: f64 = 1e-10;

    /// Sets the most cycles (`history.max_cycles`); a march that has not repeated its cycle by
    /// then is [`Error::NotSteady`].
    pub fn with_max_cycles(mut self, max_cycles: usize) -> Result<Self> {
        if !(2..=Self::MAX_CYCLES).contains(&max_cycles) {
            return Err(Error::InvalidCount {
                field: "history.max_cycles".into(),
                value: max_cycles as u64,
                min: 2,
                max: Self::MAX_CYCLES as u64,
            });
        }
        self.max_cycles = max_cycles;
        Ok(self)
    }

    /// Sets the tolerance (`history.steady_tolerance`), a fraction of `A f P_max`.
    pub fn with_tolerance(mut self, tolerance: f64) -> Result<Self> {
        if !(tolerance.is_finite() && tolerance > 0.0 && tolerance < 1.0) {
            return Err(Error::InvalidInput {
                field: "history.steady_tolerance".into(),
                value: tolerance,
                valid: "a number with 0 < t < 1 (a fraction of A f P)",
            });
        }
        self.tolerance = tolerance;
        Ok(self)
    }

    /// The most cycles.
    pub fn max_cycles(&self) -> usize {
        self.max_cycles
    }

    /// The tolerance on the change of the per-cell slip range, a fraction of `A f P_max`.
    pub fn tolerance(&self) -> f64 {
        self.tolerance
    }

    /// True when a change between consecutive cycles (as [`MarchResult::steady_change`]
    /// gives it) is within the tolerance.
    ///
    /// [`MarchResult::steady_change`]: crate::march::MarchResult::steady_change
    pub fn is_met(&self, change: f64) -> bool {
        change <= self.tolerance
    }
}

/// Where the cycles of a history start and how long they are.
///
/// Valid by construction (only [`History`] builds one): `steps_per_cycle >= 2`, `count >= 1`,
/// and the cycles fit in the history.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct CycleStructure {
    first_step: usize,
    steps_per_cycle: usize,
    count: usize,
}

impl CycleStructure {
    /// Index (0-based) of the first increment of the first cycle; the ramp comes before.
    pub fn first_step(&self) -> usize {
        self.first_step
    }

    /// Increments per cycle.
    pub fn steps_per_cycle(&self) -> usize {
        self.steps_per_cycle
    }

    /// Number of cycles.
    pub fn count(&self) -> usize {
        self.count
    }

    /// The 0-based cycle that increment `k` (0-based) belongs to, if any (`None` in the ramp).
    pub fn cycle_of(&self, k: usize) -> Option<usize> {
        let c = k.checked_sub(self.first_step)? / self.steps_per_cycle;
        (c < self.count).then_some(c)
    }

    /// True when increment `k` (0-based) is the first of its cycle.
    pub fn starts_cycle(&self, k: usize) -> bool {
        self.cycle_of(k).is_some() && (k - self.first_step).is_multiple_of(self.steps_per_cycle)
    }

    /// True when increment `k` (0-based) is the last of its cycle.
    pub fn ends_cycle(&self, k: usize) -> bool {
        self.cycle_of(k).is_some() && (k + 1 - self.first_step).is_multiple_of(self.steps_per_cycle)
    }
}

/// A sequence of load points, one per increment.
///
/// Valid by construction: at least one and at most [`MAX_INCREMENTS`] loads, each a valid
/// [`LoadPoint`]; the cycle structure, if any, fits the loads.
#[derive(Debug, Clone, PartialEq)]
pub struct History {
    loads: Vec<LoadPoint>,
    cycles: Option<CycleStructure>,
}

/// How an in-phase history reaches its first point from zero load.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Ramp {
    /// P, Q and sigma in proportion.
    Proportional,
    /// P (with its moment M) first, Q = sigma = 0; then Q and sigma at constant P and M.
    NormalFirst,
}

/// `mean + amplitude sin(2 pi t + phase)`, t in cycles, phase in degrees.
///
/// Valid by construction: all three are finite, of magnitude at most 1e30.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Harmonic {
    mean: f64,
    amplitude: f64,
    phase: f64,
}

impl Harmonic {
    /// Validates that all three are finite. `name` prefixes the field names in errors (for
    /// example `history.normal`).
    pub fn new(name: &str, mean: f64, amplitude: f64, phase: f64) -> Result<Self> {
        physical(&format!("{name}.mean"), mean)?;
        physical(&format!("{name}.amplitude"), amplitude)?;
        physical(&format!("{name}.phase"), phase)?;
        Ok(Self {
            mean,
            amplitude,
            phase,
        })
    }

    /// Mean value.
    pub fn mean(&self) -> f64 {
        self.mean
    }

    /// Amplitude.
    pub fn amplitude(&self) -> f64 {
        self.amplitude
    }

    /// Phase, degrees.
    pub fn phase(&self) -> f64 {
        self.phase
    }

    /// The value at time `t` (cycles).
    pub fn at(&self, t: f64) -> f64 {
        self.mean + self.amplitude * (2.0 * PI * t + self.phase.to_radians()).sin()
    }
}

fn count(field: &str, value: usize, min: usize) -> Result<usize> {
    if value >= min && value <= MAX_INCREMENTS {
        Ok(value)
    } else {
        Err(Error::InvalidCount {
            field: field.into(),
            value: value as u64,
            min: min as u64,
            max: MAX_INCREMENTS as u64,
        })
    }
}

/// The number of increments a generated history would have, checked against
/// [`MAX_INCREMENTS`]: `parts` lists (count, field) pairs whose sum is the total, where each
/// count is a product of whole numbers.
fn total_increments(parts: &[(Option<usize>, &str)]) -> Result<usize> {
    let mut total = 0usize;
    for &(part, field) in parts {
        total = part
            .and_then(|p| total.checked_add(p))
            .filter(|&t| t <= MAX_INCREMENTS)
            .ok_or_else(|| Error::TooManyIncrements {
                field: field.into(),
                max: MAX_INCREMENTS,
            })?;
    }
    Ok(total)
}

impl History {
    /// Explicit rows `[normal, shear, bulk]` (no moment), validated as [`LoadPoint`]s are; an
    /// invalid value is [`Error::InvalidRow`] with its 1-based row and column.
    pub fn from_rows(rows: &[[f64; 3]]) -> Result<Self> {
        let with_moment: Vec<[f64; 4]> = rows.iter().map(|r| [r[0], r[1], r[2], 0.0]).collect();
        Self::from_moment_rows(&with_moment)
    }

    /// Explicit rows `[normal, shear, bulk, moment]`, validated as [`LoadPoint`]s are; an
    /// invalid value is [`Error::InvalidRow`] with its 1-based row and column.
    pub fn from_moment_rows(rows: &[[f64; 4]]) -> Result<Self> {
        if rows.is_empty() {
            return Err(Error::EmptyTable { what: "history" });
        }
        if rows.len() > MAX_INCREMENTS {
            return Err(Error::TooManyIncrements {
                field: "history rows".into(),
                max: MAX_INCREMENTS,
            });
        }
        type Check = fn(&str, f64) -> Result<f64>;
        let checks: [(&'static str, Check); 4] = [
            ("normal", physical_positive),
            ("shear", physical),
            ("bulk", physical),
            ("moment", physical),
        ];
        for (i, r) in rows.iter().enumerate() {
            for ((column, check), &value) in checks.iter().zip(r) {
                if let Err(Error::InvalidInput { valid, .. }) = check(column, value) {
                    return Err(Error::InvalidRow {
                        table: "history",
                        row: i + 1,
                        column,
                        value,
                        valid,
                    });
                }
            }
        }
        let loads = rows
            .iter()
            .map(|r| {
                LoadPoint::new("history row", r[0], r[1], r[2])?.with_moment("history row", r[3])
            })
            .collect::<Result<_>>()?;
        Ok(Self {
            loads,
            cycles: None,
        })
    }

    /// A ramp of `ramp_steps` increments to `first`, then `cycles` in-phase cycles
    /// first -> second -> first with `steps_per_half` increments per half.
    ///
    /// Errors: a count below 1, or a history longer than [`MAX_INCREMENTS`].
    pub fn in_phase(
        first: LoadPoint,
        second: LoadPoint,
        cycles: usize,
        steps_per_half: usize,
        ramp: Ramp,
        ramp_steps: usize,
    ) -> Result<Self> {
        count("history.cycles", cycles, 1)?;
        count("history.steps_per_half", steps_per_half, 1)?;
        count("history.ramp_steps", ramp_steps, 1)?;
        let ramps = match ramp {
            Ramp::Proportional => 1,
            Ramp::NormalFirst => 2,
        };
        let per_cycle = steps_per_half.checked_mul(2);
        total_increments(&[
            (Some(ramps * ramp_steps), "history.ramp_steps"),
            (
                per_cycle.and_then(|c| c.checked_mul(cycles)),
                "history.cycles x 2 history.steps_per_half",
            ),
        ])?;
        let fraction = |i: usize, of: usize| i as f64 / of as f64;
        let mut loads = Vec::new();
        match ramp {
            Ramp::Proportional => {
                loads.extend((1..=ramp_steps).map(|i| first.scaled(fraction(i, ramp_steps))))
            }
            Ramp::NormalFirst => {
                let pressed = LoadPoint::new("history.ramp", first.normal(), 0.0, 0.0)?
                    .with_moment("history.ramp", first.moment())?;
                loads.extend((1..=ramp_steps).map(|i| pressed.scaled(fraction(i, ramp_steps))));
                loads.extend(
                    (1..=ramp_steps).map(|i| pressed.lerp(&first, fraction(i, ramp_steps))),
                );
            }
        }
        let first_step = loads.len();
        for _ in 0..cycles {
            for (from, to) in [(first, second), (second, first)] {
                loads.extend(
                    (1..=steps_per_half).map(|i| from.lerp(&to, fraction(i, steps_per_half))),
                );
            }
        }
        Ok(Self {
            loads,
            cycles: Some(CycleStructure {
                first_step,
                steps_per_cycle: 2 * steps_per_half,
                count: cycles,
            }),
        })
    }

    /// Harmonic P, Q, sigma: a proportional ramp of `ramp_steps` increments to the values at
    /// t = 0, then `cycles` cycles of `steps_per_cycle` increments. P must stay > 0.
    ///
    /// Errors: counts below their minimum (`steps_per_cycle >= 2`), a history longer than
    /// [`MAX_INCREMENTS`], or a normal amplitude that would make P reach zero.
    pub fn harmonic(
        normal: Harmonic,
        shear: Harmonic,
        bulk: Harmonic,
        cycles: usize,
        steps_per_cycle: usize,
        ramp_steps: usize,
    ) -> Result<Self> {
        let no_moment = Harmonic::new("history.moment", 0.0, 0.0, 0.0)?;
        Self::harmonic_with_moment(
            [normal, shear, bulk, no_moment],
            cycles,
            steps_per_cycle,
            ramp_steps,
        )
    }

    /// [`History::harmonic`] with a harmonic moment too: `[normal, shear, bulk, moment]`.
    pub fn harmonic_with_moment(
        loads: [Harmonic; 4],
        cycles: usize,
        steps_per_cycle: usize,
        ramp_steps: usize,
    ) -> Result<Self> {
        let [normal, shear, bulk, moment] = loads;
        count("history.cycles", cycles, 1)?;
        count("history.steps_per_cycle", steps_per_cycle, 2)?;
        count("history.ramp_steps", ramp_steps, 1)?;
        let cycle_steps = total_increments(&[
            (Some(ramp_steps), "history.ramp_steps"),
            (
                steps_per_cycle.checked_mul(cycles),
                "history.cycles x history.steps_per_cycle",
            ),
        ])? - ramp_steps;
        if normal.mean - normal.amplitude.abs() <= 0.0 {
            return Err(Error::InvalidInput {
                field: "history.normal.amplitude".into(),
                value: normal.amplitude,
                valid: "smaller in magnitude than history.normal.mean, so that P stays > 0",
            });
        }
        let at = |t: f64| {
            LoadPoint::new("history", normal.at(t), shear.at(t), bulk.at(t))?
                .with_moment("history", moment.at(t))
        };
        let start = at(0.0)?;
        let mut loads: Vec<LoadPoint> = (1..=ramp_steps)
            .map(|i| start.scaled(i as f64 / ramp_steps as f64))
            .collect();
        let first_step = loads.len();
        for i in 1..=cycle_steps {
            loads.push(at(i as f64 / steps_per_cycle as f64)?);
        }
        Ok(Self {
            loads,
            cycles: Some(CycleStructure {
                first_step,
                steps_per_cycle,
                count: cycles,
            }),
        })
    }

    /// Loads at the end of each increment.
    pub fn loads(&self) -> &[LoadPoint] {
        &self.loads
    }

    /// Cycle boundaries, for per-cycle outputs (`None` for an explicit list of rows).
    pub fn cycles(&self) -> Option<CycleStructure> {
        self.cycles
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn point(p: f64, q: f64) -> LoadPoint {
        LoadPoint::new("point", p, q, 0.0).unwrap()
    }

    #[test]
    fn huge_counts_are_errors_not_overflows_or_huge_allocations() {
        let (a, b) = (point(1000.0, -100.0), point(1200.0, 100.0));
        let too_long = |r: Result<History>| {
            matches!(
                r,
                Err(Error::TooManyIncrements { .. }) | Err(Error::InvalidCount { .. })
            )
        };
        // steps_per_half * 2 overflows usize; cycles * steps overflows; each alone is too large.
        assert!(too_long(History::in_phase(
            a,
            b,
            1,
            usize::MAX / 2 + 1,
            Ramp::Proportional,
            1
        )));
        assert!(too_long(History::in_phase(
            a,
            b,
            1 << 40,
            1 << 40,
            Ramp::Proportional,
            1
        )));
        assert!(too_long(History::in_phase(
            a,
            b,
            1,
            10,
            Ramp::NormalFirst,
            usize::MAX
        )));
        assert!(too_long(History::in_phase(
            a,
            b,
            5_000_000,
            2,
            Ramp::Proportional,
            1
        )));
        let h = |m: f64| Harmonic::new("history.normal", m, 0.0, 0.0).unwrap();
        // 2^62 cycles of 4 steps: the product wraps to 0 in u64 arithmetic.
        assert!(too_long(History::harmonic(
            h(1000.0),
            h(0.0),
            h(0.0),
            1 << 62,
            4,
            1
        )));
        assert!(matches!(
            History::harmonic(h(1000.0), h(0.0), h(0.0), 1, 0, 1),
            Err(Error::InvalidCount { min: 2, .. })
        ));
        // The limit itself is reachable.
        let longest = History::in_phase(a, b, 1, MAX_INCREMENTS / 2 - 1, Ramp::Proportional, 2);
        assert_eq!(longest.map(|h| h.loads().len()), Ok(MAX_INCREMENTS));
    }

    #[test]
    fn cycle_structure_locates_every_increment() {
        let history = History::in_phase(
            point(1000.0, -100.0),
            point(1200.0, 100.0),
            3,
            4,
            Ramp::NormalFirst,
            2,
        )
        .unwrap();
        let s = history.cycles().unwrap();
        assert_eq!((s.first_step(), s.steps_per_cycle(), s.count()), (4, 8, 3));
        assert_eq!(history.loads().len(), 4 + 24);
        assert_eq!(s.cycle_of(3), None, "the ramp belongs to no cycle");
        assert_eq!(s.cycle_of(4), Some(0));
        assert_eq!(s.cycle_of(27), Some(2));
        assert_eq!(s.cycle_of(28), None, "past the last cycle");
        assert!(s.starts_cycle(12) && s.ends_cycle(11) && !s.ends_cycle(12));
        // Each cycle ends back at point 1, exactly.
        assert_eq!(history.loads()[11], point(1000.0, -100.0));
    }

    #[test]
    fn harmonic_values_must_be_finite() {
        for bad in [f64::NAN, f64::INFINITY] {
            assert!(matches!(
                Harmonic::new("history.shear", 0.0, bad, 0.0),
                Err(Error::InvalidInput { field, .. }) if field == "history.shear.amplitude"
            ));
        }
    }
}
