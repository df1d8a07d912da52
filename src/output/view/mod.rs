//! `eulerdyn view`: a run shown in 3D, as one self-contained HTML page.
//!
//! The page carries everything it needs inline — three.js (vendored in `assets/three/`, embedded at build time),
//! its own script and style (`assets/view/`), and the run's rows as JSON numbers that read back to the same f64 —
//! and makes no network request (its Content-Security-Policy forbids any). It draws the body by its shape (from
//! the run's sidecar), space and body axes, the fixed axis and the bearings, the vectors ω, H and M (and the
//! bearings' forces), the trail of H's tip, and for free motion the polhode; it lists the run's located events
//! (its events file, [`run_events`]), each a button that jumps to its time; and it exposes
//! `window.eulerdyn = { rows, events, t_end, setTime(t), state() }` for tests and scripts.
//!
//! Long runs are decimated by the rule in [`rows`]: at most [`MAX_DRAWN_ROWS`] rows, evenly in time, plus the last.

pub mod geometry;
pub mod page;
pub mod rows;

use std::io::Read;
use std::path::{Path, PathBuf};

pub use geometry::{Geometry, read_geometry};
pub use rows::{MAX_DRAWN_ROWS, Rows, read_rows};

use super::events_file::{EventRow, run_events};
use super::run_csv::{CsvInputError, RunCsvReader};
use super::sidecar::Sidecar;

/// Why a page could not be made.
#[derive(Debug, thiserror::Error)]
pub enum ViewError {
    /// The CSV cannot be used, or the output file cannot be created (bad input, exit 2).
    #[error("{}: {problem}", file.display())]
    Input {
        /// The file.
        file: PathBuf,
        /// What is wrong.
        problem: String,
    },
    /// The page could not be written (exit 1).
    #[error("{}: {problem}", file.display())]
    Output {
        /// The file.
        file: PathBuf,
        /// What failed.
        problem: String,
    },
}

impl From<CsvInputError> for ViewError {
    fn from(e: CsvInputError) -> Self {
        ViewError::Input {
            file: e.file,
            problem: e.problem,
        }
    }
}

/// A run read for the page: its kept rows and its geometry.
#[derive(Debug, Clone, PartialEq)]
pub struct ViewRun {
    /// The CSV's name, shown in the page.
    pub file: PathBuf,
    /// The rows drawn.
    pub rows: Rows,
    /// What the page draws of the body and its supports.
    pub geometry: Geometry,
    /// The run's located events, in time order (none for a CSV from stdin).
    pub events: Vec<EventRow>,
}

impl ViewRun {
    /// What the page carries, in words: all rows, or which ones the decimation rule kept.
    pub fn rows_note(&self) -> String {
        let rows = &self.rows;
        if rows.stride == 1 {
            format!("all {} rows of the run are drawn", rows.rows_in_run)
        } else {
            format!(
                "{} of the run's {} rows are drawn: every {}th row from the first, and the last (at most {} rows \
                 are kept; between them the state is interpolated, so state() is exact only at the kept rows' times)",
                rows.len(),
                rows.rows_in_run,
                rows.stride,
                MAX_DRAWN_ROWS
            )
        }
    }
}

/// Reads the run's CSV `csv` (`-`: stdin, with no sidecar) and its sidecar, keeping at most `max_rows` rows.
pub fn read_view_run(csv: &Path, max_rows: usize) -> Result<ViewRun, ViewError> {
    if csv.as_os_str() == "-" {
        let geometry = Geometry::unknown(
            "the CSV came from stdin, so there is no sidecar: the body's shape, inertia and supports are \
             unknown; the body is drawn as a unit cube (not to scale), with no fixed axis, bearings or polhode"
                .into(),
        );
        return read_from(
            Path::new("stdin"),
            std::io::stdin().lock(),
            max_rows,
            geometry,
        );
    }
    let reader = RunCsvReader::open(csv)?;
    let geometry = read_geometry(csv);
    let rows = read_rows(reader, max_rows, &geometry.moving_mass_names())?;
    Ok(ViewRun {
        file: csv.to_path_buf(),
        rows,
        geometry,
        events: run_events(csv, Sidecar::read(csv).ok().as_ref())?,
    })
}

/// Reads a run's CSV from `reader` (`file` names it in messages), to be drawn with `geometry`.
pub fn read_from(
    file: &Path,
    reader: impl Read,
    max_rows: usize,
    geometry: Geometry,
) -> Result<ViewRun, ViewError> {
    let rows = read_rows(RunCsvReader::new(file, reader)?, max_rows, &[])?;
    Ok(ViewRun {
        file: file.to_path_buf(),
        rows,
        geometry,
        events: Vec::new(),
    })
}

/// What [`view_file`] wrote.
#[derive(Debug, Clone, PartialEq)]
pub struct ViewSummary {
    /// Data rows in the run.
    pub rows_in_run: u64,
    /// Rows the page carries.
    pub rows_drawn: usize,
    /// The decimation's stride: every `stride`th row is kept (and the last); 1 when all are.
    pub stride: u64,
    /// Bytes written.
    pub bytes: usize,
    /// What could not be drawn, in words (from [`Geometry::notes`]).
    pub notes: Vec<String>,
}

/// Reads the run's CSV `csv` and its sidecar and writes the page to `out` atomically: on any error no file (or
/// the old one) is left at `out`.
pub fn view_file(csv: &Path, out: &Path) -> Result<ViewSummary, ViewError> {
    let run = read_view_run(csv, MAX_DRAWN_ROWS)?;
    let html = page::render(&run);
    let file = super::AtomicFile::create(out).map_err(|e| ViewError::Input {
        file: out.to_path_buf(),
        problem: format!("cannot create the output file: {e}"),
    })?;
    file.write_and_commit(html.as_bytes())
        .map_err(|e| ViewError::Output {
            file: out.to_path_buf(),
            problem: e.to_string(),
        })?;
    Ok(ViewSummary {
        rows_in_run: run.rows.rows_in_run,
        rows_drawn: run.rows.len(),
        stride: run.rows.stride,
        bytes: html.len(),
        notes: run.geometry.notes,
    })
}
