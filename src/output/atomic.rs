//! Output files, one policy for every command that writes one:
//!
//! - a regular file or a new path is written atomically: into a temporary file in the destination's directory,
//!   renamed over the destination only when everything succeeded. On any failure (or drop before commit) the
//!   temporary file is removed and an existing destination is left untouched;
//! - a symlink is kept: its final target (links followed to the end) is written atomically in the target's
//!   directory;
//! - an existing path that is not a regular file — a device such as a null device, a FIFO, a socket — is opened
//!   and written through, never replaced; a write error there (a full device, a closed pipe) is the caller's error
//!   to report with the path. Nothing is written beside such a destination: [`AtomicFile::writes_through`] tells
//!   the callers that would write a sidecar.
//!
//! Writes are buffered; [`AtomicFile::commit`] flushes, fsyncs the file's data (not the directory) and renames.
//! Temporary files are registered with [`super::pending`] so that an interrupt handler can remove them.

use std::fs::File;
use std::io::{self, BufWriter, Write};
use std::os::unix::fs::PermissionsExt;
use std::path::{Path, PathBuf};

use super::pending;
use super::temp_file::TempPath;

/// Where an output path's bytes go.
#[derive(Debug, Clone, PartialEq, Eq)]
enum Destination {
    /// A regular file or a new path (a symlink's final target): replaced atomically.
    Replace(PathBuf),
    /// An existing file that is not a regular file (device, FIFO, socket): written through.
    Through,
}

/// Symlinks are followed this many times at most (as Linux's `MAXSYMLINKS`).
const MAX_LINKS: usize = 40;

/// The path `path` names once its symlinks are followed: `path` itself when it is not a symlink, else the link's
/// final target, canonical (absolute, no `..`, its directory's links resolved too). A dangling link's target
/// need not exist (it is created); a loop is an error.
fn follow_links(path: &Path) -> io::Result<PathBuf> {
    let mut current = path.to_path_buf();
    for _ in 0..MAX_LINKS {
        match std::fs::symlink_metadata(&current) {
            Ok(m) if m.file_type().is_symlink() => {
                let target = std::fs::read_link(&current)?;
                current = match current.parent() {
                    Some(dir) if target.is_relative() => dir.join(target),
                    _ => target,
                };
            }
            _ if current == path => return Ok(current),
            Ok(_) => return current.canonicalize(),
            Err(_) => return canonical_parent(&current),
        }
    }
    Err(io::Error::other(format!(
        "{}: more than {MAX_LINKS} symbolic links to follow (a loop?)",
        path.display()
    )))
}

/// `path` (which does not exist) with its directory canonical; the directory as given when it does not exist
/// (then [`AtomicFile::create`] says so).
fn canonical_parent(path: &Path) -> io::Result<PathBuf> {
    let (Some(dir), Some(name)) = (path.parent(), path.file_name()) else {
        return Ok(path.to_path_buf());
    };
    let dir = if dir.as_os_str().is_empty() {
        Path::new(".")
    } else {
        dir
    };
    Ok(dir
        .canonicalize()
        .map_or(path.to_path_buf(), |d| d.join(name)))
}

impl Destination {
    /// What writing `path` means (see the module documentation). A directory is an error.
    fn of(path: &Path) -> io::Result<Self> {
        let target = follow_links(path)?;
        match std::fs::metadata(&target) {
            Err(e) if e.kind() == io::ErrorKind::NotFound => Ok(Destination::Replace(target)),
            Err(e) => Err(e),
            Ok(m) if m.is_dir() => Err(io::Error::new(
                io::ErrorKind::IsADirectory,
                "the output path is a directory",
            )),
            Ok(m) if m.is_file() => Ok(Destination::Replace(target)),
            Ok(_) => Ok(Destination::Through),
        }
    }
}

/// How the bytes reach the destination.
enum Sink {
    /// Into a temporary file (removed when dropped before commit) renamed over `target` on commit.
    Temporary {
        temp_path: TempPath,
        target: PathBuf,
    },
    /// Straight into the destination, opened for writing.
    Through,
}

