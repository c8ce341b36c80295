//! The CSV readers, through the case parser: arbitrary bytes become the tabulated-profile file
//! (first byte even) or the history file (odd) of an otherwise valid case. A profile that loads
//! is then used: normal problem, pressure, and a partial-slip cycle scaled to the table; a history
//! that loads is marched on 16 cells when short.
#![no_main]

use halfplane::steady::analyse;
use halfplane::{Cycle, LoadPoint, SteadyOptions};
use halfplane_fuzz::{check_case, check_half_width, check_steady};
use libfuzzer_sys::fuzz_target;
use std::sync::OnceLock;

const MATERIAL: &str = "[material]\nyoungs_modulus = 200000.0\npoisson_ratio = 0.3\n\
                        [friction]\ncoefficient = 0.6\n";

fn dir() -> &'static std::path::Path {
    static DIR: OnceLock<std::path::PathBuf> = OnceLock::new();
    DIR.get_or_init(|| tempfile::tempdir().unwrap().keep())
}

fuzz_target!(|data: &[u8]| {
    let Some((&mode, bytes)) = data.split_first() else {
        return;
    };
    let dir = dir();
    if mode % 2 == 0 {
        std::fs::write(dir.join("profile.csv"), bytes).unwrap();
        // Kinks: none, or one of a few values that tables often contain.
        let kinks = [
            "",
            "kinks = [0.3]\n",
            "kinks = [0.0]\n",
            "kinks = [1.0, 0.5]\n",
        ][usize::from(mode / 2) % 4];
        let text =
            format!("{MATERIAL}[profile]\nkind = \"tabulated\"\nfile = \"profile.csv\"\n{kinks}");
        let Ok(case) = halfplane_case::case::parse(&text, dir) else {
            return;
        };
        check_case(&case, 0, 8);
        let contact = &case.contact;
        // A cycle inside the table: loads at 30% and 50% of the load that fills it.
        let end = contact.profile().extent();
        let Ok(p_max) = contact.load(0.9 * end) else {
            return;
        };
        assert!(p_max.is_finite(), "P({}) = {p_max}", 0.9 * end);
        if !(p_max > 0.0) {
            return;
        }
        for fraction in [0.3, 0.5] {
            if let Ok(a) = contact.half_width(fraction * p_max) {
                check_half_width(a, &(fraction * p_max));
                for x in [-0.99, -0.5, 0.0, 0.3, 0.999] {
                    if let Ok(p) = contact.pressure(a, x * a) {
                        assert!(p.is_finite() && p >= 0.0, "p({}) = {p} for a = {a}", x * a);
                    }
                }
            }
        }
        let f = contact.friction().value();
        let (p1, p2) = (0.3 * p_max, 0.5 * p_max);
        let (Ok(first), Ok(second)) = (
            LoadPoint::new("first", p1, -0.4 * f * p1, -0.01 * p1 / end),
            LoadPoint::new("second", p2, 0.4 * f * p2, 0.01 * p1 / end),
        ) else {
            return;
        };
        if let Ok(s) = analyse(
            contact,
            &Cycle::new(first, second),
            &SteadyOptions::default(),
        ) {
            check_steady(&s);
        }
    } else {
        std::fs::write(dir.join("history.csv"), bytes).unwrap();
        let text = format!(
            "{MATERIAL}[profile]\nkind = \"hertz\"\nradius = 50.0\n[history]\nfile = \"history.csv\"\n"
        );
        if let Ok(case) = halfplane_case::case::parse(&text, dir) {
            check_case(&case, 32, 16);
        }
    }
});
