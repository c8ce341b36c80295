//! The fatigue parameters as their authors define them (issue 17): Fatemi-Socie on the plane of
//! the largest shear strain range against a brute-force plane scan, Crossland's amplitude as the
//! minimum circumscribed ball of the deviatoric path on paths with known balls, McDiarmid against
//! hand-worked cases, and the 3-D plane search against rotated uniaxial states.

use halfplane::fatigue::{self, FatigueConstants, FatigueGrid, Parameter, Planes};
use halfplane::history::{History, Ramp};
use halfplane::march::MarchOptions;
use halfplane::stress::{self, Stress};
use halfplane::{reference, Error, LoadPoint, Material};

const K_FS: f64 = 0.5;
const YIELD: f64 = 900.0;
const K_FINDLEY: f64 = 0.25;
/// McDiarmid's t_A,B and sigma_u.
const T_AB: f64 = 300.0;
const SIGMA_U: f64 = 1200.0;

fn constants() -> FatigueConstants {
    FatigueConstants::default()
        .with_fatemi_socie_k(K_FS)
        .and_then(|c| c.with_yield_stress(YIELD))
        .and_then(|c| c.with_findley_k(K_FINDLEY))
        .and_then(|c| c.with_crossland_alpha(0.4))
        .and_then(|c| c.with_fatigue_limits(400.0, 250.0))
        .and_then(|c| c.with_mcdiarmid(T_AB, SIGMA_U))
        .unwrap()
}

fn material() -> Material {
    Material::new(200_000.0, 0.3).unwrap()
}

/// Shear modulus of [`material`].
const G: f64 = 200_000.0 / 2.6;

/// A history of `n` states over one period, `state(phase)` with the phase in radians.
fn over_a_period(n: usize, state: impl Fn(f64) -> Stress) -> Vec<Stress> {
    (0..n)
        .map(|k| state(2.0 * std::f64::consts::PI * k as f64 / n as f64))
        .collect()
}

/// Both Fatemi-Socie definitions by brute force over in-plane normals every 0.001 degree: the
/// largest product over the planes, and the product on the plane of the largest shear range
/// (of that plane and its twin 90 degrees away, the one with the larger normal stress).
fn brute_force_fatemi_socie(history: &[Stress]) -> (f64, f64) {
    let plane = |i: usize| {
        let t = (i as f64 * 0.001).to_radians();
        let (s2, c2) = (2.0 * t).sin_cos();
        let (mut n_max, mut lo, mut hi) = (f64::NEG_INFINITY, f64::INFINITY, f64::NEG_INFINITY);
        for s in history {
            let n = 0.5 * (s.sxx + s.szz) + 0.5 * (s.sxx - s.szz) * c2 + s.sxz * s2;
            let tau = -0.5 * (s.sxx - s.szz) * s2 + s.sxz * c2;
            n_max = n_max.max(n);
            lo = lo.min(tau);
            hi = hi.max(tau);
        }
        let range = hi - lo;
        (range, 0.5 * range / G * (1.0 + K_FS * n_max / YIELD))
    };
    let planes: Vec<(f64, f64)> = (0..180_000).map(plane).collect();
    let max_plane = planes.iter().map(|p| p.1).fold(f64::NEG_INFINITY, f64::max);
    let widest = (0..planes.len())
        .max_by(|&a, &b| planes[a].0.total_cmp(&planes[b].0))
        .unwrap();
    let twin = (widest + 90_000) % 180_000;
    (planes[widest].1.max(planes[twin].1), max_plane)
}

/// The Hertz cycle under constant P: R = 50, f = 0.6, P = 1000, Q = +-300, bulk +-`bulk`.
fn hertz_cycle(bulk: f64) -> History {
    History::in_phase(
        LoadPoint::new("point1", 1000.0, -300.0, -bulk).unwrap(),
        LoadPoint::new("point2", 1000.0, 300.0, bulk).unwrap(),
        2,
        20,
        Ramp::NormalFirst,
        10,
    )
    .unwrap()
}

