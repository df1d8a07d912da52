//! The scene file's own tables (a capability declares its table in its folder): one flat struct per table, every
//! optional key an `Option` (absent means the documented default), so that serde reads any file and
//! [`super::from_file`] can name the key at fault — its messages (key, line and column) would be lost inside serde's
//! internally tagged enums. The typed [`super::SceneSpec`] is read and written through this form; `[solver]`,
//! `[output]` and `[compare]` have no keys that depend on another, so their tables are their typed specs.

use serde::{Deserialize, Serialize};

use super::{InertiaSpec, MotionKind};
use crate::effects::EffectFile;
use crate::events::EventFile;
use crate::frames::Form;
use crate::keys::{file_table, key, position};
use crate::method::{Backend, Method};
use crate::motion::carrier::spec::CarrierSpec;
use crate::wheels::RotorFile;

file_table! {
    /// A whole scene, as a scene file writes it.
    pub(in crate::scene) struct SceneFile(pub(super)) "",
        "the top level of the file" {
        opt name: String = key("string", "–", "\"\"", "", "shown by `check` and in plot titles");
        opt description: String = key("string", "–", "\"\"", "", "one line, shown by `check`");
        req body: BodyFile = key("table", "–", "required", "", "the body: `[body]`");
        opt motion: MotionFile = key("table", "–", "free rotation", "", "the motion: `[motion]`");
        opt initial: InitialFile = key("table", "–", "at rest, identity attitude", "", "the state at t = 0: `[initial]`");
        list effect: EffectFile = key("array of tables", "–", "none: torque-free", "", "the moments applied: `[[effect]]`");
        list event: EventFile = key("array of tables", "–", "none", "", "moments to locate between rows: `[[event]]`");
        req solver: SolverSpec = key("table", "–", "required", "", "the integration: `[solver]`");
        req output: OutputSpec = key("table", "–", "required", "", "the rows written: `[output]`");
        opt compare: CompareSpec = key("table", "–", "tolerance 1e-8", "", "what `eulerdyn compare` accepts: `[compare]`");
    }
}

file_table! {
    /// `[body]`: the mass and either a shape or an inertia tensor about C.
    pub(in crate::scene) struct BodyFile(pub(super)) "[body]",
        "the rigid body: its mass and either a shape or an inertia tensor" {
        req mass: f64 = key("number", "kg", "required", "", "> 0");
        opt shape: ShapeFile = key("inline table", "–", "one of `shape` / `inertia`", "", "a homogeneous shape: `[body.shape]`");
        opt inertia: InertiaSpec = key("[I1, I2, I3] or 3×3 array", "kg·m²", "one of `shape` / `inertia`", "", "about C in body axes: principal moments, or the symmetric tensor with I_xy = −∫xy dm; positive semi-definite, triangle inequality");
        list point_mass: PointMassFile = key("array of tables", "–", "none", "", "point masses rigidly attached: `[[body.point_mass]]`");
        list rotor: RotorFile = key("array of tables", "–", "none", "", "wheels spinning inside the body (at most 4): `[[body.rotor]]`");
    }
    either {
        shape, inertia: "give either `shape` or `inertia`, not both";
    }
}

