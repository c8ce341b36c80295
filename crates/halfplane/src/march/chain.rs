//! Where a located solve starts (`docs/convergence.md`, "Sub-cell stick-slip boundaries"): the
//! cell-level state at the increment's last sub-step, or, through a stretch of the history in
//! which the slip zones only grow, the located solution at the stretch's start.
//!
//! At the extreme of a constant-amplitude cycle the new stick-slip boundary lands where the last
//! half's was, and the stick zone next to it still holds that half's traction, kink included.
//! Started from the cell-level state, the located solve inherited that kink at a cell edge, up
//! to half a cell from where it is, and put the new boundary 0.13 cells off (1.1e-2 p0 in the
//! surface stress at 1600 cells). Started from the located solution of the last increment at
//! every increment, the solves' errors next to their boundaries accumulated instead: each
//! increment's square root stays in the stick zone's traction where the exact increment would
//! cancel it once its boundary has receded (4e-4 f p0 more per increment at 400 cells).
//!
//! So a located solve starts from a located solution only across a *stretch*: increments at an
//! unchanged pressure in which no slipping cell sticks again or turns, the cell-level record of
//! a half-cycle. Within a stretch every stuck cell stuck throughout and every slipping cell
//! ends at the limit, so one solve from the stretch's start to the current load is exact (the
//! path does not matter, as for Cattaneo loaded in one increment). A stretch starts from the
//! last increment's located solution at the same pressure; a stuck state (the pressed one, with
//! no traction) is its own located solution, so a first loading is one stretch from it and each
//! of its increments is located as if loaded in one. Otherwise the located solve starts from the
//! cell-level state, as it always did, and so does an increment whose solution from the start
//! would break the friction limit (`boundary.rs`).
//!
//! Each stretch also carries the starts of the stretches before it at this pressure that
//! Mindlin's memory still holds (turning points, and the first, at rest). Where one of them
//! applies, the increment is that turning point's solution plus a located solve from rest
//! (`memory.rs`), not a solve from the stretch's start: solving from the start carried the
//! start's representation into the solve, and after random reversals put up to 4.2e-2 f p0 into
//! the traction at 400 cells (more than the cell level's error; docs/convergence.md).
//!
//! The start is kept in the form the solve's model has ([`Model`]): per cell a smooth part (mean
//! and slope), exact pieces near each boundary (the element's affine parts, each root within
//! `NEAR` cells), and the boundaries' kinks with their amplitudes. A boundary element
//! replaces its cells' start; the start's kinks with the boundary's stick side go back on it as
//! square roots ([`Held`], `evaluate.rs`), those inside the new stick zone at their own places:
//! without them an increment with no change of load moved the traction next to the boundary by
//! 1.4e-3 f p0. Until 2026-11-27 only the nearest kink within half a cell went back, moved onto
//! the boundary, and an increment with another kink near the element was solved from the cell
//! level instead: off Mindlin's line that left up to twice the cell level's error at 400 cells
//! (docs/convergence.md, "Bulk stress and bent paths").
//!
//! The cell-level state itself, and so the active set, the slips, the energy and the cycles'
//! repetition, never sees any of it. Owns the located solutions' model, the stretch and its
//! memory of turning points. Never solves anything.

use super::evaluate::Special;
use super::kernel::{Element, Shape};
use super::layout::{Layout, Role, SoftEnd};
use super::marcher::{Cell, Marcher};
use crate::load::LoadPoint;

/// Most exact pieces one cell keeps; beyond, the oldest is kept by its mean and slope only. A
/// cell that stays stuck through many half-cycles gathers a root piece per half.
const PIECES_PER_CELL: usize = 8;

/// A kink of the start beyond a new boundary (on its slip side) within this many cells is taken
/// over by the boundary ([`Held`]).
pub(super) const SAME_KINK: f64 = 0.5;

