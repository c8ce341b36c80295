//! Fast evaluation of the stresses at many points (`docs/stress.md`, "Fast evaluation"): a fast
//! multipole method for the Cauchy integrals of `strip.rs`, exact near the points and accurate to a
//! stated tolerance far from them.
//!
//! The sources lie on the surface, so the tree is a quadtree over the half-plane whose source boxes
//! all sit in its bottom row. The root box is the square `[c0 - H, c0 + H] x [0, 2H]`, `H` four
//! times the traction's half-span, so that the sources fill its middle quarter; level `l` has
//! boxes of width `w = 2H/2^l`, column `i` and row `k`. A source box (row 0) holds the multipole
//! moments of the elements whose midpoints it contains (`expansion.rs`, exact for linear and
//! square-root elements). The near neighbours of a box are the source boxes at most
//! [`NEAR`] columns away when the box is at most [`NEAR`] rows up; the field of all other
//! sources reaches a box through its local expansion: its parent's, shifted, plus the multipoles of
//! the parent's neighbours' children that are not its own neighbours. A point's box is the first,
//! going down, without near neighbours (all its field is then in the local expansion), or a box
//! of the finest level, whose near elements are then summed by the exact closed form. Points
//! four half-spans or more from the centre take the far field (`far.rs`), exactly as the direct
//! route does; that includes every point outside the root box (at least `H` from the centre),
//! except by rounding at the far field's radius, where the root multipole serves.
//!
//! Error: a local expansion of order `p` about a box of radius `r_t` = `w/sqrt 2` from sources
//! within `r_s` of a centre `d >= sqrt((NEAR + 1)^2 + 1/4) w` away converges like
//! `c^p`, `c = (r_s + r_t)/d`; `p` is chosen so that `c^p/(1 - c) <= TOLERANCE`.

pub(super) mod expansion;

use super::edge::SqrtEdge;
use super::far::FarField;
use super::strip::{add_edge, add_node, stresses, Sums};
use super::traction::Traction;
use expansion::{Expansions, MAX_ORDER};
use num_complex::Complex64;

/// Source boxes within this many columns (and target boxes within this many rows of the surface)
/// are near neighbours, summed exactly.
const NEAR: i64 = 2;
/// Elements per finest source box, on average.
const LEAF: usize = 4;
/// Boxes with at most this many points (above the finest level) stop the descent: their points
/// take the box's local expansion and then the near boxes' multipoles point by point, which is
/// cheaper than translating expansions for a handful of points.
const FEW: usize = 64;
/// The truncation error of one expansion, relative to the field of the source box it represents.
const TOLERANCE: f64 = 1e-13;

/// The traction element by element: element `e` spans nodes `e` and `e + 1` and carries
/// `left[e] + slope[e] (xi - x_e)`, plus the square-root edge corrections by element.
struct Elements {
    left: Vec<[f64; 2]>,
    slope: Vec<[f64; 2]>,
    edges: Vec<(usize, SqrtEdge)>,
    /// Corrections spanning several elements (the square roots of located stick-slip
    /// boundaries): a handful, summed exactly at every point instead of entering a box.
    long: Vec<SqrtEdge>,
}

impl Elements {
    fn new(t: &Traction) -> Self {
        let n = t.nodes.len();
        let mut left = Vec::with_capacity(n - 1);
        let mut slope = Vec::with_capacity(n - 1);
        let (mut v, mut s) = ([0.0; 2], [0.0; 2]);
        for e in 0..n - 1 {
            let h = t.nodes[e + 1] - t.nodes[e];
            for c in 0..2 {
                v[c] += t.jump[e][c];
                s[c] += t.kink[e][c];
            }
            left.push(v);
            slope.push(s);
            for c in 0..2 {
                v[c] += s[c] * h;
            }
        }
        let (mut edges, mut long) = (Vec::new(), Vec::new());
        for e in &t.edges {
            let start = e.edge.min(e.edge + e.length);
            let k = t.nodes.partition_point(|&x| x < start).min(n - 2);
            if t.nodes[k + 1] >= start + e.length.abs() * (1.0 - 1e-9) {
                edges.push((k, *e));
            } else {
                long.push(*e);
            }
        }
        Self {
            left,
            slope,
            edges,
            long,
        }
    }

    fn right(&self, t: &Traction, e: usize) -> [f64; 2] {
        let h = t.nodes[e + 1] - t.nodes[e];
        [
            self.left[e][0] + self.slope[e][0] * h,
            self.left[e][1] + self.slope[e][1] * h,
        ]
    }
}

