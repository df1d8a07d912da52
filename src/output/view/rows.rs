//! The rows the page draws: the columns it needs, read from the run's CSV with the shared reader, and
//! decimated for long runs; with rotors, each wheel's axial momentum `<name>_h`; with moving masses, each one's
//! position `<name>_x`, `<name>_y`, `<name>_z`.
//!
//! **Decimation rule.** At most [`MAX_DRAWN_ROWS`] rows are kept: every s-th data row counting from the first
//! (rows 0, s, 2s, …), s the smallest power of two that keeps at most [`MAX_DRAWN_ROWS`] of them, plus the last
//! row. Rows of a run are evenly spaced in time (t = k·every), so the kept rows are too. Kept rows carry their
//! values unchanged; between kept rows the page interpolates. Reading streams: memory is bounded by
//! [`MAX_DRAWN_ROWS`] whatever the run's length.

use std::io::Read;

use crate::output::run_csv::{CsvInputError, RunCsvReader};
use crate::wheels::rotor_columns;

/// The most rows a page carries (see the module documentation for which).
pub const MAX_DRAWN_ROWS: usize = 10_000;

/// The columns every page needs: time, attitude, ω in space and body axes, H and M in space axes.
pub const REQUIRED: [&str; 17] = [
    "t",
    "q_w",
    "q_x",
    "q_y",
    "q_z",
    "omega_s_x",
    "omega_s_y",
    "omega_s_z",
    "omega_b_x",
    "omega_b_y",
    "omega_b_z",
    "H_s_x",
    "H_s_y",
    "H_s_z",
    "M_s_x",
    "M_s_y",
    "M_s_z",
];

/// Column groups drawn when the CSV has all of the group: the bearings' forces on the body, in space axes; in
/// orbit, the Earth's field in body axes (drawn as its direction).
pub const OPTIONAL: [[&str; 3]; 3] = [
    ["R_A_s_x", "R_A_s_y", "R_A_s_z"],
    ["R_B_s_x", "R_B_s_y", "R_B_s_z"],
    ["B_b_x", "B_b_y", "B_b_z"],
];

/// The wheels' axial momentum columns `<name>_h`, in the header's order, of the rotors whose three columns
/// (`<name>_spin`, `<name>_h`, `<name>_torque`, [`rotor_columns`]) the CSV has.
fn rotor_momentum_columns(csv: &RunCsvReader<impl Read>) -> Vec<String> {
    let names = csv.rotor_names();
    (rotor_columns(&names, false).into_iter())
        .filter(|c| c.name.ends_with("_h"))
        .map(|c| c.name.into_owned())
        .collect()
}

/// The kept rows of a run.
#[derive(Debug, Clone, PartialEq)]
pub struct Rows {
    /// The columns of each kept row, in order.
    pub columns: Vec<String>,
    /// The kept rows, one after another (`columns.len()` values each).
    pub values: Vec<f64>,
    /// Data rows in the CSV.
    pub rows_in_run: u64,
    /// The stride s of the decimation rule (1: every row kept).
    pub stride: u64,
}

impl Rows {
    /// Number of kept rows.
    pub fn len(&self) -> usize {
        self.values.len() / self.columns.len().max(1)
    }

    /// Whether no row is kept.
    pub fn is_empty(&self) -> bool {
        self.values.is_empty()
    }

    /// Kept row `k`.
    pub fn row(&self, k: usize) -> &[f64] {
        let width = self.columns.len();
        &self.values[k * width..(k + 1) * width]
    }
}

/// Keeps every s-th row pushed and the last one, s doubling whenever more than `max` would be kept.
#[derive(Debug, Clone)]
pub struct RowKeeper {
    width: usize,
    max: usize,
    stride: u64,
    kept: Vec<f64>,
    /// Index and values of the latest row pushed.
    latest: Option<(u64, Vec<f64>)>,
    pushed: u64,
}

impl RowKeeper {
    /// A keeper of rows of `width` values, at most `max` (≥ 2) rows besides the last.
    pub fn new(width: usize, max: usize) -> Self {
        Self {
            width,
            max: max.max(2),
            stride: 1,
            kept: Vec::new(),
            latest: None,
            pushed: 0,
        }
    }

    /// Offers the next row.
    pub fn push(&mut self, row: &[f64]) {
        let index = self.pushed;
        self.pushed += 1;
        if index % self.stride == 0 {
            self.kept.extend_from_slice(row);
            if self.kept.len() / self.width > self.max {
                self.halve();
            }
        }
        match &mut self.latest {
            Some((i, values)) => {
                *i = index;
                values.copy_from_slice(row);
            }
            None => self.latest = Some((index, row.to_vec())),
        }
    }

