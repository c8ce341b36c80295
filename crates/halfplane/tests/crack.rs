//! The crack module against independent references (`docs/crack.md`): the edge crack's exact
//! factor, power-law face loads, symmetry of inclined cracks, closed faces with and without
//! friction against the open solution under the reduced shear, convergence in points, and the
//! inclined crack against a second, separately discretised solution (`crack::graded`).

use halfplane::crack::{Crack, CrackSolver, FaceState};
use halfplane::Material;
use std::f64::consts::PI;

/// Koiter (1965), Wigglesworth (1957): an edge crack normal to the surface of a half-plane under
/// uniform tension has `K_I = 1.121522 sigma sqrt(pi l)`.
const EDGE: f64 = 1.121_522;

fn steel() -> Material {
    Material::new(200_000.0, 0.3).unwrap()
}

fn solver(angle_degrees: f64, points: usize) -> CrackSolver {
    let crack = Crack::new(0.25, angle_degrees.to_radians(), 0.01).unwrap();
    CrackSolver::new(&crack, &steel(), points).unwrap()
}

/// `(K_I, K_II)/(sqrt(pi l))` of the open crack under face loads `(normal, shear)(s/l)`.
fn factors(s: &CrackSolver, normal: impl Fn(f64) -> f64, shear: impl Fn(f64) -> f64) -> (f64, f64) {
    let l = s.crack().length();
    let n: Vec<f64> = s.distances().iter().map(|d| normal(d / l)).collect();
    let t: Vec<f64> = s.distances().iter().map(|d| shear(d / l)).collect();
    let k = s.open(&n, &t).unwrap();
    let f = (PI * l).sqrt();
    (k.k1 / f, k.k2 / f)
}

#[test]
fn edge_crack_under_uniform_tension_within_0_1_percent() {
    // 40 points (the default) give 2e-4 relative; the issue asks 0.1%.
    let (f1, f2) = factors(&solver(0.0, 40), |_| 1.0, |_| 0.0);
    assert!((f1 / EDGE - 1.0).abs() < 1e-3, "{f1}");
    assert!(f2.abs() < 1e-12, "{f2}");
}

#[test]
fn convergence_in_quadrature_points_is_second_order() {
    // The error against the exact factor falls about fourfold per doubling (the density is
    // not smooth at the mouth in the rule's variable, so the rule is not spectral here).
    let mut errors = Vec::new();
    for n in [10, 20, 40, 80, 160] {
        let (f1, _) = factors(&solver(0.0, n), |_| 1.0, |_| 0.0);
        errors.push((f1 / EDGE - 1.0).abs());
    }
    for w in errors.windows(2) {
        let ratio = w[0] / w[1];
        assert!((3.0..5.0).contains(&ratio), "{errors:?}");
    }
    assert!(errors[4] < 1e-4, "{errors:?}");
}

#[test]
fn uniform_face_shear_on_a_normal_crack() {
    // Mode II of the edge crack under uniform face shear has the same factor 1.1215 (the normal
    // crack's two modes decouple by symmetry and obey the same kernel on the crack line).
    let (f1, f2) = factors(&solver(0.0, 80), |_| 0.0, |_| 1.0);
    assert!(f1.abs() < 1e-12, "{f1}");
    assert!((f2 / EDGE - 1.0).abs() < 1e-3, "{f2}");
}

#[test]
fn power_law_face_loads() {
    // sigma (s/l)^k on the faces, K_I/(sigma sqrt(pi l)). Superposition checks the linear
    // pair against the uniform load: the increasing and decreasing linear loads add up to it.
    let s = solver(0.0, 80);
    let (up, _) = factors(&s, |r| r, |_| 0.0);
    let (down, _) = factors(&s, |r| 1.0 - r, |_| 0.0);
    let (uniform, _) = factors(&s, |_| 1.0, |_| 0.0);
    assert!((up + down - uniform).abs() < 1e-12);
    println!("linear increasing {up:.5}, decreasing {down:.5}");
    // Tada, Paris and Irwin: 0.683 and 0.439 (three digits).
    assert!((up / 0.683 - 1.0).abs() < 2e-3, "{up}");
    assert!((down / 0.439 - 1.0).abs() < 3e-3, "{down}");
}

#[test]
fn inclined_cracks_mirror() {
    // The mirror image about the normal through the mouth: +angle under the same face loads
    // gives the same K_I and the opposite K_II... with the shear load mirrored too. Under
    // normal face load only, K_II changes sign, K_I does not.
    for angle in [15.0, 30.0, 45.0, 60.0] {
        let (a1, a2) = factors(&solver(angle, 60), |_| 1.0, |_| 0.0);
        let (b1, b2) = factors(&solver(-angle, 60), |_| 1.0, |_| 0.0);
        println!("{angle}: F_I {a1:.5} F_II {a2:.5}");
        assert!(
            (a1 - b1).abs() < 1e-10 && (a2 + b2).abs() < 1e-10,
            "{a1} {b1} {a2} {b2}"
        );
        assert!(a2.abs() > 1e-3, "inclined cracks couple the modes");
    }
}

