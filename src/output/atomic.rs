//! Output files written atomically: into a temporary file in the destination's directory, renamed over the
//! destination only when everything succeeded. On any failure (or drop before commit) the temporary file is
//! removed and an existing destination is left untouched.

use std::fs::File;
use std::io;
use std::os::unix::fs::PermissionsExt;
use std::path::{Path, PathBuf};

use tempfile::NamedTempFile;

/// A file being written; becomes `path` on [`AtomicFile::commit`]. Its temporary file is registered with
/// [`crate::app::interrupt`] so that an interrupt removes it (a file dropped without commit is removed by
/// `NamedTempFile` and stays registered: removing it again on interrupt is a harmless no-op).
pub struct AtomicFile {
    path: PathBuf,
    temp: NamedTempFile,
}

impl AtomicFile {
    /// Creates the temporary file next to `path`. Fails when the directory does not exist or is not writable.
    pub fn create(path: &Path) -> io::Result<Self> {
        let dir = match path.parent() {
            Some(d) if !d.as_os_str().is_empty() => d.to_path_buf(),
            _ => PathBuf::from("."),
        };
        if path.is_dir() {
            return Err(io::Error::new(
                io::ErrorKind::IsADirectory,
                "the output path is a directory",
            ));
        }
        if !dir.is_dir() {
            // Said plainly: the error from creating the temporary file would name the temporary file instead.
            return Err(io::Error::new(
                io::ErrorKind::NotFound,
                format!("the directory {} does not exist", dir.display()),
            ));
        }
        let name = path
            .file_name()
            .map(|n| n.to_string_lossy().into_owned())
            .unwrap_or_default();
        let temp = tempfile::Builder::new()
            .prefix(&format!(".{name}."))
            .suffix(".tmp")
            .tempfile_in(&dir)?;
        // tempfile creates 0600; an output file gets the usual rw-r--r--.
        temp.as_file()
            .set_permissions(std::fs::Permissions::from_mode(0o644))?;
        crate::app::interrupt::register(temp.path());
        Ok(Self {
            path: path.to_path_buf(),
            temp,
        })
    }

    /// The open temporary file, to write into.
    pub fn file(&mut self) -> &mut File {
        self.temp.as_file_mut()
    }

    /// The destination path.
    pub fn path(&self) -> &Path {
        &self.path
    }

    /// Syncs the data and renames the temporary file over the destination.
    pub fn commit(self) -> io::Result<()> {
        self.temp.as_file().sync_all()?;
        let temp_path = self.temp.path().to_path_buf();
        let result = self.temp.persist(&self.path).map_err(|e| e.error);
        crate::app::interrupt::unregister(&temp_path);
        result.map(|_| ())
    }
}
