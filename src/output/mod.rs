//! Output: CSV rows (streaming), the atomic file writer (one policy for every output path) and its registry of
//! pending temporary files, the metadata sidecar, and SVG plots of a run's CSV.

pub mod accuracy;
pub mod atomic;
pub mod csv_writer;
pub mod events_file;
pub mod pending;
pub mod plot;
pub mod run_csv;
pub mod run_file;
pub mod sidecar;
mod ticks;
pub mod view;
pub mod work_precision;

pub use atomic::{AtomicFile, same_file};
pub use csv_writer::CsvWriter;
pub use run_file::{WriteRunError, write_run, write_run_with, write_run_with_events};
pub use sidecar::{Sidecar, sidecar_path};
