//! The fast multipole route of `stress::field` against the direct sum (`stress::field_direct`).
//!
//! Tolerance: 1e-11 of the largest stress magnitude among the points. The fast route sums the
//! same closed forms exactly near each point and replaces far elements by expansions whose
//! truncation error is set to 1e-13 of the field of each source box (`docs/stress.md`, "Fast
//! evaluation"); a point collects some tens of boxes. The largest differences seen (2e-12 at 200
//! cells, 5e-12 at 1000) are at points tens of spans away and are the direct sum's own rounding:
//! there its terms `(J + S w) log w` grow with the distance and cancel. A 40-digit evaluation of
//! the same traction at such a point (3000 cells, 40 spans away) agreed with the fast route to
//! 1e-15 and with the direct sum to 7e-12 only. 1e-11 thus leaves a margin of two while an
//! expansion a few terms short, a misplaced box or a missing element fails it by orders.

use halfplane::stress::closed_form::NowellHills;
use halfplane::stress::{self, Traction};
use halfplane::{reference, Material};

fn material() -> Material {
    reference::material()
}

/// A deterministic stream of numbers in [0, 1) (a linear congruential generator).
struct Lcg(u64);

impl Lcg {
    fn next(&mut self) -> f64 {
        self.0 = self
            .0
            .wrapping_mul(6_364_136_223_846_793_005)
            .wrapping_add(1_442_695_040_888_963_407);
        (self.0 >> 11) as f64 / (1u64 << 53) as f64
    }
}

/// Nowell-Hills partial slip sampled on `n` cells of [-a, a] as a contact traction.
fn partial_slip(n: usize) -> Traction {
    let nh = NowellHills::hertz(1.0, 0.6, 1000.0, 300.0, 100.0);
    let a = 1.0;
    let mut x = vec![-a];
    x.extend((0..n).map(|i| -a + (i as f64 + 0.5) * 2.0 * a / n as f64));
    x.push(a);
    let mut p: Vec<f64> = x.iter().map(|&x| nh.pressure(x)).collect();
    let mut q: Vec<f64> = x.iter().map(|&x| nh.traction(x)).collect();
    let last = x.len() - 1;
    p[0] = 0.0;
    p[last] = 0.0;
    q[0] = 0.0;
    q[last] = 0.0;
    Traction::contact(&x, &p, &q).unwrap()
}

/// Random points below and beside the traction's span, on the surface, and close to its nodes.
fn points(t: &Traction, count: usize, seed: u64) -> (Vec<f64>, Vec<f64>) {
    let mut r = Lcg(seed);
    let nodes = t.nodes();
    let (lo, hi) = (nodes[0], nodes[nodes.len() - 1]);
    let span = hi - lo;
    let (mut x, mut z) = (Vec::new(), Vec::new());
    for i in 0..count {
        let (px, pz) = match i % 5 {
            // Anywhere within three spans, down to two spans deep.
            0 => (lo - span + 3.0 * span * r.next(), 2.0 * span * r.next()),
            // On the surface (between nodes).
            1 => (lo - 0.2 * span + 1.4 * span * r.next(), 0.0),
            // Just below a node, at depths from 1e-9 to 1e-2 of the span.
            2 => {
                let k = (r.next() * nodes.len() as f64) as usize % nodes.len();
                let d = span * 10f64.powf(-9.0 + 7.0 * r.next());
                (nodes[k] + d * (r.next() - 0.5), d)
            }
            // Close to a contact edge.
            3 => {
                let e = if r.next() < 0.5 { lo } else { hi };
                let d = span * 10f64.powf(-8.0 + 6.0 * r.next());
                (e + d * (2.0 * r.next() - 1.0), d * r.next())
            }
            // Far away.
            _ => (lo + span * (40.0 * r.next() - 20.0), span * 20.0 * r.next()),
        };
        x.push(px);
        z.push(pz);
    }
    (x, z)
}

fn compare(t: &Traction, count: usize, seed: u64) -> f64 {
    let (x, z) = points(t, count, seed);
    let m = material();
    let fast = stress::field(t, 25.0, &m, &x, &z).unwrap();
    let direct = stress::field_direct(t, 25.0, &m, &x, &z).unwrap();
    let mut peak: f64 = 0.0;
    let mut worst: f64 = 0.0;
    let mut at = 0;
    for i in 0..x.len() {
        for (a, b) in [
            (fast.sxx[i], direct.sxx[i]),
            (fast.szz[i], direct.szz[i]),
            (fast.syy[i], direct.syy[i]),
            (fast.sxz[i], direct.sxz[i]),
        ] {
            peak = peak.max(b.abs());
            if (a - b).abs() > worst {
                worst = (a - b).abs();
                at = i;
            }
        }
    }
    eprintln!(
        "worst difference {:.2e} of the peak at ({}, {})",
        worst / peak,
        x[at],
        z[at]
    );
    worst / peak
}

