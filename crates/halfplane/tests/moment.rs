//! Moment-loaded and asymmetric contacts in the steady state and in marching, against
//! independent references: the Hertz contact moved by M/P (exact), the Hertz closed form of the
//! stick zone under a changing centroid, mirror symmetry, and time marching (one cell).
//!
//! Tolerances: 1e-10 relative to the contact's size where the reference is exact (the routes
//! converge to rounding, about 1e-14; the margin covers the Newton tolerance of 1e-14 and the
//! normal solve's 1e-15 compounded over a few steps). One cell against marching: the marched
//! stick boundary is a cell edge.

mod common;
use common::*;
use halfplane::evolution::evolve;
use halfplane::history::{History, Ramp};
use halfplane::march::{march, MarchOptions};
use halfplane::steady::{self, Method, Regime, SteadyOptions};
use halfplane::{Contact, Cycle, Edge, Error, GivenPoint, LoadPoint, Profile};

fn with_moment(p: LoadPoint, moment: f64) -> LoadPoint {
    p.with_moment("test", moment).unwrap()
}

fn implicit() -> SteadyOptions {
    SteadyOptions::default().with_method(Method::Implicit)
}

/// The reference cycle with the moments `m1`, `m2`.
fn reference_with(m1: f64, m2: f64) -> Cycle {
    let (p1, p2) = theory_cycle().as_given();
    Cycle::new(with_moment(p1, m1), with_moment(p2, m2))
}

/// Two cycles of Q and sigma between -/+ (q, sigma) at constant P, with the pressure's centroid
/// at `e0` throughout (M = e0 P, the ramp included), 20 increments per half.
fn fixed_centroid(normal: f64, q: f64, sigma: f64, e0: f64) -> History {
    History::in_phase(
        with_moment(point(normal, -q, -sigma), e0 * normal),
        with_moment(point(normal, q, sigma), e0 * normal),
        2,
        20,
        Ramp::NormalFirst,
        10,
    )
    .unwrap()
}

fn close(a: f64, b: f64, scale: f64, what: &str) {
    assert!(
        (a - b).abs() <= 1e-10 * scale,
        "{what}: {a} vs {b} (difference {:.2e} of {scale})",
        (a - b).abs() / scale
    );
}

#[test]
fn hertz_under_a_constant_centroid_is_the_symmetric_solution_moved_by_m_over_p() {
    // M = e0 P at both points: the pressure is the symmetric one moved by e0 and the pad rotates
    // by -e0/R, a rigid shift of the whole problem. Every position moves by e0; every length,
    // intensity and ratio is unchanged. Both routes: the closed form and the general equations.
    let c = contact(Profile::hertz(RADIUS).unwrap());
    let plain = theory_cycle();
    for e0 in [0.2, -0.35] {
        let (p1, p2) = plain.as_given();
        let moved = Cycle::new(
            with_moment(p1, e0 * p1.normal()),
            with_moment(p2, e0 * p2.normal()),
        );
        for options in [SteadyOptions::default(), implicit()] {
            let s = steady::analyse(&c, &plain, &options).unwrap();
            let m = steady::analyse(&c, &moved, &options).unwrap();
            assert_eq!(m.regime, s.regime);
            let scale = s.half_width.first;
            for p in GivenPoint::BOTH {
                let (cs, cm) = (s.contacts[p], m.contacts[p]);
                for e in Edge::BOTH {
                    close(cm.end(e), cs.end(e) + e0, scale, "contact end");
                    let k = cs.normal_intensity(e);
                    close(cm.normal_intensity(e), k, k, "K_N");
                }
                close(cm.rotation(), -e0 / RADIUS, 1.0 / RADIUS, "rotation -e0/R");
            }
            let (zs, zm) = (s.stick_zone.unwrap(), m.stick_zone.unwrap());
            close(zm.left, zs.left + e0, scale, "stick zone left");
            close(zm.right, zs.right + e0, scale, "stick zone right");
            let (ws, wm) = (s.slip_zones.unwrap(), m.slip_zones.unwrap());
            for e in Edge::BOTH {
                for p in GivenPoint::BOTH {
                    close(wm[e][p], ws[e][p], scale, "slip zone");
                }
            }
            let (rs, rm) = (s.criteria.full_stick_ratio, m.criteria.full_stick_ratio);
            close(rm, rs, rs, "full-stick ratio");
        }
        // The evolution along the cycle moves with it too.
        let es = evolve(&c, &plain, 9, &SteadyOptions::default()).unwrap();
        let em = evolve(&c, &moved, 9, &SteadyOptions::default()).unwrap();
        for (ps, pm) in es.points.iter().zip(&em.points) {
            close(
                pm.stick_zone.left,
                ps.stick_zone.left + e0,
                1.0,
                "evolution left",
            );
            close(
                pm.stick_zone.right,
                ps.stick_zone.right + e0,
                1.0,
                "evolution right",
            );
        }
        assert_eq!(em.warnings, es.warnings);
    }
}

