//! Fretting wear (docs/wear.md) against what is known exactly: no wear where the surfaces stick,
//! the energy law as Archard's over f, the first cycle's dissipation as the plain march's, and
//! the gross-sliding scar of a cylinder tending to the rigid one (the pressure to uniform).

use halfplane::closed_form;
use halfplane::history::{History, Ramp};
use halfplane::march::{self, MarchOptions, Worn};
use halfplane::wear::{self, Law, WearOptions, WearResult};
use halfplane::{reference, LoadPoint};

const P: f64 = 1000.0;
const Q: f64 = 300.0;

fn fretting() -> History {
    let a = LoadPoint::new("a", P, -Q, 0.0).unwrap();
    let b = LoadPoint::new("b", P, Q, 0.0).unwrap();
    History::in_phase(a, b, 1, 20, Ramp::NormalFirst, 10).unwrap()
}

fn partial_slip(law: Law, coefficient: f64, cells: usize) -> WearResult {
    let options = MarchOptions::default().with_cells(cells).unwrap();
    let mut worn = Worn::new(&reference::hertz(), &fretting(), &options, 2.0).unwrap();
    let wear = WearOptions::logarithmic(law, coefficient, 1_000_000, 7).unwrap();
    wear::run(&mut worn, &wear, |_| {}).unwrap()
}

#[test]
fn the_stick_zone_never_wears_and_the_contact_shrinks_onto_it() {
    let r = partial_slip(Law::Archard, 1e-7, 400);
    let contact = reference::hertz();
    let a = closed_form::hertz_half_width(contact.compliance().value(), reference::RADIUS, P);
    let c = closed_form::cattaneo_mindlin_stick_half_width(a, reference::FRICTION, P, Q);
    for cp in &r.checkpoints {
        let f = &cp.fields;
        let w = f.x[1] - f.x[0];
        let zone = cp.stick.unwrap();
        // The stick zone is Cattaneo's while the annuli wear: located to its cell.
        assert!(
            (zone[0] + c).abs() < w && (zone[1] - c).abs() < w,
            "cycle {}: stick zone {zone:?}, Cattaneo-Mindlin +-{c}",
            cp.cycle
        );
        for (x, d) in f.x.iter().zip(&f.depth) {
            if x.abs() < c - w {
                assert_eq!(
                    *d, 0.0,
                    "cycle {}: wear at x = {x} inside the stick zone",
                    cp.cycle
                );
            }
        }
    }
    // Worn out of contact, the annuli stop slipping: the stick zone carries the load alone and
    // nothing more is dissipated (q/p at its punch-like edges is Q/P < f). Exact theory gets
    // there only asymptotically (an annulus's pressure decays like its wear rate), so the
    // tolerances are what the tail leaves; 1e-3 of each (the example's 1e6 cycles leave none,
    // docs/wear.md).
    let last = r.checkpoints.last().unwrap();
    let first = &r.checkpoints[0];
    assert!(
        last.energy_per_cycle < 1e-3 * first.energy_per_cycle,
        "still dissipating after 1e6 cycles: {} of the first cycle's energy",
        last.energy_per_cycle / first.energy_per_cycle
    );
    let f = &last.fields;
    let w = f.x[1] - f.x[0];
    let outside: f64 =
        f.x.iter()
            .zip(&f.pressure)
            .filter(|(x, _)| x.abs() > c + w)
            .map(|(_, p)| p * w)
            .sum();
    assert!(
        outside < 1e-3 * P,
        "the worn annuli still carry {outside} of P = {P} after 1e6 cycles"
    );
    // 1e6 cycles in a few thousand marches: while the annuli carry load the jumps are held to
    // the stability bound (hundreds of cycles here, docs/wear.md), and once nothing slips they
    // run to the next checkpoint.
    assert!(
        r.simulated_cycles < 5_000,
        "{} cycles marched",
        r.simulated_cycles
    );
}

