//! Runs a validated scene and streams its samples to a sink, row by row.
//!
//! Every row of a free motion passes the [`DivergenceGuard`] before it reaches the sink: a run whose energy or
//! moment of momentum leaves what the scene's effects can supply stops with [`RunError::Diverged`], and the row
//! that showed it is never written.

use std::convert::Infallible;
use std::path::{Path, PathBuf};
use std::time::Instant;

use nalgebra::{SVector, Vector3};

use crate::effects::{EffectMoments, TorqueFree};
use crate::events::{Locator, Occurrence};
use crate::frames::{BodyAxes, Form, Vector};
use crate::integrate::{self, FixedStep, IntegrateError, OdeSystem, Stats, run_fixed_step};
use crate::method::Method;
use crate::motion::attribute::{AttributeDrive, DriveVisitor};
use crate::motion::exact_flow::ExactFlow;
use crate::motion::fixed_axis::FixedAxis;
use crate::motion::free::{self, BodyForm, FreeBody, SpaceForm};
use crate::motion::hinge::{Hinge, HingeBodyForm, HingeSpaceForm};
use crate::motion::lie_poisson::{KickMoment, KickQuadrature, LiePoisson, Scheme};
use crate::sample::Sample;
use crate::scene::{Motion, Scene};

mod advice;
mod events;
mod guard;

pub use advice::{
    CoarseStep, EnergyWatch, MAX_ENERGY_DRIFT, MAX_TURN_PER_STEP, drift_warning, warnings,
    warnings_before_run,
};
pub use guard::{Divergence, DivergenceGuard, GuardedQuantity};

/// What a finished run did.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct RunReport {
    /// Integrator statistics (steps, rejected steps, right-hand-side evaluations; for split2/split4 the
    /// evaluations are sub-flows, for exact the closed-form evaluations — see [`crate::motion`]).
    pub stats: Stats,
    /// Rows delivered to the sink.
    pub rows: u64,
    /// Wall time of the run (s).
    pub wall_seconds: f64,
    /// The largest relative drift of the energy T + V where the scene conserves it ([`EnergyWatch`]).
    pub energy_drift: Option<f64>,
}

/// Why a run stopped early.
#[derive(Debug, thiserror::Error)]
pub enum RunError<E: std::error::Error + 'static> {
    /// The integration failed (diverged to a non-finite state, or the step size collapsed).
    #[error(transparent)]
    Integrate(IntegrateError<Infallible>),
    /// The rows showed the energy or the moment of momentum leaving what the scene's effects allow: the step is
    /// too large for the motion. The row that showed it was not delivered.
    #[error(transparent)]
    Diverged(Divergence),
    /// The sink refused a row (e.g. a write error).
    #[error(transparent)]
    Sink(E),
}

impl<E: std::error::Error + 'static> RunError<E> {
    /// The time (s) at which the run stopped, when known.
    pub fn time(&self) -> Option<f64> {
        match self {
            RunError::Integrate(e) => e.time(),
            RunError::Diverged(d) => Some(d.t),
            RunError::Sink(_) => None,
        }
    }
}

/// A failed run of a scene, as the command line and the Python module report it: `SCENE: the run failed: REASON`.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[error("{}: the run failed: {reason}", scene.display())]
pub struct RunFailed {
    /// The scene file (or what stands for it, e.g. `<dict>`).
    pub scene: PathBuf,
    /// The time (s) at which the run stopped, when known.
    pub t: Option<f64>,
    /// Why it stopped.
    pub reason: String,
}

impl RunFailed {
    /// The failure of the run of `scene` that stopped with `e`.
    pub fn new<E: std::error::Error + 'static>(scene: &Path, e: &RunError<E>) -> Self {
        Self {
            scene: scene.to_path_buf(),
            t: e.time(),
            reason: e.to_string(),
        }
    }
}

/// How a scene's method runs: a splitting scheme or the closed form (the project's own methods, stepped here), or
/// a Runge–Kutta method through [`integrate::integrate`] with these settings.
enum Runner {
    Splitting(Scheme),
    Exact,
    RungeKutta(integrate::Settings),
}

