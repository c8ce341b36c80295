//! Several contact-edge crossings in one sub-step, against one sub-step per crossing: a dense,
//! stand-alone measurement (BENCHMARKS.md, issue 20, "Several edge crossings per sub-step").
//! Not part of the workspace: `rustc -O benches/multi-crossing/main.rs -o target/multi-crossing`,
//! then `target/multi-crossing CELLS STEPS_PER_HALF [bands]` (see README.md).
//!
//! Hertz (R = 50, E = 200 GPa, nu = 0.3, f = 0.6), a normal ramp to P = 1000 in 10 increments,
//! then two in-phase cycles to (P, Q, sigma) = (1400, 100, 5) and back: eq. (1) holds, so exact
//! theory has no slip. The stick systems are solved densely (LU) on all contact cells, with no
//! active set: what is measured is how close each scheme comes to the friction limit
//! (`max |q| / (f p)` over every sub-step end, which is the ratio of the smallest friction
//! coefficient that keeps the scheme in full stick to f), whether the cycle reverses exactly, and
//! the traction difference against the reference at every increment end.
//!
//! Schemes. Reference: the increment is split at every crossing of a cell centre by a contact
//! end (the march's rule); each sub-step is the standard stick system. Multi-crossing: the
//! increment is split into equal parts with at most `cap` crossings per edge each; a cell that
//! enters at the fraction tau of its part is stuck from tau on, with the constraint
//! `u_k(1) - u_k(tau_k) = 0`, its traction `0` before tau and following a time profile after; a
//! cell that leaves at tau has its traction taken to zero along the mirrored profile (known) and
//! no constraint. The rigid shift and the bulk term are linear in time. Profiles: `linear` (each
//! cell's traction increment linear in time from its entry) or `pressure` (shaped like the
//! cell's Hertz pressure `sqrt(a(t)^2 - x^2)`, which is the exact full-stick shape dq = (dQ/dP) dp).
//! The entering row k then reads `sum_j G_kj dq_j (1 - R_j(tau_k)) / (1 - tau_k) + (bulk) - c = 0`
//! with `R_j` the profile (for `linear`, `1 - R_j(tau_k)` over `1 - tau_k` is
//! `1 / (1 - min(tau_j, tau_k))` between entering cells and 1 otherwise: a symmetric system).
//! Band (local time stepping): the whole increment in one system, with knots at every crossing;
//! the crossing cells and the contact cells within `band` cells inside the smaller contact carry
//! one unknown traction increment per knot interval and stick rows on each interval they are in
//! contact (a leaving cell's traction reaches zero at its crossing), the other cells one
//! increment linear over the increment and a stick row over it, with one rigid shift per
//! interval and the resultant held at every knot. With the band covering the contact it is the
//! reference.
//!
//! Conventions as in crates/halfplane/src/march: `h(x) = -(A/pi) int q ln|xi - x| dxi
//! + (A/4) sigma x + C` (A = 4(1 - nu^2)/E), traction positive in +x, p = sqrt(a^2 - x^2)/(R A),
//! a^2 = 2 P R A / pi (Johnson, *Contact Mechanics*, section 5.7).
use std::f64::consts::PI;

const RADIUS: f64 = 50.0;
const FRICTION: f64 = 0.6;

#[derive(Clone, Copy)]
struct Load {
    normal: f64,
    shear: f64,
    bulk: f64,
}

impl Load {
    fn lerp(self, to: Load, t: f64) -> Load {
        Load {
            normal: self.normal + (to.normal - self.normal) * t,
            shear: self.shear + (to.shear - self.shear) * t,
            bulk: self.bulk + (to.bulk - self.bulk) * t,
        }
    }
}

#[derive(Clone, Copy, PartialEq)]
enum Profile {
    Linear,
    Pressure,
}

/// Cell centres on a mirrored grid and the cell-mean log kernel `int_cell ln(|xi - x_i|/l)`.
struct Grid {
    x: Vec<f64>,
    width: f64,
    kernel: Vec<f64>,
    compliance: f64,
}

