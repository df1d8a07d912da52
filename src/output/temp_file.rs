//! A temporary file beside an output: created new (`O_CREAT | O_EXCL`, never an existing file), named
//! `.{name}.{pid}.{n}.tmp` after its destination, and removed when dropped unless renamed over the destination.

use std::fs::{File, OpenOptions};
use std::io;
use std::path::{Path, PathBuf};
use std::sync::atomic::{AtomicU64, Ordering};

/// Names tried before giving up, when every one is taken (left by other processes).
const ATTEMPTS: u32 = 1000;

/// The path of a temporary file, removed when dropped unless [`TempPath::rename_over`] moved it.
#[derive(Debug)]
pub(super) struct TempPath {
    /// `None` once renamed.
    path: Option<PathBuf>,
}

impl TempPath {
    /// Creates a new file `.{name}.{pid}.{n}.tmp` in `dir`, n counting up within the process past names taken.
    pub(super) fn create_in(dir: &Path, name: &str) -> io::Result<(File, TempPath)> {
        static NEXT: AtomicU64 = AtomicU64::new(0);
        let pid = std::process::id();
        for _ in 0..ATTEMPTS {
            let n = NEXT.fetch_add(1, Ordering::Relaxed);
            let path = dir.join(format!(".{name}.{pid}.{n}.tmp"));
            match OpenOptions::new().write(true).create_new(true).open(&path) {
                Ok(file) => return Ok((file, TempPath { path: Some(path) })),
                Err(e) if e.kind() == io::ErrorKind::AlreadyExists => continue,
                Err(e) => return Err(e),
            }
        }
        Err(io::Error::new(
            io::ErrorKind::AlreadyExists,
            format!(
                "{ATTEMPTS} temporary names for {name} in {} are taken",
                dir.display()
            ),
        ))
    }

    /// The temporary file's path.
    pub(super) fn path(&self) -> &Path {
        self.path
            .as_deref()
            .expect("a temporary file not yet renamed")
    }

    /// Renames the file over `target` (atomically, on one file system). On failure the file is removed.
    pub(super) fn rename_over(mut self, target: &Path) -> io::Result<()> {
        let path = self.path.take().expect("a temporary file not yet renamed");
        std::fs::rename(&path, target).inspect_err(|_| {
            let _ = std::fs::remove_file(&path);
        })
    }
}

impl Drop for TempPath {
    fn drop(&mut self) {
        if let Some(path) = self.path.take() {
            let _ = std::fs::remove_file(path);
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn names_are_new_files_removed_on_drop_and_kept_by_a_rename() {
        let dir = tempfile::tempdir().expect("a temporary directory");
        let (_, a) = TempPath::create_in(dir.path(), "out.csv").unwrap();
        let (_, b) = TempPath::create_in(dir.path(), "out.csv").unwrap();
        assert_ne!(a.path(), b.path());
        let name = a.path().file_name().unwrap().to_string_lossy().into_owned();
        assert!(
            name.starts_with(".out.csv.") && name.ends_with(".tmp"),
            "{name}"
        );
        let (a_path, b_path) = (a.path().to_path_buf(), b.path().to_path_buf());
        drop(a);
        assert!(!a_path.exists());
        let target = dir.path().join("out.csv");
        b.rename_over(&target).unwrap();
        assert!(target.exists() && !b_path.exists());
    }

    #[test]
    fn a_failed_rename_removes_the_file() {
        let dir = tempfile::tempdir().expect("a temporary directory");
        let (_, temp) = TempPath::create_in(dir.path(), "x").unwrap();
        let path = temp.path().to_path_buf();
        let missing = dir.path().join("no such directory").join("x");
        assert!(temp.rename_over(&missing).is_err());
        assert!(!path.exists());
    }
}