/// Uniform face loads `(normal, shear)` at every point, per increment.
fn uniform(s: &CrackSolver, history: &[(f64, f64)]) -> Vec<(Vec<f64>, Vec<f64>)> {
    let n = s.distances().len();
    history
        .iter()
        .map(|&(p, t)| (vec![p; n], vec![t; n]))
        .collect()
}

#[test]
fn a_compressed_crack_closes_with_k1_zero_and_no_interpenetration() {
    let s = solver(0.0, 40);
    let l = s.crack().length();
    for f in [0.0, 0.3] {
        let out = s
            .cycle(&uniform(&s, &[(-100.0, 0.0), (-50.0, 0.0)]), f)
            .unwrap();
        for inc in &out {
            assert_eq!(inc.factors.k1, 0.0);
            assert!(inc.factors.k2.abs() < 1e-9 * 100.0 * l.sqrt());
            assert!(inc.states.iter().all(|s| *s != FaceState::Open));
            let e = steel();
            let scale = 100.0 * l / e.youngs_modulus();
            assert!(
                inc.opening.iter().all(|g| g.abs() < 1e-8 * scale),
                "{:?}",
                inc.opening
            );
            // The contact pressure is the applied compression (uniform load, faces closed).
            assert!(inc.normal.iter().all(|p| *p < 0.0));
        }
    }
}

#[test]
fn closed_faces_slip_under_the_reduced_shear() {
    // Uniform compression p and shear tau > f p: every point slips and carries f p, so K_II is
    // that of the open crack under tau - f p (a second route through the open solve).
    let s = solver(0.0, 40);
    let (p, tau, f) = (100.0, 80.0, 0.5);
    let out = s.cycle(&uniform(&s, &[(-p, tau)]), f).unwrap();
    let n = s.distances().len();
    let open = s.open(&vec![0.0; n], &vec![tau - f * p; n]).unwrap();
    let k = out[0].factors;
    assert_eq!(k.k1, 0.0);
    assert!((k.k2 / open.k2 - 1.0).abs() < 1e-9, "{} {}", k.k2, open.k2);
    for (t, q) in out[0].shear.iter().zip(&out[0].normal) {
        assert!((t.abs() - f * q.abs()).abs() < 1e-6 * p, "{t} {q}");
    }
}

#[test]
fn reversed_shear_under_friction_gives_the_stick_slip_range() {
    // Constant compression p, shear tau from +ta to -ta and back: the faces slip forward, stick
    // for a change of 2 f p after each reversal, then slip back, so
    // dK_II = 2 (ta - f p) F sqrt(pi l) for ta > f p, and 0 when friction holds them (ta < f p).
    let s = solver(0.0, 40);
    let (p, ta) = (100.0, 60.0);
    let steps: Vec<(f64, f64)> = (0..=40)
        .map(|i| (-p, ta * (2.0 * PI * i as f64 / 40.0).cos()))
        .collect();
    let n = s.distances().len();
    let unit = s.open(&vec![0.0; n], &vec![1.0; n]).unwrap().k2;
    for f in [0.0, 0.2, 0.4, 0.7, 5.0] {
        let out = s.cycle(&uniform(&s, &steps), f).unwrap();
        let (lo, hi) = out.iter().fold((f64::MAX, f64::MIN), |(lo, hi), o| {
            (lo.min(o.factors.k2), hi.max(o.factors.k2))
        });
        let expect = 2.0 * (ta - f * p).max(0.0) * unit;
        println!("f {f}: dK_II {:.6} expected {expect:.6}", hi - lo);
        assert!(
            ((hi - lo) - expect).abs() < 1e-6 * ta * unit,
            "{f}: {} {expect}",
            hi - lo
        );
        for o in &out {
            assert_eq!(o.factors.k1, 0.0);
            for (t, q) in o.shear.iter().zip(&o.normal) {
                assert!(*q <= 0.0 && t.abs() <= f * q.abs() + 1e-6 * p, "{t} {q}");
            }
        }
    }
}

