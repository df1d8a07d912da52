//! The runs of one curve (a method in one form on one backend) and of one setting.
//!
//! Adaptive methods run at each relative tolerance with atol = rtol × (the scene's atol / rtol). Fixed-step
//! methods run at dt₀ = every / 2^j, the largest such step with |ω|max·dt₀ ≤ 0.5, then halved, until the error is
//! at round-off, a run would take too many steps, or a run was slow. A method with neither (`exact`) runs once.

use crate::frames::Form;
use crate::method::{Backend, Method};
use crate::sample::Sample;
use crate::scene::{Overrides, Scene, SceneSpec};
use crate::simulate;
use std::ops::ControlFlow;

use super::measure::{Errors, RowMismatch};
use super::reference::{Reference, StudyReference};
use super::{Curve, Measure, Runs, StudyOptions, StudyRow, timing};

/// What the runs of a study share: the typed scene, the reference, and the sweep's starting points.
pub(super) struct Sweep<'a> {
    spec: &'a SceneSpec,
    reference: &'a Reference,
    measure: Measure,
    options: &'a StudyOptions,
    /// The largest |ω| of the motion (rad/s).
    omega_max: f64,
    /// The first fixed step (s).
    dt0: f64,
    /// The scene's atol / rtol, kept along the sweep of tolerances.
    atol_ratio: f64,
    t_end: f64,
}

/// One run's setting: the method, backend and form, and its tolerances (rtol, atol) or fixed step.
#[derive(Debug, Clone, Copy)]
struct Setting {
    method: Method,
    backend: Backend,
    form: Form,
    tolerances: Option<(f64, f64)>,
    dt: Option<f64>,
}

impl Setting {
    /// The setting of `curve` with `tolerances` or `dt`.
    fn of(curve: &Curve, tolerances: Option<(f64, f64)>, dt: Option<f64>) -> Self {
        Self {
            method: curve.method,
            backend: curve.backend,
            form: curve.form,
            tolerances,
            dt,
        }
    }
}

/// What one planned run gives: a row, or the reason the scene refuses the setting.
enum RunOutcome {
    Row(StudyRow),
    Refused(String),
}

impl<'a> Sweep<'a> {
    /// The sweep of the scene `base` (`spec` validated) against `reference`.
    pub fn new(
        spec: &'a SceneSpec,
        base: &Scene,
        reference: &'a StudyReference,
        options: &'a StudyOptions,
    ) -> Self {
        let omega_max = reference.omega_scale(base);
        Self {
            spec,
            reference: &reference.reference,
            measure: reference.measure,
            options,
            omega_max,
            dt0: first_step(base.schedule.every(), omega_max),
            atol_ratio: base.solver.atol / base.solver.rtol,
            t_end: base.solver.t_end,
        }
    }

    /// Runs one curve into `runs`; `progress(ran, what)` is called before each run, `ran` counting the curve's
    /// runs so far, and stops the curve (before that run) when it breaks.
    pub fn curve(
        &self,
        curve: &Curve,
        runs: &mut Runs,
        mut progress: impl FnMut(usize, &str) -> ControlFlow<()>,
    ) {
        let name = label(curve.method, curve.backend);
        let what = |setting: &str| format!("{name} ({} form) {setting}", curve.form.name());
        if curve.method.is_fixed_step() {
            self.fixed_step_curve(curve, &name, runs, |ran, setting| {
                progress(ran, &what(setting))
            });
        } else if curve.method.is_adaptive() {
            self.adaptive_curve(curve, &name, runs, |ran, setting| {
                progress(ran, &what(setting))
            });
        } else {
            // No step and no tolerance (`exact`): one run.
            if progress(0, &what("(no tolerance)")).is_break() {
                return;
            }
            match self.run(&Setting::of(curve, None, None)) {
                RunOutcome::Row(row) => runs.rows.push(row),
                RunOutcome::Refused(reason) => runs.skip(name, reason),
            }
        }
    }

    /// A fixed-step curve: the step halved from dt₀ until the error is at round-off (≤ 1e-13·|ω|max, or no longer
    /// falling below 1e-8·|ω|max), a run would take too many steps, or a run was slow.
    fn fixed_step_curve(
        &self,
        curve: &Curve,
        name: &str,
        runs: &mut Runs,
        mut progress: impl FnMut(usize, &str) -> ControlFlow<()>,
    ) {
        let mut previous: Option<f64> = None;
        for k in 0..=self.options.halvings {
            let dt = self.dt0 / 2f64.powi(k as i32);
            if self.t_end / dt > self.options.max_fixed_steps {
                break;
            }
            if progress(k as usize, &format!("dt {dt:e} s")).is_break() {
                break;
            }
            let row = match self.run(&Setting::of(curve, None, Some(dt))) {
                RunOutcome::Row(row) => row,
                RunOutcome::Refused(reason) => {
                    // A method the scene refuses is skipped; a step it refuses (too many steps) ends the curve.
                    if k == 0 {
                        runs.skip(name.to_string(), reason);
                    }
                    break;
                }
            };
            let err = row.error(self.measure);
            let slow = row.wall_s > self.options.slow_curve_seconds;
            runs.rows.push(row);
            if let Some(err) = err {
                let scale = self.omega_max.max(1.0);
                let at_round_off = err <= 1e-13 * scale
                    || previous.is_some_and(|p| err < 1e-8 * scale && err > 0.7 * p);
                if at_round_off {
                    break;
                }
                previous = Some(err);
            }
            if slow {
                break;
            }
        }
    }