    /// Doubles the stride: keeps the rows at even positions of those kept (the multiples of the new stride).
    fn halve(&mut self) {
        let width = self.width;
        let rows = self.kept.len() / width;
        for (to, from) in (0..rows).step_by(2).enumerate() {
            self.kept
                .copy_within(from * width..(from + 1) * width, to * width);
        }
        self.kept.truncate(rows.div_ceil(2) * width);
        self.stride *= 2;
    }

    /// The kept rows (the last row appended when the stride skipped it), the rows pushed and the stride.
    pub fn finish(mut self) -> (Vec<f64>, u64, u64) {
        if let Some((index, values)) = self.latest
            && index % self.stride != 0
        {
            self.kept.extend_from_slice(&values);
        }
        (self.kept, self.pushed, self.stride)
    }
}

/// Reads the rows a page draws from `csv`, decimated to at most `max` rows (plus the last), with the positions of
/// the moving masses named `moving` whose three columns the CSV has. A CSV without the columns every run has is
/// refused as not an eulerdyn run.
pub fn read_rows(
    mut csv: RunCsvReader<impl Read>,
    max: usize,
    moving: &[String],
) -> Result<Rows, CsvInputError> {
    let missing: Vec<&str> = REQUIRED
        .iter()
        .copied()
        .filter(|c| csv.index_of(c).is_none())
        .collect();
    if !missing.is_empty() {
        return Err(CsvInputError::new(
            csv.file(),
            format!(
                "not a run written by `eulerdyn run`: no column {}. Its header is: {}",
                missing
                    .iter()
                    .map(|c| format!("`{c}`"))
                    .collect::<Vec<_>>()
                    .join(", "),
                csv.header_shown()
            ),
        ));
    }
    let momentum_columns = rotor_momentum_columns(&csv);
    let mut columns: Vec<&str> = REQUIRED.to_vec();
    for group in OPTIONAL {
        if group.iter().all(|c| csv.index_of(c).is_some()) {
            columns.extend(group);
        }
    }
    columns.extend(momentum_columns.iter().map(String::as_str));
    let positions: Vec<String> = (moving.iter())
        .map(|name| ["x", "y", "z"].map(|axis| format!("{name}_{axis}")))
        .filter(|group| group.iter().all(|c| csv.index_of(c).is_some()))
        .flatten()
        .collect();
    columns.extend(positions.iter().map(String::as_str));
    let index: Vec<usize> = columns.iter().filter_map(|c| csv.index_of(c)).collect();
    let mut keeper = RowKeeper::new(columns.len(), max);
    let mut values = vec![0.0; columns.len()];
    while csv.next_row(&index, &columns, &mut values)? {
        keeper.push(&values);
    }
    let (values, rows_in_run, stride) = keeper.finish();
    if rows_in_run == 0 {
        return Err(CsvInputError::new(
            csv.file(),
            "the file has a header but no data rows; nothing to show",
        ));
    }
    Ok(Rows {
        columns: columns.into_iter().map(str::to_string).collect(),
        values,
        rows_in_run,
        stride,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The indices kept from `n` rows with at most `max` kept.
    fn kept(n: u64, max: usize) -> (Vec<u64>, u64) {
        let mut keeper = RowKeeper::new(1, max);
        for k in 0..n {
            keeper.push(&[k as f64]);
        }
        let (values, pushed, stride) = keeper.finish();
        assert_eq!(pushed, n);
        (values.iter().map(|&v| v as u64).collect(), stride)
    }

    #[test]
    fn short_runs_keep_every_row() {
        assert_eq!(kept(5, 10), (vec![0, 1, 2, 3, 4], 1));
        assert_eq!(kept(10, 10).0.len(), 10);
    }

    #[test]
    fn long_runs_keep_every_s_th_row_and_the_last_with_s_the_smallest_power_of_two_that_fits() {
        let (rows, stride) = kept(1001, 100);
        // ceil(1001 / 8) = 126 > 100, ceil(1001 / 16) = 63 <= 100.
        assert_eq!(stride, 16);
        let expected: Vec<u64> = (0..=1000).step_by(16).chain([1000]).collect();
        assert_eq!(rows, expected);
        let (rows, stride) = kept(1_000_000, MAX_DRAWN_ROWS);
        assert_eq!(stride, 128);
        assert_eq!(rows.len(), 7813 + 1);
        assert_eq!(*rows.last().expect("rows"), 999_999);
    }

    #[test]
    fn the_last_row_is_not_repeated_when_the_stride_keeps_it() {
        let (rows, stride) = kept(17, 10);
        assert_eq!(stride, 2);
        assert_eq!(rows, vec![0, 2, 4, 6, 8, 10, 12, 14, 16]);
    }
}
