//! [`Backend::OdeSolvers`](super::Backend::OdeSolvers): the same methods through
//! `ode_solvers` 0.6.2, as an independent cross-check of the own implementations.
//!
//! Known defects of ode_solvers 0.6.2 and how this path avoids them (each has a regression
//! test in `tests/it/integrate_methods.rs` that shows the raw defect):
//!
//! * (a) DOP853 tabulates the nodes c12 = c13 = 0 instead of 1, so stage 12 is evaluated at t
//!   instead of t + h — wrong whenever f depends on t. Workaround: integrate the autonomous
//!   form (y, τ)' = (f(τ, y), 1); the stage "times" τ are then computed from the A matrix,
//!   whose last row sums to 1.
//! * (b) `OutputType::Dense` extrapolates its last row from an earlier step and calls `solout`
//!   with mismatched (x, y). Workaround: `OutputType::Sparse`; rows are interval end points.
//! * (c) `Rk4` takes ⌈(x_end − x0)/h⌉ steps of h, overshooting x_end. Workaround: per row
//!   interval Δ, h = Δ/n with n = ⌈Δ/dt⌉ (nudged up by ulps until ⌈Δ/h⌉ = n).
//! * (d) every step is stored in memory. Workaround: one short solve per row interval.
//! * (e) default n_max = 100000 and stiffness detection abort long runs. Workaround:
//!   `from_param` with n_max = remaining `max_steps` budget and n_stiff = u32::MAX (never
//!   tested).
//! * (f) the state cannot be modified between steps. Workaround (partial): `project` after
//!   every row interval.
//!
//! The controller parameters passed are Hairer's defaults, as in the own implementations. The
//! first interval uses ode_solvers' `hinit`; later intervals start with the largest step
//! accepted in the previous interval (ode_solvers does not expose its step proposal), so the
//! step sequence near rows differs from the own backend's. Stats are ode_solvers' own counters
//! summed over intervals (its `rejected_steps` ignores rejections before the first accepted
//! step of an interval; its `num_eval` counts every RHS call).

use std::cell::{Cell, RefCell};

use nalgebra::{DVector, SVector};
use ode_solvers::dop_shared::{IntegrationError, Stats as OsStats};
use ode_solvers::{Dop853, Dopri5, OutputType, Rk4, System};

use super::adaptive::ControllerParams;
use super::{
    IntegrateError, Method, OdeSystem, Schedule, Settings, Stats, all_finite, report, rk4_substeps,
    start,
};

/// The right-hand side f(t, y) on slices of N numbers, behind `dyn` so that ode_solvers' solvers are compiled once
/// each rather than once per system (they run at ode_solvers' own pace on heap vectors; the call is not the cost).
type DynRhs<'s> = dyn FnMut(f64, &[f64], &mut [f64]) + 's;

/// Adapter from a right-hand side on N numbers to `ode_solvers::System` on dynamic vectors. With `autonomous`,
/// the state has N + 1 components and the last one is the time τ (τ' = 1).
struct Adapter<'a, 's> {
    rhs: &'a RefCell<&'a mut DynRhs<'s>>,
    n: usize,
    autonomous: bool,
    /// Time of the last accepted step seen by `solout`, and the largest accepted step.
    last_x: &'a Cell<f64>,
    max_step: &'a Cell<f64>,
}

impl System<f64, DVector<f64>> for Adapter<'_, '_> {
    fn system(&self, x: f64, y: &DVector<f64>, dy: &mut DVector<f64>) {
        let n = self.n;
        let t = if self.autonomous { y[n] } else { x };
        (self.rhs.borrow_mut())(t, &y.as_slice()[..n], &mut dy.as_mut_slice()[..n]);
        if self.autonomous {
            dy[n] = 1.0;
        }
    }

    fn solout(&mut self, x: f64, _y: &DVector<f64>, _dy: &DVector<f64>) -> bool {
        let step = x - self.last_x.get();
        if step > self.max_step.get() {
            self.max_step.set(step);
        }
        self.last_x.set(x);
        false
    }
}

