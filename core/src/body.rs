//! Rigid bodies: mass, the central inertia tensor I_C in body axes, its principal decomposition,
//! the inertia of common shapes and the parallel-axis theorem.

use nalgebra::{Matrix3, Rotation3, SymmetricEigen, Vector3};

/// A body property that failed validation: the scene key it came from (relative to `[body]`) and what is wrong.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[error("{problem}")]
pub struct InvalidBody {
    /// The key under `[body]`, e.g. `mass`, `inertia`, `shape.radius`.
    pub key: &'static str,
    /// What is wrong and what would be valid.
    pub problem: String,
}

impl InvalidBody {
    fn new(key: &'static str, problem: impl Into<String>) -> Self {
        Self {
            key,
            problem: problem.into(),
        }
    }
}

/// Homogeneous shapes whose central inertia has a closed form.
///
/// As in the reference notes, disks and cylinders have their symmetry axis along body z and the thin rod lies
/// along body x.
///
/// Serialized as a scene file writes it: `{ type = "thin_disk", radius = 0.3 }`.
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
#[serde(tag = "type", rename_all = "snake_case")]
pub enum Shape {
    /// Thin disk of radius R: I = mR²·diag(1/4, 1/4, 1/2).
    ThinDisk {
        /// R (m).
        radius: f64,
    },
    /// Solid disk of radius R and thickness h: I_xx = I_yy = m(3R² + h²)/12, I_zz = mR²/2.
    Disk {
        /// R (m).
        radius: f64,
        /// h (m).
        thickness: f64,
    },
    /// Thin rod of length l along body x: I = (ml²/12)·diag(0, 1, 1).
    ThinRod {
        /// l (m).
        length: f64,
    },
    /// Solid sphere of radius R: I = (2/5)mR²·E.
    Sphere {
        /// R (m).
        radius: f64,
    },
    /// Box with edges (a, b, c) along body x, y, z: I_xx = m(b² + c²)/12, and cyclically.
    Box {
        /// (a, b, c) (m).
        size: [f64; 3],
    },
    /// Solid cylinder of radius R and height h along body z: I_xx = I_yy = m(3R² + h²)/12, I_zz = mR²/2.
    Cylinder {
        /// R (m).
        radius: f64,
        /// h (m).
        height: f64,
    },
}

impl Shape {
    /// A thin disk of `radius` (m), symmetry axis along body z.
    ///
    /// ```
    /// use eulerdyn::body::Shape;
    /// assert_eq!(Shape::thin_disk(0.3), Shape::ThinDisk { radius: 0.3 });
    /// ```
    pub fn thin_disk(radius: f64) -> Self {
        Self::ThinDisk { radius }
    }

    /// A disk of `radius` and `thickness` (m), symmetry axis along body z.
    ///
    /// ```
    /// use eulerdyn::body::Shape;
    /// assert_eq!(Shape::disk(0.3, 0.02), Shape::Disk { radius: 0.3, thickness: 0.02 });
    /// ```
    pub fn disk(radius: f64, thickness: f64) -> Self {
        Self::Disk { radius, thickness }
    }

    /// A thin rod of `length` (m) along body x.
    ///
    /// ```
    /// use eulerdyn::body::Shape;
    /// assert_eq!(Shape::thin_rod(1.0), Shape::ThinRod { length: 1.0 });
    /// ```
    pub fn thin_rod(length: f64) -> Self {
        Self::ThinRod { length }
    }

    /// A sphere of `radius` (m).
    ///
    /// ```
    /// use eulerdyn::body::Shape;
    /// assert_eq!(Shape::sphere(0.1), Shape::Sphere { radius: 0.1 });
    /// ```
    pub fn sphere(radius: f64) -> Self {
        Self::Sphere { radius }
    }

    /// A rectangular box of edges `size` = [x, y, z] (m) along the body axes.
    ///
    /// ```
    /// use eulerdyn::body::Shape;
    /// assert_eq!(Shape::cuboid([0.1, 0.2, 0.3]), Shape::Box { size: [0.1, 0.2, 0.3] });
    /// ```
    pub fn cuboid(size: [f64; 3]) -> Self {
        Self::Box { size }
    }

    /// A solid cylinder of `radius` and `height` (m), symmetry axis along body z.
    ///
    /// ```
    /// use eulerdyn::body::Shape;
    /// assert_eq!(Shape::cylinder(0.1, 0.5), Shape::Cylinder { radius: 0.1, height: 0.5 });
    /// ```
    pub fn cylinder(radius: f64, height: f64) -> Self {
        Self::Cylinder { radius, height }
    }

