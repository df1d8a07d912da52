//! A carrier's typed keys: what `carrier = { … }` in `[motion]` says, before validation.

use crate::profile::Profile;

/// `carrier = { rate = [x, y, z], profile = "constant" | "sine", freq_hz, phase_deg }`: a carrier turning about a
/// space axis through the axis point at the angular velocity `rate`·p(t) (rad/s, space axes), aligned with space
/// at t = 0.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct CarrierSpec {
    /// `rate`: r (rad/s, space axes).
    pub rate: [f64; 3],
    /// `profile` and its keys (absent: constant).
    pub profile: Profile,
    /// `center`, `accel`, `accel_profile`: the carrier is a vehicle (absent: it turns about the axis point, which
    /// stays fixed).
    pub vehicle: Option<VehicleSpec>,
}

/// A carrier's `center`, `accel` and `accel_profile` ([`super::vehicle`]).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct VehicleSpec {
    /// `center`: the point the carrier turns about, from the axis point at t = 0, space axes (m; absent: 0).
    pub center: [f64; 3],
    /// `accel`: the vehicle's linear acceleration, space axes (m/s²; absent: 0).
    pub accel: [f64; 3],
    /// `accel_profile` (absent: constant); a sine shares the carrier's `freq_hz` and `phase_deg`.
    pub accel_profile: Profile,
}

impl CarrierSpec {
    /// A carrier turning at the constant `rate` (rad/s, space axes).
    ///
    /// ```
    /// use eulerdyn::{profile::Profile, scene::CarrierSpec};
    /// let yaw = CarrierSpec::constant([0.0, 0.0, 0.5]);
    /// assert_eq!(yaw.profile, Profile::Constant);
    /// ```
    pub fn constant(rate: [f64; 3]) -> Self {
        Self {
            rate,
            profile: Profile::Constant,
            vehicle: None,
        }
    }

    /// A carrier rolling at `rate`·sin(2π `freq_hz` t + `phase_deg`).
    ///
    /// ```
    /// use eulerdyn::{profile::Profile, scene::CarrierSpec};
    /// let roll = CarrierSpec::sine([0.2, 0.0, 0.0], 0.1, 0.0);
    /// assert_eq!(roll.profile, Profile::Sine { freq_hz: 0.1, phase_deg: 0.0 });
    /// ```
    pub fn sine(rate: [f64; 3], freq_hz: f64, phase_deg: f64) -> Self {
        Self {
            rate,
            profile: Profile::Sine { freq_hz, phase_deg },
            vehicle: None,
        }
    }

    /// The same carrier as a vehicle ([`VehicleSpec`]).
    ///
    /// ```
    /// use eulerdyn::{profile::Profile, scene::{CarrierSpec, VehicleSpec}};
    /// let turn = CarrierSpec::constant([0.0, 0.0, 0.3]).with_vehicle(VehicleSpec {
    ///     center: [0.0, 12.0, 0.0],
    ///     accel: [0.0; 3],
    ///     accel_profile: Profile::Constant,
    /// });
    /// assert_eq!(turn.vehicle.unwrap().center, [0.0, 12.0, 0.0]);
    /// ```
    pub fn with_vehicle(mut self, vehicle: VehicleSpec) -> Self {
        self.vehicle = Some(vehicle);
        self
    }
}
