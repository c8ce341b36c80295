//! The layout of one solve of a sub-step: which cells are out, slip, or stick with an unknown
//! constant of their own, and, at each stick-slip boundary located inside a cell, the boundary
//! element that covers the stick side of that cell (`docs/convergence.md`, "Sub-cell stick-slip
//! boundaries").
//!
//! A stick zone whose end meets a slipping cell has that end at a point `at` inside a cell. The
//! stick part of that cell, `[e, at]` (e its cell edge), and the neighbouring stick cell form
//! the boundary element, one unknown constant collocated half a cell from `at`, between one and
//! two cells long. The slip part `[at, e']` carries the limit traction.
//!
//! Why always merged and collocated there: the located boundary's error is a function of where
//! `at` falls in its cell, and it vanishes where the element is one whole cell collocated at its
//! centre. With the stick part alone as the element from half a cell up (collocated at its
//! midpoint) and merged below (collocated at the neighbour's centre), `at` was off by up to
//! 7e-4 cells, with a jump where the two met; always merged and collocated half a cell from
//! `at`, the collocation points keep the spacing of whole cells next to the boundary and `at`
//! was off by 0 to 2.4e-4 cells (Cattaneo, 1600 cells, the boundary swept over four cells;
//! docs/convergence.md), and by +1.3e-4 to +2.6e-4 wherever it falls once the root's taper was
//! made flat at the boundary (`kernel.rs`). Collocated half a cell from `at`, the stick part
//! alone (shorter than a cell) put its point on or near the element's end, and `at` went up to
//! 9e-3 cells off.
//!
//! Owns the geometry of a layout only. Never solves anything.

use super::marcher::Cell;

/// What a cell is in one solve.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(super) enum Role {
    Out,
    /// Slipping: the limit traction with this sign.
    Slip(f64),
    /// Stuck, with its own unknown constant traction increment.
    Free,
    /// Covered, wholly or in part, by a boundary element.
    Element,
}

/// A stick-slip boundary inside a cell, with its boundary element.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(super) struct SoftEnd {
    /// Where the boundary is.
    pub at: f64,
    /// 1: the stick zone is to the left of `at` (the zone's right end); -1: to the right.
    pub side: f64,
    /// The slip direction on the slip side.
    pub sign: f64,
    /// The cell holding `at`.
    pub cell: usize,
    /// The boundary element, on the stick side of `at`.
    pub support: [f64; 2],
    /// Its collocation point, half a cell from `at`.
    pub colloc: f64,
    /// The stick cell next to `cell`, which the element covers too.
    pub merged: usize,
    /// The slip part of `cell`.
    pub slip_part: [f64; 2],
    /// The zone.
    pub zone: [f64; 2],
    /// The square root's window: the zone's length, or half of it when the zone's other end is
    /// a boundary too (so that neither root reaches the other end).
    pub window: f64,
}

impl SoftEnd {
    /// The square root of this boundary (unit amplitude) over its window within the zone.
    pub(super) fn root(&self) -> (f64, f64, super::kernel::Shape) {
        let (lo, hi) = if self.side > 0.0 {
            ((self.at - self.window).max(self.zone[0]), self.at)
        } else {
            (self.at, (self.at + self.window).min(self.zone[1]))
        };
        (
            lo,
            hi,
            super::kernel::Shape::Root {
                at: self.at,
                side: self.side,
                window: self.window,
            },
        )
    }
}

/// One end of a stick zone as the cell-level active set left it.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(super) enum End {
    /// Next to a cell out of contact or the end of the grid: a cell edge.
    Hard,
    /// Next to a slipping cell (this sign): a boundary inside a cell, at this point.
    Soft { at: f64, sign: f64 },
}

/// A stick zone: its cells from the cell-level active set and its two ends.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(super) struct Zone {
    pub first: usize,
    pub last: usize,
    pub left: End,
    pub right: End,
}

/// A layout: every cell's role and the boundaries inside cells.
#[derive(Debug, Clone, PartialEq)]
pub(super) struct Layout {
    pub roles: Vec<Role>,
    pub ends: Vec<SoftEnd>,
    /// Each zone's extent `[left, right]` (a boundary or a cell edge).
    pub zones: Vec<[f64; 2]>,
}

/// The zones of a cell-level state (runs of stick cells), with their ends at the cell edges.
pub(super) fn zones_of(cells: &[Cell], x: &[f64], width: f64) -> Vec<Zone> {
    let n = cells.len();
    let mut zones = Vec::new();
    let mut i = 0;
    while i < n {
        if cells[i] != Cell::Stick {
            i += 1;
            continue;
        }
        let first = i;
        while i + 1 < n && cells[i + 1] == Cell::Stick {
            i += 1;
        }
        let last = i;
        let left = match first.checked_sub(1).map(|j| cells[j]) {
            Some(Cell::Slip(sign)) => End::Soft {
                at: x[first] - 0.5 * width,
                sign,
            },
            _ => End::Hard,
        };
        let right = match cells.get(last + 1) {
            Some(Cell::Slip(sign)) => End::Soft {
                at: x[last] + 0.5 * width,
                sign: *sign,
            },
            _ => End::Hard,
        };
        zones.push(Zone {
            first,
            last,
            left,
            right,
        });
        i += 1;
    }
    zones
}

