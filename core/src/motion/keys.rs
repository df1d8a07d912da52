//! `[motion]`'s keys, declared once ([`MotionFile`]: the file form, the reference's table, its `type`
//! [`MotionKind`] with the keys each type takes, the either/or pairs and the parts a capability adds — a carrier).
//! The typed [`super::spec::MotionSpec`] is read from it and written back in `part.rs`. The scene registers it with
//! one field, `motion: Option<MotionSpec>`.

use super::carrier::keys::CarrierFile;
use super::carrier::spec::CarrierSpec;
use super::choices::{AxisDirection, RateSpec};
use crate::keys::{Keys, Kind};

/// `[motion]`.
#[derive(Debug, Clone, Copy, Default, PartialEq, Keys)]
#[keys(
    header = "[motion]",
    about = "absent: free rotation",
    either(axis, tilt_deg, "give either `axis` or `tilt_deg`, not both", AxisDirection::Body, AxisDirection::TiltDeg),
    either(
        rate,
        rate_rpm,
        "give either `rate` (rad/s) or `rate_rpm` (revolutions per minute), not both",
        RateSpec::RadPerSecond,
        RateSpec::Rpm
    ),
    parts = AxisParts
)]
pub(crate) struct MotionFile {
    /// free (no other keys), a prescribed rotation about a fixed axis, or a hinge (θ from the effects)
    #[key(rename = "type", kinds, shown = "required in the table")]
    pub(super) kind: Option<MotionKind>,
    /// the fixed axis's direction in body axes, normalised; not zero
    #[key(unit = "–", shown = "`axis` or `tilt_deg` required")]
    pub(super) axis: Option<[f64; 3]>,
    /// instead of `axis`: axis = (0, −sin tilt, cos tilt)
    #[key(unit = "deg")]
    pub(super) tilt_deg: Option<f64>,
    /// θ̇ at t = 0
    #[key(unit = "rad/s", shown = "0")]
    pub(super) rate: Option<f64>,
    /// instead of `rate`: rate = rate_rpm · 2π/60
    #[key(unit = "rpm")]
    pub(super) rate_rpm: Option<f64>,
    /// constant θ̈; fixed axis only
    #[key(unit = "rad/s²", shown = "0")]
    pub(super) accel: Option<f64>,
    /// a point of the axis: the moment center
    #[key(position, shown = "[0, 0, 0]")]
    pub(super) point: Option<[f64; 3]>,
    /// hinge only: θ at t = 0
    #[key(unit = "deg", shown = "0")]
    pub(super) angle_deg: Option<f64>,
    /// positions of bearings A and B, a ≠ b; adds the `R_*` columns
    #[key(kind = "[a, b]", unit = "m", origin = "from `point`, along the axis")]
    pub(super) bearings: Option<[f64; 2]>,
    /// the axis's direction in space axes: the attitude at t = 0 puts the body axis on it (instead of `initial.attitude`)
    #[key(unit = "–")]
    pub(super) axis_in_space: Option<[f64; 3]>,
    /// the axis turns with a carrier: `[motion.carrier]`
    #[key(kind = "inline table", part = CarrierSpec)]
    pub(super) carrier: Option<CarrierFile>,
}

/// A motion's `type`, as the scene file and the sidecar write it: `free`, `fixed_axis`, `hinge`.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Kind)]
#[kind(
    what = "motion type",
    missing = "missing: the motion needs `type` = \"free\", \"fixed_axis\" or \"hinge\""
)]
pub enum MotionKind {
    /// `free`.
    #[kind("free")]
    Free,
    /// `fixed_axis`.
    #[kind("fixed_axis", takes(axis, tilt_deg, rate, rate_rpm, point, bearings, axis_in_space, .., accel))]
    FixedAxis,
    /// `hinge`.
    #[kind("hinge", takes(axis, tilt_deg, rate, rate_rpm, point, bearings, axis_in_space, .., angle_deg))]
    Hinge,
}
