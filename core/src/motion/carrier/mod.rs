//! A carrier — a vehicle, ship or housing — that holds a fixed axis and its bearings and turns about a space
//! axis through the axis point A, so that A stays fixed in space:
//!
//! ```text
//!   Ω_c(t) = r p(t),   p = 1 (constant) or sin(ω_f t + φ) (sine),   R_c(t) = Rot(r̂, |r| ψ(t)),  ψ = ∫₀ᵗ p,
//! ```
//!
//! with r the rate vector in space axes; the carrier starts aligned with space (R_c(0) = E). Because Ω_c keeps its
//! direction, its attitude is one rotation about r̂ by |r|ψ(t), in closed form:
//! ψ = t (constant) or ψ = (cos φ − cos(ω_f t + φ))/ω_f = 2 sin(ω_f t/2 + φ) sin(ω_f t/2)/ω_f (sine; the product
//! form has no cancellation at small ω_f t).
//!
//! A carrier that is a vehicle ([`vehicle`]) turns about a point of its own and accelerates; its axis point A then
//! accelerates at a_A (its attitude, rate and angular acceleration are the same).

mod columns;
mod describe;
pub(crate) mod keys;
pub mod spec;
pub mod vehicle;

use std::any::Any;

use nalgebra::{UnitQuaternion, Vector3};

use crate::frames::Vector;
use crate::motion::moving_support::{MovingSupport, SupportMotion};
use crate::profile::Profile;
use crate::sample::ColumnGroup;
use crate::text::Description;
pub use columns::columns;
use vehicle::Vehicle;

/// A carrier turning about the space axis of `rate_s` at the rate `rate_s`·p(t): a [`MovingSupport`].
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Carrier {
    rate_s: Vector3<f64>,
    profile: Profile,
    /// The vehicle's centre and acceleration; `None`: the carrier turns about A, which stays fixed.
    vehicle: Option<Vehicle>,
}

impl Carrier {
    /// A carrier turning at `rate_s` (rad/s, space axes) times the `profile`.
    ///
    /// ```
    /// use eulerdyn::motion::carrier::Carrier;
    /// use eulerdyn::motion::moving_support::MovingSupport;
    /// use eulerdyn::profile::Profile;
    /// use nalgebra::Vector3;
    /// // A quarter turn about z in one second.
    /// let yaw = Carrier::new(Vector3::new(0.0, 0.0, std::f64::consts::FRAC_PI_2), Profile::Constant);
    /// let x_s = yaw.at(1.0).q_c * Vector3::x();
    /// assert!((x_s - Vector3::y()).norm() < 1e-15);
    /// ```
    pub fn new(rate_s: Vector3<f64>, profile: Profile) -> Self {
        Self {
            rate_s,
            profile,
            vehicle: None,
        }
    }

    /// The same carrier as a `vehicle` that turns about its own centre and accelerates.
    ///
    /// ```
    /// use eulerdyn::motion::carrier::{Carrier, vehicle::Vehicle};
    /// use eulerdyn::motion::moving_support::MovingSupport;
    /// use eulerdyn::profile::Profile;
    /// use nalgebra::Vector3;
    /// // Yawing at 2 rad/s: about A itself, A stays put; about a centre 3 m along y, A feels Ω² r = 12 m/s².
    /// let yaw = Carrier::new(Vector3::new(0.0, 0.0, 2.0), Profile::Constant);
    /// assert!(yaw.vehicle().is_none() && yaw.at(0.0).accel_a_s.is_none());
    /// let centre = Vector3::new(0.0, 3.0, 0.0);
    /// let car = yaw.with_vehicle(Vehicle::new(centre, Vector3::zeros(), Profile::Constant));
    /// assert_eq!(car.vehicle().map(Vehicle::center_s), Some(&centre));
    /// assert!((*car.at(0.0).accel_a_s.unwrap() - Vector3::new(0.0, 12.0, 0.0)).norm() < 1e-14);
    /// ```
    pub fn with_vehicle(mut self, vehicle: Vehicle) -> Self {
        self.vehicle = Some(vehicle);
        self
    }

    /// The vehicle, if the carrier is one.
    pub fn vehicle(&self) -> Option<&Vehicle> {
        self.vehicle.as_ref()
    }

    /// The rate vector r (rad/s, space axes) the profile multiplies.
    pub fn rate_s(&self) -> &Vector3<f64> {
        &self.rate_s
    }

    /// The profile.
    pub fn profile(&self) -> Profile {
        self.profile
    }
}