#[test]
fn fatemi_socie_is_taken_on_the_plane_of_the_largest_shear_strain_range() {
    // Failed before the fix: `fatemi_socie` was the largest product over all planes.
    let contact = reference::hertz();
    let options = MarchOptions::default().with_cells(400).unwrap();
    let grid = FatigueGrid::new(41, 21, 1.3, 0.6).unwrap();
    let c = constants();
    for bulk in [0.0, 60.0] {
        let history = hertz_cycle(bulk);
        let result = fatigue::analyse(&contact, &history, &options, &c, &grid).unwrap();
        let literal = result.parameter(Parameter::FatemiSocie).unwrap();
        let max_plane = result.parameter(Parameter::FatemiSocieMaxPlane).unwrap();
        let lower = 1.0 - literal.value / max_plane.value;
        eprintln!(
            "bulk {bulk}: fatemi_socie {:.6e} at ({:.4}, {:.4}), max plane {:.6e} at ({:.4}, \
             {:.4}): {:.3}% lower",
            literal.value,
            literal.x,
            literal.z,
            max_plane.value,
            max_plane.x,
            max_plane.z,
            100.0 * lower
        );
        // Each maximum, re-evaluated at its own point by the brute-force scan: the library finds
        // the planes exactly (literal) or to 0.05 degree (max plane), the scan to 0.001 degree;
        // near the plane of the largest shear range the normal stress changes to first order in
        // the angle, 0.0005 degree moves it by ~1e-5 of the stresses: 3e-5.
        let c_steps = history.cycles().unwrap();
        let start = c_steps.first_step() + (c_steps.count() - 1) * c_steps.steps_per_cycle();
        let steps: Vec<usize> = (start + 1..=start + c_steps.steps_per_cycle()).collect();
        let kept = stress::marched(&contact, &history, &options, &steps).unwrap();
        for (which, best) in [(0, literal), (1, max_plane)] {
            let at: Vec<Stress> = kept
                .iter()
                .map(|t| {
                    stress::at(
                        &t.traction,
                        t.load.bulk(),
                        &contact.material(),
                        best.x,
                        best.z,
                    )
                })
                .collect::<Result<_, _>>()
                .unwrap();
            let brute = brute_force_fatemi_socie(&at);
            let want = if which == 0 { brute.0 } else { brute.1 };
            assert!(
                (best.value - want).abs() < 3e-5 * want,
                "{}: {} vs brute force {want}",
                best.parameter.name(),
                best.value
            );
        }
        // The two definitions differ here by about 1% (issue 17 measured 1.0-1.1% on finer
        // grids): the literal one must be lower, by more than the grid's own error.
        assert!(
            (0.005..0.02).contains(&lower),
            "bulk {bulk}: literal {} vs max plane {}",
            literal.value,
            max_plane.value
        );
    }
}

/// A closed path through `vertices` (deviatoric states), `per_edge` states per edge.
fn polygon(vertices: &[Stress], per_edge: usize) -> Vec<Stress> {
    let mut path = Vec::new();
    for (i, a) in vertices.iter().enumerate() {
        let b = vertices[(i + 1) % vertices.len()];
        for k in 0..per_edge {
            let t = k as f64 / per_edge as f64;
            path.push(Stress {
                sxx: a.sxx + t * (b.sxx - a.sxx),
                szz: a.szz + t * (b.szz - a.szz),
                syy: a.syy + t * (b.syy - a.syy),
                sxz: a.sxz + t * (b.sxz - a.sxz),
            });
        }
    }
    path
}

/// A deviatoric state with no hydrostatic part at deviatoric coordinates
/// `((sxx - szz)/2, sxz, (2 syy - sxx - szz)/(2 sqrt 3))` = `(a, b, c)`, whose norm is sqrt(J2).
fn deviatoric(a: f64, b: f64, c: f64) -> Stress {
    let r3 = 3f64.sqrt();
    // sxx + szz + syy = 0 and 2 syy - sxx - szz = 2 sqrt(3) c give syy = 2c/sqrt(3).
    let syy = 2.0 * c / r3;
    let mean_xz = -0.5 * syy;
    Stress {
        sxx: mean_xz + a,
        szz: mean_xz - a,
        syy,
        sxz: b,
    }
}

/// Crossland with `alpha` times a zero hydrostatic stress: sqrt(J2,a) alone.
fn amplitude(path: &[Stress]) -> f64 {
    fatigue::critical_planes(path, &material(), &constants())
        .crossland
        .unwrap()
        .0
}

