//! The stresses at the same points under many tractions whose nodes are shared: the increments of
//! a march, whose nodes are the same cell centres at every increment (only the contact edges
//! move). Used where a few hundred points are evaluated at every increment of a cycle (the crack
//! line of [`crate::crack`]), where neither the fast method's set-up nor the direct route's
//! logarithms need repeating.
//!
//! The sum is the closed form of `strip.rs` (Johnson, *Contact Mechanics*, eqs. 2.15 and 2.19,
//! integrated exactly over piecewise-linear elements), reordered: at a point `(x, z)` a node `s`
//! contributes `S (w log w)` to the Cauchy sum `F` and `S log w` to `F'`, `w = x - s + i z`, for
//! a traction continuous there (`J = 0`, the kink `S` its change of slope). The logarithms
//! depend on the point and the node only, so they are taken once per point and node and reused
//! by every traction; the kinks of all tractions at one node are held together, so the work per
//! point is a set of vector updates. Nodes where a traction jumps, the square-root edge
//! corrections, surface points and points that take the far field go through the ordinary
//! per-traction route, so the result is [`super::field_direct`]'s sum to rounding for every point.

use super::edge::SqrtEdge;
use super::far::{is_far, FarField};
use super::strip::{add_node, stresses, Sums};
use super::traction::Traction;
use super::{check_request, point, stress_from, StressField};
use crate::error::Result;
use crate::material::Material;

/// The stresses at the points `(x[i], z[i])` under each of `loads` (a traction and its bulk
/// tension), one [`StressField`] per load, in order: what [`super::field_direct`] gives for each
/// load, to rounding. Errors are those of [`super::field`] (the first invalid point or bulk
/// tension, a surface point on a node where a traction jumps).
pub fn fields(
    loads: &[(&Traction, f64)],
    material: &Material,
    x: &[f64],
    z: &[f64],
) -> Result<Vec<StressField>> {
    for &(_, bulk) in loads {
        check_request(bulk, x, z)?;
    }
    if loads.is_empty() {
        check_request(0.0, x, z)?;
    }
    let nu = material.poisson_ratio();
    let shared = Shared::new(loads);
    let m = loads.len();
    let mut out: Vec<StressField> = (0..m)
        .map(|_| StressField {
            sxx: Vec::with_capacity(x.len()),
            szz: Vec::with_capacity(x.len()),
            syy: Vec::with_capacity(x.len()),
            sxz: Vec::with_capacity(x.len()),
        })
        .collect();
    let mut far: Vec<Option<FarField>> = (0..m).map(|_| None).collect();
    let mut sums = vec![Sums::default(); m];
    let mut acc = Accumulators::new(m);
    for (i, (&x, &z)) in x.iter().zip(z).enumerate() {
        let z = if z == 0.0 { 0.0 } else { z };
        let direct = z < DEEP_ENOUGH || loads.iter().any(|(t, _)| is_far(t, x, z));
        if direct {
            for (k, &(t, bulk)) in loads.iter().enumerate() {
                super::push(&mut out[k], point(t, &mut far[k], bulk, nu, i, x, z)?);
            }
            continue;
        }
        shared.sums(x, z, &mut acc, &mut sums);
        for (k, s) in sums.iter().enumerate() {
            let [sxx, szz, sxz] = stresses(s, z);
            super::push(&mut out[k], stress_from(sxx, szz, sxz, loads[k].1, nu));
        }
    }
    Ok(out)
}

/// Points shallower than this take the per-traction route: the surface's own limits (and
/// `u^2 + z^2` underflowing next to a node) are handled there.
const DEEP_ENOUGH: f64 = 1e-150;

/// Every load's traction in the shared form.
struct Shared<'a> {
    /// The union of the tractions' nodes, sorted.
    nodes: Vec<f64>,
    /// Kinks `S_p`, `S_q` node by node, each a run of one value per load.
    kink_p: Vec<f64>,
    kink_q: Vec<f64>,
    /// Nodes with a jump: `(load, node, jump, kink)`, summed by the closed form as they are.
    jumps: Vec<(usize, f64, [f64; 2], [f64; 2])>,
    /// The distinct square-root edge intervals, and per load `(interval, value)`.
    edges: Vec<SqrtEdge>,
    edge_values: Vec<Vec<(usize, [f64; 2])>>,
    loads: &'a [(&'a Traction, f64)],
}

