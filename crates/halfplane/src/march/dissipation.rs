//! The frictional energy dissipated in one sub-step (`docs/convergence.md`, "Energy per cycle").
//!
//! A sub-step runs between two loads on a straight path (parameter t from 0 to 1) with no contact
//! edge crossing a cell centre inside it. Its end state is exact whatever the path inside: with
//! the stick set fixed, tractions and slips are linear functions of the load and of the slipping
//! cells' tractions `q = f p sign(s)` at the end. The dissipation `sum f p |ds|` is not: it
//! depends on when, inside the sub-step, each cell slips, and on the pressure there. Three
//! things decide that (measured in `docs/convergence.md`): without the curvature term the energy
//! is first order in the step; without the onsets or the start-set rates its error is tens of
//! times larger until the step is much shorter than the interval between edge crossings.
//!
//! - **Onsets.** A cell stuck at the start and slipping at the end starts to slip at an
//!   interior time, where its stick traction reaches `f p`. The stick traction is taken linear
//!   from its start value to the active-set trial that flagged the cell, the limit as
//!   `f sqrt(u) psi` with `u = (x - b1)(b2 - x)` and `psi` linear in t, and the crossing is found by
//!   bisection. A cell entering contact at the start of the sub-step is such a cell (stuck,
//!   with zero traction and zero pressure). It dissipates only after its onset.
//! - **Start-set rates.** A cell already slipping slides at the start-set rate (the first
//!   active-set pass: stick set of the start) until the onsets occur, and the remainder of its
//!   slip after them; the remainder is placed after the mean onset time, weighted by how far
//!   each onset cell's trial traction exceeds its limit.
//! - **Curvature.** A slipping cell's traction `f p(t)` is not linear in t: near a contact edge
//!   `p` grows like the square root of the time since the edge crossed the cell. Because slips
//!   respond linearly (through the stick cells) to the slipping tractions, that curvature moves
//!   slip in time everywhere. With `r_j(t)` the departure of cell j's traction from the straight
//!   line over its slipping interval and `Gamma` the (symmetric) response of slips to tractions
//!   at fixed stick set, the energy changes by `-sum_i c_i (Gamma R)_i`, `R_j = integral r_j dt`,
//!   `c_i` the rate of cell i's traction while it slips: its change divided by the length of its
//!   slipping interval `1 - tau_i`, which weights an onset cell's own curvature (concentrated
//!   after its onset) exactly. Other cells' curvature is spread over the whole sub-step, for which
//!   the change alone would be the right weight, and a cell leaving contact nearly unloaded has
//!   its onset just before the end, so the divisor is kept at least 1/16: the weight stays
//!   bounded, and the studies' errors moved by at most 3% against an unbounded divisor (1/2 cost
//!   up to 25% at 5 steps per half; no divisor left an error floor of 5e-8 at 800 cells).
//!   `Gamma R` costs one more stick solve per sub-step in which cells slip, unless the stick
//!   set is one run: then the last pass's solution gives it (`curvature_by_columns`).
//!
//! The curvature term is the energy `integral q ds` with `s = s_lin + Gamma r` integrated by
//! parts (`r` vanishes at the ends of the slipping interval); the term quadratic in `r` drops
//! out by the symmetry of `Gamma` (`integral r^T Gamma r' dt = [r^T Gamma r]/2 = 0`).
//!
//! Sign convention as in `marcher.rs`: tractions positive in +x (the direction of positive Q),
//! slip positive in the sense positive Q drives, so a slipping cell's work `q ds` is `f p |ds|`.
//!
//! Owns the energy quadrature only. Never changes the active set or the state fields.

use super::marcher::{Cell, Marcher};
use super::solve::{add_column, apply, sum, Rhs};
use crate::error::Result;
use crate::labels::PerEdge;
use std::f64::consts::PI;

