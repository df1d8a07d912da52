//! `[body]`: the mass, a shape or an inertia tensor, and point masses.

use serde::{Deserialize, Serialize};

use crate::profile::Profile;
use crate::wheels::WheelKeys;

/// `body.shape`: a homogeneous shape, `type` and its dimensions (the vocabulary type [`crate::body::Shape`]).
pub type ShapeSpec = crate::body::Shape;

/// `[body]`: the mass, its distribution and the point masses attached.
#[derive(Debug, Clone, PartialEq)]
pub struct BodySpec {
    /// `mass`: kg, > 0 (the shape's or tensor's; point masses add theirs).
    pub mass: f64,
    /// `shape` or `inertia`.
    pub distribution: Distribution,
    /// `[[body.point_mass]]`: point masses rigidly attached.
    pub point_mass: Vec<PointMassSpec>,
    /// `[[body.rotor]]`: wheels spinning inside the body about axes fixed in it. `mass` and the inertia are the
    /// whole body with its wheels locked; a rotor adds only its spin relative to the body.
    pub rotor: Vec<RotorSpec>,
}

/// One `[[body.rotor]]`: a wheel of moment of inertia J about its axis a (fixed in the body), spinning at Ω
/// relative to the body; its momentum adds J Ω a to H (H = I ω + Σ J_k Ω_k a_k).
#[derive(Debug, Clone, PartialEq)]
pub struct RotorSpec {
    /// `name`: the prefix of its columns (absent: `rotor0`, `rotor1`, … in order).
    pub name: Option<String>,
    /// `axis`: spin axis, body axes (normalised by validation).
    pub axis: [f64; 3],
    /// `inertia`: J, kg·m², > 0.
    pub inertia: f64,
    /// `spin`: Ω at t = 0 relative to the body (rad/s; absent: 0).
    pub spin: f64,
    /// What drives it.
    pub drive: RotorDrive,
    /// `at`: the wheel's centre from the reference origin, body axes (m; absent: the origin).
    pub at: [f64; 3],
    /// `imbalance_static_gmm`: the static imbalance m·e (g·mm, ≥ 0; absent: 0).
    pub imbalance_static_gmm: f64,
    /// `imbalance_dynamic_gmm2`: the dynamic imbalance (g·mm², ≥ 0; absent: 0).
    pub imbalance_dynamic_gmm2: f64,
    /// `max_torque`, `max_speed_rpm`, `friction`: the wheel's limits and friction ([`crate::wheels`]).
    pub wheel: WheelKeys,
}

/// What drives a rotor's relative spin.
#[derive(Debug, Clone, PartialEq)]
pub enum RotorDrive {
    /// Neither `spin_accel` nor `torque`: the relative spin stays constant (the motor supplies what that takes).
    ConstantSpin,
    /// `spin_accel`: Ω(t) = spin + spin_accel·t (rad/s²); the motor torque is an output.
    SpinAccel(f64),
    /// `torque` (N·m) with a torque effect's `profile`: the motor torque on the wheel about its axis; the body
    /// feels its opposite.
    Torque {
        /// τ (N·m).
        value: f64,
        /// Its time profile.
        profile: Profile,
    },
    /// `torque_table`: the motor torque commanded by a table (header `t,torque`), relative to the scene file.
    Table(std::path::PathBuf),
    /// `mode = "free"`: no motor, the wheel spins freely (friction only).
    Free,
}

/// How the body's mass is distributed: `shape` or `inertia` (exactly one of them).
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Distribution {
    /// `shape`: uniform density; the reference origin is the shape's center.
    Shape(ShapeSpec),
    /// `inertia`: the tensor about C in body axes; the reference origin is C.
    Inertia(InertiaSpec),
}

