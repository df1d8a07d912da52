//! A scene as a typed value: what a scene file says, key for key. TOML is one way to write it
//! ([`crate::scene::parse`]); Rust code builds it with the constructors below. [`SceneSpec::build`] runs the
//! validation that every front end shares and gives a [`Scene`](crate::scene::Scene).
//!
//! Optional keys are `Option`s (absent means the documented default); tables whose keys depend on a `type`
//! (shape, motion, effect) are one flat struct each, so that every key of the file has one field.

use serde::de::Error as _;
use serde::{Deserialize, Deserializer, Serialize};

use crate::frames::{Axes, Form};
use crate::method::{Backend, Method};

/// A whole scene, as a scene file writes it.
#[derive(Debug, Clone, Default, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct SceneSpec {
    /// `name`.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub name: Option<String>,
    /// `description`.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub description: Option<String>,
    /// `[body]`.
    pub body: BodySpec,
    /// `[motion]`; absent: free rotation.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub motion: Option<MotionSpec>,
    /// `[initial]`.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub initial: Option<InitialSpec>,
    /// `[[effect]]`, in order; none: torque-free.
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub effect: Vec<EffectSpec>,
    /// `[solver]`.
    pub solver: SolverSpec,
    /// `[output]`.
    pub output: OutputSpec,
    /// `[compare]`.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub compare: Option<CompareSpec>,
}

/// `[body]`: the mass and either a shape or an inertia tensor about C.
#[derive(Debug, Clone, Default, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct BodySpec {
    /// kg, > 0.
    pub mass: f64,
    /// A shape of uniform density.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub shape: Option<ShapeSpec>,
    /// The inertia about C in body axes (kg·m²), instead of a shape.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub inertia: Option<InertiaSpec>,
    /// `[[body.point_mass]]`: point masses rigidly attached.
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub point_mass: Vec<PointMassSpec>,
}

/// One `[[body.point_mass]]`.
#[derive(Debug, Clone, Copy, Default, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct PointMassSpec {
    /// kg, > 0.
    pub mass: f64,
    /// Position from the reference origin (the shape's center, or the point the given inertia is about), body
    /// axes (m).
    #[serde(
        default,
        deserialize_with = "exactly_n",
        skip_serializing_if = "Option::is_none"
    )]
    pub at: Option<[f64; 3]>,
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
    /// [[Ixx, Ixy, Ixz], [Ixy, Iyy, Iyz], [Ixz, Iyz, Izz]].
    Full([[f64; 3]; 3]),
}

/// The `type` of a shape.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum ShapeKind {
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
pub struct ShapeSpec {
    /// `type`.
    #[serde(rename = "type", skip_serializing_if = "Option::is_none")]
    pub kind: Option<ShapeKind>,
    /// m.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub radius: Option<f64>,
    /// m.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub thickness: Option<f64>,
    /// m.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub length: Option<f64>,
    /// [x, y, z], m.
    #[serde(
        default,
        deserialize_with = "exactly_n",
        skip_serializing_if = "Option::is_none"
    )]
    pub size: Option<[f64; 3]>,
    /// m.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub height: Option<f64>,
}

/// The `type` of a motion.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum MotionKind {
    Free,
    FixedAxis,
    Hinge,
}

/// `[motion]`.
#[derive(Debug, Clone, Copy, Default, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct MotionSpec {
    /// `type`.
    #[serde(rename = "type", skip_serializing_if = "Option::is_none")]
    pub kind: Option<MotionKind>,
    /// The axis in body axes (normalised by validation).
    #[serde(
        default,
        deserialize_with = "exactly_n",
        skip_serializing_if = "Option::is_none"
    )]
    pub axis: Option<[f64; 3]>,
    /// Shorthand for the axis (0, −sin, cos) of the tilt, degrees.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub tilt_deg: Option<f64>,
    /// rad/s at t = 0.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub rate: Option<f64>,
    /// The same in revolutions per minute, instead of `rate` (rate = rate_rpm · 2π/60).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub rate_rpm: Option<f64>,
    /// rad/s², constant.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub accel: Option<f64>,
    /// A point on the axis, body axes, relative to C (m).
    #[serde(
        default,
        deserialize_with = "exactly_n",
        skip_serializing_if = "Option::is_none"
    )]
    pub point: Option<[f64; 3]>,
    /// θ at t = 0 (degrees), hinge only.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub angle_deg: Option<f64>,
    /// Axial positions [a, b] of bearings A and B from `point` along the axis (m), a ≠ b.
    #[serde(
        default,
        deserialize_with = "exactly_n",
        skip_serializing_if = "Option::is_none"
    )]
    pub bearings: Option<[f64; 2]>,
    /// The axis's direction in space axes: the attitude at t = 0 is then the smallest rotation that puts the body
    /// axis on it (instead of `initial.attitude`).
    #[serde(
        default,
        deserialize_with = "exactly_n",
        skip_serializing_if = "Option::is_none"
    )]
    pub axis_in_space: Option<[f64; 3]>,
}

