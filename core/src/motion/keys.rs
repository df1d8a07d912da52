//! `[motion]`'s keys, declared once ([`MotionFile`]: the file form, the reference's table, its `type`
//! [`MotionKind`] with the keys each type takes, the either/or pairs and the parts a capability adds — a carrier).
//! The typed [`super::spec::MotionSpec`] is read from it and written back in `part.rs`. The scene registers it with
//! one line, `maybe motion: MotionSpec`.

use super::carrier::spec::CarrierSpec;
use super::choices::{AxisDirection, RateSpec};
use crate::keys::{file_table, key, position};

file_table! {
    /// `[motion]`.
    #[derive(Copy)]
    pub(crate) struct MotionFile(pub(super)) "[motion]",
        "absent: free rotation" {
        opt kind as "type": MotionKind = key(MotionKind::CHOICES, "–", "required in the table", "", "free (no other keys), a prescribed rotation about a fixed axis, or a hinge (θ from the effects)");
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
        axis, tilt_deg => AxisDirection::{Body, TiltDeg}: "give either `axis` or `tilt_deg`, not both";
        rate, rate_rpm => RateSpec::{RadPerSecond, Rpm}: "give either `rate` (rad/s) or `rate_rpm` (revolutions per minute), not both";
    }
    parts {
        /// The capabilities with a table of their own in `[motion]` that modify a fixed axis or hinge (each a
        /// `keys::Part`, registered by its `part` line in `[motion]`'s declaration).
        #[derive(Debug, Clone, Copy, Default, PartialEq)]
        pub struct AxisParts;
    }
    kinds {
        /// A motion's `type`, as the scene file and the sidecar write it: `free`, `fixed_axis`, `hinge`.
        pub enum MotionKind("motion type", "missing: the motion needs `type` = \"free\", \"fixed_axis\" or \"hinge\"") {
            /// `free`.
            Free = "free": [];
            /// `fixed_axis`.
            FixedAxis = "fixed_axis": [axis, tilt_deg, rate, rate_rpm, point, bearings, axis_in_space, ..parts, accel];
            /// `hinge`.
            Hinge = "hinge": [axis, tilt_deg, rate, rate_rpm, point, bearings, axis_in_space, ..parts, angle_deg];
        }
    }
}
