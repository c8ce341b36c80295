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
        // The open crack's displacements and tip factors of every increment (no contact).
        let free: Vec<Free> = loads
            .iter()
            .map(|(normal, shear)| {
                let t = self.free_tractions(normal, shear);
                Free {
                    displacement: self.displacements(&t),
                    factors: self.tip(&t),
                }
            })
            .collect();
        let n = self.n;
        let mut states = vec![FaceState::Open; n];
        let mut slip = vec![0.0; n];
        let mut previous_end: Option<(Vec<FaceState>, Vec<f64>)> = None;
        let mut out = Vec::with_capacity(loads.len());
        for _ in 0..MAX_PASSES {
            out.clear();
            for (m, free) in free.iter().enumerate() {
                let solution = self
                    .increment(free, friction, &states, &slip, scale)
                    .ok_or(Error::ActiveSet {
                        step: m + 1,
                        iterations: MAX_ITERATIONS,
                    })?;
                states.clone_from(&solution.states);
                slip.copy_from_slice(&solution.displacement[..n]);
                out.push(self.report(free, &solution));
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

    /// `W t`: `A delta_1` (slip) at the collocation points, then `A delta_2` (opening).
    fn displacements(&self, t: &[f64]) -> Vec<f64> {
        let n2 = 2 * self.n;
        self.compliance
            .chunks_exact(n2)
            .map(|row| row.iter().zip(t).map(|(a, b)| a * b).sum())
            .collect()
    }

    /// One increment's active set, from the states and slips (`A delta_1`) of the previous one.
    fn increment(
        &self,
        free: &Free,
        f: f64,
        before: &[FaceState],
        slip_before: &[f64],
        scale: f64,
    ) -> Option<Contact> {
        let n = self.n;
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
        let mut best: Option<(f64, Contact)> = None;
        for _ in 0..MAX_ITERATIONS {
            let c = self.contact_tractions(free, f, &states, held)?;
            let d = &c.displacement;
            let (now, gap) = d.split_at(n);
            let (s22, s12) = c.traction.split_at(n);
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
                return Some(c);
            }
            let violation = proposals.iter().map(|p| p.2).fold(0.0, f64::max);
            if best.as_ref().is_none_or(|b| violation < b.0) {
                best = Some((violation, c));
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
                    let (v, c) = best?;
                    return (v <= TOGGLE_TOLERANCE * scale).then_some(c);
                }
            } else {
                seen.push(states.clone());
            }
        }
        None
    }

    /// The face tractions of one active set and the displacements they leave. Unknowns: at a
    /// closed point its normal traction `s22`, and its shear traction `s12` if it sticks (a
    /// slipping point carries `s12 = -sg f s22`). Equations: a closed point's opening is zero;
    /// a stuck point's slip keeps `held`. Open points carry nothing. `None` if the reduced
    /// system is singular.
    fn contact_tractions(
        &self,
        free: &Free,
        f: f64,
        states: &[FaceState],
        held: &[f64],
    ) -> Option<Contact> {
        let n = self.n;
        let n2 = 2 * n;
        let w = |r: usize, c: usize| self.compliance[r * n2 + c];
        // Unknown j: (point k, true for s22 / false for s12 of a stuck point).
        let mut unknowns: Vec<(usize, bool)> = Vec::new();
        for (k, s) in states.iter().enumerate() {
            match s {
                FaceState::Open => {}
                FaceState::Slip(_) => unknowns.push((k, true)),
                FaceState::Stick => {
                    unknowns.push((k, true));
                    unknowns.push((k, false));
                }
            }
        }
        // The displacement row `r` per unknown: a traction `s22` at k carries `s12 = -sg f s22`
        // with it if k slips.
        let column = |r: usize, (k, normal): (usize, bool)| -> f64 {
            if !normal {
                return w(r, n + k);
            }
            match states[k] {
                FaceState::Slip(sg) => w(r, k) - f64::from(sg) * f * w(r, n + k),
                _ => w(r, k),
            }
        };
        let size = unknowns.len();
        let mut traction = vec![0.0; n2];
        let mut displacement = free.displacement.clone();
        if size > 0 {
            let mut matrix = vec![0.0; size * size];
            let mut rhs = vec![0.0; size];
            for (i, &(k, normal)) in unknowns.iter().enumerate() {
                // Opening row for s22 unknowns, slip row for s12 unknowns.
                let (r, target) = if normal { (n + k, 0.0) } else { (k, held[k]) };
                for (j, &u) in unknowns.iter().enumerate() {
                    matrix[i * size + j] = column(r, u);
                }
                rhs[i] = target - free.displacement[r];
            }
            Lu::factor(matrix, size)?.solve(&mut rhs);
            for (&(k, normal), &v) in unknowns.iter().zip(&rhs) {
                if normal {
                    traction[k] = v;
                    if let FaceState::Slip(sg) = states[k] {
                        traction[n + k] = -f64::from(sg) * f * v;
                    }
                } else {
                    traction[n + k] = v;
                }
            }
            for (r, d) in displacement.iter_mut().enumerate() {
                let row = &self.compliance[r * n2..(r + 1) * n2];
                *d += (0..n)
                    .filter(|&k| states[k].closed())
                    .map(|k| row[k] * traction[k] + row[n + k] * traction[n + k])
                    .sum::<f64>();
            }
        }
        if !displacement.iter().chain(&traction).all(|v| v.is_finite()) {
            return None;
        }
        Some(Contact {
            states: states.to_vec(),
            traction,
            displacement,
        })
    }

    fn report(&self, free: &Free, c: &Contact) -> IncrementSolution {
        let n = self.n;
        let mut factors = free.factors;
        let extra = self.tip(&c.traction);
        factors.k1 += extra.k1;
        factors.k2 += extra.k2;
        if c.states[0].closed() || factors.k1 < 0.0 {
            factors.k1 = 0.0;
        }
        IncrementSolution {
            factors,
            states: c.states.clone(),
            opening: c.displacement[n..].iter().map(|d| d / self.a).collect(),
            slip: c.displacement[..n].iter().map(|d| d / self.a).collect(),
            normal: c.traction[..n].to_vec(),
            shear: c.traction[n..].iter().map(|v| -v).collect(),
        }
    }
}

/// One increment of the open crack (tractions `t`): its displacements `W t` and tip factors.
struct Free {
    displacement: Vec<f64>,
    factors: TipFactors,
}

/// One active set solved: the states, the face tractions (`s22` at every collocation point,
/// then `s12`; zero on open points) and the displacements (`A delta_1`, then `A delta_2`).
#[derive(Debug, Clone)]
struct Contact {
    states: Vec<FaceState>,
    traction: Vec<f64>,
    displacement: Vec<f64>,
}
