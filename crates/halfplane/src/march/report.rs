//! What an increment reports when its stick-slip boundaries are located inside their cells
//! (`docs/convergence.md`, "Slips and energies with located boundaries"): the slip, the bodies'
//! relative displacement and the energy of the located solution, beside the traction and the
//! kinks that `boundary.rs` reports.
//!
//! The located solve gives the slip at every slipping centre and the rigid shift over what it
//! solves (`evaluate.rs`): the increment's last sub-step from the cell-level state, or a whole
//! stretch from its located start (`chain.rs`). The reported slip is that slip added to the
//! slip of its start (the cell-level slip before the last sub-step, or the stretch start's
//! reported slip); the relative displacement likewise.
//!
//! The energy: within a stretch the pressure is constant and every cell slips one way at the
//! limit `f p`, so the Coulomb work of the increment is `integral f p |ds| dx` exactly in time
//! (Johnson, *Contact Mechanics*, section 7.2); it is summed by the limit's exact cell means
//! times the centres' slips (midpoint in space). An increment whose P or M changes is not
//! located (`marcher.rs`), so its slip and energy are the cell-level march's (`dissipation.rs`).
//!
//! Owns the reported slip, displacement and energy. Never changes the state the march goes on
//! from (the cell-level active set's: `boundary.rs` says why).

use super::marcher::Marcher;
use crate::load::LoadPoint;

/// The reported slip, its increment, the energy and the relative displacement (datum the
/// kernel's scale), after the last increment.
#[derive(Debug, Clone, PartialEq)]
pub(super) struct Reported {
    slip: Vec<f64>,
    increment: Vec<f64>,
    energy: f64,
    displacement: f64,
}

impl Reported {
    pub(super) fn new(cells: usize) -> Self {
        Self {
            slip: vec![0.0; cells],
            increment: vec![0.0; cells],
            energy: 0.0,
            displacement: 0.0,
        }
    }
}

impl Marcher {
    /// Whether increments are located (`boundary.rs`): the option on and no worn gap, whose
    /// pressure is known at the centres only, not as the closed form the limit moments integrate
    /// (`moments.rs`). `cfg!`: a build without the feature (the web page) leaves that code out.
    pub(super) fn locates(&self) -> bool {
        cfg!(feature = "sub-cell") && self.options.sub_cell() && self.gap.is_none()
    }

    /// Whether the normal loads of a sub-step to `load`, P and the moment M, are the last one's
    /// (so its pressure is), so that it may be located: where either changes, the located solve
    /// (of the last sub-step, from the cell level) was worse than the cell level near the
    /// contact edges (docs/convergence.md, "Where the normal load changes"). A history
    /// interpolated between equal loads moves them by rounding, which is no change.
    pub(super) fn normal_unchanged(&self, load: &LoadPoint) -> bool {
        let same = |a: f64, b: f64| (a - b).abs() <= 1e-12 * a.abs().max(b.abs());
        self.load
            .is_some_and(|l| same(l.normal(), load.normal()) && same(l.moment(), load.moment()))
    }

    /// A sub-step not located: nothing to report, and where the normal load changed
    /// (`unchanged` false) nothing located at another pressure may start a stretch or stay in a
    /// memory (a first version kept the last block's and was 0.42 f p0 off; `tests/sub_cell.rs`).
    pub(super) fn unlocated(&mut self, unchanged: bool) {
        self.view = None;
        if !unchanged {
            (self.located, self.stretch) = (None, None);
        }
    }

    /// Records what the increment just marched reports, given the cell-level energy
    /// `cell_energy` of its sub-steps, and returns its energy: the located solution's slip and
    /// displacement where the increment was located, and, within a stretch, the growth of the
    /// Coulomb work since the stretch's start (see the module note); the cell-level values
    /// otherwise.
    pub(super) fn report(&mut self, cell_energy: f64) -> f64 {
        let located = self.locates();
        let Some(r) = self.reported.as_mut() else {
            return cell_energy;
        };
        let (slip, displacement) = match (&self.view, located) {
            (Some(v), true) => (&v.slip, v.displacement),
            _ => (&self.slip, self.displacement),
        };
        for ((inc, old), new) in r.increment.iter_mut().zip(&mut r.slip).zip(slip) {
            *inc = new - *old;
            *old = *new;
        }
        r.displacement = displacement;
        let energy = match self.stretch.as_mut().filter(|_| located) {
            // The work since the stretch's start, less what earlier increments reported: an
            // increment of the stretch solved from the cell level (`boundary.rs`) reports its
            // own share less exactly, and the next one makes up for it.
            Some(stretch) => {
                let since: Vec<f64> = (slip.iter().zip(&stretch.start.slip))
                    .map(|(s, s0)| (s - s0).abs())
                    .collect();
                let work = coulomb_work(self.width, &self.limit_mean, &self.limit_slope, &since);
                let energy = work - stretch.work;
                stretch.work = work;
                energy
            }
            None => cell_energy,
        };
        r.energy += energy;
        energy
    }