file_table! {
    /// One `[[body.point_mass]]`.
    #[derive(Copy)]
    pub(in crate::scene) struct PointMassFile(pub(super)) "[[body.point_mass]]",
        "a point mass rigidly attached; mass, C and the inertia are then the whole body's (parallel axes)" {
        req mass: f64 = key("number", "kg", "required", "", "> 0");
        arr at: [f64; 3] = position("[0, 0, 0]", "where the mass sits");
    }
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

file_table! {
    /// `body.shape`. Disks and cylinders have their symmetry axis along body z; the thin rod lies along body x.
    #[derive(Copy)]
    pub(in crate::scene) struct ShapeFile(pub(super)) "[body.shape]",
        "a shape of uniform density (disks and cylinders: symmetry axis along body z; the thin rod along body x)" {
        opt kind as "type": ShapeKind = key("\"thin_disk\" | \"disk\" | \"thin_rod\" | \"sphere\" | \"box\" | \"cylinder\"", "–", "required", "", "the shape");
        opt radius: f64 = key("number", "m", "required for disks, cylinder, sphere", "", "> 0");
        opt thickness: f64 = key("number", "m", "required for `disk`", "", "≥ 0");
        opt length: f64 = key("number", "m", "required for `thin_rod`", "", "> 0");
        arr size: [f64; 3] = key("[a, b, c]", "m", "required for `box`", "", "edges along body x, y, z");
        opt height: f64 = key("number", "m", "required for `cylinder`", "", "> 0");
    }
}

file_table! {
    /// `[motion]`.
    #[derive(Copy)]
    pub(in crate::scene) struct MotionFile(pub(super)) "[motion]",
        "absent: free rotation" {
        opt kind as "type": MotionKind = key("\"free\" | \"fixed_axis\" | \"hinge\"", "–", "required in the table", "", "free (no other keys), a prescribed rotation about a fixed axis, or a hinge (θ from the effects)");
        arr axis: [f64; 3] = key("[x, y, z]", "–", "`axis` or `tilt_deg` required", "", "the fixed axis's direction in body axes, normalised; not zero");
        opt tilt_deg: f64 = key("number", "deg", "none", "", "instead of `axis`: axis = (0, −sin tilt, cos tilt)");
        opt rate: f64 = key("number", "rad/s", "0", "", "θ̇ at t = 0");
        opt rate_rpm: f64 = key("number", "rpm", "none", "", "instead of `rate`: rate = rate_rpm · 2π/60");
        opt accel: f64 = key("number", "rad/s²", "0", "", "constant θ̈; fixed axis only");
        arr point: [f64; 3] = position("[0, 0, 0]", "a point of the axis: the moment center");
        opt angle_deg: f64 = key("number", "deg", "0", "", "hinge only: θ at t = 0");
        arr bearings: [f64; 2] = key("[a, b]", "m", "none", "from `point`, along the axis", "positions of bearings A and B, a ≠ b; adds the `R_*` columns");
        arr axis_in_space: [f64; 3] = key("[x, y, z]", "–", "none", "", "the axis's direction in space axes: the attitude at t = 0 puts the body axis on it (instead of `initial.attitude`)");
        /// `carrier`: the axis, its point and its bearings are fixed in a carrier turning in space.
        part carrier: CarrierSpec = key("inline table", "–", "none", "", "the axis turns with a carrier: `[motion.carrier]`");
    }
    either {
        axis, tilt_deg: "give either `axis` or `tilt_deg`, not both";
        rate, rate_rpm: "give either `rate` (rad/s) or `rate_rpm` (revolutions per minute), not both";
    }
    parts {
        /// The capabilities with a table of their own in `[motion]` that modify a fixed axis or hinge (each a
        /// `keys::Part`, registered by its `part` line in `[motion]`'s declaration).
        #[derive(Debug, Clone, Copy, Default, PartialEq)]
        pub struct AxisParts;
    }
}

file_table! {
    /// `[initial]`.
    #[derive(Copy)]
    pub(in crate::scene) struct InitialFile(pub(super)) "[initial]",
        "the state at t = 0" {
        arr omega: [f64; 3] = key("[x, y, z]", "rad/s", "[0, 0, 0]", "", "ω(0) in body axes; free motion only");
        arr attitude: [f64; 4] = key("[w, x, y, z]", "1", "[1, 0, 0, 0]", "", "body → space quaternion, normalised; not zero");
        arr attitude_euler_deg: [f64; 3] = key("[z, y, x]", "deg", "none", "", "instead of `attitude`: intrinsic z-y′-x″ angles, R = R_z R_y′ R_x″");
    }
    either {
        attitude, attitude_euler_deg: "give either `attitude` or `attitude_euler_deg`, not both";
    }
}

file_table! {
    /// `[solver]`.
    #[derive(Copy)]
    pub struct SolverSpec(pub) "[solver]",
        "the integration; `run --method --frame --backend --rtol --atol --dt --t-end` override it" {
        /// Default [`Method::DEFAULT`].
        opt method: Method = key("\"rk4\" | \"split2\" | \"split4\" | \"dopri5\" | \"dop853\" | \"exact\"", "–", "\"dop853\"", "", "fixed step (`dt`), adaptive, or the torque-free closed form");
        /// The form of Euler's equation (default body).
        opt form as "frame": Form = key("\"body\" | \"space\"", "–", "\"body\"", "", "which form of Euler's equation is integrated");
        /// Default own.
        opt backend: Backend = key("\"own\" | \"ode_solvers\"", "–", "\"own\"", "", "the Runge–Kutta implementation");
        /// Default [`crate::method::defaults::RTOL`].
        opt rtol: f64 = key("number", "1", "1e-10", "", "adaptive methods, in [1e-14, 1)");
        /// Default [`crate::method::defaults::ATOL`].
        opt atol: f64 = key("number", "as the state", "1e-12", "", "adaptive methods, > 0");
        /// Default [`crate::method::defaults::DT`] (s).
        opt dt: f64 = key("number", "s", "1e-3", "", "fixed-step methods, > 0");
        /// s, ≥ 0, required.
        req t_end: f64 = key("number", "s", "required", "", "≥ 0");
    }
}

file_table! {
    /// `[output]`.
    #[derive(Copy)]
    pub struct OutputSpec(pub) "[output]",
        "the rows; `run --every` overrides it" {
        /// s between rows, > 0, required.
        req every: f64 = key("number", "s", "required", "", "> 0: rows at t = k·every and at t_end");
    }
}

file_table! {
    /// `[compare]`.
    #[derive(Copy)]
    pub struct CompareSpec(pub) "[compare]",
        "`eulerdyn compare`'s tolerance" {
        /// Largest allowed difference for `eulerdyn compare`.
        req tolerance: f64 = key("number", "as the quantity", "1e-8", "", "largest accepted difference, > 0");
    }
}