#[test]
fn a_changing_centroid_moves_the_hertz_stick_zone_by_the_mean_centroid() {
    // Hertz: the slope g' + theta_m with theta_m = -(e1 + e2)/(2R) is the Hertz slope about
    // (e1 + e2)/2, so the zone is the paper's, moved by the mean centroid:
    // e = (e1 + e2)/2 - A R dsigma/(8f), d^2 = (A R/pi)(P1 + P2 - dQ/f). The general equations
    // (Method::Implicit, Newton on the slope integrals) must give the same.
    let c = contact(Profile::hertz(RADIUS).unwrap());
    let a_comp = c.compliance().value();
    for (m1, m2) in [(100.0, 160.0), (-150.0, -100.0), (0.0, 40.0)] {
        let cycle = reference_with(m1, m2);
        let closed = steady::analyse(&c, &cycle, &SteadyOptions::default()).unwrap();
        let general = steady::analyse(&c, &cycle, &implicit()).unwrap();
        let (p1, p2) = (cycle.low(), cycle.high());
        let mean = 0.5 * (p1.centroid() + p2.centroid());
        let e = mean - a_comp * RADIUS * cycle.bulk_range() / (8.0 * 0.6);
        let d = (a_comp * RADIUS / std::f64::consts::PI
            * (p1.normal() + p2.normal() - cycle.shear_range() / 0.6))
            .sqrt();
        for s in [&closed, &general] {
            let z = s.stick_zone.unwrap();
            close(z.eccentricity(), e, d, "eccentricity");
            close(z.half_width(), d, d, "half-width");
        }
    }
}

/// The mirror image of a cycle: x -> -x takes M to -M and Q to -Q, and keeps sigma: a bulk
/// stress sigma_xx is unchanged by the reflection (the relative displacement `A sigma x/4`
/// becomes `-A sigma (-x)/4`, the same), as the paper's `K_T = Q/(pi sqrt(2a)) +/- (sigma/4)
/// sqrt(a/2)` shows: exchanging the edges and reversing q maps it to itself with Q -> -Q and
/// sigma unchanged.
fn mirrored(cycle: &Cycle) -> Cycle {
    let (p1, p2) = cycle.as_given();
    let flip = |p: LoadPoint| with_moment(point(p.normal(), -p.shear(), p.bulk()), -p.moment());
    Cycle::new(flip(p1), flip(p2))
}