/// `[initial]`.
#[derive(Debug, Clone, Copy, Default, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct InitialSpec {
    /// rad/s, body axes.
    #[serde(
        default,
        deserialize_with = "exactly_n",
        skip_serializing_if = "Option::is_none"
    )]
    pub omega: Option<[f64; 3]>,
    /// [w, x, y, z], body → space (normalised by validation).
    #[serde(
        default,
        deserialize_with = "exactly_n",
        skip_serializing_if = "Option::is_none"
    )]
    pub attitude: Option<[f64; 4]>,
    /// The attitude as intrinsic z-y'-x'' angles [z, y, x] in degrees (instead of `attitude`).
    #[serde(
        default,
        deserialize_with = "exactly_n",
        skip_serializing_if = "Option::is_none"
    )]
    pub attitude_euler_deg: Option<[f64; 3]>,
}

/// The `type` of an effect.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum EffectKind {
    Torque,
    Gravity,
    Damping,
}

/// The `profile` of a torque.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum ProfileKind {
    Constant,
    Sine,
    Step,
}

/// One `[[effect]]`.
#[derive(Debug, Clone, Copy, Default, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct EffectSpec {
    /// `type`.
    #[serde(rename = "type", skip_serializing_if = "Option::is_none")]
    pub kind: Option<EffectKind>,
    /// The axes a torque's value is given in (default body).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub frame: Option<Axes>,
    /// N·m.
    #[serde(
        default,
        deserialize_with = "exactly_n",
        skip_serializing_if = "Option::is_none"
    )]
    pub value: Option<[f64; 3]>,
    /// Default constant.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub profile: Option<ProfileKind>,
    /// Hz (sine).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub freq_hz: Option<f64>,
    /// Degrees (sine).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub phase_deg: Option<f64>,
    /// s (step).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub t_on: Option<f64>,
    /// s (step).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub t_off: Option<f64>,
    /// m/s², space axes (gravity; default (0, 0, −9.81)).
    #[serde(
        default,
        deserialize_with = "exactly_n",
        skip_serializing_if = "Option::is_none"
    )]
    pub g: Option<[f64; 3]>,
    /// The fixed point, body axes, relative to C (m) (gravity).
    #[serde(
        default,
        deserialize_with = "exactly_n",
        skip_serializing_if = "Option::is_none"
    )]
    pub pivot: Option<[f64; 3]>,
    /// N·m·s (damping).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub c: Option<f64>,
}

/// `[solver]`.
#[derive(Debug, Clone, Copy, Default, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct SolverSpec {
    /// Default [`Method::DEFAULT`].
    #[serde(skip_serializing_if = "Option::is_none")]
    pub method: Option<Method>,
    /// The form of Euler's equation (default body).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub frame: Option<Form>,
    /// Default own.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub backend: Option<Backend>,
    /// Default [`crate::method::defaults::RTOL`].
    #[serde(skip_serializing_if = "Option::is_none")]
    pub rtol: Option<f64>,
    /// Default [`crate::method::defaults::ATOL`].
    #[serde(skip_serializing_if = "Option::is_none")]
    pub atol: Option<f64>,
    /// Default [`crate::method::defaults::DT`] (s).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub dt: Option<f64>,
    /// s, ≥ 0, required.
    pub t_end: f64,
}

/// `[output]`.
#[derive(Debug, Clone, Copy, Default, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct OutputSpec {
    /// s between rows, > 0, required.
    pub every: f64,
}

