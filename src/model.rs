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
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum MethodName {
    /// Classic fourth-order Runge–Kutta, fixed step `dt` (HNW I §II.1).
    Rk4,
    /// Dormand–Prince 5(4), adaptive (HNW I §II.5).
    Dopri5,
    /// Dormand–Prince 8(5,3), adaptive (HNW I §II.5).
    Dop853,
    /// Lie–Poisson splitting of the free body into exact planar rotations, Strang composition, order 2
    /// (McLachlan 1993; Touma & Wisdom 1994), fixed step `dt`; effects applied as kicks. Preserves |H| exactly and
    /// H_s to round-off when torque-free; energy error bounded. See [`crate::motion::lie_poisson`].
    Split2,
    /// An order-4 composition of `split2`: Suzuki's fractal S(ph)S(ph)S((1−4p)h)S(ph)S(ph), p = 1/(4 − 4^{1/3})
    /// (Suzuki 1990, Phys. Lett. A 146, 319), fixed step `dt`.
    Split4,
    /// The torque-free flow in closed form (Landau & Lifshitz §37; Celledoni, Fassò, Säfström & Zanna 2008): every
    /// row evaluated directly at its time, no stepping. Torque-free scenes only. See
    /// [`crate::motion::exact_flow`].
    Exact,
}

impl MethodName {
    /// Every method, in the order they are listed to users.
    pub const ALL: [MethodName; 6] = [
        MethodName::Rk4,
        MethodName::Dopri5,
        MethodName::Dop853,
        MethodName::Split2,
        MethodName::Split4,
        MethodName::Exact,
    ];

    /// The name used in scene files and on the command line.
    pub fn name(&self) -> &'static str {
        match self {
            MethodName::Rk4 => "rk4",
            MethodName::Dopri5 => "dopri5",
            MethodName::Dop853 => "dop853",
            MethodName::Split2 => "split2",
            MethodName::Split4 => "split4",
            MethodName::Exact => "exact",
        }
    }

    /// Whether the method takes steps of the fixed size `dt` (rk4, split2, split4). The adaptive methods adapt
    /// their step to `rtol`/`atol`; `exact` takes no steps.
    pub fn is_fixed_step(&self) -> bool {
        matches!(
            self,
            MethodName::Rk4 | MethodName::Split2 | MethodName::Split4
        )
    }

    /// Whether the method adapts its step to `rtol`/`atol` (dopri5, dop853).
    pub fn is_adaptive(&self) -> bool {
        matches!(self, MethodName::Dopri5 | MethodName::Dop853)
    }

    /// Whether the method is a Runge–Kutta method, run by either backend (`own` or `ode_solvers`). The splitting
    /// methods and `exact` are the project's own only.
    pub fn is_runge_kutta(&self) -> bool {
        matches!(
            self,
            MethodName::Rk4 | MethodName::Dopri5 | MethodName::Dop853
        )
    }

    /// The order p of the method: its global error is O(dt^p) for the fixed-step methods; for the adaptive ones
    /// the order of the propagated solution. `None` for `exact` (round-off only).
    pub fn order(&self) -> Option<u32> {
        match self {
            MethodName::Rk4 | MethodName::Split4 => Some(4),
            MethodName::Split2 => Some(2),
            MethodName::Dopri5 => Some(5),
            MethodName::Dop853 => Some(8),
            MethodName::Exact => None,
        }
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
