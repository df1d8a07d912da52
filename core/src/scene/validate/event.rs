//! `[[event]]` and the run: a method whose continuous solution the events can be located on (the events
//! themselves are validated in `crate::events`).

use super::key_of;
use crate::keys::{Checked, invalid};
use crate::method::{Backend, Method};
use crate::scene::model::SolverConfig;
use crate::scene::motion::Motion;
use crate::scene::validate::Overrides;

/// Events are located on a continuous solution: the closed form of a fixed axis or of `exact`, or the own
/// Runge–Kutta methods' dense output. The splitting methods and the ode_solvers backend have none.
pub(super) fn locatable(motion: &Motion, solver: &SolverConfig, o: &Overrides) -> Checked<()> {
    if motion.prescribed().is_some() || solver.method == Method::Exact {
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