/// A file being written to the output path `path`, following the module's policy; [`AtomicFile::commit`] finishes
/// it. A temporary file is registered with [`pending`] so that an interrupt removes it (a file dropped without
/// commit is removed by its `TempPath` and stays registered: removing it again is a harmless no-op).
pub struct AtomicFile {
    /// The path as named.
    path: PathBuf,
    /// The temporary file or the destination itself, buffered (one JSON document would otherwise be a thousand
    /// small writes).
    out: BufWriter<File>,
    sink: Sink,
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
    /// Opens `path` for writing: a temporary file next to it (next to a symlink's target), or the destination
    /// itself when it exists and is not a regular file (opening a FIFO waits for its reader). Fails when the
    /// path is a directory, its directory does not exist or is not writable, or the destination cannot be opened.
    pub fn create(path: &Path) -> io::Result<Self> {
        let target = match Destination::of(path)? {
            Destination::Through => {
                let file = File::options().write(true).open(path)?;
                return Ok(Self {
                    path: path.to_path_buf(),
                    out: BufWriter::new(file),
                    sink: Sink::Through,
                });
            }
            Destination::Replace(target) => target,
        };
        let dir = match target.parent() {
            Some(d) if !d.as_os_str().is_empty() => d.to_path_buf(),
            _ => PathBuf::from("."),
        };
        if !dir.is_dir() {
            // Said plainly: the error from creating the temporary file would name the temporary file instead.
            return Err(io::Error::new(
                io::ErrorKind::NotFound,
                format!("the directory {} does not exist", dir.display()),
            ));
        }
        let name = target
            .file_name()
            .map(|n| n.to_string_lossy().into_owned())
            .unwrap_or_default();
        let (file, temp_path) = TempPath::create_in(&dir, &name)?;
        // An output file gets the usual rw-r--r--, whatever the umask.
        file.set_permissions(std::fs::Permissions::from_mode(0o644))?;
        pending::register(temp_path.path());
        Ok(Self {
            path: path.to_path_buf(),
            out: BufWriter::new(file),
            sink: Sink::Temporary { temp_path, target },
        })
    }

    /// The open file (buffered), to write into.
    pub fn file(&mut self) -> &mut BufWriter<File> {
        &mut self.out
    }

    /// The destination path, as named.
    pub fn path(&self) -> &Path {
        &self.path
    }

    /// Whether the destination is an existing file that is not a regular file (a device, a FIFO, a socket),
    /// written through rather than replaced. No sidecar or other file is to be written beside it.
    pub fn writes_through(&self) -> bool {
        matches!(self.sink, Sink::Through)
    }

    /// Flushes the buffer, syncs the file's data and metadata (`fsync`) and renames the temporary file over the
    /// destination. The directory is not synced: after a crash the destination holds the old file or the new one,
    /// complete. A destination written through is only flushed (a device or pipe has nothing to sync).
    pub fn commit(self) -> io::Result<()> {
        self.sync()?.rename()
    }

    /// Commits several files: all synced (in order), and only then renamed, in order, so that no file is renamed
    /// before all are on disk. An error says which file (its index).
    pub fn commit_all(files: Vec<AtomicFile>) -> Result<(), (usize, io::Error)> {
        let synced = (files.into_iter().enumerate())
            .map(|(i, f)| f.sync().map_err(|e| (i, e)))
            .collect::<Result<Vec<_>, _>>()?;
        for (i, file) in synced.into_iter().enumerate() {
            file.rename().map_err(|e| (i, e))?;
        }
        Ok(())
    }