    /// Checks the dimensions (finite and > 0, or ≥ 0 for a disk's thickness) and returns the central
    /// inertia tensor of the shape with mass `mass`, in body axes (formulas on each variant; e.g.
    /// Meriam & Kraige, Engineering Mechanics: Dynamics, Appendix B).
    pub fn inertia_c(&self, mass: f64) -> Result<Matrix3<f64>, InvalidBody> {
        let positive = |key: &'static str, v: f64| {
            if v.is_finite() && v > 0.0 {
                Ok(v)
            } else {
                Err(InvalidBody::new(
                    key,
                    format!("must be a finite number > 0 (m), got {v:?}"),
                ))
            }
        };
        let diag = |x: f64, y: f64, z: f64| Matrix3::from_diagonal(&Vector3::new(x, y, z));
        Ok(match *self {
            Shape::ThinDisk { radius } => {
                let r = positive("shape.radius", radius)?;
                let i = mass * r * r;
                diag(i / 4.0, i / 4.0, i / 2.0)
            }
            Shape::Disk { radius, thickness } => {
                let r = positive("shape.radius", radius)?;
                if !(thickness.is_finite() && thickness >= 0.0) {
                    return Err(InvalidBody::new(
                        "shape.thickness",
                        format!("must be a finite number >= 0 (m), got {thickness:?}"),
                    ));
                }
                let t = mass * (3.0 * r * r + thickness * thickness) / 12.0;
                diag(t, t, mass * r * r / 2.0)
            }
            Shape::Cylinder { radius, height } => {
                let r = positive("shape.radius", radius)?;
                let h = positive("shape.height", height)?;
                let t = mass * (3.0 * r * r + h * h) / 12.0;
                diag(t, t, mass * r * r / 2.0)
            }
            Shape::ThinRod { length } => {
                let l = positive("shape.length", length)?;
                let t = mass * l * l / 12.0;
                diag(0.0, t, t)
            }
            Shape::Sphere { radius } => {
                let r = positive("shape.radius", radius)?;
                let i = 0.4 * mass * r * r;
                diag(i, i, i)
            }
            Shape::Box { size } => {
                for v in size {
                    positive("shape.size", v)?;
                }
                let [a, b, c] = size.map(|v| v * v);
                diag(
                    mass * (b + c) / 12.0,
                    mass * (a + c) / 12.0,
                    mass * (a + b) / 12.0,
                )
            }
        })
    }
}

/// Principal moments and axes of an inertia tensor: I = P·diag(moments)·Pᵀ, the columns of P being the principal
/// axes in body axes, P a proper rotation (det P = +1).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Principal {
    /// Principal moments (kg·m²): in body-axis order when the tensor is diagonal, else ascending.
    pub moments: Vector3<f64>,
    /// Rotation whose columns are the principal axes expressed in body axes.
    pub axes_b: Rotation3<f64>,
}

impl Principal {
    /// Eigen-decomposition of a symmetric tensor. A diagonal tensor is returned exactly (axes = identity), so that
    /// bodies given by principal moments carry no round-off from the decomposition.
    pub fn of(inertia: &Matrix3<f64>) -> Self {
        let off_diagonal_zero = inertia[(0, 1)] == 0.0
            && inertia[(0, 2)] == 0.0
            && inertia[(1, 2)] == 0.0
            && inertia[(1, 0)] == 0.0
            && inertia[(2, 0)] == 0.0
            && inertia[(2, 1)] == 0.0;
        if off_diagonal_zero {
            return Self {
                moments: inertia.diagonal(),
                axes_b: Rotation3::identity(),
            };
        }
        let eigen = SymmetricEigen::new(*inertia);
        let mut order = [0usize, 1, 2];
        order.sort_by(|&a, &b| eigen.eigenvalues[a].total_cmp(&eigen.eigenvalues[b]));
        let moments = Vector3::from_fn(|i, _| eigen.eigenvalues[order[i]]);
        let mut axes = Matrix3::from_fn(|r, c| eigen.eigenvectors[(r, order[c])]);
        if axes.determinant() < 0.0 {
            axes.set_column(2, &(-axes.column(2)));
        }
        Self {
            moments,
            axes_b: Rotation3::from_matrix_unchecked(axes),
        }
    }