#[test]
fn the_energy_law_is_archards_over_the_friction_coefficient() {
    // dh = alpha f p |ds| is Archard's k p |ds| with k = alpha f: the same depths to rounding
    // (1e-12 of the largest: the two multiply the same sums in a different order).
    let alpha = 2e-7;
    let energy = partial_slip(Law::Energy, alpha, 200);
    let archard = partial_slip(Law::Archard, alpha * reference::FRICTION, 200);
    for (e, a) in energy.checkpoints.iter().zip(&archard.checkpoints) {
        let scale = e.max_depth.max(f64::MIN_POSITIVE);
        for (de, da) in e.fields.depth.iter().zip(&a.fields.depth) {
            assert!(
                (de - da).abs() <= 1e-12 * scale,
                "cycle {}: {de} vs {da}",
                e.cycle
            );
        }
        // The energy law's volume is alpha times the dissipated energy, jumps included.
        let v = alpha * e.dissipated_energy;
        assert!((e.wear_volume - v).abs() <= 1e-12 * v, "cycle {}", e.cycle);
    }
}

#[test]
fn the_first_cycle_dissipates_what_the_plain_march_does() {
    // Cycle 1 over the unworn gap: the grid's normal problem (gap.rs) in place of the profile's
    // closed form. The energy per cycle agrees to 0.1%: it is carried by the slip annuli, where
    // the grid's pressure is within 1e-5 p0 of Hertz; the last cell at each edge (1.4%) carries
    // little of it.
    let cells = 400;
    let options = MarchOptions::default().with_cells(cells).unwrap();
    let r = partial_slip(Law::Archard, 1e-9, cells);
    let plain = march::march(&reference::hertz(), &fretting(), &options, |_, _| {}).unwrap();
    let (worn, exact) = (r.checkpoints[0].energy_per_cycle, plain.cycles[0].energy);
    assert!(
        (worn - exact).abs() < 1e-3 * exact,
        "worn march {worn}, march {exact}"
    );
}

#[test]
fn a_sliding_cylinder_wears_a_scar_tending_to_the_rigid_one() {
    // Gross sliding of the Hertz cylinder, Archard: every contact cell slips the same distance,
    // so wear goes on until it is uniform, the pressure uniform, and the worn cylinder meets the
    // counterface on a flat of half-width a with V = 2 a^3 / (3 R) (the rigid scar). The elastic
    // part of the contact shrinks in proportion as the scar grows: within 3% of the rigid
    // half-width once the depth is ten times the elastic approach.
    let contact = reference::hertz();
    let options = MarchOptions::default().with_cells(400).unwrap();
    let load = LoadPoint::new("load", P, 0.0, 0.0).unwrap();
    let mut worn = Worn::sliding(&contact, load, 0.01, 10, 10, &options, 8.0).unwrap();
    let wear = WearOptions::logarithmic(Law::Archard, 1e-7, 100_000, 6).unwrap();
    let r = wear::run(&mut worn, &wear, |_| {}).unwrap();
    let mut before = f64::INFINITY;
    for cp in &r.checkpoints {
        assert!(
            cp.stick.is_none(),
            "cycle {}: gross sliding has no stick zone",
            cp.cycle
        );
        let rigid = (1.5 * cp.wear_volume * reference::RADIUS).cbrt();
        let ratio = 0.5 * (cp.contact[1] - cp.contact[0]) / rigid;
        assert!(
            ratio < before,
            "cycle {}: contact over rigid scar {ratio}, before {before}",
            cp.cycle
        );
        before = ratio;
    }
    let last = r.checkpoints.last().unwrap();
    assert!(
        last.max_depth > 10.0 * r.elastic_approach,
        "depth {}",
        last.max_depth
    );
    assert!(
        (before - 1.0).abs() < 0.03,
        "contact over rigid scar {before} after 1e5 cycles"
    );
    // The pressure tends to uniform: peak over mean from Hertz's 4/pi. It first rises (the
    // worn flat's edges take load: 1.37 after 1e3 cycles in examples/wear-sliding.toml), then
    // falls (1.12 there after 1e5, converged in the jump bound: docs/convergence.md).
    let uniformity = |cp: &wear::Checkpoint| cp.peak_pressure * (cp.contact[1] - cp.contact[0]) / P;
    // Unworn: the contact's ends are cell edges, a cell of the 50 across it (2%).
    let first = uniformity(&r.checkpoints[0]);
    assert!(
        (first * std::f64::consts::PI / 4.0 - 1.0).abs() < 2e-2,
        "unworn peak over mean {first}, Hertz 4/pi"
    );
    // Here (a coarser grid than the example's, 50 cells across the unworn contact) 1.205 after
    // 1e5 cycles: asserted at least 0.05 below the unworn ratio, on its way to 1.
    let end = uniformity(last);
    assert!(
        end < first - 0.05 && end > 1.0,
        "peak over mean {end} after 1e5 cycles, unworn {first}: not tending to uniform"
    );
}