/// `body.inertia`: principal moments, or the full symmetric tensor.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(
    untagged,
    expecting = "principal moments [I1, I2, I3] or a full tensor [[Ixx, Ixy, Ixz], [Ixy, Iyy, Iyz], [Ixz, Iyz, Izz]] (kg*m^2)"
)]
pub enum InertiaSpec {
    /// [I1, I2, I3]: body axes are principal axes.
    Principal([f64; 3]),
    /// [[Ixx, Ixy, Ixz], [Ixy, Iyy, Iyz], [Ixz, Iyz, Izz]]: the products of inertia with their minus sign,
    /// I_xy = −∫xy dm.
    Full([[f64; 3]; 3]),
}

/// One `[[body.point_mass]]`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PointMassSpec {
    /// kg, > 0.
    pub mass: f64,
    /// Position from the reference origin (the shape's center, or the point the given inertia is about), body
    /// axes (m).
    pub at: [f64; 3],
}

impl BodySpec {
    /// A body of `mass` (kg) and uniform density in the shape `shape`.
    ///
    /// ```
    /// use eulerdyn::scene::{BodySpec, Distribution, ShapeSpec};
    /// let disk = BodySpec::shape(2.0, ShapeSpec::thin_disk(0.3));
    /// assert_eq!(disk.distribution, Distribution::Shape(ShapeSpec::ThinDisk { radius: 0.3 }));
    /// ```
    pub fn shape(mass: f64, shape: ShapeSpec) -> Self {
        Self {
            mass,
            distribution: Distribution::Shape(shape),
            point_mass: Vec::new(),
            rotor: Vec::new(),
        }
    }

    /// A body of `mass` (kg) whose body axes are principal, with moments [I1, I2, I3] (kg·m²) about C.
    ///
    /// ```
    /// use eulerdyn::scene::{BodySpec, Distribution, InertiaSpec};
    /// let body = BodySpec::principal(1.0, [1.0, 2.0, 3.0]);
    /// assert_eq!(body.distribution, Distribution::Inertia(InertiaSpec::Principal([1.0, 2.0, 3.0])));
    /// ```
    pub fn principal(mass: f64, moments: [f64; 3]) -> Self {
        Self {
            mass,
            distribution: Distribution::Inertia(InertiaSpec::Principal(moments)),
            point_mass: Vec::new(),
            rotor: Vec::new(),
        }
    }

    /// A body of `mass` (kg) with the full inertia tensor about C in body axes (kg·m²), products of inertia
    /// with their minus sign (I_xy = −∫xy dm).
    ///
    /// ```
    /// use eulerdyn::scene::{BodySpec, SceneSpec};
    /// let body = BodySpec::tensor(1.0, [[2.0, -0.1, 0.0], [-0.1, 3.0, 0.0], [0.0, 0.0, 4.0]]);
    /// assert!(SceneSpec::new(body, 1.0, 0.5).build().is_ok());
    /// ```
    pub fn tensor(mass: f64, inertia_c_b: [[f64; 3]; 3]) -> Self {
        Self {
            mass,
            distribution: Distribution::Inertia(InertiaSpec::Full(inertia_c_b)),
            point_mass: Vec::new(),
            rotor: Vec::new(),
        }
    }

    /// With a point mass of `mass` (kg) at `at` (m, body axes, from the reference origin).
    ///
    /// ```
    /// use eulerdyn::scene::{BodySpec, ShapeSpec};
    /// let body = BodySpec::shape(1.0, ShapeSpec::sphere(0.1)).with_point_mass(0.01, [0.1, 0.0, 0.0]);
    /// assert_eq!(body.point_mass[0].at, [0.1, 0.0, 0.0]);
    /// ```
    pub fn with_point_mass(mut self, mass: f64, at: [f64; 3]) -> Self {
        self.point_mass.push(PointMassSpec { mass, at });
        self
    }

    /// With a rotor (`[[body.rotor]]`).
    ///
    /// ```
    /// use eulerdyn::scene::{BodySpec, RotorSpec};
    /// let body = BodySpec::principal(10.0, [1.0, 1.0, 2.0]).with_rotor(RotorSpec::new([0.0, 0.0, 1.0], 0.01, 100.0));
    /// assert_eq!(body.rotor[0].spin, 100.0);
    /// ```
    pub fn with_rotor(mut self, rotor: RotorSpec) -> Self {
        self.rotor.push(rotor);
        self
    }

