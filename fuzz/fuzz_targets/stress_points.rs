//! `stress::field` at points anywhere in the accepted range (|x|, z up to 1e30, on the surface, on
//! nodes and next to the edges, and invalid ones), under a contact traction of 3-80 nodes with
//! fuzzed values. Checks (issue 17): an Ok field is finite; each point alone gives its value among
//! 100 other points to 1e-12 of the traction's largest value (the route depends on the traction
//! only, `docs/stress.md`); points ten half-spans away or more are within the dipole bound of the
//! Flamant field of the traction's resultants P and Q (`sigma -> bulk`, 0, 0 far away); and an
//! invalid point is refused alone and among others.
#![no_main]

use arbitrary::Arbitrary;
use halfplane::stress::closed_form::{flamant_normal, flamant_tangential};
use halfplane::stress::{self, Evaluator, Traction};
use halfplane::Material;
use halfplane_fuzz::Num;
use libfuzzer_sys::fuzz_target;

#[derive(Debug, Arbitrary)]
struct Input {
    /// Centre and half-span of the contact (mapped to |c| <= 1e6, 1e-3 <= h <= 1e3).
    centre: i16,
    half_span: u8,
    /// Inner node values: pressure (0..1e4) and shear (-1e4..1e4) per node, 1 to 78 nodes.
    values: Vec<(u16, i16)>,
    bulk: i16,
    points: Vec<Point>,
}

/// A point: a decade and a mantissa for each coordinate, or a special place.
#[derive(Debug, Arbitrary)]
enum Point {
    Anywhere { x: (i8, u16, bool), z: (i8, u16) },
    OnNode(u8),
    NearEdge { right: bool, offset: i8, depth: i8 },
    Raw(Num, Num),
}

fn decade(e: i8, m: u16) -> f64 {
    (1.0 + 9.0 * f64::from(m) / 65535.0) * 10f64.powi(i32::from(e % 31))
}

fn point(p: &Point, nodes: &[f64], c: f64, h: f64) -> (f64, f64) {
    match *p {
        Point::Anywhere { x, z } => {
            let px = decade(x.0, x.1);
            (if x.2 { -px } else { px }, decade(z.0, z.1) - 1e-30)
        }
        Point::OnNode(k) => (nodes[usize::from(k) % nodes.len()], 0.0),
        Point::NearEdge {
            right,
            offset,
            depth,
        } => {
            let edge = if right { c + h } else { c - h };
            let d = |e: i8| h * 10f64.powi(-i32::from(e.unsigned_abs() % 17));
            (edge + offset.signum() as f64 * d(offset), d(depth))
        }
        Point::Raw(x, z) => (x.0, z.0),
    }
}

fuzz_target!(|input: Input| {
    let c = f64::from(input.centre) * 30.0;
    let h = 10f64.powf(-3.0 + 6.0 * f64::from(input.half_span) / 255.0);
    let inner = &input.values[..input.values.len().min(78)];
    if inner.is_empty() {
        return;
    }
    let n = inner.len() + 2;
    let nodes: Vec<f64> = (0..n)
        .map(|i| c - h + 2.0 * h * i as f64 / (n - 1) as f64)
        .collect();
    let (mut p, mut q) = (vec![0.0; n], vec![0.0; n]);
    for (i, &(pv, qv)) in inner.iter().enumerate() {
        p[i + 1] = f64::from(pv) * 1e4 / 65535.0;
        q[i + 1] = f64::from(qv) * 1e4 / 32768.0;
    }
    let traction = Traction::contact(&nodes, &p, &q).expect("a valid contact traction");
    let material = Material::new(200_000.0, 0.3).unwrap();
    let bulk = f64::from(input.bulk) / 100.0;
    // Resultants: linear inner elements (trapezoid, exact) and v sqrt(t/h) over the edge
    // intervals (integral 2 v h/3); `total` bounds the integral of |p| + |q| (|linear| is convex).
    // Each element's own length: far from the origin the nodes' rounding makes them differ.
    let (mut resultant_p, mut resultant_q, mut total) = (0.0, 0.0, 0.0);
    for k in 0..n - 1 {
        let step = nodes[k + 1] - nodes[k];
        let w = if k == 0 || k == n - 2 { 2.0 / 3.0 } else { 0.5 };
        let (pa, pb, qa, qb) = (p[k], p[k + 1], q[k], q[k + 1]);
        resultant_p += w * step * (pa + pb);
        resultant_q += w * step * (qa + qb);
        total += w * step * (pa.abs() + pb.abs() + qa.abs() + qb.abs());
    }
    let largest = p.iter().chain(&q).fold(0.0f64, |m, v| m.max(v.abs()));

    let points: Vec<(f64, f64)> = input
        .points
        .iter()
        .take(8)
        .map(|pt| point(pt, &nodes, c, h))
        .collect();
    // The fuzzed points among 100 fixed ones around the contact, so that the tree's boxes hold
    // more points than in the single-point evaluations.
    let (mut x, mut z): (Vec<f64>, Vec<f64>) = points.iter().copied().unzip();
    for i in 0..100 {
        x.push(c + h * (-1.5 + 3.0 * (i % 10) as f64 / 9.0));
        z.push(h * (i / 10) as f64 / 9.0);
    }
    let evaluator = Evaluator::new(&traction, bulk, &material).unwrap();
    let among = stress::field(&traction, bulk, &material, &x, &z);
    let valid: Vec<bool> = points
        .iter()
        .map(|&(px, pz)| stress::check_points(&[px], &[pz]).is_ok())
        .collect();
    if valid.iter().any(|v| !v) {
        assert!(
            among.is_err(),
            "an invalid point accepted among others: {points:?}"
        );
    }
    for (i, &(px, pz)) in points.iter().enumerate() {
        let alone = evaluator.field(&[px], &[pz]);
        if !valid[i] {
            assert!(alone.is_err(), "invalid point ({px}, {pz}) accepted");
            continue;
        }
        let Ok(alone) = alone else {
            // A contact traction is continuous: no surface point is refused.
            panic!("valid point ({px}, {pz}) refused: {alone:?}");
        };
        let s = alone.at(0);
        for v in [s.sxx, s.szz, s.syy, s.sxz] {
            assert!(v.is_finite(), "({px}, {pz}): {s:?}");
        }
        if let Ok(among) = &among {
            let t = among.at(i);
            let tol = 1e-12 * largest + 1e-15 * bulk.abs();
            for (a, b) in [
                (s.sxx, t.sxx),
                (s.szz, t.szz),
                (s.syy, t.syy),
                (s.sxz, t.sxz),
            ] {
                assert!(
                    (a - b).abs() <= tol,
                    "({px}, {pz}): {s:?} alone, {t:?} among {} points",
                    x.len()
                );
            }
        }
        // Far away: the Flamant field of the resultants at the centre, within the dipole term
        // (|F - m0/(zeta - c)| <= 2 total h/r^2 for r >= 2h, with z F' of the same order).
        let r = (px - c).hypot(pz);
        if r >= 10.0 * h {
            let (fx, fz) = (px - c, pz);
            let (nf, tf) = (flamant_normal(fx, fz), flamant_tangential(fx, fz));
            let bound = 10.0 * total * h / (r * r) + 1e-13 * total / r + 1e-15 * bulk.abs();
            for (k, got) in [s.sxx - bulk, s.szz, s.sxz].into_iter().enumerate() {
                let want = resultant_p * nf[k] + resultant_q * tf[k];
                assert!(
                    (got - want).abs() <= bound,
                    "({px}, {pz}) component {k}: {got} against the far-field limit {want} \
                     (bound {bound:e})"
                );
            }
        }
    }
});
