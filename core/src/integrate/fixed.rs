//! The fixed-step row driver, shared by RK4 and the splitting methods: between rows t_a < t_b it takes
//! n = ⌈(t_b − t_a)/dt⌉ equal steps h = (t_b − t_a)/n ([`rk4_substeps`]) at t_a + i·h (products, never a running
//! sum), the last one landing on t_b exactly.

use nalgebra::SVector;

use super::dense::{Dense, NoWatch, StepWatch};
use super::explicit_rk;
use super::tableau::RK4;
use super::{IntegrateError, OdeSystem, Schedule, Stats, all_finite, rk4_substeps};

/// A method that advances its state by steps of a given size, run by [`run_fixed_step`].
pub trait FixedStep {
    /// The state.
    type State: Copy;
    /// Advances `y` from t to t_next = t + h (t_next is passed so that the last step of a row interval lands on the
    /// row time exactly). Returns the number of evaluations (right-hand sides or sub-flows) it took.
    fn step(&mut self, t: f64, t_next: f64, h: f64, y: &mut Self::State) -> u64;
    /// Whether every component of the state is finite.
    fn is_finite(&self, y: &Self::State) -> bool;
}

/// The fixed step of a system that has none (a motion only the Runge–Kutta methods run): it cannot be made.
#[derive(Debug)]
pub enum NoSplit<const N: usize> {}

impl<const N: usize> FixedStep for NoSplit<N> {
    type State = SVector<f64, N>;

    fn step(&mut self, _: f64, _: f64, _: f64, _: &mut Self::State) -> u64 {
        match *self {}
    }

    fn is_finite(&self, _: &Self::State) -> bool {
        match *self {}
    }
}

/// Sees every step of a [`FixedStep`] method, in time order, before the row at its end is reported (the fixed-step
/// counterpart of [`StepWatch`]). A watch with `ACTIVE = false` costs nothing.
pub trait FixedStepWatch<S: FixedStep> {
    /// Whether the driver calls [`FixedStepWatch::step`].
    const ACTIVE: bool = true;
    /// The step from (t₀, y₀) to (t₁, y₁); `Some((t_stop, y_stop))` ends the run with that last row. Adds the
    /// evaluations it took to `evals`.
    fn step(
        &mut self,
        method: &mut S,
        start: (f64, &S::State),
        end: (f64, &S::State),
        evals: &mut u64,
    ) -> Option<(f64, S::State)>;
}

impl<S: FixedStep> FixedStepWatch<S> for NoWatch {
    const ACTIVE: bool = false;
    fn step(
        &mut self,
        _: &mut S,
        _: (f64, &S::State),
        _: (f64, &S::State),
        _: &mut u64,
    ) -> Option<(f64, S::State)> {
        None
    }
}

/// The fixed-step driver of [`FixedStep`] methods, with the row semantics of [`super::integrate`]:
/// `on_row(t_k, &y_k)` at every row time, starting with t = 0, the steps described in the module docs. Errors:
/// `InvalidSettings` for dt not positive and finite, `TooManySteps` past `max_steps`, `NonFinite` when the state
/// stops being finite (no such state is ever reported), `Stopped` when `on_row` fails.
pub fn run_fixed_step<S: FixedStep, E>(
    method: &mut S,
    y0: S::State,
    schedule: &Schedule,
    dt: f64,
    max_steps: u64,
    on_row: impl FnMut(f64, &S::State) -> Result<(), E>,
) -> Result<Stats, IntegrateError<E>> {
    run_fixed_step_watched(method, y0, schedule, (dt, max_steps), on_row, &mut NoWatch)
}

