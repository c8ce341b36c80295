//! Numerical time marching of the partial-slip problem for any load history (beyond the paper;
//! THEORY.md "Numerical time marching").
//!
//! Formulation: elastically similar bodies, so the pressure at each increment is the normal
//! solution for the current P. Tractions are piecewise constant on N equal cells spanning the
//! largest contact of the history, collocated at cell centres. The relative tangential surface
//! displacement is
//!
//! `h(x) = -(A/pi) integral q(xi) ln|xi - x| dxi + (A/4) sigma x + C`,
//!
//! with the rigid shift C fixed by `integral q = Q`. Lengths in the logarithm are scaled by
//! `l = 4L` (L the half-span), which changes only C and makes the cell matrix
//! `G_ij = -integral_cell_j ln(|xi - x_i|/l) dxi` symmetric positive definite Toeplitz.
//!
//! Each increment solves the Coulomb complementarity problem by an active set: cells that stick
//! keep `dh = 0` and `|q| <= f p`; cells that slip carry `q = f p sign(s)`, where the slip
//! increment `s = -dh` is positive in the sense positive Q drives (so friction opposes the relative
//! displacement increment, as THEORY.md states). Cells whose traction exceeds the limit start to
//! slip; slipping cells whose slip would reverse stick again; repeat until nothing changes. The
//! stick cells' linear system is solved exactly by the Toeplitz inverse of each contiguous stick
//! run (Gohberg-Semencul, O(n log n)), with preconditioned conjugate gradients coupling several
//! runs.
//!
//! Moving edges: each increment is split internally at the loads (linear within the increment)
//! where the contact half-width a(P) passes a cell centre. A cell joins the contact at that
//! moment, stuck with zero traction and zero pressure, and stays in contact until the receding
//! edge reaches its centre, where its pressure, and so its traction, is zero. The energy
//! dissipated is `f p |s|` per slipping cell and sub-step with the sub-step's mean pressure (see
//! `mean_pressure`); it is never negative.
//!
//! Stick and slip are reported kinematically, by the slip increment: a cell is labelled stuck in
//! an increment when it slid less than `slip_tolerance` times `A f P`. That threshold labels only;
//! the active set reverses a slipping cell only when its slip would reverse by more than rounding.

mod toeplitz;

use crate::error::{Error, Result};
use crate::history::History;
use crate::load::LoadPoint;
use crate::normal::Contact;
use std::f64::consts::PI;
use toeplitz::Toeplitz;

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
}

