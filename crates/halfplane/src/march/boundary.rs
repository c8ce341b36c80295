//! Stick-slip boundaries inside cells (`docs/convergence.md`, "Sub-cell stick-slip
//! boundaries"): where the cell-level active set ends a stick zone next to slipping cells at both
//! ends, [`Marcher::refine`] moves both ends continuously until the traction meets the friction
//! limit there without a jump, and [`Marcher::view`] reports the increment so solved.
//!
//! **Locating a boundary.** For boundaries at trial points `at`, `evaluate.rs` solves the
//! sub-step with the square root of each boundary among the unknowns and returns at each the jump
//! `J = s q(at-) - f p(at)` of the stick side's traction over the limit. In exact theory the stick
//! zone's traction has an inverse square-root singularity at a wrong end, of either sign; the
//! discrete jump measures it and is nearly linear in `at` inside a cell (slope about
//! `0.5 f p0` per cell). The boundaries are its roots, found boundary by boundary (secant, then
//! regula falsi inside a bracket) from the cell edges the active set left.
//!
//! **What it changes.** The solution reported for the increment: its traction at the cells'
//! centres, its boundaries ([`TractionKink`], for the stresses' node form) and the ends of its
//! stick intervals. The march goes on from the cell-level solution: coupled into the state, the
//! located boundaries made the cycle's end state depend on where each boundary fell in its cell
//! (a different discrete problem every increment), so cycles stopped repeating to rounding and
//! cells left at the limit by a ramp crept (docs/convergence.md gives the measurements). The
//! located solve starts from the cell-level state at the increment's last sub-step, or, within a
//! stretch of the history whose slip zones only grow, from the located solution at the stretch's
//! start (`chain.rs`).
//!
//! Owns the boundaries' search and the reported view. Never solves a linear system itself
//! (`evaluate.rs` does) and never changes the state the next increment starts from.

use super::chain::{Kink, Model};
use super::layout::{layout, zones_of, End, Layout, Role};
use super::marcher::{Cell, Marcher};
use crate::error::Result;
use crate::labels::Edge;
use crate::load::LoadPoint;
use crate::normal_moment::NormalContact;

/// Most solves spent on locating the boundaries of one sub-step.
const MAX_SOLVES: usize = 16;
/// A jump below this fraction of `f p_max` at the cell-level ends is no boundary to locate.
const QUIET: f64 = 1e-4;

/// A stick-slip boundary located inside its cell, or an earlier one that a stick zone holds: the
/// shear traction is continuous there and has a square root on the (then) stick side,
/// `q(x) = shear + amplitude sqrt(|x - x_b|) + (smooth)` on the `root` side, so that the stick
/// zone's traction met the friction limit with an infinite slope. The node form of
/// [`crate::stress::Traction::from_march_ends`] gives it its own node and its square root
/// exactly over up to four cell intervals on its stick side.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct TractionKink {
    /// Where the kink is.
    pub x: f64,
    /// The side of `x` carrying the square root (the stick side of a boundary).
    pub root: Edge,
    /// `amplitude`: the coefficient of `sqrt(|x - x_b|)`.
    pub amplitude: f64,
    /// The shear traction at `x`.
    pub shear: f64,
    /// The pressure at `x`.
    pub pressure: f64,
}

/// The increment's end as reported with its stick-slip boundaries inside their cells: the
/// centre tractions, the boundaries, the accumulated slip and the relative displacement (datum
/// the kernel's scale; `report.rs`).
#[derive(Debug, Clone, PartialEq)]
pub(super) struct View {
    pub traction: Vec<f64>,
    pub kinks: Vec<TractionKink>,
    pub slip: Vec<f64>,
    pub displacement: f64,
}

impl View {
    /// What a located solution reports, with its boundaries' `kinks` as reported.
    pub(super) fn of(located: &Model, kinks: Vec<TractionKink>) -> Self {
        Self {
            traction: located.centre.clone(),
            kinks,
            slip: located.slip.clone(),
            displacement: located.displacement,
        }
    }
}

