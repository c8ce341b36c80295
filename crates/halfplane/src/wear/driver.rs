//! The cycle-jumping loop (docs/wear.md, "Cycle jumping"): march a cycle over the current
//! gap, extrapolate its wear over as many cycles as keep the largest added depth below the
//! bound and the worn profile stable, stop at every checkpoint.

use super::{Checkpoint, CheckpointFields, Law, WearOptions, WearResult};
use crate::error::{Error, Result};
use crate::fatigue::CycleTractions;

/// The stability number of a jump, `J max_i(m_i) K` (at most this): a jump of J cycles is a
/// forward-Euler step of the depth, `d += J m p(d)` with `m_i` = wear per cycle per unit pressure
/// at cell i, and the pressure answers a depth change by `-K` times it at most (the zigzag mode,
/// [`WornCycle::pressure_stiffness`]). So that mode is multiplied by `1 - J m K` per jump: it
/// grows once that passes -1 (the profile oscillates cell to cell, pressures alternating with
/// zero: measured at 800 cells and a depth bound of 0.02, docs/wear.md) and at 1 it is damped in
/// one jump, with no overshoot.
const STABILITY: f64 = 1.0;

/// What one marched cycle over a worn gap gives the wear loop, one value per cell where a
/// vector.
#[derive(Debug, Clone, PartialEq)]
pub struct CycleWear {
    /// `integral p |ds|` over the cycle at each cell (the mean pressure of each sub-step times
    /// its slip: the march's own energy quadrature without f).
    pub pressure_slip: Vec<f64>,
    /// f, which turns it into dissipated energy density.
    pub friction: f64,
    /// Pressure at the end of the cycle.
    pub pressure: Vec<f64>,
    /// Shear traction at the end of the cycle.
    pub traction: Vec<f64>,
    /// Slip range over the cycle.
    pub slip_range: Vec<f64>,
    /// The cells that did not slip in the cycle, as an interval (`None` when every cell
    /// slipped: gross sliding).
    pub stick: Option<[f64; 2]>,
    /// The contact's ends at the end of the cycle.
    pub contact: [f64; 2],
    /// The fretting loop: the cycle's start, then every increment and slide.
    pub fretting_loop: Vec<LoopPoint>,
}

/// A point of a fretting loop.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LoopPoint {
    /// The shear load Q.
    pub shear: f64,
    /// The bodies' relative tangential displacement ([`crate::march::RelativeDisplacement`],
    /// at the march's loop datum).
    pub relative_displacement: f64,
}

/// A march of successive load cycles over a gap that wears: [`crate::march::Worn`].
pub trait WornCycle {
    /// The cell centres.
    fn x(&self) -> &[f64];
    /// The cell width.
    fn width(&self) -> f64;
    /// The elastic approach of the unworn contact (the bound on a jump's depth is a fraction
    /// of it).
    fn elastic_approach(&self) -> f64;
    /// The largest pressure change per unit depth change of the gap on this grid: the stiffness
    /// of its stiffest (cell-to-cell) mode, `pi / (A lambda_min)` with `lambda_min` the cell
    /// matrix's smallest eigenvalue (`march::kernel::smallest_eigenvalue_bound`). It bounds
    /// the jumps (docs/wear.md, "Cycle jumping").
    fn pressure_stiffness(&self) -> f64;
    /// Marches the next cycle with `depth` (both bodies, one value per cell) added to the gap.
    fn cycle(&mut self, depth: &[f64]) -> Result<CycleWear>;
    /// The tractions of every increment of the last cycle, when the march keeps them
    /// ([`crate::march::Worn::record_tractions`]); asked for at checkpoints only. None by
    /// default.
    fn tractions(&mut self) -> Result<Option<CycleTractions>> {
        Ok(None)
    }
}

