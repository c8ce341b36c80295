//! The stick intervals an increment reports: maximal runs of contact cells that did not slip
//! during it (kinematically, by their slip travel), each ending at a cell edge or at the
//! stick-slip boundary located inside the cell next to it.

use super::marcher::{Cell, Marcher};
use crate::labels::{Edge, PerEdge};

impl Marcher {
    /// The stick intervals of the increment just solved: contact cells whose slip travel over
    /// its sub-steps is at most `tolerance`, within the contact `ends`.
    pub(super) fn stick_intervals(&self, ends: PerEdge<f64>, tolerance: f64) -> Vec<[f64; 2]> {
        let n = self.x.len();
        let mut stick_intervals: Vec<[f64; 2]> = Vec::new();
        let mut open: Option<usize> = None;
        for i in 0..=n {
            let sticks = i < n && self.cells[i] != Cell::Out && self.slip_travel[i] <= tolerance;
            match (sticks, open) {
                (true, None) => open = Some(i),
                (false, Some(start)) => {
                    // A run ends at a cell edge, or at the boundary located inside a cell next to
                    // it (within a cell of that edge, with the run on its stick side).
                    let located = |edge: f64, root: Edge| {
                        self.reported_kinks
                            .iter()
                            .filter(|k| k.root == root)
                            .map(|k| k.x)
                            .find(|at| (at - edge).abs() <= self.width)
                            .unwrap_or(edge)
                    };
                    let left =
                        located(self.x[start] - 0.5 * self.width, Edge::Right).max(ends.left);
                    let right =
                        located(self.x[i - 1] + 0.5 * self.width, Edge::Left).min(ends.right);
                    stick_intervals.push([left, right]);
                    open = None;
                }
                _ => {}
            }
        }
        stick_intervals
    }
}