/// The runner of the scene's method.
fn runner(scene: &Scene) -> Runner {
    let s = &scene.solver;
    match s.method {
        Method::Split2 => Runner::Splitting(Scheme::Strang),
        Method::Split4 => Runner::Splitting(Scheme::Suzuki4),
        Method::Exact => Runner::Exact,
        method @ (Method::Rk4 | Method::Dopri5 | Method::Dop853) => {
            Runner::RungeKutta(integrate::Settings {
                method,
                backend: s.backend,
                rtol: s.rtol,
                atol: s.atol,
                dt: s.dt,
                ..integrate::Settings::default()
            })
        }
    }
}

/// The most steps a fixed-step run of the project's own methods may take (as for the Runge–Kutta methods).
fn max_steps() -> u64 {
    integrate::Settings::default().max_steps
}

/// A fixed-step method (split2/split4, or their quadrature) from `y0` over the scene's rows at its `dt`.
fn run_split<S: FixedStep, E>(
    scene: &Scene,
    method: &mut S,
    y0: S::State,
    on_row: impl FnMut(f64, &S::State) -> Result<(), E>,
) -> Result<Stats, IntegrateError<E>> {
    run_fixed_step(
        method,
        y0,
        &scene.schedule,
        scene.solver.dt,
        max_steps(),
        on_row,
    )
}

/// Why the row callback stopped a run: the guard, the sink, or an event with `stop` (a run that ends well).
enum Stop<E> {
    Diverged(Divergence),
    Sink(E),
    Finished,
}

/// Runs the scene and keeps its rows: the samples in time order and what the run did.
///
/// ```
/// use eulerdyn::scene::{BodySpec, SceneSpec};
/// // A free asymmetric body spinning about its axis of largest inertia: |H| is conserved.
/// let scene = SceneSpec::new(BodySpec::principal(1.0, [1.0, 2.0, 3.0]), 5.0, 0.5)
///     .with_omega([0.0, 0.0, 2.0])
///     .build()
///     .unwrap();
/// let (samples, report) = eulerdyn::simulate::samples(&scene).unwrap();
/// assert_eq!(samples.len() as u64, report.rows);
/// assert!((samples.last().unwrap().h_o_s.norm() - 6.0).abs() < 1e-9);
/// ```
pub fn samples(scene: &Scene) -> Result<(Vec<Sample>, RunReport), RunError<Infallible>> {
    let mut samples = Vec::with_capacity(scene.schedule.len());
    let report = run(scene, |s: &Sample| {
        samples.push(*s);
        Ok::<(), Infallible>(())
    })?;
    Ok((samples, report))
}

/// Runs the scene, calling `sink` with every row in time order. A free motion's rows pass the
/// [`DivergenceGuard`] first.
pub fn run<E: std::error::Error + 'static>(
    scene: &Scene,
    sink: impl FnMut(&Sample) -> Result<(), E>,
) -> Result<RunReport, RunError<E>> {
    run_with_events(scene, sink).map(|(report, _)| report)
}

/// [`run`], locating the scene's `[[event]]`s on the run's continuous solution ([`crate::events`]): the
/// occurrences in time order. An event with `stop` ends the run at its first occurrence, with a last row there.
pub fn run_with_events<E: std::error::Error + 'static>(
    scene: &Scene,
    mut sink: impl FnMut(&Sample) -> Result<(), E>,
) -> Result<(RunReport, Vec<Occurrence>), RunError<E>> {
    // The drivers are compiled once, for a sink behind `dyn` that only says it refused; the caller's error waits here.
    let mut refusal = None;
    let outcome = run_rows(scene, &mut |s: &Sample| {
        sink(s).map_err(|e| {
            refusal = Some(e);
            Refused
        })
    });
    outcome.map_err(|e| match e {
        RunError::Integrate(e) => RunError::Integrate(e),
        RunError::Diverged(d) => RunError::Diverged(d),
        RunError::Sink(Refused) => {
            RunError::Sink(refusal.expect("a sink that refused a row left its error"))
        }
    })
}

/// The caller's sink refused a row; its error is kept by [`run_with_events`].
#[derive(Debug, thiserror::Error)]
#[error("the sink refused a row")]
struct Refused;

