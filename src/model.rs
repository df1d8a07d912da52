//! The validated scene: everything a run needs, in the types the simulation uses. Built by [`crate::scene`].

use nalgebra::{UnitQuaternion, Vector3};

use crate::body::RigidBody;
use crate::effects::Effect;
use crate::integrate::Schedule;
use crate::motion::fixed_axis::FixedAxis;
use crate::motion::free::FreeBody;

/// Which axes a vector is expressed in, or which form of Euler's equation is integrated.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Frame {
    /// Axes fixed in the body (the axes the scene's inertia is given in).
    Body,
    /// The inertial frame.
    Space,
}

impl Frame {
    /// The name used in scene files and on the command line.
    pub fn name(&self) -> &'static str {
        match self {
            Frame::Body => "body",
            Frame::Space => "space",
        }
    }
}

/// An integration method, by its scene-file name.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum MethodName {
    /// Classic fourth-order Runge–Kutta, fixed step `dt`.
    Rk4,
    /// Dormand–Prince 5(4), adaptive.
    Dopri5,
    /// Dormand–Prince 8(5,3), adaptive.
    Dop853,
}

impl MethodName {
    /// Every method, in the order they are listed to users.
    pub const ALL: [MethodName; 3] = [MethodName::Rk4, MethodName::Dopri5, MethodName::Dop853];

    /// The name used in scene files and on the command line.
    pub fn name(&self) -> &'static str {
        match self {
            MethodName::Rk4 => "rk4",
            MethodName::Dopri5 => "dopri5",
            MethodName::Dop853 => "dop853",
        }
    }

    /// Whether the method takes steps of the fixed size `dt` (else it adapts its step to `rtol`/`atol`).
    pub fn is_fixed_step(&self) -> bool {
        matches!(self, MethodName::Rk4)
    }
}

/// Which implementation runs the Runge–Kutta methods.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum BackendName {
    /// The project's own tableaus (streaming, exact row times, renormalised every step).
    Own,
    /// The ode_solvers 0.6.2 crate, with its known defects worked around.
    OdeSolvers,
}

impl BackendName {
    /// The name used in scene files and on the command line.
    pub fn name(&self) -> &'static str {
        match self {
            BackendName::Own => "own",
            BackendName::OdeSolvers => "ode_solvers",
        }
    }
}

/// `[solver]`, validated.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SolverConfig {
    pub method: MethodName,
    pub frame: Frame,
    pub backend: BackendName,
    pub rtol: f64,
    pub atol: f64,
    pub dt: f64,
    pub t_end: f64,
}

/// The motion of the body.
#[derive(Debug, Clone, PartialEq)]
pub enum MotionSpec {
    /// Free rotation from the initial angular velocity (body axes, rad/s), about the moment center
    /// (C, or the pivot of a gravity effect).
    Free {
        omega0_b: Vector3<f64>,
        body: FreeBody,
    },
    /// Prescribed rotation about a fixed axis.
    FixedAxis(FixedAxis),
}

/// A validated scene.
#[derive(Debug, Clone, PartialEq)]
pub struct Scene {
    pub name: String,
    pub description: String,
    pub body: RigidBody,
    pub motion: MotionSpec,
    /// Attitude at t = 0 (body → space).
    pub attitude0: UnitQuaternion<f64>,
    pub effects: Vec<Effect>,
    pub solver: SolverConfig,
    /// Row times: k·every, then t_end.
    pub schedule: Schedule,
    /// Largest allowed difference for `eulerdyn compare`.
    pub compare_tolerance: f64,
}
