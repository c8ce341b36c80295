//! Fatigue parameters (`halfplane::fatigue`): the critical-plane search against a hand-worked
//! uniaxial case, the Modified Wohler Curve Method against hand-worked uniaxial, torsional and
//! combined cases, the life curves against themselves, mirror symmetry of every parameter, and the
//! marched steady cycle against the Nowell-Hills closed form at the cycle's extremes.

use halfplane::fatigue::{self, FatigueConstants, FatigueGrid, Parameter};
use halfplane::history::{History, Ramp};
use halfplane::march::MarchOptions;
use halfplane::stress::closed_form::{mcewen_pressure, NowellHills};
use halfplane::stress::{self, Stress};
use halfplane::{reference, LoadPoint, Material};

fn constants() -> FatigueConstants {
    FatigueConstants::default()
        .with_fatigue_strength(1800.0)
        .and_then(|c| c.with_fatigue_strength_exponent(-0.1))
        .and_then(|c| c.with_fatigue_ductility(0.5))
        .and_then(|c| c.with_fatigue_ductility_exponent(-0.6))
        .and_then(|c| c.with_shear_fatigue_strength(1000.0))
        .and_then(|c| c.with_shear_fatigue_ductility(0.8))
        .and_then(|c| c.with_fatemi_socie_k(0.5))
        .and_then(|c| c.with_findley_k(0.25))
        .and_then(|c| c.with_crossland_alpha(0.4))
        .and_then(|c| c.with_yield_stress(900.0))
        .and_then(|c| c.with_fatigue_limits(400.0, 250.0))
        .unwrap()
}

/// A history of `n` states over one period, `state(phase)` with the phase in radians.
fn over_a_period(n: usize, state: impl Fn(f64) -> Stress) -> Vec<Stress> {
    (0..n)
        .map(|k| state(2.0 * std::f64::consts::PI * k as f64 / n as f64))
        .collect()
}

#[test]
fn mwcm_matches_the_hand_worked_uniaxial_torsional_and_combined_cases() {
    // sigma_-1 = 400, tau_-1 = 250: kappa = tau_-1 - sigma_-1/2 = 50, cap kappa rho_lim = 125.
    let (axial, torsional) = (400.0, 250.0);
    let m = Material::new(200_000.0, 0.3).unwrap();
    let c = constants();
    let mwcm = |h: &[Stress]| fatigue::critical_planes(h, &m, &c).mwcm.unwrap();
    let close = |got: f64, want: f64, what: &str| {
        assert!(
            (got - want).abs() < 1e-9 * want.abs(),
            "{what}: MWCM {got} vs hand-worked {want}"
        );
    };
    // Fully reversed uniaxial stress at the axial limit: planes at 45 and 135 degrees with
    // tau_a = sigma_n,max = S/2, rho = 1, so tau_a + kappa = S/2 + tau_-1 - S/2 = tau_-1: the
    // method is calibrated to give its limit here.
    let uniaxial = |mean: f64, amplitude: f64| {
        over_a_period(72, |t| Stress {
            sxx: mean + amplitude * t.sin(),
            ..Stress::default()
        })
    };
    let p = mwcm(&uniaxial(0.0, axial));
    close(p.value, torsional, "uniaxial at sigma_-1");
    let plane = (p.angle - 45.0).abs().min((p.angle - 135.0).abs());
    assert!(plane < 1e-6, "uniaxial MWCM plane {}", p.angle);
    assert_eq!(p.index, 18, "the normal stress peaks at a quarter period");
    // Fully reversed shear at the torsional limit: planes at 0 and 90 degrees, tau_a = T, no
    // normal stress on them (rho = 0): tau_-1.
    let p = mwcm(&over_a_period(72, |t| Stress {
        sxz: torsional * t.sin(),
        ..Stress::default()
    }));
    close(p.value, torsional, "torsion at tau_-1");
    assert!(p.angle.min(180.0 - p.angle).min((p.angle - 90.0).abs()) < 1e-6);
    // A tensile mean: tau_a = Sa/2, sigma_n,max = (Sm + Sa)/2, rho = (Sm + Sa)/Sa.
    close(
        mwcm(&uniaxial(100.0, 300.0)).value,
        150.0 + 50.0 * 400.0 / 300.0,
        "uniaxial with mean 100",
    );
    // A large mean: rho = 3 > rho_lim = 250/100 = 2.5, so kappa rho is capped at tau_-1/2.
    close(
        mwcm(&uniaxial(600.0, 300.0)).value,
        150.0 + 125.0,
        "uniaxial with mean 600 (rho capped)",
    );
    // In-phase sxx = S sin, sxz = T sin: the largest shear amplitude is Mohr's radius
    // R = sqrt(S^2/4 + T^2), on a plane whose normal stress is the circle's centre S/2 sin, so
    // tau_a + kappa rho = R + kappa (S/2)/R. The plane is off the one-degree samples.
    let (s, t): (f64, f64) = (300.0, 120.0);
    let r: f64 = (0.25 * s * s + t * t).sqrt();
    let p = mwcm(&over_a_period(72, |w| Stress {
        sxx: s * w.sin(),
        sxz: t * w.sin(),
        ..Stress::default()
    }));
    close(
        p.value,
        r + 50.0 * 0.5 * s / r,
        "in-phase tension and shear",
    );
    // That plane is 45 degrees from the principal planes, tan(2 t_p) = 2T/S.
    let principal = 0.5 * (2.0 * t).atan2(s).to_degrees();
    let d = (p.angle - principal - 45.0).rem_euclid(90.0);
    assert!(
        d.min(90.0 - d) < 1e-6,
        "plane {} vs principal {principal} + 45",
        p.angle
    );
    // No constants, no MWCM; and the pair is validated together.
    let without = FatigueConstants::default();
    assert!(fatigue::critical_planes(&uniaxial(0.0, 1.0), &m, &without)
        .mwcm
        .is_none());
    for (a, t, field) in [
        (400.0, 190.0, "fatigue.torsional_fatigue_limit"),
        (400.0, 410.0, "fatigue.torsional_fatigue_limit"),
        (-400.0, 250.0, "fatigue.axial_fatigue_limit"),
        (400.0, f64::NAN, "fatigue.torsional_fatigue_limit"),
    ] {
        let e = FatigueConstants::default().with_fatigue_limits(a, t);
        assert!(
            matches!(&e, Err(halfplane::Error::InvalidInput { field: f, .. }) if f == field),
            "({a}, {t}): {e:?}"
        );
    }
}

