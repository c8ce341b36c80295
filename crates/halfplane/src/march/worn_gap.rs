//! The marcher's worn-gap route ([`super::Worn`]): a gap given at the cell centres in place of
//! the profile's, its contact under each load solved on the grid (`gap.rs`), and the slides of
//! gross sliding at `q = f p`.
//!
//! Owns the worn gap and its last solution. Never changes the active set's rules (`marcher.rs`).

use super::marcher::{Cell, Marcher};
use crate::error::{Error, Result};
use crate::labels::PerEdge;
use crate::load::LoadPoint;
use crate::normal_moment::NormalContact;

/// A worn gap and its last solution on the grid.
#[derive(Debug, Clone)]
pub(super) struct Gap {
    gap: Vec<f64>,
    pub(super) solution: Option<super::gap::GapContact>,
    /// The (P, M) the solution is of; `None` after the gap changed.
    solved_for: Option<(f64, f64)>,
}

impl Marcher {
    /// Marches on with the gap `gap` (one value per cell, at the cell centres) in place of the
    /// profile's: every later increment's pressure is the grid's solution of it (`gap.rs`),
    /// which must then keep P and M constant (a worn gap's contact is solved for one load; the
    /// moving edges of a changing load are the profile's normal problem's).
    pub(crate) fn set_gap(&mut self, gap: Vec<f64>) {
        let solution = self.gap.take().and_then(|g| g.solution);
        // The located boundaries stop here (`marcher.rs`), and with them their chain.
        (self.located, self.stretch) = (None, None);
        self.gap = Some(Gap {
            gap,
            solution,
            solved_for: None,
        });
    }

    /// The contact of the worn gap under `load`: solved again when the gap or the load changed
    /// (from the last solution's contact set), as a [`NormalContact`] whose ends are the outer
    /// edges of the outermost touching cells.
    pub(super) fn grid_target(&mut self, load: &LoadPoint, step: usize) -> Result<NormalContact> {
        let key = (load.normal(), load.moment());
        let gap = self.gap.as_mut().expect("grid_target is called with a gap");
        if let (Some(state), Some(before)) = (self.state, gap.solved_for) {
            if before != key {
                return Err(Error::InvalidInput {
                    field: format!("history row {step}.normal"),
                    value: load.normal(),
                    valid: "the normal load and moment of the previous row: a worn gap's contact is solved for one load",
                });
            }
            if gap.solution.is_some() && state.normal() == key.0 {
                return Ok(state);
            }
        }
        let mut grid = super::gap::Grid {
            kernel: &mut self.kernel,
            x: &self.x,
            width: self.width,
            compliance: self.compliance,
        };
        let solution = grid.solve(&gap.gap, key.0, key.1, gap.solution.as_ref())?;
        let first = solution.pressure.iter().position(|&p| p > 0.0);
        let last = solution.pressure.iter().rposition(|&p| p > 0.0);
        let (Some(first), Some(last)) = (first, last) else {
            return Err(Error::InvalidInput {
                field: "history.normal".into(),
                value: key.0,
                valid: "a load the worn gap's contact carries",
            });
        };
        let n = self.x.len();
        if first == 0 || last == n - 1 {
            return Err(Error::GridTooNarrow {
                field: "wear.span",
                end: self.x[if first == 0 { 0 } else { n - 1 }],
            });
        }
        let ends = PerEdge {
            left: self.x[first] - 0.5 * self.width,
            right: self.x[last] + 0.5 * self.width,
        };
        gap.solution = Some(solution.clone());
        gap.solved_for = Some(key);
        Ok(NormalContact::on_grid(
            key.0,
            key.1,
            ends,
            solution.rotation,
        ))
    }

    /// The bodies slide by `distance` (signed: positive in the sense positive Q drives) at the
    /// current P and M, Q at the friction limit `sign(distance) f P`: every contact cell carries
    /// `q = sign f p` and slips by the distance (at constant pressure the traction does not change
    /// while they slide). The energy is `f p |distance|` at each cell (`integral p |ds|` exact).
    pub(super) fn slide(&mut self, distance: f64) -> Result<()> {
        let Some(load) = self.load else {
            return Err(Error::InvalidInput {
                field: "history.amplitude".into(),
                value: distance,
                valid: "a slide after the contact is loaded",
            });
        };
        let (sign, f) = (distance.signum(), self.friction);
        // What the fields report is now the sliding traction, with no stick-slip boundary.
        self.view = None;
        self.reported_kinks.clear();
        (self.located, self.stretch) = (None, None);
        let mut energy = 0.0;
        for i in 0..self.x.len() {
            if self.cells[i] == Cell::Out {
                continue;
            }
            self.traction[i] = sign * f * self.pressure[i];
            self.cells[i] = Cell::Slip(sign);
            self.slip[i] += distance;
            self.pressure_slip[i] += self.pressure[i] * distance.abs();
            energy += f * self.pressure[i] * distance.abs();
        }
        self.energy += energy * self.width;
        self.displacement += distance;
        self.load = Some(
            LoadPoint::new(
                "slide",
                load.normal(),
                sign * f * load.normal(),
                load.bulk(),
            )?
            .with_moment("slide", load.moment())?,
        );
        Ok(())
    }

    /// `integral p |ds|` at each cell since the last call, and zero again.
    pub(crate) fn take_pressure_slip(&mut self) -> Vec<f64> {
        std::mem::replace(&mut self.pressure_slip, vec![0.0; self.x.len()])
    }
}
