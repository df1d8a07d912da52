//! The temporary files of outputs being written, so that whoever handles an interrupt (the command line's Ctrl-C
//! handler) can remove them before the process exits: an interrupted run then leaves no partial file. The library
//! only keeps the list; it installs no signal handler.

use std::path::{Path, PathBuf};
use std::sync::Mutex;

/// Temporary files being written.
static PENDING: Mutex<Vec<PathBuf>> = Mutex::new(Vec::new());

/// Registers a temporary file to remove on interrupt.
pub fn register(path: &Path) {
    if let Ok(mut pending) = PENDING.lock() {
        pending.push(path.to_path_buf());
    }
}

/// Forgets a temporary file (it was renamed into place or removed).
pub fn unregister(path: &Path) {
    if let Ok(mut pending) = PENDING.lock() {
        pending.retain(|p| p != path);
    }
}

/// Removes every registered temporary file (errors ignored: a file may already be gone). For an interrupt
/// handler, just before the process exits.
pub fn remove_all() {
    let pending = PENDING.lock().map(|p| p.clone()).unwrap_or_default();
    for path in &pending {
        let _ = std::fs::remove_file(path);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn remove_all_deletes_what_is_registered_and_not_what_was_unregistered() {
        let dir = tempfile::tempdir().expect("a temporary directory");
        let (kept, removed) = (dir.path().join("kept.tmp"), dir.path().join("removed.tmp"));
        std::fs::write(&kept, "k").expect("written");
        std::fs::write(&removed, "r").expect("written");
        register(&kept);
        register(&removed);
        unregister(&kept);
        remove_all();
        assert!(kept.exists() && !removed.exists());
    }
}