/// The source boxes of one level: columns `lo..hi`, multipoles and whether each holds elements.
struct Level {
    lo: i64,
    hi: i64,
    multipoles: Vec<f64>,
    occupied: Vec<bool>,
    /// Distance from each box centre to its farthest element end.
    radius: Vec<f64>,
}

/// A point to evaluate: its column and row at the finest level, and its index.
#[derive(Clone, Copy)]
struct Target {
    i: u64,
    k: u64,
    index: usize,
}

/// The tree of one traction: everything the points share.
pub(super) struct Tree<'a> {
    t: &'a Traction,
    elements: Elements,
    ex: Expansions,
    /// Left side of the root box, and its width `2H`.
    origin: f64,
    width: f64,
    /// Finest level.
    finest: usize,
    /// The convergence ratio the order was chosen for: a multipole is used directly at a point
    /// at least `radius/ratio` from its centre.
    ratio: f64,
    levels: Vec<Level>,
    /// First element of each finest source column (`lo..=hi`).
    first: Vec<usize>,
}

/// The order of the expansions for source boxes whose radius is at most `radius` box widths,
/// and the convergence ratio `c` it was chosen for.
fn order_for(radius: f64) -> (usize, f64) {
    let d = (((NEAR + 1) * (NEAR + 1)) as f64 + 0.25).sqrt();
    let c = (radius + std::f64::consts::FRAC_1_SQRT_2) / d;
    (((TOLERANCE * (1.0 - c)).ln() / c.ln()).ceil() as usize, c)
}

/// The extent `[first node, last node]` of the elements in every box (`None`: empty), and each
/// level's box columns `lo..hi`, coarsest level first: the finest level from the elements' first
/// indices per column `first` (columns `lo..hi`), each coarser one the union of its two children.
type Extents = Vec<Vec<Option<(f64, f64)>>>;

fn box_extents(
    t: &Traction,
    first: &[usize],
    (lo, hi): (i64, i64),
    finest: usize,
) -> (Extents, Vec<(i64, i64)>) {
    let mut extents: Extents = vec![(lo..hi)
        .map(|j| {
            let (a, b) = (first[(j - lo) as usize], first[(j - lo + 1) as usize]);
            (b > a).then(|| (t.nodes[a], t.nodes[b]))
        })
        .collect()];
    let mut bounds = vec![(lo, hi)];
    for _ in 0..finest {
        let (clo, chi) = *bounds.last().unwrap_or(&(lo, hi));
        let child = extents.last().cloned().unwrap_or_default();
        let (plo, phi) = (clo >> 1, ((chi - 1) >> 1) + 1);
        let mut parent = vec![None; (phi - plo) as usize];
        for (j, ext) in (clo..chi).zip(child) {
            if let Some((a, b)) = ext {
                let slot: &mut Option<(f64, f64)> = &mut parent[((j >> 1) - plo) as usize];
                *slot = Some(slot.map_or((a, b), |(pa, pb)| (pa.min(a), pb.max(b))));
            }
        }
        extents.push(parent);
        bounds.push((plo, phi));
    }
    extents.reverse();
    bounds.reverse();
    (extents, bounds)
}

/// The upward pass: every occupied box's multipoles translated to its parent's centre (`m2m`),
/// from the level above the finest to the root.
fn upward(levels: &mut [Level], finest: usize, ex: &Expansions) {
    let p = ex.order;
    for l in (0..finest).rev() {
        let (upper, lower) = levels.split_at_mut(l + 1);
        let (parent, child) = (&mut upper[l], &lower[0]);
        for j in child.lo..child.hi {
            let cs = (j - child.lo) as usize;
            if !child.occupied[cs] {
                continue;
            }
            let ps = ((j >> 1) - parent.lo) as usize;
            // Child centre minus parent centre, in parent widths: -1/4 or +1/4.
            let delta = if j & 1 == 0 { -0.25 } else { 0.25 };
            let (pm, cm) = (
                &mut parent.multipoles[ps * 2 * p..(ps + 1) * 2 * p],
                &child.multipoles[cs * 2 * p..(cs + 1) * 2 * p],
            );
            ex.m2m(pm, cm, delta);
        }
    }
}