impl Marcher {
    /// Energy dissipated in the sub-step just solved, from the contact ends `ends0` to `ends1`
    /// (`[-a0, a0]` to `[-a1, a1]` without a moment), before the
    /// state is updated: `traction` still holds the start tractions, `dq` the increments,
    /// `sub_slip` the slips, `trial_slip` the first pass's slips and `flag_traction` the trial
    /// traction with which each onset cell was flagged. The rules are the module's (derived in
    /// `docs/convergence.md`, "Energy per cycle"); the result is never negative (the exact
    /// value is not, and clamping a rounding-size negative sum was never needed in the studies).
    pub(super) fn dissipation(
        &mut self,
        ends0: PerEdge<f64>,
        ends1: PerEdge<f64>,
        d_sigma: f64,
        step: usize,
    ) -> Result<f64> {
        let n = self.x.len();
        let f = self.friction;
        // Onset times and their weighted mean.
        let (mut weight, mut weighted) = (0.0, 0.0);
        for i in 0..n {
            self.onset[i] = 0.0;
            if self.sub_slip[i] == 0.0 || self.start_cells[i] != Cell::Stick {
                continue;
            }
            let e = self.edge_factors(i, ends0, ends1);
            let (q0, q_flag) = (self.traction[i], self.flag_traction[i]);
            let tau = onset_time(q0, q_flag, f, &e);
            self.onset[i] = tau;
            let excess = (q_flag.abs() - f * self.pressure[i]).max(0.0);
            weight += excess;
            weighted += excess * tau;
        }
        let mean_onset = if weight > 0.0 { weighted / weight } else { 0.0 };
        // Onsets and start-set rates, and the curvature integrals R (into `known`) and rates c;
        // where c differs from the last pass's known increments, `differ` keeps the difference
        // (for `G c`, see `curvature_correction`).
        let mut energy = 0.0;
        let mut slipping = false;
        let mut differ: Vec<(usize, f64)> = Vec::new();
        for i in 0..n {
            let known = std::mem::take(&mut self.known[i]);
            self.change[i] = 0.0;
            let s = self.sub_slip[i];
            if s == 0.0 {
                if known != 0.0 {
                    differ.push((i, -known));
                }
                continue;
            }
            slipping = true;
            let sign = match self.cells[i] {
                Cell::Slip(sign) => sign,
                _ => s.signum(),
            };
            let e = self.edge_factors(i, ends0, ends1);
            let tau = self.onset[i];
            let p_mean = e.mean(tau);
            let pressure_slip = sign
                * if self.start_cells[i] == Cell::Stick {
                    p_mean * s
                } else {
                    // Before the onsets at the start-set rate, the rest after their mean time.
                    let early = if weight > 0.0 { self.trial_slip[i] } else { s };
                    early * p_mean + (s - early) * e.mean(mean_onset)
                };
            energy += f * pressure_slip;
            self.pressure_slip[i] += pressure_slip;
            let (p_tau, p1) = (e.at(tau), self.pressure[i]);
            self.known[i] = (1.0 - tau) * sign * f * (p_mean - 0.5 * (p_tau + p1));
            let q_tau = if tau > 0.0 {
                sign * f * p_tau
            } else {
                self.traction[i]
            };
            self.change[i] = (self.traction[i] + self.dq[i] - q_tau) / (1.0 - tau).max(1.0 / 16.0);
            if self.change[i] != known {
                differ.push((i, self.change[i] - known));
            }
        }
        if slipping {
            energy += self.curvature_correction(&differ, d_sigma, step)?;
        }
        Ok(energy.max(0.0) * self.width)
    }