#[test]
fn jumps_stay_within_the_stability_bound_so_the_worn_profile_stays_smooth() {
    // Gross sliding of the Hertz cylinder with a loose depth bound (0.1 of the elastic
    // approach): the depth bound alone would take jumps of 565 cycles, 3.3 times the cycles at
    // which the cell-to-cell mode of the worn profile grows (forward Euler on the depth, with
    // the grid's stiffest pressure response pi^2/(4 C A w), C Catalan's constant: docs/wear.md,
    // "Cycle jumping"). Without the stability bound this run ends on a checkerboard, every other
    // contact cell at zero pressure (checked by hand, raising the bound's number, `STABILITY`,
    // from 1 to 1e9: 34 zero-pressure cells inside the contact). With it the pressure stays
    // positive across the contact and mirror symmetric to rounding (1e-9 of the peak; the
    // symmetric grid mirrors the problem).
    let contact = reference::hertz();
    let options = MarchOptions::default().with_cells(400).unwrap();
    let load = LoadPoint::new("load", P, 0.0, 0.0).unwrap();
    let mut worn = Worn::sliding(&contact, load, 0.02, 10, 10, &options, 8.0).unwrap();
    let wear = WearOptions::new(Law::Archard, 3e-8, 30_000, &[30_000])
        .unwrap()
        .with_max_depth_increment(0.1)
        .unwrap();
    let r = wear::run(&mut worn, &wear, |_| {}).unwrap();
    let f = &r.checkpoints[0].fields;
    let n = f.pressure.len();
    let touching: Vec<usize> = (0..n).filter(|&i| f.pressure[i] > 0.0).collect();
    let (first, last) = (touching[0], touching[touching.len() - 1]);
    let holes = (first..=last).filter(|&i| f.pressure[i] == 0.0).count();
    assert_eq!(
        holes, 0,
        "cells without pressure inside the contact: a checkerboard"
    );
    let peak = f.pressure.iter().copied().fold(0.0, f64::max);
    let lopsided = (0..n)
        .map(|i| (f.pressure[i] - f.pressure[n - 1 - i]).abs())
        .fold(0.0, f64::max);
    assert!(
        lopsided < 1e-9 * peak,
        "mirror cells differ by {lopsided} of a peak {peak}: the worn profile oscillates"
    );
}