#[test]
fn uniaxial_reversed_stress_gives_the_hand_worked_critical_planes() {
    // sxx = S sin(wt), everything else zero (syy = 0 given explicitly: a uniaxial state).
    let s: f64 = 300.0;
    let history: Vec<Stress> = (0..72)
        .map(|k| Stress {
            sxx: s * (k as f64 * 5f64.to_radians()).sin(),
            ..Stress::default()
        })
        .collect();
    let m = Material::new(200_000.0, 0.3).unwrap();
    let c = constants();
    let p = fatigue::critical_planes(&history, &m, &c);
    // SWT: on the plane normal to x, S * (2S/E)/2 = S^2/E.
    let swt = s * s / 200_000.0;
    assert!(
        (p.swt.value - swt).abs() < 1e-12 * swt,
        "SWT {} vs S^2/E = {swt}",
        p.swt.value
    );
    assert!(
        p.swt.angle.min(180.0 - p.swt.angle) < 1e-9,
        "SWT plane {}",
        p.swt.angle
    );
    assert_eq!(
        p.swt.index, 18,
        "the peak of sxx is at 90 degrees of the cycle"
    );
    // Findley: max over t of (S/2)|sin 2t| + k S cos^2 t = (S/2)(sqrt(1 + k^2) + k), at
    // tan 2t = 1/k. Sampling at 1 degree and refining to 0.05 leaves (0.025 deg)^2: < 1e-6.
    let k: f64 = 0.25;
    let findley = p.findley.unwrap();
    let exact = 0.5 * s * ((1.0 + k * k).sqrt() + k);
    assert!(
        (findley.value - exact).abs() < 1e-6 * exact,
        "Findley {} vs {exact}",
        findley.value
    );
    let angle = 0.5 * (1.0 / k).atan().to_degrees();
    let found = findley.angle.min(180.0 - findley.angle);
    assert!(
        (found - angle).abs() < 0.06,
        "Findley plane {found} vs {angle}"
    );
    // Fatemi-Socie: brute force over 0.001 degree of (tau_a/G)(1 + k S cos^2 t/sy).
    let g = 200_000.0 / 2.6;
    let brute = (0..180_000)
        .map(|i| {
            let t = (i as f64 * 0.001).to_radians();
            0.5 * s * (2.0 * t).sin().abs() / g * (1.0 + 0.5 * s * t.cos().powi(2) / 900.0)
        })
        .fold(0.0, f64::max);
    let fs = p.fatemi_socie_max_plane.unwrap().value;
    assert!(
        (fs - brute).abs() < 1e-6 * brute,
        "max-plane Fatemi-Socie {fs} vs {brute}"
    );
    // Fatemi-Socie as defined: on the plane of the largest shear range (45 or 135 degrees, both
    // with sigma_n,max = S/2), (S/2)/G (1 + k (S/2)/sy); the plane is found exactly.
    let literal = p.fatemi_socie.unwrap();
    let exact = 0.5 * s / g * (1.0 + 0.5 * 0.5 * s / 900.0);
    assert!(
        (literal.value - exact).abs() < 1e-12 * exact,
        "Fatemi-Socie {} vs {exact}",
        literal.value
    );
    assert!(
        (literal.angle - 45.0)
            .abs()
            .min((literal.angle - 135.0).abs())
            < 1e-9
    );
    // Crossland: sqrt(J2) amplitude S/sqrt(3), hydrostatic peak S/3.
    let (cross, _) = p.crossland.unwrap();
    let exact = s / 3f64.sqrt() + 0.4 * s / 3.0;
    assert!(
        (cross - exact).abs() < 1e-9 * exact,
        "Crossland {cross} vs {exact}"
    );
}

