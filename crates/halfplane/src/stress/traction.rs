//! The surface tractions whose stresses [`crate::stress`] evaluates: pressure and shear, each
//! linear between nodes (continuous or with jumps), zero outside the loaded span.
//!
//! Held in node form: a piecewise-linear function that vanishes outside its span is a sum of a
//! step `J_k H(x - s_k)` and a ramp `S_k (x - s_k) H(x - s_k)` at each node `s_k`, `J_k` the jump
//! of the value and `S_k` the jump of the slope there. That form is what the closed forms of
//! `strip.rs` sum; it is built once here from whichever description the caller has.

use super::edge::SqrtEdge;
use crate::error::{lazily_named, physical, Error, Result};
use crate::labels::{Edge, PerEdge};
use crate::march::Fields;

/// Pressure `p` (compressive positive) and shear traction `q` (positive in `+x`, the traction
/// the other body exerts: [`crate::march`]'s sign) on the surface, each piecewise linear between
/// nodes and zero outside the span, valid by construction (finite, nodes strictly increasing).
#[derive(Debug, Clone, PartialEq)]
pub struct Traction {
    pub(super) nodes: Vec<f64>,
    /// `[J_p, J_q]` per node: jump of the value, right minus left.
    pub(super) jump: Vec<[f64; 2]>,
    /// `[S_p, S_q]` per node: jump of the slope, right minus left.
    pub(super) kink: Vec<[f64; 2]>,
    /// Square-root corrections (`edge.rs`): the intervals next to contact edges, and the
    /// intervals on the stick side of each located stick-slip boundary.
    pub(super) edges: Vec<SqrtEdge>,
}

/// Intervals on a located stick-slip boundary's stick side over which its square root is exact
/// ([`Traction::from_march_ends`]): 1600 cells, Mindlin's unloading, surface `sxx` within 5
/// cells of the boundaries off by at most 2.2e-3, 1.5e-3, 7.5e-4, 6.5e-4, 5.7e-4 p0 over 1, 2,
/// 3, 4, 8 intervals (`tests/sub_cell.rs`).
const ROOT_NODES: usize = 4;

/// Most nodes a traction may have (memory of a march with [`crate::march::MarchOptions::MAX_CELLS`]).
pub const MAX_NODES: usize = 1_000_002;

impl Traction {
    /// No traction at all: only the bulk tension stresses the body.
    pub fn unloaded() -> Self {
        Self {
            nodes: Vec::new(),
            jump: Vec::new(),
            kink: Vec::new(),
            edges: Vec::new(),
        }
    }

    /// Continuous piecewise-linear `p` and `q` through their values at the nodes `x` (strictly
    /// increasing, at least two), zero outside `[x_0, x_last]`: nonzero end values are jumps
    /// there. Errors name the array and the index.
    pub fn piecewise_linear(x: &[f64], pressure: &[f64], shear: &[f64]) -> Result<Self> {
        check_nodes("traction x", x, 2)?;
        check_values("traction pressure", pressure, x.len(), NODE)?;
        check_values("traction shear", shear, x.len(), NODE)?;
        let n = x.len();
        let slope = |v: &[f64], e: usize| (v[e + 1] - v[e]) / (x[e + 1] - x[e]);
        let mut jump = vec![[0.0; 2]; n];
        let mut kink = vec![[0.0; 2]; n];
        for (c, v) in [pressure, shear].into_iter().enumerate() {
            jump[0][c] = v[0];
            jump[n - 1][c] = -v[n - 1];
            for (k, kink) in kink.iter_mut().enumerate() {
                let right = if k + 1 < n { slope(v, k) } else { 0.0 };
                let left = if k > 0 { slope(v, k - 1) } else { 0.0 };
                kink[c] = right - left;
            }
        }
        if let Some(k) = kink
            .iter()
            .position(|s| !(s[0].is_finite() && s[1].is_finite()))
        {
            return Err(Error::InvalidInput {
                field: format!("traction x[{k}]"),
                value: x[k],
                valid: "nodes far enough apart that the tractions' slopes are finite",
            });
        }
        Ok(Self {
            nodes: x.to_vec(),
            jump,
            kink,
            edges: Vec::new(),
        })
    }

    /// Piecewise-constant `p` and `q`, one value per cell between consecutive `edges` (strictly
    /// increasing, at least two): the classical strip elements. Their surface `sxx` is
    /// logarithmically infinite at every edge where the shear traction jumps.
    pub fn piecewise_constant(edges: &[f64], pressure: &[f64], shear: &[f64]) -> Result<Self> {
        check_nodes("traction edges", edges, 2)?;
        let cells = edges.len() - 1;
        check_values("traction pressure", pressure, cells, CELL)?;
        check_values("traction shear", shear, cells, CELL)?;
        let value = |v: &[f64], i: usize| if i < cells { v[i] } else { 0.0 };
        let jump = (0..edges.len())
            .map(|k| {
                let left = |v: &[f64]| if k > 0 { value(v, k - 1) } else { 0.0 };
                [
                    value(pressure, k) - left(pressure),
                    value(shear, k) - left(shear),
                ]
            })
            .collect();
        Ok(Self {
            nodes: edges.to_vec(),
            jump,
            kink: vec![[0.0; 2]; edges.len()],
            edges: Vec::new(),
        })
    }

