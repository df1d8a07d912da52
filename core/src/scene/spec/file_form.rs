//! The scene file's own tables (a capability declares its table in its folder), each declared once by its typed
//! spec or its file form (`keys::Table`, `keys::Keys`): every optional key an `Option` in the file form (absent
//! means the documented default), so that serde reads any file and the reading can name the key at fault — its
//! messages (key, line and column) would be lost inside serde's internally tagged enums. The top level, `[body]`,
//! `[[body.point_mass]]` and `[initial]` are typed specs ([`SceneSpec`], [`BodySpec`], [`PointMassSpec`],
//! [`InitialSpec`]: read and written key for key, a capability's table by its one `table` field, a group of keys
//! by its `flatten` field); `[solver]`, `[output]` and `[compare]` have no keys that depend on another, so their
//! file forms are their typed specs.

use super::{AttitudeSpec, Distribution, InertiaSpec, ShapeSpec};
use crate::effects::EffectSpec;
use crate::events::EventSpec;
use crate::frames::Form;
use crate::keys::{Checked, Group, KeyPath, Keys, Kind, Table};
use crate::method::{Backend, Method};
use crate::motion::spec::MotionSpec;
use crate::orbit::OrbitSpec;
use crate::shape_change::{ShapeChangeKeys, ShapeChangeSpec};
use crate::wheels::RotorSpec;

/// A whole scene. Serde reads and writes it as a scene file writes it (TOML, or the same keys in JSON).
#[derive(Debug, Clone, PartialEq, Table)]
#[table(file = SceneFile, header = "", about = "the top level of the file")]
pub struct SceneSpec {
    /// shown by `check` and in plot titles
    #[key(shown = "\"\"")]
    pub name: Option<String>,
    /// one line, shown by `check`
    #[key(shown = "\"\"")]
    pub description: Option<String>,
    /// the body: `[body]`
    #[key(table)]
    pub body: BodySpec,
    /// the motion: `[motion]`
    #[key(table, shown = "free rotation")]
    pub motion: Option<MotionSpec>,
    /// the state at t = 0: `[initial]`
    #[key(table, shown = "at rest, identity attitude")]
    pub initial: Option<InitialSpec>,
    /// a circular orbit about the Earth, for the environment's effects and the LVLH columns: `[orbit]`
    #[key(table)]
    pub orbit: Option<OrbitSpec>,
    /// the moments applied: `[[effect]]`
    #[key(table, shown = "none: torque-free")]
    pub effect: Vec<EffectSpec>,
    /// moments to locate between rows: `[[event]]`
    #[key(table)]
    pub event: Vec<EventSpec>,
    /// the integration: `[solver]`
    #[key(table)]
    pub solver: SolverSpec,
    /// the rows written: `[output]`
    #[key(table)]
    pub output: OutputSpec,
    /// what `eulerdyn compare` accepts: `[compare]`
    #[key(table, shown = "tolerance 1e-8")]
    pub compare: Option<CompareSpec>,
}

/// `[body]`: the mass, its distribution and the point masses attached.
#[derive(Debug, Clone, PartialEq, Table)]
#[table(
    file = BodyFile,
    header = "[body]",
    about = "the rigid body: its mass and either a shape or an inertia tensor",
    what = "the body"
)]
pub struct BodySpec {
    /// > 0
    #[key(unit = "kg")]
    pub mass: f64,
    /// `shape` or `inertia`.
    #[key(flatten = DistributionKeys)]
    pub distribution: Distribution,
    /// point masses rigidly attached: `[[body.point_mass]]`
    #[key(table)]
    pub point_mass: Vec<PointMassSpec>,
    /// wheels spinning inside the body (at most 4): `[[body.rotor]]`
    #[key(table)]
    pub rotor: Vec<RotorSpec>,
    /// `[[body.moving_mass]]` or `inertia_table`: a body that changes shape.
    #[key(flatten = ShapeChangeKeys, default = ShapeChangeSpec::default())]
    pub shape_change: ShapeChangeSpec,
}

