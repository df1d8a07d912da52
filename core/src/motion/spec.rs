//! `[motion]` as a typed value: free rotation, a prescribed rotation about a fixed axis, or a hinge driven by the
//! effects (its keys: `motion/keys.rs`).

pub use super::carrier::spec::{CarrierSpec, VehicleSpec};
pub use super::choices::{AxisDirection, RateSpec};
pub use super::keys::{AxisParts, MotionKind};

/// `[motion]`, by its `type`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum MotionSpec {
    /// `type = "free"`: free rotation from `[initial]` (the same as no `[motion]` table).
    Free,
    /// `type = "fixed_axis"`: rotation about a fixed axis at a prescribed rate.
    FixedAxis(FixedAxisSpec),
    /// `type = "hinge"`: rotation about a fixed axis, θ̈ from the effects' moment about it.
    Hinge(HingeSpec),
}

/// The axis of a fixed-axis or hinge motion: the keys both take.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct AxisSpec {
    /// `axis` or `tilt_deg`.
    pub direction: AxisDirection,
    /// θ̇ at t = 0: `rate` or `rate_rpm` (absent: 0 rad/s).
    pub rate: RateSpec,
    /// `point`: a point on the axis, body axes, from the reference origin (m); the moment center.
    pub point: [f64; 3],
    /// `bearings = [a, b]`: axial positions of bearings A and B from `point` along the axis (m), a ≠ b.
    pub bearings: Option<[f64; 2]>,
    /// `axis_in_space`: the axis's direction in space axes; the attitude at t = 0 is then the smallest rotation
    /// that puts the body axis on it (instead of `initial.attitude`).
    pub axis_in_space: Option<[f64; 3]>,
    /// The capabilities with a table of their own in `[motion]` (a `carrier`), each registered by its `part` line
    /// in `[motion]`'s declaration.
    pub parts: AxisParts,
}

/// `type = "fixed_axis"`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct FixedAxisSpec {
    /// The axis, its rate at t = 0, point and bearings.
    pub axis: AxisSpec,
    /// `accel`: θ̈, constant (rad/s²).
    pub accel: f64,
}

/// `type = "hinge"`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct HingeSpec {
    /// The axis, its rate at t = 0, point and bearings.
    pub axis: AxisSpec,
    /// `angle_deg`: θ at t = 0 (degrees).
    pub angle_deg: f64,
}

impl AxisSpec {
    /// The axis through the reference origin along `direction`, starting at `rate` (rad/s), without bearings.
    ///
    /// ```
    /// use eulerdyn::scene::{AxisDirection, AxisSpec, RateSpec};
    /// let axis = AxisSpec::new(AxisDirection::TiltDeg(30.0), 10.0);
    /// assert_eq!((axis.rate, axis.point), (RateSpec::RadPerSecond(10.0), [0.0; 3]));
    /// ```
    pub fn new(direction: AxisDirection, rate: f64) -> Self {
        Self {
            direction,
            rate: RateSpec::RadPerSecond(rate),
            point: [0.0; 3],
            bearings: None,
            axis_in_space: None,
            parts: AxisParts::default(),
        }
    }
}

impl MotionSpec {
    /// The axis of a fixed-axis or hinge motion; `None` for free motion.
    pub fn axis(&self) -> Option<&AxisSpec> {
        match self {
            MotionSpec::Free => None,
            MotionSpec::FixedAxis(m) => Some(&m.axis),
            MotionSpec::Hinge(m) => Some(&m.axis),
        }
    }

    /// The motion's `type`.
    pub fn kind(&self) -> MotionKind {
        match self {
            MotionSpec::Free => MotionKind::Free,
            MotionSpec::FixedAxis(_) => MotionKind::FixedAxis,
            MotionSpec::Hinge(_) => MotionKind::Hinge,
        }
    }
}

impl From<FixedAxisSpec> for MotionSpec {
    fn from(motion: FixedAxisSpec) -> Self {
        MotionSpec::FixedAxis(motion)
    }
}

impl From<HingeSpec> for MotionSpec {
    fn from(motion: HingeSpec) -> Self {
        MotionSpec::Hinge(motion)
    }
}

