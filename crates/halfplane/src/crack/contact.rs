//! Crack faces in contact (Hills et al. 1996; Dai, Hills and Nowell on fretting cracks):
//! where the open solution would make the faces overlap they close; a closed point carries a
//! compressive normal traction and a friction traction `|tau| <= f |s_nn|`, sticks (its slip
//! keeps the value of the previous increment) or slips (`|tau| = f |s_nn|`, opposing the slip
//! increment). The state of each collocation point is found by an active set, increment by
//! increment, in the order of the cycle; the cycle is repeated until the states and slips at its
//! end repeat (the faces' own shakedown), and the last pass is reported.
//!
//! Conventions of `solve.rs`: opening `delta_2 >= 0`; the friction traction on the `+e2` face
//! opposes its slip `Delta delta_1` relative to the `-e2` face, i.e. `s12 = f |s22| sign(Delta
//! delta_1)`.

use super::solve::{CrackSolver, Lu, TipFactors};
use crate::error::{Error, Result};

/// The state of a collocation point.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum FaceState {
    /// Faces apart, free of traction.
    Open,
    /// Faces in contact, not slipping.
    Stick,
    /// Faces in contact, slipping; `+1` or `-1` the sign of the slip increment `Delta delta_1`.
    Slip(i8),
}

impl FaceState {
    fn closed(self) -> bool {
        self != FaceState::Open
    }
}

/// The solution at one increment.
#[derive(Debug, Clone, PartialEq)]
pub struct IncrementSolution {
    /// The tip factors: `k1 = 0` when the point nearest the tip is closed, never negative.
    pub factors: TipFactors,
    /// Per collocation point (tip first): its state.
    pub states: Vec<FaceState>,
    /// The opening `delta_2` (length; zero on closed points to the solution's accuracy).
    pub opening: Vec<f64>,
    /// The slip `delta_1` (length).
    pub slip: Vec<f64>,
    /// The total normal traction `s_nn` (zero on open points).
    pub normal: Vec<f64>,
    /// The total shear traction `tau` (zero on open points).
    pub shear: Vec<f64>,
}

/// Most passes over the cycle, and most active-set iterations per increment.
const MAX_PASSES: usize = 6;
const MAX_ITERATIONS: usize = 200;
/// The largest violation accepted, relative to the largest load, when the active set cycles.
const TOGGLE_TOLERANCE: f64 = 1e-3;

impl CrackSolver {
    /// Solves the crack with face contact through a cycle of increments: `loads[m]` holds the
    /// uncracked `(normal, shear)` stresses at the collocation points at increment `m`
    /// ([`Self::resolve`]), `friction` the faces' coefficient `f >= 0`. Returns one solution per
    /// increment of the last pass.
    pub fn cycle(
        &self,
        loads: &[(Vec<f64>, Vec<f64>)],
        friction: f64,
    ) -> Result<Vec<IncrementSolution>> {
        if !(friction.is_finite() && (0.0..=1e6).contains(&friction)) {
            return Err(Error::InvalidInput {
                field: "crack.face_friction".into(),
                value: friction,
                valid: "a friction coefficient from 0 to 1e6",
            });
        }
        let mut scale: f64 = 0.0;
        for (normal, shear) in loads {
            self.check_loads(normal, shear)?;
            for v in normal.iter().chain(shear) {
                scale = scale.max(v.abs());
            }
        }
        let scale = if scale > 0.0 { scale } else { 1.0 };
        let n = self.n;
        let mut states = vec![FaceState::Open; n];
        let mut slip = vec![0.0; n];
        let mut previous_end: Option<(Vec<FaceState>, Vec<f64>)> = None;
        let mut out = Vec::with_capacity(loads.len());
        for _ in 0..MAX_PASSES {
            out.clear();
            for (m, (normal, shear)) in loads.iter().enumerate() {
                let (psi, new_states) = self
                    .increment(normal, shear, friction, &states, &slip, scale)
                    .ok_or(Error::ActiveSet {
                        step: m + 1,
                        iterations: MAX_ITERATIONS,
                    })?;
                states = new_states;
                slip = self.displacement(&psi, 0);
                out.push(self.report(&psi, &states, normal, shear));
            }
            let tol = 1e-9 * scale * self.crack.length;
            if let Some((s, d)) = &previous_end {
                let same = *s == states && d.iter().zip(&slip).all(|(a, b)| (a - b).abs() <= tol);
                if same {
                    break;
                }
            }
            if friction == 0.0 {
                break; // no memory: every increment stands alone
            }
            previous_end = Some((states.clone(), slip.clone()));
        }
        Ok(out)
    }