impl Grid {
    fn new(n: usize, half_span: f64) -> Grid {
        let compliance = 4.0 * (1.0 - 0.3f64 * 0.3) / 200_000.0;
        let width = 2.0 * half_span / n as f64;
        let mut x: Vec<f64> = (0..n)
            .map(|i| -half_span + (i as f64 + 0.5) * width)
            .collect();
        for i in 0..n / 2 {
            x[n - 1 - i] = -x[i];
        }
        let scale = 8.0 * half_span;
        let primitive = |y: f64| {
            if y == 0.0 {
                0.0
            } else {
                y * (y.abs() / scale).ln() - y
            }
        };
        let mut kernel = vec![0.0; n * n];
        for i in 0..n {
            for j in 0..n {
                let d = x[j] - x[i];
                kernel[i * n + j] = primitive(d + 0.5 * width) - primitive(d - 0.5 * width);
            }
        }
        Grid {
            x,
            width,
            kernel,
            compliance,
        }
    }

    fn half_width_squared(&self, normal: f64) -> f64 {
        2.0 * normal * RADIUS * self.compliance / PI
    }

    fn pressure(&self, x: f64, a2: f64) -> f64 {
        (a2 - x * x).max(0.0).sqrt() / (RADIUS * self.compliance)
    }
}

/// Gaussian elimination with partial pivoting.
fn solve(mut m: Vec<f64>, mut b: Vec<f64>) -> Vec<f64> {
    let n = b.len();
    for c in 0..n {
        let pivot = (c..n)
            .max_by(|&r, &s| m[r * n + c].abs().total_cmp(&m[s * n + c].abs()))
            .unwrap();
        if pivot != c {
            for k in 0..n {
                m.swap(c * n + k, pivot * n + k);
            }
            b.swap(c, pivot);
        }
        for r in c + 1..n {
            let factor = m[r * n + c] / m[c * n + c];
            if factor != 0.0 {
                for k in c..n {
                    m[r * n + k] -= factor * m[c * n + k];
                }
                b[r] -= factor * b[c];
            }
        }
    }
    for c in (0..n).rev() {
        let s: f64 = (c + 1..n).map(|k| m[c * n + k] * b[k]).sum();
        b[c] = (b[c] - s) / m[c * n + c];
    }
    b
}

/// What a cell does over an increment, with its crossing fraction where it has one.
#[derive(Clone, Copy)]
enum Role {
    In,
    Enters(f64),
    Leaves(f64),
    Out,
}

struct March<'g> {
    grid: &'g Grid,
    profile: Profile,
    /// At most this many crossings per edge in a sub-step; 0: one sub-step per crossing.
    cap: usize,
    /// Local time stepping: cells within this many cells of a moving edge resolved at every
    /// crossing, the rest linear in time over the increment.
    band: Option<usize>,
    traction: Vec<f64>,
    load: Load,
    /// Largest `|q| / (f p)` at a sub-step end since the last reset.
    max_ratio: f64,
}

