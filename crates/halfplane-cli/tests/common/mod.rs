//! Helpers shared by the command-line tests.
#![allow(dead_code)]

use std::path::{Path, PathBuf};
use std::process::{Command, Output};

/// The bundled examples directory.
pub fn examples() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../../examples")
}

/// A bundled example's path as a string.
pub fn example(name: &str) -> String {
    examples()
        .join(name)
        .to_str()
        .expect("UTF-8 path")
        .to_string()
}

/// Runs the `halfplane` binary.
pub fn run(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_halfplane"))
        .args(args)
        .output()
        .expect("run halfplane")
}

pub fn stdout(o: &Output) -> String {
    String::from_utf8_lossy(&o.stdout).into_owned()
}

pub fn stderr(o: &Output) -> String {
    String::from_utf8_lossy(&o.stderr).into_owned()
}

/// A fresh scratch directory for one test, removed when dropped (so a test run leaves nothing
/// in the temporary directory). Derefs to its path.
pub struct Scratch(tempfile::TempDir);

impl std::ops::Deref for Scratch {
    type Target = Path;
    fn deref(&self) -> &Path {
        self.0.path()
    }
}

/// A fresh scratch directory for one test; `name` prefixes it, for debugging.
pub fn scratch(name: &str) -> Scratch {
    Scratch(
        tempfile::Builder::new()
            .prefix(&format!("halfplane-cli-{name}-"))
            .tempdir()
            .expect("scratch directory"),
    )
}

/// A file in its own scratch directory, which lives as long as this does. Derefs to the file's
/// path.
pub struct ScratchFile {
    _dir: Scratch,
    path: PathBuf,
}

impl ScratchFile {
    /// `name` inside `dir`.
    pub fn new(dir: Scratch, name: &str) -> Self {
        let path = dir.join(name);
        Self { _dir: dir, path }
    }
}

impl std::ops::Deref for ScratchFile {
    type Target = Path;
    fn deref(&self) -> &Path {
        &self.path
    }
}

/// The reference contact of docs/theory.md as case-file text (material, friction, Hertz profile).
macro_rules! reference_contact {
    () => {
        r#"[material]
youngs_modulus = 200000.0
poisson_ratio = 0.3
[friction]
coefficient = 0.6
[profile]
kind = "hertz"
radius = 50.0
"#
    };
}

/// The reference contact as case-file text, for tests that add their own `[cycle]`/`[history]`.
pub const REFERENCE_CONTACT: &str = reference_contact!();

/// The reference case (contact and cycle) as case-file text.
pub const REFERENCE_CASE: &str = concat!(
    reference_contact!(),
    "[cycle]\n",
    "point1 = { normal = 1000.0, shear = -250.0, bulk = -20.0 }\n",
    "point2 = { normal = 1400.0, shear = 250.0, bulk = 20.0 }\n"
);
