//! `[[event]]` validated: the names (letters, digits, `_`; unique), the quantity against the run's columns and a
//! finite `crosses`.

use super::EventSpec;
use super::spec::ConditionSpec;
use super::{Condition, Event, Quantity};
use crate::keys::{Checked, KeyPath, finite, invalid};
use crate::sample::Column;

/// The events of `specs` for a run that writes `columns`: each name letters, digits and `_`, unique; the
/// quantity one of the columns (or a norm of three); a finite `crosses`.
pub(crate) fn validate_events(specs: &[EventSpec], columns: &[Column]) -> Checked<Vec<Event>> {
    let mut events: Vec<Event> = Vec::with_capacity(specs.len());
    for (i, spec) in specs.iter().enumerate() {
        let key = |name: &str| KeyPath::root().key("event").index(i).key(name);
        let name = &spec.name;
        if name.is_empty() || !name.chars().all(|c| c.is_ascii_alphanumeric() || c == '_') {
            return invalid(
                key("name"),
                format!(
                    "\"{name}\": an event's name is letters, digits and _ (it names columns of a sweep)"
                ),
            );
        }
        if let Some(j) = events.iter().position(|e| e.name == *name) {
            return invalid(
                key("name"),
                format!("\"{name}\" is the name of event[{j}] too; names must be unique"),
            );
        }
        let quantity = Quantity::parse(&spec.when, columns).or_else(|e| invalid(key("when"), e))?;
        let condition = match spec.condition {
            ConditionSpec::Crosses { value, direction } => Condition::Crossing {
                value: finite(key("crosses"), value, "the quantity's unit")?,
                direction,
            },
            ConditionSpec::Extremum(e) => Condition::Extremum(e),
        };
        events.push(Event {
            name: name.clone(),
            when: spec.when.clone(),
            quantity,
            condition,
            stop: spec.stop,
        });
    }
    Ok(events)
}