#[test]
fn fast_field_matches_the_direct_sum_for_a_marched_like_traction() {
    for n in [200, 1000] {
        let rel = compare(&partial_slip(n), 4000, n as u64);
        assert!(
            rel < 1e-11,
            "fast multipole stresses differ from the direct sum by {rel:e} of the peak ({n} cells)"
        );
    }
}

#[test]
fn fast_field_matches_the_direct_sum_with_jumps_and_refuses_the_same_surface_points() {
    // Piecewise-constant cells (a jump at every node) and linear elements with end jumps.
    let n = 400;
    let x: Vec<f64> = (0..=n).map(|i| -1.0 + 2.0 * i as f64 / n as f64).collect();
    let cells: Vec<f64> = (0..n).map(|i| ((i * 7919) % 13) as f64 - 4.0).collect();
    let shear: Vec<f64> = (0..n).map(|i| ((i * 104_729) % 11) as f64 - 5.0).collect();
    let constant = Traction::piecewise_constant(&x, &cells, &shear).unwrap();
    let values: Vec<f64> = x.iter().map(|x| 3.0 + x * x).collect();
    let slopes: Vec<f64> = x.iter().map(|x| x.sin()).collect();
    let linear = Traction::piecewise_linear(&x, &values, &slopes).unwrap();
    for (t, seed) in [(&constant, 7), (&linear, 8)] {
        let rel = compare(t, 3000, seed);
        assert!(
            rel < 1e-11,
            "fast multipole stresses of a traction with jumps differ from the direct sum by \
             {rel:e} of the peak"
        );
    }
    // A surface point on a jump is refused by both routes, naming the same point.
    let mut px: Vec<f64> = (0..2000)
        .map(|i| -1.5 + 3.0 * i as f64 / 1999.0 + 1e-7)
        .collect();
    let mut pz = vec![0.0; px.len()];
    px[1234] = x[37];
    pz[1234] = 0.0;
    let m = material();
    let fast = stress::field(&constant, 0.0, &m, &px, &pz).unwrap_err();
    let direct = stress::field_direct(&constant, 0.0, &m, &px, &pz).unwrap_err();
    assert_eq!(fast, direct, "both routes refuse the point on a jump");
    assert!(fast.to_string().contains("point 1234"), "{fast}");
    pz[1234] = 1e-12;
    assert!(stress::field(&constant, 0.0, &m, &px, &pz).is_ok());
}

#[test]
fn fast_field_matches_the_direct_sum_on_a_dense_grid_at_the_surface() {
    // 30,000 points within 2% of the half-width of the surface: boxes deep in the tree hold many
    // points, so every route of the fast method (translated expansions down to the finest boxes,
    // and the point-by-point route of sparsely filled boxes) is taken.
    let t = partial_slip(1000);
    let m = material();
    let (mut x, mut z) = (Vec::new(), Vec::new());
    for j in 0..30 {
        for i in 0..1000 {
            x.push(-1.2 + 2.4 * i as f64 / 999.0);
            z.push(0.02 * j as f64 / 29.0);
        }
    }
    let fast = stress::field(&t, 0.0, &m, &x, &z).unwrap();
    let direct = stress::field_direct(&t, 0.0, &m, &x, &z).unwrap();
    let peak = direct
        .sxx
        .iter()
        .chain(&direct.szz)
        .fold(0.0f64, |a, b| a.max(b.abs()));
    for i in 0..x.len() {
        for (a, b) in [
            (fast.sxx[i], direct.sxx[i]),
            (fast.szz[i], direct.szz[i]),
            (fast.sxz[i], direct.sxz[i]),
        ] {
            assert!(
                (a - b).abs() < 1e-11 * peak,
                "fast multipole stress {a} vs direct {b} at ({}, {}) near the surface",
                x[i],
                z[i]
            );
        }
    }
}

#[test]
fn fast_field_accepts_surface_points_on_every_node_of_a_continuous_traction() {
    // The traction is continuous (zero at the contact edges): the surface stress is finite at
    // every node, including ±a. Both routes must return it, and agree. A surface point on a node
    // where two of the fast route's near ranges meet, or on a contact edge where the linear part
    // ends at a rounding-level value, was once refused as if it were a jump.
    let t = partial_slip(1000);
    let m = material();
    let x: Vec<f64> = t.nodes().to_vec();
    let z = vec![0.0; x.len()];
    let fast = stress::field(&t, 0.0, &m, &x, &z).expect("fast route: finite on every node");
    let direct = stress::field_direct(&t, 0.0, &m, &x, &z).expect("direct: finite on every node");
    let peak = direct.sxx.iter().fold(0.0f64, |a, b| a.max(b.abs()));
    for (i, xi) in x.iter().enumerate() {
        assert!(
            (fast.sxx[i] - direct.sxx[i]).abs() < 1e-11 * peak,
            "surface sxx on node {i} (x = {xi}): fast {} vs direct {}",
            fast.sxx[i],
            direct.sxx[i]
        );
    }
}