/// A kink of the start on a new boundary's stick side closer than this many cells is taken over
/// too. Kept apart, kinks gathered where a cycle's boundaries come back (0.01 cells apart on a
/// square path in the plane of Q and bulk stress), each with pieces of its own, until the
/// oldest pieces were folded into the cells' means (`PIECES_PER_CELL`): 1.3e-2 f p0 from the
/// sixth cycle on at 400 cells (against 1200), 3.1e-3 through ten cycles with this
/// (`tests/sub_cell.rs`); at 0.1 cells the nested loops of `tests/sub_cell.rs` went from 8.5e-3
/// to 1.6e-2, and 0.12 made the square path 3.1e-2 from its second cycle (a reviewer). Beyond
/// ten cycles a kink held just outside this band, its distance creeping from 0.11 to 0.04
/// cells, took the square path's error at 400 cells up to 4.4e-2 in cycles 36-40
/// (docs/convergence.md).
const TAKE_OVER: f64 = 0.02;

/// One exact part of the traction in one cell: `coefficient` times `element`'s shape.
#[derive(Debug, Clone, PartialEq)]
pub(super) struct Piece {
    pub cell: usize,
    pub element: Element,
    pub coefficient: f64,
}

/// A square root in a located solution's traction (a stick-slip boundary's, or one a stick
/// zone holds), with its amplitude: the roots at one place and side summed.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(super) struct Kink {
    pub x: f64,
    /// Its stick side: 1 to the left of `x`, -1 to the right.
    pub side: f64,
    pub amplitude: f64,
    /// The root's taper window ([`super::kernel::Shape::Root`]).
    pub window: f64,
}

impl Kink {
    /// Whether it is within [`SAME_KINK`] cells of a boundary at `at` with stick side `side`:
    /// the stresses' node form, with one node there, reports it with that boundary's.
    pub(super) fn next_to(&self, at: f64, side: f64, width: f64) -> bool {
        self.side == side && (self.x - at).abs() < SAME_KINK * width
    }
}

/// A located solution as the solve models it.
#[derive(Debug, Clone, PartialEq)]
pub(super) struct Model {
    /// The traction at each centre (what is reported).
    pub centre: Vec<f64>,
    pub cells: Cells,
    pub kinks: Vec<Kink>,
    /// The load and the pressure it was solved for.
    pub load: LoadPoint,
    pub pressure: Vec<f64>,
    /// The accumulated slip and the relative displacement (datum the kernel's scale) reported
    /// with it (`report.rs`).
    pub slip: Vec<f64>,
    pub displacement: f64,
    /// Its stick-slip boundaries `[at, side, sign]` (side and slip sign as in
    /// [`super::layout::SoftEnd`]; none for a stuck state).
    pub ends: Vec<[f64; 3]>,
}

impl Model {
    /// The summed amplitudes of its kinks within [`SAME_KINK`] cells of a boundary at `at` with
    /// stick side `side`: what the stresses' node form, with one node there, takes as that
    /// boundary's (zero without one).
    pub(super) fn kinks_near(&self, at: f64, side: f64, width: f64) -> f64 {
        (self.kinks.iter())
            .filter(|k| k.next_to(at, side, width))
            .map(|k| k.amplitude)
            .sum()
    }

    /// The kinks of this solution with `e`'s stick side that `e`'s element holds ([`Held`]):
    /// those inside the element on the stick side, at their own places, and those within
    /// [`SAME_KINK`] cells on the slip side or [`TAKE_OVER`] on the stick side, taken over by
    /// the boundary.
    pub(super) fn held(&self, e: &SoftEnd, width: f64) -> Vec<Held> {
        let [lo, hi] = e.support;
        let mut held: Vec<Held> = self
            .kinks
            .iter()
            .filter(|k| {
                k.side == e.side
                    && e.side * (e.at - k.x) > TAKE_OVER * width
                    && lo < k.x
                    && k.x < hi
            })
            .map(|k| Held {
                kink: *k,
                merged: false,
            })
            .collect();
        held.extend(
            (self.kinks.iter())
                .filter(|k| {
                    k.side == e.side
                        && e.side * (e.at - k.x) <= TAKE_OVER * width
                        && (k.x - e.at).abs() < SAME_KINK * width
                })
                .map(|k| Held {
                    kink: *k,
                    merged: true,
                }),
        );
        held
    }
}

