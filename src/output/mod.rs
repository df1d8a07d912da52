//! Output: CSV rows (streaming), the atomic file writer (one policy for every output path) and its registry of
//! pending temporary files, the metadata sidecar, and SVG plots of a run's CSV.

pub mod atomic;
pub mod csv_writer;
pub mod meta;
pub mod pending;
pub mod plot;
pub mod run_csv;
mod ticks;
pub mod view;
pub mod work_precision;

pub use atomic::AtomicFile;
pub use csv_writer::CsvWriter;