impl<'a> Tree<'a> {
    /// The tree, or `None` when the traction is too small for one to pay (fewer than
    /// three levels: sum directly).
    pub fn new(t: &'a Traction) -> Option<Self> {
        let n = t.nodes.len();
        if n < 2 {
            return None;
        }
        let (x0, x1) = (t.nodes[0], t.nodes[n - 1]);
        let half_span = 0.5 * (x1 - x0);
        let width = 8.0 * half_span;
        let origin = 0.5 * (x0 + x1) - 0.5 * width;
        let ne = n - 1;
        let longest = t.nodes.windows(2).map(|w| w[1] - w[0]).fold(0.0, f64::max);
        // Columns of the sources' quarter: about ne/LEAF of them, each at least the longest
        // element wide (so that an element overhangs its box by half a box at most).
        let mut finest = 0;
        while finest < 40
            && (1u64 << finest) < (4 * ne / LEAF) as u64
            && width / (1u64 << (finest + 1)) as f64 >= longest
        {
            finest += 1;
        }
        if finest < 3 {
            return None;
        }
        let wl = width / (1u64 << finest) as f64;
        let column = |x: f64| (((x - origin) / wl).floor() as i64).clamp(0, (1i64 << finest) - 1);
        let mid = |e: usize| 0.5 * (t.nodes[e] + t.nodes[e + 1]);
        let (lo, hi) = (column(mid(0)), column(mid(ne - 1)) + 1);
        let columns: Vec<i64> = (0..ne).map(|e| column(mid(e))).collect();
        let first: Vec<usize> = (lo..=hi)
            .map(|j| columns.partition_point(|&c| c < j))
            .collect();
        let (extents, bounds) = box_extents(t, &first, (lo, hi), finest);
        let mut radius: f64 = 0.5;
        for (l, (ext, &(blo, _))) in extents.iter().zip(&bounds).enumerate() {
            let w = width / (1u64 << l) as f64;
            for (j, e) in (blo..).zip(ext) {
                if let Some((a, b)) = e {
                    let c = origin + (j as f64 + 0.5) * w;
                    radius = radius.max((c - a).max(b - c) / w);
                }
            }
        }
        let (order, ratio) = order_for(radius);
        let ex = Expansions::new(order.clamp(4, MAX_ORDER)).ok()?;
        let elements = Elements::new(t);
        let p = ex.order;
        // Multipoles: the finest level from the elements, then upwards.
        let mut levels: Vec<Level> = bounds
            .iter()
            .zip(&extents)
            .enumerate()
            .map(|(l, (&(lo, hi), ext))| {
                let w = width / (1u64 << l) as f64;
                Level {
                    lo,
                    hi,
                    multipoles: vec![0.0; (hi - lo) as usize * 2 * p],
                    occupied: ext.iter().map(Option::is_some).collect(),
                    radius: (lo..)
                        .zip(ext)
                        .map(|(j, e)| {
                            let c = origin + (j as f64 + 0.5) * w;
                            e.map_or(0.0, |(a, b)| (c - a).max(b - c))
                        })
                        .collect(),
                }
            })
            .collect();
        {
            let leaf = &mut levels[finest];
            for j in lo..hi {
                let c = origin + (j as f64 + 0.5) * wl;
                let slot = (j - lo) as usize;
                let m = &mut leaf.multipoles[slot * 2 * p..(slot + 1) * 2 * p];
                for e in first[slot]..first[slot + 1] {
                    let (xa, xb) = (t.nodes[e], t.nodes[e + 1]);
                    ex.linear(m, c, wl, xa, xb, elements.left[e], elements.slope[e]);
                }
                for (e, edge) in &elements.edges {
                    if (first[slot]..first[slot + 1]).contains(e) {
                        ex.edge(m, c, wl, edge);
                    }
                }
            }
        }
        upward(&mut levels, finest, &ex);
        Some(Self {
            t,
            elements,
            ex,
            origin,
            width,
            finest,
            ratio,
            levels,
            first,
        })
    }

    /// `[sxx, szz, sxz]` from the traction at every point `(x[i], z[i])` (`z >= 0`, checked by
    /// the caller), or the index of the first surface point on a jump of the traction.
    /// Points that `far` reaches take the far field (`far.rs`), exactly as the direct route does.
    pub fn in_plane(
        &self,
        x: &[f64],
        z: &[f64],
        far: Option<&FarField>,
    ) -> Result<Vec<[f64; 3]>, usize> {
        let mut out = vec![[0.0; 3]; x.len()];
        let mut bad = usize::MAX;
        let wl = self.width / (1u64 << self.finest) as f64;
        let top = (1u64 << self.finest) - 1;
        let mut inside = Vec::with_capacity(x.len());
        let root = &self.levels[0].multipoles;
        let centre = self.origin + 0.5 * self.width;
        for (index, (&x, &z)) in x.iter().zip(z).enumerate() {
            let z = if z == 0.0 { 0.0 } else { z };
            if let Some(far) = far.filter(|f| f.reaches(x, z)) {
                out[index] = far.in_plane(x, z);
                continue;
            }
            let u = x - self.origin;
            if u < 0.0 || u >= self.width || z >= self.width {
                let y = Complex64::new(self.width, 0.0) / Complex64::new(x - centre, z);
                let mut s = sums_of(self.ex.m2p(root, y, self.width));
                self.add_long(&mut s, x, z);
                out[index] = stresses(&s, z);
                continue;
            }
            inside.push(Target {
                i: ((u / wl).floor() as u64).min(top),
                k: ((z / wl).floor() as u64).min(top),
                index,
            });
        }
        let zero = vec![Complex64::default(); 2 * self.ex.order];
        self.descend(0, 0, 0, &zero, &mut inside, x, z, &mut out, &mut bad);
        if bad == usize::MAX {
            Ok(out)
        } else {
            Err(bad)
        }
    }