/// Adds ode_solvers' counters to ours.
fn add(stats: &mut Stats, s: OsStats) {
    stats.steps += u64::from(s.accepted_steps);
    stats.rejected += u64::from(s.rejected_steps);
    stats.evals += u64::from(s.num_eval);
}

/// Maps ode_solvers' error to ours.
fn map_err<E>(e: IntegrationError, max_steps: u64) -> IntegrateError<E> {
    match e {
        IntegrationError::MaxNumStepReached { x, .. } => IntegrateError::TooManySteps {
            t: x,
            steps: max_steps,
        },
        IntegrationError::StepSizeUnderflow { x } => IntegrateError::StepSizeTooSmall {
            t: x,
            // ode_solvers stops when 0.1·|h| ≤ ε·|x| and does not report h.
            h: 10.0 * f64::EPSILON * x.abs(),
        },
        e @ IntegrationError::StiffnessDetected { x } => IntegrateError::Backend {
            t: x,
            message: e.to_string(),
        },
    }
}

/// Step budget for one interval as ode_solvers' `n_max` (it counts attempts; saturates).
fn n_max(settings: &Settings, stats: &Stats) -> u32 {
    let left = settings
        .max_steps
        .saturating_sub(stats.steps + stats.rejected);
    u32::try_from(left).unwrap_or(u32::MAX)
}

/// Step for ode_solvers' `Rk4` on an interval Δ: h = Δ/n, increased by ulps until
/// ⌈Δ/h⌉ = n (ode_solvers takes ⌈Δ/h⌉ steps), so it takes exactly n steps.
pub(crate) fn rk4_step_for(delta: f64, n: u64) -> f64 {
    let mut h = delta / n as f64;
    while (delta / h).ceil() > n as f64 {
        h = h.next_up();
    }
    h
}

/// One row interval [t_a, t_b] for ode_solvers: the initial step (0: its `hinit`), the largest step and the step
/// budget.
struct Interval {
    t_a: f64,
    t_b: f64,
    h_max: f64,
    h_guess: f64,
    budget: u32,
}

/// What one ode_solvers solve returns: its counters, the time of its first non-finite state (RK4 only) and its
/// last state.
type Solved = (OsStats, Option<f64>, Option<DVector<f64>>);

/// Solves one row interval with `settings.method`: RK4 with the step of [`rk4_step_for`], the adaptive pairs with
/// the controller parameters of the own implementations ([`ControllerParams`]) and sparse output.
fn solve_interval<E>(
    settings: &Settings,
    adapter: Adapter<'_, '_>,
    y_dyn: DVector<f64>,
    iv: &Interval,
) -> Result<Solved, IntegrateError<E>> {
    // Dopri5 and Dop853 of ode_solvers are distinct types with the same constructor.
    macro_rules! embedded_pair {
        ($solver:ident, $params:ty) => {{
            let mut solver = $solver::from_param(
                adapter,
                iv.t_a,
                iv.t_b,
                0.0,
                y_dyn,
                settings.rtol,
                settings.atol,
                <$params>::SAFE,
                <$params>::BETA,
                <$params>::FAC_MIN,
                <$params>::FAC_MAX,
                iv.h_max,
                iv.h_guess,
                iv.budget,
                u32::MAX,
                OutputType::Sparse,
            );
            let r = solver.integrate();
            r.map(|s| (s, None, solver.y_out().last().cloned()))
        }};
    }
    let outcome = match settings.method {
        Method::Rk4 => {
            let delta = iv.t_b - iv.t_a;
            let h = rk4_step_for(delta, rk4_substeps(delta, settings.dt));
            let mut solver = Rk4::new(adapter, iv.t_a, y_dyn, iv.t_b, h);
            let r = solver.integrate();
            // Report the first non-finite state, if any, at its own time.
            let bad = solver
                .x_out()
                .iter()
                .zip(solver.y_out())
                .find(|(_, v)| !v.iter().all(|c| c.is_finite()))
                .map(|(x, _)| *x);
            r.map(|s| (s, bad, solver.y_out().last().cloned()))
        }
        Method::Dopri5 => embedded_pair!(Dopri5, super::dopri5::Dopri5),
        Method::Dop853 => embedded_pair!(Dop853, super::dop853::Dop853),
        other => {
            return Err(IntegrateError::InvalidSettings {
                reason: super::not_runge_kutta(other),
            });
        }
    };
    outcome.map_err(|e| map_err(e, settings.max_steps))
}

