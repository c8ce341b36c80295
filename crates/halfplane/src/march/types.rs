//! The public types of time marching: the options ([`MarchOptions`], [`LinearSolver`]), the
//! fields after an increment ([`Fields`]) and the reports ([`StepReport`], [`CycleReport`],
//! [`MarchResult`]).
//!
//! Owns the options' valid ranges and the typed errors naming the case-file fields. Never
//! computes a solution: nothing here marches, solves or touches the kernel.

use super::boundary::TractionKink;
use crate::error::{Error, Result};
use crate::labels::PerEdge;
use crate::load::LoadPoint;

/// How the stick cells' linear system is solved.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
#[non_exhaustive]
pub enum LinearSolver {
    /// Exact Toeplitz inverse per stick run (Gohberg-Semencul, FFT) and FFT products:
    /// O(N log N) per pass. The default.
    #[default]
    Toeplitz,
    /// The classical dense route: the N x N kernel matrix, products in O(N^2) and a Cholesky
    /// factorisation of the stick block in O(n^3) per pass. For comparison and cross-checks.
    Dense,
}

/// Solver parameters, valid by construction: start from [`MarchOptions::default`] and change
/// what you need with the `with_*` methods, each of which checks its value and returns a typed
/// error naming the case-file field, the value and the valid range.
///
/// ```
/// use halfplane::march::{LinearSolver, MarchOptions};
/// let options = MarchOptions::default().with_cells(1000)?.with_solver(LinearSolver::Toeplitz)?;
/// assert_eq!(options.cells(), 1000);
/// assert!(MarchOptions::default().with_cells(3).is_err());
/// # Ok::<(), halfplane::Error>(())
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct MarchOptions {
    solver: LinearSolver,
    cells: usize,
    max_passes: usize,
    slip_tolerance: f64,
    shakedown_tolerance: f64,
    sub_cell: bool,
}

impl Default for MarchOptions {
    fn default() -> Self {
        Self {
            solver: LinearSolver::Toeplitz,
            cells: 400,
            max_passes: 200,
            slip_tolerance: 1e-10,
            shakedown_tolerance: 1e-3,
            sub_cell: false,
        }
    }
}

impl MarchOptions {
    /// Fewest cells: below this a contact is resolved by too few cells for a stick zone.
    pub const MIN_CELLS: usize = 8;
    /// Most cells with the Toeplitz solver. The marcher holds about 1.5 kB per cell (18 vectors
    /// of N values and up to 12 cached Toeplitz generators, each with two spectra of up to 4N
    /// points), so the limit is about 1.5 GB.
    pub const MAX_CELLS: usize = 1_000_000;
    /// Most cells with [`LinearSolver::Dense`]: its N x N kernel and the Cholesky factor of
    /// the stick block take up to 16 N^2 bytes, 1.6 GB at the limit (and a pass costs O(N^3)).
    pub const MAX_DENSE_CELLS: usize = 10_000;

    /// Sets the number of cells across the largest contact of the history (default 400: stick
    /// boundaries within 0.3% of the contact width, see `docs/convergence.md`).
    pub fn with_cells(mut self, cells: usize) -> Result<Self> {
        if !(Self::MIN_CELLS..=Self::MAX_CELLS).contains(&cells) {
            return Err(Error::InvalidCount {
                field: "solver.cells".into(),
                value: cells as u64,
                min: Self::MIN_CELLS as u64,
                max: Self::MAX_CELLS as u64,
            });
        }
        self.cells = cells;
        self.check_dense()
    }

    /// Sets the linear solver (default [`LinearSolver::Toeplitz`]).
    pub fn with_solver(mut self, solver: LinearSolver) -> Result<Self> {
        self.solver = solver;
        self.check_dense()
    }

    fn check_dense(self) -> Result<Self> {
        if self.solver == LinearSolver::Dense && self.cells > Self::MAX_DENSE_CELLS {
            return Err(Error::InvalidCount {
                field: "solver.cells (with the dense solver)".into(),
                value: self.cells as u64,
                min: Self::MIN_CELLS as u64,
                max: Self::MAX_DENSE_CELLS as u64,
            });
        }
        Ok(self)
    }

    /// Sets the active-set passes allowed per sub-step (default 200; a few are typical).
    pub fn with_max_passes(mut self, passes: usize) -> Result<Self> {
        if passes == 0 {
            return Err(Error::InvalidCount {
                field: "solver.max_passes".into(),
                value: 0,
                min: 1,
                max: usize::MAX as u64,
            });
        }
        self.max_passes = passes;
        Ok(self)
    }

    /// Sets the slip-labelling threshold, a fraction of `A f P` (default 1e-10): a cell is
    /// reported as slipping in an increment when it slides by more than this. It changes only
    /// the reported stick intervals, never the solution.
    pub fn with_slip_tolerance(mut self, tolerance: f64) -> Result<Self> {
        if !(tolerance.is_finite() && tolerance > 0.0 && tolerance < 1.0) {
            return Err(Error::InvalidInput {
                field: "solver.slip_tolerance".into(),
                value: tolerance,
                valid: "a number with 0 < t < 1 (a fraction of A f P)",
            });
        }
        self.slip_tolerance = tolerance;
        Ok(self)
    }

