//! The scene file's form: one flat struct per table, every key an `Option` (absent means the documented default),
//! so that serde reads any file and [`super::from_file`] can name the key at fault — its messages (key, line and
//! column) would be lost inside serde's internally tagged enums. The typed [`super::SceneFile`] is read and
//! written through this form.

use serde::de::Error as _;
use serde::{Deserialize, Deserializer, Serialize};

use super::{CompareSpec, Direction, Extremum, InertiaSpec, MotionKind, OutputSpec, SolverSpec};
use crate::effects::Interpolation;
use crate::frames::Axes;

/// A whole scene, as a scene file writes it.
#[derive(Debug, Clone, Default, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub(in crate::scene) struct SceneFile {
    /// `name`.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub(super) name: Option<String>,
    /// `description`.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub(super) description: Option<String>,
    /// `[body]`.
    pub(super) body: BodyFile,
    /// `[motion]`; absent: free rotation.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub(super) motion: Option<MotionFile>,
    /// `[initial]`.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub(super) initial: Option<InitialFile>,
    /// `[[effect]]`, in order; none: torque-free.
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub(super) effect: Vec<EffectFile>,
    /// `[[event]]`, in order.
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub(super) event: Vec<EventFile>,
    /// `[solver]`.
    pub(super) solver: SolverSpec,
    /// `[output]`.
    pub(super) output: OutputSpec,
    /// `[compare]`.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub(super) compare: Option<CompareSpec>,
}

/// `[body]`: the mass and either a shape or an inertia tensor about C.
#[derive(Debug, Clone, Default, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub(super) struct BodyFile {
    /// kg, > 0.
    pub(super) mass: f64,
    /// A shape of uniform density.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub(super) shape: Option<ShapeFile>,
    /// The inertia about C in body axes (kg·m²), instead of a shape.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub(super) inertia: Option<InertiaSpec>,
    /// `[[body.point_mass]]`: point masses rigidly attached.
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub(super) point_mass: Vec<PointMassFile>,
    /// `[[body.rotor]]`: wheels spinning inside the body.
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub(super) rotor: Vec<RotorFile>,
}

/// One `[[body.rotor]]`.
#[derive(Debug, Clone, Default, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub(super) struct RotorFile {
    /// Column prefix.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub(super) name: Option<String>,
    /// Spin axis, body axes.
    #[serde(
        default,
        deserialize_with = "exactly_n",
        skip_serializing_if = "Option::is_none"
    )]
    pub(super) axis: Option<[f64; 3]>,
    /// kg·m² about the spin axis.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub(super) inertia: Option<f64>,
    /// rad/s relative to the body at t = 0.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub(super) spin: Option<f64>,
    /// rad/s², prescribed.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub(super) spin_accel: Option<f64>,
    /// N·m, the motor torque on the wheel.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub(super) torque: Option<f64>,
    /// The motor torque's profile and its keys, as a torque effect's.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub(super) profile: Option<ProfileKind>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub(super) freq_hz: Option<f64>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub(super) phase_deg: Option<f64>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub(super) t_on: Option<f64>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub(super) t_off: Option<f64>,
    /// Wheel centre from the reference origin (m).
    #[serde(
        default,
        deserialize_with = "exactly_n",
        skip_serializing_if = "Option::is_none"
    )]
    pub(super) at: Option<[f64; 3]>,
    /// g·mm.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub(super) imbalance_static_gmm: Option<f64>,
    /// g·mm².
    #[serde(skip_serializing_if = "Option::is_none")]
    pub(super) imbalance_dynamic_gmm2: Option<f64>,
    /// The wheel's keys (`crate::wheels`): N·m, rpm, its friction, `mode = "free"`, its command table.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub(super) max_torque: Option<f64>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub(super) max_speed_rpm: Option<f64>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub(super) friction: Option<crate::wheels::FrictionKeys>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub(super) mode: Option<crate::wheels::WheelMode>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub(super) torque_table: Option<std::path::PathBuf>,
}

/// One `[[body.point_mass]]`.
#[derive(Debug, Clone, Copy, Default, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub(super) struct PointMassFile {
    /// kg, > 0.
    pub(super) mass: f64,
    /// Position from the reference origin (the shape's center, or the point the given inertia is about), body
    /// axes (m).
    #[serde(
        default,
        deserialize_with = "exactly_n",
        skip_serializing_if = "Option::is_none"
    )]
    pub(super) at: Option<[f64; 3]>,
}

