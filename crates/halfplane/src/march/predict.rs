//! Extrapolated stick-zone ends: fewer active-set passes when an increment moves a stick-slip
//! boundary by many cells.
//!
//! Each pass of the active set (`Marcher::advance`) flags every stick cell whose trial traction
//! exceeds its limit; the stick zone's end then moves towards its final cell by a roughly
//! constant fraction of the remaining distance per pass (about a half on Cattaneo: 966, 519,
//! 271, 138, 70, ... cells at 25,600 cells), so the passes grew by one per doubling of the
//! cells. Three positions of an end with steps `d1 > d2 > 0` fit that geometric sequence, whose
//! limit is `d2 r / (1 - r)` cells further on, `r = d2 / d1` (Aitken's delta-squared
//! extrapolation; Burden & Faires, *Numerical Analysis*, 9th ed., section 2.5). The cells up to
//! [`JUMP_FRACTION`] of the way there are flagged to slip at once. The prediction only chooses
//! the next trial set: the active set still stops only when no cell changes, so it ends on the
//! set the plain passes reach.
//!
//! Only in sub-steps whose pressure does not change (constant P and M, as in Cattaneo's
//! loading). The energy quadrature (`dissipation.rs`) times a cell's slip onset by the trial
//! traction with which the cell was flagged over its limit; a predicted cell has no such trial,
//! so its onset would read as the sub-step's start, and where the pressure changes the mean
//! pressure over its slip, and so the energy, would depend on the prediction (measured: 4e-6 to
//! 4e-5 of a sub-step's energy at 1600 cells, P changed by 0.1-1%). At constant pressure the
//! energy does not depend on the onsets.
//!
//! Measured reach (`BENCHMARKS.md`): Q from 0 to 0.5 f P in one increment takes at most 6
//! passes from 100 to 204,800 cells (plain: 5 to 17); closer to the friction limit the passes
//! still grow with the cells, more slowly (0.97 f P: 5 to 11 from 50 to 3200 cells, plain 7 to
//! 15); an increment that reverses Q re-sticks cells first and is never extrapolated.

use super::marcher::Cell;
use std::ops::Range;

/// The positions `[first, end)` of the single stick run after each pass of one sub-step.
///
/// At most [`MAX_JUMPS`] jumps per sub-step, and none once a jump has been undone (an end
/// turned back) or the run has split: after that the passes are the plain ones, whose
/// termination does not depend on this module.
pub(super) struct StickEnds {
    left: End,
    right: End,
    jumps: usize,
    done: bool,
}

/// The fraction of the fitted jump taken. The ratio falls slowly along the sequence (0.537,
/// 0.522, 0.509, ... on Cattaneo at 25,600 cells), so the full jump overshoots and the pass
/// after it un-flags cells; on Cattaneo, 100 to 204,800 cells, 0.95 took up to 12 passes, 0.85
/// at most 6, 0.8 at most 7.
const JUMP_FRACTION: f64 = 0.85;

/// Jumps per sub-step; measured on Cattaneo (one increment to Q = 0.5 f P), 100 to 204,800
/// cells, at most two were taken.
const MAX_JUMPS: usize = 4;

/// One end of the run: its positions since it last jumped or stood still, the ratio of its
/// last fitted sequence (which lets the next jump follow two positions instead of three), and
/// whether it has turned back (a jump overshot; a jump and the pass that undoes it could
/// otherwise alternate for ever).
#[derive(Default)]
struct End {
    positions: Vec<usize>,
    ratio: Option<f64>,
    turned: bool,
}

