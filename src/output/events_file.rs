//! The located events of a run ([`crate::events`]): `RUN.csv.events.csv` beside a run's CSV (header
//! `event,t,value,direction`, one row per occurrence in time order), or a table on stderr.

use std::fmt::Write as _;
use std::path::{Path, PathBuf};

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