/// The constructors both axis motions share: `new` (an axis in body axes), `tilted` (`tilt_deg`), `with_bearings`
/// and `with_point`; `$start` is the motion's own key at its default.
macro_rules! axis_motion {
    ($motion:ident, $start:ident, $what:literal) => {
        impl $motion {
            #[doc = concat!($what, " about `axis_b`, a direction in body axes through the reference origin, at `rate` (rad/s) at t = 0.")]
            ///
            /// ```
            #[doc = concat!("use eulerdyn::scene::{AxisDirection, ", stringify!($motion), "};")]
            #[doc = concat!("let m = ", stringify!($motion), "::new([0.0, 0.0, 1.0], 10.0);")]
            /// assert_eq!(m.axis.direction, AxisDirection::Body([0.0, 0.0, 1.0]));
            /// ```
            pub fn new(axis_b: [f64; 3], rate: f64) -> Self {
                Self::on(AxisSpec::new(AxisDirection::Body(axis_b), rate))
            }

            #[doc = concat!($what, " about the axis (0, −sin θ, cos θ) tilted θ = `tilt_deg` from body z, at `rate` (rad/s) at t = 0.")]
            ///
            /// ```
            #[doc = concat!("use eulerdyn::scene::{AxisDirection, ", stringify!($motion), "};")]
            #[doc = concat!("let m = ", stringify!($motion), "::tilted(30.0, 10.0);")]
            /// assert_eq!(m.axis.direction, AxisDirection::TiltDeg(30.0));
            /// ```
            pub fn tilted(tilt_deg: f64, rate: f64) -> Self {
                Self::on(AxisSpec::new(AxisDirection::TiltDeg(tilt_deg), rate))
            }

            /// On `axis`, with the motion's own key at its default.
            ///
            /// ```
            #[doc = concat!("use eulerdyn::scene::{AxisDirection, AxisSpec, ", stringify!($motion), "};")]
            #[doc = concat!("let m = ", stringify!($motion), "::on(AxisSpec::new(AxisDirection::TiltDeg(30.0), 10.0));")]
            #[doc = concat!("assert_eq!(m, ", stringify!($motion), "::tilted(30.0, 10.0));")]
            /// ```
            pub fn on(axis: AxisSpec) -> Self {
                Self { axis, $start: 0.0 }
            }

            /// With bearings A and B at `a` and `b` metres from the axis point along the axis.
            ///
            /// ```
            #[doc = concat!("use eulerdyn::scene::", stringify!($motion), ";")]
            #[doc = concat!("let m = ", stringify!($motion), "::tilted(30.0, 10.0).with_bearings(-0.1, 0.15).with_point([0.0, 0.0, 0.01]);")]
            /// assert_eq!((m.axis.bearings, m.axis.point), (Some([-0.1, 0.15]), [0.0, 0.0, 0.01]));
            /// ```
            pub fn with_bearings(mut self, a: f64, b: f64) -> Self {
                self.axis.bearings = Some([a, b]);
                self
            }

            /// With the axis through `point_b` (body axes, from the reference origin, m), the moment center.
            ///
            /// ```
            #[doc = concat!("use eulerdyn::scene::", stringify!($motion), ";")]
            #[doc = concat!("let m = ", stringify!($motion), "::tilted(30.0, 10.0).with_point([0.02, 0.0, 0.0]);")]
            /// assert_eq!(m.axis.point, [0.02, 0.0, 0.0]);
            /// ```
            pub fn with_point(mut self, point_b: [f64; 3]) -> Self {
                self.axis.point = point_b;
                self
            }

            /// With the axis, its point and its bearings fixed in a turning `carrier`.
            ///
            /// ```
            #[doc = concat!("use eulerdyn::scene::{CarrierSpec, ", stringify!($motion), "};")]
            #[doc = concat!("let m = ", stringify!($motion), "::new([1.0, 0.0, 0.0], 100.0).with_carrier(CarrierSpec::constant([0.0, 0.0, 0.5]));")]
            /// assert_eq!(m.axis.parts.carrier, Some(CarrierSpec::constant([0.0, 0.0, 0.5])));
            /// ```
            pub fn with_carrier(mut self, carrier: CarrierSpec) -> Self {
                self.axis.parts.carrier = Some(carrier);
                self
            }
        }
    };
}

axis_motion!(FixedAxisSpec, accel, "Prescribed rotation");
axis_motion!(
    HingeSpec,
    angle_deg,
    "A hinge (θ̈ from the effects' moment about the axis)"
);

impl FixedAxisSpec {
    /// With a constant angular acceleration (rad/s²).
    ///
    /// ```
    /// use eulerdyn::scene::FixedAxisSpec;
    /// assert_eq!(FixedAxisSpec::tilted(30.0, 10.0).with_accel(1.0).accel, 1.0);
    /// ```
    pub fn with_accel(mut self, accel: f64) -> Self {
        self.accel = accel;
        self
    }
}

impl HingeSpec {
    /// With θ = `angle_deg` at t = 0.
    ///
    /// ```
    /// use eulerdyn::scene::HingeSpec;
    /// assert_eq!(HingeSpec::new([0.0, 0.0, 1.0], 0.0).with_angle_deg(30.0).angle_deg, 30.0);
    /// ```
    pub fn with_angle_deg(mut self, angle_deg: f64) -> Self {
        self.angle_deg = angle_deg;
        self
    }
}
