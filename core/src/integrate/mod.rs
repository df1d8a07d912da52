//! Integration methods and the streaming driver — physics-agnostic.
//!
//! This module integrates any system y' = f(t, y) with `N` real states from y(0) = y0 and
//! streams the state at prescribed output times ("rows") to a callback. It knows nothing about
//! rigid bodies: callers implement [`OdeSystem`] for their model.
//!
//! # API
//!
//! ```text
//! pub trait OdeSystem<const N: usize> {
//!     fn rhs(&mut self, t: f64, y: &SVector<f64, N>) -> SVector<f64, N>;
//!     fn project(&self, _y: &mut SVector<f64, N>) {}
//! }
//! pub use crate::method::{Method, Backend};   // the Runge–Kutta methods run; the others are refused
//! pub struct Settings { method, backend, rtol, atol, dt, max_steps }   // + Default, validate() -> Result<(), String>
//! pub struct Stats { steps, rejected, evals }
//! pub enum IntegrateError<E = Infallible> {
//!     NonFinite { t }, StepSizeTooSmall { t, h }, TooManySteps { t, steps },
//!     Stopped { t, cause: E }, InvalidSettings { reason }, Backend { t, message },
//! }   // + split_cause() -> Result<IntegrateError<Infallible>, (t, E)>, time() -> Option<f64>
//! pub struct Schedule;   // Schedule::new(every, t_end) -> Result<Schedule, ScheduleError>;
//!                        // len(), time(k), iter(), every(), t_end()
//! pub fn integrate<const N: usize, S: OdeSystem<N>, E>(
//!     sys: &mut S, y0: SVector<f64, N>, schedule: &Schedule, settings: &Settings,
//!     on_row: impl FnMut(f64, &SVector<f64, N>) -> Result<(), E>,
//! ) -> Result<Stats, IntegrateError<E>>;
//! ```
//!
//! # Semantics
//!
//! * `on_row(t_k, &y_k)` is called for every row time of the [`Schedule`], in order, starting
//!   with t = 0 and ending with t_end. `y_k` is the state the method computed *at exactly* t_k:
//!   steps are shortened to land on row times, nothing is interpolated. `on_row` never sees a
//!   non-finite state. Returning `Err(e)` stops the run with [`IntegrateError::Stopped`].
//! * [`OdeSystem::project`] is applied to y0 and after every accepted step (own backend) or
//!   after every row interval (ode_solvers backend, which offers no hook between its steps).
//! * Memory is O(1) in the number of steps and rows: the own methods keep a fixed number of
//!   `SVector`s on the stack (no heap allocation in the step loop); the ode_solvers backend
//!   solves one row interval at a time, so its step history is bounded by one interval.
//!
//! # Methods (see [`Method`])
//!
//! * `Rk4` — classical fourth-order Runge–Kutta with a fixed step (Hairer, Nørsett, Wanner,
//!   *Solving Ordinary Differential Equations I*, 2nd ed., §II.1, Table 1.2).
//! * `Dopri5` — Dormand–Prince 5(4) with FSAL and the PI-stabilised step-size controller of
//!   Hairer's `dopri5.f` (HNW I §II.4–II.5).
//! * `Dop853` — Dormand–Prince 8(5,3) of Hairer's `dop853.f` (HNW I §II.5), with the
//!   stage-12 node c12 = 1 (ode_solvers 0.6.2 wrongly uses 0).
//!
//! # Backends (see [`Backend`])
//!
//! `Own` (default) runs the implementations in this module. `OdeSolvers` runs the same method
//! through `ode_solvers` 0.6.2 as an independent cross-check, working around its known defects
//! (see [`ode_solvers_path`]).

use std::convert::Infallible;

use nalgebra::SVector;
use thiserror::Error;

mod adaptive;
mod dense;
mod dop853;
mod dopri5;
mod explicit_rk;
mod fixed;
pub mod ode_solvers_path;
mod schedule;
mod tableau;

