//! The temporary files of outputs still being written ([`super::AtomicFile`] registers each one and forgets it when
//! it is renamed into place), so that whoever handles an interrupt (the command line's Ctrl-C handler) can remove
//! them with [`remove_all`] before the process exits: an interrupted run then leaves no partial file and an
//! existing output untouched. Plain `std`: the library knows nothing of signals.

use std::path::{Path, PathBuf};
use std::sync::Mutex;

/// A set of temporary files to remove on interrupt.
struct Registry(Mutex<Vec<PathBuf>>);

impl Registry {
    const fn new() -> Self {
        Self(Mutex::new(Vec::new()))
    }

    fn register(&self, path: &Path) {
        if let Ok(mut pending) = self.0.lock() {
            pending.push(path.to_path_buf());
        }
    }

    fn unregister(&self, path: &Path) {
        if let Ok(mut pending) = self.0.lock() {
            pending.retain(|p| p != path);
        }
    }

    fn remove_all(&self) -> usize {
        let pending = self
            .0
            .lock()
            .map(|mut p| std::mem::take(&mut *p))
            .unwrap_or_default();
        pending
            .iter()
            .filter(|path| std::fs::remove_file(path).is_ok())
            .count()
    }
}

/// The process's temporary files being written.
static PENDING: Registry = Registry::new();

/// Registers a temporary file to remove on interrupt.
pub fn register(path: &Path) {
    PENDING.register(path);
}

/// Forgets a temporary file (it was renamed into place or removed).
pub fn unregister(path: &Path) {
    PENDING.unregister(path);
}

/// Removes every registered temporary file (one already gone is skipped) and forgets them all; returns how many
/// were removed. Meant for an interrupt handler that then ends the process: a file being written at that moment
/// loses its name and cannot be renamed into place any more.
pub fn remove_all() -> usize {
    PENDING.remove_all()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn remove_all_removes_the_registered_files_only_and_forgets_them() {
        // A registry of its own: the process's one holds the temporary files of other tests running now.
        let registry = Registry::new();
        let dir = tempfile::tempdir().expect("a temporary directory");
        let [kept, gone, forgotten] = ["kept", "gone", "forgotten"].map(|n| dir.path().join(n));
        for path in [&kept, &gone, &forgotten] {
            std::fs::write(path, "x").expect("written");
        }
        registry.register(&gone);
        registry.register(&forgotten);
        registry.unregister(&forgotten);
        assert_eq!(registry.remove_all(), 1);
        assert!(kept.exists() && forgotten.exists());
        assert!(!gone.exists());
        std::fs::write(&gone, "again").expect("written");
        assert_eq!(
            registry.remove_all(),
            0,
            "forgotten after the first removal"
        );
        assert!(gone.exists());
    }
}