/// A start's kink held on a boundary element, which replaces its cells' start (`evaluate.rs`).
/// Inside the new stick zone it stays where it is: its root is zero between it and the
/// boundary, so the element's ramp keeps the limit's slope at the boundary. On the slip side,
/// where the new slip zone reaches it, or all but on the boundary, the boundary takes it over
/// (`merged`): its root goes on the boundary. Until 2026-11-27 only the nearest kink within
/// [`SAME_KINK`] cells on either side went back, moved onto the boundary (an error of order
/// `K sqrt(distance)`), and an increment with another start kink within three cells was solved
/// from the cell level instead (`docs/convergence.md`). Kinks with the other stick side are
/// not held: their roots on the element are lost (a reviewer found two, 0.4 and 0.6 cells
/// inside, in a history with Q near the limit).
#[derive(Debug, Clone, Copy, PartialEq)]
pub(super) struct Held {
    pub kink: Kink,
    pub merged: bool,
}

impl Held {
    /// Its square root on `e`'s element (unit amplitude), on its stick side only.
    pub(super) fn root(&self, e: &SoftEnd) -> Element {
        let [lo, hi] = e.support;
        let (at, window) = if self.merged {
            (e.at, e.window)
        } else {
            (self.kink.x, self.kink.window)
        };
        let (lo, hi) = if e.side > 0.0 {
            (lo, hi.min(at))
        } else {
            (lo.max(at), hi)
        };
        Element::new(
            lo,
            hi.max(lo),
            Shape::Root {
                at,
                side: e.side,
                window,
            },
        )
    }
}

/// What the kinks held at a boundary add to its own root's amplitude there.
pub(super) fn merged_amplitude(held: &[Held]) -> f64 {
    held.iter()
        .filter(|h| h.merged)
        .map(|h| h.kink.amplitude)
        .sum()
}

/// A located solution's cells as the solve models them.
#[derive(Debug, Clone, PartialEq)]
pub(super) struct Cells {
    /// The smooth part: each cell's mean and slope (first moment about the centre times
    /// `12/w^3`).
    pub mean: Vec<f64>,
    pub slope: Vec<f64>,
    /// The exact pieces, each inside its cell.
    pub pieces: Vec<Piece>,
}

/// A stretch: its start, the direction in which each cell has slipped since (0: stuck), the
/// energy dissipated since, as last reported (`report.rs`), and the located solutions at the
/// starts of the stretches at this pressure that Mindlin's memory still holds, oldest first
/// (`memory.rs`).
#[derive(Debug, Clone, PartialEq)]
pub(super) struct Stretch {
    pub start: Model,
    pub slipped: Vec<f64>,
    pub work: f64,
    pub memory: Memory,
}

/// The located solutions at the starts of the stretches at one pressure that Mindlin's memory
/// holds, oldest first, whether the oldest is where they all began, and whether the newest is
/// the current stretch's own start (`memory.rs`).
#[derive(Debug, Clone, PartialEq, Default)]
pub(super) struct Memory {
    pub turns: Vec<Model>,
    /// The first start is still held: nothing was forgotten for want of room.
    pub rooted: bool,
    /// The newest turn is the current stretch's start (its loop has not closed).
    pub start_on_top: bool,
}

/// Most stretch starts a memory holds; beyond, the oldest goes and the memory is no longer
/// rooted (an excursion that would close a loop beyond it is solved from its stretch's start,
/// `memory.rs`).
const MEMORY: usize = 16;

