//! Times the setup of a long tabulated profile, then one contact half-width and one steady
//! solve on it: `cargo run --release -p halfplane --example load_table -- ROWS` (default
//! 1,000,000; the table samples the flat-rounded punch b = 0.3, R = 50 on [0, 2]). With a second
//! argument `setup`, only the table is built (for `perf stat`, which counts the whole process).
use halfplane::{reference, steady, SteadyOptions};
use std::time::Instant;

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let rows: usize = match std::env::args().nth(1) {
        Some(r) => r.parse()?,
        None => 1_000_000,
    };
    // rows - 1 a multiple of 20 puts x = 0.3 on a row; round down to one.
    let rows = (rows.max(21) - 1) / 20 * 20 + 1;
    let start = Instant::now();
    let profile = reference::flat_rounded_table(rows)?;
    let setup = start.elapsed();
    if std::env::args().nth(2).as_deref() == Some("setup") {
        println!("{rows} rows: Profile::tabulated {setup:?}");
        return Ok(());
    }
    let contact = reference::contact(profile);
    let start = Instant::now();
    let a = contact.half_width(1000.0)?;
    let half_width = start.elapsed();
    let cycle = reference::cycle();
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