impl Marcher {
    /// The increment solved again with its stick-slip boundaries located inside their cells
    /// (`refine`), for what the increment reports: its last sub-step from the cell-level state
    /// at that sub-step's start, or the whole stretch from its located start (`chain.rs`). The
    /// state goes on from the cell-level solution, whose buffers are restored. `None` when no
    /// stretch runs and no zone has a boundary next to a slipping cell at both ends (or the
    /// search finds none to locate): the cell-level state is reported. Returns the solves used.
    pub(super) fn view(
        &mut self,
        load: LoadPoint,
        target: &NormalContact,
        d_sigma: f64,
        step: usize,
    ) -> Result<usize> {
        self.view = None;
        self.limits(target);
        if let Some(last) =
            (self.located.as_ref()).filter(|m| m.load == load && m.pressure == self.pressure)
        {
            // A dwell moves nothing in exact theory: it reports the last located solution, which
            // a solve by another route (from the stretch's start after one from the cell level)
            // moved by up to 3.2e-2 f p0, with a negative energy (a reviewer's history).
            self.view = Some(View::of(last, self.reported_kinks.clone()));
            return Ok(0);
        }
        let saved = (
            self.dq.clone(),
            self.sub_slip.clone(),
            self.known.clone(),
            self.g_known.clone(),
            self.shift,
        );
        // Where the located solve starts (`chain.rs`): a stretch's located start, over the
        // load change since it, or the cell-level state at this sub-step.
        // A slip below rounding is no slip (as for the active set's reversals, `marcher.rs`).
        let rounding = 1e-13 * self.compliance * self.friction * load.normal();
        self.stretch = self.stretch_for(&saved.1, rounding);
        let cell_level = self.traction.clone();
        if let Some(solves) = self.superposed(load, step)? {
            (self.dq, self.sub_slip, self.known, self.g_known, self.shift) = saved;
            return Ok(solves);
        }
        let mut solves = self.located_from(&cell_level, d_sigma, load, step)?;
        let mut from_start = self.stretch.is_some();
        let start_breaks_limit = || {
            self.stretch
                .as_ref()
                .is_some_and(|s| !self.keeps_limit_from(&s.start.centre))
        };
        if from_start && start_breaks_limit() {
            // The solution from the stretch's start breaks the friction limit (2.2e-3 f p0, a
            // reviewer's history: Q to 300, then Q and bulk stress cycled in phase): this
            // increment is solved from the cell level (the stretch goes on for the next).
            let stretch = self.stretch.take();
            solves += self.located_from(&cell_level, d_sigma, load, step)?;
            self.stretch = stretch;
            from_start = false;
        }
        if !from_start && !self.keeps_limit_from(&cell_level) {
            // Solved from the cell level it breaks the limit too (the same history): the
            // increment reports the cell-level solution.
            self.layout = None;
        }
        self.located = None;
        if let (Some(lay), Some(cells)) = (self.layout.take(), self.end_model.take()) {
            let start = self
                .stretch
                .as_ref()
                .filter(|_| from_start)
                .map(|s| &s.start);
            let base = start.map_or(&cell_level, |s| &s.centre);
            let traction: Vec<f64> = base.iter().zip(&self.dq).map(|(q, d)| q + d).collect();
            // The slip and the rigid displacement go on from the start's likewise; the
            // cell-level start's displacement is the state's before the sub-step's own shift.
            let c_disp = self.compliance / std::f64::consts::PI;
            let (base_slip, base_displacement) = start
                .map_or((&self.slip, self.displacement + c_disp * saved.4), |s| {
                    (&s.slip, s.displacement)
                });
            let slip: Vec<f64> = base_slip
                .iter()
                .zip(&self.sub_slip)
                .map(|(s, d)| s + d)
                .collect();
            let displacement = base_displacement - c_disp * self.shift;
            let amplitudes: Vec<f64> = self.end_solutions.iter().map(|s| s.amplitude).collect();
            let reported: Vec<f64> = (self.end_solutions.iter())
                .map(|s| s.amplitude + s.nearby)
                .collect();
            let (kinks, new) = self.kinks_of(&lay, &reported, &amplitudes)?;
            let w = self.width;
            let merged: Vec<Kink> = start.map_or(Vec::new(), |s| {
                (lay.ends.iter())
                    .flat_map(|e| s.held(e, w))
                    .filter(|h| h.merged)
                    .map(|h| h.kink)
                    .collect()
            });
            let kept = self.kept_kinks(&lay, start, new, |k| merged.contains(k));
            let located = Model {
                centre: traction,
                cells,
                kinks: kept,
                load,
                pressure: self.pressure.clone(),
                slip,
                displacement,
                ends: lay.ends.iter().map(|e| [e.at, e.side, e.sign]).collect(),
            };
            if !lay.ends.is_empty() || from_start {
                let kinks = self.with_locked_kinks(kinks, &located, &lay)?;
                self.view = Some(View::of(&located, kinks));
            }
            self.located = Some(located);
        }
        (self.dq, self.sub_slip, self.known, self.g_known, self.shift) = saved;
        Ok(solves)
    }

