//! `[body]`: the mass, a shape or an inertia tensor, and point masses.

use serde::{Deserialize, Serialize};

use super::{BodySpec, PointMassSpec};
use crate::wheels::RotorSpec;

/// `body.shape`: a homogeneous shape, `type` and its dimensions (the vocabulary type [`crate::body::Shape`]).
pub type ShapeSpec = crate::body::Shape;

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

impl BodySpec {
    /// A body of `mass` (kg) and uniform density in the shape `shape`.
    ///
    /// ```
    /// use eulerdyn::scene::{BodySpec, Distribution, ShapeSpec};
    /// let disk = BodySpec::shape(2.0, ShapeSpec::thin_disk(0.3));
    /// assert_eq!(disk.distribution, Distribution::Shape(ShapeSpec::ThinDisk { radius: 0.3 }));
    /// ```
    pub fn shape(mass: f64, shape: ShapeSpec) -> Self {
        Self::of(mass, Distribution::Shape(shape))
    }

    /// A body of `mass` (kg) whose body axes are principal, with moments [I1, I2, I3] (kg·m²) about C.
    ///
    /// ```
    /// use eulerdyn::scene::{BodySpec, Distribution, InertiaSpec};
    /// let body = BodySpec::principal(1.0, [1.0, 2.0, 3.0]);
    /// assert_eq!(body.distribution, Distribution::Inertia(InertiaSpec::Principal([1.0, 2.0, 3.0])));
    /// ```
    pub fn principal(mass: f64, moments: [f64; 3]) -> Self {
        Self::of(mass, Distribution::Inertia(InertiaSpec::Principal(moments)))
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
        Self::of(mass, Distribution::Inertia(InertiaSpec::Full(inertia_c_b)))
    }

    /// With a point mass of `mass` (kg) at `at` (m, body axes, from the reference origin).
    ///
    /// ```
    /// use eulerdyn::scene::{BodySpec, ShapeSpec};
    /// let body = BodySpec::shape(1.0, ShapeSpec::sphere(0.1)).with_point_mass(0.01, [0.1, 0.0, 0.0]);
    /// assert_eq!(body.point_mass[0].at, [0.1, 0.0, 0.0]);
    /// ```
    pub fn with_point_mass(mut self, mass: f64, at: [f64; 3]) -> Self {
        self.point_mass.push(PointMassSpec::of(mass, at));
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