/// `[compare]`.
#[derive(Debug, Clone, Copy, Default, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct CompareSpec {
    /// Largest allowed difference for `eulerdyn compare`.
    pub tolerance: f64,
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
        Self {
            body,
            solver: SolverSpec {
                t_end,
                ..SolverSpec::default()
            },
            output: OutputSpec { every },
            ..Self::default()
        }
    }

    /// With `name`.
    pub fn with_name(mut self, name: &str) -> Self {
        self.name = Some(name.to_string());
        self
    }

    /// With the `[motion]` table.
    pub fn with_motion(mut self, motion: MotionSpec) -> Self {
        self.motion = Some(motion);
        self
    }

    /// With `initial.omega` (rad/s, body axes).
    pub fn with_omega(mut self, omega_b: [f64; 3]) -> Self {
        self.initial.get_or_insert_with(InitialSpec::default).omega = Some(omega_b);
        self
    }

    /// With `initial.attitude` ([w, x, y, z], body → space).
    pub fn with_attitude(mut self, q_sb: [f64; 4]) -> Self {
        self.initial
            .get_or_insert_with(InitialSpec::default)
            .attitude = Some(q_sb);
        self
    }

    /// With one more `[[effect]]`.
    pub fn with_effect(mut self, effect: EffectSpec) -> Self {
        self.effect.push(effect);
        self
    }

    /// With `solver.method`.
    pub fn with_method(mut self, method: Method) -> Self {
        self.solver.method = Some(method);
        self
    }

    /// With `solver.frame`: the form of Euler's equation.
    pub fn with_form(mut self, form: Form) -> Self {
        self.solver.frame = Some(form);
        self
    }

    /// With `solver.rtol` and `solver.atol`.
    pub fn with_tolerances(mut self, rtol: f64, atol: f64) -> Self {
        self.solver.rtol = Some(rtol);
        self.solver.atol = Some(atol);
        self
    }

    /// With `solver.dt` (s).
    pub fn with_dt(mut self, dt: f64) -> Self {
        self.solver.dt = Some(dt);
        self
    }
}

impl BodySpec {
    /// A body of `mass` (kg) and uniform density in the shape `shape`.
    ///
    /// ```
    /// use eulerdyn::scene::{BodySpec, ShapeSpec};
    /// let disk = BodySpec::shape(2.0, ShapeSpec::thin_disk(0.3));
    /// assert_eq!(disk.shape.unwrap().radius, Some(0.3));
    /// ```
    pub fn shape(mass: f64, shape: ShapeSpec) -> Self {
        Self {
            mass,
            shape: Some(shape),
            inertia: None,
            point_mass: Vec::new(),
        }
    }

    /// A body of `mass` (kg) whose body axes are principal, with moments [I1, I2, I3] (kg·m²) about C.
    pub fn principal(mass: f64, moments: [f64; 3]) -> Self {
        Self {
            mass,
            shape: None,
            inertia: Some(InertiaSpec::Principal(moments)),
            point_mass: Vec::new(),
        }
    }

    /// A body of `mass` (kg) with the full inertia tensor about C in body axes (kg·m²).
    pub fn tensor(mass: f64, inertia_c_b: [[f64; 3]; 3]) -> Self {
        Self {
            mass,
            shape: None,
            inertia: Some(InertiaSpec::Full(inertia_c_b)),
            point_mass: Vec::new(),
        }
    }

    /// With a point mass of `mass` (kg) at `at` (m, body axes, from the reference origin).
    pub fn with_point_mass(mut self, mass: f64, at: [f64; 3]) -> Self {
        self.point_mass.push(PointMassSpec { mass, at: Some(at) });
        self
    }
}

impl ShapeSpec {
    fn of(kind: ShapeKind) -> Self {
        Self {
            kind: Some(kind),
            ..Self::default()
        }
    }

    /// A thin disk of `radius` (m), symmetry axis along body z.
    pub fn thin_disk(radius: f64) -> Self {
        Self {
            radius: Some(radius),
            ..Self::of(ShapeKind::ThinDisk)
        }
    }

    /// A disk of `radius` and `thickness` (m), symmetry axis along body z.
    pub fn disk(radius: f64, thickness: f64) -> Self {
        Self {
            radius: Some(radius),
            thickness: Some(thickness),
            ..Self::of(ShapeKind::Disk)
        }
    }

    /// A thin rod of `length` (m) along body x.
    pub fn thin_rod(length: f64) -> Self {
        Self {
            length: Some(length),
            ..Self::of(ShapeKind::ThinRod)
        }
    }

    /// A sphere of `radius` (m).
    pub fn sphere(radius: f64) -> Self {
        Self {
            radius: Some(radius),
            ..Self::of(ShapeKind::Sphere)
        }
    }

    /// A rectangular box of edges `size` = [x, y, z] (m) along the body axes.
    pub fn cuboid(size: [f64; 3]) -> Self {
        Self {
            size: Some(size),
            ..Self::of(ShapeKind::Box)
        }
    }

    /// A solid cylinder of `radius` and `height` (m), symmetry axis along body z.
    pub fn cylinder(radius: f64, height: f64) -> Self {
        Self {
            radius: Some(radius),
            height: Some(height),
            ..Self::of(ShapeKind::Cylinder)
        }
    }
}

impl MotionSpec {
    /// Free rotation from `[initial]` (the same as no `[motion]` table).
    pub fn free() -> Self {
        Self {
            kind: Some(MotionKind::Free),
            ..Self::default()
        }
    }