/// Runs `settings.method` through ode_solvers, one solve per row interval (see module docs).
pub(crate) fn run<const N: usize, S, E, F>(
    sys: &mut S,
    y0: SVector<f64, N>,
    schedule: &Schedule,
    settings: &Settings,
    on_row: &mut F,
) -> Result<Stats, IntegrateError<E>>
where
    S: OdeSystem<N>,
    F: FnMut(f64, &SVector<f64, N>) -> Result<(), E>,
{
    let mut stats = Stats::default();
    let mut y = start(&*sys, y0, on_row)?;
    let autonomous = settings.method == Method::Dop853;
    let h_max = schedule.t_end();
    let mut h_guess = 0.0; // 0 → ode_solvers' hinit
    let last_x = Cell::new(0.0);
    let max_step = Cell::new(0.0);
    let mut t_a = 0.0;

    for t_b in schedule.iter().skip(1) {
        let budget = n_max(settings, &stats);
        if budget == 0 {
            return Err(IntegrateError::TooManySteps {
                t: t_a,
                steps: stats.steps + stats.rejected,
            });
        }
        last_x.set(t_a);
        max_step.set(0.0);
        let y_dyn = DVector::<f64>::from_iterator(
            N + usize::from(autonomous),
            y.iter().copied().chain(autonomous.then_some(t_a)),
        );
        let interval = Interval {
            t_a,
            t_b,
            h_max,
            h_guess,
            budget,
        };
        let mut rhs = |t: f64, y: &[f64], dy: &mut [f64]| {
            dy.copy_from_slice(
                sys.rhs(t, &SVector::<f64, N>::from_column_slice(y))
                    .as_slice(),
            );
        };
        let rhs_cell = RefCell::new(&mut rhs as &mut DynRhs<'_>);
        let adapter = Adapter {
            rhs: &rhs_cell,
            n: N,
            autonomous,
            last_x: &last_x,
            max_step: &max_step,
        };
        let (s, bad, y_end) = solve_interval(settings, adapter, y_dyn, &interval)?;
        add(&mut stats, s);
        if let Some(t) = bad {
            return Err(IntegrateError::NonFinite { t });
        }
        // Every ode_solvers solver stores at least the initial value, so `y_end` is Some.
        let Some(y_end) = y_end else {
            return Err(IntegrateError::NonFinite { t: t_b });
        };
        y = SVector::<f64, N>::from_fn(|i, _| y_end[i]);
        sys.project(&mut y);
        if !all_finite(&y) {
            return Err(IntegrateError::NonFinite { t: t_b });
        }
        if max_step.get() > 0.0 {
            h_guess = max_step.get();
        }
        report(on_row, t_b, &y)?;
        t_a = t_b;
    }
    Ok(stats)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn rk4_step_gives_exactly_n_steps() {
        // ode_solvers' Rk4 takes ⌈Δ/h⌉ steps; h must make that exactly n for awkward Δ.
        let mut nudged = 0;
        for k in 1..2000u32 {
            let delta = f64::from(k) * 0.001 + f64::from(k % 7) * 1e-17;
            for n in [1u64, 3, 7, 10, 13, 1000] {
                let h = rk4_step_for(delta, n);
                assert_eq!((delta / h).ceil(), n as f64, "Δ = {delta:e}, n = {n}");
                // The nudge is at most a few ulps: h·n = Δ to rounding.
                assert!((h * n as f64 - delta).abs() <= 8.0 * f64::EPSILON * delta);
                if h != delta / n as f64 {
                    nudged += 1;
                }
            }
        }
        // The naive h = Δ/n would have overshot in some of these cases.
        assert!(nudged > 0);
    }
}