    /// The accumulated slip, its last increment, the energy and the relative displacement
    /// (datum the kernel's scale) as reported: located where the increments are, else the
    /// cell-level march's.
    pub(super) fn reported(&self) -> (&[f64], &[f64], f64, f64) {
        match &self.reported {
            Some(r) if self.locates() => (&r.slip, &r.increment, r.energy, r.displacement),
            _ => (
                &self.slip,
                &self.slip_increment,
                self.energy,
                self.displacement,
            ),
        }
    }
}

/// `integral f p |s| dx` at constant pressure for the slips `slip` at the centres (cell width
/// `w`, the limit's cell means and slopes `mean` and `slope`): per cell
/// `f (m0 s + m1 s' + m2 s''/2)` with `m_k` the pressure's exact moments about the centre
/// (`moments.rs`; `m2` as a smooth pressure's, `m0 w^2/12`) and the slip's derivatives by
/// central differences, between cells in contact. With the centre term alone (the midpoint
/// rule) the energy per cycle of a Cattaneo-Mindlin loop was 6.2e-5 off at 400 cells, the
/// slips' own error being nil there (docs/convergence.md).
fn coulomb_work(w: f64, mean: &[f64], slope: &[f64], slip: &[f64]) -> f64 {
    let n = slip.len();
    let mut work = 0.0;
    for i in 0..n {
        let mut cell = mean[i] * slip[i];
        if i > 0 && i + 1 < n && mean[i - 1] > 0.0 && mean[i + 1] > 0.0 {
            let (before, after) = (slip[i - 1], slip[i + 1]);
            cell += mean[i] * (after - 2.0 * slip[i] + before) / 24.0
                + slope[i] * (after - before) * w / 24.0;
        }
        work += w * cell;
    }
    work
}

#[cfg(test)]
mod tests {
    use super::super::{MarchOptions, Marcher};
    use crate::{reference, LoadPoint};

    #[test]
    fn located_reports_leave_the_marched_state_alone() {
        // The march goes on from the cell-level solution (`boundary.rs`): with the option on,
        // its slips, energy and rigid displacement are the option off's to rounding (the located
        // solves share the solvers' caches, so the cell-level solves after them start from other
        // cached orders: measured 7.8e-14 in the energy, 3.1e-13 of the largest slip, 1.7e-12 in
        // the displacement, a difference of larger terms; here 1.9e-12), while what is
        // reported differs (by up to 2.3e-2 of the largest slip).
        // Hertz, P to 1000 in ten increments, Q to 300 in 15, two cycles of +-300 at 30
        // increments per half, 400 cells.
        let mut rows: Vec<[f64; 2]> = (1..=10).map(|i| [100.0 * i as f64, 0.0]).collect();
        rows.extend((1..=15).map(|i| [1000.0, 20.0 * i as f64]));
        for _ in 0..2 {
            rows.extend((1..=30).map(|i| [1000.0, 300.0 - 20.0 * i as f64]));
            rows.extend((1..=30).map(|i| [1000.0, -300.0 + 20.0 * i as f64]));
        }
        let contact = reference::hertz();
        let half_span = contact.half_width(1000.0).unwrap();
        let base = MarchOptions::default().with_cells(400).unwrap();
        let on = base.with_sub_cell_boundaries(true).unwrap();
        let mut located = Marcher::new(&contact, half_span, &on).unwrap();
        let mut plain = Marcher::new(&contact, half_span, &base).unwrap();
        let (mut state, mut reported) = (0.0f64, 0.0f64);
        for [p, q] in rows {
            let load = LoadPoint::new("row", p, q, 0.0).unwrap();
            located.step(load).unwrap();
            plain.step(load).unwrap();
            let scale = plain.slip.iter().fold(1e-300f64, |m, s| m.max(s.abs()));
            let slip = |a: &[f64], b: &[f64]| {
                a.iter()
                    .zip(b)
                    .fold(0.0f64, |m, (x, y)| m.max((x - y).abs()))
                    / scale
            };
            let energy = (located.energy - plain.energy).abs() / plain.energy.max(1e-300);
            let shift = (located.displacement - plain.displacement).abs()
                / plain.displacement.abs().max(1e-300);
            state = state
                .max(slip(&located.slip, &plain.slip))
                .max(energy)
                .max(shift);
            reported = reported.max(slip(located.reported().0, &plain.slip));
        }
        assert!(
            state < 1e-10,
            "the located boundaries changed the marched state: {state:e} (relative)"
        );
        assert!(
            reported > 1e-4,
            "the located slips are not what is reported: {reported:e} from the cell level's"
        );
    }
}
