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
    /// dB/dt along a path through `r_s` at velocity `v_s` (m/s, space axes) at time `t` (T/s): the derivative of
    /// B = B₀R³ (m̂ r⁻³ − 3(m̂·r) r r⁻⁵) with ṙ = r̂·v and the axis turning with the Earth, ṁ̂ = Ω_E ẑ × m̂:
    /// Ḃ = B₀R³ [ṁ̂ r⁻³ − 3 m̂ ṙ r⁻⁴ − 3((ṁ̂·r + m̂·v) r + (m̂·r) v) r⁻⁵ + 15 (m̂·r) r ṙ r⁻⁶].
    pub fn b_rate_s(&self, r_s: &Vector3<f64>, v_s: &Vector3<f64>, t: f64) -> Vector3<f64> {
        let r = r_s.norm();
        let r_dot = r_s.dot(v_s) / r;
        let m_hat = self.axis_s(t);
        let m_hat_dot = Vector3::z().cross(&m_hat) * EARTH_RATE;
        let m_r = m_hat.dot(r_s);
        let m_r_dot = m_hat_dot.dot(r_s) + m_hat.dot(v_s);
        let k = self.b0 * R_EARTH.powi(3);
        (m_hat_dot / r.powi(3)
            - m_hat * (3.0 * r_dot / r.powi(4))
            - (r_s * m_r_dot + v_s * m_r) * (3.0 / r.powi(5))
            + r_s * (15.0 * m_r * r_dot / r.powi(6)))
            * k
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::orbit::CircularOrbit;

    #[test]
    fn the_fields_rate_along_an_orbit_is_the_derivative_of_the_field() {
        // Against the fourth-order central difference along a circular orbit, h = 0.5 s: the field turns at
        // harmonics of 2u, so the difference's error (h⁴/30)|B⁽⁵⁾| is about (2n h)⁴/30 ≈ 5e-14 of |Ḃ| (n ≈ 1.1e-3
        // rad/s; the Earth turns slower), its round-off u|B|/h about 2e-13 of it.
        let orbit = CircularOrbit::new(R_EARTH + 500e3, 0.9, 0.5, 0.2);
        for field in [
            DipoleField::new(3.12e-5, 0.0, 0.0),
            DipoleField::new(3.12e-5, 0.3, 1.2),
        ] {
            let b = |t: f64| field.b_s(&orbit.position_s(t), t);
            for t in [0.0, 700.0, 2100.0, 4000.0] {
                let h = 0.5;
                let difference =
                    (b(t - 2.0 * h) - b(t + 2.0 * h) + (b(t + h) - b(t - h)) * 8.0) / (12.0 * h);
                let (r_s, v_s) = orbit.position_and_velocity_s(t);
                let rate = field.b_rate_s(&r_s, &v_s, t);
                assert!(
                    (rate - difference).norm() <= 1e-11 * rate.norm(),
                    "t = {t}: {rate:?} vs {difference:?}"
                );
            }
        }
    }
}