impl<'a> Shared<'a> {
    fn new(loads: &'a [(&'a Traction, f64)]) -> Self {
        let m = loads.len();
        let mut nodes: Vec<f64> = loads
            .iter()
            .flat_map(|(t, _)| t.nodes.iter().copied())
            .collect();
        nodes.sort_by(f64::total_cmp);
        nodes.dedup();
        let mut kink_p = vec![0.0; nodes.len() * m];
        let mut kink_q = vec![0.0; nodes.len() * m];
        let mut jumps = Vec::new();
        let mut edges: Vec<SqrtEdge> = Vec::new();
        let mut edge_values = Vec::with_capacity(m);
        for (k, (t, _)) in loads.iter().enumerate() {
            for (j, &s) in t.nodes.iter().enumerate() {
                if t.jump[j] != [0.0; 2] {
                    jumps.push((k, s, t.jump[j], t.kink[j]));
                    continue;
                }
                let u = nodes.partition_point(|&v| v < s);
                kink_p[u * m + k] = t.kink[j][0];
                kink_q[u * m + k] = t.kink[j][1];
            }
            let mut values = Vec::with_capacity(t.edges.len());
            for e in &t.edges {
                let same = |g: &SqrtEdge| g.edge == e.edge && g.length == e.length;
                let g = match edges.iter().position(same) {
                    Some(g) => g,
                    None => {
                        edges.push(*e);
                        edges.len() - 1
                    }
                };
                values.push((g, e.value));
            }
            edge_values.push(values);
        }
        Self {
            nodes,
            kink_p,
            kink_q,
            jumps,
            edges,
            edge_values,
            loads,
        }
    }

    /// The Cauchy sums of every load at `(x, z)`, `z > 0`, into `sums`.
    fn sums(&self, x: f64, z: f64, acc: &mut Accumulators, sums: &mut [Sums]) {
        let m = self.loads.len();
        acc.clear();
        for (u, &s) in self.nodes.iter().enumerate() {
            let d = x - s;
            let r2 = d * d + z * z;
            let (lr, li) = (0.5 * r2.ln(), z.atan2(d));
            // S w log w = S [(d lr - z li) + i (d li + z lr)].
            let (a, b) = (d * lr - z * li, d * li + z * lr);
            let kp = &self.kink_p[u * m..(u + 1) * m];
            let kq = &self.kink_q[u * m..(u + 1) * m];
            acc.add(kp, kq, [a, b, lr, li]);
        }
        for (k, s) in sums.iter_mut().enumerate() {
            *s = Sums {
                fp: [acc.fp_re[k], acc.fp_im[k]],
                fq: [acc.fq_re[k], acc.fq_im[k]],
                dp: [acc.dp_re[k], acc.dp_im[k]],
                dq: [acc.dq_re[k], acc.dq_im[k]],
            };
        }
        for &(k, s, jump, kink) in &self.jumps {
            // Off the surface a node's terms are always finite.
            add_node(&mut sums[k], s, jump, kink, x, z);
        }
        let cauchy: Vec<([f64; 2], [f64; 2])> = self.edges.iter().map(|e| e.cauchy(x, z)).collect();
        for (k, values) in self.edge_values.iter().enumerate() {
            let s = &mut sums[k];
            for &(g, [vp, vq]) in values {
                let (f, d) = cauchy[g];
                for c in 0..2 {
                    s.fp[c] += vp * f[c];
                    s.fq[c] += vq * f[c];
                    s.dp[c] += vp * d[c];
                    s.dq[c] += vq * d[c];
                }
            }
        }
    }
}

/// The eight parts of the Cauchy sums, one value per load in each.
struct Accumulators {
    fp_re: Vec<f64>,
    fp_im: Vec<f64>,
    fq_re: Vec<f64>,
    fq_im: Vec<f64>,
    dp_re: Vec<f64>,
    dp_im: Vec<f64>,
    dq_re: Vec<f64>,
    dq_im: Vec<f64>,
}

impl Accumulators {
    fn new(m: usize) -> Self {
        Self {
            fp_re: vec![0.0; m],
            fp_im: vec![0.0; m],
            fq_re: vec![0.0; m],
            fq_im: vec![0.0; m],
            dp_re: vec![0.0; m],
            dp_im: vec![0.0; m],
            dq_re: vec![0.0; m],
            dq_im: vec![0.0; m],
        }
    }