/// Runs `options.cycles()` physical cycles: each simulated cycle marched by `worn`, its wear
/// extrapolated over a jump (the largest added depth at most `max_depth_increment` times the
/// elastic approach, and at most the cycles that keep the worn profile stable, `J m K <= 1`;
/// at least one cycle, ending on every checkpoint), each checkpoint handed to `observer` as it
/// is reached.
///
/// Wear per cycle at a cell: Archard `k integral p |ds|`, energy `alpha f integral p |ds|`; the
/// volume is their sum times the cell width (both bodies).
///
/// # Errors
/// [`Error::WearStopped`] naming the physical cycle whose march failed (the contact opened
/// entirely, left the grid, slid where it may not), with the failure; the checkpoints before it
/// have reached the observer.
pub fn run(
    worn: &mut impl WornCycle,
    options: &WearOptions,
    mut observer: impl FnMut(&Checkpoint),
) -> Result<WearResult> {
    let n = worn.x().len();
    let width = worn.width();
    let approach = worn.elastic_approach();
    let stiffness = worn.pressure_stiffness();
    let bound = options.max_depth_increment() * approach;
    let mut depth = vec![0.0; n];
    let (mut cycle, mut volume, mut energy) = (0u64, 0.0, 0.0);
    let mut simulated = 0;
    let mut checkpoints = Vec::with_capacity(options.checkpoints().len());
    for &target in options.checkpoints() {
        while cycle < target {
            let w = worn.cycle(&depth).map_err(|e| Error::WearStopped {
                cycle: cycle + 1,
                cause: Box::new(e),
            })?;
            simulated += 1;
            let factor = match options.law() {
                Law::Archard => options.coefficient(),
                Law::Energy => options.coefficient() * w.friction,
            };
            let rate: Vec<f64> = w.pressure_slip.iter().map(|ps| factor * ps).collect();
            let largest = rate.iter().copied().fold(0.0, f64::max);
            let per_cycle = sensitivity(&rate, &w.pressure) * stiffness;
            if per_cycle > 2.0 {
                // Even single cycles would make the profile oscillate: no jump rule helps.
                return Err(Error::WearStopped {
                    cycle: cycle + 1,
                    cause: Box::new(Error::InvalidInput {
                        field: "wear.coefficient".into(),
                        value: options.coefficient(),
                        valid: "a wear per cycle the grid can follow: one cycle's wear changes the pressure of neighbouring cells by more than twice itself (the worn profile would oscillate cell to cell); use fewer cells (solver.cells) or a smaller coefficient",
                    }),
                });
            }
            let cycles_within = |per: f64, allowed: f64| match per > 0.0 {
                true => (allowed / per).floor() as u64,
                false => u64::MAX,
            };
            let room = target - cycle;
            let jump = cycles_within(largest, bound)
                .min(cycles_within(per_cycle, STABILITY))
                .clamp(1, room);
            let j = jump as f64;
            for (d, r) in depth.iter_mut().zip(&rate) {
                *d += j * r;
            }
            let cycle_energy = w.friction * width * w.pressure_slip.iter().sum::<f64>();
            volume += j * width * rate.iter().sum::<f64>();
            energy += j * cycle_energy;
            cycle += jump;
            if cycle == target {
                let point = checkpoint(&w, &depth, options.share(), worn.x(), cycle);
                let tractions = worn.tractions().map_err(|e| Error::WearStopped {
                    cycle,
                    cause: Box::new(e),
                })?;
                let point = Checkpoint {
                    wear_volume: volume,
                    energy_per_cycle: cycle_energy,
                    dissipated_energy: energy,
                    tractions,
                    ..point
                };
                observer(&point);
                checkpoints.push(point);
            }
        }
    }
    Ok(WearResult {
        checkpoints,
        simulated_cycles: simulated,
        elastic_approach: approach,
    })
}

/// The largest wear per cycle per unit pressure, `m_i = rate_i / p_i` over the loaded cells (the
/// rate is linear in the pressure, which is constant along the cycle).
fn sensitivity(rate: &[f64], pressure: &[f64]) -> f64 {
    rate.iter()
        .zip(pressure)
        .filter(|(_, p)| **p > 0.0)
        .map(|(r, p)| r / p)
        .fold(0.0, f64::max)
}