#[test]
fn the_sliding_loop_is_mindlins_with_the_slides_and_its_area_the_energy() {
    // Gross sliding of the Hertz cylinder before it wears (a coefficient too small to matter):
    // Q rises to f P (the Cattaneo-Mindlin shift delta_0(f P)), the bodies slide the amplitude,
    // Q falls to -f P along the Mindlin-Deresiewicz branch, they slide back, and so on, so the
    // loop is closed-form between the slides; its area is the energy dissipated.
    let contact = reference::hertz();
    let compliance = contact.compliance().value();
    let a = closed_form::hertz_half_width(compliance, reference::RADIUS, P);
    let f = reference::FRICTION;
    let (amplitude, steps) = (0.01, 20);
    let options = MarchOptions::default().with_cells(400).unwrap();
    let load = LoadPoint::new("load", P, 0.0, 0.0).unwrap();
    let worn = Worn::sliding(&contact, load, amplitude, steps, 10, &options, 2.0).unwrap();
    let datum = 5.0 * a;
    let mut worn = worn.with_loop_datum(datum).unwrap();
    let wear = WearOptions::new(Law::Archard, 1e-15, 1, &[1]).unwrap();
    let r = wear::run(&mut worn, &wear, |_| {}).unwrap();
    let cp = &r.checkpoints[0];
    let first = |q: f64| closed_form::cattaneo_mindlin_displacement(compliance, a, f, P, q, datum);
    let top = cp.fretting_loop[0].shear;
    // Where each branch starts: (Q, delta) at the turning point.
    let mut turn = (top, first(top));
    // The cycle starts at the end of the first rise: Cattaneo-Mindlin's first loading.
    let mut worst = (cp.fretting_loop[0].relative_displacement - turn.1).abs();
    for w in cp.fretting_loop.windows(2) {
        let (before, now) = (w[0], w[1]);
        let expected = if (now.shear.abs() - f * P).abs() < 1e-9 * P {
            // A slide: the same Q, the displacement moved by the amplitude.
            turn = (
                now.shear,
                before.relative_displacement + amplitude * now.shear.signum(),
            );
            turn.1
        } else {
            // Masing: the turning point minus twice the first loading of half the change.
            turn.1 + 2.0 * first(0.5 * (now.shear - turn.0))
        };
        worst = worst.max((now.relative_displacement - expected).abs());
    }
    // Measured at 400 cells: 2.2e-4 of delta_0(f P) at the cycle's start, the end of the first
    // rise (Q = f P (1 - 1e-6), whose stick zone is narrower than a cell: a cell-level answer),
    // 1.0e-4 on the branches (3.3e-5 at 800 cells), which the slides carry round the loop.
    // Tolerance: 1.5 times the start's error.
    assert!(
        worst < 3.3e-4 * first(f * P),
        "the sliding loop is {worst:e} off Mindlin's (delta_0(fP) = {:e})",
        first(f * P)
    );
    let area: f64 = cp
        .fretting_loop
        .windows(2)
        .map(|w| {
            0.5 * (w[0].shear + w[1].shear)
                * (w[1].relative_displacement - w[0].relative_displacement)
        })
        .sum();
    // The trapezoidal rule on 20 increments per half: 2.9e-4 of the energy measured (second
    // order in the step, as in tests/fretting_loop.rs).
    assert!(
        (area - cp.energy_per_cycle).abs() < 1e-3 * cp.energy_per_cycle,
        "the sliding loop's area {area} is not the energy dissipated {}",
        cp.energy_per_cycle
    );
    // The displacement amplitude is half the loop's range: 2 delta_0(f P) plus the amplitude
    // (1.7e-5 measured; the loop points' 2e-4).
    let expected = first(f * P) + 0.5 * amplitude;
    assert!(
        (cp.displacement_amplitude - expected).abs() < 2e-4 * expected,
        "displacement amplitude {} vs {expected}",
        cp.displacement_amplitude
    );
}

#[test]
fn a_coarse_grid_reaches_the_sliding_onset() {
    // 200 cells over six times the unworn contact: 33 across it. There the pressure sampled at
    // the cell centres sums to 0.45% less than P, so Q = f P (1 - 1e-6) exceeds what the cells
    // carry at the friction limit, and the active set used to cycle between all-slip and full
    // stick until it gave up (ActiveSet error). The first rise now stops short of the cells'
    // own limit (the worn gap's pressure carries P exactly), and a stick zone narrower than a
    // cell sticks its nearest cell: the cycle runs and dissipates what a finer grid does.
    let contact = reference::hertz();
    let load = LoadPoint::new("load", P, 0.0, 0.0).unwrap();
    let energy = |cells: usize| {
        let options = MarchOptions::default().with_cells(cells).unwrap();
        let mut worn = Worn::sliding(&contact, load, 0.02, 10, 10, &options, 6.0).unwrap();
        let wear = WearOptions::new(Law::Archard, 1e-15, 2, &[2]).unwrap();
        wear::run(&mut worn, &wear, |_| {}).unwrap().checkpoints[0].energy_per_cycle
    };
    let (coarse, fine) = (energy(200), energy(800));
    assert!(
        (coarse - fine).abs() < 5e-3 * fine,
        "sliding cycle on 33 cells across the contact dissipates {coarse}, on 133 {fine}"
    );
}
