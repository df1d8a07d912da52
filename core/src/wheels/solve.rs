//! The body's and the wheels' accelerations with some wheels held: at the speed limit or stuck by friction.
//!
//! A held wheel has Ω̇ = 0 and is solved for like a prescribed one (Rigid-body dynamics, lecture notes, the
//! gyrostat; Hughes, *Spacecraft Attitude Dynamics*, §3.5): with P the prescribed and held wheels and D the driven
//! ones, I_D ω̇ = M − ω × H − Σ_P J_k α_k a_k − Σ_D (τ_m,k + τ_f,k) a_k, I_D = I − Σ_D J_k a_k a_kᵀ, and a held
//! wheel needs the torque τ_hold = J a·ω̇. A wheel at its speed limit stays held while its command pushes further
//! (τ_m + τ_f beyond τ_hold in the sense of Ω): the motor then applies τ_hold − τ_f. A wheel at rest (|Ω| ≤
//! [`STICK_SPEED`]) under Coulomb friction stays held while |τ_hold − τ_m| ≤ c + s (friction supplies it); else it
//! slips with the breakaway friction opposing τ_m − τ_hold. Being held is decided from the state alone, so an
//! adaptive step ends on the stop (its error estimate rejects the steps that cross it) and does not chatter.

use nalgebra::{Matrix3, Vector3};

use super::MAX_ROTORS;
use super::WheelControl;

/// The relative spin (rad/s) at or below which a wheel with Coulomb friction is at rest: far above the round-off
/// of a spin (1e-16 of hundreds of rad/s) and the overshoot that an adaptive step's error control lets through at
/// the default tolerances, far below any speed a wheel is run at.
pub const STICK_SPEED: f64 = 1e-8;

/// One wheel as the solve sees it (body axes).
#[derive(Debug, Clone, Copy, Default)]
pub struct Wheel {
    /// The spin axis a (unit).
    pub axis_b: Vector3<f64>,
    /// J (kg·m²).
    pub inertia: f64,
    /// Ω, relative to the body (rad/s).
    pub spin: f64,
    /// `Some(α)`: Ω̇ = α prescribed; `None`: driven by its motor.
    pub accel: Option<f64>,
    /// A driven wheel's motor torque after clipping (N·m).
    pub motor: f64,
    /// Its limits and friction.
    pub control: WheelControl,
}

/// The accelerations and each wheel's motor and friction torques (N·m).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct WheelSolve {
    /// ω̇ (rad/s², body axes).
    pub omega_dot_b: Vector3<f64>,
    /// Ω̇_k (rad/s²).
    pub spin_dot: [f64; MAX_ROTORS],
    /// The motor torque applied (a prescribed wheel's: what its spin takes, less friction).
    pub motor: [f64; MAX_ROTORS],
    /// The friction torque on each wheel (N·m).
    pub friction: [f64; MAX_ROTORS],
}

/// Why a wheel may be held.
#[derive(Debug, Clone, Copy, PartialEq)]
enum Hold {
    No,
    SpeedLimit,
    Stuck,
}

fn hold_of(w: &Wheel) -> Hold {
    if w.accel.is_some() {
        Hold::No
    } else if w.spin.abs() >= w.control.max_speed {
        Hold::SpeedLimit
    } else if w.control.friction.breakaway() > 0.0 && w.spin.abs() <= STICK_SPEED {
        Hold::Stuck
    } else {
        Hold::No
    }
}

/// ω̇_b and the wheels' torques with `rhs0_b` = M − ω × H, the body's inertia `inertia_b` (wheels locked) and
/// `driven_inv_b` = I_D⁻¹ of the wheels that are not prescribed (module doc).
pub fn solve(
    inertia_b: &Matrix3<f64>,
    driven_inv_b: &Matrix3<f64>,
    rhs0_b: &Vector3<f64>,
    wheels: &[Wheel],
) -> WheelSolve {
    let mut friction = [0.0; MAX_ROTORS];
    let mut motor = [0.0; MAX_ROTORS];
    let mut held = [false; MAX_ROTORS];
    let mut holds = [Hold::No; MAX_ROTORS];
    for (k, w) in wheels.iter().enumerate() {
        friction[k] = w.control.friction.torque(w.spin);
        motor[k] = w.motor;
        holds[k] = hold_of(w);
        held[k] = holds[k] != Hold::No;
    }
    // Each pass releases the held wheels that would not stay held; at most one pass per wheel, then one more to
    // find ω̇_b with the wheels still held.
    let mut pass = 0;
    loop {
        let omega_dot_b = accelerations(
            inertia_b,
            driven_inv_b,
            rhs0_b,
            wheels,
            &held,
            &motor,
            &friction,
        );
        let hold = Holding {
            holds: &holds,
            held: &mut held,
            motor: &mut motor,
            friction: &mut friction,
        };
        if pass > wheels.len() || !release(wheels, &omega_dot_b, hold) {
            return finish(wheels, omega_dot_b, &held, motor, friction);
        }
        pass += 1;
    }
}