/// The checkpoint's per-cycle quantities and fields (the totals are the caller's).
fn checkpoint(w: &CycleWear, depth: &[f64], share: f64, x: &[f64], cycle: u64) -> Checkpoint {
    Checkpoint {
        cycle,
        wear_volume: 0.0,
        max_depth: depth.iter().copied().fold(0.0, f64::max),
        energy_per_cycle: 0.0,
        dissipated_energy: 0.0,
        contact: w.contact,
        peak_pressure: w.pressure.iter().copied().fold(0.0, f64::max),
        stick: w.stick,
        slip_amplitude_max: 0.5 * w.slip_range.iter().copied().fold(0.0, f64::max),
        displacement_amplitude: {
            let d = w.fretting_loop.iter().map(|p| p.relative_displacement);
            let (lo, hi) = d.fold((f64::INFINITY, f64::NEG_INFINITY), |(l, h), v| {
                (l.min(v), h.max(v))
            });
            if lo <= hi {
                0.5 * (hi - lo)
            } else {
                0.0
            }
        },
        fretting_loop: w.fretting_loop.clone(),
        fields: CheckpointFields {
            x: x.to_vec(),
            depth: depth.to_vec(),
            depth_pad: depth.iter().map(|d| share * d).collect(),
            depth_specimen: depth.iter().map(|d| (1.0 - share) * d).collect(),
            pressure: w.pressure.clone(),
            traction: w.traction.clone(),
            slip_range: w.slip_range.clone(),
        },
        tractions: None,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A stand-in march: every cycle slips the same `p |ds|` profile, so the exact wear after N
    /// cycles is N times one cycle's, whatever the jumps.
    struct Steady {
        x: Vec<f64>,
        profile: Vec<f64>,
        cycles: usize,
        stiffness: f64,
    }

    impl WornCycle for Steady {
        fn x(&self) -> &[f64] {
            &self.x
        }
        fn width(&self) -> f64 {
            self.x[1] - self.x[0]
        }
        fn elastic_approach(&self) -> f64 {
            1e-3
        }
        fn pressure_stiffness(&self) -> f64 {
            self.stiffness
        }
        fn cycle(&mut self, _: &[f64]) -> Result<CycleWear> {
            self.cycles += 1;
            Ok(CycleWear {
                pressure_slip: self.profile.clone(),
                friction: 0.5,
                pressure: vec![1.0; self.x.len()],
                traction: vec![0.0; self.x.len()],
                slip_range: vec![0.0; self.x.len()],
                stick: None,
                contact: [-1.0, 1.0],
                fretting_loop: Vec::new(),
            })
        }
    }

    #[test]
    fn jumps_land_on_every_checkpoint_and_keep_the_totals_exact() {
        // With a wear that does not change, the volume and energy after N cycles are N times one
        // cycle's (to rounding: 1e-12), the depth bound caps every jump (2% of the 1e-3 approach
        // against at most 1e-9 x 0.5 x 180 per cycle: jumps of 222 cycles), and each checkpoint
        // is reached exactly.
        let x: Vec<f64> = (0..10).map(|i| 0.1 * i as f64).collect();
        let profile: Vec<f64> = (0..10).map(|i| 20.0 * i as f64).collect();
        let mut worn = Steady {
            x,
            profile: profile.clone(),
            cycles: 0,
            // Soft enough that the depth bound decides every jump.
            stiffness: 1e-3,
        };
        let options = WearOptions::new(Law::Energy, 1e-9, 1_000, &[1, 7, 500])
            .unwrap()
            .with_max_depth_increment(0.02)
            .unwrap();
        let mut seen = Vec::new();
        let r = run(&mut worn, &options, |c| seen.push(c.cycle)).unwrap();
        assert_eq!(seen, vec![1, 7, 500, 1000]);
        let per_cycle: f64 = 0.1 * 1e-9 * 0.5 * profile.iter().sum::<f64>();
        for c in &r.checkpoints {
            let expected = c.cycle as f64 * per_cycle;
            assert!((c.wear_volume - expected).abs() < 1e-12 * expected, "{c:?}");
            let energy = c.cycle as f64 * 0.5 * 0.1 * profile.iter().sum::<f64>();
            assert!((c.dissipated_energy - energy).abs() < 1e-12 * energy);
        }
        // Cycle 1; 6 cycles to 7 in one jump; 222, 222 and 49 to 500; 222, 222 and 56 to 1000.
        assert_eq!(r.simulated_cycles, 8);
        assert_eq!(worn.cycles, r.simulated_cycles);
    }

    #[test]
    fn jumps_keep_to_the_stability_bound_and_an_unstable_cycle_is_an_error() {
        // m = 1e-9 x 0.5 x 20 i / 1 per cycle at cell i (pressure 1): the largest, 9e-8 at the
        // last cell, with K = 1e5 gives m K = 9e-3, so jumps of floor(1/9e-3) = 111 cycles,
        // shorter than the depth bound's 222 (the test above).
        let x: Vec<f64> = (0..10).map(|i| 0.1 * i as f64).collect();
        let profile: Vec<f64> = (0..10).map(|i| 20.0 * i as f64).collect();
        let options = WearOptions::new(Law::Energy, 1e-9, 1_000, &[])
            .unwrap()
            .with_max_depth_increment(0.02)
            .unwrap();
        let mut worn = Steady {
            x: x.clone(),
            profile: profile.clone(),
            cycles: 0,
            stiffness: 1e5,
        };
        let r = run(&mut worn, &options, |_| {}).unwrap();
        // 9 jumps of 111 cycles and a last one of 1 to land on 1000.
        assert_eq!(r.simulated_cycles, 10);
        // m K = 9e-8 x 3e7 = 2.7 > 2: one cycle already makes the zigzag mode grow.
        let mut worn = Steady {
            x,
            profile,
            cycles: 0,
            stiffness: 3e7,
        };
        let e = run(&mut worn, &options, |_| {}).unwrap_err();
        assert!(
            matches!(&e, Error::WearStopped { cycle: 1, cause } if cause.to_string().contains("wear.coefficient")),
            "{e}"
        );
    }

    #[test]
    fn bad_options_name_their_field() {
        assert!(WearOptions::new(Law::Archard, 0.0, 10, &[]).is_err());
        assert!(WearOptions::new(Law::Archard, 1e-8, 0, &[]).is_err());
        let e = WearOptions::new(Law::Archard, 1e-8, 100, &[10, 5]).unwrap_err();
        assert!(e.to_string().contains("wear.checkpoints[1]"), "{e}");
        let e = WearOptions::new(Law::Archard, 1e-8, 100, &[])
            .unwrap()
            .with_share(1.5);
        assert!(e.unwrap_err().to_string().contains("wear.share"));
        let log = WearOptions::logarithmic(Law::Archard, 1e-8, 1_000_000, 7).unwrap();
        assert_eq!(
            log.checkpoints(),
            &[1, 10, 100, 1_000, 10_000, 100_000, 1_000_000]
        );
    }
}