/// [`run_with_events`] for a sink whose error [`run_with_events`] keeps.
fn run_rows(
    scene: &Scene,
    sink: &mut dyn FnMut(&Sample) -> Result<(), Refused>,
) -> Result<(RunReport, Vec<Occurrence>), RunError<Refused>> {
    let start = Instant::now();
    let guard = DivergenceGuard::new(scene);
    let mut rows = 0u64;
    let with_potential = scene.gravity_potential(&scene.attitude0).is_some();
    let mut watch = EnergyWatch::of(scene);
    let mut last_t = f64::NEG_INFINITY;
    let deliver = |s: &Sample| -> Result<(), Stop<Refused>> {
        // A stop event located exactly on a row already delivered ends the run there: no second row at its time.
        if s.t == last_t {
            return Ok(());
        }
        last_t = s.t;
        if let Some(guard) = &guard {
            guard.check(s).map_err(Stop::Diverged)?;
        }
        rows += 1;
        // A copy of the row only where it gains its potential energy.
        let with_v;
        let s = if with_potential {
            with_v = Sample {
                potential: scene.gravity_potential(&s.q),
                ..*s
            };
            &with_v
        } else {
            s
        };
        if let Some(watch) = &mut watch {
            watch.add(s);
        }
        sink(s).map_err(Stop::Sink)
    };
    let mut locator = (!scene.events.is_empty())
        .then(|| Locator::new(&scene.events, scene.facts().columns().clone()));
    let events = locator.as_mut();
    let stats = match &scene.motion {
        Motion::FixedAxis(motion) => run_fixed_axis(scene, motion, deliver, events),
        Motion::Hinge(hinge) => run_hinge(scene, hinge, deliver, events),
        Motion::Free {
            omega0_b,
            attribute: Some(attribute),
            ..
        } => {
            // One instance of the drivers an attribute (no torque-free specialisation): the sum of no effects is an
            // exact zero, so H_s stays put all the same.
            attribute.drive(AttributeRun {
                scene,
                omega0_b,
                moment: EffectMoments::new(&scene.effects, scene.body.mass()),
                sink: deliver,
                locator: events,
            })
        }
        Motion::Free { omega0_b, body, .. } => {
            if scene.effects.is_empty() {
                run_free(scene, (body, omega0_b), TorqueFree, deliver, events)
            } else {
                let moments = EffectMoments::new(&scene.effects, scene.body.mass());
                if moments.has_laws() && !scene.solver.method.is_runge_kutta() {
                    // `Scene::with_moment` refuses this; a scene changed by hand afterwards still gets a clear error.
                    return Err(RunError::Integrate(IntegrateError::InvalidSettings {
                        reason: format!(
                            "method \"{}\" cannot apply a moment law of omega (b_dot, a user's law): use rk4, \
                             dopri5 or dop853",
                            scene.solver.method.name()
                        ),
                    }));
                }
                run_free(scene, (body, omega0_b), moments, deliver, events)
            }
        }
    }
    .map_err(split_error)?;
    let report = RunReport {
        stats,
        rows,
        wall_seconds: start.elapsed().as_secs_f64(),
        energy_drift: watch.map(|w| w.drift()),
    };
    Ok((report, locator.map(Locator::finish).unwrap_or_default()))
}

/// Separates the guard's and the sink's errors (carried out of the integrator as `Stopped`) from integration
/// failures.
fn split_error<E: std::error::Error + 'static>(e: IntegrateError<Stop<E>>) -> RunError<E> {
    match e.split_cause() {
        Ok(failure) => RunError::Integrate(failure),
        Err((_, Stop::Diverged(d))) => RunError::Diverged(d),
        Err((_, Stop::Sink(e))) => RunError::Sink(e),
        // A stop event ends a closed-form run through its sink; events::closed_form turns it into Ok first.
        Err((t, Stop::Finished)) => RunError::Integrate(IntegrateError::Backend {
            t,
            message: "an event's stop was not taken as the end of the run".into(),
        }),
    }
}