    fn clear(&mut self) {
        for v in [
            &mut self.fp_re,
            &mut self.fp_im,
            &mut self.fq_re,
            &mut self.fq_im,
            &mut self.dp_re,
            &mut self.dp_im,
            &mut self.dq_re,
            &mut self.dq_im,
        ] {
            v.fill(0.0);
        }
    }

    /// Adds one node's terms for every load: kinks `kp`, `kq` times `[a, b, lr, li]` (module
    /// doc). One loop over equal-length slices (no bounds checks), so that it is a vector update.
    #[inline]
    fn add(&mut self, kp: &[f64], kq: &[f64], [a, b, lr, li]: [f64; 4]) {
        let m = kp.len();
        let (kq, fr, fi) = (&kq[..m], &mut self.fp_re[..m], &mut self.fp_im[..m]);
        let (qr, qi) = (&mut self.fq_re[..m], &mut self.fq_im[..m]);
        let (dr, di) = (&mut self.dp_re[..m], &mut self.dp_im[..m]);
        let (er, ei) = (&mut self.dq_re[..m], &mut self.dq_im[..m]);
        for k in 0..m {
            let (p, q) = (kp[k], kq[k]);
            fr[k] += p * a;
            fi[k] += p * b;
            qr[k] += q * a;
            qi[k] += q * b;
            dr[k] += p * lr;
            di[k] += p * li;
            er[k] += q * lr;
            ei[k] += q * li;
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::material::Material;

    /// Two tractions on shared nodes with different edges, one with jumps.
    fn tractions() -> Vec<Traction> {
        let cells: Vec<f64> = (0..41).map(|i| -1.0 + 0.05 * i as f64).collect();
        let make = |a: f64, scale: f64| {
            let mut x = vec![-a];
            let mut p = vec![0.0];
            let mut q = vec![0.0];
            for &c in cells.iter().filter(|c| c.abs() < a) {
                x.push(c);
                p.push(scale * (1.0 - c * c / (a * a)).sqrt());
                q.push(0.3 * scale * c * (1.0 - c * c / (a * a)).sqrt());
            }
            x.push(a);
            p.push(0.0);
            q.push(0.0);
            Traction::contact(&x, &p, &q).unwrap()
        };
        let stepped = Traction::piecewise_constant(
            &[-0.5, -0.1, 0.2, 0.6],
            &[1.0, 2.0, 0.5],
            &[0.1, -0.2, 0.3],
        )
        .unwrap();
        vec![make(0.93, 1.0), make(0.81, 1.3), stepped]
    }

    #[test]
    fn agrees_with_the_direct_route_point_by_point() {
        // Points near the edges, deep, on the surface (per-traction route) and far (far field):
        // every value equals field_direct's to rounding (1e-12 of the largest).
        let t = tractions();
        let loads: Vec<(&Traction, f64)> = t.iter().zip([10.0, -5.0, 0.0]).collect();
        let m = Material::new(200_000.0, 0.3).unwrap();
        let x = [-0.93, -0.9, -0.805, 0.0, 0.33, 0.95, 2.0, 40.0, 0.1];
        let z = [1e-3, 0.02, 1e-6, 0.5, 0.0, 0.01, 1.0, 3.0, 1e-9];
        let all = fields(&loads, &m, &x, &z).unwrap();
        for (k, (t, bulk)) in loads.iter().enumerate() {
            let d = super::super::field_direct(t, *bulk, &m, &x, &z).unwrap();
            for (a, b) in [
                (&all[k].sxx, &d.sxx),
                (&all[k].szz, &d.szz),
                (&all[k].syy, &d.syy),
                (&all[k].sxz, &d.sxz),
            ] {
                for (i, (a, b)) in a.iter().zip(b).enumerate() {
                    assert!((a - b).abs() < 1e-12 * (1.0 + b.abs()), "{k} {i}: {a} {b}");
                }
            }
        }
    }

    #[test]
    fn errors_as_the_single_route() {
        let t = tractions();
        let loads: Vec<(&Traction, f64)> = t.iter().map(|t| (t, 0.0)).collect();
        let m = Material::new(200_000.0, 0.3).unwrap();
        // A surface point on a jump of the stepped traction, and a point in the other body.
        assert!(fields(&loads, &m, &[-0.1], &[0.0]).is_err());
        assert!(fields(&loads, &m, &[0.0], &[-1.0]).is_err());
        assert!(fields(&[(&t[0], f64::NAN)], &m, &[0.0], &[1.0]).is_err());
    }
}
