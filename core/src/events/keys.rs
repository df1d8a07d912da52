//! `[[event]]`'s keys, declared once by the typed [`EventSpec`] (its file form `EventFile`, the reference's table,
//! both conversions): `name` and `when`, exactly one of `crosses`, with its optional
//! `direction`, and `extremum` (the [`ConditionSpec`]), `stop`. The scene registers it with one line, `each event: EventSpec`.

use super::spec::ConditionSpec;
use super::{Direction, Extremum};
use crate::keys::{Checked, Group, KeyPath, Keys, Table, invalid};

/// One `[[event]]`.
#[derive(Debug, Clone, PartialEq, Table)]
#[table(
    file = EventFile,
    header = "[[event]]",
    about = "a moment located between the rows on the continuous solution",
    what = "an event"
)]
pub struct EventSpec {
    /// letters, digits, `_`; unique
    pub name: String,
    /// a CSV column of this run, or `|X|` for the norm of X_s_x..z
    pub when: String,
    /// `crosses` (with `direction`) or `extremum`.
    #[key(flatten = ConditionKeys)]
    pub condition: ConditionSpec,
    /// true: the run ends at the first occurrence
    #[key(default = false)]
    pub stop: bool,
}

/// `crosses` (with `direction`) or `extremum`, read as the event's [`ConditionSpec`].
#[derive(Debug, Clone, Copy, Default, PartialEq, Keys)]
#[keys(either(
    crosses,
    extremum,
    "give either `crosses` (a value) or `extremum` (\"max\" or \"min\"), not both"
))]
pub(crate) struct ConditionKeys {
    /// a crossing of this value
    #[key(unit = "the column's", shown = "one of `crosses` / `extremum`")]
    crosses: Option<f64>,
    /// with `crosses`
    #[key(kind = "\"up\" | \"down\" | \"both\"", shown = "\"both\"")]
    direction: Option<Direction>,
    /// every local extremum
    #[key(kind = "\"max\" | \"min\"", shown = "one of `crosses` / `extremum`")]
    extremum: Option<Extremum>,
}

/// Exactly one of `crosses` (with its optional `direction`) and `extremum`.
impl Group<ConditionKeys> for ConditionSpec {
    fn read(doc: &ConditionKeys, at: &KeyPath) -> Checked<Self> {
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

    fn write(&self, file: &mut ConditionKeys) {
        match *self {
            ConditionSpec::Crosses { value, direction } => {
                file.crosses = Some(value);
                file.direction = Some(direction);
            }
            ConditionSpec::Extremum(e) => file.extremum = Some(e),
        }
    }
}