    /// The tractions of an incomplete contact: `x[0]` and `x[last]` are the contact edges, where
    /// `p` and `q` must be zero; linear between the inner nodes, and in the first and last
    /// intervals proportional to the square root of the distance to the edge, as the pressure of
    /// every smooth contact and the traction `f p` of a slip zone are (`docs/stress.md`, "Edges").
    /// At least three nodes.
    pub fn contact(x: &[f64], pressure: &[f64], shear: &[f64]) -> Result<Self> {
        let mut t = Self::piecewise_linear(x, pressure, shear)?;
        let n = x.len();
        if n < 3 {
            return Err(Error::InvalidCount {
                field: "traction x (number of nodes, edges included)".into(),
                value: n as u64,
                min: 3,
                max: MAX_NODES as u64,
            });
        }
        for (name, v) in [("traction pressure", pressure), ("traction shear", shear)] {
            for k in [0, n - 1] {
                if v[k] != 0.0 {
                    return Err(Error::InvalidInput {
                        field: format!("{name}[{k}]"),
                        value: v[k],
                        valid: "0 at a contact edge",
                    });
                }
            }
        }
        t.edges = vec![
            SqrtEdge {
                edge: x[0],
                length: x[1] - x[0],
                value: [pressure[1], shear[1]],
            },
            SqrtEdge {
                edge: x[n - 1],
                length: x[n - 2] - x[n - 1],
                value: [pressure[n - 2], shear[n - 2]],
            },
        ];
        Ok(t)
    }

    /// The state of a march increment as a surface-accurate traction: nodes at the contact edges
    /// `-a` and `a`, where both tractions vanish, and at every cell centre strictly inside, with the
    /// cell's exact pressure and its shear traction; linear in between and square-root shaped
    /// next to the edges ([`Traction::contact`]). Piecewise-constant cells would put a logarithmic
    /// singularity of the surface `sxx` at every cell edge (`docs/stress.md`). `half_width` 0
    /// (unloaded), or a contact without a cell centre inside, gives no traction.
    pub fn from_march(half_width: f64, fields: &Fields) -> Result<Self> {
        let a = half_width;
        if !(a.is_finite() && a >= 0.0) {
            return Err(Error::InvalidInput {
                field: "contact half-width".into(),
                value: a,
                valid: "a finite number >= 0",
            });
        }
        Self::from_march_ends(PerEdge { left: -a, right: a }, fields)
    }

