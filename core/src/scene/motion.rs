//! The scene's motion ([`Motion`]): free rotation (with the body's rotors, if any), a prescribed fixed axis, or a
//! hinge — and everything the rest of the library asks of it, answered here, so that no other file outside
//! `core/src/motion/` but the run's dispatch (`simulate`) and the motion's validation (`scene/validate/motion.rs`)
//! names a variant. It sits in `scene/`, above `motion/` and `wheels/`, because a free body's rotors (`wheels`)
//! are built on `motion::free`.

use nalgebra::{Matrix3, UnitQuaternion, Vector3};

use super::attributes::Attribute;
use super::spec::MotionKind;
use crate::frames::{BodyAxes, Vector};
use crate::motion::axis_columns::AxisColumns;
use crate::motion::fixed_axis::FixedAxis;
use crate::motion::free::FreeBody;
use crate::motion::hinge::Hinge;
use crate::sample::ColumnGroup;
use crate::wheels::gyrostat::Gyrostat;

/// A free motion's parts: ω₀, the body about its moment center, and its attribute (its rotors, or its change of
/// shape).
#[derive(Debug, Clone, Copy)]
pub struct FreeParts<'a> {
    /// ω at t = 0, body axes (rad/s).
    pub omega0_b: &'a Vector<BodyAxes>,
    /// The body about its moment center.
    pub body: &'a FreeBody,
    /// The body's attribute, when it has one.
    pub attribute: Option<&'a Attribute>,
    /// The body with its rotors, when that attribute is its wheels.
    pub gyrostat: Option<&'a Gyrostat>,
}

/// The motion of the body.
#[derive(Debug, Clone, PartialEq)]
pub enum Motion {
    /// Free rotation from the initial angular velocity (body axes, rad/s), about the moment center
    /// (C, or the pivot of a gravity effect).
    Free {
        /// ω at t = 0, body axes (rad/s).
        omega0_b: Vector<BodyAxes>,
        /// The body about its moment center.
        body: FreeBody,
        /// The body's attribute (its rotors, its change of shape), when it has one.
        attribute: Option<Attribute>,
    },
    /// Prescribed rotation about a fixed axis.
    FixedAxis(FixedAxis),
    /// Rotation about a fixed axis driven by the effects (θ integrated from their moment about the axis).
    Hinge(Hinge),
}