#[test]
fn a_crack_under_bending_closes_near_the_tip_only() {
    // Tension at the surface falling to compression at depth: the faces near the tip close,
    // K_I = 0, and the open part opens; no point interpenetrates.
    let s = solver(0.0, 40);
    let l = s.crack().length();
    let n: Vec<f64> = s
        .distances()
        .iter()
        .map(|d| 100.0 * (1.0 - 3.0 * d / l))
        .collect();
    let out = s.cycle(&[(n, vec![0.0; 40])], 0.0).unwrap();
    let inc = &out[0];
    assert_eq!(inc.factors.k1, 0.0);
    assert_eq!(
        inc.states[0],
        FaceState::Slip(1),
        "tip point closed (f = 0)"
    );
    assert_eq!(
        *inc.states.last().unwrap(),
        FaceState::Open,
        "mouth point open"
    );
    let scale = 100.0 * l / 200_000.0;
    assert!(
        inc.opening.iter().all(|g| *g > -1e-8 * scale),
        "{:?}",
        inc.opening
    );
    assert!(inc.opening.iter().any(|g| *g > 1e-3 * scale));
}

mod under_the_contact {
    use super::EDGE;
    use halfplane::crack::{self, CrackOptions, Position, Verdict};
    use halfplane::fatigue::FatigueConstants;
    use halfplane::history::{History, Ramp};
    use halfplane::march::MarchOptions;
    use halfplane::{reference, LoadPoint};
    use std::f64::consts::PI;

    /// The crack example's cycle: P = 1000 with Q and the bulk tension in phase to (q, bulk).
    pub fn history(q: f64, bulk: f64, steps_per_half: usize) -> History {
        History::in_phase(
            LoadPoint::new("point1", 1000.0, -q, -bulk).unwrap(),
            LoadPoint::new("point2", 1000.0, q, bulk).unwrap(),
            2,
            steps_per_half,
            Ramp::NormalFirst,
            10,
        )
        .unwrap()
    }

    fn constants() -> FatigueConstants {
        FatigueConstants::default()
            .with_threshold(160.0)
            .and_then(|c| c.with_endurance_range(700.0))
            .unwrap()
    }

    fn options() -> MarchOptions {
        MarchOptions::default().with_cells(200).unwrap()
    }

    #[test]
    fn far_from_the_contact_only_the_bulk_tension_acts() {
        // 1e5 from the contact the contact's own stress is below 1e-4 of the bulk tension
        // (Flamant: the surface sxx of the normal load vanishes outside it, the shear load's falls
        // as 2Q/(pi x)): K_I follows the edge crack under the bulk tension while it pulls, and is
        // zero while it pushes (the faces close).
        let l = 0.05;
        let opts = CrackOptions::new(Position::At(1e5), 0.0, vec![l], 0.0).unwrap();
        let h = history(300.0, 60.0, 10);
        let r = crack::analyse(&reference::hertz(), &h, &options(), &constants(), &opts).unwrap();
        let row = &r.rows[0];
        let expect = EDGE * 60.0 * (PI * l).sqrt();
        assert!(
            (row.k1_max / expect - 1.0).abs() < 1e-3,
            "{} {expect}",
            row.k1_max
        );
        assert_eq!(row.k1_min, 0.0);
        assert!(row.k2_max.abs() < 1e-3 * expect && row.k2_min.abs() < 1e-3 * expect);
        assert!((row.delta_k1 - row.k1_max).abs() < 1e-12);
    }

    #[test]
    fn mirror_image_under_reversed_shear() {
        // x -> -x with Q and the crack's angle reversed: the same K_I, K_II of opposite sign.
        let c = constants();
        let run = |pos: Position, angle: f64, q: f64| {
            let opts = CrackOptions::new(pos, angle, vec![0.02, 0.08], 0.3).unwrap();
            crack::analyse(
                &reference::hertz(),
                &history(q, 0.0, 10),
                &options(),
                &c,
                &opts,
            )
            .unwrap()
        };
        let a = run(Position::RightEdge, 20.0, 300.0);
        let b = run(Position::LeftEdge, -20.0, -300.0);
        assert!((a.mouth + b.mouth).abs() < 1e-12);
        for (ra, rb) in a.rows.iter().zip(&b.rows) {
            let scale = ra.delta_k_eff.max(1e-9);
            assert!(
                (ra.k1_max - rb.k1_max).abs() < 1e-6 * scale,
                "{ra:?} {rb:?}"
            );
            assert!(
                (ra.k2_max + rb.k2_min).abs() < 1e-6 * scale,
                "{ra:?} {rb:?}"
            );
            assert!((ra.delta_k_eff - rb.delta_k_eff).abs() < 1e-6 * scale);
        }
    }