/// The `type` of a shape.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub(super) enum ShapeKind {
    ThinDisk,
    Disk,
    ThinRod,
    Sphere,
    Box,
    Cylinder,
}

/// `body.shape`. Disks and cylinders have their symmetry axis along body z; the thin rod lies along body x.
#[derive(Debug, Clone, Copy, Default, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub(super) struct ShapeFile {
    /// `type`.
    #[serde(rename = "type", skip_serializing_if = "Option::is_none")]
    pub(super) kind: Option<ShapeKind>,
    /// m.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub(super) radius: Option<f64>,
    /// m.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub(super) thickness: Option<f64>,
    /// m.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub(super) length: Option<f64>,
    /// [x, y, z], m.
    #[serde(
        default,
        deserialize_with = "exactly_n",
        skip_serializing_if = "Option::is_none"
    )]
    pub(super) size: Option<[f64; 3]>,
    /// m.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub(super) height: Option<f64>,
}

/// `[motion]`.
#[derive(Debug, Clone, Copy, Default, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub(super) struct MotionFile {
    /// `type`.
    #[serde(rename = "type", skip_serializing_if = "Option::is_none")]
    pub(super) kind: Option<MotionKind>,
    /// The axis in body axes (normalised by validation).
    #[serde(
        default,
        deserialize_with = "exactly_n",
        skip_serializing_if = "Option::is_none"
    )]
    pub(super) axis: Option<[f64; 3]>,
    /// Shorthand for the axis (0, −sin, cos) of the tilt, degrees.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub(super) tilt_deg: Option<f64>,
    /// rad/s at t = 0.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub(super) rate: Option<f64>,
    /// The same in revolutions per minute, instead of `rate` (rate = rate_rpm · 2π/60).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub(super) rate_rpm: Option<f64>,
    /// rad/s², constant.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub(super) accel: Option<f64>,
    /// A point on the axis, body axes, relative to C (m).
    #[serde(
        default,
        deserialize_with = "exactly_n",
        skip_serializing_if = "Option::is_none"
    )]
    pub(super) point: Option<[f64; 3]>,
    /// θ at t = 0 (degrees), hinge only.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub(super) angle_deg: Option<f64>,
    /// Axial positions [a, b] of bearings A and B from `point` along the axis (m), a ≠ b.
    #[serde(
        default,
        deserialize_with = "exactly_n",
        skip_serializing_if = "Option::is_none"
    )]
    pub(super) bearings: Option<[f64; 2]>,
    /// The axis's direction in space axes: the attitude at t = 0 is then the smallest rotation that puts the body
    /// axis on it (instead of `initial.attitude`).
    #[serde(
        default,
        deserialize_with = "exactly_n",
        skip_serializing_if = "Option::is_none"
    )]
    pub(super) axis_in_space: Option<[f64; 3]>,
    /// The carrier that holds the axis: `{ rate, profile, freq_hz, phase_deg, center, accel, accel_profile }`.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub(super) carrier: Option<CarrierFile>,
}

/// `carrier = { … }` in `[motion]`.
#[derive(Debug, Clone, Copy, Default, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub(super) struct CarrierFile {
    /// rad/s, space axes.
    #[serde(
        default,
        deserialize_with = "exactly_n",
        skip_serializing_if = "Option::is_none"
    )]
    pub(super) rate: Option<[f64; 3]>,
    /// Default constant.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub(super) profile: Option<CarrierProfileKind>,
    /// Hz (sine).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub(super) freq_hz: Option<f64>,
    /// Degrees (sine).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub(super) phase_deg: Option<f64>,
    /// m, from the axis point at t = 0, space axes (a vehicle's centre of rotation).
    #[serde(
        default,
        deserialize_with = "exactly_n",
        skip_serializing_if = "Option::is_none"
    )]
    pub(super) center: Option<[f64; 3]>,
    /// m/s², space axes (a vehicle's own acceleration).
    #[serde(
        default,
        deserialize_with = "exactly_n",
        skip_serializing_if = "Option::is_none"
    )]
    pub(super) accel: Option<[f64; 3]>,
    /// Default constant.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub(super) accel_profile: Option<CarrierProfileKind>,
}

