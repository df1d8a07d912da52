//! The scene file's own tables (a capability declares its table in its folder): one flat struct per table, every
//! optional key an `Option` (absent means the documented default), so that serde reads any file and the reading can
//! name the key at fault — its messages (key, line and column) would be lost inside serde's internally tagged enums.
//! The top level, `[body]` and `[initial]` declare their typed specs here too ([`SceneSpec`], [`BodySpec`],
//! [`InitialSpec`]: read and written key for key, a capability's table by its one `each`/`maybe`/`one` line;
//! `from_file.rs` has the rest); `[solver]`, `[output]` and `[compare]` have no keys that depend on another, so
//! their tables are their typed specs.

use super::{AttitudeSpec, Distribution, InertiaSpec, ShapeSpec};
use crate::effects::EffectSpec;
use crate::events::EventSpec;
use crate::frames::Form;
use crate::keys::{file_table, key, position};
use crate::method::{Backend, Method};
use crate::motion::spec::MotionSpec;
use crate::wheels::RotorSpec;

file_table! {
    /// A whole scene, as a scene file writes it.
    pub(crate) struct SceneFile(pub(super)) "",
        "the top level of the file" {
        /// `name`.
        opt name: String = key("string", "–", "\"\"", "", "shown by `check` and in plot titles");
        /// `description`.
        opt description: String = key("string", "–", "\"\"", "", "one line, shown by `check`");
        /// `[body]`.
        one body: BodySpec = key("table", "–", "required", "", "the body: `[body]`");
        /// `[motion]`; absent: free rotation.
        maybe motion: MotionSpec = key("table", "–", "free rotation", "", "the motion: `[motion]`");
        /// `[initial]`.
        maybe initial: InitialSpec = key("table", "–", "at rest, identity attitude", "", "the state at t = 0: `[initial]`");
        /// `[[effect]]`, in order; none: torque-free.
        each effect: EffectSpec = key("array of tables", "–", "none: torque-free", "", "the moments applied: `[[effect]]`");
        /// `[[event]]`, in order; none: no events are located.
        each event: EventSpec = key("array of tables", "–", "none", "", "moments to locate between rows: `[[event]]`");
        /// `[solver]`.
        req solver: SolverSpec = key("table", "–", "required", "", "the integration: `[solver]`").holding(&SolverSpec::TABLE);
        /// `[output]`.
        req output: OutputSpec = key("table", "–", "required", "", "the rows written: `[output]`").holding(&OutputSpec::TABLE);
        /// `[compare]`.
        opt compare: CompareSpec = key("table", "–", "tolerance 1e-8", "", "what `eulerdyn compare` accepts: `[compare]`").holding(&CompareSpec::TABLE);
    }
    spec {
        /// A whole scene. Serde reads and writes it as a scene file writes it (TOML, or the same keys in JSON).
        #[derive(Debug, Clone, PartialEq)]
        pub struct SceneSpec;
    }
}

file_table! {
    /// `[body]`: the mass and either a shape or an inertia tensor about C.
    pub(crate) struct BodyFile(pub(super)) "[body]",
        "the rigid body: its mass and either a shape or an inertia tensor" {
        /// `mass`: kg, > 0 (the shape's or tensor's; point masses add theirs).
        req mass: f64 = key("number", "kg", "required", "", "> 0");
        /// `shape` or `inertia`.
        group distribution: Distribution {
            opt shape: ShapeFile = key("inline table", "–", "one of `shape` / `inertia`", "", "a homogeneous shape: `[body.shape]`").holding(&ShapeFile::TABLE);
            opt inertia: InertiaSpec = key("[I1, I2, I3] or 3×3 array", "kg·m²", "one of `shape` / `inertia`", "", "about C in body axes: principal moments, or the symmetric tensor with I_xy = −∫xy dm; positive semi-definite, triangle inequality");
        }
        /// `[[body.point_mass]]`: point masses rigidly attached.
        each point_mass: PointMassSpec = key("array of tables", "–", "none", "", "point masses rigidly attached: `[[body.point_mass]]`");
        /// `[[body.rotor]]`: wheels spinning inside the body about axes fixed in it. `mass` and the inertia are the
        /// whole body with its wheels locked; a rotor adds only its spin relative to the body.
        each rotor: RotorSpec = key("array of tables", "–", "none", "", "wheels spinning inside the body (at most 4): `[[body.rotor]]`");
    }
    either {
        shape, inertia: "give either `shape` or `inertia`, not both";
    }
    spec {
        /// `[body]`: the mass, its distribution and the point masses attached.
        #[derive(Debug, Clone, PartialEq)]
        pub struct BodySpec;
    }
}

