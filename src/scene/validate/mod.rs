//! Validation of a [`SceneSpec`] into a [`Scene`]: the checks and messages that every front end (a scene file,
//! Rust code, the study's per-run settings) shares. A failure names the key at fault and what is wrong; the TOML
//! front end adds the file, line and column.

mod body;
mod effect;
mod motion;
mod resolved;
mod solver;

use std::fmt;

use nalgebra::{Quaternion, UnitQuaternion, Vector3};

use super::model::{Motion, Scene};
use super::source_map::KeyPath;
use super::spec::SceneSpec;
use crate::frames::Form;
use crate::method::{Backend, Method, defaults};

pub use solver::{MAX_FIXED_STEPS, MAX_ROWS};

/// Values that replace the scene's `[solver]` and `[output]` values (the command line's `--method`, `--dt`, …).
/// A key set here is named `solver.dt (from --dt)` in messages.
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct Overrides {
    pub method: Option<Method>,
    pub frame: Option<Form>,
    pub backend: Option<Backend>,
    pub rtol: Option<f64>,
    pub atol: Option<f64>,
    pub dt: Option<f64>,
    pub t_end: Option<f64>,
    pub every: Option<f64>,
}

/// A scene that is not valid: the key at fault (e.g. `body.mass`, `effect[1].c`) and what is wrong.
#[derive(Debug, Clone, PartialEq)]
pub struct InvalidScene {
    /// The key at fault.
    pub key: KeyPath,
    /// What is wrong and what would be valid.
    pub problem: String,
}

impl fmt::Display for InvalidScene {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "key `{}`: {}", self.key, self.problem)
    }
}

impl std::error::Error for InvalidScene {}

type Invalid = InvalidScene;
type Checked<T> = Result<T, Invalid>;

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
    let attitude0 = attitude(doc)?;
    let effects = effect::validate_effects(doc, &body, &center_b)?;
    let motion = motion::validate_motion(doc, &body, &attitude0, &effects, &center_b)?;
    // An axis motion may set the attitude itself (`axis_in_space`, a hinge's `angle_deg`).
    let attitude0 = match &motion {
        Motion::FixedAxis(axis) => axis.attitude(0.0),
        Motion::Hinge(hinge) => hinge.axis().attitude(hinge.theta0()),
        Motion::Free { .. } => attitude0,
    };
    let solver = solver::validate_solver(&doc.solver, overrides)?;
    solver::validate_method(&solver, &motion, &effects, &attitude0, overrides)?;
    let schedule = solver::validate_schedule(doc, &solver, overrides)?;
    let compare_tolerance = match &doc.compare {
        None => defaults::COMPARE_TOLERANCE,
        Some(c) => positive(
            KeyPath::root().key("compare").key("tolerance"),
            c.tolerance,
            "largest allowed difference",
        )?,
    };
    Ok(Scene {
        name: doc.name.clone().unwrap_or_default(),
        description: doc.description.clone().unwrap_or_default(),
        body,
        center_b,
        motion,
        attitude0,
        effects,
        solver,
        schedule,
        compare_tolerance,
        spec: doc.resolved(&solver, schedule.every(), compare_tolerance),
        source: None,
    })
}

/// `initial.attitude`, normalised, or the rotation of `initial.attitude_euler_deg` = [z, y, x], intrinsic
/// z-y'-x'' (R = R_z R_y' R_x''); the identity when neither is given.
fn attitude(doc: &SceneSpec) -> Checked<UnitQuaternion<f64>> {
    let initial = doc.initial.as_ref();
    let key = |name: &str| KeyPath::root().key("initial").key(name);
    let axis_in_space = doc
        .motion
        .as_ref()
        .is_some_and(|m| m.axis_in_space.is_some());
    let euler = initial.and_then(|i| i.attitude_euler_deg);
    let given = initial.and_then(|i| i.attitude);
    match (given.is_some(), euler.is_some(), axis_in_space) {
        (true, true, _) => {
            return invalid(
                key("attitude_euler_deg"),
                "give either `attitude` or `attitude_euler_deg`, not both",
            );
        }
        (true, _, true) | (_, true, true) => {
            return invalid(
                KeyPath::root().key("motion").key("axis_in_space"),
                "`motion.axis_in_space` sets the attitude at t = 0: remove initial.attitude / attitude_euler_deg",
            );
        }
        _ => {}
    }
    if let Some(angles) = euler {
        let [z, y, x] = vector(key("attitude_euler_deg"), angles, "degrees")?.into();
        return Ok(UnitQuaternion::from_euler_angles(
            x.to_radians(),
            y.to_radians(),
            z.to_radians(),
        ));
    }
    let Some(q) = given else {
        return Ok(UnitQuaternion::identity());
    };
    let key = KeyPath::root().key("initial").key("attitude");
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

pub(super) fn invalid<T>(key: KeyPath, problem: impl Into<String>) -> Checked<T> {
    Err(Invalid {
        key,
        problem: problem.into(),
    })
}

/// The value of a key that `kind` requires.
pub(super) fn required<T>(key: KeyPath, value: Option<T>, kind: &str) -> Checked<T> {
    value.ok_or_else(|| Invalid {
        problem: format!("missing: {kind} needs `{}`", key.last_key()),
        key,
    })
}

/// Refuses the keys of `table` that are given (`given`: every optional key and whether it is present) but that
/// `kind` does not take (`takes`).
pub(super) fn only_keys(
    table: &KeyPath,
    kind: &str,
    takes: &[&str],
    given: &[(&str, bool)],
) -> Checked<()> {
    match given
        .iter()
        .find(|(name, present)| *present && !takes.contains(name))
    {
        None => Ok(()),
        Some((name, _)) => invalid(
            table.clone().key(name),
            if takes.is_empty() {
                format!("{kind} takes no `{name}`")
            } else {
                format!(
                    "{kind} takes no `{name}`; its keys are: {}",
                    takes.join(", ")
                )
            },
        ),
    }
}

pub(super) fn finite(key: KeyPath, v: f64, unit: &str) -> Checked<f64> {
    if v.is_finite() {
        Ok(v)
    } else {
        invalid(key, format!("must be a finite number ({unit}), got {v:?}"))
    }
}

pub(super) fn positive(key: KeyPath, v: f64, unit: &str) -> Checked<f64> {
    if v.is_finite() && v > 0.0 {
        Ok(v)
    } else {
        invalid(
            key,
            format!("must be a finite number > 0 ({unit}), got {v:?}"),
        )
    }
}

pub(super) fn vector(key: KeyPath, v: [f64; 3], unit: &str) -> Checked<Vector3<f64>> {
    if v.iter().all(|x| x.is_finite()) {
        Ok(Vector3::from(v))
    } else {
        invalid(
            key,
            format!("every component must be a finite number ({unit}), got {v:?}"),
        )
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
