//! Interrupts (Ctrl-C, SIGTERM): the process stops at once with exit code 130, after removing the temporary files
//! of outputs still being written, so an interrupted run leaves no partial file and an existing output untouched.

use std::path::{Path, PathBuf};
use std::sync::Mutex;

/// Temporary files being written, to remove if the process is interrupted.
static PENDING: Mutex<Vec<PathBuf>> = Mutex::new(Vec::new());

/// Exit code of an interrupted run (128 + SIGINT, as shells report it).
pub const EXIT_INTERRUPTED: i32 = 130;

/// Installs the handler: on SIGINT or SIGTERM, remove the pending temporary files, say so, exit 130.
/// Fails only if a handler is already installed (then the default behaviour stays).
pub fn install() -> Result<(), String> {
    ctrlc::set_handler(|| {
        let pending = PENDING.lock().map(|p| p.clone()).unwrap_or_default();
        for path in &pending {
            let _ = std::fs::remove_file(path);
        }
        crate::app::progress::clear();
        eprintln!("error: interrupted; no output file was written or changed");
        std::process::exit(EXIT_INTERRUPTED);
    })
    .map_err(|e| e.to_string())
}

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