    /// The angle (degrees) between `axis` (body axes) and the nearest principal direction, and the number (1-based)
    /// of that principal axis. Principal moments equal to 1e-9 relative span a plane (or all of space) of principal
    /// directions, and the angle is measured to that plane: every axis of a sphere is principal.
    pub fn tilt_of(&self, axis: &Vector3<f64>) -> (f64, usize) {
        let axis = axis.normalize();
        let m = self.moments;
        let scale = m.amax().max(f64::MIN_POSITIVE);
        let p = self.axes_b.matrix();
        // (angle, -|cos| to axis k itself, k): among axes at the same angle (a plane of equal moments), the one
        // closest to the axis is named.
        let mut best = (f64::INFINITY, 0.0, 1);
        for k in 0..3 {
            // The principal directions with the same moment as axis k: the projection of `axis` onto their span.
            let projection: f64 = (0..3)
                .filter(|&j| (m[j] - m[k]).abs() <= 1e-9 * scale)
                .map(|j| p.column(j).dot(&axis).powi(2))
                .sum();
            let angle = projection.sqrt().clamp(0.0, 1.0).acos().to_degrees();
            let own = -p.column(k).dot(&axis).abs();
            if angle < best.0 - 1e-9 || (angle <= best.0 + 1e-9 && own < best.1) {
                best = (angle, own, k + 1);
            }
        }
        (best.0, best.2)
    }
}

/// A rigid body: mass m and central inertia tensor I_C in body axes (origin at the mass center C).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RigidBody {
    mass: f64,
    inertia_c: Matrix3<f64>,
    principal: Principal,
}

impl RigidBody {
    /// Validates and builds a body: mass finite and > 0; tensor entries finite, symmetric (to 1e-12 of its largest
    /// entry), positive semi-definite, not zero, with principal moments satisfying the triangle inequality
    /// I_a + I_b ≥ I_c (to 1e-12 of the trace; equality is a planar body such as the thin disk).
    pub fn new(mass: f64, inertia_c: Matrix3<f64>) -> Result<Self, InvalidBody> {
        if !(mass.is_finite() && mass > 0.0) {
            return Err(InvalidBody::new(
                "mass",
                format!("must be a finite number > 0 (kg), got {mass:?}"),
            ));
        }
        if inertia_c.iter().any(|v| !v.is_finite()) {
            return Err(InvalidBody::new(
                "inertia",
                "every entry must be a finite number (kg*m^2)",
            ));
        }
        let scale = inertia_c.amax();
        if scale == 0.0 {
            return Err(InvalidBody::new(
                "inertia",
                "the inertia tensor is zero: a body needs a nonzero moment of inertia",
            ));
        }
        let tol = 1e-12 * scale;
        for (r, c) in [(0, 1), (0, 2), (1, 2)] {
            if (inertia_c[(r, c)] - inertia_c[(c, r)]).abs() > tol {
                return Err(InvalidBody::new(
                    "inertia",
                    format!(
                        "the tensor must be symmetric: entry [{r}][{c}] = {} but [{c}][{r}] = {}",
                        inertia_c[(r, c)],
                        inertia_c[(c, r)]
                    ),
                ));
            }
        }
        let symmetric = (inertia_c + inertia_c.transpose()) * 0.5;
        let principal = Principal::of(&symmetric);
        let m = principal.moments;
        let trace_tol = 1e-12 * m.iter().map(|v| v.abs()).sum::<f64>();
        if m.iter().any(|&v| v < -trace_tol) {
            return Err(InvalidBody::new(
                "inertia",
                format!(
                    "the tensor must be positive semi-definite; its principal moments are ({}, {}, {})",
                    m[0], m[1], m[2]
                ),
            ));
        }
        for i in 0..3 {
            let (a, b, c) = (m[i], m[(i + 1) % 3], m[(i + 2) % 3]);
            if a + b < c - trace_tol {
                return Err(InvalidBody::new(
                    "inertia",
                    format!(
                        "principal moments ({}, {}, {}) violate the triangle inequality {a} + {b} >= {c}: no mass distribution has them",
                        m[0], m[1], m[2]
                    ),
                ));
            }
        }
        Ok(Self {
            mass,
            inertia_c: symmetric,
            principal,
        })
    }

    /// A body from a shape ([`Shape::inertia_c`]).
    pub fn from_shape(mass: f64, shape: Shape) -> Result<Self, InvalidBody> {
        if !(mass.is_finite() && mass > 0.0) {
            return Err(InvalidBody::new(
                "mass",
                format!("must be a finite number > 0 (kg), got {mass:?}"),
            ));
        }
        Self::new(mass, shape.inertia_c(mass)?)
    }

    /// A body whose body axes are principal, I_C = diag(i1, i2, i3).
    pub fn from_principal(mass: f64, moments: [f64; 3]) -> Result<Self, InvalidBody> {
        Self::new(mass, Matrix3::from_diagonal(&Vector3::from(moments)))
    }

