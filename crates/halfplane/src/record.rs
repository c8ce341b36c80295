//! Recorders for the marching solver, built on the public [`march`](crate::march) API: copies of
//! the fields at chosen increments ([`FieldRecorder`], used in the observer of
//! [`march::march`](crate::march::march)), and the stick interval over the last cycle of a
//! cyclic history in the time of the steady cycle ([`MarchedCycle`]), for comparing with
//! [`evolution`](crate::evolution).
//!
//! Conventions are those of `docs/theory.md` ("Conventions" and "Time marching (`march`)"):
//! traction positive in `+x`, slip positive in the sense positive Q drives, stick kinematic (a
//! cell sticks when it does not slip in the increment).
//!
//! ```
//! use halfplane::history::{History, Ramp};
//! use halfplane::march::{march, MarchOptions};
//! use halfplane::record::{FieldRecorder, MarchedCycle};
//! use halfplane::{Contact, Friction, LoadPoint, Material, Profile};
//!
//! let contact = Contact::new(Profile::hertz(50.0)?, Material::new(200_000.0, 0.3)?, Friction::new(0.6)?);
//! let p1 = LoadPoint::new("point1", 1000.0, -250.0, -20.0)?;
//! let p2 = LoadPoint::new("point2", 1400.0, 250.0, 20.0)?;
//! let history = History::in_phase(p1, p2, 1, 10, Ramp::Proportional, 5)?;
//! let mut recorder = FieldRecorder::new(vec![10, 20]);
//! let options = MarchOptions::default().with_cells(40)?;
//! let result = march(&contact, &history, &options, |r, f| recorder.observe(r.step, f, 0.6))?;
//! assert_eq!(recorder.kept.len(), 2);
//! let cycle = MarchedCycle::last_cycle(&result, &history).unwrap();
//! assert!(cycle.points.iter().all(|&(t, _, _)| t > 0.0 && t <= 2.0));
//! # Ok::<(), halfplane::Error>(())
//! ```

use crate::history::History;
use crate::march::{Fields, MarchResult};

/// A marched history's stick intervals in the time of the steady cycle: `(t, left, right)` with
/// t in (0, 2] over the last cycle (half 1 then half 2, `t = 2k/steps_per_cycle` at its k-th
/// increment), for overlaying on the evolution (`docs/theory.md`, "Slip zones along the cycle,
/// exactly").
#[derive(Debug, Clone, PartialEq)]
pub struct MarchedCycle {
    /// `(t, left, right)` for every increment of the last cycle that has a stick interval (the
    /// largest one, [`StepReport::largest_stick`](crate::march::StepReport::largest_stick)).
    pub points: Vec<(f64, f64, f64)>,
}

impl MarchedCycle {
    /// The last cycle of `result`, marched through `history`; `None` when `history` has no
    /// cycles (rows from a table, harmonic histories without a cycle structure).
    pub fn last_cycle(result: &MarchResult, history: &History) -> Option<Self> {
        let c = history.cycles()?;
        let start = c.first_step() + (c.count() - 1) * c.steps_per_cycle();
        let points = (1..=c.steps_per_cycle())
            .filter_map(|k| {
                result
                    .steps
                    .get(start + k - 1)?
                    .largest_stick()
                    .map(|[l, r]| (2.0 * k as f64 / c.steps_per_cycle() as f64, l, r))
            })
            .collect();
        Some(Self { points })
    }
}

/// Fields of one increment, as kept by [`FieldRecorder`]: one value per cell.
#[derive(Debug, Clone, PartialEq)]
pub struct StepFields {
    /// Increment number (1-based, as [`StepReport::step`](crate::march::StepReport::step)).
    pub step: usize,
    /// Cell centres.
    pub x: Vec<f64>,
    /// `f p`, the friction limit of the traction.
    pub limit: Vec<f64>,
    /// Shear traction q (positive in `+x`).
    pub traction: Vec<f64>,
    /// Accumulated slip (positive in the sense positive Q drives).
    pub slip: Vec<f64>,
}