    /// `-sum_i c_i (Gamma R)_i` (the curvature term, per unit cell width): the slip response to
    /// traction increments R on the slipping cells, with the stick cells held (zero slip) and
    /// the resultant unchanged, contracted with the traction rates c. Solved exactly like an
    /// active-set pass (same stick set, so the all-ones solve is reused).
    ///
    /// The contraction `c . G dq'` is taken as `(G c) . dq'` (G is symmetric), with `G c` the
    /// last pass's `G known` plus the kernel columns of the few cells where c and known differ
    /// (onset cells): one FFT product fewer per sub-step. `differ` lists those differences.
    /// When the stick set is one run, the solve is replaced by the last pass's solution
    /// ([`Self::curvature_by_columns`]).
    fn curvature_correction(
        &mut self,
        differ: &[(usize, f64)],
        d_sigma: f64,
        step: usize,
    ) -> Result<f64> {
        const MAX_COLUMNS: usize = 64;
        if differ.len() <= MAX_COLUMNS {
            for &(k, d) in differ {
                add_column(&mut self.g_known, self.kernel.row(), k, d);
            }
        } else {
            apply(
                &mut self.kernel,
                &self.dense,
                &self.change,
                &mut self.g_known,
            );
        }
        let n = self.x.len();
        apply(&mut self.kernel, &self.dense, &self.known, &mut self.work);
        #[cfg(test)]
        tests::CURVATURE.with(|c| c.set(c.get() + 1));
        #[cfg(test)]
        let by_columns = !tests::SOLVED_ONLY.with(|s| s.get());
        #[cfg(not(test))]
        let by_columns = true;
        if by_columns && differ.len() <= MAX_COLUMNS {
            if let Some(energy) = self.curvature_by_columns(differ, d_sigma) {
                #[cfg(test)]
                tests::BY_COLUMNS.with(|c| c.set(c.get() + 1));
                return Ok(energy);
            }
        }
        for i in 0..n {
            self.rhs[i] = if self.cells[i] == Cell::Stick {
                -self.work[i]
            } else {
                0.0
            };
        }
        self.solve_stick(&Rhs::Vector, step)?;
        self.solve_stick(&Rhs::Ones, step)?;
        let sv = sum(&self.v);
        if sv == 0.0 {
            return Ok(0.0);
        }
        // Zero resultant change: sum(R) + sum(u - c v) = 0.
        let target = -sum(&self.known);
        let c = (sum(&self.u) - target) / sv;
        for i in 0..n {
            self.rhs[i] = self.known[i]
                + if self.cells[i] == Cell::Stick {
                    self.u[i] - c * self.v[i]
                } else {
                    0.0
                };
        }
        let c_disp = self.compliance / PI;
        Ok((0..n)
            .map(|i| c_disp * (self.g_known[i] * self.rhs[i] + c * self.change[i]))
            .sum())
    }

    /// The curvature term of [`Self::curvature_correction`] without its stick solve, when the
    /// stick set is one run S and each cell where c and known differ (outside S: an onset cell
    /// the passes flagged at the run's ends) lies within a few cells of it; `None` otherwise.
    ///
    /// With `u_R = -T_S^{-1} (G R)_S` and G symmetric, `(G c)_S . u_R = -w . (G R)_S` for
    /// `w = T_S^{-1} (G c)_S`, and `sum(u_R) = -v . (G R)_S` (`v = T_S^{-1} 1`). w needs no solve:
    /// the last pass solved `T_S u = b` with `b = -(G known)_S - (pi/4) dsigma x_S`, so
    /// `T_S^{-1} (G known)_S = -u - (pi/4) dsigma (x_s v + width T_S^{-1} r)` (r the ramp
    /// `0, 1, ..`, bordered like v: `Toeplitz::solve_ramp`; not needed when dsigma = 0), and
    /// each differing cell k adds `d_k T_S^{-1} (G e_k)_S`, which is `e_k` on any run holding k
    /// cut back to S: their sum is one vector on the run spanning them all, cut once
    /// (`Toeplitz::cut`, O(n) per cell cut). Equal to the solved route up to rounding.
    fn curvature_by_columns(&mut self, differ: &[(usize, f64)], d_sigma: f64) -> Option<f64> {
        const NEAR: usize = 16;
        let (s, e) = self.single_run()?;
        let near = |k: usize| (k >= e && k - e < NEAR) || (k < s && s - k <= NEAR);
        if !differ.iter().all(|&(k, _)| near(k)) {
            return None;
        }
        let sv = sum(&self.v);
        if sv == 0.0 {
            return Some(0.0);
        }
        let a = 0.25 * PI * d_sigma;
        let mut w: Vec<f64> = (s..e)
            .map(|i| -self.u[i] - a * self.x[s] * self.v[i])
            .collect();
        if a != 0.0 {
            let mut ramp = vec![0.0; e - s];
            self.kernel.solve_ramp(&mut ramp);
            w.iter_mut()
                .zip(&ramp)
                .for_each(|(wi, r)| *wi -= a * self.width * r);
        }
        if !differ.is_empty() {
            let lower = differ.iter().map(|&(k, _)| k).fold(s, usize::min);
            let upper = differ.iter().map(|&(k, _)| k + 1).fold(e, usize::max);
            let mut columns = vec![0.0; upper - lower];
            for &(k, d) in differ {
                columns[k - lower] = d;
            }
            self.kernel.cut((lower, upper), (s, e), &mut columns);
            w.iter_mut().zip(&columns).for_each(|(wi, ci)| *wi += ci);
        }
        let dot = |a: &[f64], b: &[f64]| -> f64 { a.iter().zip(b).map(|(x, y)| x * y).sum() };
        let g_r = &self.work[s..e];
        // Zero resultant change, as in the solved route: sum(R) + sum(u_R - c v) = 0.
        let c = (sum(&self.known) - dot(&self.v[s..e], g_r)) / sv;
        let c_disp = self.compliance / PI;
        Some(
            c_disp
                * (dot(&self.g_known, &self.known) - dot(&w, g_r) - c * sum(&w)
                    + c * sum(&self.change)),
        )
    }