/// The wheels held and the torques that hold them, as one pass of [`solve`] changes them.
struct Holding<'a> {
    holds: &'a [Hold; MAX_ROTORS],
    held: &'a mut [bool; MAX_ROTORS],
    motor: &'a mut [f64; MAX_ROTORS],
    friction: &'a mut [f64; MAX_ROTORS],
}

/// One pass at ω̇_b: a wheel at its speed limit stays held with the motor torque that holds it, while the command
/// pushes further; a stuck wheel stays held while the friction that holds it is within breakaway, else it slips
/// with the breakaway friction. Whether a wheel was released.
fn release(wheels: &[Wheel], omega_dot_b: &Vector3<f64>, h: Holding<'_>) -> bool {
    let mut released = false;
    for (k, w) in wheels.iter().enumerate() {
        if !h.held[k] {
            continue;
        }
        let hold = w.inertia * w.axis_b.dot(omega_dot_b);
        match h.holds[k] {
            Hold::SpeedLimit if w.spin.signum() * (w.motor + h.friction[k] - hold) > 0.0 => {
                h.motor[k] = hold - h.friction[k];
            }
            Hold::Stuck if (hold - w.motor).abs() <= w.control.friction.breakaway() => {
                h.friction[k] = hold - w.motor;
            }
            Hold::Stuck => {
                let breakaway = w.control.friction.breakaway();
                h.friction[k] = -breakaway * (w.motor - hold).signum();
                (h.held[k], released) = (false, true);
            }
            _ => (h.held[k], released) = (false, true),
        }
    }
    released
}

/// ω̇_b = I_D⁻¹ (M − ω × H − Σ_P J α a − Σ_D (τ_m + τ_f) a), the held wheels among P with α = 0.
fn accelerations(
    inertia_b: &Matrix3<f64>,
    driven_inv_b: &Matrix3<f64>,
    rhs0_b: &Vector3<f64>,
    wheels: &[Wheel],
    held: &[bool; MAX_ROTORS],
    motor: &[f64; MAX_ROTORS],
    friction: &[f64; MAX_ROTORS],
) -> Vector3<f64> {
    let any_held = held.iter().any(|&h| h);
    let mut rhs = *rhs0_b;
    let mut inertia_driven_b = *inertia_b;
    for (k, w) in wheels.iter().enumerate() {
        let push = match (w.accel, held[k]) {
            (Some(alpha), _) => w.inertia * alpha,
            (None, true) => continue,
            (None, false) => push_of(w, motor[k], friction[k]),
        };
        if any_held && w.accel.is_none() {
            inertia_driven_b -= w.axis_b * w.axis_b.transpose() * w.inertia;
        }
        rhs -= w.axis_b * push;
    }
    let inverse = match any_held {
        false => *driven_inv_b,
        true => inertia_driven_b
            .try_inverse()
            .unwrap_or(Matrix3::repeat(f64::NAN)),
    };
    inverse * rhs
}

/// What a driven wheel feels: τ_m + τ_f (τ_m alone without friction, bit for bit as before friction existed).
fn push_of(w: &Wheel, motor: f64, friction: f64) -> f64 {
    match w.control.friction.is_some() {
        true => motor + friction,
        false => motor,
    }
}

/// Ω̇ of each wheel (α, 0 held, (τ_m + τ_f)/J − a·ω̇ driven) and a prescribed wheel's motor torque
/// J (a·ω̇ + α) − τ_f.
fn finish(
    wheels: &[Wheel],
    omega_dot_b: Vector3<f64>,
    held: &[bool; MAX_ROTORS],
    mut motor: [f64; MAX_ROTORS],
    friction: [f64; MAX_ROTORS],
) -> WheelSolve {
    let mut spin_dot = [0.0; MAX_ROTORS];
    for (k, w) in wheels.iter().enumerate() {
        spin_dot[k] = match (w.accel, held[k]) {
            (Some(alpha), _) => {
                let total = w.inertia * (w.axis_b.dot(&omega_dot_b) + alpha);
                motor[k] = match w.control.friction.is_some() {
                    true => total - friction[k],
                    false => total,
                };
                alpha
            }
            (None, true) => 0.0,
            (None, false) => {
                push_of(w, motor[k], friction[k]) / w.inertia - w.axis_b.dot(&omega_dot_b)
            }
        };
    }
    WheelSolve {
        omega_dot_b,
        spin_dot,
        motor,
        friction,
    }
}
