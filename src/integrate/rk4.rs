//! Own classical Runge–Kutta method of order 4 with a fixed step.
//!
//! Tableau (HNW I, §II.1, Table 1.2, left):
//! k1 = f(t, y), k2 = f(t + h/2, y + h/2·k1), k3 = f(t + h/2, y + h/2·k2),
//! k4 = f(t + h, y + h·k3), y₁ = y + h/6·(k1 + 2k2 + 2k3 + k4).

use nalgebra::SVector;

use super::{
    IntegrateError, OdeSystem, Schedule, Settings, Stats, all_finite, report, rk4_substeps, start,
};

/// One classical RK4 step from (t, y) with step h; `t_next` is the end time of the step (used
/// for the k4 node so the last step of an interval evaluates exactly at the row time).
// Always inlined: where several callers instantiate it (the library behind the CLI), the compiler otherwise keeps
// it out of line and a step costs ~1.7 × as much (`cargo bench --bench methods`, README "What accuracy costs").
#[inline(always)]
pub(crate) fn step<const N: usize, S: OdeSystem<N>>(
    sys: &mut S,
    t: f64,
    t_next: f64,
    y: &SVector<f64, N>,
    h: f64,
) -> SVector<f64, N> {
    let half = 0.5 * h;
    let t_mid = t + half;
    let k1 = sys.rhs(t, y);
    let k2 = sys.rhs(t_mid, &(y + k1 * half));
    let k3 = sys.rhs(t_mid, &(y + k2 * half));
    let k4 = sys.rhs(t_next, &(y + k3 * h));
    y + (k1 + (k2 + k3) * 2.0 + k4) * (h / 6.0)
}

/// Fixed-step driver: for each row interval [t_a, t_b], n = ⌈Δ/dt⌉ steps of h = Δ/n at
/// t_a + i·h (by multiplication), the last one landing on t_b exactly; `project` after each step;
/// a non-finite state ends the run with `NonFinite { t }`.
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
    let mut y = start(sys, y0, on_row)?;
    let mut t_a = 0.0;
    for t_b in schedule.iter().skip(1) {
        let delta = t_b - t_a;
        let n = rk4_substeps(delta, settings.dt);
        let h = delta / n as f64;
        for i in 0..n {
            if stats.steps >= settings.max_steps {
                return Err(IntegrateError::TooManySteps {
                    t: t_a + i as f64 * h,
                    steps: stats.steps,
                });
            }
            let t = t_a + i as f64 * h;
            let t_next = if i + 1 == n {
                t_b
            } else {
                t_a + (i + 1) as f64 * h
            };
            y = step(sys, t, t_next, &y, h);
            stats.evals += 4;
            stats.steps += 1;
            sys.project(&mut y);
            if !all_finite(&y) {
                return Err(IntegrateError::NonFinite { t: t_next });
            }
        }
        report(on_row, t_b, &y)?;
        t_a = t_b;
    }
    Ok(stats)
}
