//! Subsurface stresses (`halfplane::stress`) against independent references: numerical
//! integration of the Flamant line loads, McEwen's closed forms (Hertz, full sliding, Nowell-Hills
//! partial slip with offset from a marched history), surface identities and mirror symmetry.
//!
//! Tolerance tiers, relative to the traction scale: 1e-10 where both sides are exact (closed form
//! against 10-point Gauss-Legendre on 400 panels, which resolves kernels varying on the scale z
//! to ~1e-13); 1e-12 for identities of the representation; the discretisation error of a sampled
//! or marched traction where that is what is measured (stated at each test).

mod common;
use common::integrate;
use halfplane::history::History;
use halfplane::march::{march, MarchOptions};
use halfplane::stress::closed_form::{
    flamant_normal, flamant_tangential, mcewen_pressure, mcewen_shear, NowellHills,
};
use halfplane::stress::{self, Traction};
use halfplane::{reference, Error, Material};

fn material() -> Material {
    reference::material()
}

/// Stress components `[sxx, szz, sxz]` of `t` at (x, z), no bulk tension.
fn in_plane(t: &Traction, x: f64, z: f64) -> [f64; 3] {
    let s = stress::at(t, 0.0, &material(), x, z).unwrap();
    [s.sxx, s.szz, s.sxz]
}

/// `integral rho(xi) K(x - xi, z) dxi` over [a, b] by composite Gauss-Legendre.
fn flamant_integral(
    a: f64,
    b: f64,
    p: impl Fn(f64) -> f64,
    q: impl Fn(f64) -> f64,
    x: f64,
    z: f64,
) -> [f64; 3] {
    let mut out = [0.0; 3];
    for (c, o) in out.iter_mut().enumerate() {
        *o = integrate(a, b, 400, |xi| {
            p(xi) * flamant_normal(x - xi, z)[c] + q(xi) * flamant_tangential(x - xi, z)[c]
        });
    }
    out
}

const POINTS: [(f64, f64); 8] = [
    (0.0, 0.05),
    (0.3, 0.1),
    (-0.7, 0.2),
    (1.0, 0.08),
    (-1.2, 0.5),
    (2.5, 1.0),
    (0.2, 3.0),
    (-0.5, 0.03),
];

#[test]
fn uniform_and_linear_strips_match_integrated_flamant_line_loads() {
    // Uniform strip (piecewise constant, one cell) and a trapezoid with jumps at both ends.
    type Profile = Box<dyn Fn(f64) -> f64>;
    let cases: [(Traction, Profile, Profile); 2] = [
        (
            Traction::piecewise_constant(&[-0.4, 0.6], &[3.0], &[-1.5]).unwrap(),
            Box::new(|_| 3.0),
            Box::new(|_| -1.5),
        ),
        (
            Traction::piecewise_linear(&[-0.4, 0.6], &[1.0, 4.0], &[2.0, -1.0]).unwrap(),
            Box::new(|xi| 1.0 + 3.0 * (xi + 0.4)),
            Box::new(|xi| 2.0 - 3.0 * (xi + 0.4)),
        ),
    ];
    for (t, p, q) in &cases {
        for &(x, z) in &POINTS {
            let exact = flamant_integral(-0.4, 0.6, p, q, x, z);
            let got = in_plane(t, x, z);
            for c in 0..3 {
                assert!(
                    (got[c] - exact[c]).abs() < 1e-10 * 4.0,
                    "strip closed form differs from integrated Flamant line loads at ({x}, {z}), \
                     component {c}: {} vs {}",
                    got[c],
                    exact[c]
                );
            }
        }
    }
}

#[test]
fn piecewise_linear_tractions_match_integrated_flamant_line_loads_element_by_element() {
    let x = [-1.0, -0.6, -0.1, 0.2, 0.9];
    let p = [0.0, 2.0, 3.0, 2.5, 0.0];
    let q = [0.0, -1.0, 0.5, 1.5, 0.0];
    let t = Traction::piecewise_linear(&x, &p, &q).unwrap();
    for &(px, pz) in &POINTS {
        let mut exact = [0.0; 3];
        for e in 0..4 {
            let lin = |v: [f64; 5]| {
                move |xi: f64| v[e] + (v[e + 1] - v[e]) * (xi - x[e]) / (x[e + 1] - x[e])
            };
            let part = flamant_integral(x[e], x[e + 1], lin(p), lin(q), px, pz);
            for c in 0..3 {
                exact[c] += part[c];
            }
        }
        let got = in_plane(&t, px, pz);
        for c in 0..3 {
            assert!(
                (got[c] - exact[c]).abs() < 1e-10 * 3.0,
                "piecewise-linear closed form differs from integrated line loads at ({px}, {pz}), \
                 component {c}: {} vs {}",
                got[c],
                exact[c]
            );
        }
    }
}

