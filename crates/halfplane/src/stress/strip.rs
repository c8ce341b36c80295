//! The closed form of the stresses under piecewise-linear surface tractions (`docs/stress.md`,
//! "Closed form"): exact integration of the Flamant line loads over every element, summed node by
//! node.
//!
//! With `w = zeta - xi`, `zeta = x + i z`, the Flamant fields of a compressive line load `p` and a
//! tangential line load `q` at `xi` combine into
//! `sxx + szz = (2/pi) Im(p/w) - (2/pi) Re(q/w)` and
//! `szz - sxx + 2i sxz = (2/pi)[z p/w^2 + q/w - i z q/w^2]`
//! (Johnson, *Contact Mechanics*, eqs. 2.15 and 2.19, in complex form). Integrating over a
//! traction given in node form (steps `J_k` and ramps `S_k`, `traction.rs`) needs only the
//! Cauchy integral `F(zeta) = integral rho(xi)/(zeta - xi) dxi`, which is exactly
//! `F = sum_k (J_k + S_k w_k) log w_k + sum_k J_k`, `w_k = zeta - s_k`, with `F' = sum_k (S_k log w_k
//! + J_k/w_k)` and `integral rho/(zeta - xi)^2 = -F'`. The principal logarithm is continuous in the
//! closed upper half-plane, which is the body `z >= 0`, so the sum is exact on the surface too,
//! where a continuous traction leaves only the finite `(x - s_k) ln|x - s_k|` at each node.

use super::edge::SqrtEdge;
use super::traction::Traction;
use std::f64::consts::FRAC_2_PI;

/// The four Cauchy sums at one point: `F_p`, `F_q` (real and imaginary parts) and their
/// derivatives (zero on the surface, where only `z F'` enters and vanishes).
#[derive(Debug, Clone, Copy, Default)]
pub(super) struct Sums {
    pub fp: [f64; 2],
    pub fq: [f64; 2],
    pub dp: [f64; 2],
    pub dq: [f64; 2],
}

/// Adds the terms of one node `s_k` with jumps `[J_p, J_q]` and ramps `[S_p, S_q]` at `(x, z)`:
/// `(J + S w) log w + J` to `F` and `S log w + J/w` to `F'` (off the surface), `w = zeta - s_k`.
/// `false` at a surface point on a node where a traction jumps (the stress is infinite there).
#[inline(always)]
pub(super) fn add_node(
    s: &mut Sums,
    node: f64,
    jump: [f64; 2],
    kink: [f64; 2],
    x: f64,
    z: f64,
) -> bool {
    let [jp, jq] = jump;
    let [sp, sq] = kink;
    let u = x - node;
    s.fp[0] += jp;
    s.fq[0] += jq;
    let surface = z == 0.0;
    if surface && u == 0.0 {
        // (J + S w) log w -> 0 as w -> 0 when J = 0.
        return jp == 0.0 && jq == 0.0;
    }
    let r2 = u * u + z * z;
    if r2 < f64::MIN_POSITIVE {
        // A point within 1e-154 of the node: r^2 underflows, so take ln r and 1/w from r.
        return add_near_node(s, jump, kink, u, z);
    }
    let (lr, li) = (0.5 * r2.ln(), z.atan2(u));
    // (J + S w) log w, w = u + i z.
    let (cr, ci) = (jp + sp * u, sp * z);
    s.fp[0] += cr * lr - ci * li;
    s.fp[1] += cr * li + ci * lr;
    let (cr, ci) = (jq + sq * u, sq * z);
    s.fq[0] += cr * lr - ci * li;
    s.fq[1] += cr * li + ci * lr;
    if !surface {
        // S log w + J / w, 1/w = (u - i z)/r2.
        let (ir, ii) = (u / r2, -z / r2);
        s.dp[0] += sp * lr + jp * ir;
        s.dp[1] += sp * li + jp * ii;
        s.dq[0] += sq * lr + jq * ir;
        s.dq[1] += sq * li + jq * ii;
    }
    true
}