impl End {
    /// The cells to jump inwards after the end reached `at` (`inwards`: the direction in which
    /// flagging moves it, up for the left end), by the geometric fit above.
    fn record(&mut self, at: usize, inwards: bool) -> usize {
        let step = |from: usize, to: usize| {
            if inwards {
                to as f64 - from as f64
            } else {
                from as f64 - to as f64
            }
        };
        if let Some(&last) = self.positions.last() {
            self.turned |= step(last, at) < 0.0;
            if step(last, at) <= 0.0 {
                self.positions.clear();
            }
        }
        self.positions.push(at);
        let k = self.positions.len();
        let ratio = match k {
            0 | 1 => return 0,
            2 => match self.ratio {
                Some(r) => r,
                None => return 0,
            },
            _ => {
                let d1 = step(self.positions[k - 3], self.positions[k - 2]);
                let d2 = step(self.positions[k - 2], self.positions[k - 1]);
                if d2 >= d1 {
                    return 0;
                }
                d2 / d1
            }
        };
        self.ratio = Some(ratio);
        let d = step(self.positions[k - 2], at);
        (d * ratio / (1.0 - ratio) * JUMP_FRACTION).floor() as usize
    }
}

impl StickEnds {
    /// For one sub-step; extrapolates nothing unless its pressure is unchanged (module docs).
    pub(super) fn new(pressure_unchanged: bool) -> Self {
        Self {
            left: End::default(),
            right: End::default(),
            jumps: 0,
            done: !pressure_unchanged,
        }
    }