file_table! {
    /// One `[[body.point_mass]]`.
    #[derive(Copy)]
    pub(crate) struct PointMassFile(pub(super)) "[[body.point_mass]]",
        "a point mass rigidly attached; mass, C and the inertia are then the whole body's (parallel axes)" {
        /// kg, > 0.
        req mass: f64 = key("number", "kg", "required", "", "> 0");
        /// Position from the reference origin (the shape's center, or the point the given inertia is about), body
        /// axes (m).
        arr(required) at: [f64; 3] = position("required", "where the mass sits");
    }
    spec {
        /// One `[[body.point_mass]]`.
        #[derive(Debug, Clone, Copy, PartialEq)]
        pub struct PointMassSpec("a point mass");
    }
}

file_table! {
    /// `body.shape`. Disks and cylinders have their symmetry axis along body z; the thin rod lies along body x.
    #[derive(Copy)]
    pub(crate) struct ShapeFile(pub(super)) "[body.shape]",
        "a shape of uniform density (disks and cylinders: symmetry axis along body z; the thin rod along body x)" {
        opt kind as "type": ShapeKind = key(ShapeKind::CHOICES, "–", "required", "", "the shape");
        opt radius: f64 = key("number", "m", "required for disks, cylinder, sphere", "", "> 0");
        opt thickness: f64 = key("number", "m", "required for `disk`", "", "≥ 0");
        opt length: f64 = key("number", "m", "required for `thin_rod`", "", "> 0");
        arr size: [f64; 3] = key("[a, b, c]", "m", "required for `box`", "", "edges along body x, y, z");
        opt height: f64 = key("number", "m", "required for `cylinder`", "", "> 0");
    }
    kinds {
        /// The `type` of a shape.
        pub(crate) enum ShapeKind("shape type", "missing: the shape needs `type` = \"thin_disk\" | \"disk\" | \"thin_rod\" | \"sphere\" | \"box\" | \"cylinder\"") for ShapeSpec {
            ThinDisk = "thin_disk": [radius];
            Disk = "disk": [radius, thickness];
            ThinRod = "thin_rod": [length];
            Sphere = "sphere": [radius];
            Box = "box": [size];
            Cylinder = "cylinder": [radius, height];
        }
    }
}

file_table! {
    /// `[initial]`.
    #[derive(Copy)]
    pub(crate) struct InitialFile(pub(super)) "[initial]",
        "the state at t = 0" {
        /// `omega`: rad/s, body axes.
        arr omega: [f64; 3] = key("[x, y, z]", "rad/s", "[0, 0, 0]", "", "ω(0) in body axes; free motion only");
        /// `attitude` or `attitude_euler_deg`; absent: the identity (or what the motion's `axis_in_space` sets).
        group attitude: Option<AttitudeSpec> {
            arr attitude: [f64; 4] = key("[w, x, y, z]", "1", "[1, 0, 0, 0]", "", "body → space quaternion, normalised; not zero");
            arr attitude_euler_deg: [f64; 3] = key("[z, y, x]", "deg", "none", "", "instead of `attitude`: intrinsic z-y′-x″ angles, R = R_z R_y′ R_x″");
        }
    }
    either {
        attitude, attitude_euler_deg => AttitudeSpec::{Quaternion, EulerDeg}: "give either `attitude` or `attitude_euler_deg`, not both";
    }
    spec {
        /// `[initial]`.
        #[derive(Debug, Clone, Copy, Default, PartialEq)]
        pub struct InitialSpec;
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