    /// `A delta_j` at the collocation points from `psi` (`j = 0` slip, `1` opening).
    fn displacement(&self, psi: &[f64], j: usize) -> Vec<f64> {
        let n = self.n;
        self.tail
            .iter()
            .map(|row| (0..n).map(|i| row[i] * psi[j * n + i]).sum())
            .collect()
    }

    /// The total `(s22, s12)` at the collocation points.
    fn tractions(&self, psi: &[f64], normal: &[f64], shear: &[f64]) -> (Vec<f64>, Vec<f64>) {
        let n2 = 2 * self.n;
        let row = |r: usize| -> f64 { (0..n2).map(|c| self.influence[r * n2 + c] * psi[c]).sum() };
        let s22 = (0..self.n).map(|k| normal[k] + row(k)).collect();
        let s12 = (0..self.n).map(|k| -shear[k] + row(self.n + k)).collect();
        (s22, s12)
    }

    /// One increment's active set, from the states and slips (`A delta_1`) of the previous one.
    fn increment(
        &self,
        normal: &[f64],
        shear: &[f64],
        f: f64,
        before: &[FaceState],
        slip_before: &[f64],
        scale: f64,
    ) -> Option<(Vec<f64>, Vec<FaceState>)> {
        let n = self.n;
        let n2 = 2 * n;
        let mut states = before.to_vec();
        if f == 0.0 {
            for s in &mut states {
                if s.closed() {
                    *s = FaceState::Slip(1);
                }
            }
        }
        // The slip a stuck point holds: the previous increment's (a point closing within the
        // increment is taken to close at its start, an error of the order of the increment).
        let held = slip_before;
        let gap_tol = 1e-9 * scale * self.crack.length;
        let traction_tol = 1e-9 * scale;
        let mut seen: Vec<Vec<FaceState>> = vec![states.clone()];
        let mut one_at_a_time = false;
        let mut repeats = 0;
        let mut best: Option<(f64, Vec<f64>, Vec<FaceState>)> = None;
        for _ in 0..MAX_ITERATIONS {
            let (a, mut psi) = self.system(normal, shear, f, &states, held);
            if states.iter().all(|s| !s.closed()) {
                self.open.solve(&mut psi); // the open crack's factorisation, made once
            } else {
                Lu::factor(a, n2)?.solve(&mut psi);
            }
            let gap = self.displacement(&psi, 1);
            let now = self.displacement(&psi, 0);
            let (s22, s12) = self.tractions(&psi, normal, shear);
            // Proposed changes with the size of their violation (stress units); changes of
            // contact come before changes of stick and slip, and once a set of states repeats
            // only the largest violation is corrected per pass, which ends the cycling.
            let l = self.crack.length;
            let mut proposals: Vec<(usize, FaceState, f64, bool)> = Vec::new();
            for k in 0..n {
                match states[k] {
                    FaceState::Open if gap[k] < -gap_tol => {
                        let closed = if f > 0.0 {
                            FaceState::Stick
                        } else {
                            FaceState::Slip(1)
                        };
                        proposals.push((k, closed, -gap[k] / l, true));
                    }
                    FaceState::Open => {}
                    _ if s22[k] > traction_tol => {
                        proposals.push((k, FaceState::Open, s22[k], true));
                    }
                    FaceState::Stick if s12[k].abs() > f * (-s22[k]) + traction_tol => {
                        let sg = if s12[k] > 0.0 { 1 } else { -1 };
                        let excess = s12[k].abs() - f * (-s22[k]);
                        proposals.push((k, FaceState::Slip(sg), excess, false));
                    }
                    FaceState::Slip(sg)
                        if f > 0.0 && f64::from(sg) * (now[k] - held[k]) < -gap_tol =>
                    {
                        let back = -f64::from(sg) * (now[k] - held[k]) / l;
                        proposals.push((k, FaceState::Stick, back, false));
                    }
                    _ => {}
                }
            }
            if proposals.is_empty() {
                return Some((psi, states));
            }
            let violation = proposals.iter().map(|p| p.2).fold(0.0, f64::max);
            if best.as_ref().is_none_or(|b| violation < b.0) {
                best = Some((violation, psi.clone(), states.clone()));
            }
            if !one_at_a_time && proposals.iter().any(|p| p.3) {
                proposals.retain(|p| p.3);
            }
            if one_at_a_time {
                let worst = proposals
                    .iter()
                    .copied()
                    .max_by(|a, b| a.2.total_cmp(&b.2))?;
                proposals = vec![worst];
            }
            for (k, next, _, _) in proposals {
                states[k] = next;
            }
            if seen.contains(&states) {
                if one_at_a_time {
                    repeats += 1;
                }
                one_at_a_time = true;
                if repeats >= 2 {
                    // A point toggling between two states that each violate a condition
                    // slightly (the discrete contact has no exact solution there): keep the
                    // state of the smallest violation if it is small.
                    let (v, psi, states) = best?;
                    return (v <= TOGGLE_TOLERANCE * scale).then_some((psi, states));
                }
            } else {
                seen.push(states.clone());
            }
        }
        None
    }