    /// Flushes the buffer and, for a temporary file, syncs its data and metadata (`fsync`).
    fn sync(self) -> io::Result<Synced> {
        let file = self.out.into_inner().map_err(|e| e.into_error())?;
        if let Sink::Temporary { .. } = self.sink {
            file.sync_all()?;
        }
        Ok(Synced(self.sink))
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

/// A file whose data is on disk (or, written through, flushed), to be renamed over its destination.
struct Synced(Sink);

impl Synced {
    /// Renames the temporary file over its target (nothing to do for a destination written through).
    fn rename(self) -> io::Result<()> {
        let Sink::Temporary { temp_path, target } = self.0 else {
            return Ok(());
        };
        let temp = temp_path.path().to_path_buf();
        let result = temp_path.rename_over(&target);
        pending::unregister(&temp);
        result
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::os::unix::fs::FileTypeExt;
    use std::process::Command;

    fn names(dir: &Path) -> Vec<String> {
        let mut names: Vec<String> = std::fs::read_dir(dir)
            .expect("listing")
            .map(|e| e.expect("entry").file_name().to_string_lossy().into_owned())
            .collect();
        names.sort();
        names
    }

    /// A character device node `dir/name` (major 1: minor 3 the null device, 7 the full device), made with
    /// `mknod`; `None` (said on stderr) where that is not permitted (not root).
    fn device(dir: &Path, name: &str, minor: &str) -> Option<PathBuf> {
        let path = dir.join(name);
        let made = Command::new("mknod")
            .arg(&path)
            .args(["c", "1", minor])
            .status()
            .is_ok_and(|s| s.success());
        if !made {
            eprintln!("skipped: cannot make a device node with mknod here (not root?)");
        }
        made.then_some(path)
    }

    fn is_char_device(path: &Path) -> bool {
        std::fs::symlink_metadata(path).is_ok_and(|m| m.file_type().is_char_device())
    }

    #[test]
    fn the_destination_is_the_old_file_until_commit_and_the_new_one_after() {
        let dir = tempfile::tempdir().expect("a temporary directory");
        let out = dir.path().join("out.json");
        std::fs::write(&out, "old").expect("written");
        let mut file = AtomicFile::create(&out).expect("created");
        assert!(!file.writes_through());
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

    #[test]
    fn a_symlink_is_kept_and_its_target_in_another_directory_is_replaced() {
        let dir = tempfile::tempdir().expect("a temporary directory");
        let (data, report) = (dir.path().join("data"), dir.path().join("report"));
        std::fs::create_dir_all(&data).expect("made");
        std::fs::create_dir_all(&report).expect("made");
        std::fs::write(data.join("run.csv"), "old").expect("written");
        let link = report.join("run.csv");
        std::os::unix::fs::symlink("../data/run.csv", &link).expect("linked");
        let file = AtomicFile::create(&link).expect("created");
        assert!(!file.writes_through());
        assert_eq!(file.path(), link);
        file.write_and_commit(b"new").expect("committed");
        assert!(
            std::fs::symlink_metadata(&link)
                .expect("there")
                .is_symlink()
        );
        assert_eq!(
            std::fs::read_link(&link).expect("a link"),
            Path::new("../data/run.csv")
        );
        assert_eq!(
            std::fs::read_to_string(data.join("run.csv")).expect("read"),
            "new"
        );
        // The temporary file was made beside the target and renamed; nothing is left in either directory.
        assert_eq!(names(&data), ["run.csv"]);
        assert_eq!(names(&report), ["run.csv"]);
    }

    #[test]
    fn a_chain_of_links_and_a_dangling_link_are_followed_to_the_end() {
        let dir = tempfile::tempdir().expect("a temporary directory");
        let target = dir.path().join("target.csv");
        let (first, second) = (dir.path().join("a.csv"), dir.path().join("b.csv"));
        std::os::unix::fs::symlink(&second, &first).expect("linked");
        std::os::unix::fs::symlink("target.csv", &second).expect("linked");
        // Dangling: the target is created.
        AtomicFile::create(&first)
            .expect("created")
            .write_and_commit(b"one")
            .expect("committed");
        assert_eq!(std::fs::read_to_string(&target).expect("read"), "one");
        assert!(first.is_symlink() && second.is_symlink());
        let looped = dir.path().join("loop");
        std::os::unix::fs::symlink(&looped, &looped).expect("linked");
        let e = AtomicFile::create(&looped)
            .err()
            .expect("a loop is refused");
        assert!(e.to_string().contains("symbolic links"), "{e}");
    }

    #[test]
    fn a_directory_and_a_missing_directory_are_refused() {
        let dir = tempfile::tempdir().expect("a temporary directory");
        let e = AtomicFile::create(dir.path()).err().expect("refused");
        assert_eq!(e.kind(), io::ErrorKind::IsADirectory);
        let e = AtomicFile::create(&dir.path().join("no/such/out.csv"))
            .err()
            .expect("refused");
        assert!(e.to_string().contains("does not exist"), "{e}");
    }

    #[test]
    fn a_fifo_is_written_through_to_its_reader_and_stays_a_fifo() {
        let dir = tempfile::tempdir().expect("a temporary directory");
        let fifo = dir.path().join("pipe");
        let made = Command::new("mkfifo")
            .arg(&fifo)
            .status()
            .expect("mkfifo runs");
        assert!(made.success());
        let reader = {
            let fifo = fifo.clone();
            std::thread::spawn(move || std::fs::read(fifo).expect("read to the end"))
        };
        let bytes: Vec<u8> = (0..100_000u32).flat_map(|k| k.to_le_bytes()).collect();
        let file = AtomicFile::create(&fifo).expect("opened");
        assert!(file.writes_through());
        file.write_and_commit(&bytes).expect("written");
        assert_eq!(reader.join().expect("the reader"), bytes);
        assert!(
            std::fs::symlink_metadata(&fifo)
                .expect("there")
                .file_type()
                .is_fifo()
        );
        assert_eq!(names(dir.path()), ["pipe"]);
    }

    #[test]
    fn a_null_device_is_written_through_and_stays_a_device() {
        let dir = tempfile::tempdir().expect("a temporary directory");
        let Some(null) = device(dir.path(), "null", "3") else {
            return;
        };
        let link = dir.path().join("link");
        std::os::unix::fs::symlink(&null, &link).expect("linked");
        for path in [&null, &link] {
            let file = AtomicFile::create(path).expect("opened");
            assert!(file.writes_through());
            file.write_and_commit(&[7; 100_000]).expect("written");
        }
        assert!(is_char_device(&null));
        assert!(link.is_symlink());
        assert_eq!(names(dir.path()), ["link", "null"]);
    }

    #[test]
    fn a_full_device_fails_to_write_and_stays_a_device() {
        let dir = tempfile::tempdir().expect("a temporary directory");
        let Some(full) = device(dir.path(), "full", "7") else {
            return;
        };
        for size in [10, 100_000] {
            let e = AtomicFile::create(&full)
                .expect("opened")
                .write_and_commit(&vec![7; size])
                .expect_err("a full device refuses the bytes");
            assert!(e.to_string().contains("No space left"), "{e}");
        }
        assert!(is_char_device(&full));
        assert_eq!(names(dir.path()), ["full"]);
    }
}