/// `[body]`'s `shape` or `inertia`, read as the body's [`Distribution`].
#[derive(Debug, Clone, Default, PartialEq, Keys)]
#[keys(either(shape, inertia, "give either `shape` or `inertia`, not both"))]
pub(crate) struct DistributionKeys {
    /// a homogeneous shape: `[body.shape]`
    #[key(table, kind = "inline table", shown = "one of `shape` / `inertia`")]
    pub(super) shape: Option<ShapeFile>,
    /// about C in body axes: principal moments, or the symmetric tensor with I_xy = −∫xy dm; positive
    /// semi-definite, triangle inequality
    #[key(
        kind = "[I1, I2, I3] or 3×3 array",
        unit = "kg·m²",
        shown = "one of `shape` / `inertia`"
    )]
    pub(super) inertia: Option<InertiaSpec>,
}

/// One `[[body.point_mass]]`: a point mass rigidly attached.
#[derive(Debug, Clone, Copy, PartialEq, Table)]
#[table(
    file = PointMassFile,
    header = "[[body.point_mass]]",
    about = "a point mass rigidly attached; mass, C and the inertia are then the whole body's (parallel axes)",
    what = "a point mass",
    derive(Copy)
)]
pub struct PointMassSpec {
    /// > 0
    #[key(unit = "kg")]
    pub mass: f64,
    /// where the mass sits
    #[key(position)]
    pub at: [f64; 3],
}

/// `body.shape`. Disks and cylinders have their symmetry axis along body z; the thin rod lies along body x.
#[derive(Debug, Clone, Copy, Default, PartialEq, Keys)]
#[keys(
    header = "[body.shape]",
    about = "a shape of uniform density (disks and cylinders: symmetry axis along body z; the thin rod along body x)"
)]
pub(crate) struct ShapeFile {
    /// the shape
    #[key(rename = "type", kinds, shown = "required")]
    pub(super) kind: Option<ShapeKind>,
    /// > 0
    #[key(unit = "m", shown = "required for disks, cylinder, sphere")]
    pub(super) radius: Option<f64>,
    /// ≥ 0
    #[key(unit = "m", shown = "required for `disk`")]
    pub(super) thickness: Option<f64>,
    /// > 0
    #[key(unit = "m", shown = "required for `thin_rod`")]
    pub(super) length: Option<f64>,
    /// edges along body x, y, z
    #[key(kind = "[a, b, c]", unit = "m", shown = "required for `box`")]
    pub(super) size: Option<[f64; 3]>,
    /// > 0
    #[key(unit = "m", shown = "required for `cylinder`")]
    pub(super) height: Option<f64>,
}

/// The `type` of a shape.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Kind)]
#[kind(
    what = "shape type",
    missing = "missing: the shape needs `type` = \"thin_disk\" | \"disk\" | \"thin_rod\" | \"sphere\" | \"box\" | \"cylinder\"",
    spec = ShapeSpec,
    file = ShapeFile
)]
pub(crate) enum ShapeKind {
    #[kind("thin_disk", takes(radius))]
    ThinDisk,
    #[kind("disk", takes(radius, thickness))]
    Disk,
    #[kind("thin_rod", takes(length))]
    ThinRod,
    #[kind("sphere", takes(radius))]
    Sphere,
    #[kind("box", takes(size))]
    Box,
    #[kind("cylinder", takes(radius, height))]
    Cylinder,
}

/// `[initial]`.
#[derive(Debug, Clone, Copy, Default, PartialEq, Table)]
#[table(
    file = InitialFile,
    header = "[initial]",
    about = "the state at t = 0",
    either(omega, omega_lvlh, "give either `omega` (inertial) or `omega_lvlh` (relative to LVLH), not both"),
    derive(Copy)
)]
pub struct InitialSpec {
    /// ω(0) in body axes; free motion only
    #[key(unit = "rad/s", shown = "[0, 0, 0]")]
    pub omega: Option<[f64; 3]>,
    /// `attitude`, `attitude_euler_deg` or `attitude_lvlh_deg`; absent: the identity (or what the motion's
    /// `axis_in_space` sets).
    #[key(flatten = AttitudeKeys)]
    pub attitude: Option<AttitudeSpec>,
    /// instead of `omega`: ω(0) relative to the LVLH frame, body axes (ω = this + the frame's rate n ĥ); needs an `[orbit]`
    #[key(unit = "rad/s")]
    pub omega_lvlh: Option<[f64; 3]>,
}