#[test]
fn life_curves_invert_their_own_values_and_constants_are_validated() {
    let c = constants();
    for n in [1e3f64, 1e5, 1e7] {
        let e = 200_000.0;
        let swt =
            1800.0f64.powi(2) / e * (2.0 * n).powf(-0.2) + 1800.0 * 0.5 * (2.0 * n).powf(-0.7);
        let got = fatigue::swt_life(swt, e, &c).unwrap();
        assert!((got - n).abs() < 1e-9 * n, "SWT life {got} vs {n}");
        let g = e / 2.6;
        let fs = 1000.0 / g * (2.0 * n).powf(-0.1) + 0.8 * (2.0 * n).powf(-0.6);
        let got = fatigue::fatemi_socie_life(fs, g, &c).unwrap();
        assert!((got - n).abs() < 1e-9 * n, "Fatemi-Socie life {got} vs {n}");
    }
    assert_eq!(fatigue::swt_life(1e-30, 200_000.0, &c), None, "run-out");
    assert_eq!(
        fatigue::swt_life(1.0, 200_000.0, &FatigueConstants::default()),
        None
    );
    let l = FatigueConstants::default()
        .with_threshold(150.0)
        .and_then(|c| c.with_endurance_range(500.0))
        .unwrap()
        .critical_distance()
        .unwrap();
    assert!((l - 0.09 / std::f64::consts::PI).abs() < 1e-15);
    for bad in [
        FatigueConstants::default().with_fatigue_strength_exponent(0.1),
        FatigueConstants::default().with_findley_k(-1.0),
        FatigueConstants::default().with_yield_stress(f64::NAN),
    ] {
        assert!(
            matches!(bad, Err(halfplane::Error::InvalidInput { field, .. }) if field.starts_with("fatigue."))
        );
    }
    assert!(
        FatigueGrid::new(1, 10, 1.5, 1.0).is_err() && FatigueGrid::new(10, 10, 0.0, 1.0).is_err()
    );
}

fn cycle(q: f64, bulk: f64) -> History {
    cycle_between([1000.0, -q, -bulk], [1000.0, q, bulk])
}

fn cycle_between(one: [f64; 3], two: [f64; 3]) -> History {
    History::in_phase(
        LoadPoint::new("point1", one[0], one[1], one[2]).unwrap(),
        LoadPoint::new("point2", two[0], two[1], two[2]).unwrap(),
        2,
        20,
        Ramp::NormalFirst,
        10,
    )
    .unwrap()
}