    /// Sets the shakedown test: cycles repeat when their slip ranges and energies agree to this
    /// fraction (default 1e-3).
    pub fn with_shakedown_tolerance(mut self, tolerance: f64) -> Result<Self> {
        if !(tolerance.is_finite() && tolerance > 0.0 && tolerance < 1.0) {
            return Err(Error::InvalidInput {
                field: "solver.shakedown_tolerance".into(),
                value: tolerance,
                valid: "a number with 0 < t < 1 (a relative difference)",
            });
        }
        self.shakedown_tolerance = tolerance;
        Ok(self)
    }

    /// Whether each increment locates its stick-slip boundaries inside their cells (default
    /// false; `docs/convergence.md`, "Sub-cell stick-slip boundaries"). When on, the increment's
    /// last sub-step is solved once more with every stick zone that ends next to slipping cells
    /// at both ends bounded where its traction meets the limit continuously, and that solution
    /// is what the increment reports: the fields' traction, their square-root kinks (which the
    /// stresses' node form takes), the ends of the stick intervals, the slips and the relative
    /// displacement and the energy (`docs/convergence.md`, "Slips and energies with located
    /// boundaries"). Only increments at an unchanged normal load, P and moment, are located:
    /// where either changes, the located solve was worse than the cell level near the contact
    /// edges, and the increment reports the cell-level solution ("Where the normal load
    /// changes"). The largest traction error of a Cattaneo load falls from 8e-3 to 2e-4 of f p0
    /// at 400 cells, the slip range's of its loop from 5.6e-4 to 3.4e-5 of the largest range
    /// and the energy per cycle's from 2.1e-4 to 1.5e-5.
    /// The march goes on from the cell-level solution, so the active set and the cycle's
    /// repetition are the cell-level march's. It costs several solves per increment (`BENCHMARKS.md`),
    /// hence off by default. A march over a worn gap ([`Worn`](super::Worn), once its gap is
    /// set) reports the cell-level solution whatever this says: its pressure is known only at
    /// the cell centres, not as the profile's closed form the located boundaries integrate.
    pub fn with_sub_cell_boundaries(mut self, on: bool) -> Result<Self> {
        self.sub_cell = on;
        Ok(self)
    }

    /// Whether increments report stick-slip boundaries located inside their cells.
    pub fn sub_cell(&self) -> bool {
        self.sub_cell
    }

    /// The linear solver.
    pub fn solver(&self) -> LinearSolver {
        self.solver
    }

    /// Cells across the largest contact of the history.
    pub fn cells(&self) -> usize {
        self.cells
    }

    /// Active-set passes allowed per sub-step.
    pub fn max_passes(&self) -> usize {
        self.max_passes
    }

    /// The slip-labelling threshold, a fraction of `A f P`.
    pub fn slip_tolerance(&self) -> f64 {
        self.slip_tolerance
    }

    /// The relative tolerance of the shakedown test.
    pub fn shakedown_tolerance(&self) -> f64 {
        self.shakedown_tolerance
    }
}

/// The fields after an increment, one value per cell.
#[derive(Debug, Clone, Copy)]
pub struct Fields<'a> {
    /// Cell centres.
    pub x: &'a [f64],
    /// Contact pressure p.
    pub pressure: &'a [f64],
    /// Shear traction q (positive in the direction of positive Q).
    pub traction: &'a [f64],
    /// Accumulated slip (positive in the sense positive Q drives).
    pub slip: &'a [f64],
    /// Slip increment of this step.
    pub slip_increment: &'a [f64],
    /// The square-root kinks of the shear traction: the stick-slip boundaries of this
    /// increment, located inside their cells, each with the amplitudes of the earlier kinks
    /// within half a cell of it added, and the earlier boundaries' kinks that its stick zones
    /// hold further away.
    pub kinks: &'a [TractionKink],
}

/// Summary of one increment.
#[derive(Debug, Clone, PartialEq)]
pub struct StepReport {
    /// 1-based increment number.
    pub step: usize,
    /// The load reached.
    pub load: LoadPoint,
    /// Contact half-width `(b2 - b1)/2`.
    pub half_width: f64,
    /// The contact ends `[b1, b2]` reached (`[-a, a]` without a moment on a symmetric profile).
    pub ends: PerEdge<f64>,
    /// Every stick interval `[left, right]` (kinematic: no slip in this increment), left to right.
    pub stick_intervals: Vec<[f64; 2]>,
    /// Frictional energy dissipated in this increment (per unit thickness).
    pub energy_increment: f64,
    /// Total dissipated so far.
    pub energy: f64,
    /// Active-set passes used.
    pub passes: usize,
    /// The bodies' relative tangential displacement after the increment (the fretting loop is
    /// it against the shear load).
    pub relative_displacement: RelativeDisplacement,
}

