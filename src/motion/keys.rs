//! `[motion]`'s keys, declared once ([`MotionFile`]: the file form, the reference's table, its `type`
//! [`MotionKind`] with the keys each type takes, the either/or pairs and the parts a capability adds — a carrier),
//! and [`MotionSpec`] as a [`Part`]: read from that table and written back. The scene registers it with one line,
//! `opt motion: MotionFile`.

use super::carrier::spec::CarrierSpec;
use super::spec::{AxisDirection, AxisSpec, FixedAxisSpec, HingeSpec, MotionSpec, RateSpec};
use crate::keys::{Checked, KeyPath, Part, Table, file_table, invalid, key, position};

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
        axis, tilt_deg: "give either `axis` or `tilt_deg`, not both";
        rate, rate_rpm: "give either `rate` (rad/s) or `rate_rpm` (revolutions per minute), not both";
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

impl Part for MotionSpec {
    type File = MotionFile;
    const TABLE: Table = MotionFile::TABLE;

    /// `[motion]` (its table at `at`): its `type` and the keys that type takes; a free motion refuses its parts'
    /// keys with their own messages first.
    fn read(doc: &MotionFile, at: &KeyPath) -> Checked<Self> {
        if doc.kind == Some(MotionKind::Free) {
            AxisParts::refuse_unattached(doc, at)?;
        }
        Ok(match doc.kind_given(at)?.0 {
            MotionKind::Free => MotionSpec::Free,
            MotionKind::FixedAxis => MotionSpec::FixedAxis(FixedAxisSpec {
                axis: axis(doc, at)?,
                accel: doc.accel.unwrap_or(0.0),
            }),
            MotionKind::Hinge => MotionSpec::Hinge(HingeSpec {
                axis: axis(doc, at)?,
                angle_deg: doc.angle_deg.unwrap_or(0.0),
            }),
        })
    }

    fn write(&self) -> MotionFile {
        match self {
            MotionSpec::Free => MotionFile {
                kind: Some(MotionKind::Free),
                ..MotionFile::default()
            },
            MotionSpec::FixedAxis(m) => MotionFile {
                accel: Some(m.accel),
                ..axis_file(MotionKind::FixedAxis, &m.axis)
            },
            MotionSpec::Hinge(m) => MotionFile {
                angle_deg: Some(m.angle_deg),
                ..axis_file(MotionKind::Hinge, &m.axis)
            },
        }
    }
}

/// The keys of a fixed-axis or hinge motion's axis (the table at `at`): `axis` or `tilt_deg`, `rate` or
/// `rate_rpm`, and the parts.
fn axis(doc: &MotionFile, at: &KeyPath) -> Checked<AxisSpec> {
    doc.exclusive(at)?;
    let direction = match (doc.axis, doc.tilt_deg) {
        (None, None) => {
            return invalid(
                at.clone(),
                "a fixed-axis motion needs `axis = [x, y, z]` (body axes) or `tilt_deg`",
            );
        }
        (Some(a), _) => AxisDirection::Body(a),
        (None, Some(tilt)) => AxisDirection::TiltDeg(tilt),
    };
    let rate = match (doc.rate, doc.rate_rpm) {
        (None, Some(rpm)) => RateSpec::Rpm(rpm),
        (rate, _) => RateSpec::RadPerSecond(rate.unwrap_or(0.0)),
    };
    Ok(AxisSpec {
        direction,
        rate,
        point: doc.point.unwrap_or([0.0; 3]),
        bearings: doc.bearings,
        axis_in_space: doc.axis_in_space,
        parts: AxisParts::read(doc, at)?,
    })
}

/// The file form of an axis motion of type `kind`, its own keys (`accel`, `angle_deg`) left to the caller.
fn axis_file(kind: MotionKind, axis: &AxisSpec) -> MotionFile {
    let (rate, rate_rpm) = match axis.rate {
        RateSpec::RadPerSecond(rate) => (Some(rate), None),
        RateSpec::Rpm(rpm) => (None, Some(rpm)),
    };
    let (axis_b, tilt_deg) = match axis.direction {
        AxisDirection::Body(a) => (Some(a), None),
        AxisDirection::TiltDeg(tilt) => (None, Some(tilt)),
    };
    let mut file = MotionFile {
        kind: Some(kind),
        axis: axis_b,
        tilt_deg,
        rate,
        rate_rpm,
        point: Some(axis.point),
        bearings: axis.bearings,
        axis_in_space: axis.axis_in_space,
        ..MotionFile::default()
    };
    axis.parts.write(&mut file);
    file
}
