//! The case-file parser on arbitrary UTF-8 text. Relative `file = ...` paths resolve in a
//! directory holding the bundled example CSV files, so the CSV readers are reached too.
#![no_main]

use halfplane_fuzz::{check_case, files_are_contained, fixture_dir};
use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| {
    let Ok(text) = std::str::from_utf8(data) else {
        return;
    };
    let dir = fixture_dir();
    if !files_are_contained(text, dir) {
        return;
    }
    if let Ok(case) = halfplane_case::case::parse(text, dir) {
        check_case(&case, 32, 16);
    }
});