/// `[initial]`'s attitude: a quaternion, Euler angles, or angles from LVLH, read as an [`AttitudeSpec`].
#[derive(Debug, Clone, Copy, Default, PartialEq, Keys)]
#[keys(either(
    attitude,
    attitude_euler_deg,
    attitude_lvlh_deg,
    "give one of `attitude`, `attitude_euler_deg` and `attitude_lvlh_deg`"
))]
pub(crate) struct AttitudeKeys {
    /// body → space quaternion, normalised; not zero
    #[key(kind = "[w, x, y, z]", unit = "1", shown = "[1, 0, 0, 0]")]
    attitude: Option<[f64; 4]>,
    /// instead of `attitude`: intrinsic z-y′-x″ angles, R = R_z R_y′ R_x″
    #[key(kind = "[z, y, x]", unit = "deg")]
    attitude_euler_deg: Option<[f64; 3]>,
    /// instead of `attitude`: 3-2-1 angles from the LVLH frame at t = 0, R_LVLH←body = R_z(yaw) R_y(pitch) R_x(roll); needs an `[orbit]`
    #[key(kind = "[roll, pitch, yaw]", unit = "deg")]
    attitude_lvlh_deg: Option<[f64; 3]>,
}

/// The attitude the file gives, if any (`exclusive()` has refused two).
impl Group<AttitudeKeys> for Option<AttitudeSpec> {
    fn read(keys: &AttitudeKeys, _at: &KeyPath) -> Checked<Self> {
        Ok(match *keys {
            AttitudeKeys {
                attitude: Some(q), ..
            } => Some(AttitudeSpec::Quaternion(q)),
            AttitudeKeys {
                attitude_euler_deg: Some(zyx),
                ..
            } => Some(AttitudeSpec::EulerDeg(zyx)),
            AttitudeKeys {
                attitude_lvlh_deg: Some(rpy),
                ..
            } => Some(AttitudeSpec::LvlhDeg(rpy)),
            _ => None,
        })
    }

    fn write(&self, keys: &mut AttitudeKeys) {
        match *self {
            Some(AttitudeSpec::Quaternion(q)) => keys.attitude = Some(q),
            Some(AttitudeSpec::EulerDeg(zyx)) => keys.attitude_euler_deg = Some(zyx),
            Some(AttitudeSpec::LvlhDeg(rpy)) => keys.attitude_lvlh_deg = Some(rpy),
            None => {}
        }
    }
}

/// `[solver]`.
#[derive(Debug, Clone, Copy, Default, PartialEq, Keys)]
#[keys(
    header = "[solver]",
    about = "the integration; `run --method --frame --backend --rtol --atol --dt --t-end` override it",
    spec
)]
pub struct SolverSpec {
    /// fixed step (`dt`), adaptive, or the torque-free closed form
    #[key(
        kind = "\"rk4\" | \"split2\" | \"split4\" | \"dopri5\" | \"dop853\" | \"exact\"",
        shown = "\"dop853\""
    )]
    pub method: Option<Method>,
    /// which form of Euler's equation is integrated
    #[key(rename = "frame", kind = "\"body\" | \"space\"", shown = "\"body\"")]
    pub form: Option<Form>,
    /// the Runge–Kutta implementation
    #[key(kind = "\"own\" | \"ode_solvers\"", shown = "\"own\"")]
    pub backend: Option<Backend>,
    /// adaptive methods, in [1e-14, 1)
    #[key(unit = "1", shown = "1e-10")]
    pub rtol: Option<f64>,
    /// adaptive methods, > 0
    #[key(unit = "as the state", shown = "1e-12")]
    pub atol: Option<f64>,
    /// fixed-step methods, > 0
    #[key(unit = "s", shown = "1e-3")]
    pub dt: Option<f64>,
    /// ≥ 0
    #[key(unit = "s")]
    pub t_end: f64,
}

/// `[output]`.
#[derive(Debug, Clone, Copy, Default, PartialEq, Keys)]
#[keys(
    header = "[output]",
    about = "the rows; `run --every` overrides it",
    spec
)]
pub struct OutputSpec {
    /// > 0: rows at t = k·every and at t_end
    #[key(unit = "s")]
    pub every: f64,
}

/// `[compare]`.
#[derive(Debug, Clone, Copy, Default, PartialEq, Keys)]
#[keys(header = "[compare]", about = "`eulerdyn compare`'s tolerance", spec)]
pub struct CompareSpec {
    /// largest accepted difference, > 0
    #[key(unit = "as the quantity", shown = "1e-8")]
    pub tolerance: f64,
}