#[test]
fn mirror_image_swaps_the_edges() {
    // A flat punch with unequal edge radii and moment, and its mirror image (radii swapped, M and
    // Q reversed, sigma kept, see `mirrored`): every zone is reflected, left and right
    // exchanged. Exact by symmetry, so both analyses must agree to the solvers' tolerance.
    let c = contact(Profile::flat_rounded_asymmetric(0.3, 40.0, 70.0).unwrap());
    let m = contact(Profile::flat_rounded_asymmetric(0.3, 70.0, 40.0).unwrap());
    let cycle = Cycle::new(
        with_moment(point(1000.0, -250.0, -20.0), 60.0),
        with_moment(point(1400.0, 250.0, 20.0), 150.0),
    );
    let s = steady::analyse(&c, &cycle, &SteadyOptions::default()).unwrap();
    let r = steady::analyse(&m, &mirrored(&cycle), &SteadyOptions::default()).unwrap();
    assert_eq!(s.regime, Regime::PartialSlip);
    assert_eq!(r.regime, s.regime);
    let scale = s.half_width.first;
    let (zs, zr) = (s.stick_zone.unwrap(), r.stick_zone.unwrap());
    close(zr.left, -zs.right, scale, "mirrored stick zone left");
    close(zr.right, -zs.left, scale, "mirrored stick zone right");
    let (ws, wr) = (s.slip_zones.unwrap(), r.slip_zones.unwrap());
    for p in GivenPoint::BOTH {
        close(wr.left[p], ws.right[p], scale, "mirrored slip left");
        close(wr.right[p], ws.left[p], scale, "mirrored slip right");
        close(
            r.contacts[p].end(Edge::Left),
            -s.contacts[p].end(Edge::Right),
            scale,
            "mirrored contact",
        );
    }
}

/// The stick zone at the end of each half of the second of two in-phase cycles, marched.
fn marched_zones(c: &Contact, cycle: &Cycle, cells: usize, steps: usize) -> (f64, [[f64; 2]; 2]) {
    let (p1, p2) = cycle.as_given();
    let history = History::in_phase(p1, p2, 2, steps, Ramp::NormalFirst, 10).unwrap();
    let r = march(
        c,
        &history,
        &MarchOptions::default().with_cells(cells).unwrap(),
        |_, _| {},
    )
    .unwrap();
    let start = history.cycles().unwrap().first_step() + 2 * steps;
    let w = r.x[1] - r.x[0];
    let zone = |k: usize| r.steps[k].largest_stick().unwrap();
    (w, [zone(start + steps - 1), zone(start + 2 * steps - 1)])
}

#[test]
fn steady_agrees_with_marching_when_the_centroid_moves_along_the_cycle() {
    // Hertz and a flat punch with unequal radii, with M/P changing along the cycle: the
    // permanent stick zone of the analysis against the stick zone marched at both ends of the
    // steady cycle, within one cell at 800 cells.
    let cases = [
        (
            contact(Profile::hertz(RADIUS).unwrap()),
            reference_with(50.0, 120.0),
        ),
        (
            contact(Profile::flat_rounded_asymmetric(0.3, 40.0, 70.0).unwrap()),
            Cycle::new(
                with_moment(point(1000.0, -250.0, -20.0), 60.0),
                with_moment(point(1400.0, 250.0, 20.0), 150.0),
            ),
        ),
    ];
    for (c, cycle) in cases {
        let s = steady::analyse(&c, &cycle, &SteadyOptions::default()).unwrap();
        let z = s.stick_zone.unwrap();
        let (w, zones) = marched_zones(&c, &cycle, 800, 40);
        for [l, r] in zones {
            assert!(
                (l - z.left).abs() <= w && (r - z.right).abs() <= w,
                "{:?}: marched [{l:.5}, {r:.5}] vs steady [{:.5}, {:.5}], cell {w:.5}",
                c.profile().shape(),
                z.left,
                z.right
            );
        }
    }
}

#[test]
fn a_moment_beyond_a_table_is_refused_naming_the_point() {
    // A table from -1 to 1: at P = 1000 the contact (a ~ 0.76 for Hertz R = 50) leaves it when
    // its centroid passes about 0.25. The error names the point's moment and the valid range.
    let x: Vec<f64> = (0..=40).map(|i| -1.0 + 0.05 * i as f64).collect();
    let g = x.iter().map(|x| x * x / (2.0 * RADIUS)).collect();
    let c = contact(Profile::tabulated(x, g, vec![]).unwrap());
    let cycle = reference_with(0.0, 900.0);
    let err = steady::analyse(&c, &cycle, &SteadyOptions::default()).unwrap_err();
    let Error::MomentOutsideTable {
        field,
        value,
        largest,
        ..
    } = err
    else {
        panic!("{err:?}");
    };
    assert_eq!(field, "cycle.point2.moment");
    assert_eq!(value, 900.0);
    assert!(largest < 900.0 && largest > 0.0, "largest {largest}");
}