pub use dense::{Dense, NoWatch, StepWatch};
pub use fixed::{FixedStep, FixedStepWatch, NoSplit, run_fixed_step, run_fixed_step_watched};
pub use schedule::{Schedule, ScheduleError, ScheduleIter};

use crate::method::defaults;
pub use crate::method::{Backend, Method};

/// Right-hand side y' = f(t, y) of a system with `N` real states.
///
/// The integrators are monomorphised over the implementing type (no dynamic dispatch in the
/// step loop).
pub trait OdeSystem<const N: usize> {
    /// Evaluates f(t, y). Called once per Runge–Kutta stage; [`Stats::evals`] counts the calls.
    fn rhs(&mut self, t: f64, y: &SVector<f64, N>) -> SVector<f64, N>;

    /// Called after every accepted step (and at t0): project the state back onto the
    /// constraint manifold (e.g. renormalise a quaternion). Default: nothing.
    ///
    /// With the own backend this runs after every accepted step, before the state is reported
    /// or used for the next step. (If it changes the state of a DOPRI5 step, the FSAL
    /// derivative is re-evaluated at the projected state, costing one extra evaluation.)
    /// With the ode_solvers backend it runs once per row interval.
    fn project(&self, _y: &mut SVector<f64, N>) {}

    /// The first time later than `t` at which f is not smooth in t (a corner of a tabulated input): the adaptive
    /// drivers of the own backend end a step there, as on a row, so that no step straddles it. Default: none.
    fn next_breakpoint(&self, _t: f64) -> Option<f64> {
        None
    }
}

/// Integrator settings.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Settings {
    /// Integration method.
    pub method: Method,
    /// Implementation of the method.
    pub backend: Backend,
    /// Relative tolerance of the adaptive methods (must be > 10·ε and finite; HNW I eq. (4.10):
    /// sc_i = atol + rtol·max(|y_i|, |ŷ_i|)). Ignored by `Rk4`.
    pub rtol: f64,
    /// Absolute tolerance of the adaptive methods (must be > 0 and finite). Ignored by `Rk4`.
    pub atol: f64,
    /// Maximum step of `Rk4` (must be > 0 and finite); the actual step is
    /// h = Δ/⌈Δ/dt⌉ ≤ dt·(1 + 1e-9) for each row interval Δ (the 1e-9 absorbs rounding of Δ
    /// so that Δ = 10·dt is 10 steps, not 11). Ignored by the adaptive methods, whose step is
    /// limited only by the tolerances, the row times and t_end.
    pub dt: f64,
    /// Maximum number of attempted steps (accepted + rejected) for the whole run; exceeding it
    /// gives [`IntegrateError::TooManySteps`].
    pub max_steps: u64,
}

impl Default for Settings {
    /// The scene defaults of [`crate::method::defaults`]: DOP853 on the own backend, rtol = 1e-10, atol = 1e-12,
    /// dt = 1e-3, max_steps = 10^8.
    fn default() -> Self {
        Self {
            method: Method::DEFAULT,
            backend: Backend::Own,
            rtol: defaults::RTOL,
            atol: defaults::ATOL,
            dt: defaults::DT,
            max_steps: defaults::MAX_STEPS,
        }
    }
}

impl Settings {
    /// Checks the fields the chosen method uses: `dt > 0` (finite) for `Rk4`; for the adaptive
    /// methods `atol > 0` and `rtol > 10·ε` (finite), Hairer's admissibility test in
    /// `dopri5.f`/`dop853.f`. Returns the reason on failure ([`integrate`] reports it as
    /// [`IntegrateError::InvalidSettings`]).
    pub fn validate(&self) -> Result<(), String> {
        match self.method {
            Method::Rk4 => {
                if !(self.dt.is_finite() && self.dt > 0.0) {
                    return Err(format!("dt = {} must be positive and finite", self.dt));
                }
            }
            Method::Dopri5 | Method::Dop853 => {
                if !(self.rtol.is_finite() && self.rtol > 10.0 * f64::EPSILON) {
                    return Err(format!(
                        "rtol = {} must be finite and > 10·ε ≈ 2.2e-15",
                        self.rtol
                    ));
                }
                if !(self.atol.is_finite() && self.atol > 0.0) {
                    return Err(format!("atol = {} must be positive and finite", self.atol));
                }
            }
            other => return Err(not_runge_kutta(other)),
        }
        Ok(())
    }
}

