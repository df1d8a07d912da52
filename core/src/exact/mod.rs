//! Closed-form solutions: oracles for tests, `compare` and `accuracy`.
//!
//! Pure mathematics, no I/O. Frames are part of every name: `_p` principal (body) axes,
//! `_s` space axes; attitudes are unit quaternions mapping principal to space axes
//! (`v_s = q * v_p`).
//!
//! - [`jacobi`]: Jacobi elliptic functions sn, cn, dn and the amplitude am (hand-written;
//!   descending Landen / ascending Gauss transformations, A&S 16.12–16.15, DLMF 22.7, 22.20).
//! - [`torque_free`]: the torque-free (Euler–Poinsot) rigid body, any moments, any initial
//!   state: angular velocity and exact attitude (Landau & Lifshitz, *Mechanics*, §37).
//! - [`equal_grid`]: the torque-free body on an equal grid of times, advanced row by row by the addition theorems
//!   of sn, cn, dn and of the precession angle's elliptic integral (DLMF 22.8, §19.11), re-anchored periodically.
//! - [`symmetric`]: symmetric bodies: torque-free precession, constant axial torque, and the
//!   heavy symmetric top in steady precession (Goldstein, *Classical Mechanics*, §§5.6–5.7).

pub mod damped_spin;
mod double_double;
pub mod equal_grid;
pub mod jacobi;
pub mod symmetric;
pub mod torque_free;

pub use damped_spin::{DampedSpin, DampedSpinState};
pub use equal_grid::{ANCHOR_ROWS, EqualGrid};
pub use jacobi::{JacobiElliptic, amplitude, sn_cn_dn};
pub use symmetric::{
    AxialTorqueSymmetric, HeavySymmetricTop, PrecessionRoots, SteadyPrecession, SymmetricTorqueFree,
};
pub use torque_free::{TorqueFreeBody, TorqueFreeCase};

/// Invalid input to a closed-form solution.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum ExactError {
    /// An input was NaN or infinite.
    #[error("non-finite input: {0}")]
    NonFinite(&'static str),
    /// A moment of inertia (or mass, length, …) that must be positive was not.
    #[error("{what} must be positive, got {value}")]
    NonPositive {
        /// Which quantity.
        what: &'static str,
        /// The offending value.
        value: f64,
    },
    /// The principal moments violate `I_i ≤ I_j + I_k` (no real body has them).
    #[error("principal moments ({0}, {1}, {2}) violate the triangle inequality I_i <= I_j + I_k")]
    TriangleInequality(f64, f64, f64),
    /// Another domain violation (described in the message).
    #[error("invalid argument: {0}")]
    InvalidArgument(&'static str),
    /// An elliptic-integral routine refused arguments that should be valid.
    #[error("elliptic integral evaluation failed: {0}")]
    Numerical(&'static str),
}

/// Check three principal moments: finite, positive, and `I_i ≤ (I_j + I_k)(1 + 16ε)`
/// (the triangle inequality, which holds for every real mass distribution; equality is a
/// lamina, allowed up to rounding).
pub(crate) fn check_moments(moments: &[f64; 3]) -> Result<(), ExactError> {
    if moments.iter().any(|x| !x.is_finite()) {
        return Err(ExactError::NonFinite("principal moments"));
    }
    for &value in moments {
        if value <= 0.0 {
            return Err(ExactError::NonPositive {
                what: "principal moment of inertia",
                value,
            });
        }
    }
    let [a, b, c] = *moments;
    let slack = 1.0 + 16.0 * f64::EPSILON;
    if a > (b + c) * slack || b > (a + c) * slack || c > (a + b) * slack {
        return Err(ExactError::TriangleInequality(a, b, c));
    }
    Ok(())
}

/// Rotation by `angle` about the unit vector `axis`, as a quaternion whose components are
/// `(cos(angle/2), sin(angle/2)·axis)` evaluated directly (no wrapping of the angle, so the
/// result is continuous in `angle` beyond ±2π).
pub(crate) fn axis_angle_quat(
    axis: &nalgebra::Vector3<f64>,
    angle: f64,
) -> nalgebra::UnitQuaternion<f64> {
    let (s, c) = (0.5 * angle).sin_cos();
    nalgebra::UnitQuaternion::new_unchecked(nalgebra::Quaternion::new(
        c,
        s * axis.x,
        s * axis.y,
        s * axis.z,
    ))
}
