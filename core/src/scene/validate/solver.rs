//! `[solver]` and `[output]`: the method and its settings, whether the method can run the scene, and the row
//! times.

use nalgebra::UnitQuaternion;

use super::super::model::SolverConfig;
use super::super::motion::Motion;
use super::super::spec::{SceneSpec, SolverSpec};
use super::{Checked, Invalid, Overrides, finite, invalid, key_of, positive};
use crate::effects::Effect;
use crate::frames::Form;
use crate::integrate::Schedule;
use crate::method::{Backend, Method, defaults};
use crate::motion::exact_flow::ExactFlow;

/// Most rows a run may write (a CSV of about 10 GB).
pub const MAX_ROWS: f64 = 5e7;
/// Most fixed steps a run may take (minutes of computing at ~100 ns per step).
pub const MAX_FIXED_STEPS: f64 = 1e10;

pub(super) fn validate_solver(doc: &SolverSpec, o: &Overrides) -> Checked<SolverConfig> {
    let method = o.method.or(doc.method).unwrap_or(Method::DEFAULT);
    let form = o.form.or(doc.form).unwrap_or(Form::Body);
    let backend = o.backend.or(doc.backend).unwrap_or_default();
    let rtol = o.rtol.or(doc.rtol).unwrap_or(defaults::RTOL);
    let rtol_key = key_of("solver", "rtol", o.rtol.is_some());
    if !(rtol.is_finite() && (1e-14..1.0).contains(&rtol)) {
        return invalid(
            rtol_key,
            format!(
                "must be a finite number in [1e-14, 1) (relative tolerance; 1e-14 is the limit of double precision), got {rtol:?}"
            ),
        );
    }
    let atol = o.atol.or(doc.atol).unwrap_or(defaults::ATOL);
    if !(atol.is_finite() && atol > 0.0) {
        return invalid(
            key_of("solver", "atol", o.atol.is_some()),
            format!("must be a finite number > 0 (absolute tolerance), got {atol:?}"),
        );
    }
    let dt = positive(
        key_of("solver", "dt", o.dt.is_some()),
        o.dt.or(doc.dt).unwrap_or(defaults::DT),
        "s",
    )?;
    let t_end_key = key_of("solver", "t_end", o.t_end.is_some());
    let t_end = finite(t_end_key.clone(), o.t_end.unwrap_or(doc.t_end), "s")?;
    if t_end < 0.0 {
        return invalid(t_end_key, format!("must be >= 0 (s), got {t_end:?}"));
    }
    Ok(SolverConfig {
        method,
        form,
        backend,
        rtol,
        atol,
        dt,
        t_end,
    })
}

/// Checks that the method can run the scene: the splitting methods and `exact` are the project's own (no
/// ode_solvers backend); `exact` is the torque-free closed form, so it refuses effects, and its closed form must
/// accept the body.
pub(super) fn validate_method(
    solver: &SolverConfig,
    motion: &Motion,
    effects: &[Effect],
    attitude0: &UnitQuaternion<f64>,
    o: &Overrides,
) -> Checked<()> {
    let method = solver.method;
    if let Some(problem) = (motion.attribute()).and_then(|a| a.door().refuses(method, effects)) {
        return invalid(key_of("solver", "method", o.method.is_some()), problem);
    }
    if motion.hinge().is_some() && !method.is_runge_kutta() {
        return invalid(
            key_of("solver", "method", o.method.is_some()),
            format!(
                "method \"{}\" does not run a hinge: split2/split4 split a free body's rotation into planar rotations and exact is the torque-free closed form, while a hinge has one degree of freedom, θ; use rk4, dopri5 or dop853",
                method.name()
            ),
        );
    }
    if solver.backend != Backend::Own && !method.is_runge_kutta() {
        return invalid(
            key_of("solver", "backend", o.backend.is_some()),
            format!(
                "backend \"{}\" runs only rk4, dopri5 and dop853; method \"{}\" is the project's own: remove the backend or use backend = \"own\"",
                solver.backend.name(),
                method.name()
            ),
        );
    }
    if !method.is_runge_kutta()
        && let Some((index, effect)) =
            (effects.iter().enumerate()).find(|(_, e)| e.depends_on_rate())
    {
        return invalid(
            key_of("solver", "method", o.method.is_some()),
            format!(
                "method \"{}\" cannot apply the scene's effect[{index}] ({}): its moment depends on omega, which \
                 split2/split4 hold fixed in each kick and exact leaves out; use rk4, dopri5 or dop853",
                method.name(),
                effect.kind()
            ),
        );
    }
    if method != Method::Exact {
        return Ok(());
    }
    let method_key = key_of("solver", "method", o.method.is_some());
    if let Some((index, effect)) = effects.iter().enumerate().next() {
        let others: Vec<&str> = Method::ALL
            .iter()
            .filter(|m| **m != Method::Exact)
            .map(|m| m.name())
            .collect();
        let (last, first) = others.split_last().map_or((&"", &[][..]), |(l, f)| (l, f));
        return invalid(
            method_key,
            format!(
                "method \"exact\" is the torque-free closed form; the scene's effect[{index}] ({}) needs {} or {last}",
                effect.kind(),
                first.join(", "),
            ),
        );
    }
    if let Some(free) = motion.free() {
        ExactFlow::new(free.body, free.omega0_b, attitude0).map_err(|e| Invalid {
            key: method_key,
            problem: format!("method \"exact\" cannot solve this body in closed form: {e}"),
        })?;
    }
    Ok(())
}

/// The row times: `output.every` (> 0, at most t_end when t_end > 0), within [`MAX_ROWS`] rows, and a fixed step
/// within [`MAX_FIXED_STEPS`] steps.
pub(super) fn validate_schedule(
    doc: &SceneSpec,
    solver: &SolverConfig,
    overrides: &Overrides,
) -> Checked<Schedule> {
    let every_key = key_of("output", "every", overrides.every.is_some());
    let every = positive(
        every_key.clone(),
        overrides.every.unwrap_or(doc.output.every),
        "s",
    )?;
    if solver.t_end > 0.0 && every > solver.t_end {
        return invalid(
            every_key,
            format!(
                "every = {every:?} s is longer than t_end = {:?} s: the run would have no rows between its ends; use every <= t_end",
                solver.t_end
            ),
        );
    }
    let schedule = Schedule::new(every, solver.t_end).map_err(|e| Invalid {
        key: every_key.clone(),
        problem: e.to_string(),
    })?;
    let rows = schedule.len() as f64;
    if rows > MAX_ROWS {
        return invalid(
            every_key,
            format!(
                "t_end / every would write {rows:.3e} rows, more than the limit of {MAX_ROWS:.0e}; use a larger every"
            ),
        );
    }
    if solver.method.is_fixed_step() {
        let steps = (solver.t_end / solver.dt).ceil();
        if steps > MAX_FIXED_STEPS {
            return invalid(
                key_of("solver", "dt", overrides.dt.is_some()),
                format!(
                    "t_end / dt would take {steps:.3e} steps, more than the limit of {MAX_FIXED_STEPS:.0e}; use a larger dt or an adaptive method"
                ),
            );
        }
    }
    Ok(schedule)
}