    fn edge_factors(&self, i: usize, ends0: PerEdge<f64>, ends1: PerEdge<f64>) -> EdgeFactors {
        let x = self.x[i];
        let u = |e: PerEdge<f64>| ((x - e.left) * (e.right - x)).max(0.0);
        let (u0, u1) = (u(ends0), u(ends1));
        let (p0, p1) = (self.pressure_start[i], self.pressure[i]);
        let psi0 = if u0 > 0.0 {
            p0 / u0.sqrt()
        } else if u1 > 0.0 {
            p1 / u1.sqrt()
        } else {
            0.0
        };
        let psi1 = if u1 > 0.0 { p1 / u1.sqrt() } else { psi0 };
        EdgeFactors { u0, u1, psi0, psi1 }
    }
}

/// A cell's pressure over a sub-step in the form `p = sqrt(u) psi`, `u = (x - b1)(b2 - x)`
/// (`a^2 - x^2` for a centred contact), `psi` smooth, with `u` and `psi` linear in the
/// sub-step's parameter t.
///
/// Every profile's pressure has this form (the normal problem's pressure formula, as in
/// Johnson, *Contact Mechanics*, section 5.7: the factor `sqrt(a^2 - x^2)` multiplies a regular
/// integral); for Hertz `psi` is constant and `u` exactly linear (`a^2` is linear in P). At an
/// end where `u = 0` (the cell enters or leaves contact there) `psi` is taken from the other end.
struct EdgeFactors {
    u0: f64,
    u1: f64,
    psi0: f64,
    psi1: f64,
}

impl EdgeFactors {
    fn u(&self, t: f64) -> f64 {
        self.u0 + (self.u1 - self.u0) * t
    }

    fn psi(&self, t: f64) -> f64 {
        self.psi0 + (self.psi1 - self.psi0) * t
    }

    /// The pressure at t.
    fn at(&self, t: f64) -> f64 {
        self.psi(t) * self.u(t).sqrt()
    }

    /// The mean pressure over `[tau, 1]` by product integration (Atkinson, *An Introduction to
    /// Numerical Analysis*, 2nd ed., section 5.6): `sqrt(u)` exactly,
    /// `mean sqrt(u) = (2/3)(u0 + sqrt(u0 u1) + u1)/(sqrt(u0) + sqrt(u1))`, and `psi` by the
    /// trapezoidal rule. The trapezoidal rule on `p` itself has an error `O(dt^1.5)` per step
    /// near an edge, where `sqrt(u)` is not smooth in time.
    fn mean(&self, tau: f64) -> f64 {
        let (u0, u1) = (self.u(tau), self.u1);
        let (r0, r1) = (u0.sqrt(), u1.sqrt());
        if r0 + r1 == 0.0 {
            return 0.0;
        }
        (2.0 / 3.0) * (u0 + r0 * r1 + u1) / (r0 + r1) * 0.5 * (self.psi(tau) + self.psi1)
    }
}

