//! Runs a validated scene and streams its samples to a sink, row by row.

use std::time::Instant;

use nalgebra::{SVector, Vector3};

use crate::integrate::{self, IntegrateError, OdeSystem, Stats};
use crate::model::{BackendName, Frame, MethodName, MotionSpec, Scene};
use crate::motion::fixed_axis::FixedAxis;
use crate::motion::free::{
    self, AppliedMoment, BodyForm, EffectMoments, FreeBody, SpaceForm, TorqueFree,
};
use crate::output::{ColumnSet, Sample};

/// What a finished run did.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct RunReport {
    /// Integrator statistics (steps, rejected steps, right-hand-side evaluations).
    pub stats: Stats,
    /// Rows delivered to the sink.
    pub rows: u64,
    /// Wall time of the run (s).
    pub wall_seconds: f64,
}

/// Why a run stopped early.
#[derive(Debug, thiserror::Error)]
pub enum RunError<E: std::error::Error + 'static> {
    /// The integration failed (diverged, or the step size collapsed).
    #[error(transparent)]
    Integrate(IntegrateError<std::convert::Infallible>),
    /// The sink refused a row (e.g. a write error).
    #[error(transparent)]
    Sink(E),
}

/// The optional columns a scene's run writes.
pub fn columns(scene: &Scene) -> ColumnSet {
    match &scene.motion {
        MotionSpec::FixedAxis(motion) => ColumnSet {
            theta: true,
            force: motion.center_off_axis(),
            h_s_integrated: true,
        },
        MotionSpec::Free { .. } => ColumnSet::default(),
    }
}

/// The integrator settings a scene asks for.
pub fn settings(scene: &Scene) -> integrate::Settings {
    let s = &scene.solver;
    integrate::Settings {
        method: match s.method {
            MethodName::Rk4 => integrate::Method::Rk4,
            MethodName::Dopri5 => integrate::Method::Dopri5,
            MethodName::Dop853 => integrate::Method::Dop853,
        },
        backend: match s.backend {
            BackendName::Own => integrate::Backend::Own,
            BackendName::OdeSolvers => integrate::Backend::OdeSolvers,
        },
        rtol: s.rtol,
        atol: s.atol,
        dt: s.dt,
        ..integrate::Settings::default()
    }
}

/// Runs the scene, calling `sink` with every row in time order.
pub fn run<E: std::error::Error + 'static>(
    scene: &Scene,
    mut sink: impl FnMut(&Sample) -> Result<(), E>,
) -> Result<RunReport, RunError<E>> {
    let start = Instant::now();
    let mut rows = 0u64;
    let counted = |s: &Sample| {
        rows += 1;
        sink(s)
    };
    let stats = match &scene.motion {
        MotionSpec::FixedAxis(motion) => run_fixed_axis(scene, motion, counted),
        MotionSpec::Free { omega0_b, body } => {
            if scene.effects.is_empty() {
                run_free(scene, body, omega0_b, TorqueFree, counted)
            } else {
                let moments = EffectMoments::new(&scene.effects, scene.body.mass());
                run_free(scene, body, omega0_b, moments, counted)
            }
        }
    }
    .map_err(split_error)?;
    Ok(RunReport {
        stats,
        rows,
        wall_seconds: start.elapsed().as_secs_f64(),
    })
}

/// Separates the sink's own error (carried out of the integrator as `Stopped`) from integration failures.
fn split_error<E: std::error::Error + 'static>(e: IntegrateError<E>) -> RunError<E> {
    RunError::Integrate(match e {
        IntegrateError::Stopped { cause, .. } => return RunError::Sink(cause),
        IntegrateError::NonFinite { t } => IntegrateError::NonFinite { t },
        IntegrateError::StepSizeTooSmall { t, h } => IntegrateError::StepSizeTooSmall { t, h },
        IntegrateError::TooManySteps { t, steps } => IntegrateError::TooManySteps { t, steps },
        IntegrateError::InvalidSettings { reason } => IntegrateError::InvalidSettings { reason },
        IntegrateError::Backend { t, message } => IntegrateError::Backend { t, message },
    })
}

/// Free rotation in the form the scene's frame selects, streaming each row.
fn run_free<M: AppliedMoment + Clone, E>(
    scene: &Scene,
    body: &FreeBody,
    omega0_b: &Vector3<f64>,
    moment: M,
    mut sink: impl FnMut(&Sample) -> Result<(), E>,
) -> Result<Stats, IntegrateError<E>> {
    let frame = scene.solver.frame;
    let y0 = free::initial_state(body, frame, omega0_b, &scene.attitude0);
    let on_row = |t: f64, y: &free::State| sink(&free::sample(body, &moment, frame, t, y));
    let settings = settings(scene);
    match frame {
        Frame::Body => {
            let mut system = BodyForm {
                body: *body,
                moment: moment.clone(),
            };
            integrate::integrate(&mut system, y0, &scene.schedule, &settings, on_row)
        }
        Frame::Space => {
            let mut system = SpaceForm {
                body: *body,
                moment: moment.clone(),
            };
            integrate::integrate(&mut system, y0, &scene.schedule, &settings, on_row)
        }
    }
}

/// Euler's equation in space axes for a prescribed motion, Ḣ_s = M_s(t) (eq. 8.9), with M_s from the form the
/// scene's frame selects.
struct RequiredMomentRate<'a> {
    motion: &'a FixedAxis,
    frame: Frame,
}

impl OdeSystem<3> for RequiredMomentRate<'_> {
    fn rhs(&mut self, t: f64, _h_s: &SVector<f64, 3>) -> SVector<f64, 3> {
        let angle = self.motion.angle(t);
        match self.frame {
            Frame::Space => self.motion.moment_s(&angle),
            Frame::Body => self.motion.attitude(angle.theta) * self.motion.moment_b(&angle),
        }
    }
}

/// Prescribed fixed-axis motion: each row from the closed form, plus H_s integrated numerically from H_s(0) with
/// the scene's method (the check that Euler's equation in space axes reproduces I_s(θ)·ω_s).
fn run_fixed_axis<E>(
    scene: &Scene,
    motion: &FixedAxis,
    mut sink: impl FnMut(&Sample) -> Result<(), E>,
) -> Result<Stats, IntegrateError<E>> {
    let frame = scene.solver.frame;
    let h_s0: Vector3<f64> = motion.sample(0.0, frame).h_s;
    let mut system = RequiredMomentRate { motion, frame };
    integrate::integrate(
        &mut system,
        h_s0,
        &scene.schedule,
        &settings(scene),
        |t, h_s_int| {
            let mut sample = motion.sample(t, frame);
            sample.h_s_integrated = Some(*h_s_int);
            sink(&sample)
        },
    )
}
