//! [`MotionSpec`] as a [`Part`]: `[motion]`'s file form ([`MotionFile`], declared in `keys.rs`) read into the
//! typed spec — its `type`, the keys that type takes, `axis` or `tilt_deg`, `rate` or `rate_rpm`, the parts — and
//! written back.

use super::keys::{AxisParts, MotionFile, MotionKind};
use super::spec::{AxisSpec, FixedAxisSpec, HingeSpec, MotionSpec, RateSpec};
use crate::keys::{Checked, Either, KeyPath, Keys, Part, Table, invalid};

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
    let Some(direction) = doc.either() else {
        return invalid(
            at.clone(),
            "a fixed-axis motion needs `axis = [x, y, z]` (body axes) or `tilt_deg`",
        );
    };
    Ok(AxisSpec {
        direction,
        rate: doc.either().unwrap_or(RateSpec::RadPerSecond(0.0)),
        point: doc.point.unwrap_or([0.0; 3]),
        bearings: doc.bearings,
        axis_in_space: doc.axis_in_space,
        parts: AxisParts::read(doc, at)?,
    })
}

/// The file form of an axis motion of type `kind`, its own keys (`accel`, `angle_deg`) left to the caller.
fn axis_file(kind: MotionKind, axis: &AxisSpec) -> MotionFile {
    let mut file = MotionFile {
        kind: Some(kind),
        point: Some(axis.point),
        bearings: axis.bearings,
        axis_in_space: axis.axis_in_space,
        ..MotionFile::default()
    };
    file.set_either(Some(axis.direction));
    file.set_either(Some(axis.rate));
    axis.parts.write(&mut file);
    file
}
