//! Runs one steady solve many times, for profiling: `valgrind --tool=callgrind
//! target/release/examples/profile_steady KIND` with KIND hertz-implicit | flat-rounded |
//! power-law | tabulated.
use halfplane::reference::{self, FLAT_HALF_WIDTH, RADIUS};
use halfplane::steady::{self, Method, SteadyOptions};
use halfplane::Profile;

fn main() {
    let kind = std::env::args()
        .nth(1)
        .unwrap_or_else(|| "flat-rounded".into());
    let profile = match kind.as_str() {
        "hertz-implicit" | "hertz" => Profile::hertz(RADIUS),
        "flat-rounded" => Profile::flat_rounded(FLAT_HALF_WIDTH, RADIUS),
        "power-law" => Profile::power_law(0.01, 2.5),
        _ => reference::flat_rounded_table(41),
    }
    .unwrap();
    let method = if kind == "hertz" {
        Method::Auto
    } else {
        Method::Implicit
    };
    let contact = reference::contact(profile);
    let cycle = reference::cycle();
    let options = SteadyOptions::default().with_method(method);
    let mut sum = 0.0;
    for _ in 0..1000 {
        sum += steady::analyse(&contact, &cycle, &options)
            .unwrap()
            .stick_zone
            .unwrap()
            .right;
    }
    println!("{sum}");
}