#[test]
fn the_edge_test_under_a_moment_is_where_marching_stops_slipping_at_the_start_of_a_half() {
    // Hertz, (1000, -250, 0, M = 0) -> (1400, 250, 0, M2). At the start of the rising half the
    // right edge's pressure coefficient changes by dP_right = dP + 2 dM/a1 (c = 0 at point 1), so
    // slip starts there only while dS = dQ = 500 > f dP_right, i.e. M2 < (dQ/f - dP) a1/2 =
    // 164.9. Below it the analysis is accepted and marching slips at the right edge from the
    // first increment; above it the analysis refuses the cycle, naming half 1 and the right edge,
    // and marching shows the right edge sticking (no slip zone, within half a cell) over the
    // first increments: the assumption the analysis needs does fail there.
    let c = contact(Profile::hertz(RADIUS).unwrap());
    let a1 = c.half_width(1000.0).unwrap();
    let boundary = (500.0 / 0.6 - 400.0) * a1 / 2.0;
    assert!((boundary - 164.9).abs() < 0.1, "{boundary}");
    for (m2, accepted) in [(150.0, true), (200.0, false)] {
        let cycle = Cycle::new(
            point(1000.0, -250.0, 0.0),
            with_moment(point(1400.0, 250.0, 0.0), m2),
        );
        let verdict = steady::analyse(&c, &cycle, &SteadyOptions::default());
        match (&verdict, accepted) {
            (Ok(s), true) => assert_eq!(s.regime, Regime::PartialSlip),
            (
                Err(Error::SlipReversesInHalf {
                    half: halfplane::Half::First,
                    edge: Edge::Right,
                    fraction,
                    ..
                }),
                false,
            ) => assert_eq!(*fraction, 0.0),
            _ => panic!("M2 = {m2}: {verdict:?}"),
        }
        let steps = 40;
        let history =
            History::in_phase(cycle.low(), cycle.high(), 2, steps, Ramp::NormalFirst, 10).unwrap();
        let r = march(
            &c,
            &history,
            &MarchOptions::default().with_cells(400).unwrap(),
            |_, _| {},
        )
        .unwrap();
        let w = r.x[1] - r.x[0];
        let start = history.cycles().unwrap().first_step() + 2 * steps;
        // The second cycle's rising half: its first three increments.
        let right_slip: Vec<f64> = r.steps[start..start + 3]
            .iter()
            .map(|s| (s.ends.right - s.largest_stick().unwrap()[1]) / w)
            .collect();
        if accepted {
            assert!(
                right_slip.iter().all(|&cells| cells > 1.0),
                "M2 = {m2}: the right edge must slip from the start: {right_slip:?} cells"
            );
        } else {
            assert!(
                right_slip.iter().all(|&cells| cells < 0.5),
                "M2 = {m2}: the right edge sticks at the start: {right_slip:?} cells"
            );
        }
    }
}

