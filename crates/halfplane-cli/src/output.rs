//! Writing to stdout and stderr without panicking: a closed pipe or a full disk is an error the
//! caller decides about (`main` ends quietly on a closed stdout pipe, with exit 2 otherwise).

use std::io::{self, Write};

/// A failed write to stdout. Kept apart from other errors so that `main` can end quietly when
/// the reader has gone away (`halfplane march case.toml --csv | head`).
#[derive(Debug)]
pub struct StdoutError(pub io::Error);

impl std::fmt::Display for StdoutError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "cannot write to stdout: {}", self.0)
    }
}

impl std::error::Error for StdoutError {}

/// Writes `text` to stdout and flushes it. `print!` would panic on a closed pipe or a full disk;
/// this returns the error instead.
pub fn emit(text: &str) -> anyhow::Result<()> {
    let mut out = io::stdout().lock();
    out.write_all(text.as_bytes())
        .and_then(|()| out.flush())
        .map_err(|e| StdoutError(e).into())
}

/// A line on stderr. `eprintln!` would panic when stderr cannot be written (a full disk): the
/// message is then lost, but the run's outcome and exit code stand.
pub fn note(text: &str) {
    let _ = writeln!(io::stderr().lock(), "{text}");
}