    /// The kinks of the boundaries of `lay`: as reported with the square roots' `reported`
    /// amplitudes (for the stresses' node form) and as a located solution keeps them, with their
    /// `kept` ones.
    pub(super) fn kinks_of(
        &self,
        lay: &Layout,
        reported: &[f64],
        kept: &[f64],
    ) -> Result<(Vec<TractionKink>, impl Iterator<Item = Kink>)> {
        let mut kinks = Vec::with_capacity(lay.ends.len());
        let mut new = Vec::with_capacity(lay.ends.len());
        for ((e, &amplitude), &whole) in lay.ends.iter().zip(reported).zip(kept) {
            let pressure = self.pressure_at(e.at)?;
            let kink = Kink {
                x: e.at,
                side: e.side,
                amplitude: whole,
                window: e.window,
            };
            let shear = e.sign * self.friction * pressure;
            kinks.push(reported_kink(&kink, amplitude, shear, pressure));
            new.push(kink);
        }
        Ok((kinks, new.into_iter()))
    }

    /// `kinks` (the boundaries') and the kinks of `located` that its stick zones hold further than
    /// [`super::chain::SAME_KINK`] cells from a boundary with their stick side (those nearer are reported with
    /// the boundary's), each with the located traction and the pressure there: as reported, for
    /// the stresses' node form. Without them, one increment after a reversal of Q = 300 the
    /// surface `sxx` at the first loading's boundary, held in the stick zone, was 1.7e-2 p0 off
    /// McEwen's fields at 1600 cells (`tests/sub_cell.rs`).
    pub(super) fn with_locked_kinks(
        &self,
        mut kinks: Vec<TractionKink>,
        located: &Model,
        lay: &Layout,
    ) -> Result<Vec<TractionKink>> {
        let w = self.width;
        for k in &located.kinks {
            if (lay.ends.iter()).any(|e| k.next_to(e.at, e.side, w)) {
                continue;
            }
            let (shear, pressure) = (self.smooth_at(&located.centre, k), self.pressure_at(k.x)?);
            kinks.push(reported_kink(k, k.amplitude, shear, pressure));
        }
        Ok(kinks)
    }

    /// The traction at kink `k` from the centre values `centre` of the cells either side: their
    /// values less the kink's root, interpolated linearly (what the node form does between its
    /// nodes). Evaluating the located model there instead was off wherever its oldest pieces had
    /// been folded into the cells' means.
    fn smooth_at(&self, centre: &[f64], k: &Kink) -> f64 {
        let n = self.x.len();
        let i = self.x.partition_point(|&x| x <= k.x).clamp(1, n - 1) - 1;
        let smooth = |j: usize| {
            let d = k.side * (k.x - self.x[j]);
            centre[j] - if d > 0.0 { k.amplitude * d.sqrt() } else { 0.0 }
        };
        let t = (k.x - self.x[i]) / (self.x[i + 1] - self.x[i]);
        (1.0 - t) * smooth(i) + t * smooth(i + 1)
    }

    /// The located solve of the increment from the stretch's start (over the load change since
    /// it) or, without one, from `cell_level` (the cell-level state at the last sub-step, whose
    /// tension change is `d_sigma`). Leaves `traction` as it found it (`cell_level`). Returns
    /// the solves used.
    fn located_from(
        &mut self,
        cell_level: &[f64],
        d_sigma: f64,
        load: LoadPoint,
        step: usize,
    ) -> Result<usize> {
        let d_sigma = match &self.stretch {
            Some(s) => {
                self.traction.copy_from_slice(&s.start.centre);
                self.start_mean.copy_from_slice(&s.start.cells.mean);
                self.start_slope.copy_from_slice(&s.start.cells.slope);
                load.bulk() - s.start.load.bulk()
            }
            None => {
                self.start_mean.copy_from_slice(cell_level);
                self.start_slope.fill(0.0);
                d_sigma
            }
        };
        self.layout = None;
        let solves = self.located_solve(d_sigma, load.shear(), step);
        self.traction.copy_from_slice(cell_level);
        solves
    }

    /// Whether the located solve just made, added to the start `base` (centre values), keeps
    /// the friction limit.
    fn keeps_limit_from(&self, base: &[f64]) -> bool {
        let traction: Vec<f64> = base.iter().zip(&self.dq).map(|(q, d)| q + d).collect();
        self.keeps_limit(&traction)
    }