impl March<'_> {
    fn increment(&mut self, to: Load) {
        let (from, g) = (self.load, self.grid);
        let (a0, a1) = (
            g.half_width_squared(from.normal),
            g.half_width_squared(to.normal),
        );
        let mut crossings = Vec::new();
        let mut per_edge = 0;
        let roles: Vec<Role> =
            g.x.iter()
                .map(|&x| {
                    let x2 = x * x;
                    let tau = (x2 - a0) / (a1 - a0);
                    let role = match (x2 < a0, x2 < a1) {
                        (true, true) => Role::In,
                        (false, true) => Role::Enters(tau),
                        (true, false) => Role::Leaves(tau),
                        _ => Role::Out,
                    };
                    if !matches!(role, Role::In | Role::Out) {
                        crossings.push(tau);
                        per_edge += usize::from(x > 0.0);
                    }
                    role
                })
                .collect();
        if let Some(d) = self.band {
            crossings.sort_by(f64::total_cmp);
            crossings.dedup();
            crossings.retain(|t| *t > 0.0 && *t < 1.0);
            self.banded(from, to, &roles, &crossings, d, a0.min(a1));
        } else if self.cap == 0 {
            crossings.sort_by(f64::total_cmp);
            crossings.dedup();
            let mut start = 0.0;
            for &t in crossings.iter().filter(|t| **t > 0.0 && **t < 1.0) {
                self.sub_step(from, to, [start, t], &roles);
                start = t;
            }
            self.sub_step(from, to, [start, 1.0], &roles);
        } else {
            let parts = per_edge.div_ceil(self.cap).max(1);
            for k in 0..parts {
                let span = [k as f64, (k + 1) as f64].map(|v| v / parts as f64);
                self.sub_step(from, to, span, &roles);
            }
        }
        self.load = to;
    }

    /// The whole increment in one solve: knots at every crossing; cells near the edges (the
    /// crossing cells and contact cells within `d` cells inside the smaller contact) carry one
    /// unknown increment per knot interval, the others one increment linear in time.
    fn banded(
        &mut self,
        from: Load,
        to: Load,
        roles: &[Role],
        knots: &[f64],
        d: usize,
        a2_min: f64,
    ) {
        let g = self.grid;
        let n = g.x.len();
        let mut t = vec![0.0];
        t.extend_from_slice(knots);
        t.push(1.0);
        let m = t.len() - 1;
        let inner = a2_min.sqrt() - d as f64 * g.width;
        // in contact over interval s, and whether it leaves at its end
        let in_contact = |i: usize, s: usize| -> bool {
            match roles[i] {
                Role::In => true,
                Role::Enters(tau) => tau <= t[s],
                Role::Leaves(tau) => tau >= t[s + 1],
                Role::Out => false,
            }
        };
        let leaves_at =
            |i: usize, s: usize| matches!(roles[i], Role::Leaves(tau) if tau == t[s + 1]);
        let mut far = Vec::new();
        let mut band = Vec::new();
        for i in 0..n {
            match roles[i] {
                Role::Out => {}
                Role::In if g.x[i].abs() < inner => far.push(i),
                _ => band.push(i),
            }
        }
        // variable indices
        let mut idx = std::collections::BTreeMap::new();
        let mut nv = far.len();
        for &j in &band {
            for s in 0..m {
                if in_contact(j, s) {
                    idx.insert((j, s), nv);
                    nv += 1;
                }
            }
        }
        let c0 = nv;
        nv += m;
        let mut a = vec![0.0; nv * nv];
        let mut b = vec![0.0; nv];
        let mut row = 0;
        let d_bulk = to.bulk - from.bulk;
        let d_shear = to.shear - from.shear;
        // far rows: over the whole increment
        for &i in &far {
            for (c, &j) in far.iter().enumerate() {
                a[row * nv + c] = g.kernel[i * n + j];
            }
            for (&(j, _), &v) in &idx {
                a[row * nv + v] = g.kernel[i * n + j];
            }
            for s in 0..m {
                a[row * nv + c0 + s] = -1.0;
            }
            b[row] = 0.25 * PI * d_bulk * g.x[i];
            row += 1;
        }
        // band rows per interval
        for &k in &band {
            for s in 0..m {
                if !in_contact(k, s) {
                    continue;
                }
                if leaves_at(k, s) {
                    // traction to zero at the end of the interval
                    for s2 in 0..=s {
                        a[row * nv + idx[&(k, s2)]] = 1.0;
                    }
                    b[row] = -self.traction[k];
                    row += 1;
                    continue;
                }
                let h = t[s + 1] - t[s];
                for (c, &j) in far.iter().enumerate() {
                    a[row * nv + c] = g.kernel[k * n + j] * h;
                }
                for &j in &band {
                    if let Some(&v) = idx.get(&(j, s)) {
                        a[row * nv + v] = g.kernel[k * n + j];
                    }
                }
                a[row * nv + c0 + s] = -1.0;
                b[row] = 0.25 * PI * d_bulk * h * g.x[k];
                row += 1;
            }
        }
        // resultant per interval
        for s in 0..m {
            let h = t[s + 1] - t[s];
            for c in 0..far.len() {
                a[row * nv + c] = g.width * h;
            }
            for &j in &band {
                if let Some(&v) = idx.get(&(j, s)) {
                    a[row * nv + v] = g.width;
                }
            }
            b[row] = d_shear * h;
            row += 1;
        }
        assert_eq!(row, nv);
        let z = solve(a, b);
        for (c, &j) in far.iter().enumerate() {
            self.traction[j] += z[c];
        }
        for (&(j, _), &v) in &idx {
            self.traction[j] += z[v];
        }
        let a2_end = g.half_width_squared(to.normal);
        for i in 0..n {
            let inside = match roles[i] {
                Role::In | Role::Enters(_) => true,
                _ => false,
            };
            if !inside {
                self.traction[i] = 0.0;
                continue;
            }
            let p = g.pressure(g.x[i], a2_end);
            self.max_ratio = self.max_ratio.max(self.traction[i].abs() / (FRICTION * p));
        }
    }

    /// The sub-step over the increment fractions `[s0, s1]`.
    fn sub_step(&mut self, from: Load, to: Load, [s0, s1]: [f64; 2], roles: &[Role]) {
        let g = self.grid;
        let n = g.x.len();
        let (start, end) = (from.lerp(to, s0), from.lerp(to, s1));
        let relative = |tau: f64| (tau - s0) / (s1 - s0);
        // Unknown cells with their entry fraction (0: in contact from the start), leaving cells
        // with their exit fraction.
        let (mut unknown, mut leaving) = (Vec::new(), Vec::new());
        for (i, role) in roles.iter().enumerate() {
            match *role {
                Role::In => unknown.push((i, 0.0)),
                Role::Enters(tau) if tau <= s0 => unknown.push((i, 0.0)),
                Role::Enters(tau) if tau < s1 => unknown.push((i, relative(tau))),
                Role::Leaves(tau) if tau > s1 => unknown.push((i, 0.0)),
                Role::Leaves(tau) if tau > s0 => leaving.push((i, relative(tau))),
                _ => {}
            }
        }
        let (a2_start, a2_end) = (
            g.half_width_squared(start.normal),
            g.half_width_squared(end.normal),
        );
        // u = a(t)^2 - x^2, linear in t for Hertz (a^2 is linear in P).
        let u = |j: usize, t: f64| {
            let x2 = g.x[j] * g.x[j];
            ((a2_start - x2) + (a2_end - a2_start) * t).max(0.0)
        };
        let pressure_shaped = self.profile == Profile::Pressure && a2_end != a2_start;
        // The fraction of cell j's increment reached at t (it enters at `entry`).
        let reached = |j: usize, entry: f64, t: f64| {
            if entry > 0.0 {
                let s = ((t - entry) / (1.0 - entry)).max(0.0);
                if self.profile == Profile::Pressure {
                    s.sqrt()
                } else {
                    s
                }
            } else if pressure_shaped {
                let (r0, r1) = (u(j, 0.0).sqrt(), u(j, 1.0).sqrt());
                (u(j, t).sqrt() - r0) / (r1 - r0)
            } else {
                t
            }
        };
        // The fraction of a leaving cell's traction removed at t (it leaves at `exit`).
        let removed = |l: usize, exit: f64, t: f64| {
            if t >= exit {
                1.0
            } else if self.profile == Profile::Pressure {
                1.0 - (u(l, t) / u(l, 0.0)).sqrt()
            } else {
                t / exit
            }
        };
        let m = unknown.len() + 1;
        let (mut matrix, mut rhs) = (vec![0.0; m * m], vec![0.0; m]);
        let d_bulk = end.bulk - start.bulk;
        for (r, &(k, entry_k)) in unknown.iter().enumerate() {
            // Over [entry_k, 1], divided by its length.
            let weight = |reached_at_entry: f64| {
                if entry_k > 0.0 {
                    (1.0 - reached_at_entry) / (1.0 - entry_k)
                } else {
                    1.0
                }
            };
            for (c, &(j, entry_j)) in unknown.iter().enumerate() {
                matrix[r * m + c] = g.kernel[k * n + j] * weight(reached(j, entry_j, entry_k));
            }
            matrix[r * m + m - 1] = -1.0;
            rhs[r] = 0.25 * PI * d_bulk * g.x[k]
                + leaving
                    .iter()
                    .map(|&(l, exit)| {
                        g.kernel[k * n + l] * self.traction[l] * weight(removed(l, exit, entry_k))
                    })
                    .sum::<f64>();
        }
        for c in 0..m - 1 {
            matrix[(m - 1) * m + c] = g.width;
        }
        rhs[m - 1] = end.shear - start.shear
            + g.width * leaving.iter().map(|&(l, _)| self.traction[l]).sum::<f64>();
        let dq = solve(matrix, rhs);
        for (c, &(j, _)) in unknown.iter().enumerate() {
            self.traction[j] += dq[c];
            let p = g.pressure(g.x[j], a2_end);
            self.max_ratio = self.max_ratio.max(self.traction[j].abs() / (FRICTION * p));
        }
        for &(l, _) in &leaving {
            self.traction[l] = 0.0;
        }
    }
}