/// Work counters of one [`integrate`] run.
///
/// Own backend, exactly: `Rk4` evals = 4·steps; `Dopri5` evals = 2 (k1 and `hinit`) +
/// 6·(steps + rejected) + 1 per accepted step whose state `project` changed (FSAL refresh);
/// `Dop853` evals = 2 + 11·(steps + rejected) + steps. With t_end = 0 all counters are 0.
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct Stats {
    /// Accepted steps.
    pub steps: u64,
    /// Rejected step attempts (error estimate > 1, or a non-finite trial state/derivative).
    /// The ode_solvers backend reports its own count, which ignores rejections before the
    /// first accepted step of each row interval.
    pub rejected: u64,
    /// Right-hand-side evaluations ([`OdeSystem::rhs`] calls), including the initial-step
    /// heuristic and FSAL re-evaluations.
    pub evals: u64,
}

/// Why [`integrate`] stopped early. `E` is the error type of the row callback.
#[derive(Debug, Error)]
pub enum IntegrateError<E = Infallible> {
    /// The state (or, after projection, the projected state) became NaN or infinite.
    #[error(
        "the state became non-finite (NaN or infinite) at t = {t}: the step is unstable or the \
         solution blows up there — use a smaller dt, or try an adaptive method"
    )]
    NonFinite {
        /// Time of the first non-finite state.
        t: f64,
    },
    /// The adaptive step size fell below the resolution of t (h ≤ 16·ε·|t|).
    #[error(
        "step size h = {h:e} became too small at t = {t}: the solution may blow up near t, or \
         the problem is stiff — check the model near t, or try a looser rtol/atol"
    )]
    StepSizeTooSmall {
        /// Time reached.
        t: f64,
        /// Last proposed step size (for the ode_solvers backend: its underflow bound 10·ε·|t|).
        h: f64,
    },
    /// [`Settings::max_steps`] attempts were used before reaching t_end.
    #[error(
        "max_steps exhausted after {steps} steps at t = {t} — raise max_steps, use a larger dt \
         (RK4), or try an adaptive method / looser rtol"
    )]
    TooManySteps {
        /// Time reached.
        t: f64,
        /// Attempted steps (accepted + rejected).
        steps: u64,
    },
    /// The row callback returned an error at row time `t`.
    #[error("stopped by the row callback at t = {t}: {cause}")]
    Stopped {
        /// Row time at which the callback failed.
        t: f64,
        /// The callback's error.
        cause: E,
    },
    /// [`Settings::validate`] failed.
    #[error("invalid integrator settings: {reason}")]
    InvalidSettings {
        /// What is wrong.
        reason: String,
    },
    /// The ode_solvers backend failed in a way with no counterpart above (e.g. its stiffness
    /// detection, which this crate disables).
    #[error("ode_solvers failed at t = {t}: {message} — try Backend::Own")]
    Backend {
        /// Time reached.
        t: f64,
        /// ode_solvers' message.
        message: String,
    },
}

impl<E> IntegrateError<E> {
    /// Separates the row callback's error from the integrator's own failures: `Err((t, cause))` for
    /// [`IntegrateError::Stopped`], `Ok(failure)` for every other variant (which carries no callback error).
    pub fn split_cause(self) -> Result<IntegrateError<Infallible>, (f64, E)> {
        Ok(match self {
            Self::Stopped { t, cause } => return Err((t, cause)),
            Self::NonFinite { t } => IntegrateError::NonFinite { t },
            Self::StepSizeTooSmall { t, h } => IntegrateError::StepSizeTooSmall { t, h },
            Self::TooManySteps { t, steps } => IntegrateError::TooManySteps { t, steps },
            Self::InvalidSettings { reason } => IntegrateError::InvalidSettings { reason },
            Self::Backend { t, message } => IntegrateError::Backend { t, message },
        })
    }

