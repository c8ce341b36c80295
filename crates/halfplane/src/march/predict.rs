//! Extrapolated stick-zone ends: fewer active-set passes when an increment moves a stick-slip
//! boundary by many cells.
//!
//! Each pass of the active set (`Marcher::advance`) flags every stick cell whose trial traction
//! exceeds its limit, and the stick run's end then moves towards its final cell by a near-constant
//! fraction of the remaining distance per pass, so the plain passes grow by one per doubling of
//! the cells. The fraction is exact for a Hertz contact in the squared distance from the
//! contact's centre: with the stick run at `|x| < e` and the cells outside it slipping at
//! `f p`, the stick traction is the Cattaneo-Mindlin one, `q = f p_a(x) - f (p0 / a) sqrt(e^2 -
//! x^2) + C / sqrt(e^2 - x^2)`, with `pi C = f P (e^2 - c^2) / a^2` from the resultant (Johnson,
//! *Contact Mechanics*, section 7.1; `c` the final stick half-width, `p0 = 2 P / (pi a)`). It
//! exceeds the limit where `e^2 - x^2 < C a / (f p0)`, so the next pass's stick run has
//! `e'^2 - c^2 = (e^2 - c^2) / 2`: the squared distance closes geometrically with ratio one
//! half (measured at 6400 cells, Q = 0.97 f P: 0.4999, 0.4998, 0.5001; the plain positions' own
//! ratio drifts, 0.68 to 0.59). So three squared distances `u1 > u2 > u3` of an end fit that
//! sequence, whose limit is `u3 - d2 r / (1 - r)`, `d2 = u2 - u3`, `r = d2 / (u1 - u2)` (Aitken's
//! delta-squared extrapolation; Burden & Faires, *Numerical Analysis*, 9th ed., section 2.5),
//! and the cells up to [`JUMP_FRACTION`] of the way to the limit's position are flagged to slip
//! at once. Other profiles close less exactly geometrically in `u`; the fraction keeps a jump
//! short of its limit there. The prediction only chooses the next trial set: the active set
//! still stops only when no cell changes, so it ends on the set the plain passes reach.
//!
//! Only in sub-steps whose pressure does not change (constant P and M, as in Cattaneo's
//! loading). The energy quadrature (`dissipation.rs`) times a cell's slip onset by the trial
//! traction with which the cell was flagged over its limit; a predicted cell has no such trial,
//! so its onset would read as the sub-step's start, and where the pressure changes the mean
//! pressure over its slip, and so the energy, would depend on the prediction (measured: 4e-6 to
//! 4e-5 of a sub-step's energy at 1600 cells, P changed by 0.1-1%). At constant pressure the
//! energy does not depend on the onsets.
//!
//! Measured reach (`BENCHMARKS.md`, with [`restick_reversed`]): Hertz and flat-rounded contacts,
//! Q to 0.5, 0.8 and 0.97 f P in one increment and back to minus that in one, 100 to 204,800
//! cells: at most 10 passes per increment (at most 8 but for two cases), where the plain passes
//! grew to 14-20.

use super::marcher::Cell;
use std::ops::Range;

/// The ends `[first, end)` of the single stick run after each pass of one sub-step, as squared
/// distances from the contact's centre.
///
/// At most [`MAX_JUMPS`] jumps per sub-step, and none once a jump has been undone (an end
/// turned back) or the run has split: after that the passes are the plain ones, whose
/// termination does not depend on this module.
pub(super) struct StickEnds {
    centre: f64,
    left: End,
    right: End,
    jumps: usize,
    done: bool,
}

/// The fraction of the fitted jump taken, in cells. Measured (100 to 204,800 cells, the cases
/// of the module docs): 0.85 at most 10 passes per increment; 0.9 and 0.95 up to 11 and 13 on
/// the flat-rounded contact, whose sequence is not exactly geometric; the whole jump (1.0) up to
/// 14 there, from overshoots the next pass undoes.
const JUMP_FRACTION: f64 = 0.85;

/// Jumps per sub-step: a bound on the trials this module chooses.
const MAX_JUMPS: usize = 4;

