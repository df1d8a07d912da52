//! `[[event]]`'s keys, declared once ([`EventFile`]: the file form and the reference's table), and [`EventSpec`]
//! as a [`Part`]: read from that table (`name` and `when`, exactly one of `crosses`, with its optional
//! `direction`, and `extremum`) and written back. The scene registers it with one line, `each event: EventSpec`.

use super::spec::{ConditionSpec, EventSpec};
use super::{Direction, Extremum};
use crate::keys::{Checked, KeyPath, Part, Table, file_table, invalid, key, required};

file_table! {
    /// One `[[event]]`.
    pub(crate) struct EventFile(pub(super)) "[[event]]",
        "a moment located between the rows on the continuous solution" {
        opt name: String = key("string", "–", "required", "", "letters, digits, `_`; unique");
        opt when: String = key("string", "–", "required", "", "a CSV column of this run, or `|X|` for the norm of X_s_x..z");
        opt crosses: f64 = key("number", "the column's", "one of `crosses` / `extremum`", "", "a crossing of this value");
        opt direction: Direction = key("\"up\" | \"down\" | \"both\"", "–", "\"both\"", "", "with `crosses`");
        opt extremum: Extremum = key("\"max\" | \"min\"", "–", "one of `crosses` / `extremum`", "", "every local extremum");
        opt stop: bool = key("bool", "–", "false", "", "true: the run ends at the first occurrence");
    }
    either {
        crosses, extremum: "give either `crosses` (a value) or `extremum` (\"max\" or \"min\"), not both";
    }
}

impl Part for EventSpec {
    type File = EventFile;
    const TABLE: Table = EventFile::TABLE;

    /// One `[[event]]` (its table at `at`): `name` and `when`, and exactly one of `crosses` (with its optional
    /// `direction`) and `extremum`.
    fn read(doc: &EventFile, at: &KeyPath) -> Checked<Self> {
        let key = |name: &str| at.clone().key(name);
        let kind = "an event";
        doc.exclusive(at)?;
        let condition = match (doc.crosses, doc.extremum) {
            (None, None) => {
                return invalid(
                    at.clone(),
                    "an event needs `crosses = VALUE` (with `direction` = \"up\" | \"down\" | \"both\") or `extremum` = \"max\" | \"min\"",
                );
            }
            (Some(value), _) => ConditionSpec::Crosses {
                value,
                direction: doc.direction.unwrap_or(Direction::Both),
            },
            (None, Some(extremum)) => {
                if doc.direction.is_some() {
                    return invalid(
                        key("direction"),
                        "`direction` applies to `crosses` only; an extremum is \"max\" or \"min\"",
                    );
                }
                ConditionSpec::Extremum(extremum)
            }
        };
        Ok(EventSpec {
            name: required(key("name"), doc.name.clone(), kind)?,
            when: required(key("when"), doc.when.clone(), kind)?,
            condition,
            stop: doc.stop.unwrap_or(false),
        })
    }

    fn write(&self) -> EventFile {
        let (crosses, direction, extremum) = match self.condition {
            ConditionSpec::Crosses { value, direction } => (Some(value), Some(direction), None),
            ConditionSpec::Extremum(e) => (None, None, Some(e)),
        };
        EventFile {
            name: Some(self.name.clone()),
            when: Some(self.when.clone()),
            crosses,
            direction,
            extremum,
            stop: Some(self.stop),
        }
    }
}
