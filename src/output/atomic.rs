//! Output files written atomically: into a temporary file in the destination's directory, renamed over the
//! destination only when everything succeeded. On any failure (or drop before commit) the temporary file is
//! removed and an existing destination is left untouched. Writes are buffered; [`AtomicFile::commit`] flushes,
//! fsyncs the file's data (not the directory) and renames.

use std::fs::File;
use std::io::{self, BufWriter, Write};
use std::os::unix::fs::PermissionsExt;
use std::path::{Path, PathBuf};

use tempfile::TempPath;

/// A file being written; becomes `path` on [`AtomicFile::commit`]. Its temporary file is registered with
/// [`super::pending`] so that an interrupt handler can remove it (a file dropped without commit is removed by
/// its `TempPath` and stays registered: removing it again on interrupt is a harmless no-op).
pub struct AtomicFile {
    path: PathBuf,
    /// The temporary file, buffered (one JSON document would otherwise be a thousand small writes).
    out: BufWriter<File>,
    /// Removes the temporary file when dropped before [`AtomicFile::commit`].
    temp_path: TempPath,
}

/// Why [`AtomicFile::write_and_commit`] failed; its message starts with the step (`cannot write: …`).
#[derive(Debug, thiserror::Error)]
pub enum CommitError {
    /// The bytes could not be written.
    #[error("cannot write: {0}")]
    Write(io::Error),
    /// The file could not be synced or renamed over its destination.
    #[error("cannot save: {0}")]
    Save(io::Error),
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
        super::pending::register(temp.path());
        let (file, temp_path) = temp.into_parts();
        Ok(Self {
            path: path.to_path_buf(),
            out: BufWriter::new(file),
            temp_path,
        })
    }

    /// The open temporary file (buffered), to write into.
    pub fn file(&mut self) -> &mut BufWriter<File> {
        &mut self.out
    }

    /// The destination path.
    pub fn path(&self) -> &Path {
        &self.path
    }

    /// Flushes the buffer, syncs the file's data and metadata (`fsync`) and renames the temporary file over the
    /// destination. The directory is not synced: after a crash the destination holds the old file or the new one,
    /// complete.
    pub fn commit(self) -> io::Result<()> {
        self.sync()?.rename()
    }

    /// Commits two files: both flushed and synced — at the same time, so that the file system can write both in
    /// one journal commit — and only then renamed, `first` before `second`. An error says which file (0 or 1).
    pub fn commit_both(first: AtomicFile, second: AtomicFile) -> Result<(), (usize, io::Error)> {
        let (first, second) = std::thread::scope(|scope| {
            let second = scope.spawn(|| second.sync());
            let first = first.sync();
            (
                first,
                second
                    .join()
                    .unwrap_or_else(|_| Err(io::Error::other("sync failed"))),
            )
        });
        let (first, second) = (first.map_err(|e| (0, e))?, second.map_err(|e| (1, e))?);
        first.rename().map_err(|e| (0, e))?;
        second.rename().map_err(|e| (1, e))
    }

    /// Flushes the buffer and syncs the file's data and metadata (`fsync`).
    fn sync(self) -> io::Result<Synced> {
        let file = self.out.into_inner().map_err(|e| e.into_error())?;
        file.sync_all()?;
        Ok(Synced {
            path: self.path,
            temp_path: self.temp_path,
        })
    }

    /// Writes `bytes` into the buffer, to commit later.
    pub fn write(mut self, bytes: &[u8]) -> io::Result<Self> {
        self.out.write_all(bytes)?;
        Ok(self)
    }

    /// Writes `bytes` and commits: the whole file at once.
    pub fn write_and_commit(mut self, bytes: &[u8]) -> Result<(), CommitError> {
        self.out.write_all(bytes).map_err(CommitError::Write)?;
        self.commit().map_err(CommitError::Save)
    }
}

/// Whether two paths name the same existing file (an output that would overwrite an input).
pub fn same_file(a: &Path, b: &Path) -> bool {
    match (a.canonicalize(), b.canonicalize()) {
        (Ok(a), Ok(b)) => a == b,
        _ => false,
    }
}

/// A temporary file whose data is on disk, to be renamed over its destination.
struct Synced {
    path: PathBuf,
    temp_path: TempPath,
}

impl Synced {
    /// Renames the temporary file over the destination.
    fn rename(self) -> io::Result<()> {
        let temp_path = self.temp_path.to_path_buf();
        let result = self.temp_path.persist(&self.path).map_err(|e| e.error);
        super::pending::unregister(&temp_path);
        result
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn names(dir: &Path) -> Vec<String> {
        let mut names: Vec<String> = std::fs::read_dir(dir)
            .expect("listing")
            .map(|e| e.expect("entry").file_name().to_string_lossy().into_owned())
            .collect();
        names.sort();
        names
    }

    #[test]
    fn the_destination_is_the_old_file_until_commit_and_the_new_one_after() {
        let dir = tempfile::tempdir().expect("a temporary directory");
        let out = dir.path().join("out.json");
        std::fs::write(&out, "old").expect("written");
        let mut file = AtomicFile::create(&out).expect("created");
        for k in 0..1000 {
            write!(file.file(), "{k},").expect("buffered");
        }
        assert_eq!(std::fs::read_to_string(&out).expect("read"), "old");
        file.commit().expect("committed");
        let text = std::fs::read_to_string(&out).expect("read");
        assert!(text.starts_with("0,1,2,") && text.ends_with("998,999,"));
        assert_eq!(names(dir.path()), ["out.json"]);
    }

    #[test]
    fn a_file_dropped_before_commit_leaves_the_old_one_and_no_temporary_file() {
        let dir = tempfile::tempdir().expect("a temporary directory");
        let out = dir.path().join("out.csv");
        std::fs::write(&out, "old").expect("written");
        let mut file = AtomicFile::create(&out).expect("created");
        file.file().write_all(b"new").expect("buffered");
        drop(file);
        assert_eq!(std::fs::read_to_string(&out).expect("read"), "old");
        assert_eq!(names(dir.path()), ["out.csv"]);
        AtomicFile::create(&out)
            .expect("created")
            .write_and_commit(b"new")
            .expect("committed");
        assert_eq!(std::fs::read_to_string(&out).expect("read"), "new");
    }
}