    /// Prescribed rotation at `rate` (rad/s) about `axis_b`, a direction in body axes through C.
    pub fn fixed_axis(axis_b: [f64; 3], rate: f64) -> Self {
        Self {
            kind: Some(MotionKind::FixedAxis),
            axis: Some(axis_b),
            rate: Some(rate),
            ..Self::default()
        }
    }

    /// Prescribed rotation at `rate` (rad/s) about the axis (0, −sin θ, cos θ) tilted `tilt_deg` from body z.
    ///
    /// ```
    /// use eulerdyn::scene::MotionSpec;
    /// let m = MotionSpec::fixed_axis_tilted(30.0, 10.0).with_accel(1.0);
    /// assert_eq!((m.tilt_deg, m.rate, m.accel), (Some(30.0), Some(10.0), Some(1.0)));
    /// ```
    pub fn fixed_axis_tilted(tilt_deg: f64, rate: f64) -> Self {
        Self {
            kind: Some(MotionKind::FixedAxis),
            tilt_deg: Some(tilt_deg),
            rate: Some(rate),
            ..Self::default()
        }
    }

    /// A hinge: rotation about the axis (0, −sin θ, cos θ) tilted `tilt_deg` from body z, not prescribed: θ
    /// follows from the effects' moment about the axis, starting at `rate` (rad/s).
    pub fn hinge_tilted(tilt_deg: f64, rate: f64) -> Self {
        Self {
            kind: Some(MotionKind::Hinge),
            ..Self::fixed_axis_tilted(tilt_deg, rate)
        }
    }

    /// A hinge about `axis_b` (body axes), starting at `rate` (rad/s).
    pub fn hinge(axis_b: [f64; 3], rate: f64) -> Self {
        Self {
            kind: Some(MotionKind::Hinge),
            ..Self::fixed_axis(axis_b, rate)
        }
    }

    /// With bearings A and B at `a` and `b` metres from the axis point along the axis.
    pub fn with_bearings(mut self, a: f64, b: f64) -> Self {
        self.bearings = Some([a, b]);
        self
    }

    /// With θ = `angle_deg` at t = 0 (a hinge).
    pub fn with_angle_deg(mut self, angle_deg: f64) -> Self {
        self.angle_deg = Some(angle_deg);
        self
    }

    /// With a constant angular acceleration (rad/s²).
    pub fn with_accel(mut self, accel: f64) -> Self {
        self.accel = Some(accel);
        self
    }

    /// With the axis through `point_b` (body axes, relative to C, m), the moment center.
    pub fn with_point(mut self, point_b: [f64; 3]) -> Self {
        self.point = Some(point_b);
        self
    }
}

impl EffectSpec {
    fn of(kind: EffectKind) -> Self {
        Self {
            kind: Some(kind),
            ..Self::default()
        }
    }

    /// A constant torque `value` (N·m) in `axes`.
    pub fn torque(axes: Axes, value: [f64; 3]) -> Self {
        Self {
            frame: Some(axes),
            value: Some(value),
            ..Self::of(EffectKind::Torque)
        }
    }

    /// This torque times sin(2π f t + φ), f = `freq_hz`, φ = `phase_deg`.
    pub fn sine(mut self, freq_hz: f64, phase_deg: f64) -> Self {
        self.profile = Some(ProfileKind::Sine);
        self.freq_hz = Some(freq_hz);
        self.phase_deg = Some(phase_deg);
        self
    }

    /// This torque for t_on ≤ t < t_off only.
    pub fn step(mut self, t_on: f64, t_off: f64) -> Self {
        self.profile = Some(ProfileKind::Step);
        self.t_on = Some(t_on);
        self.t_off = Some(t_off);
        self
    }

    /// Uniform gravity `g_s` (m/s², space axes) acting at C, the body turning about `pivot_b` (body axes,
    /// relative to C, m).
    pub fn gravity(g_s: [f64; 3], pivot_b: [f64; 3]) -> Self {
        Self {
            g: Some(g_s),
            pivot: Some(pivot_b),
            ..Self::of(EffectKind::Gravity)
        }
    }

    /// Uniform gravity `g_s` (m/s², space axes) acting at C of a body on a fixed axis or hinge, whose axis point
    /// is the moment center (no pivot).
    pub fn weight(g_s: [f64; 3]) -> Self {
        Self {
            g: Some(g_s),
            ..Self::of(EffectKind::Gravity)
        }
    }

    /// Viscous damping M = −c ω, `c` in N·m·s.
    pub fn damping(c: f64) -> Self {
        Self {
            c: Some(c),
            ..Self::of(EffectKind::Damping)
        }
    }
}
