//! The Earth's magnetic field as a centred dipole (`[[effect]] type = "magnetic"`): B(r) = B₀ (R/r)³ (m̂ − 3(m̂·r̂) r̂),
//! m̂ the dipole's axis toward geographic north — along the Earth's axis, or tilted from it and turning with the
//! Earth. On the equator of an aligned dipole B = B₀ (R/r)³ northward; over a pole 2B₀ (R/r)³, inward (Jackson,
//! *Classical Electrodynamics*, 3rd ed., eq. 5.56, for the Earth's moment pointing south; Wertz, *Spacecraft
//! Attitude Determination and Control*, 1978, appendix H).

use nalgebra::{Rotation3, Vector3};

use super::R_EARTH;

/// The Earth's rotation rate (rad/s, sidereal: IERS).
pub const EARTH_RATE: f64 = 7.2921159e-5;

/// The field's strength on the equator at the Earth's surface when a scene does not give it (T).
pub const DEFAULT_B0: f64 = 3.12e-5;

/// A centred dipole field: its strength B₀ on the equator at the surface (T) and its north axis in space at t = 0,
/// turning with the Earth about z when it is tilted.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct DipoleField {
    b0: f64,
    axis0_s: Vector3<f64>,
}

impl DipoleField {
    /// The field of strength `b0` (T) whose axis is tilted by `tilt` from the Earth's (rad), toward longitude `lon`
    /// (rad, from space x at t = 0).
    ///
    /// ```
    /// use eulerdyn::orbit::{DipoleField, R_EARTH};
    /// use nalgebra::Vector3;
    /// let field = DipoleField::new(3.12e-5, 0.0, 0.0);
    /// let b = field.b_s(&Vector3::new(R_EARTH, 0.0, 0.0), 0.0);
    /// assert!((b - Vector3::new(0.0, 0.0, 3.12e-5)).norm() < 1e-20); // on the equator: B₀, northward
    /// ```
    pub fn new(b0: f64, tilt: f64, lon: f64) -> Self {
        DipoleField {
            b0,
            axis0_s: Vector3::new(tilt.sin() * lon.cos(), tilt.sin() * lon.sin(), tilt.cos()),
        }
    }

    /// The dipole's north axis at time `t` (s): turned by the Earth's rotation about z.
    pub fn axis_s(&self, t: f64) -> Vector3<f64> {
        if self.axis0_s.x == 0.0 && self.axis0_s.y == 0.0 {
            return self.axis0_s;
        }
        Rotation3::from_axis_angle(&Vector3::z_axis(), EARTH_RATE * t) * self.axis0_s
    }

    /// The largest |B| on an orbit of radius `radius` (m): 2B₀ (R/r)³, over a pole of the dipole.
    pub fn largest_b(&self, radius: f64) -> f64 {
        2.0 * self.b0 * (R_EARTH / radius).powi(3)
    }

    /// B₀ (T).
    pub fn b0(&self) -> f64 {
        self.b0
    }

    /// B at the position `r_s` (m, space axes) at time `t` (T): B₀ (R/r)³ (m̂ − 3(m̂·r̂) r̂).
    pub fn b_s(&self, r_s: &Vector3<f64>, t: f64) -> Vector3<f64> {
        let r = r_s.norm();
        let r_hat = r_s / r;
        let m_hat = self.axis_s(t);
        (m_hat - r_hat * (3.0 * m_hat.dot(&r_hat))) * (self.b0 * (R_EARTH / r).powi(3))
    }
}