    /// [`Marcher::refine`]; from a stretch's located start with no boundary to locate, the
    /// cell-level layout solved from that start (its cells stuck since the start keep its
    /// traction). Returns the solves used.
    fn located_solve(&mut self, d_sigma: f64, shear: f64, step: usize) -> Result<usize> {
        let solves = self.refine(d_sigma, shear, step)?;
        if self.layout.is_some() || self.stretch.is_none() {
            return Ok(solves);
        }
        let lay = Layout::cells(&self.cells, &self.x, self.width);
        self.end_solutions = self.evaluate(&lay, d_sigma, shear, step)?;
        self.layout = Some(lay);
        Ok(solves + 1)
    }

    /// Locates the stick-slip boundaries of the sub-step inside their cells, starting from the
    /// cell-level active set's zones, and leaves the solution of the last solve in the work
    /// buffers with its layout in `self.layout`. Returns the solves used (none without a zone end
    /// next to a slipping cell: the cell-level solution stands).
    ///
    /// Each boundary is searched on its own jump (the others move at the same time; they couple
    /// only through the resultant and the zone): a secant step on the last two points, or on the
    /// slope `f p_max/(2 w)` at first, until the jump changes sign, then regula falsi (Illinois)
    /// inside the bracket. The jump is continuous inside a cell but steps where `at` crosses a
    /// cell edge (the element goes from two cells to one); a root there is taken at the step
    /// (the bracket closes on it).
    pub(super) fn refine(&mut self, d_sigma: f64, shear: f64, step: usize) -> Result<usize> {
        let w = self.width;
        // Only zones with a boundary at both ends: a zone that reaches a contact edge (full stick
        // at an advancing edge) keeps cell-level ends, where its one boundary's jump was found to
        // wander (a few cells of stick between the edge and a slip zone).
        let zones: Vec<super::layout::Zone> = zones_of(&self.cells, &self.x, w)
            .into_iter()
            .map(|mut z| {
                if !matches!((z.left, z.right), (End::Soft { .. }, End::Soft { .. })) {
                    (z.left, z.right) = (End::Hard, End::Hard);
                }
                z
            })
            .collect();
        let soft: Vec<(usize, bool)> = zones
            .iter()
            .enumerate()
            .flat_map(|(z, zone)| {
                let mut v = Vec::new();
                if matches!(zone.left, End::Soft { .. }) {
                    v.push((z, false));
                }
                if matches!(zone.right, End::Soft { .. }) {
                    v.push((z, true));
                }
                v
            })
            .collect();
        if soft.is_empty() {
            return Ok(0);
        }
        // Each boundary's outward coordinate y = side at (its jump grows with y).
        let side = |right: bool| if right { 1.0 } else { -1.0 };
        let mut searches: Vec<Search> = soft
            .iter()
            .map(|&(z, right)| {
                let end = if right { zones[z].right } else { zones[z].left };
                let End::Soft { at, .. } = end else {
                    unreachable!("only soft ends are searched")
                };
                Search::new(side(right) * at)
            })
            .collect();
        let place = |searches: &[Search]| {
            let mut zs = zones.clone();
            for (&(z, right), sr) in soft.iter().zip(searches) {
                let at = side(right) * sr.y;
                let end = if right {
                    &mut zs[z].right
                } else {
                    &mut zs[z].left
                };
                if let End::Soft { sign, .. } = *end {
                    *end = End::Soft { at, sign };
                }
            }
            zs
        };
        let f_scale = self.friction * self.pressure.iter().fold(0.0f64, |a, p| a.max(*p));
        let slope = 0.5 * f_scale / w;
        let mut solves = 0;
        let mut best: Option<(f64, Vec<f64>)> = None;
        while solves < MAX_SOLVES {
            let Some(lay) = layout(&self.cells, &self.x, w, &place(&searches)) else {
                break;
            };
            if lay
                .roles
                .iter()
                .zip(&self.cells)
                .any(|(r, c)| *c == Cell::Out && *r != Role::Out)
            {
                break;
            }
            solves += 1;
            let ends = self.evaluate(&lay, d_sigma, shear, step)?;
            let mut done = true;
            for (sr, e) in searches.iter_mut().zip(&ends) {
                done &= sr.record(e.jump, 1e-10 * f_scale, 1e-9 * w);
            }
            let size = ends.iter().fold(0.0f64, |a, e| a.max(e.jump.abs()));
            if solves == 1 && size <= QUIET * f_scale {
                // The traction meets the limit at the cell edges already: the boundaries are
                // there (or in a band of cells at the limit, where the jump is only
                // discretisation noise and any point of the band would do).
                self.end_solutions = ends;
                self.layout = Some(lay);
                return Ok(solves);
            }
            if best.as_ref().is_none_or(|b| size < b.0) {
                best = Some((size, searches.iter().map(|s| s.y).collect()));
            }
            self.end_solutions = ends;
            self.layout = Some(lay);
            if done {
                return Ok(solves);
            }
            for sr in searches.iter_mut() {
                sr.advance(slope, w);
            }
        }
        // Not converged: the best point if its jumps are small (a root at a step of the jump
        // between two branches leaves them at the step's size), else the cell-level layout.
        if let Some((size, ys)) = best {
            if size <= 1e-2 * f_scale {
                for (sr, y) in searches.iter_mut().zip(ys) {
                    sr.y = y;
                }
                if let Some(lay) = layout(&self.cells, &self.x, w, &place(&searches)) {
                    self.end_solutions = self.evaluate(&lay, d_sigma, shear, step)?;
                    self.layout = Some(lay);
                    return Ok(solves + 1);
                }
            }
        }
        let lay = Layout::cells(&self.cells, &self.x, w);
        self.end_solutions = self.evaluate(&lay, d_sigma, shear, step)?;
        self.layout = Some(lay);
        Ok(solves + 1)
    }
}

