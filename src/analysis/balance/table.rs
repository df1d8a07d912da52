//! The measured table of `eulerdyn balance --measured PHASORS.csv`: one row per run, header
//! `run,trial_plane,trial_mass_g,trial_angle_deg,A_amp,A_phase_deg,B_amp,B_phase_deg`. A row with `trial_plane`
//! empty is an initial run (its trial cells empty or 0); a row with `A` or `B` had a trial mass (g, > 0) at the
//! angle `trial_angle_deg` in that plane, at the correction radius. Messages name the file, the line and the
//! column.

use std::path::Path;

use crate::scene::SceneError;

use super::influence::{Run, phasor};

/// The header, exactly.
pub const HEADER: [&str; 8] = [
    "run",
    "trial_plane",
    "trial_mass_g",
    "trial_angle_deg",
    "A_amp",
    "A_phase_deg",
    "B_amp",
    "B_phase_deg",
];

/// One row: its line in the file, its `run` label and what it measured.
#[derive(Debug, Clone, PartialEq)]
pub struct Row {
    /// Its line in the file (1 is the header).
    pub line: usize,
    /// Its `run` label.
    pub label: String,
    /// What it measured: an initial run or a trial in plane A or B.
    pub run: Run,
}

/// The rows of a measured table, checked: at least one initial run, and trials either in both planes or in none.
#[derive(Debug, Clone, PartialEq)]
pub struct Table {
    /// The rows, in file order.
    pub rows: Vec<Row>,
}

impl Table {
    /// The runs in file order.
    pub fn runs(&self) -> Vec<Run> {
        self.rows.iter().map(|r| r.run).collect()
    }

    /// Whether the table has trial runs (else it is balanced one-shot, with the model's coefficients).
    pub fn has_trials(&self) -> bool {
        self.rows.iter().any(|r| r.run.trial.is_some())
    }

    /// "lines 3, 5" of the trial runs in `plane` (0 = A, 1 = B).
    pub fn trial_lines(&self, plane: usize) -> String {
        let lines: Vec<String> = self
            .rows
            .iter()
            .filter(|r| r.run.trial.is_some_and(|(p, _)| p == plane))
            .map(|r| format!("{} (run {})", r.line, r.label))
            .collect();
        let word = if lines.len() == 1 { "line" } else { "lines" };
        format!("{word} {}", lines.join(", "))
    }
}

/// The text of the table file `path`: an unreadable file is an error naming it.
pub fn read(path: &Path) -> Result<String, SceneError> {
    std::fs::read_to_string(path).map_err(|e| SceneError {
        file: path.to_path_buf(),
        key: None,
        location: None,
        problem: format!("cannot read the table: {e}"),
    })
}

/// Reads the table `text` of the file `path` (named in messages).
pub fn parse(path: &Path, text: &str) -> Result<Table, SceneError> {
    let error = |problem: String| SceneError {
        file: path.to_path_buf(),
        key: None,
        location: None,
        problem,
    };
    // A spreadsheet's byte-order mark and CRLF line ends: made plain here, so that the reader's line numbers are
    // the file's (the csv reader counts the first record after a CRLF header as line 1).
    let text = text
        .strip_prefix('\u{feff}')
        .unwrap_or(text)
        .replace("\r\n", "\n");
    let mut reader = csv::ReaderBuilder::new()
        .has_headers(true)
        .trim(csv::Trim::All)
        .from_reader(text.as_bytes());
    let header = reader
        .headers()
        .map_err(|e| error(format!("cannot read the header: {e}")))?;
    if header.iter().ne(HEADER) {
        return Err(error(format!(
            "the header must be `{}` (it is `{}`)",
            HEADER.join(","),
            header.iter().collect::<Vec<_>>().join(",")
        )));
    }
    let mut rows = Vec::new();
    for record in reader.records() {
        let record = record.map_err(|e| error(read_error(&e)))?;
        let line = record.position().map_or(0, |p| p.line() as usize);
        rows.push(parse_row(&record, line).map_err(error)?);
    }
    check(Table { rows }).map_err(error)
}

/// What the CSV reader could not read: a row of the wrong length by its line, anything else as the reader says.
fn read_error(e: &csv::Error) -> String {
    match e.kind() {
        csv::ErrorKind::UnequalLengths {
            pos: Some(pos),
            expected_len,
            len,
        } => format!(
            "line {}: a row has the header's {expected_len} cells (this one has {len})",
            pos.line()
        ),
        _ => format!("cannot read the table: {e}"),
    }
}

/// One record (`line` in the file) as a row.
fn parse_row(record: &csv::StringRecord, line: usize) -> Result<Row, String> {
    let label = record[0].to_string();
    let at = |k: usize, problem: &str| {
        format!(
            "line {line} (run {label}), {} `{}`: {problem}",
            HEADER[k], &record[k]
        )
    };
    let number = |k: usize| -> Result<Option<f64>, String> {
        match &record[k] {
            "" => Ok(None),
            cell => match cell.parse::<f64>() {
                Ok(x) if x.is_finite() => Ok(Some(x)),
                _ => Err(at(k, "not a finite number")),
            },
        }
    };
    let required = |k: usize| number(k)?.ok_or_else(|| at(k, "a number is needed"));
    let trial = match record[1].to_ascii_uppercase().as_str() {
        "" => {
            for k in [2, 3] {
                if number(k)?.is_some_and(|x| x != 0.0) {
                    return Err(at(
                        k,
                        "an initial run (trial_plane empty) has no trial mass",
                    ));
                }
            }
            None
        }
        plane @ ("A" | "B") => {
            let mass = required(2)?;
            if mass <= 0.0 {
                return Err(at(2, "the trial mass must be > 0 g"));
            }
            Some((usize::from(plane == "B"), phasor(mass, required(3)?)))
        }
        _ => return Err(at(1, "give A or B, or leave it empty for the initial run")),
    };
    let mut readings = [phasor(0.0, 0.0); 2];
    for (sensor, k) in [(0, 4), (1, 6)] {
        let amp = required(k)?;
        if amp < 0.0 {
            return Err(at(k, "an amplitude is >= 0"));
        }
        readings[sensor] = phasor(amp, required(k + 1)?);
    }
    Ok(Row {
        line,
        label,
        run: Run { trial, readings },
    })
}

/// The table's structure: runs at all, an initial run, and trials in both planes or in none.
fn check(table: Table) -> Result<Table, String> {
    if table.rows.is_empty() {
        return Err(
            "no runs: the table needs an initial run (trial_plane empty) and trial runs".into(),
        );
    }
    if table.rows.iter().all(|r| r.run.trial.is_some()) {
        return Err(
            "no initial run: one row must leave trial_plane empty (the run without trial masses)"
                .into(),
        );
    }
    let in_plane = |p: usize| {
        table
            .rows
            .iter()
            .any(|r| r.run.trial.is_some_and(|(q, _)| q == p))
    };
    match (in_plane(0), in_plane(1)) {
        (true, false) | (false, true) => {
            let (has, lacks) = if in_plane(0) { (0, "B") } else { (1, "A") };
            Err(format!(
                "trial runs in plane {} ({}) but none in plane {lacks}: add a trial run in plane {lacks}, or give \
                 only the initial run to balance with the scene's model (one-shot)",
                ["A", "B"][has],
                table.trial_lines(has)
            ))
        }
        _ => Ok(table),
    }
}
