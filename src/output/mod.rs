//! Output: CSV rows (streaming), the atomic file writer (one policy for every output path) and its registry of
//! pending temporary files, the metadata sidecar, and (features `plot` and `view`) SVG plots of a run's CSV and its 3D
//! page.

pub mod atomic;
pub mod csv_writer;
pub mod events_file;
pub mod pending;
#[cfg(feature = "plot")]
pub mod plot;
pub mod run_csv;
pub mod run_file;
pub mod sidecar;
mod temp_file;
#[cfg(feature = "plot")]
mod ticks;
#[cfg(feature = "view")]
pub mod view;

pub use atomic::{AtomicFile, same_file};
pub use csv_writer::CsvWriter;
pub use run_file::{WriteRunError, write_run, write_run_with, write_run_with_events};
pub use sidecar::{Sidecar, sidecar_path};