impl Marcher {
    /// The stretch the current increment continues, or the one it starts from the last located
    /// solution, or `None` (the located solve starts from the cell level). `sub_slip` is the
    /// cell-level slip of the increment's last sub-step, not yet added to the state; a cell's
    /// slip within `rounding` is none (a dwell leaves reversed slips of 1e-19 on slipping cells,
    /// which broke the stretch).
    pub(super) fn stretch_for(&mut self, sub_slip: &[f64], rounding: f64) -> Option<Stretch> {
        // This increment's slip direction per cell: 0 stuck, NaN when it turned within it.
        let turned = f64::NAN;
        let moved: Vec<f64> = (0..self.x.len())
            .map(|i| {
                let travel = self.slip_travel[i] + sub_slip[i].abs();
                let net = self.slip_increment[i] + sub_slip[i];
                if travel <= rounding {
                    0.0
                } else if net.abs() < travel * (1.0 - 1e-9) - rounding {
                    turned
                } else {
                    net.signum()
                }
            })
            .collect();
        let grows = |slipped: &[f64]| {
            self.cells
                .iter()
                .zip(slipped.iter().zip(&moved))
                .all(|(c, (s, m))| {
                    !m.is_nan()
                        && match *s {
                            0.0 => true,
                            s => (*m == s || *m == 0.0) && *c == Cell::Slip(s),
                        }
                })
        };
        let mut memory = Memory::default();
        if let Some(mut stretch) = self.stretch.take() {
            if stretch.start.pressure != self.pressure {
                // Turning points at another pressure describe nothing here.
            } else if grows(&stretch.slipped) {
                for (s, m) in stretch.slipped.iter_mut().zip(&moved) {
                    if *s == 0.0 {
                        *s = *m;
                    }
                }
                return Some(stretch);
            } else {
                memory = stretch.memory;
            }
        }
        let last = self.located.take()?;
        if last.pressure != self.pressure {
            return None;
        }
        let mut slipped = vec![0.0; self.x.len()];
        if !grows(&slipped) {
            return None;
        }
        slipped.copy_from_slice(&moved);
        if memory.turns.is_empty() {
            memory.rooted = true;
        }
        if memory.turns.len() == MEMORY {
            memory.turns.remove(0);
            memory.rooted = false;
        }
        memory.turns.push(last.clone());
        memory.start_on_top = true;
        Some(Stretch {
            start: last,
            slipped,
            work: 0.0,
            memory,
        })
    }

    /// A stuck state's located solution: the cell-level traction `centre` (piecewise constant,
    /// no boundary), slip and displacement, at `load` and the current pressure.
    pub(super) fn stuck_model(&self, centre: Vec<f64>, load: LoadPoint) -> Model {
        Model {
            cells: Cells {
                mean: centre.clone(),
                slope: vec![0.0; centre.len()],
                pieces: Vec::new(),
            },
            centre,
            kinks: Vec::new(),
            load,
            pressure: self.pressure.clone(),
            slip: self.slip.clone(),
            displacement: self.displacement,
            ends: Vec::new(),
        }
    }

    /// The kinks of a located solution on `layout`: the `new` boundaries', and those of its
    /// `start` (a stretch's or a turning point's, or `None` from the cell level) that its stick
    /// zones still hold and that no new boundary `took` over.
    pub(super) fn kept_kinks(
        &self,
        layout: &Layout,
        start: Option<&Model>,
        new: impl Iterator<Item = Kink>,
        took: impl Fn(&Kink) -> bool,
    ) -> Vec<Kink> {
        // A kink at a zone's end to rounding is the stick zone's (a loop closed at its turning
        // point puts the new boundary on the old one).
        let tolerance = 1e-6 * self.width;
        let mut kinks: Vec<Kink> = start.map_or(Vec::new(), |s| {
            s.kinks
                .iter()
                .filter(|k| {
                    let inside = |z: &[f64; 2]| z[0] - tolerance <= k.x && k.x <= z[1] + tolerance;
                    layout.zones.iter().any(inside) && !took(k)
                })
                .copied()
                .collect()
        });
        // Kinks at one place with one stick side are one root: summed, so that a cycle whose
        // half-cycles close on the same turning points does not add an entry per half (a
        // reviewer counted 4000 after 1000 cycles, and the solves leaving the cycle took up to
        // 46 times as long).
        for k in new {
            match (kinks.iter_mut()).find(|o| o.side == k.side && (o.x - k.x).abs() <= tolerance) {
                Some(o) => o.amplitude += k.amplitude,
                None => kinks.push(k),
            }
        }
        kinks
    }

