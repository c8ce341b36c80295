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
//! The rule needs one-parametric loading ([`one_line`]) for every turning point but the
//! stretch's own start: from that start the superposition holds for any path. Within a stretch
//! each point slips one way and is still slipping (`chain.rs`), so the state is the solution of
//! a single step from the start, a convex problem with one solution at constant pressure; the
//! start plus twice the solve from rest is admissible, so it is that solution, when `within`
//! finds the solve slipping only where the start was at the opposite limit (`-s f p` to
//! `s f p`) and `plausible` finds the limit kept elsewhere. A memory that has lost
//! turning points for want of room takes no excursion from rest (`chain.rs`); and a superposed
//! traction that breaks the friction limit is not reported. In each case the increment is
//! solved from its stretch's start instead. A reviewer's probes found each needed
//! (docs/convergence.md).
//!
//! Owns the choice of the turning point and the superposition. Never changes the march's state.

use super::boundary::View;
use super::chain::Memory;
use super::chain::{Cells, Model, Piece};
use super::layout::{Layout, Role};
use super::marcher::Marcher;
use crate::error::Result;
use crate::load::LoadPoint;

impl Marcher {
    /// The increment located by Mindlin's memory, when the memory holds a turning point whose
    /// slip zones contain the increment's (or, rooted, the pressed state at rest): the stretch's
    /// own start on any path, older ones when the loads since the memory's first start lie on
    /// one line in the plane of shear and bulk stress ([`one_line`]). Sets the located solution
    /// and the view and returns the solves used; `None` otherwise (the stretch's start, or the
    /// cell level, is solved from instead). Forgets the turning points whose loops the
    /// increment has closed.
    pub(super) fn superposed(&mut self, load: LoadPoint, step: usize) -> Result<Option<usize>> {
        let Some(stretch) = self.stretch.as_mut() else {
            return Ok(None);
        };
        if !one_line(&stretch.memory, &load) {
            // The path has left the line: the turning points before the stretch's start no
            // longer describe the state. The start itself still does (below).
            let memory = &mut stretch.memory;
            let start = memory.start_on_top.then(|| memory.turns.pop()).flatten();
            *memory = Memory {
                start_on_top: start.is_some(),
                turns: start.into_iter().collect(),
                rooted: false,
            };
        }
        let mut solves = 0;
        // Each turning point is taken out of the memory while it is tried (the solve and the
        // superposition need the marcher), and put back unless the excursion has closed its loop.
        while let Some(memory) = self.stretch.as_mut().map(|s| &mut s.memory) {
            let is_start = std::mem::take(&mut memory.start_on_top);
            let Some(reference) = memory.turns.pop() else {
                break;
            };
            // The stretch's own start holds for any path (each point slipped one way since it);
            // an older turning point only by the one-parametric memory, and a first start
            // only at rest: the excursion has then closed every loop since, and is the first
            // loading. A first start with traction is no turning point.
            let first = !is_start && memory.turns.is_empty() && memory.rooted;
            let at_rest = (is_start || first) && reference.centre.iter().all(|q| *q == 0.0);
            if first && !at_rest {
                self.remember(reference, is_start);
                return Ok(None);
            }
            let factor = if at_rest { 1.0 } else { 2.0 };
            let shear = (load.shear() - reference.load.shear()) / factor;
            let d_sigma = (load.bulk() - reference.load.bulk()) / factor;
            solves += self.solved_from_rest(d_sigma, shear, step)?;
            if at_rest || self.within(&reference) {
                self.superpose(&reference, factor, load)?;
                self.remember(reference, is_start);
                if self.plausible() {
                    return Ok(Some(solves));
                }
                (self.view, self.located) = (None, None);
                return Ok(None);
            }
            // The excursion has closed the reference's loop: it stays out.
        }
        Ok(None)
    }