/// [`add_node`]'s terms (after the constant `J`) at `w = u + i z` so close to the node that
/// `u^2 + z^2` underflows: `ln r` and `1/w = (u/r - i z/r)/r` from `r = hypot(u, z)`.
#[cold]
fn add_near_node(s: &mut Sums, jump: [f64; 2], kink: [f64; 2], u: f64, z: f64) -> bool {
    let [jp, jq] = jump;
    let [sp, sq] = kink;
    let r = u.hypot(z);
    let (lr, li) = (r.ln(), z.atan2(u));
    let (cr, ci) = (jp + sp * u, sp * z);
    s.fp[0] += cr * lr - ci * li;
    s.fp[1] += cr * li + ci * lr;
    let (cr, ci) = (jq + sq * u, sq * z);
    s.fq[0] += cr * lr - ci * li;
    s.fq[1] += cr * li + ci * lr;
    if z != 0.0 {
        // 1/w overflows at r < 1e-308; where J = 0 (a continuous traction) its term is exactly
        // 0, not 0 * inf = NaN (z = 5e-324 under an edge node, found by `stress_points`).
        let (ir, ii) = ((u / r) / r, (-z / r) / r);
        let over = |j: f64, v: f64| if j == 0.0 { 0.0 } else { j * v };
        s.dp[0] += sp * lr + over(jp, ir);
        s.dp[1] += sp * li + over(jp, ii);
        s.dq[0] += sq * lr + over(jq, ir);
        s.dq[1] += sq * li + over(jq, ii);
    }
    true
}

/// Adds the square-root edge correction `e` at `(x, z)`.
pub(super) fn add_edge(s: &mut Sums, e: &SqrtEdge, x: f64, z: f64) {
    let (f, d) = e.cauchy(x, z);
    let [vp, vq] = e.value;
    for c in 0..2 {
        s.fp[c] += vp * f[c];
        s.fq[c] += vq * f[c];
        if z != 0.0 {
            s.dp[c] += vp * d[c];
            s.dq[c] += vq * d[c];
        }
    }
}

/// `Some(sums)` at `(x, z)`, `z >= 0`; `None` at a surface point on a node where a traction
/// jumps (the surface stress is infinite there).
fn sums(t: &Traction, x: f64, z: f64) -> Option<Sums> {
    let mut s = Sums::default();
    for k in 0..t.nodes.len() {
        if !add_node(&mut s, t.nodes[k], t.jump[k], t.kink[k], x, z) {
            return None;
        }
    }
    for e in &t.edges {
        add_edge(&mut s, e, x, z);
    }
    Some(s)
}

/// `[sxx, szz, sxz]` from the traction alone at `(x, z)`, `z >= 0`; `None` on the surface at a
/// node where a traction jumps. Sign convention of [`crate::stress`].
pub(super) fn in_plane(t: &Traction, x: f64, z: f64) -> Option<[f64; 3]> {
    Some(stresses(&sums(t, x, z)?, z))
}

/// `[sxx, szz, sxz]` at depth `z` from the Cauchy sums there (Johnson eqs. 2.15 and 2.19 in
/// complex form, module documentation). Sign convention of [`crate::stress`].
pub(super) fn stresses(s: &Sums, z: f64) -> [f64; 3] {
    // sxx + szz = (2/pi)(Im F_p - Re F_q);
    // szz - sxx + 2i sxz = (2/pi)(F_q - z F_p' + i z F_q').
    let first = FRAC_2_PI * (s.fp[1] - s.fq[0]);
    let second_re = FRAC_2_PI * (s.fq[0] - z * s.dp[0] - z * s.dq[1]);
    let second_im = FRAC_2_PI * (s.fq[1] - z * s.dp[1] + z * s.dq[0]);
    [
        0.5 * (first - second_re),
        0.5 * (first + second_re),
        0.5 * second_im,
    ]
}
