//! A carrier that is a vehicle (`motion.carrier`'s `center` and `accel`): it turns about a point D of its own
//! instead of the axis point A, and it accelerates. The body's rotation about A is unchanged; A accelerates at
//!
//! ```text
//!   a_A(t) = a_v(t) + Ω̇_c × r + Ω_c × (Ω_c × r),   r = R_c(t) r₀,   r₀ = −d₀,
//!   a_v(t) = a p_a(t),   p_a = 1 (constant) or sin(ω_f t + φ) (sine),
//! ```
//!
//! with d₀ the centre D from A at t = 0 (space axes; D is fixed in the vehicle, so r from D to A turns with the
//! carrier) and a the vehicle's own linear acceleration (space axes) — the acceleration of a point of a rigid frame
//! (Rigid-body dynamics, lecture notes: the derivative of a vector fixed in a turning frame, ṙ = Ω × r, twice).
//! The support then carries m a_A besides the weight and the gyroscopic couple (see [`crate::motion::fixed_axis`]).

use nalgebra::{UnitQuaternion, Vector3};

use crate::profile::Profile;

/// The vehicle: its centre of rotation (from the axis point at t = 0, space axes) and its own acceleration.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Vehicle {
    /// d₀: the centre D from the axis point A at t = 0, space axes (m).
    center_s: Vector3<f64>,
    /// a: the vehicle's linear acceleration, space axes (m/s²), times `profile`.
    accel_s: Vector3<f64>,
    /// p_a(t).
    profile: Profile,
}

impl Vehicle {
    /// A vehicle turning about `center_s` (m, from the axis point at t = 0, space axes) and accelerating at
    /// `accel_s` (m/s², space axes) times `profile`.
    ///
    /// ```
    /// use eulerdyn::motion::carrier::vehicle::Vehicle;
    /// use eulerdyn::profile::Profile;
    /// use nalgebra::{UnitQuaternion, Vector3};
    /// // Turning at 2 rad/s about a centre 3 m along y: A feels Ω² r = 12 m/s² toward the centre.
    /// let v = Vehicle::new(Vector3::new(0.0, 3.0, 0.0), Vector3::zeros(), Profile::Constant);
    /// let a_a = v.accel_a_s(0.0, &UnitQuaternion::identity(), &Vector3::new(0.0, 0.0, 2.0), &Vector3::zeros());
    /// assert!((a_a - Vector3::new(0.0, 12.0, 0.0)).norm() < 1e-14);
    /// ```
    pub fn new(center_s: Vector3<f64>, accel_s: Vector3<f64>, profile: Profile) -> Self {
        Self {
            center_s,
            accel_s,
            profile,
        }
    }

    /// d₀: the centre from the axis point at t = 0, space axes (m).
    pub fn center_s(&self) -> &Vector3<f64> {
        &self.center_s
    }

    /// a: the acceleration the profile multiplies, space axes (m/s²).
    pub fn accel_s(&self) -> &Vector3<f64> {
        &self.accel_s
    }

    /// p_a.
    pub fn profile(&self) -> Profile {
        self.profile
    }

    /// a_v(t) = a p_a(t), space axes.
    pub fn accel_v_s(&self, t: f64) -> Vector3<f64> {
        match self.profile {
            Profile::Constant => self.accel_s,
            _ => self.accel_s * self.profile.at(t),
        }
    }

    /// a_A(t) = a_v(t) + Ω̇_c × r + Ω_c × (Ω_c × r) with r = R_c(t)(−d₀), for the carrier's attitude `q_c`, rate
    /// `omega_c_s` and angular acceleration `omega_c_dot_s` at t (space axes).
    pub fn accel_a_s(
        &self,
        t: f64,
        q_c: &UnitQuaternion<f64>,
        omega_c_s: &Vector3<f64>,
        omega_c_dot_s: &Vector3<f64>,
    ) -> Vector3<f64> {
        let r_s = -(q_c * self.center_s);
        self.accel_v_s(t) + omega_c_dot_s.cross(&r_s) + omega_c_s.cross(&omega_c_s.cross(&r_s))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::motion::carrier::Carrier;
    use crate::motion::moving_support::MovingSupport;
    use approx::assert_relative_eq;

    /// a_A is the second derivative of A's position p_A(t) = D + R_c(t)(−d₀) + ½ a t² (constant a, D fixed in
    /// space): central differences (error O(h²) ≈ 1e-8 here, and round-off |p|·1e-16/h² ≈ 1e-8).
    #[test]
    fn the_axis_point_accelerates_as_a_point_of_the_turning_vehicle() {
        let (center_s, accel_s) = (Vector3::new(1.0, -2.0, 0.5), Vector3::new(0.3, 0.0, -0.7));
        let carrier = Carrier::new(
            Vector3::new(0.1, -0.2, 0.3),
            Profile::Sine {
                freq_hz: 1.7 / std::f64::consts::TAU,
                phase_deg: 0.4f64.to_degrees(),
            },
        )
        .with_vehicle(Vehicle::new(center_s, accel_s, Profile::Constant));
        let p_a = |t: f64| center_s + carrier.at(t).q_c * (-center_s) + accel_s * (0.5 * t * t);
        let (t, h) = (2.3, 1e-4);
        let second = (p_a(t + h) - p_a(t) * 2.0 + p_a(t - h)) / (h * h);
        assert_relative_eq!(second, *carrier.at(t).accel_a_s.unwrap(), epsilon = 1e-6);
    }
}