/// Free rotation with the scene's method, in the form the scene's frame selects, streaming each row.
fn run_free<M: KickMoment + Clone, E>(
    scene: &Scene,
    (body, omega0_b): (&FreeBody, &Vector<BodyAxes>),
    moment: M,
    mut sink: impl FnMut(&Sample) -> Result<(), Stop<E>>,
    locator: Option<&mut Locator>,
) -> Result<Stats, IntegrateError<Stop<E>>> {
    let form = scene.solver.form;
    let settings = match runner(scene) {
        Runner::Splitting(scheme) => {
            let mut split = LiePoisson::new(body, form, scheme, moment);
            let sampler = split.clone();
            let y0 = split.initial_state(body, omega0_b, &scene.attitude0);
            return run_split(scene, &mut split, y0, |t, y| sink(&sampler.sample(t, y)));
        }
        Runner::Exact => {
            if !M::ZERO {
                // Validation refuses this (scene/validate/solver.rs); a scene built by hand still gets a clear error.
                return Err(IntegrateError::InvalidSettings {
                    reason:
                        "method \"exact\" is the torque-free closed form; the scene has effects"
                            .into(),
                });
            }
            let flow = ExactFlow::new(body, omega0_b, &scene.attitude0).map_err(|e| {
                IntegrateError::InvalidSettings {
                    reason: format!("method \"exact\": {e}"),
                }
            })?;
            return match locator {
                None => flow.run(&scene.schedule, form, sink),
                Some(locator) => {
                    let closed = |t: f64| events::with_potential(scene, flow.sample(t, form));
                    events::closed_form(locator, closed, sink, |sink| {
                        flow.run(&scene.schedule, form, sink)
                    })
                }
            };
        }
        Runner::RungeKutta(settings) => settings,
    };
    let y0 = free::initial_state(body, form, omega0_b, &scene.attitude0);
    let row = |t: f64, y: &free::State| free::sample(body, &moment, form, t, y);
    let on_row = |t: f64, y: &free::State| sink(&row(t, y));
    let run = events::Integration {
        scene,
        settings: &settings,
        locator,
    };
    match form {
        Form::Body => {
            let mut system = BodyForm {
                body: *body,
                moment: moment.clone(),
            };
            run.integrate(&mut system, y0, on_row, row)
        }
        Form::Space => {
            let mut system = SpaceForm {
                body: *body,
                moment: moment.clone(),
            };
            run.integrate(&mut system, y0, on_row, row)
        }
    }
}

/// A free body's attribute (its wheels, its changing shape) run by the scene's method in the form its frame
/// selects: the visitor of [`Attribute::drive`](crate::scene::Attribute::drive), at the attribute's state size.
struct AttributeRun<'a, 'e, F> {
    scene: &'a Scene,
    omega0_b: &'a Vector<BodyAxes>,
    moment: EffectMoments,
    sink: F,
    locator: Option<&'a mut Locator<'e>>,
}

impl<F: FnMut(&Sample) -> Result<(), Stop<E>>, E> DriveVisitor for AttributeRun<'_, '_, F> {
    type Output = Result<Stats, IntegrateError<Stop<E>>>;

    fn visit<const N: usize, A: AttributeDrive<N>>(self, attribute: &A) -> Self::Output {
        let AttributeRun {
            scene,
            omega0_b,
            moment,
            mut sink,
            locator,
        } = self;
        let form = scene.solver.form;
        let y0 = attribute.initial_state(form, omega0_b, &scene.attitude0);
        let refused = || IntegrateError::InvalidSettings {
            // Validation refuses these (the attribute's `refuses`); a scene built by hand still gets its reason.
            reason: (attribute.refuses(scene.solver.method, &scene.effects)).unwrap_or_else(|| {
                format!(
                    "method \"{}\" cannot run this body",
                    scene.solver.method.name()
                )
            }),
        };
        let settings = match runner(scene) {
            Runner::RungeKutta(settings) => settings,
            Runner::Splitting(scheme) => {
                let split = attribute.split(scene.body.mass(), form, scheme, moment.clone());
                let mut split = split.ok_or_else(refused)?;
                return run_split(scene, &mut split, y0, |t, y| {
                    sink(&attribute.sample(&moment, form, t, y))
                });
            }
            Runner::Exact => return Err(refused()),
        };
        let row = |t: f64, y: &SVector<f64, N>| attribute.sample(&moment, form, t, y);
        let on_row = |t: f64, y: &SVector<f64, N>| sink(&row(t, y));
        let mut system = attribute.system(moment.clone(), form);
        let run = events::Integration {
            scene,
            settings: &settings,
            locator,
        };
        run.integrate(&mut system, y0, on_row, row)
    }
}

/// Euler's equation in space axes for a prescribed motion, Ḣ_s = M_s(t) (eq. 8.9), with M_s from the form the
/// scene's frame selects.
struct RequiredMomentRate<'a> {
    motion: &'a FixedAxis,
    form: Form,
}

