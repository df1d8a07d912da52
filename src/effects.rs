//! The effects a scene may call for. Only the effects a scene lists are simulated; none means torque-free.

use nalgebra::Vector3;

use crate::model::Frame;

/// Time profile of an applied torque.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum TorqueProfile {
    /// M(t) = value.
    Constant,
    /// M(t) = value · sin(2π f t + φ).
    Sine { freq_hz: f64, phase_rad: f64 },
    /// M(t) = value for t_on ≤ t < t_off, else 0.
    Step { t_on: f64, t_off: f64 },
}

impl TorqueProfile {
    /// The factor multiplying the torque's value at time t.
    pub fn factor(&self, t: f64) -> f64 {
        match *self {
            TorqueProfile::Constant => 1.0,
            TorqueProfile::Sine { freq_hz, phase_rad } => {
                (2.0 * std::f64::consts::PI * freq_hz * t + phase_rad).sin()
            }
            TorqueProfile::Step { t_on, t_off } => {
                if t_on <= t && t < t_off {
                    1.0
                } else {
                    0.0
                }
            }
        }
    }
}

/// One effect of the scene's `[[effect]]` list, validated.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Effect {
    /// An applied torque (N·m), given in body or space axes, with a time profile.
    Torque {
        frame: Frame,
        value: Vector3<f64>,
        profile: TorqueProfile,
    },
    /// Uniform gravity g (space axes, m/s²) acting at C while the body turns about a fixed pivot
    /// (body axes, relative to C); the pivot becomes the moment center.
    Gravity {
        g_s: Vector3<f64>,
        pivot_b: Vector3<f64>,
    },
    /// Viscous damping M = −c ω (N·m·s).
    Damping { c: f64 },
}

impl Effect {
    /// The name used in scene files.
    pub fn kind(&self) -> &'static str {
        match self {
            Effect::Torque { .. } => "torque",
            Effect::Gravity { .. } => "gravity",
            Effect::Damping { .. } => "damping",
        }
    }
}
