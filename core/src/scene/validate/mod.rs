//! Validation of a [`SceneSpec`] into a [`Scene`]: the checks and messages that every front end (a scene file,
//! Rust code, the study's per-run settings) shares. A failure names the key at fault and what is wrong; the TOML
//! front end adds the file, line and column.

mod body;
mod event;
mod motion;
mod resolved;
mod solver;

use nalgebra::{Quaternion, UnitQuaternion, Vector3};

use super::facts::Facts;
use super::model::Scene;
use super::source_map::KeyPath;
use super::spec::{AttitudeSpec, MotionSpec, SceneSpec};
use crate::body::RigidBody;
use crate::effects::Effect;
use crate::frames::Form;
use crate::keys::{Checked, Invalid, finite, invalid, positive, vector};
use crate::method::{Backend, Method, defaults};
use crate::orbit::CircularOrbit;

pub use crate::keys::InvalidScene;
pub use solver::{MAX_FIXED_STEPS, MAX_ROWS};

/// Values that replace the scene's `[solver]` and `[output]` values (the command line's `--method`, `--dt`, …).
/// A key set here is named `solver.dt (from --dt)` in messages.
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct Overrides {
    /// `--method`.
    pub method: Option<Method>,
    /// `--frame` (the form integrated).
    pub form: Option<Form>,
    /// `--backend`.
    pub backend: Option<Backend>,
    /// `--rtol`.
    pub rtol: Option<f64>,
    /// `--atol`.
    pub atol: Option<f64>,
    /// `--dt` (s).
    pub dt: Option<f64>,
    /// `--t-end` (s).
    pub t_end: Option<f64>,
    /// `--every` (s).
    pub every: Option<f64>,
}

impl SceneSpec {
    /// Validates the scene: the [`Scene`] a run needs, or the first key at fault.
    ///
    /// ```
    /// use eulerdyn::scene::{BodySpec, SceneSpec};
    /// let bad = SceneSpec::new(BodySpec::principal(-1.0, [1.0, 2.0, 3.0]), 1.0, 0.1);
    /// let err = bad.build().unwrap_err();
    /// assert_eq!(err.key.to_string(), "body.mass");
    /// ```
    pub fn build(&self) -> Result<Scene, InvalidScene> {
        self.build_with(&Overrides::default())
    }

    /// Validates the scene with `overrides` replacing its solver and output values.
    pub fn build_with(&self, overrides: &Overrides) -> Result<Scene, InvalidScene> {
        validate(self, overrides)
    }
}

fn validate(doc: &SceneSpec, overrides: &Overrides) -> Checked<Scene> {
    let (body, center_b) = body::validate_body(&doc.body)?;
    let orbit = doc
        .orbit
        .as_ref()
        .map(crate::orbit::validate_orbit)
        .transpose()?;
    let attitude0 = attitude(doc, orbit.as_ref())?;
    let effects = effects(doc, &body, &center_b, orbit.as_ref())?;
    let omega0 = motion::initial_omega(doc, orbit.as_ref(), &attitude0)?;
    let motion = motion::validate_motion(doc, &body, &attitude0, (omega0, &effects), &center_b)?;
    // An axis motion may set the attitude itself (`axis_in_space`, a hinge's `angle_deg`).
    let attitude0 = motion.attitude0(attitude0);
    let solver = solver::validate_solver(&doc.solver, overrides)?;
    solver::validate_method(&solver, &motion, &effects, &attitude0, overrides)?;
    let schedule = solver::validate_schedule(doc, &solver, overrides)?;
    if !doc.event.is_empty() {
        event::locatable(&motion, &solver, overrides)?;
    }
    let compare_tolerance = match &doc.compare {
        None => defaults::COMPARE_TOLERANCE,
        Some(c) => positive(
            KeyPath::root().key("compare").key("tolerance"),
            c.tolerance,
            "largest allowed difference",
        )?,
    };
    let mut scene = Scene {
        name: doc.name.clone().unwrap_or_default(),
        description: doc.description.clone().unwrap_or_default(),
        body,
        center_b,
        motion,
        attitude0,
        effects,
        events: Vec::new(),
        orbit,
        solver,
        schedule,
        compare_tolerance,
        spec: doc.resolved(&solver, schedule.every(), compare_tolerance),
        source: None,
        facts: Facts::default(),
    };
    scene.facts = Facts::of(&scene);
    scene.events = crate::events::validate_events(&doc.event, &scene.facts.columns().columns())?;
    Ok(scene)
}