    #[test]
    fn critical_plane_angle_lies_in_the_plane_of_largest_swt() {
        // A mouth in the trailing slip zone (x = -0.7, a = 0.761), where the surface shear
        // traction tilts the principal planes. The crack must lie in the plane on which
        // SWT = sigma_n,max d(eps_n)/2 (plane strain, elastic) is largest: computed here from the
        // mouth's stress history on every plane (0.1 degree apart), independently of the
        // fatigue module's search (0.05 degree refinement).
        let c = constants();
        let h = history(300.0, 60.0, 20);
        let contact = reference::hertz();
        let opts = CrackOptions::new(Position::At(-0.7), 0.0, vec![0.01], 0.0)
            .unwrap()
            .with_critical_plane(halfplane::fatigue::Parameter::Swt)
            .unwrap();
        let r = crack::analyse(&contact, &h, &options(), &c, &opts).unwrap();
        let theta = r.angle.to_radians();
        let spc = h.cycles().unwrap().steps_per_cycle();
        let last = h.loads().len();
        let steps: Vec<usize> = (last + 1 - spc..=last).collect();
        let kept = halfplane::stress::marched(&contact, &h, &options(), &steps).unwrap();
        let m = contact.material();
        let nu = m.poisson_ratio();
        let history: Vec<_> = kept
            .iter()
            .map(|k| halfplane::stress::at(&k.traction, k.load.bulk(), &m, -0.7, 0.0).unwrap())
            .collect();
        let swt = |beta: f64| {
            let (s, co) = beta.sin_cos();
            let (mut smax, mut emin, mut emax) = (f64::MIN, f64::MAX, f64::MIN);
            for st in &history {
                let sn = st.sxx * co * co + st.szz * s * s + 2.0 * st.sxz * co * s;
                let en =
                    ((1.0 + nu) * sn - nu * (1.0 + nu) * (st.sxx + st.szz)) / m.youngs_modulus();
                smax = smax.max(sn);
                emin = emin.min(en);
                emax = emax.max(en);
            }
            smax * (emax - emin) / 2.0
        };
        // The crack's normal n = (cos theta, -sin theta): the plane normal at -theta from +x.
        let on_crack = swt(-theta);
        let best = (0..1800)
            .map(|i| swt((i as f64 * 0.1).to_radians()))
            .fold(f64::MIN, f64::max);
        println!(
            "angle {:.3} degrees, SWT on the crack {on_crack:.6e}, best {best:.6e}",
            r.angle
        );
        assert!(on_crack >= best * (1.0 - 1e-6), "{on_crack} {best}");
        assert!(r.angle.abs() > 1.0, "the tilt is not trivial: {}", r.angle);
    }

    #[test]
    fn the_example_cycle_and_its_verdict() {
        let lengths: Vec<f64> = (0..12).map(|i| 0.002 * 1.6f64.powi(i)).collect();
        let opts = CrackOptions::new(Position::LargerRange, 0.0, lengths, 0.0).unwrap();
        let h = history(300.0, 60.0, 30);
        let r = crack::analyse(&reference::hertz(), &h, &options(), &constants(), &opts).unwrap();
        for row in &r.rows {
            println!(
                "{:.5} K1 [{:.2}, {:.2}] K2 [{:.2}, {:.2}] dKeff {:.2} th {:.2}",
                row.length,
                row.k1_min,
                row.k1_max,
                row.k2_min,
                row.k2_max,
                row.delta_k_eff,
                row.threshold
            );
            assert!(row.k1_min >= 0.0);
        }
        println!("{:?} {:?} mouth {}", r.verdict, r.arrest_length, r.mouth);
        let (v, l) = Verdict::of(&r.rows);
        assert_eq!((v, l), (r.verdict, r.arrest_length));
    }
}

mod weight_function {
    use halfplane::crack::{reference, Crack, CrackSolver, FaceState};
    use halfplane::march::MarchOptions;
    use halfplane::{reference as contacts, stress};

