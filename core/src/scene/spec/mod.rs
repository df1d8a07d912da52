//! A scene as a typed value: what a scene file says, with each table whose keys depend on a `type` (shape, motion,
//! effect, a torque's profile) an enum whose variants hold exactly that type's keys — a wrong combination does not
//! compile. TOML is one way to write it ([`crate::scene::parse`]); Rust code builds it with the constructors below.
//! [`SceneSpec::build`] runs the validation that every front end shares and gives a [`Scene`](crate::scene::Scene).
//!
//! Serde reads and writes a `SceneSpec` in the scene file's form (`file_form.rs`: one flat table per `[section]`,
//! key for key, which declares `SceneSpec`, `BodySpec`, `InitialSpec` and `PointMassSpec` with it), read and written as a
//! `keys::Part`; a reading names the key at fault when a table is not one of its type's.

mod body;
pub(in crate::scene) mod file_form;
mod from_file;

use serde::{Deserialize, Deserializer, Serialize, Serializer};

use crate::frames::Form;
use crate::keys::{KeyPath, Part};
use crate::method::Method;

pub use crate::effects::{EffectSpec, MagneticSpec, TorqueSpec, TorqueTableSpec};
pub use crate::events::{ConditionSpec, Direction, EventSpec, Extremum};
pub use crate::motion::spec::{
    AxisDirection, AxisParts, AxisSpec, CarrierSpec, FixedAxisSpec, HingeSpec, MotionKind,
    MotionSpec, RateSpec, VehicleSpec,
};
pub use crate::wheels::{RotorDrive, RotorSpec};
pub use body::{Distribution, InertiaSpec, ShapeSpec};
pub(in crate::scene) use file_form::SceneFile;
pub use file_form::{
    BodySpec, CompareSpec, InitialSpec, OutputSpec, PointMassSpec, SceneSpec, SolverSpec,
};

/// The attitude at t = 0, body → space.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum AttitudeSpec {
    /// `attitude = [w, x, y, z]` (normalised by validation).
    Quaternion([f64; 4]),
    /// `attitude_euler_deg = [z, y, x]`: intrinsic z-y'-x'' angles in degrees.
    EulerDeg([f64; 3]),
    /// `attitude_lvlh_deg = [roll, pitch, yaw]`: 3-2-1 angles in degrees from the LVLH frame of the scene's orbit
    /// at t = 0.
    LvlhDeg([f64; 3]),
}

impl Serialize for SceneSpec {
    fn serialize<S: Serializer>(&self, serializer: S) -> Result<S::Ok, S::Error> {
        self.write().serialize(serializer)
    }
}

impl<'de> Deserialize<'de> for SceneSpec {
    /// Reads the scene file's form; a table that is not one of its type's is an error naming the key
    /// ("key `effect[0].c`: effect type = \"torque\" takes no `c`; …").
    fn deserialize<D: Deserializer<'de>>(deserializer: D) -> Result<Self, D::Error> {
        let file = SceneFile::deserialize(deserializer)?;
        SceneSpec::read(&file, &KeyPath::root()).map_err(serde::de::Error::custom)
    }
}

impl SceneSpec {
    /// A torque-free scene of `body` from rest, run to `t_end` (s) with rows every `every` (s); the rest as the
    /// scene format's defaults.
    ///
    /// ```
    /// use eulerdyn::scene::{BodySpec, SceneSpec};
    /// let spec = SceneSpec::new(BodySpec::principal(1.0, [1.0, 2.0, 3.0]), 10.0, 0.1)
    ///     .with_omega([0.1, 2.0, 0.0]);
    /// let scene = spec.build().unwrap();
    /// assert_eq!(scene.schedule.len(), 101);
    /// ```
    pub fn new(body: BodySpec, t_end: f64, every: f64) -> Self {
        let solver = SolverSpec {
            t_end,
            ..SolverSpec::default()
        };
        Self::of(body, solver, OutputSpec { every })
    }

    /// With `name`.
    ///
    /// ```
    /// use eulerdyn::scene::{BodySpec, SceneSpec};
    /// let spec = SceneSpec::new(BodySpec::principal(1.0, [1.0, 2.0, 3.0]), 1.0, 0.1).with_name("box");
    /// assert_eq!(spec.build().unwrap().name, "box");
    /// ```
    pub fn with_name(mut self, name: &str) -> Self {
        self.name = Some(name.to_string());
        self
    }

    /// With the `[motion]` table: a [`FixedAxisSpec`], a [`HingeSpec`] or [`MotionSpec::Free`].
    ///
    /// ```
    /// use eulerdyn::scene::{BodySpec, FixedAxisSpec, MotionKind, SceneSpec, ShapeSpec};
    /// let body = BodySpec::shape(2.0, ShapeSpec::thin_disk(0.3));
    /// let scene = SceneSpec::new(body, 1.0, 0.1).with_motion(FixedAxisSpec::tilted(30.0, 10.0)).build().unwrap();
    /// assert_eq!(scene.motion.kind(), MotionKind::FixedAxis);
    /// ```
    pub fn with_motion(mut self, motion: impl Into<MotionSpec>) -> Self {
        self.motion = Some(motion.into());
        self
    }

