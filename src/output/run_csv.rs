//! Reading a run's CSV back: the one reader that `plot` and `view` share.
//!
//! Columns are found by their header names (the order does not matter, extra columns are ignored), rows are
//! streamed (memory does not grow with the number of rows), and only the asked-for cells are parsed. A file that
//! cannot be used — a directory, empty, a row of the wrong length, a cell that is not a finite number — is refused
//! with a [`CsvInputError`] that names the file, the row (and line) and the column.

use std::fs::File;
use std::io::Read;
use std::path::{Path, PathBuf};

/// Why a run's CSV cannot be read: the file and the problem in words.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[error("{}: {problem}", file.display())]
pub struct CsvInputError {
    /// The file (or `stdin`).
    pub file: PathBuf,
    /// What is wrong, with row, line and column where known.
    pub problem: String,
}

impl CsvInputError {
    /// The error `problem` about `file`.
    pub fn new(file: &Path, problem: impl Into<String>) -> Self {
        Self {
            file: file.to_path_buf(),
            problem: problem.into(),
        }
    }
}

/// A run's CSV being read: its header, then data rows one at a time.
pub struct RunCsvReader<R: Read> {
    /// The file, for messages.
    file: PathBuf,
    csv: csv::Reader<R>,
    header: Vec<String>,
    record: csv::ByteRecord,
    /// Data rows read so far.
    rows: u64,
}

impl RunCsvReader<File> {
    /// Opens the CSV file `path` and reads its header; a directory, an unreadable or an empty file is refused.
    pub fn open(path: &Path) -> Result<Self, CsvInputError> {
        if path.is_dir() {
            return Err(CsvInputError::new(
                path,
                "is a directory; give the CSV file written by `eulerdyn run`",
            ));
        }
        let file = File::open(path)
            .map_err(|e| CsvInputError::new(path, format!("cannot read the file: {e}")))?;
        RunCsvReader::new(path, file)
    }
}

impl<R: Read> RunCsvReader<R> {
    /// Reads the header from `reader`; `file` names it in messages. An empty file is refused.
    pub fn new(file: &Path, reader: R) -> Result<Self, CsvInputError> {
        let mut csv = csv::ReaderBuilder::new()
            .has_headers(true)
            .trim(csv::Trim::All)
            .from_reader(reader);
        let header: Vec<String> = csv
            .byte_headers()
            .map_err(|e| CsvInputError::new(file, csv_problem(&e)))?
            .iter()
            .map(|name| String::from_utf8_lossy(name).into_owned())
            .collect();
        if header.is_empty() || header.iter().all(String::is_empty) {
            return Err(CsvInputError::new(
                file,
                "the file is empty; expected a CSV written by `eulerdyn run` (header `t,q_w,q_x,...`, then one row per time)",
            ));
        }
        Ok(Self {
            file: file.to_path_buf(),
            csv,
            header,
            record: csv::ByteRecord::new(),
            rows: 0,
        })
    }

    /// The rotors whose three columns (`<name>_spin`, `<name>_h`, `<name>_torque`) the header has, in its order.
    pub fn rotor_names(&self) -> Vec<String> {
        (self.header().iter())
            .filter_map(|c| c.strip_suffix("_spin"))
            .filter(|name| {
                ["h", "torque"]
                    .iter()
                    .all(|s| self.index_of(&format!("{name}_{s}")).is_some())
            })
            .map(String::from)
            .collect()
    }

    /// The column names, in file order.
    pub fn header(&self) -> &[String] {
        &self.header
    }

    /// The file's name in messages.
    pub fn file(&self) -> &Path {
        &self.file
    }

    /// Data rows read so far.
    pub fn rows(&self) -> u64 {
        self.rows
    }

    /// The index of column `name` in the header.
    pub fn index_of(&self, name: &str) -> Option<usize> {
        self.header.iter().position(|h| h == name)
    }

    /// The header shown in a message: at most 120 characters.
    pub fn header_shown(&self) -> String {
        let shown = self.header.join(",");
        if shown.chars().count() > 120 {
            shown.chars().take(117).collect::<String>() + "..."
        } else {
            shown
        }
    }

    /// Reads the next data row into `values`: `values[k]` is the cell of column `index[k]`, named `names[k]` in
    /// messages. `Ok(false)` at the end of the file; a cell that is not a finite number is refused.
    pub fn next_row(
        &mut self,
        index: &[usize],
        names: &[&str],
        values: &mut [f64],
    ) -> Result<bool, CsvInputError> {
        match self.csv.read_byte_record(&mut self.record) {
            Ok(false) => return Ok(false),
            Ok(true) => {}
            Err(e) => return Err(CsvInputError::new(&self.file, csv_problem(&e))),
        }
        self.rows += 1;
        parse_row(&self.file, &self.record, self.rows, index, names, values)?;
        Ok(true)
    }
}

/// Parses the wanted cells of data row `row` into `values`; a cell that is not a finite number is refused.
fn parse_row(
    file: &Path,
    record: &csv::ByteRecord,
    row: u64,
    index: &[usize],
    names: &[&str],
    values: &mut [f64],
) -> Result<(), CsvInputError> {
    let line = record.position().map_or(row + 1, |p| p.line());
    for (k, (&i, &name)) in index.iter().zip(names).enumerate() {
        let cell = record.get(i).unwrap_or_default();
        let text = String::from_utf8_lossy(cell);
        let value = text.parse::<f64>().ok().filter(|v| v.is_finite());
        values[k] = value.ok_or_else(|| {
            let what = if text.is_empty() {
                "is empty".to_string()
            } else if text.parse::<f64>().is_ok() {
                format!("`{text}` is not a finite number")
            } else {
                format!("`{text}` is not a number")
            };
            CsvInputError::new(
                file,
                format!("row {row} (line {line}), column `{name}`: {what}"),
            )
        })?;
    }
    Ok(())
}

/// A CSV reader error in words, with its line.
fn csv_problem(e: &csv::Error) -> String {
    let line = e
        .position()
        .map(|p| format!("line {}: ", p.line()))
        .unwrap_or_default();
    match e.kind() {
        csv::ErrorKind::UnequalLengths {
            expected_len, len, ..
        } => format!(
            "{line}the row has {len} fields but the header has {expected_len}; every row of a run's CSV has one value per column"
        ),
        csv::ErrorKind::Io(io) => format!("cannot read the file: {io}"),
        _ => format!("{line}not a valid CSV file: {e}"),
    }
}