/// The search for one boundary, in its outward coordinate y (the jump J grows with y).
struct Search {
    y: f64,
    jump: f64,
    /// The previous point and its jump.
    last: Option<(f64, f64)>,
    /// The bracket: the last points with J < 0 and with J > 0.
    below: Option<(f64, f64)>,
    above: Option<(f64, f64)>,
    /// How many times running the new point fell on the same side (+ above, - below): Illinois
    /// halves the jump of the end that stays.
    kept: i32,
}

impl Search {
    fn new(y: f64) -> Self {
        Self {
            y,
            jump: 0.0,
            last: None,
            below: None,
            above: None,
            kept: 0,
        }
    }

    /// Records the jump at the current point; true when it is within `tolerance` or the
    /// bracket is narrower than `width`.
    fn record(&mut self, jump: f64, tolerance: f64, width: f64) -> bool {
        self.jump = jump;
        if jump < 0.0 {
            self.kept = self.kept.min(0) - 1;
            self.below = Some((self.y, jump));
        } else {
            self.kept = self.kept.max(0) + 1;
            self.above = Some((self.y, jump));
        }
        let narrow = match (self.below, self.above) {
            (Some(b), Some(a)) => (a.0 - b.0).abs() <= width,
            _ => false,
        };
        jump.abs() <= tolerance || narrow
    }

    /// The next point: regula falsi inside a bracket (Illinois: when the new points keep falling
    /// on one side, the other end's jump is halved), else a secant step on the last two points
    /// or on `slope`, at most four cells.
    fn advance(&mut self, slope: f64, w: f64) {
        let (y, jump) = (self.y, self.jump);
        self.y = match (self.below, self.above) {
            (Some((yb, mut jb)), Some((ya, mut ja))) => {
                if self.kept >= 2 {
                    jb *= 0.5f64.powi(self.kept - 1);
                } else if self.kept <= -2 {
                    ja *= 0.5f64.powi(-self.kept - 1);
                }
                let t = (yb * ja - ya * jb) / (ja - jb);
                let (lo, hi) = (yb.min(ya), yb.max(ya));
                if t.is_finite() && t > lo && t < hi {
                    t
                } else {
                    0.5 * (lo + hi)
                }
            }
            _ => {
                let s = match self.last {
                    Some((y0, j0)) if y != y0 && (jump - j0) / (y - y0) > 0.0 => {
                        (jump - j0) / (y - y0)
                    }
                    _ => slope,
                };
                y - (jump / s).clamp(-4.0 * w, 4.0 * w)
            }
        };
        self.last = Some((y, jump));
    }
}

impl Layout {
    /// The layout of the cell-level state: stick cells free, no boundary inside a cell.
    pub(super) fn cells(cells: &[Cell], x: &[f64], width: f64) -> Layout {
        let roles = cells
            .iter()
            .map(|c| match c {
                Cell::Out => Role::Out,
                Cell::Slip(s) => Role::Slip(*s),
                Cell::Stick => Role::Free,
            })
            .collect();
        let zones = zones_of(cells, x, width)
            .iter()
            .map(|z| [x[z.first] - 0.5 * width, x[z.last] + 0.5 * width])
            .collect();
        Layout {
            roles,
            ends: Vec::new(),
            zones,
        }
    }
}

/// Kink `k` as reported, with the square root's `amplitude` there and the `shear` and
/// `pressure` at it.
fn reported_kink(k: &Kink, amplitude: f64, shear: f64, pressure: f64) -> TractionKink {
    TractionKink {
        x: k.x,
        root: if k.side > 0.0 {
            Edge::Left
        } else {
            Edge::Right
        },
        amplitude,
        shear,
        pressure,
    }
}