#[test]
fn matching_takes_the_chosen_edges_intensity_and_a_moved_hertz_contact_matches_as_centred() {
    use halfplane::matching::{match_cycle, match_cycle_at, Mode};
    let hertz = contact(Profile::hertz(RADIUS).unwrap());
    let test = contact(Profile::hertz(80.0).unwrap());
    // A Hertz prototype under a constant centroid is the centred one moved: whichever edge is
    // matched, the test (without a moment) is the centred prototype's test, to rounding.
    let plain = theory_cycle();
    let (p1, p2) = plain.as_given();
    let moved = Cycle::new(
        with_moment(p1, 0.2 * p1.normal()),
        with_moment(p2, 0.2 * p2.normal()),
    );
    let reference = match_cycle(&hertz, &plain, &test, Mode::Asymptotic).unwrap();
    for edge in Edge::BOTH {
        let m = match_cycle_at(&hertz, &moved, &test, Mode::Asymptotic, Some(edge)).unwrap();
        let (a, b) = (m.test.cycle.as_given(), reference.test.cycle.as_given());
        for (x, y) in [(a.0, b.0), (a.1, b.1)] {
            close(x.normal(), y.normal(), y.normal(), "matched P");
            close(x.shear(), y.shear(), y.normal(), "matched Q");
            close(x.bulk(), y.bulk(), y.bulk().abs().max(1.0), "matched sigma");
        }
    }
    // The dovetail-like pad: K_N differs at its edges; the test takes the chosen edge's, and K_T
    // at both edges still match.
    let pad = contact(Profile::flat_rounded_asymmetric(0.3, 40.0, 70.0).unwrap());
    let cycle = Cycle::new(
        with_moment(point(1000.0, -250.0, -20.0), 60.0),
        with_moment(point(1400.0, 250.0, 20.0), 150.0),
    );
    let mut tests = Vec::new();
    for edge in Edge::BOTH {
        let m = match_cycle_at(&pad, &cycle, &test, Mode::Asymptotic, Some(edge)).unwrap();
        assert_eq!(m.prototype.edge, edge);
        for p in GivenPoint::BOTH {
            let k = m.prototype.edges[p].contact.normal_intensity(edge);
            close(
                m.normal_intensity[p].test,
                k,
                k,
                "matched K_N at the chosen edge",
            );
            for e in Edge::BOTH {
                let c = m.shear_intensity[e][p];
                close(c.test, c.prototype, c.prototype.abs(), "K_T at both edges");
            }
        }
        tests.push(m.test.cycle.as_given().1.normal());
    }
    // The two edges' K_N differ, so the two tests differ.
    assert!((tests[0] - tests[1]).abs() > 1e-3 * tests[0], "{tests:?}");
    // By default, the edge whose K_T changes more.
    let m = match_cycle(&pad, &cycle, &test, Mode::Asymptotic).unwrap();
    let range = |e: Edge| {
        (m.prototype.edges.second.shear_intensity[e] - m.prototype.edges.first.shear_intensity[e])
            .abs()
    };
    let larger = if range(Edge::Left) >= range(Edge::Right) {
        Edge::Left
    } else {
        Edge::Right
    };
    assert_eq!(m.prototype.edge, larger);
}

#[test]
fn marched_stresses_under_a_moment_have_the_contacts_pressure_at_the_surface() {
    // An off-centre contact (a punch with unequal radii under P and M, pressed alone): the
    // stress field built from the march's traction has szz = -p(x) at the surface, with p the
    // normal problem's own pressure (`Contact::pressure_at`), so the traction's node form carries
    // the moved ends. At every cell centre inside the contact, just below the surface (1e-9 of the
    // contact's size), to 1e-6 of the peak pressure.
    use halfplane::stress;
    let c = contact(Profile::flat_rounded_asymmetric(0.3, 40.0, 70.0).unwrap());
    let load = with_moment(point(1200.0, 0.0, 0.0), 150.0);
    let history = History::from_moment_rows(&[[1200.0, 0.0, 0.0, 150.0]]).unwrap();
    let options = MarchOptions::default().with_cells(200).unwrap();
    let kept = stress::marched(&c, &history, &options, &[1]).unwrap();
    let state = c.contact_at(&load).unwrap();
    assert_eq!(kept[0].ends, state.ends());
    let r = march(&c, &history, &options, |_, _| {}).unwrap();
    let x: Vec<f64> =
        r.x.iter()
            .copied()
            .filter(|&x| x > state.end(Edge::Left) && x < state.end(Edge::Right))
            .collect();
    let z = vec![1e-9 * state.half_width(); x.len()];
    let field = stress::field(&kept[0].traction, 0.0, &c.material(), &x, &z).unwrap();
    let peak = x
        .iter()
        .map(|&x| c.pressure_at(&state, x).unwrap())
        .fold(0.0, f64::max);
    for (i, &xi) in x.iter().enumerate() {
        let p = c.pressure_at(&state, xi).unwrap();
        assert!(
            (field.szz[i] + p).abs() <= 1e-6 * peak,
            "x = {xi}: szz {} against -p {}",
            field.szz[i],
            -p
        );
    }
}