/// The time in `[0, 1]` at which a stick traction moving linearly from `q0` to `q1` first
/// reaches the friction limit `f p(t)`; 0 when it starts at the limit. Bisection on
/// `q(t)^2 - f^2 p(t)^2` (52 halvings: the parameter to rounding), which is positive at t = 1
/// for a flagged cell. A cell entering contact at t = 0 starts at zero traction and zero
/// pressure, so at the limit in both senses; its onset is the later crossing.
fn onset_time(q0: f64, q1: f64, f: f64, e: &EdgeFactors) -> f64 {
    let excess = |t: f64| {
        let q = q0 + (q1 - q0) * t;
        let psi = e.psi(t);
        q * q - f * f * psi * psi * e.u(t)
    };
    let entering = e.u0 == 0.0;
    if (excess(0.0) >= 0.0 && !entering) || excess(1.0) <= 0.0 {
        return 0.0;
    }
    let (mut lo, mut hi) = (0.0, 1.0);
    for _ in 0..52 {
        let mid = 0.5 * (lo + hi);
        if excess(mid) > 0.0 {
            hi = mid;
        } else {
            lo = mid;
        }
    }
    0.5 * (lo + hi)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::history::{History, Ramp};
    use crate::march::{march, MarchOptions};
    use crate::reference;
    use std::cell::Cell as Flag;

    thread_local! {
        /// Set: the curvature term always takes its stick solve.
        pub(super) static SOLVED_ONLY: Flag<bool> = const { Flag::new(false) };
        /// Sub-steps with a curvature term, and those whose term took
        /// [`Marcher::curvature_by_columns`].
        pub(super) static CURVATURE: Flag<usize> = const { Flag::new(0) };
        pub(super) static BY_COLUMNS: Flag<usize> = const { Flag::new(0) };
    }

    #[test]
    fn the_curvature_term_without_its_solve_is_the_solved_one() {
        // The reference cycle (examples/march-cycle.toml: P, Q and the bulk stress all change)
        // at 400 cells, every sub-step's curvature term by its stick solve and, where the stick
        // set is one run, from the last pass's solution. The two are the same algebra in a
        // different order: each increment's energy within 1e-10 of the cycle's largest (a few
        // hundred roundings of terms up to that size), and the route used in most sub-steps.
        let (p1, p2) = (reference::point1(), reference::point2());
        let history = History::in_phase(p1, p2, 3, 45, Ramp::NormalFirst, 15).unwrap();
        let options = MarchOptions::default().with_cells(400).unwrap();
        let energies = |solved_only: bool| {
            SOLVED_ONLY.with(|s| s.set(solved_only));
            BY_COLUMNS.with(|c| c.set(0));
            CURVATURE.with(|c| c.set(0));
            let r = march(&reference::hertz(), &history, &options, |_, _| {}).unwrap();
            let used = (BY_COLUMNS.with(|c| c.get()), CURVATURE.with(|c| c.get()));
            let e: Vec<f64> = r.steps.iter().map(|s| s.energy_increment).collect();
            (e, used)
        };
        let (solved, (none, _)) = energies(true);
        let (by_columns, (used, terms)) = energies(false);
        SOLVED_ONLY.with(|s| s.set(false));
        assert_eq!(none, 0, "the solved route took no shortcut");
        // Measured: 378 of 465 (the others have stick cells apart from the main run).
        assert!(
            4 * used >= 3 * terms,
            "the column route used in {used} of {terms} sub-steps only"
        );
        let largest = solved.iter().fold(0.0f64, |m, e| m.max(e.abs()));
        assert!(largest > 0.0, "the cycle dissipates");
        for (k, (a, b)) in solved.iter().zip(&by_columns).enumerate() {
            assert!(
                (a - b).abs() <= 1e-10 * largest,
                "increment {k}: energy {b:e} without the curvature solve, {a:e} with it"
            );
        }
    }

    #[test]
    fn mean_pressure_is_exact_for_a_square_root_and_onsets_are_where_the_limit_is_reached() {
        // p = sqrt(t) (u = t, psi = 1): mean over [0, 1] is 2/3, over [1/4, 1] it is
        // (2/3)(1 - 1/8)/(3/4) = 7/9 (exact integrals).
        let e = EdgeFactors {
            u0: 0.0,
            u1: 1.0,
            psi0: 1.0,
            psi1: 1.0,
        };
        assert!((e.mean(0.0) - 2.0 / 3.0).abs() < 1e-15);
        assert!((e.mean(0.25) - 7.0 / 9.0).abs() < 1e-15);
        // Stick traction q = 2t against the limit f sqrt(t) with f = 0.5: 2t = 0.5 sqrt(t) at
        // t = 1/16.
        assert!((onset_time(0.0, 2.0, 0.5, &e) - 1.0 / 16.0).abs() < 1e-15);
        // Already at the limit at the start: no interior onset.
        let inside = EdgeFactors {
            u0: 1.0,
            u1: 1.0,
            psi0: 1.0,
            psi1: 1.0,
        };
        assert_eq!(onset_time(0.5, 1.0, 0.5, &inside), 0.0);
    }
}