    #[test]
    fn an_open_crack_under_the_contact_stress_against_the_weight_function() {
        // The example's cycle (Hertz, P = 1000, Q and bulk tension in phase to (300, 60)); a
        // crack normal to the surface at the trailing edge x = -a. At the increment of the
        // largest K_I every collocation point is open (checked: the comparison is of the open
        // crack), and K_I must equal the weight-function integral of the uncracked sxx along the
        // crack line (Hartranft-Sih/Tada, crack::reference) within 0.5%: the weight function's own
        // accuracy is 0.06-0.22% on polynomial loads.
        let h = super::under_the_contact::history(300.0, 60.0, 30);
        let contact = contacts::hertz();
        let material = contact.material();
        let options = MarchOptions::default().with_cells(400).unwrap();
        let steps: Vec<usize> = (h.loads().len() - 59..=h.loads().len()).collect();
        let kept = stress::marched(&contact, &h, &options, &steps).unwrap();
        let a = kept[0].half_width;
        for l in [0.002, 0.01, 0.03, 0.08] {
            let s = CrackSolver::new(&Crack::new(-a, 0.0, l).unwrap(), &material, 40).unwrap();
            let increments: Vec<(&stress::Traction, f64)> =
                kept.iter().map(|k| (&k.traction, k.load.bulk())).collect();
            let loads: Vec<(Vec<f64>, Vec<f64>)> =
                stress::fields(&increments, &material, s.x(), s.z())
                    .unwrap()
                    .iter()
                    .map(|f| {
                        (0..f.len())
                            .map(|i| s.resolve(f.sxx[i], f.szz[i], f.sxz[i]))
                            .unzip()
                    })
                    .collect();
            let out = s.cycle(&loads, 0.0).unwrap();
            let (m, peak) = out
                .iter()
                .enumerate()
                .max_by(|x, y| x.1.factors.k1.total_cmp(&y.1.factors.k1))
                .unwrap();
            assert!(
                peak.states.iter().all(|s| *s == FaceState::Open),
                "{l}: {:?}",
                peak.states
            );
            let weights = reference::edge_crack_weights(l, 64).unwrap();
            let depths: Vec<f64> = weights.iter().map(|w| w.0).collect();
            let f = stress::field(
                &kept[m].traction,
                kept[m].load.bulk(),
                &material,
                &vec![-a; depths.len()],
                &depths,
            )
            .unwrap();
            let expect: f64 = weights.iter().zip(&f.sxx).map(|(w, s)| w.1 * s).sum();
            let k1 = peak.factors.k1;
            println!(
                "l {l}: K_I {k1:.4}, weight function {expect:.4}, {:+.3}%",
                100.0 * (k1 / expect - 1.0)
            );
            assert!((k1 / expect - 1.0).abs() < 5e-3, "{l}: {k1} {expect}");
        }
    }
}

mod inclined {
    use super::{solver, steel};
    use halfplane::crack::CrackSolver;
    use std::f64::consts::PI;

    /// `(K_I, K_II)/(sigma sqrt(pi l))` and `2U/l` over `(1 - nu^2)/E sigma^2 pi l` of the open
    /// crack under remote tension `sxx = 1`, `U` the energy the crack releases,
    /// `(1/2) integral (s_nn delta_2 + tau delta_1) ds`, taken from the face displacements at the
    /// collocation points (Gauss-Jacobi weights of `sqrt((1 - u)/(1 + u))`).
    pub fn remote(s: &CrackSolver) -> (f64, f64, f64) {
        let (normal, shear): (Vec<f64>, Vec<f64>) = s
            .distances()
            .iter()
            .map(|_| s.resolve(1.0, 0.0, 0.0))
            .unzip();
        let out = &s.cycle(&[(normal.clone(), shear.clone())], 0.0).unwrap()[0];
        let l = s.crack().length();
        let n = normal.len();
        let m = (2 * n + 1) as f64;
        let mut u = 0.0;
        for (k, d) in s.distances().iter().enumerate() {
            let x = 2.0 * d / l - 1.0;
            let w = 2.0 * PI * (1.0 - x) / m;
            // delta = sqrt((1 - x)/(1 + x)) h: the rule integrates h.
            let h = |v: f64| v * ((1.0 + x) / (1.0 - x)).sqrt();
            u += 0.5 * (l / 2.0) * w * (normal[k] * h(out.opening[k]) - shear[k] * h(out.slip[k]));
        }
        let e = steel();
        let nu = e.poisson_ratio();
        let scale = (1.0 - nu * nu) / e.youngs_modulus() * PI * l;
        let f = (PI * l).sqrt();
        (out.factors.k1 / f, out.factors.k2 / f, 2.0 * u / l / scale)
    }

    #[test]
    fn inclined_edge_cracks_release_the_energy_their_factors_give() {
        // Irwin: G = (1 - nu^2)/E (K_I^2 + K_II^2) (plane strain), and under remote tension the
        // energy the crack releases is U = C l^2 (the only length is l), so G = dU/dl = 2U/l.
        // U comes from the face displacements, K from the density at the tip: two routes through
        // the solution. At 160 points they agree within 1e-3 for angles to 60 degrees (measured
        // 1e-4 or better at 0-45, 8e-4 at 60; convergence in crack.md and convergence.md).
        for angle in [0.0, 15.0, 30.0, 45.0, 60.0] {
            let (f1, f2, g) = remote(&solver(angle, 160));
            let k2 = f1 * f1 + f2 * f2;
            println!("{angle}: F_I {f1:.5} F_II {f2:.5} energy {g:.6} factors {k2:.6}");
            assert!((g / k2 - 1.0).abs() < 1e-3, "{angle}: {g} {k2}");
            // Both modes act on inclined cracks.
            assert!(angle == 0.0 || (f1 > 0.1 && f2 > 0.1), "{f1} {f2}");
        }
    }
}