    /// The system of one active set: open points keep their traction equations; a closed
    /// point's normal row sets its opening to zero, its shear row holds its slip (stick) or
    /// makes the shear traction `f |s22|` with the slip's sign (slip).
    fn system(
        &self,
        normal: &[f64],
        shear: &[f64],
        f: f64,
        states: &[FaceState],
        held: &[f64],
    ) -> (Vec<f64>, Vec<f64>) {
        let n = self.n;
        let n2 = 2 * n;
        let mut a = self.influence.clone();
        let mut rhs: Vec<f64> = normal.iter().map(|v| -v).collect();
        rhs.extend_from_slice(shear);
        for k in 0..n {
            match states[k] {
                FaceState::Open => {}
                closed => {
                    let (lower, upper) = a.split_at_mut((n + k) * n2);
                    let normal_row = &mut lower[k * n2..(k + 1) * n2];
                    let shear_row = &mut upper[..n2];
                    if let FaceState::Slip(sg) = closed {
                        let c = f64::from(sg) * f;
                        for (s, v) in shear_row.iter_mut().zip(normal_row.iter()) {
                            *s += c * v;
                        }
                        rhs[n + k] = shear[k] - c * normal[k];
                    } else {
                        shear_row.fill(0.0);
                        shear_row[..n].copy_from_slice(&self.tail[k]);
                        rhs[n + k] = held[k];
                    }
                    normal_row.fill(0.0);
                    normal_row[n..].copy_from_slice(&self.tail[k]);
                    rhs[k] = 0.0;
                }
            }
        }
        (a, rhs)
    }

    fn report(
        &self,
        psi: &[f64],
        states: &[FaceState],
        normal: &[f64],
        shear: &[f64],
    ) -> IncrementSolution {
        let mut factors = self.tip(psi);
        if states[0].closed() || factors.k1 < 0.0 {
            factors.k1 = 0.0;
        }
        let (s22, s12) = self.tractions(psi, normal, shear);
        let on = |v: Vec<f64>| -> Vec<f64> {
            v.into_iter()
                .zip(states)
                .map(|(v, s)| if s.closed() { v } else { 0.0 })
                .collect()
        };
        IncrementSolution {
            factors,
            states: states.to_vec(),
            opening: self
                .displacement(psi, 1)
                .iter()
                .map(|d| d / self.a)
                .collect(),
            slip: self
                .displacement(psi, 0)
                .iter()
                .map(|d| d / self.a)
                .collect(),
            normal: on(s22),
            shear: on(s12.into_iter().map(|v| -v).collect()),
        }
    }
}
