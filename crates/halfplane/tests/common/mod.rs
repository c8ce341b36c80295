//! Shared fixtures and an independent brute-force integrator for the tests.
#![allow(dead_code)]

use halfplane::{reference, Contact, Cycle, LoadPoint, Profile};

/// The reference material and friction ([`halfplane::reference`]).
pub fn contact(profile: Profile) -> Contact {
    reference::contact(profile)
}

pub fn point(normal: f64, shear: f64, bulk: f64) -> LoadPoint {
    LoadPoint::new("test", normal, shear, bulk).unwrap()
}

/// The reference cycle ([`halfplane::reference`]).
pub fn theory_cycle() -> Cycle {
    reference::cycle()
}

pub const RADIUS: f64 = reference::RADIUS;

/// Tabulated samples of a profile function g on [0, end] with `n` intervals.
pub fn sampled(g: impl Fn(f64) -> f64, end: f64, n: usize) -> (Vec<f64>, Vec<f64>) {
    let x: Vec<f64> = (0..=n).map(|i| end * i as f64 / n as f64).collect();
    let y = x.iter().map(|&x| g(x)).collect();
    (x, y)
}

/// Composite 10-point Gauss-Legendre over [a, b] with `panels` equal panels; independent of the
/// library's quadrature module. Callers put panel boundaries at kinks.
pub fn integrate(a: f64, b: f64, panels: usize, f: impl Fn(f64) -> f64) -> f64 {
    #[allow(clippy::excessive_precision)]
    const X: [f64; 5] = [
        0.148_874_338_981_631_2,
        0.433_395_394_129_247_2,
        0.679_409_568_299_024_4,
        0.865_063_366_688_984_5,
        0.973_906_528_517_171_7,
    ];
    #[allow(clippy::excessive_precision)]
    const W: [f64; 5] = [
        0.295_524_224_714_752_9,
        0.269_266_719_309_996_4,
        0.219_086_362_515_982_04,
        0.149_451_349_150_580_6,
        0.066_671_344_308_688_14,
    ];
    let h = (b - a) / panels as f64;
    let mut sum = 0.0;
    for i in 0..panels {
        let mid = a + (i as f64 + 0.5) * h;
        for (x, w) in X.iter().zip(W) {
            sum += w * (f(mid - 0.5 * h * x) + f(mid + 0.5 * h * x));
        }
    }
    0.5 * h * sum
}

pub fn rel(a: f64, b: f64) -> f64 {
    (a - b).abs() / b.abs()
}

/// Like [`integrate`] but with panels graded geometrically (ratio 1/2, 60 levels) towards both
/// ends, so endpoint singularities such as `(x - b) ln|x - b|` are resolved to ~1e-14.
pub fn integrate_graded(a: f64, b: f64, f: impl Fn(f64) -> f64) -> f64 {
    let mid = 0.5 * (a + b);
    let mut sum = 0.0;
    for (end, towards) in [(a, mid), (b, mid)] {
        let mut outer = towards;
        for _ in 0..60 {
            let inner = end + 0.5 * (outer - end);
            sum += if end < towards {
                integrate(inner, outer, 1, &f)
            } else {
                integrate(outer, inner, 1, &f)
            };
            outer = inner;
        }
    }
    sum
}

/// A flat-rounded table with the kink at b stated (b and R as the analytic profile).
pub fn flat_rounded_table(b: f64, r: f64) -> Profile {
    let (x, g) = sampled(
        |x: f64| {
            if x <= b {
                0.0
            } else {
                (x - b).powi(2) / (2.0 * r)
            }
        },
        2.0,
        40,
    );
    Profile::tabulated(x, g, vec![b]).unwrap()
}

/// P pressed to 1000 N/mm in ten increments, then each `[Q, bulk stress]` target reached in
/// `steps` increments, linearly: a history at constant P for the located boundaries' studies.
pub fn ramps(targets: &[[f64; 2]], steps: usize) -> Vec<[f64; 3]> {
    let mut rows: Vec<[f64; 3]> = (1..=10).map(|i| [100.0 * i as f64, 0.0, 0.0]).collect();
    let mut from = [0.0, 0.0];
    for to in targets {
        rows.extend((1..=steps).map(|i| {
            let t = i as f64 / steps as f64;
            [
                1000.0,
                from[0] + t * (to[0] - from[0]),
                from[1] + t * (to[1] - from[1]),
            ]
        }));
        from = *to;
    }
    rows
}

/// Q to 280, then 20 loops of falling amplitude with the bulk stress stepped between -30, 0 and
/// 30 (off Mindlin's line), then out to +-290: `[Q, bulk stress]` targets for [`ramps`].
pub fn nested_loops_bulk_stepped() -> Vec<[f64; 2]> {
    std::iter::once([280.0, 0.0])
        .chain((0..20).map(|k| {
            let a = 280.0 * (1.0 - (k as f64 + 1.0) / 22.0);
            [
                if k % 2 == 0 { -a } else { a },
                30.0 * ((k % 3) as f64 - 1.0),
            ]
        }))
        .chain([[290.0, 10.0], [-290.0, -10.0]])
        .collect()
}

/// A square in the plane of Q and bulk stress, (300, 100) -> (300, -100) -> (-300, -100) ->
/// (-300, 100), `cycles` times: `[Q, bulk stress]` targets for [`ramps`].
pub fn square_path(cycles: usize) -> Vec<[f64; 2]> {
    (0..cycles)
        .flat_map(|_| {
            [
                [300.0, 100.0],
                [300.0, -100.0],
                [-300.0, -100.0],
                [-300.0, 100.0],
            ]
        })
        .collect()
}
