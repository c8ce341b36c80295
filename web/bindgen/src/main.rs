//! `halfplane-bindgen WASM OUT_DIR`: the JavaScript glue of the compiled binding, as
//! `wasm-bindgen --target no-modules --no-typescript` writes it (`--version`: the version of
//! wasm-bindgen it is built on, and the revision of this tool). A classic script (not an ES
//! module), so that the page also works when opened from `file://`, where browsers refuse
//! module scripts.

use std::process::ExitCode;

/// Raised at every change of this tool, so that `./scripts/web` reinstalls it (it compares the
/// `--version` of the installed tool with this line).
const REVISION: u32 = 3;

fn main() -> ExitCode {
    let args: Vec<String> = std::env::args().skip(1).collect();
    if args == ["--version"] {
        println!("halfplane-bindgen {} r{REVISION}", env!("CARGO_PKG_VERSION"));
        return ExitCode::SUCCESS;
    }
    let [wasm, out] = args.as_slice() else {
        eprintln!("usage: halfplane-bindgen WASM OUT_DIR");
        return ExitCode::from(2);
    };
    let generated = wasm_bindgen_cli_support::Bindgen::new()
        .input_path(wasm)
        .no_modules(true)
        .and_then(|b| b.typescript(false).generate(out));
    match generated {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => {
            eprintln!("halfplane-bindgen: {e:#}");
            ExitCode::from(2)
        }
    }
}