/// The scene's effects (`crate::effects::validate_effects`), gravity's moment center on an axis its point; a
/// fixed-axis motion takes gravity only.
fn effects(
    doc: &SceneSpec,
    body: &RigidBody,
    center_b: &Vector3<f64>,
    orbit: Option<&CircularOrbit>,
) -> Checked<Vec<Effect>> {
    let axis_point_b = match doc.motion.as_ref().and_then(MotionSpec::axis) {
        Some(axis) => {
            Some(vector(KeyPath::root().key("motion").key("point"), axis.point, "m")? - center_b)
        }
        None => None,
    };
    let effects = crate::effects::validate_effects(
        &doc.effect,
        axis_point_b.as_ref(),
        body,
        center_b,
        orbit,
    )?;
    let not_gravity = (effects.iter()).position(|e| e.gravity().is_none());
    if let (Some(MotionSpec::FixedAxis(_)), Some(index)) = (&doc.motion, not_gravity) {
        return invalid(
            KeyPath::root().key("effect").index(index),
            "a fixed-axis motion is prescribed: its moment is computed from the motion (M = dH/dt), so it takes no torque or damping (only gravity, whose weight its bearings carry); remove the effect, or use type = \"hinge\" to let the effects drive the rotation",
        );
    }
    Ok(effects)
}

/// `initial.attitude`, normalised, the rotation of `initial.attitude_euler_deg` = [z, y, x], intrinsic
/// z-y'-x'' (R = R_z R_y' R_x''), or of `attitude_lvlh_deg` = [roll, pitch, yaw] from the LVLH frame of `orbit` at
/// t = 0; the identity when none is given.
fn attitude(doc: &SceneSpec, orbit: Option<&CircularOrbit>) -> Checked<UnitQuaternion<f64>> {
    let key = |name: &str| KeyPath::root().key("initial").key(name);
    let axis_in_space = (doc.motion.as_ref())
        .and_then(MotionSpec::axis)
        .is_some_and(|a| a.axis_in_space.is_some());
    let given = doc.initial.as_ref().and_then(|i| i.attitude);
    if given.is_some() && axis_in_space {
        return invalid(
            KeyPath::root().key("motion").key("axis_in_space"),
            "`motion.axis_in_space` sets the attitude at t = 0: remove initial.attitude / attitude_euler_deg / attitude_lvlh_deg",
        );
    }
    match given {
        None => Ok(UnitQuaternion::identity()),
        Some(AttitudeSpec::LvlhDeg(angles)) => {
            let key = key("attitude_lvlh_deg");
            let [roll, pitch, yaw] = vector(key.clone(), angles, "degrees")?
                .map(f64::to_radians)
                .into();
            match orbit {
                Some(orbit) => Ok(orbit.attitude_from_lvlh(0.0, [roll, pitch, yaw])),
                None => invalid(
                    key,
                    "angles from the LVLH frame need an `[orbit]` (altitude_km or radius_km)",
                ),
            }
        }
        Some(AttitudeSpec::EulerDeg(angles)) => {
            let [z, y, x] = vector(key("attitude_euler_deg"), angles, "degrees")?.into();
            Ok(UnitQuaternion::from_euler_angles(
                x.to_radians(),
                y.to_radians(),
                z.to_radians(),
            ))
        }
        Some(AttitudeSpec::Quaternion(q)) => {
            let key = key("attitude");
            if !q.iter().all(|x| x.is_finite()) {
                return invalid(key, format!("every component must be finite, got {q:?}"));
            }
            let quat = Quaternion::new(q[0], q[1], q[2], q[3]);
            if quat.norm() < 1e-12 {
                return invalid(
                    key,
                    "the zero quaternion is not an attitude; give [w, x, y, z] with a nonzero norm (identity: [1, 0, 0, 0])",
                );
            }
            Ok(UnitQuaternion::from_quaternion(quat))
        }
    }
}

/// The key of an overridable value: `solver.dt`, or `solver.dt (from --dt)` when the command line set it.
pub(super) fn key_of(section: &str, name: &str, overridden: bool) -> KeyPath {
    let key = KeyPath::root().key(section).key(name);
    if overridden {
        key.from_flag(&format!("--{}", name.replace('_', "-")))
    } else {
        key
    }
}