/// A carrier's `profile`.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub(super) enum CarrierProfileKind {
    Constant,
    Sine,
}

/// `[initial]`.
#[derive(Debug, Clone, Copy, Default, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub(super) struct InitialFile {
    /// rad/s, body axes.
    #[serde(
        default,
        deserialize_with = "exactly_n",
        skip_serializing_if = "Option::is_none"
    )]
    pub(super) omega: Option<[f64; 3]>,
    /// [w, x, y, z], body → space (normalised by validation).
    #[serde(
        default,
        deserialize_with = "exactly_n",
        skip_serializing_if = "Option::is_none"
    )]
    pub(super) attitude: Option<[f64; 4]>,
    /// The attitude as intrinsic z-y'-x'' angles [z, y, x] in degrees (instead of `attitude`).
    #[serde(
        default,
        deserialize_with = "exactly_n",
        skip_serializing_if = "Option::is_none"
    )]
    pub(super) attitude_euler_deg: Option<[f64; 3]>,
}

/// The `type` of an effect.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub(super) enum EffectKind {
    Torque,
    Gravity,
    Damping,
    TorqueTable,
}

/// The `profile` of a torque.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub(super) enum ProfileKind {
    Constant,
    Sine,
    Step,
}

/// One `[[effect]]`.
#[derive(Debug, Clone, Default, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub(super) struct EffectFile {
    /// `type`.
    #[serde(rename = "type", skip_serializing_if = "Option::is_none")]
    pub(super) kind: Option<EffectKind>,
    /// The axes a torque's value is given in (default body).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub(super) frame: Option<Axes>,
    /// N·m.
    #[serde(
        default,
        deserialize_with = "exactly_n",
        skip_serializing_if = "Option::is_none"
    )]
    pub(super) value: Option<[f64; 3]>,
    /// Default constant.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub(super) profile: Option<ProfileKind>,
    /// Hz (sine).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub(super) freq_hz: Option<f64>,
    /// Degrees (sine).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub(super) phase_deg: Option<f64>,
    /// s (step).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub(super) t_on: Option<f64>,
    /// s (step).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub(super) t_off: Option<f64>,
    /// m/s², space axes (gravity; default (0, 0, −9.81)).
    #[serde(
        default,
        deserialize_with = "exactly_n",
        skip_serializing_if = "Option::is_none"
    )]
    pub(super) g: Option<[f64; 3]>,
    /// The fixed point, body axes, relative to C (m) (gravity).
    #[serde(
        default,
        deserialize_with = "exactly_n",
        skip_serializing_if = "Option::is_none"
    )]
    pub(super) pivot: Option<[f64; 3]>,
    /// N·m·s (damping).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub(super) c: Option<f64>,
    /// The CSV file of a torque table, relative to the scene file.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub(super) file: Option<std::path::PathBuf>,
    /// A torque table's interpolation (default linear).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub(super) interpolation: Option<Interpolation>,
}

/// One `[[event]]`.
#[derive(Debug, Clone, Default, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub(super) struct EventFile {
    #[serde(skip_serializing_if = "Option::is_none")]
    pub(super) name: Option<String>,
    /// A column, or `|X|`.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub(super) when: Option<String>,
    /// The value crossed.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub(super) crosses: Option<f64>,
    /// `up`, `down` or `both` (crossings; default both).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub(super) direction: Option<Direction>,
    /// `max` or `min`.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub(super) extremum: Option<Extremum>,
    /// Default false.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub(super) stop: Option<bool>,
}

/// An array of exactly `N` numbers. (serde's `[f64; N]` ignores extra elements when TOML drives it, so
/// `omega = [1, 2, 3, 4]` would pass silently.)
fn exactly_n<'de, D: Deserializer<'de>, const N: usize>(
    deserializer: D,
) -> Result<Option<[f64; N]>, D::Error> {
    let items = Vec::<f64>::deserialize(deserializer)?;
    <[f64; N]>::try_from(items.as_slice())
        .map(Some)
        .map_err(|_| {
            D::Error::invalid_length(items.len(), &format!("an array of {N} numbers").as_str())
        })
}