/// [`run_fixed_step`] with a watch that sees every step and may end the run ([`FixedStepWatch`]).
#[inline(never)]
pub fn run_fixed_step_watched<S: FixedStep, E, W: FixedStepWatch<S>>(
    method: &mut S,
    y0: S::State,
    schedule: &Schedule,
    (dt, max_steps): (f64, u64),
    mut on_row: impl FnMut(f64, &S::State) -> Result<(), E>,
    watch: &mut W,
) -> Result<Stats, IntegrateError<E>> {
    if !(dt.is_finite() && dt > 0.0) {
        return Err(IntegrateError::InvalidSettings {
            reason: format!("dt = {dt} must be positive and finite"),
        });
    }
    if !method.is_finite(&y0) {
        return Err(IntegrateError::NonFinite { t: 0.0 });
    }
    on_row(0.0, &y0).map_err(|cause| IntegrateError::Stopped { t: 0.0, cause })?;
    let mut stats = Stats::default();
    let mut y = y0;
    let mut t_a = 0.0;
    for t_b in schedule.iter().skip(1) {
        let delta = t_b - t_a;
        let n = rk4_substeps(delta, dt);
        let h = delta / n as f64;
        // The steps work on a copy that nothing else sees (`on_row` takes a reference), so that it can stay in
        // registers.
        let mut y_steps = y;
        for i in 0..n {
            let t = t_a + i as f64 * h;
            if stats.steps >= max_steps {
                return Err(IntegrateError::TooManySteps {
                    t,
                    steps: stats.steps,
                });
            }
            let t_next = if i + 1 == n {
                t_b
            } else {
                t_a + (i + 1) as f64 * h
            };
            let y_before = y_steps;
            stats.evals += method.step(t, t_next, h, &mut y_steps);
            stats.steps += 1;
            if !method.is_finite(&y_steps) {
                return Err(IntegrateError::NonFinite { t: t_next });
            }
            if W::ACTIVE
                && let Some((t_stop, y_stop)) =
                    watch.step(method, (t, &y_before), (t_next, &y_steps), &mut stats.evals)
            {
                on_row(t_stop, &y_stop)
                    .map_err(|cause| IntegrateError::Stopped { t: t_stop, cause })?;
                return Ok(stats);
            }
        }
        y = y_steps;
        on_row(t_b, &y).map_err(|cause| IntegrateError::Stopped { t: t_b, cause })?;
        t_a = t_b;
    }
    Ok(stats)
}

/// The classical RK4 method ([`RK4`]) on a system, with [`OdeSystem::project`] after every step.
pub(crate) struct Rk4<'a, S, const N: usize> {
    /// The system.
    pub sys: &'a mut S,
}

impl<S: OdeSystem<N>, const N: usize> FixedStep for Rk4<'_, S, N> {
    type State = SVector<f64, N>;

    // Always inlined (see explicit_rk::step).
    #[inline(always)]
    fn step(&mut self, t: f64, t_next: f64, h: f64, y: &mut SVector<f64, N>) -> u64 {
        let k1 = self.sys.rhs(t, y);
        *y = explicit_rk::step(self.sys, &RK4, t, t_next, y, &k1, h).y_new;
        self.sys.project(y);
        4
    }

    fn is_finite(&self, y: &SVector<f64, N>) -> bool {
        all_finite(y)
    }
}

/// A [`StepWatch`] over RK4's steps: each step's cubic Hermite interpolant from the states and f at both ends
/// ([`Dense::hermite`], error O(h⁴) like the method's), with f at the end kept for the next step (one evaluation of
/// f per step).
pub(crate) struct HermiteWatch<'w, const N: usize, W> {
    pub watch: &'w mut W,
    /// f at the end of the last step, (t, f).
    pub f_end: Option<(f64, SVector<f64, N>)>,
}

impl<S: OdeSystem<N>, W: StepWatch<N>, const N: usize> FixedStepWatch<Rk4<'_, S, N>>
    for HermiteWatch<'_, N, W>
{
    const ACTIVE: bool = W::ACTIVE;

    fn step(
        &mut self,
        method: &mut Rk4<'_, S, N>,
        (t0, y0): (f64, &SVector<f64, N>),
        (t1, y1): (f64, &SVector<f64, N>),
        evals: &mut u64,
    ) -> Option<(f64, SVector<f64, N>)> {
        let f0 = match self.f_end {
            Some((t, f)) if t == t0 => f,
            _ => {
                *evals += 1;
                method.sys.rhs(t0, y0)
            }
        };
        *evals += 1;
        let f1 = method.sys.rhs(t1, y1);
        self.f_end = Some((t1, f1));
        let dense = Dense::hermite(t0, t1, y0, &f0, y1, &f1);
        let t_stop = self.watch.step(&dense)?;
        Some((t_stop, dense.at(t_stop)))
    }
}
