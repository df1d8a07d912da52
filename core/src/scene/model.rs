//! The validated scene: everything a run needs, in the types the simulation uses. Built by [`crate::scene`].

use nalgebra::{Matrix3, UnitQuaternion, Vector3};

use crate::body::RigidBody;
use crate::effects::Effect;
use crate::events::Event;
use crate::frames::{BodyAxes, Form, Vector};
use crate::integrate::Schedule;
use crate::method::{Backend, Method};
use crate::motion::fixed_axis::FixedAxis;
use crate::motion::free::FreeBody;
use crate::motion::hinge::Hinge;

use super::facts::Facts;
use super::spec::{MotionKind, SceneSpec};
use crate::effects::potential_columns;
use crate::motion::axis_columns::AxisColumns;
use crate::sample::{ColumnGroup, ColumnSet};
use crate::wheels::gyrostat::Gyrostat;

/// `[solver]`, validated.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SolverConfig {
    /// The method (`solver.method`).
    pub method: Method,
    /// The form of Euler's equation integrated (the scene file's `solver.frame`).
    pub form: Form,
    /// The Runge–Kutta implementation (`solver.backend`).
    pub backend: Backend,
    /// Relative tolerance (`solver.rtol`).
    pub rtol: f64,
    /// Absolute tolerance (`solver.atol`).
    pub atol: f64,
    /// The step (`solver.dt`, s).
    pub dt: f64,
    /// The end time (`solver.t_end`, s).
    pub t_end: f64,
}

/// The motion of the body.
#[derive(Debug, Clone, PartialEq)]
pub enum Motion {
    /// Free rotation from the initial angular velocity (body axes, rad/s), about the moment center
    /// (C, or the pivot of a gravity effect).
    Free {
        /// ω at t = 0, body axes (rad/s).
        omega0_b: Vector<BodyAxes>,
        /// The body about its moment center.
        body: FreeBody,
        /// The body with its rotors (`[[body.rotor]]`), when it has any.
        gyrostat: Option<Box<Gyrostat>>,
    },
    /// Prescribed rotation about a fixed axis.
    FixedAxis(FixedAxis),
    /// Rotation about a fixed axis driven by the effects (θ integrated from their moment about the axis).
    Hinge(Hinge),
}

impl Motion {
    /// The motion's `type` in a scene file.
    pub fn kind(&self) -> MotionKind {
        match self {
            Motion::Free { .. } => MotionKind::Free,
            Motion::FixedAxis(_) => MotionKind::FixedAxis,
            Motion::Hinge(_) => MotionKind::Hinge,
        }
    }

    /// The name of the wheel law that commands the wheels ([`Scene::with_wheel_law`]), if one does.
    pub fn wheel_law(&self) -> Option<&str> {
        match self {
            Motion::Free {
                gyrostat: Some(g), ..
            } => g.law().map(|law| law.name.as_str()),
            _ => None,
        }
    }

    /// The optional columns of an axis motion ([`AxisColumns`]): the force only when C is off the axis, H_s
    /// integrated for a prescribed motion, the loads only with bearings; `None` for free motion.
    pub fn axis_columns(&self) -> Option<AxisColumns> {
        self.axis().map(|axis| AxisColumns {
            force: axis.center_off_axis(),
            h_s_integrated: matches!(self, Motion::FixedAxis(_)),
            bearings: axis.bearings().is_some(),
        })
    }

    /// The columns its capabilities add after all others: a moving support's, a body's wheels'.
    pub fn capability_columns(&self) -> Option<ColumnGroup> {
        match self {
            Motion::Free {
                gyrostat: Some(g), ..
            } => Some(g.columns()),
            _ => (self.axis())
                .and_then(FixedAxis::moving_support)
                .map(|s| s.columns()),
        }
    }

    /// The attitude at t = 0: an axis motion's own (its `axis_in_space`, and a hinge's θ₀), else `given`.
    pub fn attitude0(&self, given: UnitQuaternion<f64>) -> UnitQuaternion<f64> {
        match self {
            Motion::FixedAxis(axis) => axis.attitude(0.0),
            Motion::Hinge(hinge) => hinge.axis().attitude(hinge.theta0()),
            Motion::Free { .. } => given,
        }
    }

    /// The largest rate (rad/s) the motion has at its start or, for a prescribed spin-up, its end `t_end`: |ω₀|
    /// of a free body, the hinge's θ̇₀, max(|θ̇₀|, |θ̇₀ + α t_end|) of a fixed axis; plus a carrier's largest rate.
    pub fn largest_rate(&self, t_end: f64) -> f64 {
        let support =
            (self.axis().and_then(FixedAxis::moving_support)).map_or(0.0, |s| s.largest_rate());
        support
            + match self {
                Motion::Free { omega0_b, .. } => omega0_b.norm(),
                Motion::FixedAxis(axis) => {
                    (axis.rate().abs()).max((axis.rate() + axis.accel() * t_end).abs())
                }
                Motion::Hinge(hinge) => hinge.rate0().abs(),
            }
    }

    /// A free rigid body without rotors: its ω₀ (body axes) and the body about its moment center.
    pub fn rigid_free(&self) -> Option<(&Vector<BodyAxes>, &FreeBody)> {
        match self {
            Motion::Free {
                omega0_b,
                body,
                gyrostat: None,
            } => Some((omega0_b, body)),
            _ => None,
        }
    }