#[test]
fn every_parameter_is_mirror_symmetric_under_x_to_minus_x_with_q_reversed() {
    let options = MarchOptions::default().with_cells(200).unwrap();
    let grid = FatigueGrid::new(21, 6, 1.5, 0.5).unwrap();
    let c = constants()
        .with_threshold(200.0)
        .and_then(|c| c.with_endurance_range(600.0))
        .unwrap();
    let a = fatigue::analyse(&reference::hertz(), &cycle(300.0, 0.0), &options, &c, &grid).unwrap();
    let b = fatigue::analyse(
        &reference::hertz(),
        &cycle(-300.0, 0.0),
        &options,
        &c,
        &grid,
    )
    .unwrap();
    assert_eq!(a.parameters.len(), 8, "every parameter but McDiarmid");
    for (p, m) in a.parameters.iter().zip(&b.parameters) {
        assert_eq!(p.parameter, m.parameter);
        let scale = p.value.abs().max(1e-300);
        assert!(
            (p.value - m.value).abs() < 1e-8 * scale,
            "{}: {} vs mirrored {}",
            p.parameter.name(),
            p.value,
            m.value
        );
        // The maximum's location mirrors up to ties between x and -x (both runs can pick the same
        // one of two equal values), so only |x| and z are compared; the whole SWT map is compared
        // point by point below.
        assert!(
            (p.x.abs() - m.x.abs()).abs() < 1e-9 && p.z == m.z,
            "{}: x {} vs mirrored {}",
            p.parameter.name(),
            p.x,
            m.x
        );
        if let (Some(u), Some(v)) = (p.angle, m.angle) {
            // Mirrored location: mirrored plane (t -> 180 - t); a tie at the same x: same plane.
            let expected = if (p.x + m.x).abs() < 1e-9 {
                180.0 - u
            } else {
                u
            };
            let d = (v - expected).rem_euclid(180.0);
            assert!(
                d.min(180.0 - d) < 1e-6,
                "{}: plane {u} at x = {} vs {v} at x = {}",
                p.parameter.name(),
                p.x,
                m.x
            );
        }
        for (u, v) in [
            (p.point_method, m.point_method),
            (p.line_method, m.line_method),
        ] {
            if let (Some(u), Some(v)) = (u, v) {
                assert!((u - v).abs() < 1e-8 * u.abs().max(1e-300));
            }
        }
    }
    let nx = a.grid_x.len();
    for (k, v) in a.swt_map.iter().enumerate() {
        let (i, j) = (k % nx, k / nx);
        let w = b.swt_map[j * nx + nx - 1 - i];
        assert!(
            (v - w).abs() <= 1e-8 * v.abs().max(1e-12),
            "SWT map not mirrored at x = {}, z = {}: {v} vs {w}",
            a.grid_x[i],
            a.grid_z[j]
        );
    }
    // Ruiz F2 peaks on one side for each sign of Q.
    let f2 = a
        .parameters
        .iter()
        .find(|p| p.parameter == Parameter::RuizF2)
        .unwrap();
    assert!(f2.value > 0.0);
}