    /// Time at which the run stopped (`None` for [`IntegrateError::InvalidSettings`]).
    pub fn time(&self) -> Option<f64> {
        match self {
            Self::NonFinite { t }
            | Self::StepSizeTooSmall { t, .. }
            | Self::TooManySteps { t, .. }
            | Self::Stopped { t, .. }
            | Self::Backend { t, .. } => Some(*t),
            Self::InvalidSettings { .. } => None,
        }
    }
}

/// Integrates y' = f(t, y) from y(0) = `y0` and calls `on_row(t_k, &y_k)` at every row time of
/// `schedule`, in order, with the state the method computed at exactly t_k (including t = 0 and
/// t_end). Returns the work counters.
///
/// Algorithm per method: see [`Method`]; the adaptive methods carry their step-size proposal
/// across rows (a step shortened to land on a row does not shrink the next step), start with
/// Hairer's `hinit` (HNW I §II.4, "Starting step size"; `dopri5.f`), and treat a non-finite
/// trial state like a rejected step. Errors: see [`IntegrateError`]. `on_row` returning
/// `Err(cause)` stops the run with `IntegrateError::Stopped { t, cause }`.
pub fn integrate<const N: usize, S, E, F>(
    sys: &mut S,
    y0: SVector<f64, N>,
    schedule: &Schedule,
    settings: &Settings,
    on_row: F,
) -> Result<Stats, IntegrateError<E>>
where
    S: OdeSystem<N>,
    F: FnMut(f64, &SVector<f64, N>) -> Result<(), E>,
{
    integrate_watched(sys, y0, schedule, settings, on_row, &mut NoWatch)
}

/// [`integrate`] with a [`StepWatch`] that sees the continuous solution of every accepted step before the row at
/// its end (DOPRI5's and DOP853's own dense output, RK4's cubic Hermite interpolant) and may end the run at a time
/// inside a step, with a last row there. The ode_solvers backend offers no hook between its steps: an active watch
/// is refused there ([`IntegrateError::InvalidSettings`]).
pub fn integrate_watched<const N: usize, S, E, F, W>(
    sys: &mut S,
    y0: SVector<f64, N>,
    schedule: &Schedule,
    settings: &Settings,
    mut on_row: F,
    watch: &mut W,
) -> Result<Stats, IntegrateError<E>>
where
    S: OdeSystem<N>,
    F: FnMut(f64, &SVector<f64, N>) -> Result<(), E>,
    W: StepWatch<N>,
{
    settings
        .validate()
        .map_err(|reason| IntegrateError::InvalidSettings { reason })?;
    // An own adaptive pair with its number of stages (a const generic: the stage arrays' length).
    macro_rules! adaptive {
        ($pair:ty, $stages:literal) => {
            adaptive::run::<$pair, $stages, N, S, E, F, W>(
                sys,
                y0,
                schedule,
                settings,
                &mut on_row,
                watch,
            )
        };
    }
    match (settings.backend, settings.method) {
        (Backend::Own, Method::Rk4) => {
            let mut y0 = y0;
            sys.project(&mut y0);
            let limits = (settings.dt, settings.max_steps);
            let mut hermite = fixed::HermiteWatch { watch, f_end: None };
            let rk4 = &mut fixed::Rk4 { sys };
            run_fixed_step_watched(rk4, y0, schedule, limits, on_row, &mut hermite)
        }
        (Backend::Own, Method::Dopri5) => adaptive!(dopri5::Dopri5, 7),
        (Backend::Own, Method::Dop853) => adaptive!(dop853::Dop853, 12),
        (Backend::OdeSolvers, _) if W::ACTIVE => Err(IntegrateError::InvalidSettings {
            reason:
                "events are located on the own methods' steps; the ode_solvers backend has no hook \
                     between its steps"
                    .into(),
        }),
        (Backend::OdeSolvers, _) => ode_solvers_path::run(sys, y0, schedule, settings, &mut on_row),
        (Backend::Own, other) => Err(IntegrateError::InvalidSettings {
            reason: not_runge_kutta(other),
        }),
    }
}

