//! Times the setup of a long tabulated profile, then one contact half-width and one steady
//! solve on it: `cargo run --release -p halfplane --example load_table -- ROWS` (default
//! 1,000,000; the table samples the flat-rounded punch b = 0.3, R = 50 on [0, 2]). With a second
//! argument `setup`, only the table is built (for `perf stat`, which counts the whole process).
use halfplane::{steady, Contact, Cycle, Friction, LoadPoint, Material, Profile, SteadyOptions};
use std::time::Instant;

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let rows: usize = match std::env::args().nth(1) {
        Some(r) => r.parse()?,
        None => 1_000_000,
    };
    // rows - 1 a multiple of 20 puts x = 0.3 on a row; round down to one.
    let rows = (rows.max(21) - 1) / 20 * 20 + 1;
    let x: Vec<f64> = (0..rows)
        .map(|i| 2.0 * i as f64 / (rows - 1) as f64)
        .collect();
    let g = x
        .iter()
        .map(|&x| {
            if x <= 0.3 {
                0.0
            } else {
                (x - 0.3).powi(2) / 100.0
            }
        })
        .collect();
    let start = Instant::now();
    let profile = Profile::tabulated(x, g, vec![0.3])?;
    let setup = start.elapsed();
    if std::env::args().nth(2).as_deref() == Some("setup") {
        println!("{rows} rows: Profile::tabulated {setup:?}");
        return Ok(());
    }
    let contact = Contact::new(profile, Material::new(200_000.0, 0.3)?, Friction::new(0.6)?);
    let start = Instant::now();
    let a = contact.half_width(1000.0)?;
    let half_width = start.elapsed();
    let cycle = Cycle::new(
        LoadPoint::new("point1", 1000.0, -250.0, -20.0)?,
        LoadPoint::new("point2", 1400.0, 250.0, 20.0)?,
    );
    let start = Instant::now();
    let state = steady::analyse(&contact, &cycle, &SteadyOptions::default())?;
    let solve = start.elapsed();
    println!(
        "{rows} rows: Profile::tabulated {setup:?}, one half-width {half_width:?} (a = {a:.9}), \
         steady::analyse {solve:?} (stick zone {:?})",
        state.stick_zone
    );
    Ok(())
}