/// The relative tangential displacement of the bodies, pad minus specimen, positive in the sense
/// positive Q drives: the rigid displacement `delta` in `s(x) = u(x) + delta`, s the slip and
///
/// `u(x) = (A/pi) integral q(xi) ln(|x - xi|/d) dxi - (A/4) sigma x`
///
/// the surfaces' elastic relative displacement (the log kernel the march solves with: the
/// tangential counterpart of Johnson, *Contact Mechanics*, eq. 2.25a, summed over both bodies;
/// the bulk stress's strain measured from x = 0). Half-plane displacements need a datum, the
/// length `d` at which a point load's logarithm vanishes: for `d` well beyond the contact and no
/// bulk stress, the bodies' surface points at distance `d` from it, where the contact's traction
/// acts as a point load (with bulk stress those points also move by `∓(A/4) sigma d`, which
/// delta leaves out). [`RelativeDisplacement::at`] takes it. Changing it adds `(A/pi) Q ln(d2/d1)`, a shear
/// of the loop: a loop's area (the energy dissipated) and its width at Q = 0 do not depend on
/// it. Zero unloaded and under normal load alone.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RelativeDisplacement {
    /// delta with the datum `scale`.
    at_scale: f64,
    scale: f64,
    /// `(A/pi) Q`.
    log_coefficient: f64,
    shear: f64,
}

impl RelativeDisplacement {
    pub(super) fn new(at_scale: f64, scale: f64, compliance: f64, shear: f64) -> Self {
        Self {
            at_scale,
            scale,
            log_coefficient: compliance / std::f64::consts::PI * shear,
            shear,
        }
    }

    /// The shear load Q it is under.
    pub fn shear(&self) -> f64 {
        self.shear
    }

    /// delta with the datum `datum` (a length > 0).
    ///
    /// # Errors
    /// [`Error::InvalidInput`] naming the datum when it is not a positive length.
    pub fn at(&self, datum: f64) -> Result<f64> {
        crate::error::physical_positive("relative displacement datum", datum)?;
        Ok(self.at_positive(datum))
    }

    /// [`RelativeDisplacement::at`] for a datum known to be a positive length.
    fn at_positive(&self, datum: f64) -> f64 {
        self.at_scale + self.log_coefficient * (datum / self.scale).ln()
    }
}

impl StepReport {
    /// The largest stick interval, if any.
    pub fn largest_stick(&self) -> Option<[f64; 2]> {
        self.stick_intervals
            .iter()
            .copied()
            .max_by(|a, b| (a[1] - a[0]).total_cmp(&(b[1] - b[0])))
    }
}

/// Per-cycle results.
#[derive(Debug, Clone, PartialEq)]
pub struct CycleReport {
    /// 1-based cycle number.
    pub index: usize,
    /// Energy dissipated during the cycle.
    pub energy: f64,
    /// Peak-to-peak range of the accumulated slip over the cycle, per cell.
    pub slip_range: Vec<f64>,
}

impl CycleReport {
    /// Largest slip amplitude (half the peak-to-peak range).
    pub fn max_slip_amplitude(&self) -> f64 {
        0.5 * self.slip_range.iter().fold(0.0f64, |m, v| m.max(*v))
    }
}

/// Result of [`march`](super::march).
#[derive(Debug, Clone, PartialEq)]
pub struct MarchResult {
    /// Cell centres.
    pub x: Vec<f64>,
    /// One report per increment.
    pub steps: Vec<StepReport>,
    /// One report per cycle (histories with cycles only).
    pub cycles: Vec<CycleReport>,
    /// The first cycle that the next one repeats (slip ranges and energy within
    /// `shakedown_tolerance`), if any.
    pub shakedown_cycle: Option<usize>,
    /// The largest change of a cell's peak-to-peak slip range between the last two cycles, as a
    /// fraction of `A f P_max` (the scale of [`Steady`](crate::history::Steady)'s tolerance);
    /// `None` with fewer than two cycles. For a march until steady, the change that met the
    /// tolerance.
    pub steady_change: Option<f64>,
}

impl MarchResult {
    /// The datum at which the front ends report each increment's relative displacement
    /// ([`MarchResult::relative_displacements`]): ten times the largest contact half-width the
    /// march reached, far enough that the contact's traction acts on the datum points as a point
    /// load (as `[wear] loop_datum` defaults to ten unworn half-widths); the distance between the
    /// outer cell centres if nothing touched. Always a length > 0.
    pub fn loop_datum(&self) -> f64 {
        let largest = self
            .steps
            .iter()
            .map(|s| 0.5 * (s.ends.right - s.ends.left))
            .fold(0.0, f64::max);
        if largest > 0.0 {
            return 10.0 * largest;
        }
        // Nothing touched: no shear, so every displacement is zero whatever the (positive) datum.
        match (self.x.first(), self.x.last()) {
            (Some(a), Some(b)) if b > a => b - a,
            _ => 1.0,
        }
    }

    /// The bodies' relative tangential displacement after each increment (the fretting loop
    /// against each step's Q), at the datum [`MarchResult::loop_datum`]:
    /// [`RelativeDisplacement`] for the definition and sign.
    pub fn relative_displacements(&self) -> Vec<f64> {
        let datum = self.loop_datum();
        self.steps
            .iter()
            .map(|s| s.relative_displacement.at_positive(datum))
            .collect()
    }
}
