//! The located events of a run ([`crate::events`]): `RUN.csv.events.csv` beside a run's CSV (header
//! `event,t,value,direction`, one row per occurrence in time order), or a table on stderr; read back by `plot` and
//! `view` ([`run_events`]).

use std::fmt::Write as _;
use std::path::{Path, PathBuf};

use super::run_csv::CsvInputError;
use super::sidecar::Sidecar;
use crate::events::Occurrence;

/// The events file of the run whose CSV is `csv`: `csv` with `.events.csv` appended.
///
/// ```
/// use std::path::Path;
/// assert_eq!(eulerdyn::output::events_file::events_path(Path::new("runs/p.csv")), Path::new("runs/p.csv.events.csv"));
/// ```
pub fn events_path(csv: &Path) -> PathBuf {
    PathBuf::from(format!("{}.events.csv", csv.display()))
}

/// The events file's text: the header and one row per occurrence (numbers as the shortest text that reads back
/// to the same f64).
pub fn events_csv(occurrences: &[Occurrence]) -> String {
    let mut text = String::from("event,t,value,direction\n");
    for o in occurrences {
        let _ = writeln!(text, "{},{},{},{}", o.name, o.t, o.value, o.kind.name());
    }
    text
}

/// The occurrences as a table for a terminal (aligned columns, 12 significant digits; "no events" when none).
pub fn events_table(occurrences: &[Occurrence]) -> String {
    if occurrences.is_empty() {
        return "events: none located\n".into();
    }
    let width = (occurrences.iter().map(|o| o.name.len()))
        .max()
        .unwrap_or(0)
        .max(5);
    let mut text = format!(
        "{:<width$}  {:>19}  {:>19}  direction\n",
        "event", "t (s)", "value"
    );
    for o in occurrences {
        let _ = writeln!(
            text,
            "{:<width$}  {:>19.12e}  {:>19.12e}  {}",
            o.name,
            o.t,
            o.value,
            o.kind.name()
        );
    }
    text
}

/// One located event as read back from a run's files: the events file's row, and the quantity (`when`) its
/// `[[event]]` watches where the run's sidecar tells it.
#[derive(Debug, Clone, PartialEq)]
pub struct EventRow {
    /// The `[[event]]`'s name.
    pub event: String,
    /// The time (s).
    pub t: f64,
    /// The quantity's value there.
    pub value: f64,
    /// `up`, `down`, `max` or `min`.
    pub direction: String,
    /// The quantity: a CSV column or `|X|` (None without the scene in a sidecar).
    pub when: Option<String>,
}

/// The directions an events file may name.
const DIRECTIONS: [&str; 4] = ["up", "down", "max", "min"];

/// Parses the text of an events file (`file` names it in messages): the header `event,t,value,direction`, then rows
/// of a name, two finite numbers and a direction. A file that is not one is refused naming its line.
pub fn parse_events_csv(file: &Path, text: &str) -> Result<Vec<EventRow>, CsvInputError> {
    let mut lines = text.lines().map(|l| l.trim_end_matches('\r'));
    let header = lines.next().unwrap_or("");
    if header != "event,t,value,direction" {
        return Err(CsvInputError::new(
            file,
            format!(
                "line 1: the header is \"{header}\", not \"event,t,value,direction\": is it an events file written by `eulerdyn run`?"
            ),
        ));
    }
    let mut rows = Vec::new();
    for (k, line) in lines.enumerate().filter(|(_, l)| !l.is_empty()) {
        let at = |problem: String| CsvInputError::new(file, format!("line {}: {problem}", k + 2));
        let cells: Vec<&str> = line.split(',').collect();
        let [event, t, value, direction] = cells[..] else {
            return Err(at(format!("{} cells, not 4: \"{line}\"", cells.len())));
        };
        let number = |name: &str, cell: &str| match cell.trim().parse::<f64>() {
            Ok(v) if v.is_finite() => Ok(v),
            _ => Err(at(format!("{name} \"{cell}\" is not a finite number"))),
        };
        if event.is_empty() {
            return Err(at("the event has no name".into()));
        }
        if !DIRECTIONS.contains(&direction) {
            return Err(at(format!(
                "direction \"{direction}\" is not one of up, down, max, min"
            )));
        }
        rows.push(EventRow {
            event: event.to_string(),
            t: number("t", t)?,
            value: number("value", value)?,
            direction: direction.to_string(),
            when: None,
        });
    }
    Ok(rows)
}

/// The located events of the run whose CSV is `csv`, for `plot` and `view`: its events file (the one the sidecar
/// lists, else `csv.events.csv`) when it exists, else the occurrences the sidecar lists, else none; each with the
/// quantity its `[[event]]` watches, from the scene in the sidecar. A file that cannot be read or parsed is refused
/// naming it.
pub fn run_events(csv: &Path, sidecar: Option<&Sidecar>) -> Result<Vec<EventRow>, CsvInputError> {
    let listed = sidecar.and_then(|s| s.events.as_ref());
    let path = match listed {
        Some(l) => csv.with_file_name(&l.file),
        None => events_path(csv),
    };
    let mut rows = match std::fs::read_to_string(&path) {
        Ok(text) => parse_events_csv(&path, &text)?,
        Err(e) if e.kind() == std::io::ErrorKind::NotFound => (listed.iter())
            .flat_map(|l| &l.occurrences)
            .map(|o| EventRow {
                event: o.event.clone(),
                t: o.t,
                value: o.value,
                direction: o.direction.clone(),
                when: None,
            })
            .collect(),
        Err(e) => {
            return Err(CsvInputError::new(
                &path,
                format!("cannot read the events file: {e}"),
            ));
        }
    };
    if let Some(sidecar) = sidecar {
        for row in &mut rows {
            row.when = (sidecar.scene.spec.event.iter())
                .find(|e| e.name == row.event)
                .map(|e| e.when.clone());
        }
    }
    Ok(rows)
}