    /// Passes the local expansion of box `(l, i, k)` down to the boxes of its points.
    #[allow(clippy::too_many_arguments)]
    fn descend(
        &self,
        l: usize,
        i: u64,
        k: u64,
        local: &[Complex64],
        targets: &mut [Target],
        x: &[f64],
        z: &[f64],
        out: &mut [[f64; 3]],
        bad: &mut usize,
    ) {
        let p = self.ex.order;
        let shift = self.finest - l - 1;
        let w = self.width / (1u64 << (l + 1)) as f64;
        let mut child_local = vec![Complex64::default(); 2 * p];
        let split = partition(targets, |t| (t.i >> shift) & 1 == 0);
        let (left, right) = targets.split_at_mut(split);
        for (ci, half) in [(2 * i, left), (2 * i + 1, right)] {
            let split = partition(half, |t| (t.k >> shift) & 1 == 0);
            let (low, high) = half.split_at_mut(split);
            for (ck, group) in [(2 * k, low), (2 * k + 1, high)] {
                if group.is_empty() {
                    continue;
                }
                let tx = self.origin + (ci as f64 + 0.5) * w;
                let tz = (ck as f64 + 0.5) * w;
                if l == 0 {
                    child_local.fill(Complex64::default());
                } else {
                    let delta = Complex64::new(
                        if ci & 1 == 0 { -0.25 } else { 0.25 },
                        if ck & 1 == 0 { -0.25 } else { 0.25 },
                    );
                    self.ex.l2l(&mut child_local, local, delta);
                }
                let level = &self.levels[l + 1];
                let (ci, ck) = (ci as i64, ck as i64);
                let parent = ci >> 1;
                let from = (2 * (parent - NEAR)).max(level.lo);
                let to = (2 * (parent + NEAR) + 2).min(level.hi);
                for j in from..to {
                    let slot = (j - level.lo) as usize;
                    if !level.occupied[slot] || ((j - ci).abs() <= NEAR && ck <= NEAR) {
                        continue;
                    }
                    let c = self.origin + (j as f64 + 0.5) * w;
                    let y0 = Complex64::new(w, 0.0) / Complex64::new(tx - c, tz);
                    let m = &level.multipoles[slot * 2 * p..(slot + 1) * 2 * p];
                    self.ex.m2l(&mut child_local, m, y0, w);
                }
                if ck > NEAR || l + 1 == self.finest {
                    let near = if ck <= NEAR {
                        let (lo, hi) = (self.levels[self.finest].lo, self.levels[self.finest].hi);
                        let (a, b) = ((ci - NEAR).max(lo), (ci + NEAR + 1).min(hi));
                        (a < b)
                            .then(|| (self.first[(a - lo) as usize], self.first[(b - lo) as usize]))
                    } else {
                        None
                    };
                    for t in group.iter() {
                        let (px, pz) =
                            (x[t.index], if z[t.index] == 0.0 { 0.0 } else { z[t.index] });
                        let f = self.ex.l2p(
                            &child_local,
                            Complex64::new((px - tx) / w, (pz - tz) / w),
                            w,
                        );
                        let mut s = sums_of(f);
                        if let Some((e0, e1)) = near {
                            if e1 > e0 && !self.near(&mut s, e0, e1, px, pz) {
                                *bad = (*bad).min(t.index);
                                continue;
                            }
                        }
                        self.add_long(&mut s, px, pz);
                        out[t.index] = stresses(&s, pz);
                    }
                } else if group.len() <= FEW {
                    for t in group.iter() {
                        let (px, pz) =
                            (x[t.index], if z[t.index] == 0.0 { 0.0 } else { z[t.index] });
                        let f = self.ex.l2p(
                            &child_local,
                            Complex64::new((px - tx) / w, (pz - tz) / w),
                            w,
                        );
                        let mut s = sums_of(f);
                        let mut direct = (i64::MAX, i64::MIN);
                        for j in ci - NEAR..=ci + NEAR {
                            self.add_box(l + 1, j, px, pz, &mut s, &mut direct);
                        }
                        if direct.0 <= direct.1 {
                            let lo = self.levels[self.finest].lo;
                            let (e0, e1) = (
                                self.first[(direct.0 - lo) as usize],
                                self.first[(direct.1 + 1 - lo) as usize],
                            );
                            if e1 > e0 && !self.near(&mut s, e0, e1, px, pz) {
                                *bad = (*bad).min(t.index);
                                continue;
                            }
                        }
                        self.add_long(&mut s, px, pz);
                        out[t.index] = stresses(&s, pz);
                    }
                } else {
                    self.descend(
                        l + 1,
                        ci as u64,
                        ck as u64,
                        &child_local,
                        group,
                        x,
                        z,
                        out,
                        bad,
                    );
                }
            }
        }
    }