mod nowell_hills {
    use halfplane::crack::graded::GradedCrack;
    use halfplane::crack::{
        default_points, reference, Crack, CrackSolver, FaceState, EDGE_CRACK_FACTOR,
    };
    use halfplane::march::MarchOptions;
    use halfplane::stress::closed_form::NowellHills;
    use halfplane::stress::MarchedTraction;
    use halfplane::{reference as contacts, stress, Material};
    use std::f64::consts::PI;

    /// The crack example's cycle at its peak (point 2: P = 1000, Q = 300, sigma = 60, f = 0.6),
    /// marched on 400 cells: the material, the marched traction and Nowell and Hills' closed form
    /// for the same state.
    fn peak() -> (Material, MarchedTraction, NowellHills) {
        let h = super::under_the_contact::history(300.0, 60.0, 30);
        let contact = contacts::hertz();
        let options = MarchOptions::default().with_cells(400).unwrap();
        let peak = h.loads().len() - 30; // the end of the last rising half: point 2
        let kept = stress::marched(&contact, &h, &options, &[peak])
            .unwrap()
            .remove(0);
        assert!((kept.load.shear() - 300.0).abs() < 1e-9);
        let nh = NowellHills::hertz(kept.half_width, 0.6, 1000.0, 300.0, 60.0);
        (contact.material(), kept, nh)
    }

    #[test]
    fn trailing_edge_cracks_under_the_published_partial_slip_field() {
        // The crack example's cycle at its peak (P = 1000, Q = 300, sigma = 60, f = 0.6): the
        // steady traction there is Nowell and Hills' monotonic partial-slip traction (1987), whose
        // stress field is published in closed form (stress::closed_form::NowellHills). A crack
        // normal to the surface at the trailing edge x = -a, open there: K_I of the whole chain
        // (march, stress, dislocations) against the weight function over the closed-form sxx,
        // within 0.5% (the weight function's own 0.06-0.22% and the march's trailing-edge stress,
        // -1.3e-3 p0 at 400 cells). As the crack shortens K_I/(sqrt(pi l)) tends to 1.1215 times
        // the closed form's trailing-edge peak, slowly (printed: the stress falls steeply below
        // the edge).
        let (material, kept, nh) = peak();
        let a = kept.half_width;
        let increments = [(&kept.traction, kept.load.bulk())];
        println!("| l (mm) | K_I here | K_I closed form + weight function | difference |");
        for l in [0.002, 0.005, 0.01, 0.02, 0.05, 0.1, 0.2] {
            let s = CrackSolver::new(&Crack::new(-a, 0.0, l).unwrap(), &material, 40).unwrap();
            let f = &stress::fields(&increments, &material, s.x(), s.z()).unwrap()[0];
            let (normal, shear): (Vec<f64>, Vec<f64>) = (0..f.len())
                .map(|i| s.resolve(f.sxx[i], f.szz[i], f.sxz[i]))
                .unzip();
            let out = &s.cycle(&[(normal, shear)], 0.0).unwrap()[0];
            assert!(out.states.iter().all(|s| *s == FaceState::Open), "{l}");
            let k1 = out.factors.k1;
            let expect: f64 = reference::edge_crack_weights(l, 64)
                .unwrap()
                .iter()
                .map(|(z, w)| w * nh.stress(-a, *z)[0])
                .sum();
            println!(
                "| {l} | {k1:.3} | {expect:.3} | {:+.3}% |",
                100.0 * (k1 / expect - 1.0)
            );
            assert!((k1 / expect - 1.0).abs() < 5e-3, "{l}: {k1} {expect}");
            // The steep gradient at the edge: the short-crack limit is approached slowly.
            let limit = EDGE_CRACK_FACTOR * nh.trailing_edge_peak() * (PI * l).sqrt();
            println!("  K_I / (1.1215 sxx(-a, 0) sqrt(pi l)) = {:.4}", k1 / limit);
        }
    }