    /// Puts a turning point taken out by [`Marcher::superposed`] back on top of the memory,
    /// marked as the stretch's start if it was.
    fn remember(&mut self, reference: Model, is_start: bool) {
        if let Some(s) = self.stretch.as_mut() {
            s.memory.turns.push(reference);
            s.memory.start_on_top = is_start;
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

    /// Whether the superposed traction keeps the friction limit at every centre: a guard against
    /// a turning point wrongly taken (bulk stress cycled alone at constant Q, in a reviewer's
    /// probe, broke it by 0.22 f p0 at 400 cells; the increment is then solved from its
    /// stretch's start).
    fn plausible(&self) -> bool {
        self.view
            .as_ref()
            .is_some_and(|v| self.keeps_limit(&v.traction))
    }

    /// Whether `traction` keeps the friction limit `f p` at every centre, to 1e-6 of `f p_max`.
    pub(super) fn keeps_limit(&self, traction: &[f64]) -> bool {
        let f = self.friction;
        let scale = f * self.pressure.iter().fold(0.0f64, |m, p| m.max(*p));
        traction
            .iter()
            .zip(&self.pressure)
            .all(|(q, p)| q.abs() <= f * p + 1e-6 * scale)
    }

    /// The increment's located solution: `reference` plus `factor` times the solve from rest in
    /// the work buffers, as the located solution the next increments may start from and as the
    /// view reported.
    fn superpose(&mut self, reference: &Model, factor: f64, load: LoadPoint) -> Result<()> {
        let (Some(lay), Some(rest)) = (self.layout.take(), self.end_model.take()) else {
            // A solve from rest always leaves both; without them nothing is reported, and
            // `plausible` sends the increment to its stretch's start.
            return Ok(());
        };
        let w = self.width;
        let add = |a: &[f64], b: &[f64]| -> Vec<f64> {
            a.iter().zip(b).map(|(a, b)| a + factor * b).collect()
        };
        let traction = add(&reference.centre, &self.dq);
        let slip = add(&reference.slip, &self.sub_slip);
        let c_disp = self.compliance / std::f64::consts::PI;
        let displacement = reference.displacement - factor * c_disp * self.shift;
        // The reference's pieces are all kept, and so are its kinks, each at its own place; a
        // boundary reports those next to it with its own (the stresses' node form has one node
        // there).
        let amplitudes: Vec<f64> = (self.end_solutions.iter())
            .map(|s| factor * s.amplitude)
            .collect();
        let reported: Vec<f64> = (lay.ends.iter().zip(&amplitudes))
            .map(|(e, a)| a + reference.kinks_near(e.at, e.side, w))
            .collect();
        let (kinks, new) = self.kinks_of(&lay, &reported, &amplitudes)?;
        let kept = self.kept_kinks(&lay, Some(reference), new, |_| false);
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
        let located = Model {
            centre: traction,
            cells: Cells {
                mean,
                slope,
                pieces,
            },
            kinks: kept,
            load,
            pressure: self.pressure.clone(),
            slip,
            displacement,
            ends: lay.ends.iter().map(|e| [e.at, e.side, e.sign]).collect(),
        };
        let kinks = self.with_locked_kinks(kinks, &located, &lay)?;
        self.view = Some(View::of(&located, kinks));
        self.located = Some(located);
        Ok(())
    }
}

/// Whether every start the memory holds and `load` lie on one line through the first start in
/// the plane of shear and bulk stress: the loading is then one-parametric and Mindlin's memory
/// holds (with bulk stress in proportion, as Nowell and Hills's memory rule has it). A bulk
/// stress changing apart from the shear makes the stick zones depend on the path in other
/// ways; the increment is then solved from its stretch's start.
fn one_line(memory: &Memory, load: &LoadPoint) -> bool {
    let Some(first) = memory.turns.first() else {
        return false;
    };
    let (q0, s0) = (first.load.shear(), first.load.bulk());
    let (dq, ds) = (load.shear() - q0, load.bulk() - s0);
    memory.turns.iter().all(|m| {
        let (eq, es) = (m.load.shear() - q0, m.load.bulk() - s0);
        (eq * ds - es * dq).abs() <= 1e-9 * ((eq * ds).abs() + (es * dq).abs())
    })
}
