//! `[[event]]`: the names (letters, digits, `_`; unique), the quantity against the run's columns, a finite
//! `crosses`, and a method whose continuous solution the events can be located on.

use super::key_of;
use crate::events::{Condition, Event, Quantity};
use crate::keys::{Checked, finite, invalid};
use crate::method::{Backend, Method};
use crate::sample::ColumnSet;
use crate::scene::model::{Motion, SolverConfig};
use crate::scene::source_map::KeyPath;
use crate::scene::spec::{ConditionSpec, SceneSpec};
use crate::scene::validate::Overrides;

/// The scene's events, for a run with `columns`, `motion` and `solver`.
pub(super) fn validate_events(
    doc: &SceneSpec,
    columns: ColumnSet,
    motion: &Motion,
    solver: &SolverConfig,
    o: &Overrides,
) -> Checked<Vec<Event>> {
    if doc.event.is_empty() {
        return Ok(Vec::new());
    }
    locatable(motion, solver, o)?;
    let names = columns.columns();
    let mut events: Vec<Event> = Vec::with_capacity(doc.event.len());
    for (i, spec) in doc.event.iter().enumerate() {
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
        let quantity = Quantity::parse(&spec.when, &names).or_else(|e| invalid(key("when"), e))?;
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

/// Events are located on a continuous solution: the closed form of a fixed axis or of `exact`, or the own
/// Runge–Kutta methods' dense output. The splitting methods and the ode_solvers backend have none.
fn locatable(motion: &Motion, solver: &SolverConfig, o: &Overrides) -> Checked<()> {
    if matches!(motion, Motion::FixedAxis(_)) || solver.method == Method::Exact {
        return Ok(());
    }
    if matches!(solver.method, Method::Split2 | Method::Split4) {
        return invalid(
            key_of("solver", "method", o.method.is_some()),
            format!(
                "method \"{}\" has no continuous solution between its steps to locate [[event]]s on; use rk4, dopri5 or dop853 (or exact)",
                solver.method.name()
            ),
        );
    }
    if solver.backend != Backend::Own {
        return invalid(
            key_of("solver", "backend", o.backend.is_some()),
            "backend \"ode_solvers\" offers no hook between its steps to locate [[event]]s; use backend = \"own\"",
        );
    }
    Ok(())
}
