//! The binding of halfplane for the web page (`scripts/web` builds it for
//! `wasm32-unknown-unknown` and writes the page into `target/web/`). A thin layer like the Python
//! binding: each function takes the text of a case file, reads it with `halfplane-case` (the
//! command's own parser) and answers with JSON, `{"ok": ...}` or `{"error": ...}` (the message as
//! the command prints it, and the form field it concerns; [`errors::PageError`]). Nothing is
//! computed here that the library or the case crate does not compute for the command.

pub mod analyses;
pub mod errors;
pub mod form;

use errors::PageError;
use serde_json::{json, Value};
use wasm_bindgen::prelude::wasm_bindgen;

/// `{"ok": value}` or `{"error": PageError}`, as text.
fn answer(result: anyhow::Result<Value>) -> String {
    match result {
        Ok(value) => json!({ "ok": value }),
        Err(e) => json!({ "error": PageError::new(&e) }),
    }
    .to_string()
}

/// The package version, shown in the page's footer.
#[wasm_bindgen]
pub fn version() -> String {
    env!("CARGO_PKG_VERSION").into()
}

/// The steady state of the case: [`analyses::steady`].
#[wasm_bindgen]
pub fn steady(case: &str) -> String {
    answer(analyses::steady(case))
}

/// The stick zone along the cycle at `points` (the form's text) points per half:
/// [`analyses::evolve`].
#[wasm_bindgen]
pub fn evolve(case: &str, points: &str) -> String {
    answer(analyses::evolve(case, points))
}

/// The pressure at both ends of the cycle: [`analyses::contact`].
#[wasm_bindgen]
pub fn contact(case: &str) -> String {
    answer(analyses::contact(case))
}

/// The regime over the load space: [`analyses::regime_map`].
#[wasm_bindgen]
pub fn regime_map(case: &str, columns: u32, rows: u32) -> String {
    answer(analyses::regime_map(case, columns as usize, rows as usize))
}

/// The march of the case's history: [`analyses::march`].
#[wasm_bindgen]
pub fn march(case: &str) -> String {
    answer(analyses::march(case))
}

/// The case text's fields by dotted name, to fill the form: [`form::fields`].
#[wasm_bindgen]
pub fn case_fields(case: &str) -> String {
    answer(form::fields(case))
}

/// The sections of the case text that the form does not write: [`form::other_sections`].
#[wasm_bindgen]
pub fn other_sections(case: &str, owned: &str) -> String {
    answer(form::other_sections(case, owned))
}
