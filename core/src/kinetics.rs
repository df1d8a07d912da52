//! Kinetic states of a rigid body (the reference notes, Theorems 23–25). Every function works in whatever axes its
//! arguments are expressed in, as long as they are all in the same axes.

use nalgebra::{Matrix3, Vector3};

/// Momentum P = m v_C (Theorem 23, eq. 8.1).
pub fn momentum(mass: f64, v_c: &Vector3<f64>) -> Vector3<f64> {
    v_c * mass
}

/// Moment of momentum about a body point A: H_A = m ρ_C × v_A + I_A · ω (Theorem 25, eq. 8.4), with ρ_C the
/// position of C relative to A and I_A the inertia about A. When A is fixed (v_A = 0), A = C, or ρ_C ∥ v_A it
/// reduces to H_A = I_A · ω (eq. 8.6).
pub fn moment_of_momentum_a(
    mass: f64,
    rho_c: &Vector3<f64>,
    v_a: &Vector3<f64>,
    inertia_a: &Matrix3<f64>,
    omega: &Vector3<f64>,
) -> Vector3<f64> {
    rho_c.cross(v_a) * mass + inertia_a * omega
}

/// Rotational kinetic energy about a fixed or central point: T = ½ ω · H = ½ ω · I ω.
pub fn kinetic_energy(omega: &Vector3<f64>, h: &Vector3<f64>) -> f64 {
    0.5 * omega.dot(h)
}

/// Whole kinetic energy from the mass center (König): T = ½ m |v_C|² + ½ ω · I_C ω.
pub fn kinetic_energy_c(
    mass: f64,
    v_c: &Vector3<f64>,
    inertia_c: &Matrix3<f64>,
    omega: &Vector3<f64>,
) -> f64 {
    0.5 * mass * v_c.norm_squared() + 0.5 * omega.dot(&(inertia_c * omega))
}