#[test]
fn a_crack_at_the_edge_of_a_moved_hertz_contact_is_the_centred_ones() {
    // Hertz under a constant centroid e0 is the centred contact moved by e0: the crack at its
    // right edge sees the same stress as the centred contact's, so K_I and K_II agree within the
    // marching discretisation (the two grids differ: the moved contact's is spanned from its own
    // ends, 200 cells either way, so 1% of the range is the bound).
    use halfplane::crack::{self, CrackOptions, Position};
    use halfplane::fatigue::FatigueConstants;
    let c = contact(Profile::hertz(RADIUS).unwrap());
    let constants = FatigueConstants::default()
        .with_threshold(160.0)
        .and_then(|k| k.with_endurance_range(700.0))
        .unwrap();
    let e0 = 0.25;
    let options = MarchOptions::default().with_cells(200).unwrap();
    let crack = CrackOptions::new(Position::RightEdge, 0.0, vec![0.05], 0.0).unwrap();
    let history = |e| fixed_centroid(1000.0, 300.0, 60.0, e);
    let centred = crack::analyse(&c, &history(0.0), &options, &constants, &crack).unwrap();
    let moved = crack::analyse(&c, &history(e0), &options, &constants, &crack).unwrap();
    close(
        moved.mouth,
        centred.mouth + e0,
        1.0,
        "the mouth moves with the contact",
    );
    let (a, b) = (&moved.rows[0], &centred.rows[0]);
    for (x, y, what) in [
        (a.delta_k1, b.delta_k1, "dK_I"),
        (a.delta_k2, b.delta_k2, "dK_II"),
    ] {
        assert!(
            (x - y).abs() <= 1e-2 * y.abs().max(1.0),
            "{what}: moved {x} against centred {y}"
        );
    }
}

#[test]
fn fatigue_maxima_of_a_moved_hertz_contact_are_the_centred_ones_moved() {
    // As for the crack: Hertz under a constant centroid e0 is the centred contact moved by e0.
    // The fatigue grid is centred on the cycle's contacts, so its points move with them; every
    // parameter's maximum must agree within the marching discretisation (the grids of the two
    // marches differ: 1% of each value), at the same depth, e0 further along x.
    use halfplane::fatigue::{self, FatigueConstants, FatigueGrid};
    let c = contact(Profile::hertz(RADIUS).unwrap());
    let constants = FatigueConstants::default()
        .with_fatigue_strength(1800.0)
        .and_then(|k| k.with_fatigue_strength_exponent(-0.1))
        .and_then(|k| k.with_fatigue_ductility(0.5))
        .and_then(|k| k.with_fatigue_ductility_exponent(-0.6))
        .and_then(|k| k.with_shear_fatigue_strength(1000.0))
        .and_then(|k| k.with_shear_fatigue_ductility(0.8))
        .and_then(|k| k.with_findley_k(0.25))
        .and_then(|k| k.with_yield_stress(900.0))
        .unwrap();
    let e0 = -0.15;
    let options = MarchOptions::default().with_cells(200).unwrap();
    let grid = FatigueGrid::new(21, 6, 1.5, 0.5).unwrap();
    let history = |e| fixed_centroid(1000.0, 300.0, 40.0, e);
    let a = fatigue::analyse(&c, &history(0.0), &options, &constants, &grid).unwrap();
    let b = fatigue::analyse(&c, &history(e0), &options, &constants, &grid).unwrap();
    close(b.grid_x[10], a.grid_x[10] + e0, 1.0, "the grid's centre");
    assert_eq!(a.parameters.len(), b.parameters.len());
    let step = a.grid_x[1] - a.grid_x[0];
    for (p, m) in a.parameters.iter().zip(&b.parameters) {
        assert_eq!(p.parameter, m.parameter);
        assert!(
            (p.value - m.value).abs() <= 1e-2 * p.value.abs(),
            "{}: centred {} against moved {}",
            p.parameter.name(),
            p.value,
            m.value
        );
        assert!(
            (m.x - (p.x + e0)).abs() <= step + 1e-12 && (m.z - p.z).abs() <= 1e-12,
            "{}: at x = {}, z = {} against {} moved",
            p.parameter.name(),
            m.x,
            m.z,
            p.x
        );
    }
}