#[test]
fn crossland_amplitude_is_the_minimum_circumscribed_ball_of_the_deviatoric_path() {
    // Failed before the fix (half the longest chord): the triangle gave s/2, not s/sqrt(3).
    // Welzl's ball is exact up to rounding (points count as inside within 1e-12 of the path's
    // extent), so every known radius is checked to 1e-12.
    let rho = 150.0;
    let close = |got: f64, want: f64, what: &str| {
        assert!((got - want).abs() < 1e-12 * want, "{what}: {got} vs {want}");
    };
    // Equilateral triangle of circumradius rho in the (a, b) plane: side s = rho sqrt(3), longest
    // chord s (a side), ball radius s/sqrt(3) = rho, 15.5% above s/2.
    let corner = |k: f64, plane: usize| {
        let t = std::f64::consts::FRAC_PI_2 + k * 2.0 * std::f64::consts::PI / 3.0;
        let (u, v) = (rho * t.cos(), rho * t.sin());
        if plane == 0 {
            deviatoric(u, v, 0.0)
        } else {
            deviatoric(u, 0.0, v)
        }
    };
    for plane in 0..2 {
        let triangle = polygon(
            &[corner(0.0, plane), corner(1.0, plane), corner(2.0, plane)],
            25,
        );
        let s = rho * 3f64.sqrt();
        let got = amplitude(&triangle);
        eprintln!(
            "triangle (plane {plane}): ball {got:.6}, s/sqrt(3) {:.6}, half chord s/2 {:.6}",
            s / 3f64.sqrt(),
            s / 2.0
        );
        close(got, s / 3f64.sqrt(), "triangle");
    }
    // Circle of radius rho (a = rho cos, b = rho sin): ball and half chord are both rho.
    let circle = over_a_period(360, |t| deviatoric(rho * t.cos(), rho * t.sin(), 0.0));
    close(amplitude(&circle), rho, "circle");
    // Regular tetrahedron in (a, b, c) with edge e: circumradius e sqrt(3/8), four boundary points.
    let e = 200.0;
    let tetra = [
        [1.0, 1.0, 1.0],
        [1.0, -1.0, -1.0],
        [-1.0, 1.0, -1.0],
        [-1.0, -1.0, 1.0],
    ]
    .map(|p| {
        let h = e / (2.0 * 2f64.sqrt());
        deviatoric(h * p[0] + 10.0, h * p[1] - 20.0, h * p[2] + 5.0)
    });
    close(
        amplitude(&polygon(&tetra, 7)),
        e * (3.0f64 / 8.0).sqrt(),
        "tetrahedron",
    );
    // Proportional: a segment of length 2 rho gives rho.
    let segment = over_a_period(72, |t| deviatoric(rho * t.sin(), 0.5 * rho * t.sin(), 0.0));
    close(amplitude(&segment), rho * 1.25f64.sqrt(), "segment");
}

#[test]
fn mcdiarmid_matches_the_hand_worked_torsion_and_tension_cases() {
    let m = material();
    let c = constants();
    let value = |h: &[Stress]| fatigue::critical_planes(h, &m, &c).mcdiarmid.unwrap();
    // Reversed shear T: the plane 0 (or 90) degrees, tau_a = T, sigma_n,max = 0.
    let t = 180.0;
    let torsion = value(&over_a_period(72, |p| Stress {
        sxz: t * p.sin(),
        ..Stress::default()
    }));
    assert!((torsion.value - t).abs() < 1e-12 * t, "{torsion:?}");
    // Reversed uniaxial S: the plane at 45 degrees, tau_a = S/2 = sigma_n,max:
    // S/2 + t_AB (S/2)/(2 sigma_u).
    let s = 400.0;
    let tension = value(&over_a_period(72, |p| Stress {
        sxx: s * p.sin(),
        ..Stress::default()
    }));
    let want = 0.5 * s + T_AB * 0.5 * s / (2.0 * SIGMA_U);
    assert!(
        (tension.value - want).abs() < 1e-12 * want,
        "{tension:?} vs {want}"
    );
    assert!(
        (tension.angle - 45.0)
            .abs()
            .min((tension.angle - 135.0).abs())
            < 1e-9
    );
    // Its constants are validated and reported missing when absent.
    assert!(FatigueConstants::default()
        .with_mcdiarmid(1300.0, 1200.0)
        .is_err());
    assert!(FatigueConstants::default()
        .with_mcdiarmid(f64::NAN, 1200.0)
        .is_err());
    assert_eq!(
        FatigueConstants::default().missing_for(Parameter::McDiarmid),
        ["mcdiarmid_shear_limit", "ultimate_strength"]
    );
    assert!(fatigue::critical_planes(
        &over_a_period(4, |_| Stress::default()),
        &m,
        &FatigueConstants::default()
    )
    .mcdiarmid
    .is_none());
}

