//! Vectors that carry their axes in their type, after Principia's `geometry::Vector<Scalar, Frame>`: a
//! [`Vector<BodyAxes>`] cannot be passed where a [`Vector<SpaceAxes>`] is asked; a vector changes axes only where a
//! rotation is written, on its coordinates. The type is a [`Vector3`] and a zero-sized marker (`repr(transparent)`): it
//! costs nothing at run time, and its coordinates are read through [`Deref`].

use std::fmt;
use std::marker::PhantomData;
use std::ops::{Add, AddAssign, Deref, Div, Mul, Neg, Sub};

use nalgebra::{UnitQuaternion, Vector3};

/// The axes a [`Vector`] is expressed in (a marker type, never built).
pub trait Frame: Copy + fmt::Debug + PartialEq + 'static {
    /// The suffix that names these axes in a field or column (`omega_b`, `H_s_x`).
    const SUFFIX: &'static str;
}

/// Axes fixed in the body, origin at the mass center C: the axes the scene's inertia is given in (suffix `_b`).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum BodyAxes {}

/// The inertial axes (suffix `_s`).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum SpaceAxes {}

/// The axes of the support a fixed axis, its point and its bearings are fixed in (suffix `_c`, for carrier): a
/// moving support's, which turn in space (`crate::motion::moving_support`), or space's own when nothing moves it.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum SupportAxes {}

impl Frame for BodyAxes {
    const SUFFIX: &'static str = "b";
}

impl Frame for SpaceAxes {
    const SUFFIX: &'static str = "s";
}

impl Frame for SupportAxes {
    const SUFFIX: &'static str = "c";
}

/// A vector of three coordinates in the axes `F`.
#[repr(transparent)]
pub struct Vector<F: Frame> {
    coordinates: Vector3<f64>,
    axes: PhantomData<F>,
}

impl<F: Frame> Vector<F> {
    /// The vector whose coordinates in the axes `F` are `coordinates`.
    ///
    /// ```
    /// use eulerdyn::frames::{SpaceAxes, Vector};
    /// use nalgebra::{UnitQuaternion, Vector3};
    /// let g_s = Vector::<SpaceAxes>::new(Vector3::new(0.0, 0.0, -9.81));
    /// assert_eq!(g_s.z, -9.81);
    /// ```
    pub const fn new(coordinates: Vector3<f64>) -> Self {
        Self {
            coordinates,
            axes: PhantomData,
        }
    }

    /// The zero vector.
    ///
    /// ```
    /// use eulerdyn::frames::{BodyAxes, Vector};
    /// assert_eq!(Vector::<BodyAxes>::zeros().norm(), 0.0);
    /// ```
    pub fn zeros() -> Self {
        Self::new(Vector3::zeros())
    }

    /// The coordinates, leaving the type's axes behind (for arithmetic nalgebra does and this type does not).
    pub fn into_inner(self) -> Vector3<f64> {
        self.coordinates
    }
}

impl Vector<BodyAxes> {
    /// The same vector in space axes, v_s = R(q) v_b, q the attitude (body → space).
    ///
    /// ```
    /// use eulerdyn::frames::{BodyAxes, Vector};
    /// use nalgebra::{UnitQuaternion, Vector3};
    /// let q = UnitQuaternion::from_axis_angle(&Vector3::z_axis(), std::f64::consts::FRAC_PI_2);
    /// let x_b = Vector::<BodyAxes>::new(Vector3::x());
    /// assert!((*x_b.in_space(&q) - Vector3::y()).norm() < 1e-15);
    /// ```
    #[inline(always)]
    pub fn in_space(&self, q: &UnitQuaternion<f64>) -> Vector<SpaceAxes> {
        Vector::new(q * self.coordinates)
    }
}

impl Vector<SpaceAxes> {
    /// The same vector in body axes, v_b = R(q)ᵀ v_s, q the attitude (body → space).
    ///
    /// ```
    /// use eulerdyn::frames::{SpaceAxes, Vector};
    /// use nalgebra::{UnitQuaternion, Vector3};
    /// let q = UnitQuaternion::from_axis_angle(&Vector3::z_axis(), std::f64::consts::FRAC_PI_2);
    /// let y_s = Vector::<SpaceAxes>::new(Vector3::y());
    /// assert!((*y_s.in_body(&q) - Vector3::x()).norm() < 1e-15);
    /// ```
    #[inline(always)]
    pub fn in_body(&self, q: &UnitQuaternion<f64>) -> Vector<BodyAxes> {
        Vector::new(q.inverse_transform_vector(&self.coordinates))
    }
}

impl<F: Frame> Default for Vector<F> {
    /// The zero vector.
    fn default() -> Self {
        Self::zeros()
    }
}

impl<F: Frame> Deref for Vector<F> {
    type Target = Vector3<f64>;

    fn deref(&self) -> &Vector3<f64> {
        &self.coordinates
    }
}

impl<F: Frame> Clone for Vector<F> {
    fn clone(&self) -> Self {
        *self
    }
}

impl<F: Frame> Copy for Vector<F> {}

impl<F: Frame> PartialEq for Vector<F> {
    fn eq(&self, other: &Self) -> bool {
        self.coordinates == other.coordinates
    }
}

impl<F: Frame> fmt::Debug for Vector<F> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let [x, y, z] = [self.x, self.y, self.z];
        write!(f, "[{x:?}, {y:?}, {z:?}]_{}", F::SUFFIX)
    }
}

/// The coordinates as nalgebra prints them.
impl<F: Frame> fmt::Display for Vector<F> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        fmt::Display::fmt(&self.coordinates, f)
    }
}

impl<F: Frame> Add for Vector<F> {
    type Output = Self;

    fn add(self, other: Self) -> Self {
        Self::new(self.coordinates + other.coordinates)
    }
}

impl<F: Frame> AddAssign for Vector<F> {
    fn add_assign(&mut self, other: Self) {
        self.coordinates += other.coordinates;
    }
}

impl<F: Frame> Sub for Vector<F> {
    type Output = Self;

    fn sub(self, other: Self) -> Self {
        Self::new(self.coordinates - other.coordinates)
    }
}

impl<F: Frame> Neg for Vector<F> {
    type Output = Self;

    fn neg(self) -> Self {
        Self::new(-self.coordinates)
    }
}

impl<F: Frame> Mul<f64> for Vector<F> {
    type Output = Self;

    fn mul(self, factor: f64) -> Self {
        Self::new(self.coordinates * factor)
    }
}

impl<F: Frame> Mul<Vector<F>> for f64 {
    type Output = Vector<F>;

    fn mul(self, v: Vector<F>) -> Vector<F> {
        v * self
    }
}

impl<F: Frame> Div<f64> for Vector<F> {
    type Output = Self;

    fn div(self, divisor: f64) -> Self {
        Self::new(self.coordinates / divisor)
    }
}