/// Why a method that is not a Runge–Kutta method cannot run here.
fn not_runge_kutta(method: Method) -> String {
    format!(
        "method \"{}\" is not a Runge–Kutta method; it has a driver of its own (splitting or closed form)",
        method.name()
    )
}

/// True if every component is finite.
fn all_finite<const N: usize>(y: &SVector<f64, N>) -> bool {
    y.iter().all(|v| v.is_finite())
}

/// Common start of every driver: projects y0, checks it, and reports the row t = 0.
fn start<const N: usize, S, E, F>(
    sys: &S,
    mut y0: SVector<f64, N>,
    on_row: &mut F,
) -> Result<SVector<f64, N>, IntegrateError<E>>
where
    S: OdeSystem<N>,
    F: FnMut(f64, &SVector<f64, N>) -> Result<(), E>,
{
    sys.project(&mut y0);
    if !all_finite(&y0) {
        return Err(IntegrateError::NonFinite { t: 0.0 });
    }
    report(on_row, 0.0, &y0)?;
    Ok(y0)
}

/// Calls the row callback, mapping its error to [`IntegrateError::Stopped`].
fn report<const N: usize, E, F>(
    on_row: &mut F,
    t: f64,
    y: &SVector<f64, N>,
) -> Result<(), IntegrateError<E>>
where
    F: FnMut(f64, &SVector<f64, N>) -> Result<(), E>,
{
    on_row(t, y).map_err(|cause| IntegrateError::Stopped { t, cause })
}

/// Number of equal fixed steps for a row interval Δ with maximum step `dt`:
/// n = ⌈(Δ/dt)·(1 − 1e-9)⌉ ≥ 1, so h = Δ/n ≤ dt·(1 + 1e-9). Shared by the own RK4 and the
/// ode_solvers RK4 path so both take the same steps.
pub(crate) fn rk4_substeps(delta: f64, dt: f64) -> u64 {
    let r = delta / dt * (1.0 - 1e-9);
    // `as` saturates; a huge count is caught by max_steps.
    (r.ceil() as u64).max(1)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn substeps_absorb_rounding_of_the_interval() {
        // Δ = (k+1)·0.01 − k·0.01 is not exactly 0.01; it must still be 10 steps of ≈ 1e-3.
        for k in [1u32, 7, 99, 12345, 999_999] {
            let delta = f64::from(k + 1) * 0.01 - f64::from(k) * 0.01;
            assert_eq!(rk4_substeps(delta, 1e-3), 10, "k = {k}, Δ = {delta:e}");
        }
        assert_eq!(rk4_substeps(1.0, 0.3), 4);
        assert_eq!(rk4_substeps(1e-9, 0.3), 1);
        assert_eq!(rk4_substeps(0.7, 0.1), 7);
    }

    #[test]
    fn validate_reports_reasons() {
        let s = Settings {
            method: Method::Rk4,
            dt: -1.0,
            ..Settings::default()
        };
        assert!(s.validate().unwrap_err().contains("dt"));
        let s = Settings {
            rtol: 1e-16,
            ..Settings::default()
        };
        assert!(s.validate().unwrap_err().contains("rtol"));
        let s = Settings {
            atol: 0.0,
            ..Settings::default()
        };
        assert!(s.validate().unwrap_err().contains("atol"));
        assert!(Settings::default().validate().is_ok());
    }

    #[test]
    fn split_cause_and_time() {
        let e: IntegrateError<&str> = IntegrateError::Stopped {
            t: 2.5,
            cause: "full",
        };
        assert_eq!(e.time(), Some(2.5));
        assert!(matches!(e.split_cause(), Err((2.5, "full"))));
        let e: IntegrateError<&str> = IntegrateError::NonFinite { t: 1.0 };
        assert!(matches!(
            e.split_cause(),
            Ok(IntegrateError::NonFinite { t: 1.0 })
        ));
        let msg = IntegrateError::<Infallible>::NonFinite { t: 1.25 }.to_string();
        assert!(msg.contains("1.25") && msg.contains("smaller dt"));
    }
}
