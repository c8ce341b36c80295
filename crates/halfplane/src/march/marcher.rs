//! The marcher: the state of one march ([`Marcher`]) and its increments. `Marcher::new` sets
//! up the grid and the kernel; `step` splits an increment where a contact end crosses a cell
//! centre (`crossings.rs`); `advance` solves one sub-step's Coulomb complementarity problem by
//! the active set and adds up its dissipation.
//!
//! Owns the active set (which cells are out, stuck or slipping) and the state fields. Never
//! solves a linear system (`solve.rs`), builds the kernel (`kernel.rs`), integrates a sub-step's
//! energy (`dissipation.rs`), labels its stick intervals (`intervals.rs`), does cycle accounting
//! (`cycles.rs`) or holds a worn gap (`worn_gap.rs`).

use super::evaluate::EndSolution;
use super::kernel;
use super::layout::Layout;
use super::moments::PressureShape;
use super::predict::{restick_reversed, StickEnds};
use super::solve::{apply, sum, Rhs, SchurCache};
use super::toeplitz::Toeplitz;
use super::types::{Fields, LinearSolver, MarchOptions, RelativeDisplacement, StepReport};
use super::worn::Worn;
use super::worn_gap::Gap;
use crate::error::{Error, Result};
use crate::labels::{Edge, PerEdge};
use crate::load::LoadPoint;
use crate::normal::Contact;
use crate::normal_moment::NormalContact;
use std::f64::consts::PI;

/// What a cell does in the current increment.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(super) enum Cell {
    Out,
    Stick,
    /// Slipping with `q = sign f p`.
    Slip(f64),
}

/// The marching state: `new` sets up the grid (the init stage), `step` advances one increment.
///
/// The fields `solve.rs` needs (the stick set, the kernel, the right-hand side, the solutions and
/// the solver caches), those `dissipation.rs` reads (the sub-step's start and end, its trial
/// pass, and work buffers) and those `cycles.rs` reads (grid, slip, energy) are visible to the
/// `march` module; the rest of the state is this file's alone.
pub struct Marcher {
    pub(super) contact: Contact,
    pub(super) options: MarchOptions,
    pub(super) compliance: f64,
    pub(super) friction: f64,
    pub(super) width: f64,
    /// The length `l` scaling the logarithm of the kernel.
    pub(super) scale: f64,
    pub(super) x: Vec<f64>,
    pub(super) kernel: Toeplitz,
    /// Row-major N x N kernel for [`LinearSolver::Dense`].
    pub(super) dense: Option<Vec<f64>>,
    step: usize,
    /// The load reached by the last increment; `None` before the first (unloaded).
    pub(super) load: Option<LoadPoint>,
    pub(super) energy: f64,
    /// The bodies' relative tangential displacement, datum the kernel's scale `l`
    /// ([`RelativeDisplacement`]).
    pub(super) displacement: f64,
    pub(super) pressure: Vec<f64>,
    /// The shear traction at each cell's centre (what is reported).
    pub(super) traction: Vec<f64>,
    /// The limit `f p` of the current sub-step: its cell means and slopes, and its shape
    /// (`moments.rs`; for the sub-cell boundaries).
    pub(super) limit_mean: Vec<f64>,
    pub(super) limit_slope: Vec<f64>,
    pub(super) shape: PressureShape,
    pub(super) slip: Vec<f64>,
    pub(super) slip_increment: Vec<f64>,
    /// Sum of |slip| over the sub-steps of the current increment (for the stick/slip labels).
    pub(super) slip_travel: Vec<f64>,
    /// Slip of the current sub-step.
    pub(super) sub_slip: Vec<f64>,
    /// Slip of the current sub-step's first active-set pass (the stick set of its start).
    pub(super) trial_slip: Vec<f64>,
    /// The trial traction with which a stick cell was last flagged to slip.
    pub(super) flag_traction: Vec<f64>,
    /// The cells at the start of the current sub-step (entering cells stuck).
    pub(super) start_cells: Vec<Cell>,
    /// Pressure at the start of the current sub-step.
    pub(super) pressure_start: Vec<f64>,
    /// The contact reached; `None` unloaded.
    pub(super) state: Option<NormalContact>,
    /// The contact the current sub-step goes to.
    pub(super) target: Option<NormalContact>,
    /// A worn gap at the cell centres (`set_gap`): the contact's pressure comes from the grid
    /// (`gap.rs`) instead of the profile's normal problem.
    pub(super) gap: Option<Gap>,
    /// `integral p |ds|` at each cell since the last `take_pressure_slip` (the energy
    /// quadrature's per-cell sums without f): what wear removes.
    pub(super) pressure_slip: Vec<f64>,
    pub(super) cells: Vec<Cell>,
    /// The last solve of `evaluate.rs`: its layout, its boundaries' solutions and its shift
    /// (also the cell-level sub-step's, for `boundary.rs`).
    pub(super) layout: Option<Layout>,
    pub(super) end_solutions: Vec<EndSolution>,
    pub(super) shift: f64,
    /// The last increment as reported with its boundaries inside cells (`boundary.rs`).
    pub(super) view: Option<super::boundary::View>,
    /// The kinks, and the located slip, displacement and energy, as reported (`report.rs`).
    pub(super) reported_kinks: Vec<super::boundary::TractionKink>,
    pub(super) reported: Option<super::report::Reported>,
    /// The last increment's located solution and the stretch the located solves start from
    /// (`chain.rs`).
    pub(super) located: Option<super::chain::Model>,
    pub(super) stretch: Option<super::chain::Stretch>,
    /// A located solve's start (the smooth part's cell means and slopes) and end (its cells'
    /// model; `evaluate.rs`).
    pub(super) start_mean: Vec<f64>,
    pub(super) start_slope: Vec<f64>,
    pub(super) end_model: Option<super::chain::Cells>,
    // Work buffers, reused by every increment.
    pub(super) known: Vec<f64>,
    /// `G known` of the last pass (`dissipation.rs` reuses it).
    pub(super) g_known: Vec<f64>,
    pub(super) dq: Vec<f64>,
    pub(super) work: Vec<f64>,
    /// Onset time of each cell in the current sub-step (`dissipation.rs`).
    pub(super) onset: Vec<f64>,
    /// Traction rate of each slipping cell while it slips (`dissipation.rs`).
    pub(super) change: Vec<f64>,
    pub(super) rhs: Vec<f64>,
    pub(super) u: Vec<f64>,
    pub(super) v: Vec<f64>,
    /// The stick set `v` was solved for (empty: none).
    pub(super) v_mask: Vec<bool>,
    /// Block elimination of the few stick cells outside the main run, for the current stick set.
    pub(super) schur: Option<SchurCache>,
    pub(super) pcg: [Vec<f64>; 4],
}