#[test]
fn mcewen_fields_match_integrated_flamant_line_loads() {
    // The references themselves, against direct quadrature of the Hertzian tractions
    // (substitution xi = a sin t removes the square-root ends).
    let (p0, q0, a) = (2.0, 0.7, 1.0);
    for &(x, z) in &POINTS {
        let mut exact = [0.0; 3];
        for (c, e) in exact.iter_mut().enumerate() {
            *e = integrate(
                -0.5 * std::f64::consts::PI,
                0.5 * std::f64::consts::PI,
                400,
                |t| {
                    let xi = a * t.sin();
                    let w = a * t.cos() * t.cos(); // sqrt(1 - xi^2/a^2) dxi/dt
                    w * (p0 * flamant_normal(x - xi, z)[c] + q0 * flamant_tangential(x - xi, z)[c])
                },
            );
        }
        let p = mcewen_pressure(p0, a, x, z);
        let q = mcewen_shear(q0, a, x, z);
        for c in 0..3 {
            assert!(
                (p[c] + q[c] - exact[c]).abs() < 1e-10,
                "McEwen's field differs from integrated line loads at ({x}, {z}), component {c}"
            );
        }
    }
    // Published identities: szz on the axis, surface sxx inside the contact.
    for z in [0.1, 0.5, 2.0] {
        let s = mcewen_pressure(p0, a, 0.0, z);
        assert!((s[1] + p0 * a / (a * a + z * z).sqrt()).abs() < 1e-13);
    }
    for x in [-0.9f64, -0.3, 0.0, 0.5] {
        let p = p0 * (1.0 - x * x).sqrt();
        assert!((mcewen_pressure(p0, a, x, 0.0)[0] + p).abs() < 1e-13);
        assert!((mcewen_shear(q0, a, x, 0.0)[0] + 2.0 * q0 * x / a).abs() < 1e-13);
    }
}

/// Hertzian `p0 sqrt(1 - x^2)` and `f` times it, sampled on `n + 1` nodes across [-1, 1],
/// square-root shaped next to the edges ([`Traction::contact`]).
fn sampled_hertz(n: usize, f: f64) -> Traction {
    let x: Vec<f64> = (0..=n).map(|i| -1.0 + 2.0 * i as f64 / n as f64).collect();
    let p: Vec<f64> = x.iter().map(|x| (1.0 - x * x).max(0.0).sqrt()).collect();
    let q: Vec<f64> = p.iter().map(|p| f * p).collect();
    Traction::contact(&x, &p, &q).unwrap()
}

#[test]
fn square_root_edge_intervals_match_integrated_flamant_line_loads() {
    // Nodes -1, 0.2, 1 with values (0, 2, 0) and (0, -1, 0): tractions v sqrt(t/h) in both
    // intervals (t from the nearer edge). Quadrature in u = sqrt(t) removes the square roots.
    let t = Traction::contact(&[-1.0, 0.2, 1.0], &[0.0, 2.0, 0.0], &[0.0, -1.0, 0.0]).unwrap();
    for &(x, z) in &POINTS {
        let mut exact = [0.0; 3];
        for (c, e) in exact.iter_mut().enumerate() {
            let piece = |edge: f64, h: f64, u: f64| {
                // xi = edge + sign(h) u^2 h... with t = u^2 |h|, v sqrt(t/|h|) = v u.
                let xi = edge + h * u * u;
                let jac = 2.0 * h.abs() * u;
                jac * u * (2.0 * flamant_normal(x - xi, z)[c] - flamant_tangential(x - xi, z)[c])
            };
            *e = integrate(0.0, 1.0, 400, |u| piece(-1.0, 1.2, u) + piece(1.0, -0.8, u));
        }
        let got = in_plane(&t, x, z);
        for c in 0..3 {
            assert!(
                (got[c] - exact[c]).abs() < 1e-10 * 2.0,
                "square-root edge closed form differs from integrated line loads at ({x}, {z}), \
                 component {c}: {} vs {}",
                got[c],
                exact[c]
            );
        }
    }
    // Its values: v sqrt(t/h) inside, zero at the edges.
    let [p, q] = t.at(-1.0 + 0.3);
    assert!(
        (p - 2.0 * (0.3f64 / 1.2).sqrt()).abs() < 1e-14
            && (q + (0.3f64 / 1.2).sqrt()).abs() < 1e-14
    );
}