    /// The fixed axis of a fixed-axis or hinge motion (its direction, point, bearings); `None` for free motion.
    pub fn axis(&self) -> Option<&FixedAxis> {
        match self {
            Motion::Free { .. } => None,
            Motion::FixedAxis(axis) => Some(axis),
            Motion::Hinge(hinge) => Some(hinge.axis()),
        }
    }

    /// C from the moment center O (the pivot, the axis point, or C itself), and the inertia about O, body axes.
    pub fn about_moment_center(&self) -> (Vector3<f64>, Matrix3<f64>) {
        match (self, self.axis()) {
            (Motion::Free { body, .. }, _) => (**body.rho_c_b(), *body.inertia_b()),
            (_, axis) => axis.map_or((Vector3::zeros(), Matrix3::zeros()), |a| {
                (**a.rho_c_b(), *a.inertia_a_b())
            }),
        }
    }
}

impl Scene {
    /// What the scene conserves, the closed form that applies (evaluated once), the columns and panels of its
    /// runs and the numbers `check` prints ([`Facts::of`], computed when the scene was built).
    pub fn facts(&self) -> &Facts {
        &self.facts
    }

    /// The step a fixed-step method (rk4, split2, split4) takes: `dt`, or less where the rows come more often
    /// ([`Schedule::largest_fixed_step`]); `None` for the adaptive and exact methods.
    pub fn fixed_step(&self) -> Option<f64> {
        let s = &self.solver;
        s.method
            .is_fixed_step()
            .then(|| self.schedule.largest_fixed_step(s.dt))
    }

    /// The optional columns a run of `motion` with `effects` writes, in order: an axis motion's leading groups,
    /// gravity's potential, the axis motion's trailing group, then the capabilities' ([`Motion::capability_columns`]).
    pub fn run_columns(motion: &Motion, effects: &[Effect]) -> ColumnSet {
        let gravity = crate::effects::gravity(effects).is_some();
        Self::own_columns(motion.axis_columns(), gravity, motion.capability_columns())
    }

    /// Every optional column of a scene's own (an axis motion's with force, H_s integrated and bearings, and the
    /// potential's), no capability's: what a sweep may summarise when no scene of it builds.
    ///
    /// ```
    /// let names: Vec<String> = eulerdyn::scene::Scene::all_own_columns().columns().iter()
    ///     .map(|c| c.name.to_string()).collect();
    /// assert!(names.contains(&"R_B_b_z".to_string()) && names.contains(&"energy_total".to_string()));
    /// ```
    pub fn all_own_columns() -> ColumnSet {
        Self::own_columns(Some(AxisColumns::ALL), true, None)
    }

    /// The column groups in the order a run writes them.
    fn own_columns(
        axis: Option<AxisColumns>,
        gravity: bool,
        capability: Option<ColumnGroup>,
    ) -> ColumnSet {
        let mut groups = axis.map_or_else(Vec::new, AxisColumns::leading);
        groups.extend(gravity.then(potential_columns));
        groups.extend(axis.map(AxisColumns::trailing));
        groups.extend(capability);
        ColumnSet { groups }
    }

    /// The potential energy of the scene's gravity at the attitude `q`: V = −m g·r_C, with r_C = q ρ_C the
    /// mass center from the moment center (the pivot or the axis point) in space axes; `None` without gravity.
    pub fn gravity_potential(&self, q: &UnitQuaternion<f64>) -> Option<f64> {
        (self.effects.iter()).find_map(|e| e.potential(self.body.mass(), q))
    }
}

/// A validated scene.
#[derive(Debug, Clone, PartialEq)]
pub struct Scene {
    /// `name`.
    pub name: String,
    /// `description`.
    pub description: String,
    /// The body: its mass distribution (`[body]`).
    pub body: RigidBody,
    /// The mass center C from the reference origin, body axes (m): zero without point masses. Every position
    /// in a scene file is measured from the reference origin; every position in the validated scene from C.
    pub center_b: Vector3<f64>,
    /// The motion (`[motion]`).
    pub motion: Motion,
    /// Attitude at t = 0 (body → space).
    pub attitude0: UnitQuaternion<f64>,
    /// The effects (`[[effect]]`), in order.
    pub effects: Vec<Effect>,
    /// `[[event]]`s to locate between the rows.
    pub events: Vec<Event>,
    /// `[solver]`.
    pub solver: SolverConfig,
    /// Row times: k·every, then t_end.
    pub schedule: Schedule,
    /// Largest allowed difference for `eulerdyn compare`.
    pub compare_tolerance: f64,
    /// The scene as simulated: the spec it was built from, with the overrides applied and every default that a
    /// key leaves out written in (the solver and output values as run, each effect's and motion's defaults). The
    /// analyses that vary a scene (accuracy, balance, sweeps) start from it, and the run's sidecar records it.
    pub spec: SceneSpec,
    /// The scene file it was read from and that file's text; `None` for a scene built in code.
    pub source: Option<SceneSource>,
    /// What it conserves, the closed form that applies, its columns and panels ([`Scene::facts`]), computed when
    /// it is built (and again when a user's moment is added).
    pub(super) facts: Facts,
}

/// Where a scene came from: its file (or `<dict>` for a Python dict) and the text as written.
#[derive(Debug, Clone, PartialEq)]
pub struct SceneSource {
    /// The scene file (`<dict>` for a Python dict).
    pub path: std::path::PathBuf,
    /// Its text as written.
    pub text: String,
}