impl Marcher {
    /// A grid of `options.cells` cells spanning `[-half_span, half_span]`, which must cover every
    /// contact the history will reach. Starts unloaded.
    pub fn new(contact: &Contact, half_span: f64, options: &MarchOptions) -> Result<Self> {
        crate::error::positive("grid half-span", half_span)?;
        Self::spanning(contact, [-half_span, half_span], options)
    }

    /// A grid of `options.cells` cells spanning `[lower, upper]` (`lower < upper`), which must
    /// cover every contact the history will reach: under a moment, or on an asymmetric profile,
    /// the contacts need not be centred on x = 0. A grid centred on 0 is mirrored exactly (see
    /// [`Marcher::new`]). Starts unloaded.
    pub fn spanning(contact: &Contact, span: [f64; 2], options: &MarchOptions) -> Result<Self> {
        let n = options.cells();
        let [lower, upper] = span;
        crate::error::physical("grid lower end", lower)?;
        crate::error::physical("grid upper end", upper)?;
        crate::error::positive("grid length", upper - lower)?;
        let width = (upper - lower) / n as f64;
        let mut x: Vec<f64> = (0..n).map(|i| lower + (i as f64 + 0.5) * width).collect();
        if lower == -upper {
            // Exactly symmetric (mirrored, not recomputed), so that both edges of a centred
            // contact cross their cell centres at the same load, where a sub-step puts the
            // half-width at the centre exactly.
            for i in 0..n / 2 {
                x[n - 1 - i] = -x[i];
            }
            if n % 2 == 1 {
                x[n / 2] = 0.0;
            }
        }
        // The log kernel's scale must exceed the grid's length to stay positive definite
        // (kernel.rs); twice the length, as 4L for the symmetric span [-L, L].
        let scale = 2.0 * (upper - lower);
        let row = kernel::cell_row(n, width, scale);
        let dense = (options.solver() == LinearSolver::Dense).then(|| kernel::dense_matrix(&row));
        let mut kernel = Toeplitz::new(row)?;
        if options.sub_cell() && !cfg!(feature = "sub-cell") {
            return Err(Error::InvalidInput {
                field: "solver.sub_cell_boundaries".into(),
                value: 1.0,
                valid: "false in this build: the library's `sub-cell` feature (on by default, off in the web page) is left out",
            });
        }
        if options.sub_cell() {
            // The slopes' product only serves the located boundaries (`evaluate.rs`).
            kernel = kernel.with_slopes(&kernel::slope_column(n, width));
        }
        let zeros = vec![0.0; n];
        Ok(Self {
            contact: contact.clone(),
            options: *options,
            compliance: contact.compliance().value(),
            friction: contact.friction.value(),
            width,
            scale,
            shape: PressureShape::new(&x, &zeros, PerEdge::default()),
            x,
            kernel,
            dense,
            step: 0,
            load: None,
            energy: 0.0,
            displacement: 0.0,
            pressure: zeros.clone(),
            traction: zeros.clone(),
            limit_mean: zeros.clone(),
            limit_slope: zeros.clone(),
            slip: zeros.clone(),
            slip_increment: zeros.clone(),
            slip_travel: zeros.clone(),
            sub_slip: zeros.clone(),
            trial_slip: zeros.clone(),
            flag_traction: zeros.clone(),
            start_cells: vec![Cell::Out; n],
            pressure_start: zeros.clone(),
            state: None,
            target: None,
            gap: None,
            pressure_slip: zeros.clone(),
            cells: vec![Cell::Out; n],
            layout: None,
            end_solutions: Vec::new(),
            shift: 0.0,
            view: None,
            reported_kinks: Vec::new(),
            reported: options.sub_cell().then(|| super::report::Reported::new(n)),
            located: None,
            stretch: None,
            start_mean: zeros.clone(),
            start_slope: zeros.clone(),
            end_model: None,
            known: zeros.clone(),
            g_known: zeros.clone(),
            dq: zeros.clone(),
            work: zeros.clone(),
            onset: zeros.clone(),
            change: zeros.clone(),
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
        let (slip, slip_increment, ..) = self.reported();
        Fields {
            x: &self.x,
            pressure: &self.pressure,
            traction: self.view.as_ref().map_or(&self.traction, |v| &v.traction),
            slip,
            slip_increment,
            kinks: &self.reported_kinks,
        }
    }

    /// The relative tangential displacement of the bodies after the last increment.
    pub fn relative_displacement(&self) -> RelativeDisplacement {
        let shear = self.load.map_or(0.0, |l| l.shear());
        RelativeDisplacement::new(self.reported().3, self.scale, self.compliance, shear)
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
    /// increment, not with the cell size). Several cells entering in one sub-step, each stuck
    /// from its own crossing fraction with a traction linear in time after it, was measured and
    /// not adopted: it lifted cells near the edge from 0.43 to 0.61-0.79 of the friction limit on
    /// a full-stick cycle (BENCHMARKS.md, issue 20). The sub-steps are reported as one increment,
    /// with the energy their sum.
    pub fn step(&mut self, load: LoadPoint) -> Result<StepReport> {
        let step = self.step + 1;
        let name = format!("history row {step}");
        let load = LoadPoint::new(&name, load.normal(), load.shear(), load.bulk())?
            .with_moment(&name, load.moment())?;
        let f = self.friction;
        if load.shear().abs() >= f * load.normal() {
            return Err(Error::SlidesAtStep {
                step,
                shear: load.shear().abs(),
                limit: f * load.normal(),
            });
        }
        let target = match (&self.gap, &self.state) {
            // `cfg!`: a build without the feature (the web page) leaves the grid's normal
            // problem out of its binary; `Worn` refuses to start there, so no gap is ever set.
            (Some(_), _) if cfg!(feature = "wear") => self.grid_target(&load, step)?,
            (Some(_), _) => return Err(Worn::not_built()),
            (None, Some(near)) => self
                .contact
                .contact_near(load.normal(), load.moment(), near)
                .map_err(|e| e.with_moment_field(&format!("{name}.moment")))?,
            (None, None) => self
                .contact
                .contact_at(&load)
                .map_err(|e| e.with_moment_field(&format!("{name}.moment")))?,
        };
        let (lower, upper) = (
            self.x[0] - 0.5 * self.width,
            self.x[self.x.len() - 1] + 0.5 * self.width,
        );
        let slack = 1e-12 * (upper - lower);
        if target.end(Edge::Left) < lower - slack || target.end(Edge::Right) > upper + slack {
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
        // Sub-steps: the load fractions at which a contact end passes a cell centre, with that
        // end at the centre exactly, so the tests `b1 < x < b2` in `press` are exact there.
        let start = self.load;
        let start_bulk = start.map_or(0.0, |p| p.bulk());
        let pressing = load.shear() == 0.0
            && load.bulk() == start_bulk
            && self.traction.iter().all(|q| *q == 0.0);
        let mut crossings = if pressing {
            // Pressing alone: every sub-step would only move the edges (zero traction sticks, see
            // `advance`), so the end state is reached in one, without the O(N) work per crossing.
            Vec::new()
        } else {
            self.crossings(start, &load, &target)?
        };
        crossings.push((1.0, target));
        self.slip_increment.fill(0.0);
        self.slip_travel.fill(0.0);
        let (mut energy_increment, mut passes) = (0.0, 0);
        for (t, contact_t) in crossings {
            let target_load = match start {
                _ if t == 1.0 => load,
                Some(from) => from.lerp(&load, t),
                None => load.scaled(t),
            };
            let (energy, used) = self.advance(target_load, contact_t, step, t == 1.0)?;
            energy_increment += energy;
            passes += used;
        }
        if self.locates()
            && self.located.is_none()
            && !self.cells.iter().any(|c| matches!(c, Cell::Slip(_)))
        {
            // Stuck (the pressed state above all): the cell-level state is its own located
            // solution, and may start a stretch (`chain.rs`).
            self.located = Some(self.stuck_model(self.traction.clone(), load));
        }
        self.energy += energy_increment;
        let energy_increment = self.report(energy_increment);
        self.step = step;
        self.reported_kinks = self.view.as_ref().map_or(Vec::new(), |v| v.kinks.clone());
        // Kinematic classification: contact cells that did not slip this increment.
        let ends = target.ends();
        let tolerance = self.options.slip_tolerance() * self.compliance * f * load.normal();
        let stick_intervals = self.stick_intervals(ends, tolerance);
        Ok(StepReport {
            step,
            load,
            half_width: target.half_width(),
            ends,
            stick_intervals,
            energy_increment,
            energy: self.reported().2,
            passes,
            relative_displacement: self.relative_displacement(),
        })
    }

    /// One sub-step: from the current state to `load`, whose contact is `target` (cells inside
    /// both it and the current contact are in contact during the whole sub-step). Returns the
    /// energy dissipated and the active-set passes used.
    ///
    /// The dissipation is the Coulomb work `f p |ds|` (Johnson, *Contact Mechanics*, section
    /// 7.2, for the frictional work `q ds` with `|q| = f p` while slipping), integrated over the
    /// sub-step by `dissipation.rs` with the onsets, the start-set slip rates and the curvature
    /// of the slipping tractions taken into account. It is never negative. The end-of-step
    /// traction alone (`f p_end |s|`) is the rectangle rule, first order in the time step; the
    /// mean pressure times the slip is first order too, near moving edges.
    fn advance(
        &mut self,
        load: LoadPoint,
        target: NormalContact,
        step: usize,
        last: bool,
    ) -> Result<(f64, usize)> {
        let n = self.x.len();
        let f = self.friction;
        self.press(&target)?;
        let ends_start = self.ends();
        let d_sigma = load.bulk() - self.load.map_or(0.0, |p| p.bulk());
        if load.shear() == 0.0 && d_sigma == 0.0 && self.traction.iter().all(|q| *q == 0.0) {
            // Pressing alone (the first leg of a normal-first ramp): zero traction sticks and
            // carries no shear, which is the solution; nothing slips.
            self.sub_slip.fill(0.0);
            self.view = None;
            self.located = None;
            self.load = Some(load);
            self.state = Some(target);
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
        let q_old_sum = sum(&self.traction);
        let mut passes = 0;
        let mut shift;
        let (mut restarts, mut forced) = (0, None);
        let pressure_unchanged = self.pressure == self.pressure_start;
        if pressure_unchanged && d_sigma == 0.0 {
            let d_shear = load.shear() - self.load.map_or(0.0, |p| p.shear());
            restick_reversed(&mut self.cells, d_shear);
        }
        let centre = {
            // In cell widths from the grid's left edge, where the cell indices count from.
            let e = target.ends();
            (0.5 * (e.left + e.right) - (self.x[0] - 0.5 * self.width)) / self.width
        };
        let mut ends = StickEnds::new(pressure_unchanged, centre);
        // The single stick run the last pass solved on (`solve_after_cut`).
        let mut run = None;
        loop {
            passes += 1;
            if passes > self.options.max_passes() {
                return Err(Error::ActiveSet {
                    step,
                    iterations: self.options.max_passes(),
                });
            }
            if !self.cells.contains(&Cell::Stick) {
                // All contact cells were flagged to slip while |Q| < fP: restart from full stick.
                // Flagged again, the stick zone is narrower than a cell (as at the onset of
                // sliding): the cell that exceeded its limit least sticks alone for the rest of
                // the sub-step and carries what the slipping cells leave of Q, which must be
                // within its own limit (checked below).
                restarts += 1;
                if restarts == 1 {
                    for c in self.cells.iter_mut().filter(|c| matches!(c, Cell::Slip(_))) {
                        *c = Cell::Stick;
                    }
                } else {
                    let excess = |i: usize| self.flag_traction[i].abs() - f * self.pressure[i];
                    let nearest = (0..n)
                        .filter(|&i| self.pressure[i] > 0.0)
                        .min_by(|&i, &j| excess(i).total_cmp(&excess(j)));
                    let Some(i) = nearest else {
                        return Err(Error::ActiveSet {
                            step,
                            iterations: passes,
                        });
                    };
                    self.cells[i] = Cell::Stick;
                    forced = Some(i);
                }
            }
            let changed = self.known_increments(passes == 1);
            for i in 0..n {
                self.rhs[i] = if self.cells[i] == Cell::Stick {
                    -self.g_known[i] - 0.25 * PI * d_sigma * self.x[i]
                } else {
                    0.0
                };
            }
            let target = load.shear() / self.width - q_old_sum - sum(&self.known);
            // After the first pass, a run that only lost cells at its ends is cut, not solved.
            let current = self.single_run();
            run = match (run, current, changed) {
                (Some(from), Some(to), Some(changed)) => self.solve_after_cut(from, to, &changed),
                _ => None,
            };
            if run.is_none() {
                self.solve_stick(&Rhs::Vector, step)?;
                run = current;
            }
            self.solve_stick(&Rhs::Ones, step)?;
            let (su, sv) = (sum(&self.u), sum(&self.v));
            let c = (su - target) / sv;
            shift = c;
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
                        if q.abs() > f * self.pressure[i] + traction_tolerance && forced != Some(i)
                        {
                            self.flag_traction[i] = q;
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
            if passes == 1 {
                self.trial_slip.copy_from_slice(&self.sub_slip);
            }
            if !changed {
                break;
            }
            // Flag at once the cells the stick run's ends are heading past (`predict.rs`).
            for (cells, sign) in ends.record(&self.cells) {
                for i in cells {
                    self.flag_traction[i] = self.traction[i] + self.dq[i];
                    self.cells[i] = Cell::Slip(sign);
                }
            }
        }
        if let Some(i) = forced {
            // Q beyond what the cells' pressure carries at the limit, `f sum(p) w`: the sampled
            // pressure of a coarse grid sums to less than P, so Q just below f P can exceed it.
            if (self.traction[i] + self.dq[i]).abs() > f * self.pressure[i] + traction_tolerance {
                return Err(Error::InvalidInput {
                    field: format!("history row {step}.shear"),
                    value: load.shear().abs(),
                    valid: "a shear load the grid's cells carry at the friction limit (f times their pressure, which falls short of f P on a coarse grid): use more cells (solver.cells)",
                });
            }
        }
        // Slip is `s = du - c_disp c` with du the surfaces' relative displacement (datum l):
        // the bodies' rigid relative displacement moves by `-c_disp c`.
        self.displacement -= c_disp * shift;
        self.shift = shift;
        let energy = self.dissipation(ends_start, target.ends(), d_sigma, step)?;
        let unchanged = self.normal_unchanged(&load);
        if last && self.locates() && unchanged {
            passes += self.view(load, &target, d_sigma, step)?;
        } else {
            self.unlocated(unchanged);
        }
        self.commit(load, target);
        Ok((energy, passes))
    }

    /// The contact ends reached, `[0, 0]` unloaded.
    fn ends(&self) -> PerEdge<f64> {
        self.state.map_or(PerEdge::default(), |s| s.ends())
    }

    /// Ends the sub-step at `load` (contact `target`): the traction increments and the settled
    /// slips added, the traction of cells out of contact zero.
    fn commit(&mut self, load: LoadPoint, target: NormalContact) {
        for i in 0..self.x.len() {
            self.traction[i] += self.dq[i];
            if self.cells[i] == Cell::Out {
                self.traction[i] = 0.0;
            }
            let s = self.sub_slip[i];
            self.slip[i] += s;
            self.slip_increment[i] += s;
            self.slip_travel[i] += s.abs();
        }
        self.load = Some(load);
        self.state = Some(target);
    }
}
