//! Load histories for the time-marching solver: explicit rows, an in-phase cycle between two
//! points, or harmonic components (out-of-phase loading, elliptical trajectories).
//!
//! Every history starts from zero load (nothing in contact); its first point is reached in one
//! increment, so generated histories begin with a ramp.

use crate::error::{Error, Result};
use crate::load::LoadPoint;
use std::f64::consts::PI;

/// Where the cycles of a history start and how long they are.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct CycleStructure {
    /// Index (0-based) of the first increment of the first cycle; the ramp comes before.
    pub first_step: usize,
    /// Increments per cycle.
    pub steps_per_cycle: usize,
    /// Number of cycles.
    pub count: usize,
}

/// A sequence of load points, one per increment.
#[derive(Debug, Clone, PartialEq)]
pub struct History {
    /// Loads at the end of each increment.
    pub loads: Vec<LoadPoint>,
    /// Cycle boundaries, for per-cycle outputs (`None` for an explicit list of rows).
    pub cycles: Option<CycleStructure>,
}

/// How an in-phase history reaches its first point from zero load.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Ramp {
    /// P, Q and sigma in proportion.
    Proportional,
    /// P first (Q = sigma = 0), then Q and sigma at constant P.
    NormalFirst,
}

/// `mean + amplitude sin(2 pi t + phase)`, t in cycles, phase in degrees.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Harmonic {
    /// Mean value.
    pub mean: f64,
    /// Amplitude.
    pub amplitude: f64,
    /// Phase, degrees.
    pub phase: f64,
}

impl Harmonic {
    /// The value at time `t` (cycles).
    pub fn at(&self, t: f64) -> f64 {
        self.mean + self.amplitude * (2.0 * PI * t + self.phase.to_radians()).sin()
    }
}

fn whole(field: &str, value: usize, min: usize) -> Result<usize> {
    if value >= min {
        Ok(value)
    } else {
        Err(Error::InvalidInput {
            field: field.into(),
            value: value as f64,
            valid: if min == 0 {
                "a whole number >= 0"
            } else {
                "a whole number >= 1"
            },
        })
    }
}

impl History {
    /// Explicit rows (validated: finite, P > 0); errors name the row (1-based).
    pub fn from_rows(rows: &[[f64; 3]]) -> Result<Self> {
        if rows.is_empty() {
            return Err(Error::InvalidTable {
                row: 0,
                problem: "the history has no rows".into(),
            });
        }
        let loads = rows
            .iter()
            .enumerate()
            .map(|(i, r)| LoadPoint::new(&format!("history row {}", i + 1), r[0], r[1], r[2]))
            .collect::<Result<_>>()?;
        Ok(Self {
            loads,
            cycles: None,
        })
    }

    /// A ramp of `ramp_steps` increments to `first`, then `cycles` in-phase cycles
    /// first -> second -> first with `steps_per_half` increments per half.
    pub fn in_phase(
        first: LoadPoint,
        second: LoadPoint,
        cycles: usize,
        steps_per_half: usize,
        ramp: Ramp,
        ramp_steps: usize,
    ) -> Result<Self> {
        whole("history.cycles", cycles, 1)?;
        whole("history.steps_per_half", steps_per_half, 1)?;
        whole("history.ramp_steps", ramp_steps, 1)?;
        let zero = LoadPoint {
            normal: 0.0,
            shear: 0.0,
            bulk: 0.0,
        };
        let mut loads = Vec::new();
        match ramp {
            Ramp::Proportional => loads
                .extend((1..=ramp_steps).map(|i| zero.lerp(&first, i as f64 / ramp_steps as f64))),
            Ramp::NormalFirst => {
                let pressed = LoadPoint {
                    normal: first.normal,
                    shear: 0.0,
                    bulk: 0.0,
                };
                loads.extend(
                    (1..=ramp_steps).map(|i| zero.lerp(&pressed, i as f64 / ramp_steps as f64)),
                );
                loads.extend(
                    (1..=ramp_steps).map(|i| pressed.lerp(&first, i as f64 / ramp_steps as f64)),
                );
            }
        }
        let first_step = loads.len();
        for _ in 0..cycles {
            for (from, to) in [(first, second), (second, first)] {
                loads.extend(
                    (1..=steps_per_half).map(|i| from.lerp(&to, i as f64 / steps_per_half as f64)),
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
    pub fn harmonic(
        normal: Harmonic,
        shear: Harmonic,
        bulk: Harmonic,
        cycles: usize,
        steps_per_cycle: usize,
        ramp_steps: usize,
    ) -> Result<Self> {
        whole("history.cycles", cycles, 1)?;
        whole("history.steps_per_cycle", steps_per_cycle, 2)?;
        whole("history.ramp_steps", ramp_steps, 1)?;
        for (name, h) in [
            ("history.normal", normal),
            ("history.shear", shear),
            ("history.bulk", bulk),
        ] {
            for (part, v) in [
                ("mean", h.mean),
                ("amplitude", h.amplitude),
                ("phase", h.phase),
            ] {
                crate::error::finite(&format!("{name}.{part}"), v)?;
            }
        }
        if normal.mean - normal.amplitude.abs() <= 0.0 {
            return Err(Error::InvalidInput {
                field: "history.normal.amplitude".into(),
                value: normal.amplitude,
                valid: "smaller in magnitude than history.normal.mean, so that P stays > 0",
            });
        }
        let at = |t: f64| LoadPoint {
            normal: normal.at(t),
            shear: shear.at(t),
            bulk: bulk.at(t),
        };
        let zero = LoadPoint {
            normal: 0.0,
            shear: 0.0,
            bulk: 0.0,
        };
        let start = at(0.0);
        let mut loads: Vec<LoadPoint> = (1..=ramp_steps)
            .map(|i| zero.lerp(&start, i as f64 / ramp_steps as f64))
            .collect();
        let first_step = loads.len();
        loads.extend((1..=cycles * steps_per_cycle).map(|i| at(i as f64 / steps_per_cycle as f64)));
        Ok(Self {
            loads,
            cycles: Some(CycleStructure {
                first_step,
                steps_per_cycle,
                count: cycles,
            }),
        })
    }
}