/// One end of the run: its squared distances from the centre since it last jumped or stood
/// still, the ratio of its last fitted sequence (which lets the next jump follow two positions
/// instead of three), and whether it has turned back (a jump overshot; a jump and the pass that
/// undoes it could otherwise alternate for ever).
#[derive(Default)]
struct End {
    squares: Vec<f64>,
    ratio: Option<f64>,
    turned: bool,
}

impl End {
    /// The cells to jump inwards after the end reached `e` cells from the contact's centre, by
    /// the geometric fit of the module docs.
    fn record(&mut self, e: f64) -> usize {
        let u = e * e;
        if let Some(&last) = self.squares.last() {
            self.turned |= u > last;
            if u >= last {
                self.squares.clear();
            }
        }
        self.squares.push(u);
        let k = self.squares.len();
        let ratio = match k {
            0 | 1 => return 0,
            2 => match self.ratio {
                Some(r) => r,
                None => return 0,
            },
            _ => {
                let d1 = self.squares[k - 3] - self.squares[k - 2];
                let d2 = self.squares[k - 2] - self.squares[k - 1];
                if d2 >= d1 {
                    return 0;
                }
                d2 / d1
            }
        };
        self.ratio = Some(ratio);
        let d = self.squares[k - 2] - u;
        let limit = (u - d * ratio / (1.0 - ratio)).max(0.0).sqrt();
        ((e - limit) * JUMP_FRACTION).floor() as usize
    }
}

impl StickEnds {
    /// For one sub-step whose contact's centre is `centre` cell widths from the grid's left
    /// edge; extrapolates nothing unless its pressure is unchanged (module docs).
    pub(super) fn new(pressure_unchanged: bool, centre: f64) -> Self {
        Self {
            centre,
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
        let (e_left, e_right) = (self.centre - first as f64, end as f64 - self.centre);
        if e_left <= 0.0 || e_right <= 0.0 {
            // The run on one side of the centre (a moment's offset stick zone).
            self.done = true;
            return none;
        }
        let (left, right) = (self.left.record(e_left), self.right.record(e_right));
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
            self.left.squares = vec![(e_left - left as f64).powi(2)];
        }
        if right > 0 && right <= room && sign(Some(end)) != 0.0 {
            out[1] = (end - right..end, sign(Some(end)));
            self.right.squares = vec![(e_right - right as f64).powi(2)];
        }
        if !out[0].0.is_empty() || !out[1].0.is_empty() {
            self.jumps += 1;
        }
        out
    }
}

