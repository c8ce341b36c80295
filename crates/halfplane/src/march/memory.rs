//! Mindlin's memory at constant pressure (`docs/convergence.md`, "Variable amplitudes: Mindlin's
//! memory"): an increment's located solution as a turning point's plus a located solve from
//! rest.
//!
//! At constant normal load, from a turning point T (the end of a stretch, where the slip zones
//! slipped at `-s f p`) the change of the traction during the next excursion, as long as its
//! slip zones lie within T's, is twice the solution of the first loading from rest for half the
//! change of load: in the new slip zones it is `2 s f p`, in the stick zone it keeps the
//! displacement rigid, and both conditions are those of that first loading doubled (Mindlin and
//! Deresiewicz, *J. Appl. Mech.* 20, 1953; for any half-plane profile Ciavarella, *Int. J.
//! Solids Struct.* 35, 1998, and Jäger). Once the excursion's slip zones pass T's, the loop
//! closes and T and the turning point before it are forgotten: the excursion continues the one
//! before, from an older turning point. From the stretch start at rest (the pressed state, no
//! traction), the first loading itself is that solution once.
//!
//! Solving each increment from its stretch's located start instead (`chain.rs`) carries the
//! start's representation (cell means, slopes and pieces) into the solve; after random
//! reversals that moved located boundaries next to the kinks the memory holds and put up to
//! 7.5e-2 f p0 into the traction (400 cells), more than the cell-level march's error. Here every
//! located solve starts from rest, as Cattaneo's does (2e-4 f p0 at 400 cells), and the
//! turning points are added as values.
//!
//! Owns the choice of the turning point and the superposition. Never changes the march's state.

use super::boundary::{TractionKink, View};
use super::chain::{Cells, Kink, Model, Piece};
use super::layout::{Layout, Role};
use super::marcher::Marcher;
use crate::error::Result;
use crate::labels::Edge;
use crate::load::LoadPoint;

impl Marcher {
    /// The increment located by Mindlin's memory, when its stretch holds a turning point whose
    /// slip zones contain the increment's (or the pressed state, at rest): sets the located
    /// solution and the view and returns the solves used; `None` otherwise (the stretch's
    /// start, or the cell level, is solved from instead). Forgets the turning points whose
    /// loops the increment has closed.
    pub(super) fn superposed(&mut self, load: LoadPoint, step: usize) -> Result<Option<usize>> {
        let mut solves = 0;
        loop {
            let Some(reference) = self.stretch.as_ref().and_then(|s| s.memory.last()) else {
                return Ok(None);
            };
            let at_rest = reference.centre.iter().all(|q| *q == 0.0);
            let factor = if at_rest { 1.0 } else { 2.0 };
            let depth = self.stretch.as_ref().map_or(0, |s| s.memory.len());
            if !at_rest && depth == 1 {
                // The stretches began from a state with traction that is not a turning point.
                return Ok(None);
            }
            let shear = (load.shear() - reference.load.shear()) / factor;
            let d_sigma = (load.bulk() - reference.load.bulk()) / factor;
            solves += self.solved_from_rest(d_sigma, shear, step)?;
            let reference = self
                .stretch
                .as_ref()
                .and_then(|s| s.memory.last())
                .expect("the reference is still held");
            if at_rest || self.within(reference) {
                let reference = reference.clone();
                self.superpose(&reference, factor, load)?;
                return Ok(Some(solves));
            }
            // The excursion has closed the reference's loop.
            if let Some(s) = self.stretch.as_mut() {
                s.memory.pop();
            }
        }
    }

    /// Solves the increment's layout from rest (no traction, no located start) for the shear
    /// `shear` and the tension change `d_sigma`: the boundaries located where the cell-level
    /// active set has them, or its cells alone when it has none to locate. Leaves the solution
    /// in the work buffers and `layout`, and the marcher's traction as it found it.
    fn solved_from_rest(&mut self, d_sigma: f64, shear: f64, step: usize) -> Result<usize> {
        let traction = std::mem::replace(&mut self.traction, vec![0.0; self.x.len()]);
        let stretch = self.stretch.take();
        self.start_mean.fill(0.0);
        self.start_slope.fill(0.0);
        self.layout = None;
        let solved = self.refine(d_sigma, shear, step).and_then(|solves| {
            if self.layout.is_some() {
                return Ok(solves);
            }
            let lay = Layout::cells(&self.cells, &self.x, self.width);
            self.end_solutions = self.evaluate(&lay, d_sigma, shear, step)?;
            self.layout = Some(lay);
            Ok(solves + 1)
        });
        self.stretch = stretch;
        self.traction = traction;
        solved
    }

