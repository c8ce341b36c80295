//! Fretting wear: the gap evolves where the surfaces slip, over millions of cycles
//! ([docs/wear.md](../../docs/wear.md)).
//!
//! The model: a wear law gives the depth removed per unit of slip at each point,
//!
//! - Archard: `dh = k p |ds|` (k in 1/stress; Archard, *J. Appl. Phys.* 24, 1953),
//! - dissipated energy: `dh = alpha q ds = alpha f p |ds|` where the surfaces slip (Fouvry,
//!   Kapsa and Vincent, *Wear* 185, 1995; alpha in 1/stress),
//!
//! summed over the surfaces (the gap sees the total; `share` of it is the pad's). Each simulated
//! cycle marches one load cycle over the current worn gap ([`crate::march::Worn`], the gap's
//! normal problem solved on the grid), and its wear is extrapolated over a jump of N cycles chosen so
//! that the largest depth added by the jump stays below `max_depth_increment` times the elastic
//! approach (the gap the elastic deformation closes inside the unworn contact: `a^2/(2R)` for
//! Hertz); jumps end on every checkpoint and at the last cycle.
//!
//! Conventions: x along the surface as in `march`, depths positive into the bodies (the gap
//! grows by the depth), P > 0 compresses.
//!
//! Rooms: this file holds the options and the results; `driver.rs` the cycle-jumping loop.

mod driver;

pub use driver::{run, CycleWear, LoopPoint, WornCycle};

use crate::error::{Error, Result};

/// Most checkpoints a run reports (each may carry the fields of every cell).
pub const MAX_CHECKPOINTS: usize = 10_000;

/// Most physical cycles (the jumps cover them; the count must stay exact in f64).
pub const MAX_CYCLES: u64 = 1_000_000_000_000;

/// The wear law.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Law {
    /// `dh = k p |ds|`.
    Archard,
    /// `dh = alpha f p |ds|`, the dissipated energy density times alpha.
    Energy,
}

impl Law {
    /// "archard" or "energy": the names the case file uses.
    pub fn as_str(self) -> &'static str {
        match self {
            Law::Archard => "archard",
            Law::Energy => "energy",
        }
    }
}

/// The wear options, valid by construction.
#[derive(Debug, Clone, PartialEq)]
pub struct WearOptions {
    law: Law,
    coefficient: f64,
    share: f64,
    cycles: u64,
    checkpoints: Vec<u64>,
    max_depth_increment: f64,
}

impl WearOptions {
    /// The default bound on the depth a jump adds: 1% of the elastic approach (docs/wear.md
    /// shows the answer converging as it tightens).
    pub const DEFAULT_MAX_DEPTH_INCREMENT: f64 = 0.01;

    /// Wear by `law` with `coefficient` (k or alpha, > 0, in 1/stress) over `cycles` physical
    /// cycles (1 to [`MAX_CYCLES`]), reported at `checkpoints` (strictly increasing cycle numbers
    /// from 1 to `cycles`; the last cycle is always one), half of the depth taken from the pad.
    ///
    /// # Errors
    /// [`Error::InvalidInput`] naming `wear.coefficient`; [`Error::InvalidCount`] naming
    /// `wear.cycles` or a checkpoint; [`Error::InvalidInput`] naming `wear.checkpoints` for an
    /// unordered list.
    pub fn new(law: Law, coefficient: f64, cycles: u64, checkpoints: &[u64]) -> Result<Self> {
        crate::error::physical_positive("wear.coefficient", coefficient)?;
        if !(1..=MAX_CYCLES).contains(&cycles) {
            return Err(Error::InvalidCount {
                field: "wear.cycles".into(),
                value: cycles,
                min: 1,
                max: MAX_CYCLES,
            });
        }
        if checkpoints.len() > MAX_CHECKPOINTS {
            return Err(Error::InvalidCount {
                field: "wear.checkpoints (number of checkpoints)".into(),
                value: checkpoints.len() as u64,
                min: 0,
                max: MAX_CHECKPOINTS as u64,
            });
        }
        for (i, &c) in checkpoints.iter().enumerate() {
            if !(1..=cycles).contains(&c) {
                return Err(Error::InvalidCount {
                    field: format!("wear.checkpoints[{i}]"),
                    value: c,
                    min: 1,
                    max: cycles,
                });
            }
            if i > 0 && c <= checkpoints[i - 1] {
                return Err(Error::InvalidInput {
                    field: format!("wear.checkpoints[{i}]"),
                    value: c as f64,
                    valid: "a cycle after the previous checkpoint (strictly increasing)",
                });
            }
        }
        let mut checkpoints = checkpoints.to_vec();
        if checkpoints.last() != Some(&cycles) {
            checkpoints.push(cycles);
        }
        Ok(Self {
            law,
            coefficient,
            share: 0.5,
            cycles,
            checkpoints,
            max_depth_increment: Self::DEFAULT_MAX_DEPTH_INCREMENT,
        })
    }

    /// `count` checkpoints spaced logarithmically from cycle 1 to `cycles` (whole cycles, each
    /// once: fewer when the range is short).
    ///
    /// # Errors
    /// As [`WearOptions::new`]; [`Error::InvalidCount`] naming `wear.checkpoints` for a count
    /// of 0 or above [`MAX_CHECKPOINTS`].
    pub fn logarithmic(law: Law, coefficient: f64, cycles: u64, count: usize) -> Result<Self> {
        if !(1..=MAX_CHECKPOINTS).contains(&count) {
            return Err(Error::InvalidCount {
                field: "wear.checkpoints".into(),
                value: count as u64,
                min: 1,
                max: MAX_CHECKPOINTS as u64,
            });
        }
        let top = (cycles.max(1) as f64).ln();
        let mut points: Vec<u64> = (0..count)
            .map(|k| {
                let t = if count == 1 {
                    1.0
                } else {
                    k as f64 / (count - 1) as f64
                };
                ((t * top).exp().round() as u64).clamp(1, cycles.max(1))
            })
            .collect();
        points.dedup();
        Self::new(law, coefficient, cycles, &points)
    }

