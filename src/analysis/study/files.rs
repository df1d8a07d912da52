//! The work-precision study ([`crate::analysis::study`]) of a scene file with its table and figure written
//! atomically (`eulerdyn accuracy SCENE -o TABLE.csv --plot FIG.svg`).

use std::path::Path;

use super::figure;
use crate::analysis::study::{self, Study, StudyError, StudyOptions};
use crate::output::{AtomicFile, same_file};
use crate::scene::{self, Overrides};

/// Opens an output file atomically, refusing the scene file itself.
fn create_output(scene: &Path, out: &Path) -> Result<AtomicFile, StudyError> {
    let refuse = |problem: String| StudyError::Output {
        file: out.to_path_buf(),
        problem,
        input: true,
    };
    if same_file(scene, out) {
        return Err(refuse(
            "the output would overwrite the scene file; give another path".into(),
        ));
    }
    AtomicFile::create(out).map_err(|e| refuse(format!("cannot create the output file: {e}")))
}

/// Writes `bytes` into an open output file and renames it over its destination.
fn finish_output(file: AtomicFile, bytes: &[u8]) -> Result<(), StudyError> {
    let path = file.path().to_path_buf();
    file.write_and_commit(bytes)
        .map_err(|e| StudyError::Output {
            file: path,
            problem: e.to_string(),
            input: false,
        })
}

/// Reads and validates the scene, creates the output files (before the study, so that a bad path fails at once),
/// runs the study with `progress` (see [`study::accuracy`]), then writes the table and the figure atomically: on
/// any failure no partial file is left and existing files are untouched. Returns the study; print
/// [`Study::summary`], and [`Study::table_csv`] when no table file is given.
pub fn run_accuracy_command(
    scene_path: &Path,
    table: Option<&Path>,
    plot: Option<&Path>,
    options: &StudyOptions,
    progress: impl FnMut(usize, usize, &str),
) -> Result<Study, StudyError> {
    let scene = scene::load(scene_path, &Overrides::default())?;
    if let (Some(t), Some(p)) = (table, plot)
        && t == p
    {
        return Err(StudyError::Output {
            file: p.to_path_buf(),
            problem: "the table and the figure would be the same file".into(),
            input: true,
        });
    }
    let table_file = table.map(|p| create_output(scene_path, p)).transpose()?;
    let plot_file = plot.map(|p| create_output(scene_path, p)).transpose()?;
    let study = study::accuracy(&scene, options, progress)?;
    let svg = match &plot_file {
        Some(f) => Some(
            figure::render_svg(&study).map_err(|problem| StudyError::Output {
                file: f.path().to_path_buf(),
                problem,
                input: false,
            })?,
        ),
        None => None,
    };
    if let Some(f) = table_file {
        finish_output(f, study.table_csv().as_bytes())?;
    }
    if let (Some(f), Some(svg)) = (plot_file, svg) {
        finish_output(f, svg.as_bytes())?;
    }
    Ok(study)
}
