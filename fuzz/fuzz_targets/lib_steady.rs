//! Library entry points on arbitrary floats (finite, huge, tiny, NaN, infinite): Material::new,
//! the Profile constructors, Contact::half_width / load / pressure / normal_intensity,
//! steady::analyse (both methods), asymptotic::steady and evolution::evolve (2-7 points).
#![no_main]

use arbitrary::Arbitrary;
use halfplane::steady::Method;
use halfplane::steady::analyse;
use halfplane::{asymptotic, evolution, Cycle, LoadPoint, SteadyOptions};
use halfplane_fuzz::{
    check_asymptotic, check_evolution, check_half_width, check_steady, fuzzed_contact,
    sticks_at_both_ends, Num, ProfileInput,
};
use libfuzzer_sys::fuzz_target;

#[derive(Debug, Arbitrary)]
struct Input {
    youngs_modulus: Num,
    poisson_ratio: Num,
    friction: Num,
    profile: ProfileInput,
    points: [[Num; 3]; 2],
    x: Num,
    points_per_half: u8,
    implicit: bool,
}

fuzz_target!(|input: Input| {
    let Some(contact) = fuzzed_contact(
        input.youngs_modulus,
        input.poisson_ratio,
        input.friction,
        &input.profile,
    ) else {
        return;
    };
    let mut loads = Vec::new();
    for (i, p) in input.points.iter().enumerate() {
        let normal = p[0].0;
        if let Ok(a) = contact.half_width(normal) {
            check_half_width(a, &(normal, &contact));
            if let Ok(back) = contact.load(a) {
                assert!(
                    back.is_finite() && back >= 0.0,
                    "P({a}) = {back} for {contact:?}"
                );
            }
            if let Ok(k) = contact.normal_intensity(a) {
                assert!(k.is_finite(), "K_N({a}) = {k} for {contact:?}");
            }
            let x = input.x.0;
            for x in [x, x * a] {
                if let Ok(p) = contact.pressure(a, x) {
                    assert!(
                        p.is_finite() && p >= 0.0,
                        "p({x}) = {p} at a = {a} for {contact:?}"
                    );
                }
            }
        }
        if let Ok(l) = LoadPoint::new(
            if i == 0 { "first" } else { "second" },
            normal,
            p[1].0,
            p[2].0,
        ) {
            loads.push(l);
        }
    }
    let [first, second] = loads[..] else {
        return;
    };
    let cycle = Cycle::new(first, second);
    let options = SteadyOptions::default().with_method(if input.implicit {
        Method::Implicit
    } else {
        Method::Auto
    });
    if let Ok(s) = analyse(&contact, &cycle, &options) {
        check_steady(&s);
    }
    if let Ok(a) = asymptotic::steady(&contact, &cycle) {
        if sticks_at_both_ends(&contact, &cycle) {
            check_asymptotic(&a);
        }
    }
    let points = 2 + usize::from(input.points_per_half % 6);
    if let Ok(e) = evolution::evolve(&contact, &cycle, points, &options) {
        check_evolution(&e);
    }
});
