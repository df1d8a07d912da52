//! A run written to a file: the CSV and its sidecar, both written atomically ([`AtomicFile`]: synced, then
//! renamed, the CSV first), so that a failed or interrupted run leaves no partial file and an existing output
//! untouched. A destination that is a device or a FIFO is written through, without a sidecar (the output policy
//! of [`AtomicFile`]).

use std::io;
use std::path::{Path, PathBuf};

use super::atomic::{AtomicFile, same_file};
use super::csv_writer::CsvWriter;
use super::events_file::{events_csv, events_path};
use super::sidecar::{Sidecar, sidecar_path};
use crate::events::Occurrence;
use crate::scene::Scene;
use crate::simulate::{self, RunError, RunReport};

/// Why [`write_run`] failed.
#[derive(Debug, thiserror::Error)]
pub enum WriteRunError {
    /// The output cannot be created (a missing directory, the scene file itself): bad input, nothing written.
    #[error("{}: {problem}", file.display())]
    Output {
        /// The output path.
        file: PathBuf,
        /// What is wrong with it.
        problem: String,
    },
    /// The run failed (diverged, or the integrator gave up) or a file could not be written or saved.
    #[error(transparent)]
    Run(#[from] RunError<io::Error>),
    /// A file could not be written or saved after the run.
    #[error("{}: {problem}", file.display())]
    Save {
        /// The file.
        file: PathBuf,
        /// What failed.
        problem: String,
    },
}

/// Runs `scene` and writes its CSV to `path` and its [`Sidecar`] to `path.meta.json` (none beside a device or a
/// FIFO).
///
/// ```
/// use eulerdyn::scene::{BodySpec, SceneSpec};
/// let dir = tempfile::tempdir()?;
/// let scene = SceneSpec::new(BodySpec::principal(1.0, [1.0, 2.0, 3.0]), 1.0, 0.5).with_omega([0.1, 2.0, 0.0]).build()?;
/// let report = eulerdyn::output::write_run(&scene, &dir.path().join("run.csv"))?;
/// assert_eq!(report.rows, 3);
/// assert!(dir.path().join("run.csv.meta.json").exists());
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
pub fn write_run(scene: &Scene, path: &Path) -> Result<RunReport, WriteRunError> {
    write_run_with(scene, path, |_| {})
}

/// [`write_run`], telling `progress` the time of every row written.
pub fn write_run_with(
    scene: &Scene,
    path: &Path,
    progress: impl FnMut(f64),
) -> Result<RunReport, WriteRunError> {
    write_run_with_events(scene, path, progress).map(|(report, _)| report)
}

/// [`write_run_with`], returning the located events too; a scene with `[[event]]`s also gets `path.events.csv`
/// ([`events_csv`]), listed in the sidecar, all three files committed together (none beside a device or a FIFO).
pub fn write_run_with_events(
    scene: &Scene,
    path: &Path,
    mut progress: impl FnMut(f64),
) -> Result<(RunReport, Vec<Occurrence>), WriteRunError> {
    if let Some(source) = &scene.source
        && same_file(&source.path, path)
    {
        return Err(WriteRunError::Output {
            file: path.to_path_buf(),
            problem: "the output would overwrite the scene file; give another path".into(),
        });
    }
    let columns = scene.facts().columns().clone();
    let mut csv_file = AtomicFile::create(path).map_err(|e| WriteRunError::Output {
        file: path.to_path_buf(),
        problem: format!("cannot create the output file: {e}"),
    })?;
    let mut writer = CsvWriter::new(csv_file.file(), columns.clone()).map_err(RunError::Sink)?;
    let (report, events) = simulate::run_with_events(scene, |s| {
        progress(s.t);
        writer.write(s)
    })?;
    writer.finish().map_err(RunError::Sink)?;
    let save = |file: &Path, what: &str, e: io::Error| WriteRunError::Save {
        file: file.to_path_buf(),
        problem: format!("{what}: {e}"),
    };
    if csv_file.writes_through() {
        // A device or a FIFO: no sidecar beside it (`/dev/null.meta.json`).
        csv_file
            .commit()
            .map_err(|e| save(path, "cannot write", e))?;
        return Ok((report, events));
    }
    let meta_path = sidecar_path(path);
    let events_file = (!scene.events.is_empty()).then(|| events_path(path));
    let sidecar = Sidecar::of_run(scene, &report, &columns.columns())
        .with_events(events_file.as_deref(), &events);
    let mut files = vec![(path.to_path_buf(), csv_file)];
    let mut extra = vec![(meta_path, sidecar.to_json())];
    if let Some(events_file) = events_file {
        extra.push((events_file, events_csv(&events)));
    }
    for (file, text) in extra {
        let out = AtomicFile::create(&file).map_err(|e| save(&file, "cannot create", e))?;
        let out = (out.write(text.as_bytes())).map_err(|e| save(&file, "cannot write", e))?;
        files.push((file, out));
    }
    // Every file on disk before any is renamed: the CSV first, then its sidecar and events.
    let (names, files): (Vec<PathBuf>, Vec<AtomicFile>) = files.into_iter().unzip();
    AtomicFile::commit_all(files).map_err(|(which, e)| save(&names[which], "cannot save", e))?;
    Ok((report, events))
}
