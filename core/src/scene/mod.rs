//! Scenes: a scene as a typed value ([`SceneSpec`], built in code or read from TOML by [`load`] and [`parse`]),
//! its validation ([`SceneSpec::build`]) and the validated [`Scene`] a run needs.

pub mod advice;
mod attributes;
mod facts;
mod file;
mod model;
mod motion;
mod oracle;
pub mod reference;
pub mod source_map;
mod spec;
mod template;
mod user_moment;
mod validate;
mod wheel_law;

pub use attributes::Attribute;
pub use facts::{
    AxisNumbers, BearingNumbers, CheckNumbers, Facts, Invariant, MomentCenter, MotionNumbers,
    StartNumbers,
};
pub use file::parse_toml;
pub use file::{Flags, SceneError, flag_value, load, load_spec, parse, parse_spec, read};
pub use model::{Scene, SceneSource, SolverConfig};
pub use motion::{FreeParts, Motion};
pub use oracle::{ClosedForm, Exact, Oracle};
pub use spec::{
    AttitudeSpec, AxisDirection, AxisParts, AxisSpec, BodySpec, CarrierSpec, CompareSpec,
    ConditionSpec, Direction, Distribution, EffectSpec, EventSpec, Extremum, FixedAxisSpec,
    HingeSpec, InertiaSpec, InitialSpec, MagneticSpec, MotionKind, MotionSpec, OutputSpec,
    PointMassSpec, RateSpec, RotorDrive, RotorSpec, SceneSpec, ShapeSpec, SolverSpec, TorqueSpec,
    TorqueTableSpec, VehicleSpec,
};
pub use template::SceneTemplate;
pub use validate::{InvalidScene, MAX_FIXED_STEPS, MAX_ROWS, Overrides};