impl MovingSupport for Carrier {
    /// R_c(t) = exp(ψ(t) r̂) with ψ = ∫₀ᵗ p, Ω_c(t) = r p(t), Ω̇_c(t) = r p'(t) (a step's jumps left out) and, in a
    /// vehicle, a_A(t).
    fn at(&self, t: f64) -> SupportMotion {
        let (p, p_dot, psi) = match (self.profile, self.profile.sine_rad()) {
            (_, Some((omega_f, phase))) => {
                let (s, c) = (omega_f * t + phase).sin_cos();
                let psi = if omega_f == 0.0 {
                    t * phase.sin()
                } else {
                    let half = 0.5 * omega_f * t;
                    2.0 * (half + phase).sin() * half.sin() / omega_f
                };
                (s, omega_f * c, psi)
            }
            (Profile::Step { t_on, t_off }, None) => {
                (self.profile.at(t), 0.0, (t.min(t_off) - t_on).max(0.0))
            }
            _ => (1.0, 0.0, t),
        };
        let (q_c, omega_c_s, omega_c_dot_s) = (
            UnitQuaternion::from_scaled_axis(self.rate_s * psi),
            self.rate_s * p,
            self.rate_s * p_dot,
        );
        SupportMotion {
            q_c,
            omega_c_s: Vector::new(omega_c_s),
            omega_c_dot_s: Vector::new(omega_c_dot_s),
            accel_a_s: (self.vehicle.as_ref())
                .map(|v| Vector::new(v.accel_a_s(t, &q_c, &omega_c_s, &omega_c_dot_s))),
        }
    }

    /// |r| max|p| = |r| (every profile's |p| ≤ 1).
    fn largest_rate(&self) -> f64 {
        self.rate_s.norm()
    }

    fn describe(&self, mass: f64, w: &mut Description) {
        describe::lines(self, mass, w);
    }

    fn columns(&self) -> ColumnGroup {
        columns::columns()
    }

    fn as_any(&self) -> &dyn Any {
        self
    }

    fn same_as(&self, other: &dyn MovingSupport) -> bool {
        other.as_any().downcast_ref::<Self>() == Some(self)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use approx::assert_relative_eq;

    /// The attitude's derivative is Ω_c: (R_c(t + h) − R_c(t − h))/2h ≈ Ω̂_c R_c, and Ω̇_c is p' r (central
    /// differences, error O(h²)).
    #[test]
    fn sine_carrier_attitude_and_rate_agree() {
        let carrier = Carrier::new(
            Vector3::new(0.1, -0.2, 0.3),
            Profile::Sine {
                freq_hz: 1.7 / std::f64::consts::TAU,
                phase_deg: 0.4f64.to_degrees(),
            },
        );
        let (t, h) = (2.3, 1e-5);
        let r = |t: f64| carrier.at(t).q_c.to_rotation_matrix().into_inner();
        let now = carrier.at(t);
        let r_dot = (r(t + h) - r(t - h)) / (2.0 * h);
        assert_relative_eq!(r_dot, now.omega_c_s.cross_matrix() * r(t), epsilon = 1e-9);
        let rate_dot = (carrier.at(t + h).omega_c_s - carrier.at(t - h).omega_c_s) / (2.0 * h);
        assert_relative_eq!(*rate_dot, *now.omega_c_dot_s, epsilon = 1e-9);
    }

    /// Two supports are equal through the trait when they are the same kind with equal values (what `FixedAxis`'s
    /// equality asks).
    #[test]
    fn supports_compare_by_kind_and_value() {
        let yaw = |rate| Carrier::new(Vector3::new(0.0, 0.0, rate), Profile::Constant);
        let (a, b, c) = (yaw(0.5), yaw(0.5), yaw(0.6));
        let (a, b, c): (&dyn MovingSupport, &dyn MovingSupport, &dyn MovingSupport) = (&a, &b, &c);
        assert!(a == b && a != c);
    }

    /// A step profile turns the carrier by ψ = ∫₀ᵗ p = clamp(t, t_on, t_off) − t_on about r̂, at r while on.
    #[test]
    fn a_step_carrier_turns_while_it_is_on() {
        let rate_s = Vector3::new(0.0, 0.0, 0.5);
        let carrier = Carrier::new(
            rate_s,
            Profile::Step {
                t_on: 1.0,
                t_off: 2.0,
            },
        );
        for (t, psi, on) in [(0.5, 0.0, 0.0), (1.5, 0.5, 1.0), (3.0, 1.0, 0.0)] {
            let now = carrier.at(t);
            assert_relative_eq!(now.q_c.angle(), 0.5 * psi, epsilon = 1e-15);
            assert_eq!(*now.omega_c_s, rate_s * on);
        }
    }
}