    /// [`Traction::from_march`] for a contact `[b1, b2]` anywhere (under a moment, or on an
    /// asymmetric profile): nodes at `b1` and `b2` and at every cell centre strictly between.
    /// `b1 = b2` (unloaded), or a contact without a cell centre inside, gives no traction.
    ///
    /// A stick-slip boundary that the march located inside its cell (the fields' `kinks`, with
    /// [`MarchOptions::with_sub_cell_boundaries`](crate::march::MarchOptions::with_sub_cell_boundaries))
    /// is a node of its own, with the pressure and shear there, and the four (`ROOT_NODES`) intervals
    /// from it towards its stick side (fewer before a contact edge's interval or another kink)
    /// carry the square root `amplitude sqrt(|x - x_b|)` exactly: the nodes inside take off the
    /// root's departure from its chord over those intervals, so that the linear interpolant
    /// holds only the smooth rest, and one correction of the contact edges' shape
    /// (`docs/stress.md`) spans them. Interpolated linearly between the centres around it, the
    /// kink put an error of `O(K sqrt(w))` (1.8e-2 p0 at 1600 cells) into the surface stress
    /// there; with the root over its first interval only, 2e-3 p0 one cell inside.
    pub fn from_march_ends(ends: PerEdge<f64>, fields: &Fields) -> Result<Self> {
        let PerEdge { left, right } = ends;
        physical("contact end b1", left)?;
        physical("contact end b2", right)?;
        if right < left {
            return Err(Error::InvalidInput {
                field: "contact end b2".into(),
                value: right,
                valid: "a contact end at or beyond b1",
            });
        }
        if right == left {
            return Ok(Self::unloaded());
        }
        let mut x = vec![left];
        let mut p = vec![0.0];
        let mut q = vec![0.0];
        for i in 0..fields.x.len() {
            if fields.x[i] > left && fields.x[i] < right {
                x.push(fields.x[i]);
                p.push(fields.pressure[i]);
                q.push(fields.traction[i]);
            }
        }
        if x.len() == 1 {
            return Ok(Self::unloaded());
        }
        x.push(right);
        p.push(0.0);
        q.push(0.0);
        // The kinks strictly inside, each with the spacing of its cells' centres (a node within a
        // millionth of that of another one replaces it).
        let spacing = fields.x.get(1).map_or(right - left, |x1| x1 - fields.x[0]);
        let mut kinks: Vec<(f64, Edge, f64)> = Vec::new();
        for (k, kink) in fields.kinks.iter().enumerate() {
            for (name, v) in [
                ("x", kink.x),
                ("amplitude", kink.amplitude),
                ("shear", kink.shear),
                ("pressure", kink.pressure),
            ] {
                physical(&format!("kink {k} {name}"), v)?;
            }
            if !(kink.x > left && kink.x < right) {
                continue;
            }
            let at = x.partition_point(|&v| v < kink.x);
            if (x[at] - kink.x).abs() <= 1e-6 * spacing {
                (p[at], q[at]) = (kink.pressure, kink.shear);
            } else if (kink.x - x[at - 1]).abs() <= 1e-6 * spacing {
                (p[at - 1], q[at - 1]) = (kink.pressure, kink.shear);
            } else {
                x.insert(at, kink.x);
                p.insert(at, kink.pressure);
                q.insert(at, kink.shear);
            }
            kinks.push((kink.x, kink.root, kink.amplitude));
        }
        // Each kink's root spans ROOT_NODES intervals on its stick side (fewer before a contact
        // edge's interval or another kink): the nodes inside take the root's departure from its
        // chord, so that the linear interpolant carries only the smooth rest of the traction.
        let kink_nodes: Vec<usize> = kinks
            .iter()
            .map(|&(at, ..)| x.partition_point(|&v| v < at - 1e-6 * spacing))
            .collect();
        let mut roots = Vec::with_capacity(kinks.len());
        for (&(at, root, amplitude), &k) in kinks.iter().zip(&kink_nodes) {
            let last = x.len() - 1;
            let towards = |i: usize| match root {
                Edge::Left => i.checked_sub(1).filter(|&j| j >= 1),
                Edge::Right => Some(i + 1).filter(|&j| j < last),
            };
            let mut end = k;
            for _ in 0..ROOT_NODES {
                match towards(end) {
                    Some(j) if !kink_nodes.contains(&j) => end = j,
                    _ => break,
                }
            }
            if end == k {
                // No node on the stick side short of a contact edge's interval: the root spans
                // the one interval there.
                end = match root {
                    Edge::Left => k.saturating_sub(1),
                    Edge::Right => (k + 1).min(last),
                };
            }
            let length = x[end] - at;
            if length == 0.0 {
                continue;
            }
            let (lo, hi) = (k.min(end) + 1, k.max(end));
            for i in lo..hi {
                let d = (x[i] - at).abs();
                q[i] += amplitude * (d / length.abs().sqrt() - d.sqrt());
            }
            roots.push(SqrtEdge {
                edge: at,
                length,
                value: [0.0, amplitude * length.abs().sqrt()],
            });
        }
        let mut t = Self::contact(&x, &p, &q)?;
        t.edges.extend(roots);
        Ok(t)
    }

    /// The nodes (sorted).
    pub fn nodes(&self) -> &[f64] {
        &self.nodes
    }

    /// `[p, q]` at `x`, the right-hand limit at a jump (for checks and figures).
    pub fn at(&self, x: f64) -> [f64; 2] {
        let mut v = [0.0; 2];
        for k in 0..self.nodes.len() {
            let d = x - self.nodes[k];
            if d < 0.0 {
                break;
            }
            for (c, v) in v.iter_mut().enumerate() {
                *v += self.jump[k][c] + self.kink[k][c] * d;
            }
        }
        for e in &self.edges {
            let [p, q] = e.at(x);
            v[0] += p;
            v[1] += q;
        }
        v
    }
}

fn check_nodes(field: &str, x: &[f64], min: usize) -> Result<()> {
    if x.len() < min || x.len() > MAX_NODES {
        return Err(Error::InvalidCount {
            field: format!("{field} (number of nodes)"),
            value: x.len() as u64,
            min: min as u64,
            max: MAX_NODES as u64,
        });
    }
    for (i, v) in x.iter().enumerate() {
        lazily_named(physical, *v, || format!("{field}[{i}]"))?;
        if i > 0 && *v <= x[i - 1] {
            return Err(Error::InvalidInput {
                field: format!("{field}[{i}]"),
                value: *v,
                valid: "a node after the previous one (strictly increasing)",
            });
        }
    }
    Ok(())
}

/// What a traction's values go with, for [`Error::LengthMismatch`]: nodes, or cells.
const NODE: &str = "one value per node";
/// See [`NODE`].
const CELL: &str = "one value per cell between two edges";

fn check_values(field: &str, v: &[f64], len: usize, per: &'static str) -> Result<()> {
    if v.len() != len {
        return Err(Error::LengthMismatch {
            field: field.into(),
            length: v.len(),
            expected: len,
            per,
        });
    }
    for (i, v) in v.iter().enumerate() {
        lazily_named(physical, *v, || format!("{field}[{i}]"))?;
    }
    Ok(())
}