/// The layout of `zones` over the cell-level state `cells` (cells `x`, width `width`): cells of
/// a zone are free unknowns, cells of a boundary element are `Element`; outside the zones, cells
/// keep their cell-level role, and stick cells a boundary has left behind slip with that
/// boundary's sign. `None` when a zone is too short for its boundary elements (fewer than one
/// free cell between them), or a boundary leaves its zone's cells or the grid.
pub(super) fn layout(cells: &[Cell], x: &[f64], width: f64, zones: &[Zone]) -> Option<Layout> {
    let n = cells.len();
    let edge = |i: usize| x[i] - 0.5 * width;
    let cell_of = |at: f64| ((at - edge(0)) / width).floor();
    let mut roles: Vec<Role> = cells
        .iter()
        .map(|c| match c {
            Cell::Out => Role::Out,
            Cell::Slip(s) => Role::Slip(*s),
            // A stick cell no zone claims: set below from the nearest boundary.
            Cell::Stick => Role::Slip(0.0),
        })
        .collect();
    let mut ends = Vec::new();
    let mut extents = Vec::new();
    for z in zones {
        // Cells strictly inside the zone, and its extent.
        let (mut lo, mut lo_x) = (z.first, edge(z.first));
        let (mut hi, mut hi_x) = (z.last, edge(z.last) + width);
        if let End::Soft { at, .. } = z.left {
            let k = cell_of(at);
            if !(k >= 0.0 && (k as usize) < n) {
                return None;
            }
            lo = k as usize;
            lo_x = at;
        }
        if let End::Soft { at, .. } = z.right {
            let k = cell_of(at);
            if !(k >= 0.0 && (k as usize) < n) {
                return None;
            }
            hi = k as usize;
            hi_x = at;
        }
        if hi_x <= lo_x {
            return None;
        }
        let zone = [lo_x, hi_x];
        let both = matches!((z.left, z.right), (End::Soft { .. }, End::Soft { .. }));
        let window = if both { 0.5 } else { 1.0 } * (hi_x - lo_x);
        // Free cells: [free_lo, free_hi] after the boundary elements take their cells.
        let (mut free_lo, mut free_hi) = (lo as i64, hi as i64);
        if let End::Soft { at, sign } = z.left {
            let k = lo;
            if k + 1 >= n {
                return None;
            }
            free_lo = k as i64 + 2;
            ends.push(SoftEnd {
                at,
                side: -1.0,
                sign,
                cell: k,
                support: [at, edge(k) + 2.0 * width],
                colloc: at + 0.5 * width,
                merged: k + 1,
                slip_part: [edge(k), at],
                zone,
                window,
            });
        }
        if let End::Soft { at, sign } = z.right {
            let k = hi;
            if k == 0 {
                return None;
            }
            free_hi = k as i64 - 2;
            ends.push(SoftEnd {
                at,
                side: 1.0,
                sign,
                cell: k,
                support: [edge(k) - width, at],
                colloc: at - 0.5 * width,
                merged: k - 1,
                slip_part: [at, edge(k) + width],
                zone,
                window,
            });
        }
        if free_hi < free_lo {
            return None;
        }
        if (lo..=hi).any(|i| cells[i] == Cell::Out) {
            return None;
        }
        // Cells of the zone: hard ends keep their cells; the boundary cells are elements.
        for (i, role) in roles.iter_mut().enumerate().take(hi + 1).skip(lo) {
            *role = if (i as i64) < free_lo || (i as i64) > free_hi {
                Role::Element
            } else {
                Role::Free
            };
        }
        extents.push(zone);
    }
    // Overlapping zones are not a layout.
    for w in extents.windows(2) {
        if w[1][0] < w[0][1] + width {
            return None;
        }
    }
    // Stick cells left outside every zone slip with the nearest boundary's sign.
    for i in 0..n {
        if roles[i] == Role::Slip(0.0) {
            let nearest = ends
                .iter()
                .min_by(|a, b| (a.at - x[i]).abs().total_cmp(&(b.at - x[i]).abs()));
            match nearest {
                Some(e) => roles[i] = Role::Slip(e.sign),
                None => return None,
            }
        }
    }
    Some(Layout {
        roles,
        ends,
        zones: extents,
    })
}

impl Layout {
    /// Whether cell `i` (centre `x`) is stuck in this layout: a free cell, or an element cell
    /// whose centre is on the stick side of its boundary.
    pub(super) fn sticks(&self, i: usize, x: f64) -> bool {
        match self.roles[i] {
            Role::Free => true,
            Role::Element => !self
                .ends
                .iter()
                .any(|e| e.cell == i && e.side * (x - e.at) >= 0.0),
            _ => false,
        }
    }

    /// The cells that are free unknowns.
    pub(super) fn free(&self) -> Vec<bool> {
        self.roles.iter().map(|r| *r == Role::Free).collect()
    }
}