    /// An adaptive curve: every relative tolerance of the options, until a run was slow.
    fn adaptive_curve(
        &self,
        curve: &Curve,
        name: &str,
        runs: &mut Runs,
        mut progress: impl FnMut(usize, &str) -> ControlFlow<()>,
    ) {
        let curve_start = runs.rows.len();
        for (ran, &rtol) in self.options.rtols.iter().enumerate() {
            if progress(ran, &format!("rtol {rtol:e}")).is_break() {
                break;
            }
            // Rounded to 12 digits, so that 1e-6 × 1e-2 is written 1e-8, not 1.0000000000000001e-8.
            let atol = format!("{:.11e}", rtol * self.atol_ratio)
                .parse()
                .unwrap_or(rtol * self.atol_ratio);
            let tolerances = Some((rtol, atol));
            match self.run(&Setting::of(curve, tolerances, None)) {
                RunOutcome::Row(row) => {
                    let slow = row.wall_s > self.options.slow_curve_seconds;
                    runs.rows.push(row);
                    if slow {
                        break;
                    }
                }
                RunOutcome::Refused(reason) => {
                    if runs.rows.len() == curve_start {
                        runs.skip(name.to_string(), reason);
                        break;
                    }
                }
            }
        }
    }

    /// The scene of one run: the typed scene with the method, form, backend, tolerances and step overridden.
    fn scene_for(&self, setting: &Setting) -> Result<Scene, String> {
        let overrides = Overrides {
            method: Some(setting.method),
            form: Some(setting.form),
            backend: Some(setting.backend),
            rtol: setting.tolerances.map(|t| t.0),
            atol: setting.tolerances.map(|t| t.1),
            dt: setting.dt,
            ..Overrides::default()
        };
        self.spec.build_with(&overrides).map_err(|e| e.problem)
    }

    /// Runs one setting: errors on a first streaming run, then the timed repeats.
    fn run(&self, setting: &Setting) -> RunOutcome {
        let scene = match self.scene_for(setting) {
            Ok(s) => s,
            Err(problem) => return RunOutcome::Refused(problem),
        };
        let mut row = empty_row(setting);
        let mut errors = Errors::default();
        let first = match self.measure_errors(&scene, &mut errors) {
            Ok(report) => report,
            // Diverged, failed, or (never expected) a row without a reference row.
            Err(e) => {
                row.failure = Some(e.to_string());
                return RunOutcome::Row(row);
            }
        };
        row.err_omega = errors.omega;
        row.err_attitude = errors.attitude;
        row.energy_drift = errors.energy_drift();
        row.h_drift = errors.h_drift();
        row.err_h_s = errors.h_s;
        row.steps = first.stats.steps;
        row.rejected = first.stats.rejected;
        row.evals = first.stats.evals;
        let repeats = timing::repeats_after(first.wall_seconds, self.options.repeats);
        match timing::median_wall_time(&scene, repeats) {
            Ok(wall_s) => {
                row.wall_s = wall_s;
                row.repeats = repeats;
            }
            Err(e) => {
                row.failure = Some(format!("a repeat failed where the first run did not: {e}"));
            }
        }
        RunOutcome::Row(row)
    }

    /// The first run of a setting: its rows compared, as they stream, with the reference's.
    fn measure_errors(
        &self,
        scene: &Scene,
        errors: &mut Errors,
    ) -> Result<simulate::RunReport, simulate::RunError<RowMismatch>> {
        let mut k = 0usize;
        simulate::run(scene, |s: &Sample| {
            match self.reference {
                Reference::Rows(rows) => match rows.get(k) {
                    Some(r) if r.t == s.t => errors.add(s, r),
                    _ => return Err(RowMismatch { row: k, t: s.t }),
                },
                Reference::FixedAxis => errors.add_fixed_axis(s),
            }
            k += 1;
            Ok(())
        })
    }
}

/// A row of the setting with no result yet (NaN errors and time, zero counters).
fn empty_row(setting: &Setting) -> StudyRow {
    StudyRow {
        method: label(setting.method, setting.backend),
        method_name: setting.method,
        backend: setting.backend,
        form: setting.form,
        rtol: setting.tolerances.map(|t| t.0),
        atol: setting.tolerances.map(|t| t.1),
        dt: setting.dt,
        err_omega: f64::NAN,
        err_attitude: None,
        energy_drift: f64::NAN,
        h_drift: f64::NAN,
        err_h_s: None,
        wall_s: f64::NAN,
        steps: 0,
        rejected: 0,
        evals: 0,
        repeats: 0,
        failure: None,
    }
}

/// `dop853` or `dop853/ode_solvers`.
fn label(method: Method, backend: Backend) -> String {
    match backend {
        Backend::Own => method.name().to_string(),
        other => format!("{}/{}", method.name(), other.name()),
    }
}

/// The first fixed step: every / 2^j, the largest with |ω|max·dt ≤ 0.5 (at most 2^-40·every).
fn first_step(every: f64, omega_max: f64) -> f64 {
    let mut dt = every;
    let mut j = 0;
    while omega_max * dt > 0.5 && j < 40 {
        dt *= 0.5;
        j += 1;
    }
    dt
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn first_step_is_a_power_of_two_fraction_of_every() {
        assert_eq!(first_step(0.5, 2.02), 0.125);
        assert_eq!(first_step(0.5, 0.0), 0.5);
        assert_eq!(first_step(0.01, 10.0), 0.01);
        assert!(first_step(1.0, f64::MAX) > 0.0);
    }
}