    /// With `initial.omega` (rad/s, body axes).
    ///
    /// ```
    /// use eulerdyn::scene::{BodySpec, SceneSpec};
    /// let spec = SceneSpec::new(BodySpec::principal(1.0, [1.0, 2.0, 3.0]), 1.0, 0.1).with_omega([0.0, 0.0, 5.0]);
    /// assert_eq!(spec.initial.unwrap().omega, Some([0.0, 0.0, 5.0]));
    /// ```
    pub fn with_omega(mut self, omega_b: [f64; 3]) -> Self {
        self.initial.get_or_insert_with(InitialSpec::default).omega = Some(omega_b);
        self
    }

    /// With `initial.attitude` ([w, x, y, z], body → space).
    ///
    /// ```
    /// use eulerdyn::scene::{AttitudeSpec, BodySpec, SceneSpec};
    /// let q = [0.0, 0.0, 0.0, 1.0]; // half a turn about z
    /// let spec = SceneSpec::new(BodySpec::principal(1.0, [1.0, 2.0, 3.0]), 1.0, 0.1).with_attitude(q);
    /// assert_eq!(spec.initial.unwrap().attitude, Some(AttitudeSpec::Quaternion(q)));
    /// ```
    pub fn with_attitude(mut self, q_sb: [f64; 4]) -> Self {
        self.initial
            .get_or_insert_with(InitialSpec::default)
            .attitude = Some(AttitudeSpec::Quaternion(q_sb));
        self
    }

    /// With one more `[[effect]]`: a [`TorqueSpec`], a [`TorqueTableSpec`] or an [`EffectSpec`].
    ///
    /// ```
    /// use eulerdyn::scene::{BodySpec, EffectSpec, SceneSpec};
    /// let spec = SceneSpec::new(BodySpec::principal(1.0, [1.0, 2.0, 3.0]), 1.0, 0.1)
    ///     .with_effect(EffectSpec::damping(0.01));
    /// assert_eq!(spec.effect, [EffectSpec::damping(0.01)]);
    /// ```
    pub fn with_effect(mut self, effect: impl Into<EffectSpec>) -> Self {
        self.effect.push(effect.into());
        self
    }

    /// With one more `[[event]]`.
    ///
    /// ```
    /// use eulerdyn::events::Direction;
    /// use eulerdyn::scene::{BodySpec, EventSpec, SceneSpec};
    /// let flip = EventSpec::crossing("flip", "omega_b_y", 0.0, Direction::Down);
    /// let spec = SceneSpec::new(BodySpec::principal(1.0, [1.0, 2.0, 3.0]), 1.0, 0.1).with_event(flip.clone());
    /// assert_eq!(spec.event, [flip]);
    /// ```
    pub fn with_event(mut self, event: EventSpec) -> Self {
        self.event.push(event);
        self
    }

    /// With `solver.method`.
    ///
    /// ```
    /// use eulerdyn::Method;
    /// use eulerdyn::scene::{BodySpec, SceneSpec};
    /// let spec = SceneSpec::new(BodySpec::principal(1.0, [1.0, 2.0, 3.0]), 1.0, 0.1).with_method(Method::Rk4);
    /// assert_eq!(spec.solver.method, Some(Method::Rk4));
    /// ```
    pub fn with_method(mut self, method: Method) -> Self {
        self.solver.method = Some(method);
        self
    }

    /// With `solver.frame`: the form of Euler's equation.
    ///
    /// ```
    /// use eulerdyn::Form;
    /// use eulerdyn::scene::{BodySpec, SceneSpec};
    /// let spec = SceneSpec::new(BodySpec::principal(1.0, [1.0, 2.0, 3.0]), 1.0, 0.1).with_form(Form::Space);
    /// assert_eq!(spec.solver.form, Some(Form::Space));
    /// ```
    pub fn with_form(mut self, form: Form) -> Self {
        self.solver.form = Some(form);
        self
    }

    /// With `solver.rtol` and `solver.atol`.
    ///
    /// ```
    /// use eulerdyn::scene::{BodySpec, SceneSpec};
    /// let spec = SceneSpec::new(BodySpec::principal(1.0, [1.0, 2.0, 3.0]), 1.0, 0.1).with_tolerances(1e-12, 1e-14);
    /// assert_eq!((spec.solver.rtol, spec.solver.atol), (Some(1e-12), Some(1e-14)));
    /// ```
    pub fn with_tolerances(mut self, rtol: f64, atol: f64) -> Self {
        self.solver.rtol = Some(rtol);
        self.solver.atol = Some(atol);
        self
    }

    /// With `solver.dt` (s).
    ///
    /// ```
    /// use eulerdyn::scene::{BodySpec, SceneSpec};
    /// let spec = SceneSpec::new(BodySpec::principal(1.0, [1.0, 2.0, 3.0]), 1.0, 0.1).with_dt(1e-3);
    /// assert_eq!(spec.solver.dt, Some(1e-3));
    /// ```
    pub fn with_dt(mut self, dt: f64) -> Self {
        self.solver.dt = Some(dt);
        self
    }

    /// The scene with each torque table's relative `file` (an effect's, a wheel's) taken relative to `dir` (a scene
    /// file's directory).
    pub(in crate::scene) fn with_files_in(mut self, dir: &std::path::Path) -> Self {
        self.take_files_in(dir);
        self
    }
}
