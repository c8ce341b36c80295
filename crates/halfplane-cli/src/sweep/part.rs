//! The `.part` file a sweep writes until it completes. A sweep that fails part-way (a full disk, a
//! write error) or is interrupted (Ctrl-C, SIGTERM) removes it and says so on stderr, so that no
//! incomplete output is left behind under a name that could be taken for a result.

use crate::output::note;
use std::path::{Path, PathBuf};
use std::sync::{Mutex, MutexGuard, Once};

/// The `.part` file being written, if any: what an interrupt removes.
static CURRENT: Mutex<Option<PathBuf>> = Mutex::new(None);

fn current() -> MutexGuard<'static, Option<PathBuf>> {
    CURRENT.lock().unwrap_or_else(|e| e.into_inner())
}

/// Marks `part` as the file in progress and, once per process, installs the handler that removes
/// it on Ctrl-C or SIGTERM and ends the run with exit 2. If no handler can be installed (another
/// one is), an interrupt leaves the `.part` file, whose name still says it is incomplete.
pub fn watch(part: &Path) {
    *current() = Some(part.to_path_buf());
    static HANDLER: Once = Once::new();
    HANDLER.call_once(|| {
        let _ = ctrlc::set_handler(|| {
            // The lock is held until exit, so a completing sweep cannot rename the file meanwhile.
            let mut guard = current();
            match guard.take() {
                Some(part) if std::fs::remove_file(&part).is_ok() => note(&format!(
                    "interrupted: removed the incomplete output {}",
                    part.display()
                )),
                _ => note("interrupted"),
            }
            std::process::exit(2);
        });
    });
}

/// Runs `finish` (which renames the `.part` file to its final name) so that an interrupt cannot
/// remove the file while it is being renamed, then forgets the file.
pub fn commit<T>(finish: impl FnOnce() -> T) -> T {
    let mut guard = current();
    let out = finish();
    *guard = None;
    out
}

/// After a failed sweep: removes `part` if it exists and says so in the error.
pub fn abandon(part: &Path, error: anyhow::Error) -> anyhow::Error {
    let mut guard = current();
    *guard = None;
    match std::fs::remove_file(part) {
        Ok(()) => error.context(format!(
            "the sweep stopped; removed the incomplete output {}",
            part.display()
        )),
        Err(_) => error,
    }
}