#[test]
fn sampled_hertz_full_sliding_converges_to_mcewen() {
    // Full sliding, q = f p, sampled at nodes with square-root edge intervals. Below the surface
    // the error falls like h^1.5 or faster (measured 1.2e-4 -> 1.8e-5 p0, 400 -> 1600 nodes, the
    // worst point 0.08 below the edge). On the surface at the trailing edge it falls like h^0.5
    // (5.7e-4 -> 2.6e-4 p0): linear interpolation of sqrt(t) in the intervals after the first.
    let f = 0.6;
    let error = |n: usize, points: &[(f64, f64)]| {
        let t = sampled_hertz(n, f);
        points
            .iter()
            .map(|&(x, z)| {
                let got = in_plane(&t, x, z);
                let p = mcewen_pressure(1.0, 1.0, x, z);
                let q = mcewen_shear(f, 1.0, x, z);
                (0..3)
                    .map(|c| (got[c] - p[c] - q[c]).abs())
                    .fold(0.0, f64::max)
            })
            .fold(0.0, f64::max)
    };
    let below = (error(400, &POINTS), error(1600, &POINTS));
    assert!(
        below.1 < 3e-5,
        "sampled Hertz sliding off McEwen by {} p0 below the surface",
        below.1
    );
    assert!(
        below.0 / below.1 > 5.0,
        "no h^1.5 convergence below the surface: {below:?}"
    );
    let surface = [(-1.0, 0.0), (-0.5, 0.0), (0.7, 0.0), (1.5, 0.0)];
    let on = (error(400, &surface), error(1600, &surface));
    assert!(
        on.1 < 4e-4,
        "sampled Hertz sliding off McEwen by {} p0 on the surface",
        on.1
    );
    assert!(
        on.0 / on.1 > 1.8,
        "no h^0.5 convergence at the trailing edge: {on:?}"
    );
}

#[test]
fn surface_sxx_from_pressure_alone_is_minus_the_pressure() {
    let t = sampled_hertz(50, 0.0);
    for x in [-0.99, -0.5123, 0.0, 0.31, 0.77] {
        let s = stress::at(&t, 0.0, &material(), x, 0.0).unwrap();
        let [p, _] = t.at(x);
        assert!(
            (s.sxx + p).abs() < 1e-12 && (s.szz + p).abs() < 1e-12 && s.sxz.abs() < 1e-12,
            "surface stresses under pressure alone at x = {x}: {s:?}, p = {p}"
        );
    }
    // Outside the loaded span, the surface sxx and szz from pressure alone vanish.
    for x in [-1.5, 1.2] {
        let s = stress::at(&t, 0.0, &material(), x, 0.0).unwrap();
        assert!(s.szz.abs() < 1e-12 && s.sxx.abs() < 1e-12);
    }
}

#[test]
fn plane_strain_and_bulk_tension_enter_as_stated() {
    let t = sampled_hertz(100, 0.3);
    let nu = material().poisson_ratio();
    let plain = stress::at(&t, 0.0, &material(), 0.2, 0.3).unwrap();
    let tensed = stress::at(&t, 50.0, &material(), 0.2, 0.3).unwrap();
    assert_eq!(tensed.sxx, plain.sxx + 50.0);
    assert_eq!((tensed.szz, tensed.sxz), (plain.szz, plain.sxz));
    assert!((tensed.syy - nu * (tensed.sxx + tensed.szz)).abs() < 1e-14);
}

#[test]
fn mirror_symmetry_x_to_minus_x_with_shear_reversed() {
    // p(x) -> p(-x), q(x) -> -q(-x) mirrors the field: sxx, szz even, sxz odd.
    let x = [-0.8, -0.3, 0.1, 0.5, 0.9];
    let p = [0.0, 1.0, 2.0, 1.5, 0.0];
    let q = [0.0, 0.4, -0.2, 0.8, 0.0];
    let mx: Vec<f64> = x.iter().rev().map(|v| -v).collect();
    let mp: Vec<f64> = p.iter().rev().copied().collect();
    let mq: Vec<f64> = q.iter().rev().map(|v| -v).collect();
    let t = Traction::piecewise_linear(&x, &p, &q).unwrap();
    let m = Traction::piecewise_linear(&mx, &mp, &mq).unwrap();
    for &(px, pz) in POINTS.iter().chain(&[(0.37, 0.0), (-0.3, 0.0)]) {
        let a = in_plane(&t, px, pz);
        let b = in_plane(&m, -px, pz);
        assert!(
            (a[0] - b[0]).abs() < 1e-13
                && (a[1] - b[1]).abs() < 1e-13
                && (a[2] + b[2]).abs() < 1e-13,
            "mirror image differs at ({px}, {pz}): {a:?} vs {b:?}"
        );
    }
}