impl RequiredMomentRate<'_> {
    /// M_s(t): (dI_s/dθ) θ̇ ω_s + I_s ω̇_s (space form, eq. 8.10) or R(θ)·(I α + ω × I ω) (body form).
    fn moment_s(&self, t: f64) -> Vector3<f64> {
        self.motion.required_moment_a_s(t, self.form).into_inner()
    }
}

impl OdeSystem<3> for RequiredMomentRate<'_> {
    fn rhs(&mut self, t: f64, _h_s: &SVector<f64, 3>) -> SVector<f64, 3> {
        self.moment_s(t)
    }
}

/// Prescribed fixed-axis motion: each row from the closed form, plus H_s integrated numerically from H_s(0) with
/// the scene's method (the check that Euler's equation in space axes reproduces I_s(θ)·ω_s): the Runge–Kutta
/// methods integrate Ḣ_s = M_s(t); split2/split4, having nothing to split, integrate it by their kicks alone (the
/// trapezoidal rule and its order-4 composition); `exact` reports the exact integral, H_s(t) itself.
fn run_fixed_axis<E>(
    scene: &Scene,
    motion: &FixedAxis,
    mut sink: impl FnMut(&Sample) -> Result<(), Stop<E>>,
    locator: Option<&mut Locator>,
) -> Result<Stats, IntegrateError<Stop<E>>> {
    let form = scene.solver.form;
    let h_s0: Vector3<f64> = *motion.sample(0.0, form).h_o_s;
    let mut system = RequiredMomentRate { motion, form };
    let row = |t: f64, h_s_int: &Vector3<f64>| Sample {
        h_o_s_integrated: Some(Vector::new(*h_s_int)),
        ..motion.sample(t, form)
    };
    let on_row = |t: f64, h_s_int: &Vector3<f64>| sink(&row(t, h_s_int));
    let settings = match runner(scene) {
        Runner::Splitting(scheme) => {
            let mut quadrature = KickQuadrature::new(scheme, |t| system.moment_s(t));
            return run_split(scene, &mut quadrature, h_s0, on_row);
        }
        Runner::Exact => {
            // The exact integral of Ḣ_s = M_s is H_s itself.
            let exact_row = |t: f64| row(t, &motion.sample(t, form).h_o_s);
            let rows = |sink: &mut dyn FnMut(&Sample) -> Result<(), Stop<E>>| {
                let mut stats = Stats::default();
                for t in scene.schedule.iter() {
                    stats.evals += 1;
                    if t > 0.0 {
                        stats.steps += 1;
                    }
                    sink(&exact_row(t)).map_err(|cause| IntegrateError::Stopped { t, cause })?;
                }
                Ok(stats)
            };
            return match locator {
                None => rows(&mut sink),
                Some(locator) => {
                    let closed = |t: f64| events::with_potential(scene, exact_row(t));
                    events::closed_form(locator, closed, sink, |mut sink| rows(&mut sink))
                }
            };
        }
        Runner::RungeKutta(settings) => settings,
    };
    let run = events::Integration {
        scene,
        settings: &settings,
        locator,
    };
    run.integrate(&mut system, h_s0, on_row, row)
}

/// A hinge: θ integrated from the effects' moment about the axis by the scene's Runge–Kutta method, in the form
/// the scene's frame selects; every row is the axis kinematics at (θ, θ̇) with the support's loads. The splitting
/// methods and `exact` do not apply (validation refuses them).
fn run_hinge<E>(
    scene: &Scene,
    hinge: &Hinge,
    mut sink: impl FnMut(&Sample) -> Result<(), Stop<E>>,
    locator: Option<&mut Locator>,
) -> Result<Stats, IntegrateError<Stop<E>>> {
    let form = scene.solver.form;
    let Runner::RungeKutta(settings) = runner(scene) else {
        return Err(IntegrateError::InvalidSettings {
            reason: format!(
                "method \"{}\" does not run a hinge: use rk4, dopri5 or dop853",
                scene.solver.method.name()
            ),
        });
    };
    let y0 = hinge.initial_state(form);
    let row = |t: f64, y: &SVector<f64, 2>| hinge.sample(t, y, form);
    let on_row = |t: f64, y: &SVector<f64, 2>| sink(&row(t, y));
    let run = events::Integration {
        scene,
        settings: &settings,
        locator,
    };
    match form {
        Form::Body => run.integrate(&mut HingeBodyForm(hinge), y0, on_row, row),
        Form::Space => run.integrate(&mut HingeSpaceForm(hinge), y0, on_row, row),
    }
}
