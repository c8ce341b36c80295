//! Runs one steady solve many times, for profiling: `valgrind --tool=callgrind
//! target/release/examples/profile_steady KIND` with KIND hertz-implicit | flat-rounded |
//! power-law | tabulated.
use halfplane::steady::{self, Method, SteadyOptions};
use halfplane::{Contact, Cycle, Friction, LoadPoint, Material, Profile};

fn main() {
    let kind = std::env::args()
        .nth(1)
        .unwrap_or_else(|| "flat-rounded".into());
    let profile = match kind.as_str() {
        "hertz-implicit" | "hertz" => Profile::hertz(50.0),
        "flat-rounded" => Profile::flat_rounded(0.3, 50.0),
        "power-law" => Profile::power_law(0.01, 2.5),
        _ => {
            let x: Vec<f64> = (0..=40).map(|i| i as f64 / 20.0).collect();
            let g = x
                .iter()
                .map(|&x: &f64| {
                    if x <= 0.3 {
                        0.0
                    } else {
                        (x - 0.3).powi(2) / 100.0
                    }
                })
                .collect();
            Profile::tabulated(x, g, vec![0.3])
        }
    }
    .unwrap();
    let method = if kind == "hertz" {
        Method::Auto
    } else {
        Method::Implicit
    };
    let contact = Contact::new(
        profile,
        Material::new(200_000.0, 0.3).unwrap(),
        Friction::new(0.6).unwrap(),
    );
    let cycle = Cycle::new(
        LoadPoint::new("p1", 1000.0, -250.0, -20.0).unwrap(),
        LoadPoint::new("p2", 1400.0, 250.0, 20.0).unwrap(),
    );
    let options = SteadyOptions {
        method,
        ..Default::default()
    };
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