/// Marches the reference Hertz contact: P to `normal` in 20 steps, then Q and sigma together in
/// `steps`; returns the traction of the last increment and its half-width.
fn nowell_hills_march(cells: usize, normal: f64, shear: f64, bulk: f64) -> (Traction, f64) {
    let mut rows: Vec<[f64; 3]> = (1..=20)
        .map(|i| [normal * i as f64 / 20.0, 0.0, 0.0])
        .collect();
    rows.extend((1..=40).map(|i| {
        let t = i as f64 / 40.0;
        [normal, shear * t, bulk * t]
    }));
    let history = History::from_rows(&rows).unwrap();
    let mut last = None;
    march(
        &reference::hertz(),
        &history,
        &MarchOptions::default().with_cells(cells).unwrap(),
        |r, f| {
            if r.step == rows.len() {
                last = Some((Traction::from_march(r.half_width, f), r.half_width));
            }
        },
    )
    .unwrap();
    let (t, a) = last.unwrap();
    (t.unwrap(), a)
}

#[test]
fn marched_nowell_hills_partial_slip_matches_mcewen_superposition_with_offset() {
    // P = 1000 N/mm, then Q = 300 N/mm (Q/fP = 0.5) and sigma = 100 MPa together: stick zone
    // of half-width c = 0.707 a centred at e = 0.05 a.
    let (normal, shear, bulk) = (1000.0, 300.0, 100.0);
    let (t, a) = nowell_hills_march(1600, normal, shear, bulk);
    let nh = NowellHills::hertz(a, reference::FRICTION, normal, shear, bulk);
    let p0 = nh.peak_pressure;
    let mut worst: f64 = 0.0;
    for i in 0..=40 {
        for z in [0.05, 0.2, 0.5, 1.0] {
            let x = -1.5 * a + 3.0 * a * i as f64 / 40.0;
            let s = stress::at(&t, bulk, &material(), x, z * a).unwrap();
            let e = nh.stress(x, z * a);
            let d = [s.sxx - e[0], s.szz - e[1], s.sxz - e[2]];
            worst = d.iter().fold(worst, |m, v| m.max(v.abs() / p0));
        }
    }
    // Measured 3.6e-5 p0 at 1600 cells (the march's traction error near the stick boundaries).
    assert!(
        worst < 1e-4,
        "marched partial slip off the Nowell-Hills field by {worst} p0"
    );
    // The surface peak at the trailing edge, against the closed form.
    let peak = stress::at(&t, bulk, &material(), -a, 0.0).unwrap().sxx;
    let exact = nh.trailing_edge_peak();
    let mc = nh.stress(-a, 0.0)[0];
    assert!(
        (mc - exact).abs() < 1e-9 * p0,
        "McEwen superposition {mc} vs peak formula {exact}"
    );
    // Measured 6.3e-4 p0 at 1600 cells: the O(h^0.5) edge error of the sampled traction (see
    // sampled_hertz_full_sliding_converges_to_mcewen) plus the march's own.
    assert!(
        (peak - exact).abs() < 1.5e-3 * p0,
        "trailing-edge sxx {peak} vs 2 f p0 [sqrt((1 + e/a)^2 - (c/a)^2) - e/a] + sigma = {exact}"
    );
}

#[test]
fn invalid_points_are_refused_with_the_point_named() {
    let t = sampled_hertz(10, 0.2);
    let m = material();
    match stress::field(&t, 0.0, &m, &[0.0, 0.1], &[0.1, -0.2]) {
        Err(Error::InvalidInput { field, value, .. }) => {
            assert_eq!((field.as_str(), value), ("point 1: z", -0.2))
        }
        other => panic!("{other:?}"),
    }
    assert!(matches!(
        stress::field(&t, 0.0, &m, &[0.0], &[f64::NAN]),
        Err(Error::InvalidInput { .. })
    ));
    match stress::field(&t, 0.0, &m, &[0.0, 1.0], &[0.1]) {
        Err(Error::LengthMismatch {
            field,
            length,
            expected,
            ..
        }) => assert_eq!((field.as_str(), length, expected), ("z", 1, 2)),
        other => panic!("{other:?}"),
    }
    // A surface point on a traction jump has an infinite stress: refused, never NaN.
    let strip = Traction::piecewise_constant(&[-1.0, 1.0], &[1.0], &[1.0]).unwrap();
    assert!(stress::at(&strip, 0.0, &m, 1.0, 0.0).is_err());
    assert!(stress::at(&strip, 0.0, &m, 1.0, 1e-9)
        .unwrap()
        .sxx
        .is_finite());
    // Tractions: nodes must increase, values must be finite and one per node.
    assert!(Traction::piecewise_linear(&[0.0, 0.0], &[1.0, 1.0], &[0.0, 0.0]).is_err());
    assert!(Traction::piecewise_linear(&[0.0, 1.0], &[1.0], &[0.0, 0.0]).is_err());
    assert!(Traction::piecewise_linear(&[0.0, 1.0], &[1.0, f64::INFINITY], &[0.0, 0.0]).is_err());
}
