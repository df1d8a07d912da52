//! Output: CSV rows (streaming), the atomic file writer, and the metadata sidecar.

pub mod atomic;
pub mod csv_writer;
pub mod meta;
pub mod sample;

pub use atomic::AtomicFile;
pub use csv_writer::CsvWriter;
pub use sample::{Column, ColumnSet, Sample};
