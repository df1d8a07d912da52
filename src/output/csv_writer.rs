//! Streaming CSV writer: one header row, then one line per sample, numbers in the shortest form that reads back
//! to the same f64 (ryu). Memory does not grow with the number of rows.

use std::io::{self, BufWriter, Write};

use crate::sample::{ColumnSet, Sample};

/// Writes samples as CSV rows to any writer.
pub struct CsvWriter<W: Write> {
    out: BufWriter<W>,
    columns: ColumnSet,
    values: Vec<f64>,
    number: ryu::Buffer,
    rows: u64,
}

impl<W: Write> CsvWriter<W> {
    /// Starts the file with its header row.
    pub fn new(inner: W, columns: ColumnSet) -> io::Result<Self> {
        let mut out = BufWriter::with_capacity(1 << 16, inner);
        let header = columns.columns();
        let names: Vec<&str> = header.iter().map(|c| c.name.as_ref()).collect();
        writeln!(out, "{}", names.join(","))?;
        Ok(Self {
            out,
            columns,
            values: Vec::with_capacity(names.len()),
            number: ryu::Buffer::new(),
            rows: 0,
        })
    }

    /// Appends one row. A non-finite value is refused (an `InvalidData` error naming the column): the simulation
    /// must stop before it produces one.
    pub fn write(&mut self, sample: &Sample) -> io::Result<()> {
        self.columns
            .finite_values(sample, &mut self.values)
            .map_err(|e| io::Error::new(io::ErrorKind::InvalidData, e))?;
        for (i, v) in self.values.iter().enumerate() {
            if i > 0 {
                self.out.write_all(b",")?;
            }
            self.out
                .write_all(self.number.format_finite(*v).as_bytes())?;
        }
        self.out.write_all(b"\n")?;
        self.rows += 1;
        Ok(())
    }

    /// Rows written so far (header not counted).
    pub fn rows(&self) -> u64 {
        self.rows
    }

    /// Flushes and returns the inner writer.
    pub fn finish(self) -> io::Result<W> {
        self.out.into_inner().map_err(|e| e.into_error())
    }
}