    /// Adds the field of source box `(l, j)` at the point `(x, z)`: its multipole when the point
    /// is far enough for the expansion's accuracy, else its children's; finest boxes that are too
    /// close widen `direct`, the columns to sum exactly (they are contiguous: the boxes too close
    /// to a point surround it).
    fn add_box(&self, l: usize, j: i64, x: f64, z: f64, s: &mut Sums, direct: &mut (i64, i64)) {
        let level = &self.levels[l];
        if j < level.lo || j >= level.hi || !level.occupied[(j - level.lo) as usize] {
            return;
        }
        let slot = (j - level.lo) as usize;
        let w = self.width / (1u64 << l) as f64;
        let c = self.origin + (j as f64 + 0.5) * w;
        if level.radius[slot] <= self.ratio * (x - c).hypot(z) {
            let p = self.ex.order;
            let m = &level.multipoles[slot * 2 * p..(slot + 1) * 2 * p];
            let add = sums_of(
                self.ex
                    .m2p(m, Complex64::new(w, 0.0) / Complex64::new(x - c, z), w),
            );
            for k in 0..2 {
                s.fp[k] += add.fp[k];
                s.dp[k] += add.dp[k];
                s.fq[k] += add.fq[k];
                s.dq[k] += add.dq[k];
            }
        } else if l == self.finest {
            *direct = (direct.0.min(j), direct.1.max(j));
        } else {
            self.add_box(l + 1, 2 * j, x, z, s, direct);
            self.add_box(l + 1, 2 * j + 1, x, z, s, direct);
        }
    }

    /// Adds the corrections that span several elements, exactly.
    fn add_long(&self, s: &mut Sums, x: f64, z: f64) {
        for edge in &self.elements.long {
            add_edge(s, edge, x, z);
        }
    }

    /// Adds the exact field of the elements `e0..e1` at `(x, z)`: the node form of `strip.rs`
    /// restricted to them (their end values become jumps at the range's ends). `false` on the
    /// surface at a jump of the traction.
    ///
    /// Whether a surface point sits on a jump is decided from the traction's own jumps, not from
    /// the range's: a range ends where the traction is continuous (between boxes, or at a contact
    /// edge where the linear part ends at a rounding-level value), and the log terms that
    /// `add_node` leaves out there cancel with the neighbouring range's or vanish in the limit.
    fn near(&self, s: &mut Sums, e0: usize, e1: usize, x: f64, z: f64) -> bool {
        let (t, el) = (self.t, &self.elements);
        add_node(s, t.nodes[e0], el.left[e0], el.slope[e0], x, z);
        for k in e0 + 1..e1 {
            add_node(s, t.nodes[k], t.jump[k], t.kink[k], x, z);
        }
        let r = el.right(t, e1 - 1);
        let sl = el.slope[e1 - 1];
        add_node(s, t.nodes[e1], [-r[0], -r[1]], [-sl[0], -sl[1]], x, z);
        for (e, edge) in &el.edges {
            if (e0..e1).contains(e) {
                add_edge(s, edge, x, z);
            }
        }
        z != 0.0 || (e0..=e1).all(|k| t.nodes[k] != x || t.jump[k] == [0.0, 0.0])
    }
}

fn sums_of(f: [Complex64; 4]) -> Sums {
    Sums {
        fp: [f[0].re, f[0].im],
        dp: [f[1].re, f[1].im],
        fq: [f[2].re, f[2].im],
        dq: [f[3].re, f[3].im],
    }
}

/// Moves the targets satisfying `first` to the front; returns how many there are.
fn partition(t: &mut [Target], first: impl Fn(&Target) -> bool) -> usize {
    let mut n = 0;
    for j in 0..t.len() {
        if first(&t[j]) {
            t.swap(n, j);
            n += 1;
        }
    }
    n
}
