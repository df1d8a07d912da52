//! The validated scene: everything a run needs, in the types the simulation uses. Built by [`crate::scene`].

use nalgebra::{UnitQuaternion, Vector3};

use crate::body::RigidBody;
use crate::effects::Effect;
use crate::events::Event;
use crate::frames::Form;
use crate::integrate::Schedule;
use crate::method::{Backend, Method};

use super::facts::Facts;
use super::motion::Motion;
use super::spec::SceneSpec;
use crate::effects::potential_columns;
use crate::motion::axis_columns::AxisColumns;
use crate::orbit::{CircularOrbit, field_columns, lvlh_columns};
use crate::sample::{ColumnGroup, ColumnSet};

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
    /// gravity's potential, the axis motion's trailing group, the capabilities' ([`Motion::capability_columns`]),
    /// then an orbit's LVLH angles, the Earth's field in body axes (with an effect that acts in it) and the effects'
    /// own (B-dot's dipole).
    pub fn run_columns(
        motion: &Motion,
        effects: &[Effect],
        orbit: Option<&CircularOrbit>,
    ) -> ColumnSet {
        let gravity = crate::effects::gravity(effects).is_some();
        let mut columns =
            Self::own_columns(motion.axis_columns(), gravity, motion.capability_columns());
        columns.groups.extend(orbit.copied().map(lvlh_columns));
        let field = effects.iter().find_map(Effect::field);
        columns
            .groups
            .extend(field.map(|(orbit, field)| field_columns(orbit, field)));
        columns
            .groups
            .extend(effects.iter().filter_map(Effect::columns));
        columns
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
    /// `[orbit]`: where the environment's effects take the body, and the frame of the LVLH columns.
    pub orbit: Option<CircularOrbit>,
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