    /// Whether the slip zones of the solve just made lie within `reference`'s, slipping the
    /// other way there: every slipping cell was at the opposite limit in the reference, and
    /// every located boundary lies at or beyond a boundary of the reference on its side whose
    /// slip went the other way.
    fn within(&self, reference: &Model) -> bool {
        let Some(lay) = &self.layout else {
            return false;
        };
        let f = self.friction;
        let scale = 1e-9 * f * self.pressure.iter().fold(0.0f64, |m, p| m.max(*p));
        let slips = lay.roles.iter().enumerate().all(|(i, role)| match role {
            Role::Slip(s) => (reference.centre[i] + s * f * self.pressure[i]).abs() <= scale,
            _ => true,
        });
        let tolerance = 1e-9 * self.width;
        let ends = lay.ends.iter().all(|e| {
            reference.ends.iter().any(|&[at, side, sign]| {
                side == e.side && sign == -e.sign && side * (e.at - at) >= -tolerance
            })
        });
        slips && ends
    }

    /// The increment's located solution: `reference` plus `factor` times the solve from rest in
    /// the work buffers, as the located solution the next increments may start from and as the
    /// view reported.
    fn superpose(&mut self, reference: &Model, factor: f64, load: LoadPoint) -> Result<()> {
        let lay = self.layout.take().expect("a solve from rest has a layout");
        let rest = self
            .end_model
            .take()
            .expect("a solve from rest has a model");
        let w = self.width;
        let add = |a: &[f64], b: &[f64]| -> Vec<f64> {
            a.iter().zip(b).map(|(a, b)| a + factor * b).collect()
        };
        let traction = add(&reference.centre, &self.dq);
        let slip = add(&reference.slip, &self.sub_slip);
        let c_disp = self.compliance / std::f64::consts::PI;
        let displacement = reference.displacement - factor * c_disp * self.shift;
        let mut kinks = Vec::with_capacity(lay.ends.len());
        for (e, sol) in lay.ends.iter().zip(&self.end_solutions) {
            let pressure = self.pressure_at(e.at)?;
            kinks.push(TractionKink {
                x: e.at,
                root: if e.side > 0.0 {
                    Edge::Left
                } else {
                    Edge::Right
                },
                amplitude: factor * sol.amplitude + reference.kink_at(e.at, e.side, w),
                shear: e.sign * self.friction * pressure,
                pressure,
            });
        }
        let new = lay.ends.iter().zip(&kinks).map(|(e, k)| Kink {
            x: e.at,
            side: e.side,
            amplitude: k.amplitude,
        });
        let kept = self.kept_kinks(&lay, Some(reference), new);
        let (mut mean, mut slope) = (
            add(&reference.cells.mean, &rest.mean),
            add(&reference.cells.slope, &rest.slope),
        );
        let mut pieces: Vec<Piece> = reference.cells.pieces.clone();
        pieces.extend(rest.pieces.into_iter().map(|p| Piece {
            coefficient: factor * p.coefficient,
            ..p
        }));
        self.fold_oldest(&mut pieces, &mut mean, &mut slope);
        self.located = Some(Model {
            centre: traction.clone(),
            cells: Cells {
                mean,
                slope,
                pieces,
            },
            kinks: kept,
            load,
            pressure: self.pressure.clone(),
            slip: slip.clone(),
            displacement,
            ends: lay.ends.iter().map(|e| [e.at, e.side, e.sign]).collect(),
        });
        self.view = Some(View {
            traction,
            kinks,
            slip,
            displacement,
        });
        Ok(())
    }
}
