//! The typed choices an axis's either/or keys make (`axis` or `tilt_deg`, `rate` or `rate_rpm`), read and written
//! back by `[motion]`'s declaration (`keys.rs`).

/// The axis's direction in body axes.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum AxisDirection {
    /// `axis = [x, y, z]` (normalised by validation).
    Body([f64; 3]),
    /// `tilt_deg`: the axis (0, −sin θ, cos θ), tilted θ degrees from body z about body x.
    TiltDeg(f64),
}

/// θ̇ at t = 0.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum RateSpec {
    /// `rate`, rad/s.
    RadPerSecond(f64),
    /// `rate_rpm`, revolutions per minute (rate = rate_rpm · 2π/60).
    Rpm(f64),
}

impl RateSpec {
    /// The rate in rad/s.
    pub fn rad_per_second(&self) -> f64 {
        match *self {
            RateSpec::RadPerSecond(rate) => rate,
            RateSpec::Rpm(rpm) => rpm * std::f64::consts::TAU / 60.0,
        }
    }
}
