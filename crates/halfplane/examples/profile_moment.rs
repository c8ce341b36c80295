//! The cost of a moment, for profiling and for the instruction counts of BENCHMARKS.md ("Steady
//! state and march with a moment"): `valgrind --tool=callgrind
//! target/release/examples/profile_moment KIND MOMENT ROUTE` with KIND hertz | flat-rounded |
//! power-law | table-41 (the `moment` bench's profiles), MOMENT `none` (the reference cycle) or
//! `moment` (M = 50 at point 1, 120 N mm/mm at point 2) and ROUTE `steady` (200 solves of
//! `steady::analyse`) or `march` (one march of the `moment` bench's history: two cycles of 30
//! increments per half after a 10-increment ramp, 400 cells; it prints the active-set passes,
//! the increments, and the contact ends' crossings of cell centres: `paired` where both ends
//! cross in the same increment, which the symmetric grid makes one sub-step).
use halfplane::history::{History, Ramp};
use halfplane::labels::Edge;
use halfplane::march::{march, MarchOptions};
use halfplane::reference::{self, contact};
use halfplane::steady::{self, SteadyOptions};
use halfplane::{Cycle, Profile};

fn main() {
    let args: Vec<String> = std::env::args().collect();
    let arg = |i: usize, default: &str| args.get(i).cloned().unwrap_or_else(|| default.into());
    let contact = contact(match arg(1, "flat-rounded").as_str() {
        "hertz" => Profile::hertz(reference::RADIUS).unwrap(),
        "flat-rounded" => Profile::flat_rounded(0.3, reference::RADIUS).unwrap(),
        "power-law" => Profile::power_law(0.01, 2.5).unwrap(),
        _ => reference::flat_rounded_table(41).unwrap(),
    });
    let (m1, m2) = if arg(2, "moment") == "moment" {
        (50.0, 120.0)
    } else {
        (0.0, 0.0)
    };
    let (p1, p2) = reference::cycle().as_given();
    let (p1, p2) = (
        p1.with_moment("profile", m1).unwrap(),
        p2.with_moment("profile", m2).unwrap(),
    );
    if arg(3, "steady") == "march" {
        let history = History::in_phase(p1, p2, 2, 30, Ramp::NormalFirst, 10).unwrap();
        let options = MarchOptions::default().with_cells(400).unwrap();
        let (mut passes, mut increments) = (0, 0);
        let (mut left, mut right, mut paired) = (0, 0, 0);
        let mut ends: Option<[f64; 2]> = None;
        march(&contact, &history, &options, |s, fields| {
            passes += s.passes;
            increments += 1;
            let now = [s.ends[Edge::Left], s.ends[Edge::Right]];
            if let Some(before) = ends {
                let crossed = |a: f64, b: f64| {
                    let (lo, hi) = (a.min(b), a.max(b));
                    fields.x.iter().filter(|&&x| x > lo && x < hi).count()
                };
                let (l, r) = (crossed(before[0], now[0]), crossed(before[1], now[1]));
                left += l;
                right += r;
                paired += l.min(r);
            }
            ends = Some(now);
        })
        .unwrap();
        println!(
            "{passes} passes, {increments} increments, crossings: {left} left, {right} right, {paired} paired"
        );
    } else {
        let cycle = Cycle::new(p1, p2);
        let mut sum = 0.0;
        for _ in 0..200 {
            let s = steady::analyse(&contact, &cycle, &SteadyOptions::default()).unwrap();
            sum += s.stick_zone.map_or(0.0, |z| z.right);
        }
        println!("{sum}");
    }
}