    /// The model of the traction a located solve on `layout` ends with: on free cells the
    /// start's smooth part plus the cell's constant `z` and the roots beyond their near parts by
    /// means and slopes, the start's pieces kept and each root's near part as pieces; on
    /// slipping cells the limit by its mean and slope (as the solve has it); on each boundary's
    /// cells its element's constant and ramp, the start's kinks put back (`held`) and the roots
    /// on the stick side, and the limit's fit on the slip side, all as pieces; zero out of
    /// contact. `unknown` and `specials` are the solve's shapes and values (per boundary, the
    /// element's constant and the root), `slopes` the elements' ramps, `start` the stretch's
    /// start (`None`: the cell-level state, whose model is `start_mean` alone).
    #[allow(clippy::too_many_arguments)]
    pub(super) fn located_model(
        &self,
        layout: &Layout,
        unknown: &[Special],
        specials: &[f64],
        slopes: &[f64],
        held: &[Vec<Held>],
        z: &[f64],
        start: Option<&Model>,
    ) -> Cells {
        let n = self.x.len();
        let w = self.width;
        let edge0 = self.x[0] - 0.5 * w;
        let (mut mean, mut slope) = (vec![0.0; n], vec![0.0; n]);
        for i in 0..n {
            (mean[i], slope[i]) = match layout.roles[i] {
                Role::Out | Role::Element => (0.0, 0.0),
                Role::Slip(s) => (s * self.limit_mean[i], s * self.limit_slope[i]),
                Role::Free => (self.start_mean[i] + z[i], self.start_slope[i]),
            };
        }
        let mut pieces: Vec<Piece> = start.map_or(Vec::new(), |m| {
            m.cells
                .pieces
                .iter()
                .filter(|p| layout.roles[p.cell] == Role::Free)
                .cloned()
                .collect()
        });
        let mut add = |element: Element, coefficient: f64| {
            let [lo, hi] = element.range();
            if hi <= lo || coefficient == 0.0 {
                return;
            }
            let first = (((lo - edge0) / w).floor().max(0.0) as usize).min(n - 1);
            for cell in first..n {
                let (cl, ch) = (self.x[cell] - 0.5 * w, self.x[cell] + 0.5 * w);
                if cl >= hi {
                    break;
                }
                let (a, b) = (cl.max(lo), ch.min(hi));
                if b > a {
                    pieces.push(Piece {
                        cell,
                        element: element.clipped(a, b),
                        coefficient,
                    });
                }
            }
        };
        for (q, e) in layout.ends.iter().enumerate() {
            let root = &unknown[2 * q + 1];
            let amplitude = specials[2 * q + 1];
            add(root.near.clone(), amplitude);
            if let Some((m, s)) = &root.far {
                for i in 0..n {
                    mean[i] += amplitude * m[i];
                    slope[i] += amplitude * s[i];
                }
            }
            let [lo, hi] = e.support;
            let stick = Shape::Affine {
                centre: e.at,
                value: specials[2 * q],
                slope: slopes[q],
            };
            add(Element::new(lo, hi, stick), 1.0);
            for h in &held[q] {
                add(h.root(e), h.kink.amplitude);
            }
            let [lo, hi] = e.slip_part;
            if hi > lo {
                let [value, s] = self.limit_fit(e.cell, e.sign, lo, hi);
                let limit = Shape::Affine {
                    centre: 0.5 * (lo + hi),
                    value,
                    slope: s,
                };
                add(Element::new(lo, hi, limit), 1.0);
            }
        }
        self.fold_oldest(&mut pieces, &mut mean, &mut slope);
        Cells {
            mean,
            slope,
            pieces,
        }
    }

    /// Keeps at most [`PIECES_PER_CELL`] pieces per cell: the oldest beyond go into the cell's
    /// mean and slope.
    pub(super) fn fold_oldest(&self, pieces: &mut Vec<Piece>, mean: &mut [f64], slope: &mut [f64]) {
        let w = self.width;
        let mut count = vec![0usize; self.x.len()];
        for p in pieces.iter() {
            count[p.cell] += 1;
        }
        if count.iter().all(|c| *c <= PIECES_PER_CELL) {
            return;
        }
        pieces.retain(|p| {
            if count[p.cell] <= PIECES_PER_CELL {
                return true;
            }
            count[p.cell] -= 1;
            let xc = self.x[p.cell];
            mean[p.cell] += p.coefficient * p.element.moment(0, xc) / w;
            slope[p.cell] += p.coefficient * 12.0 * p.element.moment(1, xc) / (w * w * w);
            false
        });
    }
}