#[test]
fn marched_steady_cycle_matches_the_closed_form_at_the_cycle_extremes() {
    // Constant P = 1000, Q and sigma in phase between -(300, 60) and (300, 60): the steady
    // extremes are +/- the monotonic Nowell-Hills tractions (with the offset of sigma0 = 60).
    let (q0, s0) = (300.0, 60.0);
    let history = cycle(q0, s0);
    let c = history.cycles().unwrap();
    let start = c.first_step() + (c.count() - 1) * c.steps_per_cycle();
    let steps: Vec<usize> = (start + 1..=start + c.steps_per_cycle()).collect();
    let kept = stress::marched(
        &reference::hertz(),
        &history,
        &MarchOptions::default().with_cells(1600).unwrap(),
        &steps,
    )
    .unwrap();
    let a = kept[0].half_width;
    let nh = NowellHills::hertz(a, 0.6, 1000.0, q0, s0);
    let p0 = nh.peak_pressure;
    let m = reference::material();
    let nu = m.poisson_ratio();
    let state = |sign: f64, x: f64, z: f64| {
        let p = mcewen_pressure(p0, a, x, z);
        let full = nh.stress(x, z);
        let sxx = p[0] + sign * (full[0] - p[0] - s0) + sign * s0;
        let szz = p[1] + sign * (full[1] - p[1]);
        Stress {
            sxx,
            szz,
            syy: nu * (sxx + szz),
            sxz: p[2] + sign * (full[2] - p[2]),
        }
    };
    let k = constants();
    // The marched extremes: the increments at Q = +/- q0 of the last cycle.
    let ends: Vec<usize> = (0..kept.len())
        .filter(|&i| (kept[i].load.shear().abs() - q0).abs() < 1e-9)
        .collect();
    assert_eq!(ends.len(), 2, "one increment at each extreme");
    let values = |p: &fatigue::CriticalPlanes| {
        [
            p.swt.value,
            p.fatemi_socie.unwrap().value,
            p.findley.unwrap().value,
            p.crossland.unwrap().0,
            p.mwcm.unwrap().value,
            p.fatemi_socie_max_plane.unwrap().value,
        ]
    };
    const NAMES: [&str; 6] = [
        "swt",
        "fatemi_socie",
        "findley",
        "crossland",
        "mwcm",
        "fatemi_socie_max_plane",
    ];
    // Per parameter and point: the whole marched cycle, the marched extremes alone, the closed form.
    let mut cycle = Vec::new();
    let mut marched_ends = Vec::new();
    let mut closed = Vec::new();
    for (x, z) in [
        (-1.0, 0.05),
        (-0.9, 0.1),
        (-0.5, 0.2),
        (0.0, 0.3),
        (0.8, 0.1),
        (-1.1, 0.1),
    ] {
        let (x, z) = (x * a, z * a);
        let marched: Vec<Stress> = kept
            .iter()
            .map(|t| stress::at(&t.traction, t.load.bulk(), &m, x, z).unwrap())
            .collect();
        let extremes = [state(-1.0, x, z), state(1.0, x, z)];
        let two = [marched[ends[0]], marched[ends[1]]];
        cycle.push(values(&fatigue::critical_planes(&marched, &m, &k)));
        marched_ends.push(values(&fatigue::critical_planes(&two, &m, &k)));
        closed.push(values(&fatigue::critical_planes(&extremes, &m, &k)));
    }
    // Each parameter's error relative to its largest closed-form value over the points (SWT is
    // zero where the normal stress stays compressive, so a pointwise ratio would be 0/0).
    let error = |got: &[[f64; 6]], j: usize| {
        let scale = closed.iter().map(|w| w[j].abs()).fold(0.0, f64::max);
        got.iter()
            .zip(&closed)
            .map(|(g, w)| (g[j] - w[j]).abs() / scale)
            .fold(0.0, f64::max)
    };
    // Measured at 1600 cells and 20 increments per half-cycle (fs: Fatemi-Socie on the plane of
    // the largest shear range; fs max: the largest product over the planes):
    //                      swt      fs       findley  crossland  mwcm     fs max
    //   marched extremes   1.7e-5   1.3e-5   1.2e-5   1.1e-5     1.4e-5   1.3e-5
    //   whole cycle        1.7e-5   7.1e-4   1.2e-5   1.1e-5     2.4e-3   2.0e-4
    // The marched extremes differ from the closed form by the march's traction error alone
    // (3.6e-5 p0 below the surface, docs/stress.md): 5e-5 leaves a third for the refinement of
    // the planes and the rounding of the points' stresses.
    const EXTREMES: f64 = 5e-5;
    for (j, name) in NAMES.iter().enumerate() {
        let e = error(&marched_ends, j);
        assert!(
            e < EXTREMES,
            "{name} of the marched extremes off the Nowell-Hills extremes by {e:.2e} of its scale"
        );
    }
    // Over the whole cycle SWT, Findley and Crossland are set by the extremes (the same error).
    // Both Fatemi-Socie products and the MWCM take the peak normal stress on a plane chosen by its shear
    // amplitude, and that peak can come between the extremes: partial slip makes the stress path
    // between them curved (the largest difference is at x = 0.8a, near the leading edge). There
    // the cycle can only add to the extremes, and is bounded by what was measured with a margin
    // of a quarter.
    for (j, name) in NAMES.iter().enumerate() {
        let e = error(&cycle, j);
        let bound = match *name {
            "fatemi_socie" => 1e-3,
            "fatemi_socie_max_plane" => 2.5e-4,
            "mwcm" => 3e-3,
            _ => EXTREMES,
        };
        assert!(
            e < bound,
            "{name} over the marched cycle off the Nowell-Hills extremes by {e:.2e} of its scale"
        );
        for (c, two) in cycle.iter().zip(&marched_ends) {
            assert!(
                c[j] >= two[j] - 1e-12 * two[j].abs(),
                "{name}: the whole cycle {} below its own extremes {}",
                c[j],
                two[j]
            );
        }
    }
}