    /// The share of the depth taken from the pad, from 0 to 1 (default 0.5).
    ///
    /// # Errors
    /// [`Error::InvalidInput`] naming `wear.share` outside [0, 1].
    pub fn with_share(self, share: f64) -> Result<Self> {
        if !(share.is_finite() && (0.0..=1.0).contains(&share)) {
            return Err(Error::InvalidInput {
                field: "wear.share".into(),
                value: share,
                valid: "a fraction from 0 to 1 (the share of the depth taken from the pad)",
            });
        }
        Ok(Self { share, ..self })
    }

    /// The largest depth a jump may add, as a fraction of the elastic approach (default
    /// [`WearOptions::DEFAULT_MAX_DEPTH_INCREMENT`]), from 1e-6 to 1.
    ///
    /// # Errors
    /// [`Error::InvalidInput`] naming `wear.max_depth_increment` outside that range.
    pub fn with_max_depth_increment(self, fraction: f64) -> Result<Self> {
        if !(fraction.is_finite() && (1e-6..=1.0).contains(&fraction)) {
            return Err(Error::InvalidInput {
                field: "wear.max_depth_increment".into(),
                value: fraction,
                valid: "a fraction of the elastic approach from 1e-6 to 1",
            });
        }
        Ok(Self {
            max_depth_increment: fraction,
            ..self
        })
    }

    /// The law.
    pub fn law(&self) -> Law {
        self.law
    }

    /// k or alpha (1/stress).
    pub fn coefficient(&self) -> f64 {
        self.coefficient
    }

    /// The pad's share of the depth.
    pub fn share(&self) -> f64 {
        self.share
    }

    /// Physical cycles.
    pub fn cycles(&self) -> u64 {
        self.cycles
    }

    /// The checkpoints, strictly increasing, the last one `cycles`.
    pub fn checkpoints(&self) -> &[u64] {
        &self.checkpoints
    }

    /// The bound on a jump's depth, as a fraction of the elastic approach.
    pub fn max_depth_increment(&self) -> f64 {
        self.max_depth_increment
    }
}

/// The state at a checkpoint: the last simulated cycle's (which the cycles up to the checkpoint
/// repeat) and the totals over every cycle up to it.
#[derive(Debug, Clone, PartialEq)]
#[non_exhaustive]
pub struct Checkpoint {
    /// The physical cycle.
    pub cycle: u64,
    /// Volume removed from both bodies per unit thickness, up to this cycle.
    pub wear_volume: f64,
    /// The largest depth (both bodies).
    pub max_depth: f64,
    /// Energy dissipated in one cycle (per unit thickness).
    pub energy_per_cycle: f64,
    /// Energy dissipated up to this cycle.
    pub dissipated_energy: f64,
    /// The contact's ends at the end of the cycle.
    pub contact: [f64; 2],
    /// The largest pressure at the end of the cycle.
    pub peak_pressure: f64,
    /// The permanent stick zone of the cycle (cells that did not slip in it); `None` in gross
    /// sliding.
    pub stick: Option<[f64; 2]>,
    /// The largest slip amplitude (half the slip range) in the cycle.
    pub slip_amplitude_max: f64,
    /// Half the range of the bodies' relative displacement over the cycle (the fretting loop's
    /// displacement amplitude, with the loop's datum: [`crate::march::RelativeDisplacement`]).
    pub displacement_amplitude: f64,
    /// The fretting loop of the cycle: Q and the bodies' relative displacement at its start and
    /// after every increment and slide.
    pub fretting_loop: Vec<LoopPoint>,
    /// The fields of every cell.
    pub fields: CheckpointFields,
    /// The tractions of every increment of the cycle, when the march recorded them
    /// ([`crate::march::Worn::record_tractions`]): what [`crate::fatigue::analyse_cycle`]
    /// evaluates.
    pub tractions: Option<crate::fatigue::CycleTractions>,
}

/// The fields at a checkpoint, one value per cell.
#[derive(Debug, Clone, PartialEq)]
#[non_exhaustive]
pub struct CheckpointFields {
    /// Cell centres.
    pub x: Vec<f64>,
    /// Depth removed from both bodies.
    pub depth: Vec<f64>,
    /// From the pad (`share` of it).
    pub depth_pad: Vec<f64>,
    /// From the specimen.
    pub depth_specimen: Vec<f64>,
    /// Pressure at the end of the cycle.
    pub pressure: Vec<f64>,
    /// Shear traction at the end of the cycle.
    pub traction: Vec<f64>,
    /// The slip range over the cycle.
    pub slip_range: Vec<f64>,
}

/// The outcome of [`run`].
#[derive(Debug, Clone, PartialEq)]
#[non_exhaustive]
pub struct WearResult {
    /// One per checkpoint, in order.
    pub checkpoints: Vec<Checkpoint>,
    /// Cycles marched (the rest were jumped).
    pub simulated_cycles: usize,
    /// The elastic approach the jumps' depth bound is a fraction of.
    pub elastic_approach: f64,
}