    #[test]
    fn inclined_cracks_under_the_published_partial_slip_field() {
        // The same peak and the same trailing edge, cracks at -60 to 60 degrees (negative: away
        // from the contact): K_I and K_II of the whole chain (march, stress, the Gauss-Jacobi
        // solution with its default points) against the graded solution under the closed-form
        // field, where the weight function (normal cracks only) cannot reach. Within 1% of |K|:
        // measured at most 0.62% (-60 degrees, 0.1 mm, where 80 points leave 0.4% on their own,
        // see crack::graded's test), 0.2% or less from -45 to 45 degrees. Every crack here is
        // open at this peak (checked); 60 degrees at 0.1 mm closes and is left out.
        let (material, kept, nh) = peak();
        let a = kept.half_width;
        let increments = [(&kept.traction, kept.load.bulk())];
        println!(
            "| angle | l (mm) | K_I, K_II here | graded, closed-form field | difference / abs(K) |"
        );
        for (angle, l) in [
            (-60.0_f64, 0.1),
            (-60.0, 0.005),
            (-30.0, 0.1),
            (0.0, 0.02),
            (30.0, 0.1),
            (45.0, 0.02),
            (60.0, 0.02),
        ] {
            let crack = Crack::new(-a, angle.to_radians(), l).unwrap();
            let s = CrackSolver::new(&crack, &material, default_points(angle)).unwrap();
            let f = &stress::fields(&increments, &material, s.x(), s.z()).unwrap()[0];
            let (normal, shear): (Vec<f64>, Vec<f64>) = (0..f.len())
                .map(|i| s.resolve(f.sxx[i], f.szz[i], f.sxz[i]))
                .unzip();
            let out = &s.cycle(&[(normal, shear)], 0.0).unwrap()[0];
            assert!(
                out.states.iter().all(|s| *s == FaceState::Open),
                "{angle} {l}"
            );
            let k = out.factors;
            let g = GradedCrack::solve(&crack, &super::graded::mesh(), |x, z| nh.stress(x, z))
                .unwrap()
                .tip_factors();
            let size = g.k1.hypot(g.k2);
            let (d1, d2) = ((k.k1 - g.k1) / size, (k.k2 - g.k2) / size);
            println!(
                "| {angle} | {l} | {:.3}, {:.3} | {:.3}, {:.3} | {:+.3}%, {:+.3}% |",
                k.k1,
                k.k2,
                g.k1,
                g.k2,
                100.0 * d1,
                100.0 * d2
            );
            assert!(d1.abs() < 1e-2 && d2.abs() < 1e-2, "{angle} {l}: {d1} {d2}");
        }
    }
}

/// The open crack solved a second way (`crack::graded`: piecewise polynomials on panels graded
/// towards the mouth, product integration of the Cauchy part, the factors from the opening at the
/// tip) against the exact factors, against the stress ahead of its own tip, and against the
/// Gauss-Jacobi solution of `CrackSolver` for inclined cracks, where no published table was
/// found to compare with (crack.md, "Inclined edge crack under remote tension").
mod graded {
    use super::solver;
    use halfplane::crack::graded::{GradedCrack, GradedMesh};
    use halfplane::crack::{default_points, Crack, EDGE_CRACK_FACTOR};
    use std::f64::consts::PI;

    /// The mesh of the comparisons: 41 panels halving towards the mouth (the first 9e-13 of the
    /// crack long), 12 points each. At 75 degrees, the hardest case, it agrees with meshes of
    /// ratio 0.3 and 0.7 and 16 points within 3e-6 (crack_convergence.rs).
    pub fn mesh() -> GradedMesh {
        GradedMesh::new(40, 12, 0.5).unwrap()
    }

    /// `(F_I, F_II)` of the graded solution of a unit crack under the uncracked `stress`.
    pub fn factors(angle_degrees: f64, stress: impl Fn(f64, f64) -> [f64; 3]) -> (f64, f64) {
        let crack = Crack::new(0.0, angle_degrees.to_radians(), 1.0).unwrap();
        let k = GradedCrack::solve(&crack, &mesh(), stress)
            .unwrap()
            .tip_factors();
        (k.k1 / PI.sqrt(), k.k2 / PI.sqrt())
    }

    #[test]
    fn the_graded_solution_against_the_exact_factors() {
        // Normal crack: uniform tension against Koiter's 1.1215222553 (measured 5e-9), uniform
        // shear gives the same factor in mode II (the same kernel on the crack line), linear
        // normal loads against 0.68286288 (zero at the mouth) and 0.43865938 (zero at the tip),
        // Tada, Paris and Irwin's 0.683 and 0.439 to the digits the Gauss-Jacobi solution
        // converges to. The face load `sxx(z)` is applied as the uncracked stress at depth z.
        let (f1, f2) = factors(0.0, |_, _| [1.0, 0.0, 0.0]);
        assert!(
            (f1 - EDGE_CRACK_FACTOR).abs() < 1e-7 && f2.abs() < 1e-12,
            "{f1} {f2}"
        );
        let (f1, f2) = factors(0.0, |_, _| [0.0, 0.0, 1.0]);
        assert!(
            f1.abs() < 1e-12 && (f2 - EDGE_CRACK_FACTOR).abs() < 1e-7,
            "{f1} {f2}"
        );
        let (up, _) = factors(0.0, |_, z| [z, 0.0, 0.0]);
        let (down, _) = factors(0.0, |_, z| [1.0 - z, 0.0, 0.0]);
        println!("uniform {f2:.9} up {up:.9} down {down:.9}");
        assert!((up - 0.682_862_88).abs() < 1e-7, "{up}");
        assert!((down - 0.438_659_38).abs() < 1e-7, "{down}");
    }