/// The run: the increment-end tractions of the two cycles, the largest `|q| / (f p)` in them and
/// the difference between the cycles' last tractions.
fn run(
    grid: &Grid,
    steps: usize,
    cap: usize,
    profile: Profile,
    band: Option<usize>,
) -> (Vec<Vec<f64>>, f64, f64) {
    let low = Load {
        normal: 1000.0,
        shear: 0.0,
        bulk: 0.0,
    };
    let high = Load {
        normal: 1400.0,
        shear: 100.0,
        bulk: 5.0,
    };
    let mut march = March {
        grid,
        profile,
        cap,
        band,
        traction: vec![0.0; grid.x.len()],
        load: Load {
            normal: 1e-9,
            ..low
        },
        max_ratio: 0.0,
    };
    for k in 1..=10 {
        march.increment(Load {
            normal: low.normal * k as f64 / 10.0,
            ..low
        });
    }
    march.max_ratio = 0.0;
    let mut ends = Vec::new();
    let mut cycle_ends = Vec::new();
    for _ in 0..2 {
        for (a, b) in [(low, high), (high, low)] {
            for k in 1..=steps {
                march.increment(a.lerp(b, k as f64 / steps as f64));
                ends.push(march.traction.clone());
            }
        }
        cycle_ends.push(march.traction.clone());
    }
    let reversal = max_difference(&cycle_ends[0], &cycle_ends[1]);
    (ends, march.max_ratio, reversal)
}

