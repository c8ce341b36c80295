//! Where an increment is split: the load fractions at which a contact end passes a cell centre
//! (docs/theory.md, "Time marching": moving edges, exactly), each with the contact there, found
//! from the contact law on the mirrored grid or by bisection on each end.
//!
//! Owns the sub-step ends of [`Marcher::step`] and each sub-step's pressure and cells in contact
//! (`press`). Never solves the tangential problem.

use super::marcher::{Cell, Marcher};
use crate::error::{Error, Result};
use crate::labels::Edge;
use crate::load::LoadPoint;
use crate::normal_moment::NormalContact;
use std::f64::consts::PI;

impl Marcher {
    /// The sub-step ends inside an increment from `start` (`None`: unloaded) to `load`, whose
    /// contact is `target`: every fraction t in (0, 1) where a contact end passes a cell centre,
    /// with the contact there (that end exactly at the centre), in increasing t.
    ///
    /// A centred contact at both ends of the increment (symmetric profile, no moment) crosses
    /// cell centres in pairs on the mirrored grid: the fraction comes from the contact law,
    /// `t = (P(x_c) - P_start)/(P_end - P_start)`. Otherwise each end's crossings are found on
    /// their own by [`Marcher::crossing`].
    pub(super) fn crossings(
        &self,
        start: Option<LoadPoint>,
        load: &LoadPoint,
        target: &NormalContact,
    ) -> Result<Vec<(f64, NormalContact)>> {
        let from_normal = start.map_or(0.0, |p| p.normal());
        let centred = target.is_centred() && self.state.is_none_or(|s| s.is_centred());
        let mut crossings: Vec<(f64, NormalContact)> = Vec::new();
        if centred {
            let n = self.x.len();
            let a0 = self.state.map_or(0.0, |s| s.half_width());
            let a = target.half_width();
            let (lo, hi) = (a0.min(a), a0.max(a));
            for &r in &self.x[n / 2..] {
                if r > lo && r < hi {
                    let normal = self.contact.load(r)?;
                    let t = (normal - from_normal) / (load.normal() - from_normal);
                    if t > 0.0 && t < 1.0 {
                        let k_n = self.contact.normal_intensity(r)?;
                        let at = NormalContact::centred(normal, r, k_n);
                        crossings.push((t, at));
                    }
                }
            }
        } else {
            // From unloaded, the ends start where the smallest load puts them (a point at M/P
            // for Hertz, about the flat for a flat punch).
            let begin = match (&self.state, start) {
                (Some(s), _) => *s,
                (None, _) => self.contact.contact_at(&load.scaled(1e-9))?,
            };
            for edge in Edge::BOTH {
                let (from, to) = (begin.end(edge), target.end(edge));
                let (lo, hi) = (from.min(to), from.max(to));
                let first = self.x.partition_point(|&x| x <= lo);
                for &r in self.x[first..].iter().take_while(|&&x| x < hi) {
                    if let Some(found) = self.crossing(start, load, &begin, target, edge, r)? {
                        crossings.push(found);
                    }
                }
            }
        }
        crossings.sort_by(|p, q| p.0.total_cmp(&q.0));
        Ok(crossings)
    }

    /// The fraction t of the increment from `start` to `load` at which the contact end `edge`
    /// reaches `centre`, with the contact there (that end set to `centre` exactly): Newton's
    /// method on `b(t) - centre` with the end's exact speed ([`NormalContact::edge_load_changes`]:
    /// an end moves out by `2 dP_edge/(pi sqrt(2a) K_N)` per unit of the load change), each
    /// contact solved from the previous one, inside a bracket that bisection keeps. `None` when
    /// the end does not reach the centre inside (0, 1) (it moved there and back within the
    /// increment).
    fn crossing(
        &self,
        start: Option<LoadPoint>,
        load: &LoadPoint,
        begin: &NormalContact,
        target: &NormalContact,
        edge: Edge,
        centre: f64,
    ) -> Result<Option<(f64, NormalContact)>> {
        let at = |t: f64| match start {
            Some(from) => from.lerp(load, t),
            None => load.scaled(t),
        };
        let (from, to) = (begin.end(edge), target.end(edge));
        let rising = to > from;
        // residual(t) = b(t) - centre, negative at t = 0 when the end rises through the centre.
        let (mut lo, mut hi) = (0.0, 1.0);
        let mut t = ((centre - from) / (to - from)).clamp(0.0, 1.0);
        let mut near = if t < 0.5 { *begin } else { *target };
        let scale = 1e-13 * (self.width + begin.half_width().max(target.half_width()));
        for _ in 0..60 {
            let point = at(t);
            near = self
                .contact
                .contact_near(point.normal(), point.moment(), &near)?;
            let residual = near.end(edge) - centre;
            if residual.abs() <= scale || hi - lo <= 1e-15 {
                if t <= 0.0 || t >= 1.0 {
                    return Ok(None);
                }
                return Ok(Some((t, near.with_end(edge, centre))));
            }
            if (residual < 0.0) == rising {
                lo = t;
            } else {
                hi = t;
            }
            // The end's rate along the increment: the load change over it is (load - start).
            let (d_normal, d_moment) = match start {
                Some(p) => (load.normal() - p.normal(), load.moment() - p.moment()),
                None => (load.normal(), load.moment()),
            };
            let d_edge = near.edge_load_changes(d_normal, d_moment)[edge];
            let outward = 2.0 * d_edge
                / (PI * (2.0 * near.half_width()).sqrt() * near.normal_intensity(edge));
            let rate = match edge {
                Edge::Left => -outward,
                Edge::Right => outward,
            };
            let newton = t - residual / rate;
            t = if newton > lo && newton < hi && newton.is_finite() {
                newton
            } else {
                0.5 * (lo + hi)
            };
        }
        Err(Error::NoConvergence {
            what: "load fraction where a contact end crosses a cell centre",
            iterations: 60,
            last_step: hi - lo,
        })
    }

    /// The pressure of the new contact `target` and the cells in contact: a cell stays in
    /// contact until the receding edge reaches its centre (its pressure, and so its traction, is
    /// zero then) and joins, sticking, when the advancing edge does. Keeps the sub-step's start.
    pub(super) fn press(&mut self, target: &NormalContact) -> Result<()> {
        self.target = Some(*target);
        self.pressure_start.copy_from_slice(&self.pressure);
        let (now, then) = (
            target.ends(),
            self.state.map_or(target.ends(), |s| s.ends()),
        );
        let (lower, upper) = (now.left.min(then.left), now.right.max(then.right));
        for i in 0..self.x.len() {
            if let Some(gap) = &self.gap {
                // On the grid the solved pressure says which cells touch.
                let p = gap.solution.as_ref().map_or(0.0, |s| s.pressure[i]);
                self.pressure[i] = p;
                match (p > 0.0, self.cells[i]) {
                    (false, _) => self.cells[i] = Cell::Out,
                    (true, Cell::Out) => self.cells[i] = Cell::Stick,
                    _ => {}
                }
                continue;
            }
            let inside = self.x[i] > lower && self.x[i] < upper;
            self.pressure[i] = if inside {
                self.contact.pressure_at(target, self.x[i])?
            } else {
                0.0
            };
            match (inside, self.cells[i]) {
                (false, _) => self.cells[i] = Cell::Out,
                (true, Cell::Out) => self.cells[i] = Cell::Stick,
                _ => {}
            }
        }
        self.start_cells.copy_from_slice(&self.cells);
        Ok(())
    }
}
