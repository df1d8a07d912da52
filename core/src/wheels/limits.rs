//! A wheel's limits and friction as `[[body.rotor]]` gives them: `max_torque`, `max_speed_rpm` and
//! `friction = { coulomb, viscous, stribeck = { torque, speed } }` (the scene file's form and the typed spec are
//! the same types; `mode = "free"` is [`WheelMode`]), and their validation into a [`WheelControl`].

use serde::{Deserialize, Serialize};

use super::{Friction, RPM, WheelControl};
use crate::keys::{Checked, KeyPath, Keys, finite, invalid, positive};

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
#[derive(Debug, Clone, Copy, PartialEq, Default, Keys)]
pub struct WheelKeys {
    /// > 0: the motor torque is clipped to ±max_torque (`<name>_torque_cmd` keeps the command)
    #[key(unit = "N·m")]
    pub max_torque: Option<f64>,
    /// > 0: the relative spin's limit (the initial spin must be within it); at it the motor can only slow the wheel
    #[key(unit = "rpm")]
    pub max_speed_rpm: Option<f64>,
    /// friction opposing the relative spin: τ_f = −(coulomb + stribeck.torque·exp(−(Ω/stribeck.speed)²))·sign(Ω) − viscous·Ω
    #[key(
        kind = "{ coulomb, viscous, stribeck = { torque, speed } }",
        unit = "N·m, N·m·s, (N·m, rad/s)"
    )]
    pub friction: Option<FrictionKeys>,
}

impl WheelKeys {
    /// The wheel's limits and friction, validated at `table` (its `[[body.rotor]]`): `max_torque` (N·m) and
    /// `max_speed_rpm` > 0, each friction level ≥ 0 and the Stribeck speed > 0. A limit needs a motor that a law or
    /// a table may command: `motorless` says why the wheel has none (`spin_accel`, `mode = "free"`).
    pub(crate) fn validate(
        &self,
        table: &KeyPath,
        motorless: Option<&str>,
    ) -> Checked<WheelControl> {
        let key = |name: &str| table.clone().key(name);
        let limits = [
            ("max_torque", self.max_torque, "N*m"),
            ("max_speed_rpm", self.max_speed_rpm, "rpm"),
        ];
        for (name, value, unit) in limits {
            let Some(value) = value else { continue };
            positive(key(name), value, unit)?;
            if let Some(why) = motorless {
                return invalid(
                    key(name),
                    format!("`{name}` limits a wheel's motor, but {why}"),
                );
            }
        }
        Ok(WheelControl {
            max_torque: self.max_torque.unwrap_or(f64::INFINITY),
            max_speed: self.max_speed_rpm.map_or(f64::INFINITY, |rpm| rpm * RPM),
            friction: self
                .friction
                .unwrap_or_default()
                .validate(&key("friction"))?,
        })
    }
}

impl FrictionKeys {
    /// The friction, validated at `at` (the `friction` key): each level ≥ 0 (absent: 0), the Stribeck speed > 0.
    fn validate(&self, at: &KeyPath) -> Checked<Friction> {
        let at_least_zero = |name: KeyPath, v: Option<f64>, unit: &str| -> Checked<f64> {
            let v = finite(name.clone(), v.unwrap_or(0.0), unit)?;
            if v < 0.0 {
                return invalid(name, format!("must be >= 0 ({unit}), got {v}"));
            }
            Ok(v)
        };
        let mut friction = Friction {
            coulomb: at_least_zero(at.clone().key("coulomb"), self.coulomb, "N*m")?,
            viscous: at_least_zero(at.clone().key("viscous"), self.viscous, "N*m*s")?,
            ..Friction::default()
        };
        if let Some(stribeck) = self.stribeck {
            let at = at.clone().key("stribeck");
            friction.stribeck_torque =
                at_least_zero(at.clone().key("torque"), Some(stribeck.torque), "N*m")?;
            friction.stribeck_speed = positive(at.key("speed"), stribeck.speed, "rad/s")?;
        }
        Ok(friction)
    }
}
