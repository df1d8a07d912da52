//! A motion modifier: what moves the support of an axis (its point A and its bearings) in space. The axis motions
//! ([`crate::motion::fixed_axis`], [`crate::motion::hinge`]) take the support's motion at each time — its attitude
//! R_c, rate Ω_c, angular acceleration Ω̇_c and the acceleration a_A of the axis point — and nothing else of the
//! modifier, so that a modifier is one folder ([`crate::motion::carrier`] is the model) that implements
//! [`MovingSupport`].

use std::any::Any;
use std::fmt;

use nalgebra::UnitQuaternion;

use crate::frames::{SpaceAxes, Vector};

use crate::sample::ColumnGroup;
use crate::text::Description;

/// The support at one time: its attitude R_c (support → space), rate Ω_c and angular acceleration Ω̇_c (space
/// axes), and the acceleration a_A of the axis point A when A moves.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SupportMotion {
    /// R_c, support → space.
    pub q_c: UnitQuaternion<f64>,
    /// Ω_c (rad/s, space axes).
    pub omega_c_s: Vector<SpaceAxes>,
    /// Ω̇_c (rad/s², space axes).
    pub omega_c_dot_s: Vector<SpaceAxes>,
    /// a_A (m/s², space axes); `None` when A stays fixed in space.
    pub accel_a_s: Option<Vector<SpaceAxes>>,
}

/// A support that moves in space, as an axis motion sees it ([`SupportMotion`] at each time), with what the rest
/// of the library asks of it: its largest rate (the step-size guard), its `check` lines and its CSV columns.
pub trait MovingSupport: fmt::Debug + Send + Sync + Any {
    /// R_c, Ω_c, Ω̇_c and a_A at time `t`; R_c(0) = E (the support starts aligned with space).
    fn at(&self, t: f64) -> SupportMotion;

    /// The largest |Ω_c| over all times (rad/s).
    fn largest_rate(&self) -> f64;

    /// Appends its lines of `check` for a body of `mass` (kg).
    fn describe(&self, mass: f64, w: &mut Description);

    /// The columns a run with it writes after the support's own ([`crate::sample::ColumnSet::groups`]).
    fn columns(&self) -> ColumnGroup;

    /// Itself, so that two supports can be compared ([`PartialEq`] for `dyn MovingSupport`).
    fn as_any(&self) -> &dyn Any;

    /// Whether `other` is the same support: the same type with equal values.
    fn same_as(&self, other: &dyn MovingSupport) -> bool;
}

impl PartialEq for dyn MovingSupport {
    fn eq(&self, other: &Self) -> bool {
        self.same_as(other)
    }
}