#[test]
fn the_3d_search_finds_planes_tilted_towards_y() {
    let m = material();
    let c = constants();
    let s = 300.0;
    let along = |axis: usize| {
        over_a_period(72, move |p| {
            let v = s * p.sin();
            if axis == 0 {
                Stress {
                    sxx: v,
                    ..Stress::default()
                }
            } else {
                Stress {
                    syy: v,
                    ..Stress::default()
                }
            }
        })
    };
    let values = |p: &fatigue::CriticalPlanes| {
        [
            p.swt.value,
            p.fatemi_socie.unwrap().value,
            p.fatemi_socie_max_plane.unwrap().value,
            p.findley.unwrap().value,
            p.mwcm.unwrap().value,
            p.mcdiarmid.unwrap().value,
        ]
    };
    // Uniaxial along x: the critical planes contain y, both searches agree (the sampled ones to
    // the in-plane refinement, which the 3-D search starts from: 1e-12).
    let x_in = values(&fatigue::critical_planes_over(
        &along(0),
        &m,
        &c,
        Planes::InPlane,
    ));
    let x_3d = values(&fatigue::critical_planes_over(
        &along(0),
        &m,
        &c,
        Planes::Full3d,
    ));
    // The exact planes (Fatemi-Socie, MWCM, McDiarmid) to 1e-12; the sampled ones, which the 3-D
    // pattern search refines further from the in-plane result (never below it), to their error,
    // second order in the 0.05-degree step: 1e-6.
    let exact = |j: usize| [1, 4, 5].contains(&j);
    for (j, (a, b)) in x_in.iter().zip(&x_3d).enumerate() {
        let tol = if exact(j) { 1e-12 } else { 1e-6 };
        assert!(
            *b >= *a && b - a <= tol * a.abs(),
            "{j}: {x_in:?} vs {x_3d:?}"
        );
    }
    // Uniaxial along y: no plane containing y sees it (every in-plane value has no shear and no
    // tension), while the 3-D search finds the same values as along x, by isotropy (tolerances as
    // above).
    let y_in = fatigue::critical_planes_over(&along(1), &m, &c, Planes::InPlane);
    assert_eq!(y_in.swt.value, 0.0);
    assert!(y_in.fatemi_socie.unwrap().value < 1e-12);
    let y_3d = fatigue::critical_planes_over(&along(1), &m, &c, Planes::Full3d);
    let got = values(&y_3d);
    for (j, (a, b)) in x_in.iter().zip(&got).enumerate() {
        let tol = if exact(j) { 1e-12 } else { 1e-6 };
        assert!(
            (a - b).abs() <= tol * a.abs(),
            "{j}: along x {a} vs along y {b}"
        );
    }
    assert!((y_3d.swt.tilt - 90.0).abs() < 0.06, "{:?}", y_3d.swt);
    assert!((y_3d.fatemi_socie.unwrap().tilt - 45.0).abs() < 1e-9);
    // A marched Hertz cycle: every sampled 3-D value (SWT, max-plane Fatemi-Socie, Findley) at
    // least the in-plane one. (The parameters on the plane of the largest shear range need not
    // be: a tilted plane can have the larger shear range and the smaller normal stress.)
    let history = hertz_cycle(60.0);
    let cs = history.cycles().unwrap();
    let start = cs.first_step() + (cs.count() - 1) * cs.steps_per_cycle();
    let steps: Vec<usize> = (start + 1..=start + cs.steps_per_cycle()).collect();
    let contact = reference::hertz();
    let options = MarchOptions::default().with_cells(200).unwrap();
    let kept = stress::marched(&contact, &history, &options, &steps).unwrap();
    for (x, z) in [(-0.7, 0.0), (-0.5, 0.1), (0.0, 0.3), (0.5, 0.05)] {
        let h: Vec<Stress> = kept
            .iter()
            .map(|t| stress::at(&t.traction, t.load.bulk(), &contact.material(), x, z).unwrap())
            .collect();
        let a = values(&fatigue::critical_planes_over(&h, &m, &c, Planes::InPlane));
        let b = values(&fatigue::critical_planes_over(&h, &m, &c, Planes::Full3d));
        for j in [0, 2, 3] {
            let (u, v) = (&a[j], &b[j]);
            assert!(
                *v >= u - 1e-12 * u.abs(),
                "at ({x}, {z}): 3-D {b:?} vs in-plane {a:?}"
            );
        }
    }
}

#[test]
fn planes_names_are_validated() {
    assert_eq!(Planes::from_name("3d").unwrap(), Planes::Full3d);
    assert_eq!(Planes::from_name("in-plane").unwrap(), Planes::InPlane);
    match Planes::from_name("3D") {
        Err(Error::InvalidText {
            field,
            value,
            valid,
        }) => {
            assert_eq!(field, "fatigue.planes");
            assert_eq!(value, "3D");
            assert!(valid.contains("\"3d\"") && valid.contains("\"in-plane\""));
        }
        other => panic!("{other:?}"),
    }
}