    /// Mass m (kg).
    pub fn mass(&self) -> f64 {
        self.mass
    }

    /// Central inertia tensor I_C in body axes (kg·m²).
    pub fn inertia_c(&self) -> &Matrix3<f64> {
        &self.inertia_c
    }

    /// Principal moments and axes of I_C.
    pub fn principal(&self) -> &Principal {
        &self.principal
    }

    /// The body with point masses attached: `masses` are (m_k, p_k) with p_k from this body's mass center (body
    /// axes). Returns the whole body — mass M = m + Σ m_k, inertia about its mass center C' — and the position c of
    /// C' from this body's mass center: c = Σ m_k p_k / M, and by the parallel-axis theorem (eq. 8.4's I_A)
    /// I_C' = I_C + m (|c|² E − c cᵀ) + Σ m_k (|p_k − c|² E − (p_k − c)(p_k − c)ᵀ).
    ///
    /// ```
    /// use eulerdyn::body::RigidBody;
    /// use nalgebra::Vector3;
    /// let disk = RigidBody::from_principal(2.0, [0.045, 0.045, 0.09]).unwrap();
    /// let (whole, c) = disk.with_point_masses(&[(0.5, Vector3::new(0.1, 0.0, 0.0))]).unwrap();
    /// assert_eq!(whole.mass(), 2.5);
    /// assert!((c - Vector3::new(0.02, 0.0, 0.0)).norm() < 1e-16);
    /// ```
    pub fn with_point_masses(
        &self,
        masses: &[(f64, Vector3<f64>)],
    ) -> Result<(RigidBody, Vector3<f64>), InvalidBody> {
        let total = self.mass + masses.iter().map(|(m, _)| m).sum::<f64>();
        let c = masses.iter().map(|(m, p)| p * *m).sum::<Vector3<f64>>() / total;
        let steiner = |m: f64, rho: &Vector3<f64>| {
            (Matrix3::identity() * rho.norm_squared() - rho * rho.transpose()) * m
        };
        let inertia = masses
            .iter()
            .fold(self.inertia_c + steiner(self.mass, &c), |sum, (m, p)| {
                sum + steiner(*m, &(p - c))
            });
        Ok((RigidBody::new(total, inertia)?, c))
    }

    /// Inertia tensor about the body point A, by the parallel-axis theorem:
    /// I_A = I_C + m (|ρ|² E − ρ ρᵀ), ρ = r_C − r_A (Steiner; the notes' eq. 7.x, used in 8.4).
    /// `rho_c_b` is the position of C relative to A, in body axes.
    pub fn inertia_about(&self, rho_c_b: &Vector3<f64>) -> Matrix3<f64> {
        self.inertia_c
            + (Matrix3::identity() * rho_c_b.norm_squared() - rho_c_b * rho_c_b.transpose())
                * self.mass
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn principal(moments: [f64; 3]) -> Principal {
        Principal {
            moments: Vector3::from(moments),
            axes_b: Rotation3::identity(),
        }
    }

    #[test]
    fn the_tilt_is_measured_to_the_nearest_principal_axis() {
        let disk = principal([1.0, 1.0, 2.0]);
        let tilt = 30f64.to_radians();
        let (angle, k) = disk.tilt_of(&Vector3::new(0.0, -tilt.sin(), tilt.cos()));
        assert!((angle - 30.0).abs() < 1e-9, "{angle}");
        assert_eq!(k, 3);
        // 60 deg from the symmetry axis is 30 deg from the plane of equal moments, whatever its azimuth.
        let a = 60f64.to_radians();
        let axis = Vector3::new(a.sin() * 0.6, a.sin() * 0.8, a.cos());
        let (angle, k) = disk.tilt_of(&axis);
        assert!((angle - 30.0).abs() < 1e-9, "{angle}");
        // Of the axes in that plane, the one nearer the axis is named.
        assert_eq!(k, 2);
        // Along an axis of the plane of equal moments: that axis is named.
        let (angle, k) = disk.tilt_of(&Vector3::new(0.0, 0.0, -1.0));
        assert!(angle < 1e-6 && k == 3, "{angle} {k}");
        let (angle, k) = disk.tilt_of(&Vector3::new(0.0, 2.0, 0.0));
        assert!(angle < 1e-6 && k == 2, "{angle} {k}");
    }

    #[test]
    fn every_axis_of_a_sphere_is_principal() {
        let sphere = principal([2.0, 2.0, 2.0]);
        let (angle, _) = sphere.tilt_of(&Vector3::new(1.0, 2.0, 3.0));
        assert!(angle < 1e-6, "{angle}");
    }
}