    #[test]
    fn the_factors_are_the_limit_of_the_stress_ahead_of_the_tip() {
        // K_I = lim sqrt(2 pi r) s_nn and K_II = lim sqrt(2 pi r) tau on the line ahead of the
        // tip (their definitions and signs, crack.md), from the stress the solution carries
        // there, against the factors from the opening at the tip. The limit is taken from
        // r = 1e-6, 4e-6 and 1.6e-5 of the length, removing the sqrt(r) and r terms
        // (Richardson); measured to 1e-8.
        for angle in [-60.0_f64, 0.0, 30.0, 75.0] {
            let crack = Crack::new(0.0, angle.to_radians(), 1.0).unwrap();
            let g = GradedCrack::solve(&crack, &mesh(), |_, _| [1.0, 0.0, 0.0]).unwrap();
            let k = g.tip_factors();
            let (sin, cos) = angle.to_radians().sin_cos();
            // The uncracked traction on the line: s_nn = cos^2, tau = sin cos.
            let scaled = |r: f64| {
                let (n, t) = g.traction_ahead(r);
                let w = (2.0 * PI * r).sqrt();
                (w * (n + cos * cos), w * (t + sin * cos))
            };
            let limit = |f: [f64; 3]| (4.0 * (2.0 * f[0] - f[1]) - (2.0 * f[1] - f[2])) / 3.0;
            let f: Vec<(f64, f64)> = [1e-6, 4e-6, 1.6e-5].map(scaled).to_vec();
            let k1 = limit([f[0].0, f[1].0, f[2].0]);
            let k2 = limit([f[0].1, f[1].1, f[2].1]);
            println!("{angle}: K_I {k1:.9} {:.9} K_II {k2:.9} {:.9}", k.k1, k.k2);
            let scale = k.k1.hypot(k.k2);
            assert!((k1 - k.k1).abs() < 1e-6 * scale, "{angle}: {k1} {}", k.k1);
            assert!((k2 - k.k2).abs() < 1e-6 * scale, "{angle}: {k2} {}", k.k2);
        }
    }

    #[test]
    fn inclined_edge_cracks_against_the_graded_solution() {
        // Remote tension sxx = 1. The Gauss-Jacobi solution with its default points (40 to 45
        // degrees, 80 to 60, 160 beyond) against the graded one, within 0.6% of the larger
        // factor: measured at most 0.43% (F_I at 60 degrees) and 0.48% (F_I at 75), where the
        // mouth's non-smooth density slows the global rule (crack.md). The criterion is
        // 1% against a handbook. Both modes, each relative to the larger factor so that a small
        // F_II at a small angle does not inflate the measure; the sign of each is checked too.
        println!("| angle | graded F_I, F_II | default points F_I, F_II | differences |");
        for angle in [0.0, 15.0, 30.0, 45.0, 60.0, 75.0] {
            let (g1, g2) = factors(angle, |_, _| [1.0, 0.0, 0.0]);
            let s = solver(angle, default_points(angle));
            let (n, t): (Vec<f64>, Vec<f64>) = s
                .distances()
                .iter()
                .map(|_| s.resolve(1.0, 0.0, 0.0))
                .unzip();
            let k = s.open(&n, &t).unwrap();
            let f = (PI * s.crack().length()).sqrt();
            let (h1, h2) = (k.k1 / f, k.k2 / f);
            let scale = g1.max(g2.abs());
            let (d1, d2) = ((h1 - g1) / scale, (h2 - g2) / scale);
            println!(
                "| {angle} | {g1:.6}, {g2:.6} | {h1:.6}, {h2:.6} | {:+.3}%, {:+.3}% |",
                100.0 * d1,
                100.0 * d2
            );
            assert!(d1.abs() < 6e-3 && d2.abs() < 6e-3, "{angle}: {d1} {d2}");
            assert!(g1 > 0.0 && (angle == 0.0 || g2 > 0.0) && h2 * g2 >= 0.0);
        }
    }
}

/// A length the crack rejects is one its message calls invalid: 1e-30 (the input range's lower
/// end, > 0) was refused with "must be a crack length > 0".
#[test]
fn crack_lengths_follow_the_input_range_the_message_states() {
    assert!(Crack::new(0.0, 0.0, 1e-30).is_ok());
    assert!(Crack::new(0.0, 0.0, 1e30).is_ok());
    for bad in [0.0, -1.0, 9e-31, 1.1e30, f64::NAN, f64::INFINITY] {
        let e = Crack::new(0.0, 0.0, bad).unwrap_err().to_string();
        assert!(
            e.contains("crack.lengths") && e.contains("1e-30 to 1e30"),
            "{bad}: {e}"
        );
    }
}