/// The first trial set of a sub-step that drives the shear against the slip of cells slipping
/// at its start (`d_shear` the change of Q): those cells stuck. Left slipping, their slip
/// reverses in the first pass while the old stick run carries the whole change, whose ends then
/// exceed the limit the other way: the first pass splits the run into three and the passes grow
/// with the cells (13 at 6400 cells, 15 at 25,600, Q from 0.5 f P to -0.5 f P); stuck, the first
/// pass is the full-stick solution and the reversed slip zones grow in from the contact edges
/// as one run's ends, which [`StickEnds`] follows. Only at constant pressure and bulk stress,
/// where nothing else drives slip; the passes still end on the set whose check changes no cell.
pub(super) fn restick_reversed(cells: &mut [Cell], d_shear: f64) {
    for c in cells.iter_mut() {
        if matches!(c, Cell::Slip(s) if *s * d_shear < 0.0) {
            *c = Cell::Stick;
        }
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

    /// The contact's centre on the tests' 10,000-cell grid.
    const CENTRE: f64 = 5000.0;

    /// The stick runs of the first passes on a Hertz contact filling the grid, final stick
    /// half-width 2000 cells: `e^2 - c^2` halves each pass (module docs), `e` rounded to cells.
    const HERTZ_RUNS: [(usize, usize); 3] = [(0, 10000), (1192, 8808), (1959, 8041)];

    #[test]
    fn a_hertz_approach_jumps_most_of_the_way_to_its_limit() {
        let mut ends = StickEnds::new(true, CENTRE);
        for &(first, end) in &HERTZ_RUNS[..2] {
            let out = ends.record(&cells(10000, first, end));
            assert!(
                out.iter().all(|(r, _)| r.is_empty()),
                "no fit from two positions"
            );
        }
        let (first, end) = HERTZ_RUNS[2];
        let [left, right] = ends.record(&cells(10000, first, end));
        // From 3041 cells off the centre to within 80-90% of the way to 2000.
        let reached = CENTRE - left.0.end as f64;
        assert!(
            (2000.0 + 0.1 * 1041.0..2000.0 + 0.2 * 1041.0).contains(&reached),
            "left end jumped to {reached} cells from the centre"
        );
        assert_eq!(left.1, 1.0, "flagged with its neighbours' slip");
        assert_eq!(right.0.len(), left.0.len(), "the ends jump alike");
        assert_eq!(right.0.end, end);
    }

    #[test]
    fn an_end_that_turns_back_stops_the_jumps() {
        let mut ends = StickEnds::new(true, CENTRE);
        let mut jump = 0..0;
        for &(first, end) in &HERTZ_RUNS {
            jump = ends.record(&cells(10000, first, end))[0].0.clone();
        }
        // The jump overshot: the next pass un-flags cells back outwards of its end.
        let back = jump.end - 20;
        let out = ends.record(&cells(10000, back, 10000 - back));
        assert!(out.iter().all(|(r, _)| r.is_empty()));
        for first in [back + 10, back + 15, back + 17] {
            let out = ends.record(&cells(10000, first, 10000 - first));
            assert!(out.iter().all(|(r, _)| r.is_empty()), "a turned end jumped");
        }
    }

    /// Records [`HERTZ_RUNS`] on `cells` changed by `edit` (after each is built), returning the
    /// last record.
    fn third_record(
        ends: &mut StickEnds,
        edit: impl Fn(&mut Vec<Cell>),
    ) -> [(Range<usize>, f64); 2] {
        let mut out = [(0..0, 0.0), (0..0, 0.0)];
        for &(first, end) in &HERTZ_RUNS {
            let mut set = cells(10000, first, end);
            edit(&mut set);
            out = ends.record(&set);
        }
        out
    }

    #[test]
    fn nothing_is_extrapolated_while_the_pressure_changes() {
        let out = third_record(&mut StickEnds::new(false, CENTRE), |_| {});
        assert!(out.iter().all(|(r, _)| r.is_empty()));
    }

    #[test]
    fn an_end_with_no_slipping_neighbour_does_not_jump() {
        // Left of the run out of contact, right of it the grid's end (a run reaching cell N - 1).
        let out = third_record(&mut StickEnds::new(true, CENTRE), |set| {
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
        // A Hertz approach to a stick half-width of 200 cells: 5000, 3538, 2506 cells from the
        // centre, a jump of about 0.85 * 2306 cells > 2 * 2506 / 4.
        let mut ends = StickEnds::new(true, CENTRE);
        for (first, end) in [(0, 10000), (1462, 8538)] {
            ends.record(&cells(10000, first, end));
        }
        let out = ends.record(&cells(10000, 2494, 7506));
        assert!(out.iter().all(|(r, _)| r.is_empty()));
    }

    #[test]
    fn at_most_four_jumps_per_sub_step() {
        // Each end approaching its limit by halves from afar: every record after the second
        // jumps, until the fifth would.
        let mut ends = StickEnds::new(true, 500_000.0);
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
        let mut ends = StickEnds::new(true, CENTRE);
        let (first, end) = HERTZ_RUNS[2];
        let mut split = cells(10000, first, end);
        split[5000] = Cell::Slip(-1.0);
        let [(f0, e0), (f1, e1), _] = HERTZ_RUNS;
        for set in [cells(10000, f0, e0), cells(10000, f1, e1), split] {
            let out = ends.record(&set);
            assert!(out.iter().all(|(r, _)| r.is_empty()));
        }
    }

    #[test]
    fn a_reversing_increment_starts_from_its_slipping_cells_stuck() {
        let start = [
            Cell::Out,
            Cell::Slip(1.0),
            Cell::Stick,
            Cell::Slip(-1.0),
            Cell::Out,
        ];
        let mut set = start;
        restick_reversed(&mut set, -1.0);
        assert_eq!(
            set,
            [
                Cell::Out,
                Cell::Stick,
                Cell::Stick,
                Cell::Slip(-1.0),
                Cell::Out
            ]
        );
        let mut set = start;
        restick_reversed(&mut set, 0.0);
        assert_eq!(set, start, "no change of Q: nothing to reverse");
    }
}
