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
