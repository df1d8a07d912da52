//! `[[event]]`'s keys, declared once ([`EventFile`]: the file form, the reference's table and the typed
//! [`EventSpec`], read from it and written back): `name` and `when`, exactly one of `crosses`, with its optional
//! `direction`, and `extremum` (the [`ConditionSpec`]), `stop`. The scene registers it with one line, `each event: EventSpec`.

use super::spec::ConditionSpec;
use super::{Direction, Extremum};
use crate::keys::{Checked, Group, KeyPath, file_table, invalid, key};

file_table! {
    /// One `[[event]]`.
    pub(crate) struct EventFile(pub(super)) "[[event]]",
        "a moment located between the rows on the continuous solution" {
        /// `name`: letters, digits and `_`, unique in the scene.
        opt(required) name: String = key("string", "–", "required", "", "letters, digits, `_`; unique");
        /// `when`: a CSV column of the run, or `|X|` for the norm of X_s_x..z.
        opt(required) when: String = key("string", "–", "required", "", "a CSV column of this run, or `|X|` for the norm of X_s_x..z");
        /// `crosses` (with `direction`) or `extremum`.
        group condition: ConditionSpec {
            opt crosses: f64 = key("number", "the column's", "one of `crosses` / `extremum`", "", "a crossing of this value");
            opt direction: Direction = key("\"up\" | \"down\" | \"both\"", "–", "\"both\"", "", "with `crosses`");
            opt extremum: Extremum = key("\"max\" | \"min\"", "–", "one of `crosses` / `extremum`", "", "every local extremum");
        }
        /// `stop`: the run ends at the first occurrence (absent: false).
        opt(false) stop: bool = key("bool", "–", "false", "", "true: the run ends at the first occurrence");
    }
    either {
        crosses, extremum: "give either `crosses` (a value) or `extremum` (\"max\" or \"min\"), not both";
    }
    spec {
        /// One `[[event]]`.
        #[derive(Debug, Clone, PartialEq)]
        pub struct EventSpec("an event");
    }
}

/// Exactly one of `crosses` (with its optional `direction`) and `extremum`.
impl Group<EventFile> for ConditionSpec {
    fn read(doc: &EventFile, at: &KeyPath) -> Checked<Self> {
        match (doc.crosses, doc.extremum) {
            (None, None) => invalid(
                at.clone(),
                "an event needs `crosses = VALUE` (with `direction` = \"up\" | \"down\" | \"both\") or `extremum` = \"max\" | \"min\"",
            ),
            (Some(value), _) => Ok(ConditionSpec::Crosses {
                value,
                direction: doc.direction.unwrap_or(Direction::Both),
            }),
            (None, Some(extremum)) => match doc.direction {
                Some(_) => invalid(
                    at.clone().key("direction"),
                    "`direction` applies to `crosses` only; an extremum is \"max\" or \"min\"",
                ),
                None => Ok(ConditionSpec::Extremum(extremum)),
            },
        }
    }

    fn write(&self, file: &mut EventFile) {
        match *self {
            ConditionSpec::Crosses { value, direction } => {
                file.crosses = Some(value);
                file.direction = Some(direction);
            }
            ConditionSpec::Extremum(e) => file.extremum = Some(e),
        }
    }
}