impl Motion {
    /// A free motion's parts; `None` for an axis motion.
    pub fn free(&self) -> Option<FreeParts<'_>> {
        match self {
            Motion::Free {
                omega0_b,
                body,
                attribute,
            } => Some(FreeParts {
                omega0_b,
                body,
                attribute: attribute.as_ref(),
                gyrostat: attribute.as_ref().and_then(Attribute::gyrostat),
            }),
            _ => None,
        }
    }

    /// Whether the body turns freely (with or without rotors).
    pub fn is_free(&self) -> bool {
        matches!(self, Motion::Free { .. })
    }

    /// The body's rotors, when it is free and has any.
    pub fn gyrostat(&self) -> Option<&Gyrostat> {
        self.free().and_then(|f| f.gyrostat)
    }

    /// The body's attribute (its rotors, its change of shape), when it is free and has one.
    pub fn attribute(&self) -> Option<&Attribute> {
        self.free().and_then(|f| f.attribute)
    }

    /// The body's rotors and ω₀, to change the rotors (a wheel law) when it is free and has any.
    pub(crate) fn gyrostat_mut(&mut self) -> Option<(&mut Gyrostat, &Vector<BodyAxes>)> {
        match self {
            Motion::Free {
                attribute: Some(a),
                omega0_b,
                ..
            } => a.gyrostat_mut().map(|g| (g, &*omega0_b)),
            _ => None,
        }
    }

    /// The axis of a prescribed fixed-axis motion (θ(t) given, M = dH/dt computed); `None` otherwise.
    pub fn prescribed(&self) -> Option<&FixedAxis> {
        match self {
            Motion::FixedAxis(axis) => Some(axis),
            _ => None,
        }
    }

    /// The hinge, when the effects drive the rotation about a fixed axis; `None` otherwise.
    pub fn hinge(&self) -> Option<&Hinge> {
        match self {
            Motion::Hinge(hinge) => Some(hinge),
            _ => None,
        }
    }

    /// The motion's `type` in a scene file.
    pub fn kind(&self) -> MotionKind {
        match self {
            Motion::Free { .. } => MotionKind::Free,
            Motion::FixedAxis(_) => MotionKind::FixedAxis,
            Motion::Hinge(_) => MotionKind::Hinge,
        }
    }

    /// The name of the wheel law that commands the wheels
    /// ([`Scene::with_wheel_law`](super::Scene::with_wheel_law)), if one does.
    pub fn wheel_law(&self) -> Option<&str> {
        self.gyrostat()
            .and_then(|g| g.law())
            .map(|law| law.name.as_str())
    }

    /// The optional columns of an axis motion ([`AxisColumns`]): the force only when C is off the axis, H_s
    /// integrated for a prescribed motion, the loads only with bearings; `None` for free motion.
    pub fn axis_columns(&self) -> Option<AxisColumns> {
        self.axis().map(|axis| AxisColumns {
            force: axis.center_off_axis(),
            h_s_integrated: matches!(self, Motion::FixedAxis(_)),
            bearings: axis.bearings().is_some(),
        })
    }

    /// The columns its capabilities add after all others: a moving support's, a free body's attribute's (its
    /// wheels', its changing shape's).
    pub fn capability_columns(&self) -> Option<ColumnGroup> {
        match self.attribute() {
            Some(attribute) => Some(attribute.door().columns()),
            None => (self.axis())
                .and_then(FixedAxis::moving_support)
                .map(|s| s.columns()),
        }
    }

    /// The attitude at t = 0: an axis motion's own (its `axis_in_space`, and a hinge's θ₀), else `given`.
    pub fn attitude0(&self, given: UnitQuaternion<f64>) -> UnitQuaternion<f64> {
        match self {
            Motion::FixedAxis(axis) => axis.attitude(0.0),
            Motion::Hinge(hinge) => hinge.axis().attitude(hinge.theta0()),
            Motion::Free { .. } => given,
        }
    }

    /// The largest rate (rad/s) the motion has at its start or, for a prescribed spin-up, its end `t_end`: |ω₀|
    /// of a free body, the hinge's θ̇₀, max(|θ̇₀|, |θ̇₀ + α t_end|) of a fixed axis; plus a carrier's largest rate.
    pub fn largest_rate(&self, t_end: f64) -> f64 {
        let support =
            (self.axis().and_then(FixedAxis::moving_support)).map_or(0.0, |s| s.largest_rate());
        support
            + match self {
                Motion::Free { omega0_b, .. } => omega0_b.norm(),
                Motion::FixedAxis(axis) => {
                    (axis.rate().abs()).max((axis.rate() + axis.accel() * t_end).abs())
                }
                Motion::Hinge(hinge) => hinge.rate0().abs(),
            }
    }

    /// A free rigid body without an attribute (no rotors, a shape that does not change): its ω₀ (body axes) and
    /// the body about its moment center.
    pub fn rigid_free(&self) -> Option<(&Vector<BodyAxes>, &FreeBody)> {
        match self {
            Motion::Free {
                omega0_b,
                body,
                attribute: None,
            } => Some((omega0_b, body)),
            _ => None,
        }
    }

    /// The fixed axis of a fixed-axis or hinge motion (its direction, point, bearings); `None` for free motion.
    pub fn axis(&self) -> Option<&FixedAxis> {
        match self {
            Motion::Free { .. } => None,
            Motion::FixedAxis(axis) => Some(axis),
            Motion::Hinge(hinge) => Some(hinge.axis()),
        }
    }

    /// C from the moment center O (the pivot, the axis point, or C itself), and the inertia about O, body axes.
    pub fn about_moment_center(&self) -> (Vector3<f64>, Matrix3<f64>) {
        match (self, self.axis()) {
            (Motion::Free { body, .. }, _) => (**body.rho_c_b(), *body.inertia_b()),
            (_, axis) => axis.map_or((Vector3::zeros(), Matrix3::zeros()), |a| {
                (**a.rho_c_b(), *a.inertia_a_b())
            }),
        }
    }
}