    /// Records the stick set the next pass will solve; returns the cells to flag to slip at
    /// each end of the run (empty ranges when there is nothing to extrapolate), with the sign
    /// of the slip of their flagged neighbours.
    pub(super) fn record(&mut self, cells: &[Cell]) -> [(Range<usize>, f64); 2] {
        let none = [(0..0, 0.0), (0..0, 0.0)];
        if self.done {
            return none;
        }
        let stick = |c: &Cell| *c == Cell::Stick;
        let (Some(first), Some(last)) =
            (cells.iter().position(stick), cells.iter().rposition(stick))
        else {
            self.done = true;
            return none;
        };
        let end = last + 1;
        if cells[first..end].iter().any(|c| *c != Cell::Stick) {
            // Several runs: no single pair of ends to follow.
            self.done = true;
            return none;
        }
        let (left, right) = (self.left.record(first, true), self.right.record(end, false));
        if self.left.turned || self.right.turned || self.jumps == MAX_JUMPS {
            self.done = true;
            return none;
        }
        // Never past the run's middle; only next to cells flagged to slip.
        let room = (end - first) / 4;
        let sign = |i: Option<usize>| match i.and_then(|i| cells.get(i)) {
            Some(Cell::Slip(s)) => *s,
            _ => 0.0,
        };
        let mut out = none;
        if left > 0 && left <= room && sign(first.checked_sub(1)) != 0.0 {
            out[0] = (first..first + left, sign(first.checked_sub(1)));
            self.left.positions = vec![first + left];
        }
        if right > 0 && right <= room && sign(Some(end)) != 0.0 {
            out[1] = (end - right..end, sign(Some(end)));
            self.right.positions = vec![end - right];
        }
        if !out[0].0.is_empty() || !out[1].0.is_empty() {
            self.jumps += 1;
        }
        out
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Cells `[0, n)` with the stick run `[first, end)`, slipping forwards on both sides.
    fn cells(n: usize, first: usize, end: usize) -> Vec<Cell> {
        (0..n)
            .map(|i| {
                if (first..end).contains(&i) {
                    Cell::Stick
                } else {
                    Cell::Slip(1.0)
                }
            })
            .collect()
    }

    #[test]
    fn a_geometric_approach_jumps_short_of_its_limit() {
        // Ends approaching 1000 and 9000 by halves: 0, 500, 750 -> limit 1000, jump 0.85 * 250.
        let mut ends = StickEnds::new(true);
        for (first, end) in [(0, 10000), (500, 9500)] {
            let out = ends.record(&cells(10000, first, end));
            assert!(
                out.iter().all(|(r, _)| r.is_empty()),
                "no fit from two positions"
            );
        }
        let [left, right] = ends.record(&cells(10000, 750, 9250));
        assert_eq!(left, (750..962, 1.0));
        assert_eq!(right, (9038..9250, 1.0));
    }

    #[test]
    fn an_end_that_turns_back_stops_the_jumps() {
        let mut ends = StickEnds::new(true);
        for (first, end) in [(0, 10000), (500, 9500), (750, 9250)] {
            ends.record(&cells(10000, first, end));
        }
        // The jump to 962 overshot: the next pass un-flags cells down to 950.
        let out = ends.record(&cells(10000, 950, 9038));
        assert!(out.iter().all(|(r, _)| r.is_empty()));
        for (first, end) in [(975, 9038), (990, 9038), (995, 9038)] {
            let out = ends.record(&cells(10000, first, end));
            assert!(out.iter().all(|(r, _)| r.is_empty()), "a turned end jumped");
        }
    }

    /// Records the three positions of `a_geometric_approach_jumps_short_of_its_limit` on
    /// `cells` changed by `edit` (after each is built), returning the last record.
    fn third_record(
        ends: &mut StickEnds,
        edit: impl Fn(&mut Vec<Cell>),
    ) -> [(Range<usize>, f64); 2] {
        let mut out = [(0..0, 0.0), (0..0, 0.0)];
        for (first, end) in [(0, 10000), (500, 9500), (750, 9250)] {
            let mut set = cells(10000, first, end);
            edit(&mut set);
            out = ends.record(&set);
        }
        out
    }

    #[test]
    fn nothing_is_extrapolated_while_the_pressure_changes() {
        let out = third_record(&mut StickEnds::new(false), |_| {});
        assert!(out.iter().all(|(r, _)| r.is_empty()));
    }

    #[test]
    fn an_end_with_no_slipping_neighbour_does_not_jump() {
        // Left of the run out of contact, right of it the grid's end (a run reaching cell N - 1).
        let out = third_record(&mut StickEnds::new(true), |set| {
            let first = set.iter().position(|c| *c == Cell::Stick).unwrap_or(0);
            set[..first].fill(Cell::Out);
            let end = set.iter().rposition(|c| *c == Cell::Stick).unwrap_or(0) + 1;
            set.truncate(end);
        });
        assert!(out[0].0.is_empty(), "jumped next to cells out of contact");
        assert!(out[1].0.is_empty(), "jumped at the grid's end");
    }

    #[test]
    fn a_jump_past_a_quarter_of_the_run_is_refused() {
        // Ends 0, 3000, 4500 of a 10000-cell grid: limit 6000, a jump of 1275 > (5500 - 4500) / 4.
        let mut ends = StickEnds::new(true);
        for (first, end) in [(0, 10000), (3000, 7000)] {
            ends.record(&cells(10000, first, end));
        }
        let out = ends.record(&cells(10000, 4500, 5500));
        assert!(out.iter().all(|(r, _)| r.is_empty()));
    }

    #[test]
    fn at_most_four_jumps_per_sub_step() {
        // Each end approaching its limit by halves from afar: every record after the second
        // jumps, until the fifth would.
        let mut ends = StickEnds::new(true);
        let (mut first, mut end, mut step) = (0usize, 1_000_000usize, 100_000usize);
        let mut jumps = 0;
        for _ in 0..12 {
            let out = ends.record(&cells(1_000_000, first, end));
            if !out[0].0.is_empty() {
                jumps += 1;
                first = out[0].0.end;
                end = out[1].0.start;
            }
            first += step;
            end -= step;
            step /= 2;
        }
        assert_eq!(jumps, MAX_JUMPS);
    }

    #[test]
    fn several_runs_are_not_extrapolated() {
        let mut ends = StickEnds::new(true);
        let mut split = cells(10000, 750, 9250);
        split[5000] = Cell::Slip(-1.0);
        for set in [cells(10000, 0, 10000), cells(10000, 500, 9500), split] {
            let out = ends.record(&set);
            assert!(out.iter().all(|(r, _)| r.is_empty()));
        }
    }
}