fn max_difference(a: &[f64], b: &[f64]) -> f64 {
    a.iter()
        .zip(b)
        .map(|(p, q)| (p - q).abs())
        .fold(0.0, f64::max)
}

fn main() {
    let arg = |i: usize, default: usize| {
        std::env::args()
            .nth(i)
            .map_or(default, |s| s.parse().expect("a whole number"))
    };
    let (cells, steps) = (arg(1, 400), arg(2, 5));
    let probe = Grid::new(2, 1.0);
    let grid = Grid::new(cells, 1.01 * probe.half_width_squared(1400.0).sqrt());
    let p0 = grid.pressure(0.0, grid.half_width_squared(1400.0));
    let (reference, ratio, reversal) = run(&grid, steps, 0, Profile::Linear, None);
    println!(
        "cells {cells}, {steps} steps per half; traction differences in f p0 = {:.1} N/mm^2",
        FRICTION * p0
    );
    println!("scheme                                         | max |q|/(f p) | cycle 2 - cycle 1 | max vs reference | at half ends");
    println!("                      one sub-step per crossing | {ratio:.4}        | {:.1e}           |                  |", reversal / (FRICTION * p0));
    let mut variants: Vec<(String, usize, Profile, Option<usize>)> = Vec::new();
    for profile in [Profile::Linear, Profile::Pressure] {
        for cap in [1, 4, usize::MAX] {
            let name = if profile == Profile::Linear {
                "linear"
            } else {
                "pressure"
            };
            let cap_name = if cap == usize::MAX {
                "all crossings in one sub-step".to_string()
            } else {
                format!("at most {cap} crossings per edge")
            };
            variants.push((format!("{name}, {cap_name}"), cap, profile, None));
        }
    }
    for band in [2, 8, 32] {
        variants.push((
            format!("band of {band} cells, knots at crossings"),
            0,
            Profile::Linear,
            Some(band),
        ));
    }
    let only_bands = std::env::args().nth(3).as_deref() == Some("bands");
    for (name, cap, profile, band) in variants {
        if only_bands && band.is_none() {
            continue;
        }
        let (ends, ratio, reversal) = run(&grid, steps, cap, profile, band);
        let each: Vec<f64> = ends
            .iter()
            .zip(&reference)
            .map(|(a, b)| max_difference(a, b) / (FRICTION * p0))
            .collect();
        let worst = each.iter().copied().fold(0.0, f64::max);
        let half_ends = (1..=4).map(|h| each[h * steps - 1]).fold(0.0, f64::max);
        println!(
            "{name:>46} | {ratio:.4}        | {:.1e}           | {worst:.2e}         | {half_ends:.1e}",
            reversal / (FRICTION * p0)
        );
    }
}