impl Default for MarchOptions {
    fn default() -> Self {
        Self {
            solver: LinearSolver::Toeplitz,
            cells: 400,
            max_passes: 200,
            slip_tolerance: 1e-10,
            shakedown_tolerance: 1e-3,
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

/// What a cell does in the current increment.
#[derive(Debug, Clone, Copy, PartialEq)]
enum Cell {
    Out,
    Stick,
    /// Slipping with `q = sign f p`.
    Slip(f64),
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
}

/// Summary of one increment.
#[derive(Debug, Clone, PartialEq)]
pub struct StepReport {
    /// 1-based increment number.
    pub step: usize,
    /// The load reached.
    pub load: LoadPoint,
    /// Contact half-width.
    pub half_width: f64,
    /// Every stick interval `[left, right]` (kinematic: no slip in this increment), left to right.
    pub stick_intervals: Vec<[f64; 2]>,
    /// Frictional energy dissipated in this increment (per unit thickness).
    pub energy_increment: f64,
    /// Total dissipated so far.
    pub energy: f64,
    /// Active-set passes used.
    pub passes: usize,
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

/// The marching state: `new` sets up the grid (the init stage), `step` advances one increment.
pub struct Marcher {
    contact: Contact,
    options: MarchOptions,
    compliance: f64,
    friction: f64,
    width: f64,
    x: Vec<f64>,
    kernel: Toeplitz,
    /// Row-major N x N kernel for [`LinearSolver::Dense`].
    dense: Option<Vec<f64>>,
    step: usize,
    /// The load reached by the last increment; `None` before the first (unloaded).
    load: Option<LoadPoint>,
    energy: f64,
    pressure: Vec<f64>,
    traction: Vec<f64>,
    slip: Vec<f64>,
    slip_increment: Vec<f64>,
    /// Sum of |slip| over the sub-steps of the current increment (for the stick/slip labels).
    slip_travel: Vec<f64>,
    /// Slip of the current sub-step.
    sub_slip: Vec<f64>,
    /// Pressure at the start of the current sub-step.
    pressure_start: Vec<f64>,
    /// Contact half-width reached (0 unloaded).
    half_width: f64,
    cells: Vec<Cell>,
    // Work buffers, reused by every increment.
    known: Vec<f64>,
    dq: Vec<f64>,
    work: Vec<f64>,
    rhs: Vec<f64>,
    u: Vec<f64>,
    v: Vec<f64>,
    /// The stick set `v` was solved for (empty: none).
    v_mask: Vec<bool>,
    /// Block elimination of the few stick cells outside the main run, for the current stick set.
    schur: Option<SchurCache>,
    pcg: [Vec<f64>; 4],
}

impl Marcher {
    /// A grid of `options.cells` cells spanning `[-half_span, half_span]`, which must cover every
    /// contact the history will reach. Starts unloaded.
    pub fn new(contact: &Contact, half_span: f64, options: &MarchOptions) -> Result<Self> {
        let n = options.cells;
        crate::error::positive("grid half-span", half_span)?;
        let width = 2.0 * half_span / n as f64;
        // Exactly symmetric (mirrored, not recomputed), so that both edges cross their cell
        // centres at the same load, where a sub-step puts the half-width at the centre exactly.
        let mut x: Vec<f64> = (0..n)
            .map(|i| -half_span + (i as f64 + 0.5) * width)
            .collect();
        for i in 0..n / 2 {
            x[n - 1 - i] = -x[i];
        }
        if n % 2 == 1 {
            x[n / 2] = 0.0;
        }
        let scale = 4.0 * half_span;
        let antiderivative = |t: f64| {
            if t == 0.0 {
                0.0
            } else {
                t * (t.abs() / scale).ln() - t
            }
        };
        let row = (0..n).map(|k| {
            let k = k as f64;
            -(antiderivative((k + 0.5) * width) - antiderivative((k - 0.5) * width))
        });
        let row: Vec<f64> = row.collect();
        let dense = (options.solver == LinearSolver::Dense).then(|| {
            let mut m = vec![0.0; n * n];
            for i in 0..n {
                for j in 0..n {
                    m[i * n + j] = row[i.abs_diff(j)];
                }
            }
            m
        });
        let kernel = Toeplitz::new(row)?;
        let zeros = vec![0.0; n];
        Ok(Self {
            contact: contact.clone(),
            options: *options,
            compliance: contact.compliance().value(),
            friction: contact.friction.value(),
            width,
            x,
            kernel,
            dense,
            step: 0,
            load: None,
            energy: 0.0,
            pressure: zeros.clone(),
            traction: zeros.clone(),
            slip: zeros.clone(),
            slip_increment: zeros.clone(),
            slip_travel: zeros.clone(),
            sub_slip: zeros.clone(),
            pressure_start: zeros.clone(),
            half_width: 0.0,
            cells: vec![Cell::Out; n],
            known: zeros.clone(),
            dq: zeros.clone(),
            work: zeros.clone(),
            rhs: zeros.clone(),
            u: zeros.clone(),
            v: zeros.clone(),
            v_mask: Vec::new(),
            schur: None,
            pcg: [zeros.clone(), zeros.clone(), zeros.clone(), zeros],
        })
    }

    /// The fields after the last increment.
    pub fn fields(&self) -> Fields<'_> {
        Fields {
            x: &self.x,
            pressure: &self.pressure,
            traction: &self.traction,
            slip: &self.slip,
            slip_increment: &self.slip_increment,
        }
    }

    /// Cell width.
    pub fn cell_width(&self) -> f64 {
        self.width
    }

    /// Advances to `load`, the load moving linearly from the previous one (the in-phase path of
    /// an increment).
    ///
    /// The increment is split internally wherever the contact edge crosses a cell centre (both
    /// edges cross together on the symmetric grid), so that a cell enters contact, stuck with
    /// zero traction and zero pressure, exactly when the edge reaches it, and leaves contact,
    /// releasing its traction, exactly when the edge passes it going back. Constraining a new
    /// cell from the start of the increment instead made its traction rise like
    /// `c dP / (pi sqrt(2 a s))` against a pressure `K_N sqrt(s)` (s from the edge), so cells
    /// just inside an advancing edge slipped forward on every rising half (a ratchet that
    /// dissipated even in full stick, with an energy growing like the squared edge advance per
    /// increment, not with the cell size). The sub-steps are reported as one increment, with
    /// the energy their sum.
    pub fn step(&mut self, load: LoadPoint) -> Result<StepReport> {
        let step = self.step + 1;
        let name = format!("history row {step}");
        let load = LoadPoint::new(&name, load.normal(), load.shear(), load.bulk())?;
        let f = self.friction;
        if load.shear().abs() >= f * load.normal() {
            return Err(Error::SlidesAtStep {
                step,
                shear: load.shear().abs(),
                limit: f * load.normal(),
            });
        }
        let a = self.contact.half_width(load.normal())?;
        let half_span = self.x[self.x.len() - 1] + 0.5 * self.width;
        if a > half_span * (1.0 + 1e-12) {
            return Err(Error::InvalidInput {
                field: format!("{name}.normal"),
                value: load.normal(),
                valid: "a load whose contact fits the grid (size the grid from the whole history)",
            });
        }
        // Receding increments need them too: without them (cells uncovered during the increment
        // kept in contact to its end, where their pressure is zero) a full-stick cycle
        // dissipated 7.7e-7 N mm/mm per cycle (flat-rounded, 100 cells, 100 steps per half) and
        // the energy per cycle was 2e-3 off at 10 steps per half, against 1e-4 with them: the
        // unloading increment reverses the loading one only when both see the same contact set.
        // Sub-steps: the load fractions at which a(P) passes a cell centre. The half-width at a
        // crossing is the centre itself, exactly, so the test `|x| < a` below is exact there.
        let n = self.x.len();
        let start = self.load;
        let (lo, hi) = (self.half_width.min(a), self.half_width.max(a));
        let mut crossings: Vec<(f64, f64)> = Vec::new();
        for &r in &self.x[n / 2..] {
            if r > lo && r < hi {
                let from = start.map_or(0.0, |p| p.normal());
                let t = (self.contact.load(r)? - from) / (load.normal() - from);
                if t > 0.0 && t < 1.0 {
                    crossings.push((t, r));
                }
            }
        }
        crossings.sort_by(|p, q| p.0.total_cmp(&q.0));
        crossings.push((1.0, a));
        self.slip_increment.fill(0.0);
        self.slip_travel.fill(0.0);
        let (mut energy_increment, mut passes) = (0.0, 0);
        for (t, a_t) in crossings {
            let target = match start {
                _ if t == 1.0 => load,
                Some(from) => from.lerp(&load, t),
                None => load.scaled(t),
            };
            let (energy, used) = self.advance(target, a_t, step)?;
            energy_increment += energy;
            passes += used;
        }
        self.energy += energy_increment;
        self.step = step;
        // Kinematic classification: contact cells that did not slip this increment.
        let tolerance = self.options.slip_tolerance * self.compliance * f * load.normal();
        let mut stick_intervals: Vec<[f64; 2]> = Vec::new();
        let mut open: Option<usize> = None;
        for i in 0..=n {
            let sticks = i < n && self.cells[i] != Cell::Out && self.slip_travel[i] <= tolerance;
            match (sticks, open) {
                (true, None) => open = Some(i),
                (false, Some(start)) => {
                    let left = (self.x[start] - 0.5 * self.width).max(-a);
                    let right = (self.x[i - 1] + 0.5 * self.width).min(a);
                    stick_intervals.push([left, right]);
                    open = None;
                }
                _ => {}
            }
        }
        Ok(StepReport {
            step,
            load,
            half_width: a,
            stick_intervals,
            energy_increment,
            energy: self.energy,
            passes,
        })
    }

    /// One sub-step: from the current state to `load`, whose contact half-width is `a` (cells
    /// with `|x| < a` are in contact during the whole sub-step). Returns the energy dissipated
    /// and the active-set passes used.
    ///
    /// The dissipation is the Coulomb rate `f p |ds/dt|` integrated by the trapezoidal rule,
    /// `f (p_start + p_end)/2 |s|` per slipping cell (Johnson, *Contact Mechanics*, section 7.2,
    /// for the frictional work `q ds` with `|q| = f p` while slipping). It is never negative.
    /// The end-of-step traction alone (`f p_end |s|`) is the rectangle rule, first order in the
    /// time step.
    fn advance(&mut self, load: LoadPoint, a: f64, step: usize) -> Result<(f64, usize)> {
        let n = self.x.len();
        let f = self.friction;
        self.pressure_start.copy_from_slice(&self.pressure);
        for i in 0..n {
            // A cell stays in contact until the receding edge reaches its centre (its pressure,
            // and so its traction, is zero then) and joins when the advancing edge does.
            let inside = self.x[i].abs() < a.max(self.half_width);
            self.pressure[i] = if inside {
                self.contact.pressure(a, self.x[i])?
            } else {
                0.0
            };
            match (inside, self.cells[i]) {
                (false, _) => self.cells[i] = Cell::Out,
                (true, Cell::Out) => self.cells[i] = Cell::Stick,
                _ => {}
            }
        }
        let d_sigma = load.bulk() - self.load.map_or(0.0, |p| p.bulk());
        if load.shear() == 0.0 && d_sigma == 0.0 && self.traction.iter().all(|q| *q == 0.0) {
            // Pressing alone (the first leg of a normal-first ramp): zero traction sticks and
            // carries no shear, which is the solution; nothing slips.
            self.sub_slip.fill(0.0);
            self.load = Some(load);
            self.half_width = a;
            return Ok((0.0, 0));
        }
        let c_disp = self.compliance / PI;
        // A slipping cell sticks again only when its slip would reverse by more than rounding
        // (1e-13 of A f P, the displacement scale; PCG stops at 1e-13 of its residual). This
        // is a property of the arithmetic, not the user's slip-labelling threshold, which must
        // not change the solution.
        let reversal = 1e-13 * self.compliance * f * load.normal();
        // A stick cell starts to slip only when its traction exceeds the limit by more than
        // rounding. Cells can sit exactly at the limit without slipping; with a relative test,
        // rounding pushed such cells over one at a time (190 passes where 5 do).
        let traction_tolerance = 1e-9 * f * self.pressure.iter().fold(0.0f64, |m, p| m.max(*p));
        let q_old_sum: f64 = self.traction.iter().sum();
        let mut passes = 0;
        loop {
            passes += 1;
            if passes > self.options.max_passes {
                return Err(Error::ActiveSet {
                    step,
                    iterations: self.options.max_passes,
                });
            }
            if !self.cells.contains(&Cell::Stick) {
                // All contact cells were flagged to slip while |Q| < fP: restart from full stick.
                for c in self.cells.iter_mut().filter(|c| matches!(c, Cell::Slip(_))) {
                    *c = Cell::Stick;
                }
            }
            // Known traction increments: slip cells at the friction limit, released cells to zero.
            for i in 0..n {
                self.known[i] = match self.cells[i] {
                    Cell::Out => -self.traction[i],
                    Cell::Slip(sign) => sign * f * self.pressure[i] - self.traction[i],
                    Cell::Stick => 0.0,
                };
            }
            apply(&mut self.kernel, &self.dense, &self.known, &mut self.work);
            for i in 0..n {
                self.rhs[i] = if self.cells[i] == Cell::Stick {
                    -self.work[i] - 0.25 * PI * d_sigma * self.x[i]
                } else {
                    0.0
                };
            }
            let target = load.shear() / self.width - q_old_sum - self.known.iter().sum::<f64>();
            self.solve_stick(&Rhs::Vector, step)?;
            self.solve_stick(&Rhs::Ones, step)?;
            let (su, sv) = (self.u.iter().sum::<f64>(), self.v.iter().sum::<f64>());
            let c = (su - target) / sv;
            for i in 0..n {
                self.dq[i] = self.known[i]
                    + if self.cells[i] == Cell::Stick {
                        self.u[i] - c * self.v[i]
                    } else {
                        0.0
                    };
            }
            apply(&mut self.kernel, &self.dense, &self.dq, &mut self.work);
            let mut changed = false;
            for i in 0..n {
                let s = -c_disp * (self.work[i] + 0.25 * PI * d_sigma * self.x[i] + c);
                match self.cells[i] {
                    Cell::Out => self.sub_slip[i] = 0.0,
                    Cell::Stick => {
                        self.sub_slip[i] = 0.0;
                        let q = self.traction[i] + self.dq[i];
                        if q.abs() > f * self.pressure[i] + traction_tolerance {
                            self.cells[i] = Cell::Slip(q.signum());
                            changed = true;
                        }
                    }
                    Cell::Slip(_) if self.pressure[i] == 0.0 => {
                        // Leaving contact: its traction goes to zero whichever way it slips.
                        self.sub_slip[i] = s;
                        self.cells[i] = Cell::Slip(if s < 0.0 { -1.0 } else { 1.0 });
                    }
                    Cell::Slip(sign) => {
                        self.sub_slip[i] = s;
                        if s * sign < -reversal {
                            self.cells[i] = Cell::Stick;
                            changed = true;
                        }
                    }
                }
            }
            if !changed {
                break;
            }
        }
        let mut energy = 0.0;
        for i in 0..n {
            self.traction[i] += self.dq[i];
            if self.cells[i] == Cell::Out {
                self.traction[i] = 0.0;
            }
            let s = self.sub_slip[i];
            self.slip[i] += s;
            self.slip_increment[i] += s;
            self.slip_travel[i] += s.abs();
            if s != 0.0 {
                let p = mean_pressure(
                    self.half_width,
                    a,
                    self.x[i],
                    self.pressure_start[i],
                    self.pressure[i],
                );
                energy += f * p * s.abs() * self.width;
            }
        }
        self.load = Some(load);
        self.half_width = a;
        Ok((energy, passes))
    }

    /// Solves `G_SS z = b` on the stick cells S, into `u` (b = rhs) or `v` (b = 1).
    fn solve_stick(&mut self, which: &Rhs, step: usize) -> Result<()> {
        if matches!(which, Rhs::Ones) {
            // v depends only on the stick set, which most passes and sub-steps keep.
            let same = self.v_mask.len() == self.cells.len()
                && self
                    .v_mask
                    .iter()
                    .zip(&self.cells)
                    .all(|(m, c)| *m == (*c == Cell::Stick));
            if same {
                return Ok(());
            }
            self.v_mask.clear();
        }
        let runs = stick_runs(&self.cells);
        let mut out = std::mem::take(match which {
            Rhs::Vector => &mut self.u,
            Rhs::Ones => &mut self.v,
        });
        let b: Vec<f64> = match which {
            Rhs::Vector => self.rhs.clone(),
            Rhs::Ones => self
                .cells
                .iter()
                .map(|c| if *c == Cell::Stick { 1.0 } else { 0.0 })
                .collect(),
        };
        out.iter_mut().for_each(|v| *v = 0.0);
        let result = if let Some(g) = &self.dense {
            dense_stick_solve(g, &self.cells, &b, &mut out, step)
        } else if runs.len() == 1 {
            let (s, e) = runs[0];
            self.kernel.solve(&b[s..e], &mut out[s..e]);
            Ok(())
        } else if self.schur_solve(&runs, &b, &mut out) {
            Ok(())
        } else {
            out.iter_mut().for_each(|v| *v = 0.0);
            self.pcg(&runs, &b, &mut out, step)
        };
        match which {
            Rhs::Vector => self.u = out,
            Rhs::Ones => {
                self.v = out;
                if result.is_ok() {
                    self.v_mask
                        .extend(self.cells.iter().map(|c| *c == Cell::Stick));
                }
            }
        }
        result
    }

    /// `G_SS z = b` when S is one long run B plus a few other cells E (typically cells that
    /// have just entered contact at an advancing edge and stick while their neighbours slip), by
    /// block elimination (the Schur complement; Golub & Van Loan, *Matrix Computations*, 4th ed.,
    /// section 3.2.11): `W = G_BB^{-1} G_BE`, `S = G_EE - G_EB W` (symmetric positive definite
    /// because G is), `z_E = S^{-1} (b_E - G_EB G_BB^{-1} b_B)`, `z_B = G_BB^{-1} b_B - W z_E`.
    /// W and the Cholesky factor of S are kept while the stick set is unchanged. Exact up to
    /// rounding, like the single-run solve. Returns false (nothing solved) when E is too large
    /// or S is not numerically positive definite; the caller then uses CG.
    fn schur_solve(&mut self, runs: &[(usize, usize)], b: &[f64], z: &mut [f64]) -> bool {
        const MAX_EXTRA: usize = 32;
        let same = self.schur.as_ref().is_some_and(|c| {
            c.mask.len() == self.cells.len()
                && c.mask
                    .iter()
                    .zip(&self.cells)
                    .all(|(m, cell)| *m == (*cell == Cell::Stick))
        });
        if !same {
            self.schur = None;
            // No stick cell at all (no cell centre inside the contact yet): nothing to eliminate.
            let Some(&(s0, e0)) = runs.iter().max_by_key(|(s, e)| e - s) else {
                return false;
            };
            let extra: Vec<usize> = runs
                .iter()
                .filter(|r| r.0 != s0)
                .flat_map(|&(s, e)| s..e)
                .collect();
            let (k, nb) = (extra.len(), e0 - s0);
            if k > MAX_EXTRA || nb == 0 {
                return false;
            }
            let row = self.kernel.row().to_vec();
            let mut w = vec![0.0; k * nb];
            let mut column = vec![0.0; nb];
            for (j, &e) in extra.iter().enumerate() {
                for (i, c) in column.iter_mut().enumerate() {
                    *c = row[(s0 + i).abs_diff(e)];
                }
                self.kernel.solve(&column, &mut w[j * nb..(j + 1) * nb]);
            }
            // S = G_EE - G_EB W, then its Cholesky factor (lower, row-major).
            let mut l = vec![0.0; k * k];
            for a in 0..k {
                for c in 0..=a {
                    let coupling: f64 = (0..nb)
                        .map(|i| row[(s0 + i).abs_diff(extra[a])] * w[c * nb + i])
                        .sum();
                    l[a * k + c] = row[extra[a].abs_diff(extra[c])] - coupling;
                }
            }
            for a in 0..k {
                for c in 0..=a {
                    let mut sum = l[a * k + c];
                    for m in 0..c {
                        sum -= l[a * k + m] * l[c * k + m];
                    }
                    if a == c {
                        if sum.is_nan() || sum <= 0.0 {
                            return false;
                        }
                        l[a * k + a] = sum.sqrt();
                    } else {
                        l[a * k + c] = sum / l[c * k + c];
                    }
                }
            }
            self.schur = Some(SchurCache {
                mask: self.cells.iter().map(|c| *c == Cell::Stick).collect(),
                start: s0,
                end: e0,
                extra,
                w,
                l,
            });
        }
        let Some(cache) = self.schur.as_ref() else {
            return false;
        };
        let (s0, e0, k) = (cache.start, cache.end, cache.extra.len());
        let nb = e0 - s0;
        let mut y = vec![0.0; nb];
        self.kernel.solve(&b[s0..e0], &mut y);
        let row = self.kernel.row();
        let mut r: Vec<f64> = cache
            .extra
            .iter()
            .map(|&e| {
                b[e] - (0..nb)
                    .map(|i| row[(s0 + i).abs_diff(e)] * y[i])
                    .sum::<f64>()
            })
            .collect();
        // Forward and back substitution with L L^T.
        for a in 0..k {
            let sum: f64 = (0..a).map(|m| cache.l[a * k + m] * r[m]).sum();
            r[a] = (r[a] - sum) / cache.l[a * k + a];
        }
        for a in (0..k).rev() {
            let sum: f64 = (a + 1..k).map(|m| cache.l[m * k + a] * r[m]).sum();
            r[a] = (r[a] - sum) / cache.l[a * k + a];
        }
        for (j, &e) in cache.extra.iter().enumerate() {
            z[e] = r[j];
            for (yi, wi) in y.iter_mut().zip(&cache.w[j * nb..(j + 1) * nb]) {
                *yi -= wi * r[j];
            }
        }
        z[s0..e0].copy_from_slice(&y);
        true
    }

    /// Conjugate gradients on the stick cells, preconditioned by the exact inverse of each run.
    fn pcg(
        &mut self,
        runs: &[(usize, usize)],
        b: &[f64],
        z: &mut [f64],
        step: usize,
    ) -> Result<()> {
        let [r, p, ap, y] = &mut self.pcg;
        r.copy_from_slice(b);
        let b_norm = b.iter().map(|v| v * v).sum::<f64>().sqrt();
        if b_norm == 0.0 {
            return Ok(());
        }
        let precondition = |kernel: &mut Toeplitz, r: &[f64], y: &mut [f64]| {
            y.iter_mut().for_each(|v| *v = 0.0);
            for &(s, e) in runs {
                kernel.solve(&r[s..e], &mut y[s..e]);
            }
        };
        precondition(&mut self.kernel, r, y);
        p.copy_from_slice(y);
        let mut rz: f64 = r.iter().zip(y.iter()).map(|(a, b)| a * b).sum();
        for _ in 0..500 {
            self.kernel.apply(p, ap);
            for (i, c) in self.cells.iter().enumerate() {
                if *c != Cell::Stick {
                    ap[i] = 0.0;
                }
            }
            let alpha = rz / p.iter().zip(ap.iter()).map(|(a, b)| a * b).sum::<f64>();
            for i in 0..z.len() {
                z[i] += alpha * p[i];
                r[i] -= alpha * ap[i];
            }
            if r.iter().map(|v| v * v).sum::<f64>().sqrt() <= 1e-13 * b_norm {
                return Ok(());
            }
            precondition(&mut self.kernel, r, y);
            let next: f64 = r.iter().zip(y.iter()).map(|(a, b)| a * b).sum();
            let beta = next / rz;
            rz = next;
            for i in 0..p.len() {
                p[i] = y[i] + beta * p[i];
            }
        }
        Err(Error::ActiveSet {
            step,
            iterations: 500,
        })
    }
}

/// Mean pressure at `x` over a sub-step in which the half-width moves from `a0` to `a1`, given
/// the pressures `p0`, `p1` at its ends (compressive positive).
///
/// Every profile's pressure has the form `p = sqrt(u) psi` with `u = a^2 - x^2` and `psi`
/// smooth (the normal problem's pressure formula, as in Johnson, *Contact Mechanics*, section 5.7: the factor
/// `sqrt(a^2 - x^2)` multiplies a regular integral). Near an edge `sqrt(u)` is not smooth in
/// time, and the trapezoidal rule on `p` then has an error `O(dt^1.5)` summed over a cell's
/// steps. This is product integration (Atkinson, *An Introduction to Numerical Analysis*, 2nd
/// ed., section 5.6): `sqrt(u)` is integrated exactly with `u` linear over the sub-step (exact for
/// Hertz, where `a^2` is linear in P),
/// `mean sqrt(u) = (2/3)(u0 + sqrt(u0 u1) + u1)/(sqrt(u0) + sqrt(u1))`, and `psi` by the
/// trapezoidal rule; at an end where `u = 0` (the cell entered there) `psi` is taken from the
/// other end.
fn mean_pressure(a0: f64, a1: f64, x: f64, p0: f64, p1: f64) -> f64 {
    let u0 = (a0 * a0 - x * x).max(0.0);
    let u1 = (a1 * a1 - x * x).max(0.0);
    let (r0, r1) = (u0.sqrt(), u1.sqrt());
    if r0 + r1 == 0.0 {
        return 0.0;
    }
    let psi0 = if r0 > 0.0 { p0 / r0 } else { p1 / r1 };
    let psi1 = if r1 > 0.0 { p1 / r1 } else { psi0 };
    let root_mean = (2.0 / 3.0) * (u0 + r0 * r1 + u1) / (r0 + r1);
    root_mean * 0.5 * (psi0 + psi1)
}

/// See [`Marcher::schur_solve`].
struct SchurCache {
    mask: Vec<bool>,
    start: usize,
    end: usize,
    extra: Vec<usize>,
    /// `G_BB^{-1} G_BE`, one column of length `end - start` per extra cell.
    w: Vec<f64>,
    /// Cholesky factor of the Schur complement, row-major k x k.
    l: Vec<f64>,
}

enum Rhs {
    Vector,
    Ones,
}

/// `y = G v`, by FFT or by the dense matrix.
fn apply(kernel: &mut Toeplitz, dense: &Option<Vec<f64>>, v: &[f64], y: &mut [f64]) {
    match dense {
        None => kernel.apply(v, y),
        Some(g) => {
            let n = v.len();
            for (i, yi) in y.iter_mut().enumerate() {
                *yi = g[i * n..(i + 1) * n]
                    .iter()
                    .zip(v)
                    .map(|(a, b)| a * b)
                    .sum();
            }
        }
    }
}

/// Cholesky solve of `G_SS z = b` over all stick cells (the dense route).
fn dense_stick_solve(
    g: &[f64],
    cells: &[Cell],
    b: &[f64],
    z: &mut [f64],
    step: usize,
) -> Result<()> {
    let n_all = cells.len();
    let s: Vec<usize> = (0..n_all).filter(|&i| cells[i] == Cell::Stick).collect();
    let n = s.len();
    let mut l = vec![0.0; n * n];
    for i in 0..n {
        for j in 0..=i {
            let mut sum = g[s[i] * n_all + s[j]];
            for k in 0..j {
                sum -= l[i * n + k] * l[j * n + k];
            }
            if i == j {
                if sum <= 0.0 || sum.is_nan() {
                    return Err(Error::NonPositivePivot { step, index: s[i] });
                }
                l[i * n + i] = sum.sqrt();
            } else {
                l[i * n + j] = sum / l[j * n + j];
            }
        }
    }
    let mut y: Vec<f64> = s.iter().map(|&i| b[i]).collect();
    for i in 0..n {
        let sum: f64 = (0..i).map(|k| l[i * n + k] * y[k]).sum();
        y[i] = (y[i] - sum) / l[i * n + i];
    }
    for i in (0..n).rev() {
        let sum: f64 = (i + 1..n).map(|k| l[k * n + i] * y[k]).sum();
        y[i] = (y[i] - sum) / l[i * n + i];
    }
    for (k, &i) in s.iter().enumerate() {
        z[i] = y[k];
    }
    Ok(())
}

/// Maximal runs `[start, end)` of stick cells.
fn stick_runs(cells: &[Cell]) -> Vec<(usize, usize)> {
    let mut runs = Vec::new();
    let mut start = None;
    for i in 0..=cells.len() {
        let stick = i < cells.len() && cells[i] == Cell::Stick;
        match (stick, start) {
            (true, None) => start = Some(i),
            (false, Some(s)) => {
                runs.push((s, i));
                start = None;
            }
            _ => {}
        }
    }
    runs
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

/// Result of [`march`].
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
}

/// Marches through `history`. `observer` sees each increment's report and fields as it is made
/// (for progress bars and field output); nothing is printed or written here.
pub fn march(
    contact: &Contact,
    history: &History,
    options: &MarchOptions,
    mut observer: impl FnMut(&StepReport, &Fields),
) -> Result<MarchResult> {
    if history.loads().is_empty() {
        return Err(Error::InvalidTable {
            row: 0,
            problem: "the history has no rows".into(),
        });
    }
    for (i, p) in history.loads().iter().enumerate() {
        LoadPoint::new(
            &format!("history row {}", i + 1),
            p.normal(),
            p.shear(),
            p.bulk(),
        )?;
    }
    let p_max = history
        .loads()
        .iter()
        .map(|p| p.normal())
        .fold(0.0, f64::max);
    let span = contact.half_width(p_max)?;
    let mut marcher = Marcher::new(contact, span, options)?;
    let n = options.cells;
    let mut steps = Vec::with_capacity(history.loads().len());
    let mut cycles = Vec::new();
    let (mut low, mut high) = (vec![0.0; n], vec![0.0; n]);
    let mut cycle_energy_start = 0.0;
    for (k, load) in history.loads().iter().enumerate() {
        let cycle_of = |k: usize| {
            history
                .cycles()
                .and_then(|c| {
                    (k >= c.first_step()).then(|| (k - c.first_step()) / c.steps_per_cycle())
                })
                .filter(|&c| history.cycles().is_some_and(|s| c < s.count()))
        };
        if let Some(c) = cycle_of(k) {
            if k == history.cycles().unwrap().first_step()
                + c * history.cycles().unwrap().steps_per_cycle()
            {
                low.copy_from_slice(&marcher.slip);
                high.copy_from_slice(&marcher.slip);
                cycle_energy_start = marcher.energy;
            }
        }
        let report = marcher.step(*load)?;
        observer(&report, &marcher.fields());
        if let Some(c) = cycle_of(k) {
            for i in 0..n {
                low[i] = low[i].min(marcher.slip[i]);
                high[i] = high[i].max(marcher.slip[i]);
            }
            let s = history.cycles().unwrap();
            if k + 1 == s.first_step() + (c + 1) * s.steps_per_cycle() {
                cycles.push(CycleReport {
                    index: c + 1,
                    energy: marcher.energy - cycle_energy_start,
                    slip_range: high.iter().zip(&low).map(|(h, l)| h - l).collect(),
                });
            }
        }
        steps.push(report);
    }
    let tol = options.shakedown_tolerance;
    let slip_floor = 1e-12 * contact.compliance().value() * contact.friction.value() * p_max;
    let shakedown_cycle = cycles.windows(2).find_map(|w| {
        let scale = w[0].slip_range.iter().fold(slip_floor, |m, v| m.max(*v));
        let ranges = w[0]
            .slip_range
            .iter()
            .zip(&w[1].slip_range)
            .all(|(a, b)| (a - b).abs() <= tol * scale);
        let energy =
            (w[0].energy - w[1].energy).abs() <= tol * w[0].energy.abs().max(slip_floor * p_max);
        (ranges && energy).then_some(w[0].index)
    });
    Ok(MarchResult {
        x: marcher.x.clone(),
        steps,
        cycles,
        shakedown_cycle,
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::{Friction, Material, Profile};

    #[test]
    fn several_stick_runs_are_solved_exactly_by_block_elimination_and_by_pcg() {
        // Two stick runs couple through the kernel; block elimination of the shorter run and PCG
        // (run-exact preconditioner) must both agree with dense elimination of G_SS to 1e-10
        // relative (PCG stops at 1e-13 on the residual; the kernel's condition number is ~1e3).
        let contact = Contact::new(
            Profile::hertz(50.0).unwrap(),
            Material::new(200_000.0, 0.3).unwrap(),
            Friction::new(0.6).unwrap(),
        );
        let mut m = Marcher::new(
            &contact,
            1.0,
            &MarchOptions::default().with_cells(64).unwrap(),
        )
        .unwrap();
        let stick: Vec<usize> = (5..20).chain(31..52).collect();
        for (i, c) in m.cells.iter_mut().enumerate() {
            *c = if stick.contains(&i) {
                Cell::Stick
            } else {
                Cell::Slip(1.0)
            };
        }
        for i in 0..64 {
            m.rhs[i] = if stick.contains(&i) {
                (i as f64 * 0.7).sin() + 0.3
            } else {
                0.0
            };
        }
        m.solve_stick(&Rhs::Vector, 1).unwrap();
        // Dense reference from the kernel's definition.
        let w = m.width;
        let scale = 4.0;
        let f = |t: f64| {
            if t == 0.0 {
                0.0
            } else {
                t * (t.abs() / scale).ln() - t
            }
        };
        let g = |k: usize| -(f((k as f64 + 0.5) * w) - f((k as f64 - 0.5) * w));
        let matrix = stick
            .iter()
            .map(|&i| stick.iter().map(|&j| g(i.abs_diff(j))).collect())
            .collect();
        let b: Vec<f64> = stick.iter().map(|&i| m.rhs[i]).collect();
        let z = toeplitz::tests::dense_solve(matrix, &b);
        let size = z.iter().fold(0.0f64, |s, v| s.max(v.abs()));
        for (k, &i) in stick.iter().enumerate() {
            assert!(
                (m.u[i] - z[k]).abs() < 1e-10 * size,
                "cell {i}: {} vs {}",
                m.u[i],
                z[k]
            );
        }
        assert!(m
            .u
            .iter()
            .enumerate()
            .all(|(i, v)| stick.contains(&i) || *v == 0.0));
        // The same system by CG alone (the route for many cells outside the longest run).
        let runs = stick_runs(&m.cells);
        let b = m.rhs.clone();
        let mut by_cg = vec![0.0; 64];
        m.pcg(&runs, &b, &mut by_cg, 1).unwrap();
        for (k, &i) in stick.iter().enumerate() {
            assert!(
                (by_cg[i] - z[k]).abs() < 1e-10 * size,
                "CG, cell {i}: {} vs {}",
                by_cg[i],
                z[k]
            );
        }
    }

    #[test]
    fn a_failed_cholesky_pivot_is_its_own_error() {
        // The kernel block is positive definite in exact arithmetic; a matrix that is not must be
        // reported as a non-positive pivot at the cell where it fails, not as an active-set
        // failure. [[1, 2], [2, 1]] fails at its second pivot (1 - 4 < 0).
        let g = [1.0, 2.0, 2.0, 1.0];
        let cells = [Cell::Stick, Cell::Stick];
        let mut z = [0.0; 2];
        let err = dense_stick_solve(&g, &cells, &[1.0, 1.0], &mut z, 7).unwrap_err();
        assert_eq!(err, Error::NonPositivePivot { step: 7, index: 1 });
        assert!(err.to_string().contains("step 7"), "{err}");
    }
}