    /// The shape, when the body is given by one.
    pub fn shape_spec(&self) -> Option<&ShapeSpec> {
        match &self.distribution {
            Distribution::Shape(shape) => Some(shape),
            Distribution::Inertia(_) => None,
        }
    }
}

impl RotorSpec {
    /// A wheel of moment of inertia `inertia` (kg·m²) about `axis_b` (body axes) at the reference origin, spinning
    /// at `spin` (rad/s) relative to the body, kept constant.
    ///
    /// ```
    /// use eulerdyn::scene::{RotorDrive, RotorSpec};
    /// let wheel = RotorSpec::new([1.0, 0.0, 0.0], 0.01, 0.0).with_drive(RotorDrive::SpinAccel(2.0));
    /// assert_eq!(wheel.drive, RotorDrive::SpinAccel(2.0));
    /// ```
    pub fn new(axis_b: [f64; 3], inertia: f64, spin: f64) -> Self {
        Self {
            name: None,
            axis: axis_b,
            inertia,
            spin,
            drive: RotorDrive::ConstantSpin,
            at: [0.0; 3],
            imbalance_static_gmm: 0.0,
            imbalance_dynamic_gmm2: 0.0,
            wheel: WheelKeys::default(),
        }
    }

    /// With the static imbalance `static_gmm` (g·mm) and the dynamic imbalance `dynamic_gmm2` (g·mm²) of a wheel
    /// centred at `at` (m, body axes, from the reference origin).
    ///
    /// ```
    /// use eulerdyn::scene::RotorSpec;
    /// let wheel = RotorSpec::new([0.0, 0.0, 1.0], 0.01, 600.0).with_imbalance([0.1, 0.0, 0.0], 2.0, 50.0);
    /// assert_eq!((wheel.imbalance_static_gmm, wheel.imbalance_dynamic_gmm2), (2.0, 50.0));
    /// ```
    pub fn with_imbalance(mut self, at: [f64; 3], static_gmm: f64, dynamic_gmm2: f64) -> Self {
        self.at = at;
        self.imbalance_static_gmm = static_gmm;
        self.imbalance_dynamic_gmm2 = dynamic_gmm2;
        self
    }

    /// With `drive`.
    ///
    /// ```
    /// use eulerdyn::scene::{RotorDrive, RotorSpec};
    /// let wheel = RotorSpec::new([0.0, 0.0, 1.0], 0.01, 0.0).with_drive(RotorDrive::SpinAccel(2.0));
    /// assert_eq!(wheel.drive, RotorDrive::SpinAccel(2.0));
    /// ```
    pub fn with_drive(mut self, drive: RotorDrive) -> Self {
        self.drive = drive;
        self
    }

    /// With the limits and friction `wheel`.
    ///
    /// ```
    /// use eulerdyn::scene::RotorSpec;
    /// use eulerdyn::wheels::WheelKeys;
    /// let limits = WheelKeys { max_torque: Some(0.05), ..WheelKeys::default() };
    /// let wheel = RotorSpec::new([0.0, 0.0, 1.0], 0.01, 0.0).with_wheel(limits.clone());
    /// assert_eq!(wheel.wheel, limits);
    /// ```
    pub fn with_wheel(mut self, wheel: WheelKeys) -> Self {
        self.wheel = wheel;
        self
    }

    /// With `name`.
    ///
    /// ```
    /// use eulerdyn::scene::RotorSpec;
    /// let wheel = RotorSpec::new([0.0, 0.0, 1.0], 0.01, 0.0).with_name("wheel_z");
    /// assert_eq!(wheel.name.as_deref(), Some("wheel_z"));
    /// ```
    pub fn with_name(mut self, name: &str) -> Self {
        self.name = Some(name.to_string());
        self
    }
}
