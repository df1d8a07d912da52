//! Spin about a principal axis under viscous damping M = −c·ω, in closed form.
//!
//! With ω along a principal axis of moment I, H = I·ω stays along that axis and Euler's equation reduces to
//! I·ω̇ = −c·ω, whose solution is
//!
//! ```text
//!   ω(t) = ω(0)·exp(−c t / I),   turned angle φ(t) = |ω(0)|·I/c·(1 − exp(−c t / I)),
//! ```
//!
//! a rotation about the fixed axis (fixed in the body and in space). Frames: `_b` body axes, `_s` space axes; the
//! attitude maps body to space axes (`v_s = q * v_b`).

use nalgebra::{Unit, UnitQuaternion, Vector3};

use super::ExactError;

/// A body spinning about a principal axis of moment `inertia` under the damping moment M = −c·ω.
#[derive(Debug, Clone, PartialEq)]
pub struct DampedSpin {
    omega0_b: Vector3<f64>,
    inertia: f64,
    c: f64,
    q0: UnitQuaternion<f64>,
}

/// The closed-form state of a [`DampedSpin`] at one time.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct DampedSpinState {
    /// Angular velocity, body axes (rad/s).
    pub omega_b: Vector3<f64>,
    /// Attitude, body → space.
    pub q: UnitQuaternion<f64>,
    /// Moment of momentum, space axes (kg·m²/s).
    pub h_s: Vector3<f64>,
    /// |H| = I·|ω| (kg·m²/s).
    pub h_norm: f64,
    /// Kinetic energy ½·I·|ω|² (J).
    pub energy: f64,
}

impl DampedSpin {
    /// `omega0_b` the initial angular velocity (body axes, along a principal axis: not checked), `inertia` the
    /// moment about that axis, `c` the damping coefficient (N·m·s), `q0` the initial attitude (body → space).
    /// Errors on non-finite input, a zero ω(0), or a non-positive moment or coefficient.
    pub fn new(
        omega0_b: Vector3<f64>,
        inertia: f64,
        c: f64,
        q0: UnitQuaternion<f64>,
    ) -> Result<Self, ExactError> {
        if !(omega0_b.iter().all(|v| v.is_finite()) && inertia.is_finite() && c.is_finite()) {
            return Err(ExactError::NonFinite("damped spin"));
        }
        for (what, value) in [
            ("moment of inertia", inertia),
            ("damping coefficient", c),
            ("|omega(0)|", omega0_b.norm()),
        ] {
            if value <= 0.0 {
                return Err(ExactError::NonPositive { what, value });
            }
        }
        Ok(Self {
            omega0_b,
            inertia,
            c,
            q0,
        })
    }

    /// The state at time `t`: ω(t) = ω(0)·exp(−c t / I), the attitude turned by φ(t) about the axis.
    pub fn at(&self, t: f64) -> DampedSpinState {
        let (inertia, c) = (self.inertia, self.c);
        let decay = (-c * t / inertia).exp();
        let w0 = self.omega0_b.norm();
        let turned = w0 * inertia / c * (-(-c * t / inertia).exp_m1());
        let axis = Unit::new_normalize(self.omega0_b);
        let q = self.q0 * UnitQuaternion::from_axis_angle(&axis, turned);
        DampedSpinState {
            omega_b: self.omega0_b * decay,
            q,
            h_s: q * (self.omega0_b * (inertia * decay)),
            h_norm: inertia * w0 * decay,
            energy: 0.5 * inertia * w0 * w0 * decay * decay,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_spin_decays_exponentially_about_its_fixed_axis() {
        let spin = DampedSpin::new(
            Vector3::new(0.0, 0.0, 2.0),
            3.0,
            0.6,
            UnitQuaternion::identity(),
        )
        .expect("valid");
        let t = 5.0;
        let s = spin.at(t);
        let decay = (-0.6 * t / 3.0f64).exp();
        assert!((s.omega_b.z - 2.0 * decay).abs() < 1e-15);
        // φ(t) = |ω(0)|·I/c·(1 − exp(−c t / I)), about z.
        let turned = 2.0 * 3.0 / 0.6 * (1.0 - decay);
        let expected = UnitQuaternion::from_axis_angle(&Vector3::z_axis(), turned);
        assert!(s.q.angle_to(&expected) < 1e-12);
        assert!((s.h_norm - 3.0 * 2.0 * decay).abs() < 1e-15);
        assert!((s.energy - 0.5 * 3.0 * (2.0 * decay).powi(2)).abs() < 1e-14);
        assert!(DampedSpin::new(Vector3::zeros(), 3.0, 0.6, UnitQuaternion::identity()).is_err());
        assert!(DampedSpin::new(Vector3::z(), 3.0, 0.0, UnitQuaternion::identity()).is_err());
    }
}
