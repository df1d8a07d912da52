//! A body's wheels (`[[body.rotor]]`), one capability in one folder: the rotors spinning inside a freely turning
//! body — their state and equations ([`gyrostat`]), their keys declared once and read (`keys.rs`, `spec.rs`,
//! `limits.rs`), validated (`validate.rs`), their columns (`columns.rs`) and `check` lines (`describe.rs`) — and
//! the wheels under control: what a wheel's motor is told (a law, a table, nothing), what it can do (a torque
//! limit, a speed limit) and what it loses (friction). Each wheel's torques:
//!
//! ```text
//!   τ_cmd                          the command: the wheel law's, the torque table's, 0 for a free wheel
//!   τ_m = clamp(τ_cmd, ±τ_max)     the motor torque applied (then the speed limit, below)
//!   τ_f = −(c + s·exp(−(Ω/Ω_s)²))·sign(Ω) − v·Ω     friction, opposing the relative spin Ω
//!   J (a·ω̇ + Ω̇) = τ_m + τ_f       the wheel about its axis; the body feels −(τ_m + τ_f)
//! ```
//!
//! (Basilisk's `reactionWheelStateEffector`: Coulomb, viscous and Stribeck friction, torque and speed saturation;
//! Rigid-body dynamics, lecture notes, the gyrostat.) Friction is internal: H stays conserved and the kinetic
//! energy falls. At |Ω| = Ω_max a command that pushes further applies only the torque that holds Ω there; a wheel
//! whose relative spin has reached zero under Coulomb friction sticks while the torque that holds it is within
//! the breakaway level c + s (no chatter: [`solve`]).

mod attribute;
mod columns;
mod describe;
pub mod gyrostat;
mod keys;
mod law;
mod limits;
mod rows;
mod solve;
mod spec;
mod table;
mod take_law;
mod validate;

pub use columns::{columns, rotor_columns};
pub use keys::RotorSpec;
pub use law::{AttitudePd, WheelInputs, WheelLaw, WheelTorqueLaw};
pub use limits::{FrictionKeys, StribeckKeys, WheelKeys, WheelMode};
pub use rows::RotorRows;
pub use solve::{STICK_SPEED, Wheel, WheelSolve, solve};
pub use spec::RotorDrive;
pub use table::{WHEEL_TABLE_HEADER, read_wheel_table};

/// The most rotors a body may carry (a reaction-wheel pyramid has four).
pub const MAX_ROTORS: usize = 4;

/// One rpm in rad/s.
pub const RPM: f64 = std::f64::consts::PI / 30.0;

/// A wheel's friction, validated (N·m, N·m·s, N·m and rad/s).
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct Friction {
    /// c (N·m).
    pub coulomb: f64,
    /// v (N·m·s).
    pub viscous: f64,
    /// s (N·m).
    pub stribeck_torque: f64,
    /// Ω_s (rad/s).
    pub stribeck_speed: f64,
}

impl Friction {
    /// τ_f(Ω) = −(c + s·exp(−(Ω/Ω_s)²))·sign(Ω) − v·Ω, with sign(0) = 0.
    ///
    /// ```
    /// use eulerdyn::wheels::Friction;
    /// let f = Friction { coulomb: 0.002, viscous: 1e-5, ..Friction::default() };
    /// assert_eq!(f.torque(100.0), -0.002 - 1e-3);
    /// ```
    pub fn torque(&self, spin: f64) -> f64 {
        let mut level = self.coulomb;
        if self.stribeck_torque > 0.0 {
            let x = spin / self.stribeck_speed;
            level += self.stribeck_torque * (-x * x).exp();
        }
        let sign = if spin == 0.0 { 0.0 } else { spin.signum() };
        -level * sign - self.viscous * spin
    }

    /// The breakaway level c + s: the most torque the friction of a wheel at rest can hold.
    pub fn breakaway(&self) -> f64 {
        self.coulomb + self.stribeck_torque
    }

    /// Whether there is any friction.
    pub fn is_some(&self) -> bool {
        self.coulomb > 0.0 || self.viscous > 0.0 || self.stribeck_torque > 0.0
    }
}

/// A wheel's limits and friction, validated; no limit is +∞.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct WheelControl {
    /// τ_max (N·m).
    pub max_torque: f64,
    /// Ω_max (rad/s), on the relative spin.
    pub max_speed: f64,
    /// Its friction.
    pub friction: Friction,
}

impl Default for WheelControl {
    fn default() -> Self {
        Self {
            max_torque: f64::INFINITY,
            max_speed: f64::INFINITY,
            friction: Friction::default(),
        }
    }
}

impl WheelControl {
    /// The command clipped to ±τ_max.
    pub fn clip(&self, command: f64) -> f64 {
        command.clamp(-self.max_torque, self.max_torque)
    }

    /// Whether the wheel may be held (at its speed limit, or stuck by Coulomb friction) at some state.
    pub fn may_hold(&self) -> bool {
        self.max_speed.is_finite() || self.friction.breakaway() > 0.0
    }
}
