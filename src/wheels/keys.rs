//! A wheel's keys in `[[body.rotor]]`: `max_torque`, `max_speed_rpm`, `friction = { coulomb, viscous, stribeck =
//! { torque, speed } }` and `mode = "free"` (the scene file's form and the typed spec are the same types).

use serde::{Deserialize, Serialize};

/// `friction.stribeck`: the extra breakaway torque (N·m) and the speed over which it fades (rad/s).
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct StribeckKeys {
    /// N·m.
    pub torque: f64,
    /// rad/s.
    pub speed: f64,
}

/// `friction`: Coulomb (N·m), viscous (N·m·s) and Stribeck friction, each absent as zero.
#[derive(Debug, Clone, Copy, PartialEq, Default, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct FrictionKeys {
    #[serde(default, skip_serializing_if = "Option::is_none")]
    /// Coulomb level (N·m).
    pub coulomb: Option<f64>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    /// Viscous coefficient (N·m·s).
    pub viscous: Option<f64>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    /// Stribeck breakaway.
    pub stribeck: Option<StribeckKeys>,
}

/// `mode`: `"free"`, a wheel without a motor.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum WheelMode {
    /// No motor: the wheel spins freely.
    Free,
}

/// A wheel's limits and friction as the scene gives them (absent: none).
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct WheelKeys {
    /// `max_torque` (N·m, > 0).
    pub max_torque: Option<f64>,
    /// `max_speed_rpm` (rpm, > 0): the limit of the relative spin.
    pub max_speed_rpm: Option<f64>,
    /// `friction`.
    pub friction: Option<FrictionKeys>,
}