/// Keeps copies of the fields at chosen increments: call [`observe`](Self::observe) from the
/// observer of [`march::march`](crate::march::march).
#[derive(Debug, Clone, PartialEq, Default)]
pub struct FieldRecorder {
    /// Increments to keep (1-based).
    pub steps: Vec<usize>,
    /// What was kept, in the order the increments were made.
    pub kept: Vec<StepFields>,
}

impl FieldRecorder {
    /// A recorder of the increments `steps`, with nothing kept yet.
    pub fn new(steps: Vec<usize>) -> Self {
        Self {
            steps,
            kept: Vec::new(),
        }
    }

    /// Records `fields` if `step` is wanted; `friction` is the coefficient f of the friction
    /// limit `f p`.
    pub fn observe(&mut self, step: usize, fields: &Fields, friction: f64) {
        if self.steps.contains(&step) {
            self.kept.push(StepFields {
                step,
                x: fields.x.to_vec(),
                limit: fields.pressure.iter().map(|p| friction * p).collect(),
                traction: fields.traction.to_vec(),
                slip: fields.slip.to_vec(),
            });
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::history::Ramp;
    use crate::march::{march, MarchOptions};
    use crate::reference::hertz as contact;
    use crate::LoadPoint;

    fn history() -> History {
        History::in_phase(
            LoadPoint::new("point1", 1000.0, -250.0, -20.0).unwrap(),
            LoadPoint::new("point2", 1400.0, 250.0, 20.0).unwrap(),
            2,
            10,
            Ramp::Proportional,
            5,
        )
        .unwrap()
    }

    #[test]
    fn recorder_keeps_the_requested_steps_with_a_value_per_cell() {
        let cells = 50;
        let mut recorder = FieldRecorder::new(vec![25, 3, 10, 1000]);
        let mut pressure_at_10 = Vec::new();
        let result = march(
            &contact(),
            &history(),
            &MarchOptions::default().with_cells(cells).unwrap(),
            |r, f| {
                if r.step == 10 {
                    pressure_at_10 = f.pressure.to_vec();
                }
                recorder.observe(r.step, f, 0.6)
            },
        )
        .unwrap();
        // In the order made; a step the history does not have is simply never seen.
        let steps: Vec<usize> = recorder.kept.iter().map(|k| k.step).collect();
        assert_eq!(steps, vec![3, 10, 25]);
        for k in &recorder.kept {
            for v in [&k.x, &k.limit, &k.traction, &k.slip] {
                assert_eq!(v.len(), cells);
            }
            assert_eq!(k.x, result.x);
            // The traction never exceeds the friction limit (up to rounding).
            for (q, l) in k.traction.iter().zip(&k.limit) {
                assert!(q.abs() <= l + 1e-9 * (1.0 + l), "{q} vs {l}");
            }
        }
        let at_10 = &recorder.kept[1];
        for (l, p) in at_10.limit.iter().zip(&pressure_at_10) {
            assert_eq!(*l, 0.6 * p);
        }
    }

    #[test]
    fn last_cycle_covers_the_last_cycle_in_cycle_time() {
        let h = history();
        let result = march(
            &contact(),
            &h,
            &MarchOptions::default().with_cells(60).unwrap(),
            |_, _| {},
        )
        .unwrap();
        let m = MarchedCycle::last_cycle(&result, &h).unwrap();
        let c = h.cycles().unwrap();
        let start = c.first_step() + (c.count() - 1) * c.steps_per_cycle();
        assert!(!m.points.is_empty() && m.points.len() <= c.steps_per_cycle());
        for &(t, l, r) in &m.points {
            assert!(t > 0.0 && t <= 2.0, "{t}");
            let k = (t * c.steps_per_cycle() as f64 / 2.0).round() as usize;
            let report = &result.steps[start + k - 1];
            assert_eq!(report.largest_stick(), Some([l, r]));
            assert!(l < r && -report.half_width <= l && r <= report.half_width);
        }
    }

    #[test]
    fn last_cycle_needs_a_cyclic_history() {
        let h = History::from_rows(&[[1000.0, 0.0, 0.0]]).unwrap();
        let result = march(
            &contact(),
            &h,
            &MarchOptions::default().with_cells(20).unwrap(),
            |_, _| {},
        )
        .unwrap();
        assert_eq!(MarchedCycle::last_cycle(&result, &h), None);
    }
}
