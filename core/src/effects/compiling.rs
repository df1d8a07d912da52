//! What an effect kind compiles itself into ([`EffectKind::compile`](super::EffectKind::compile)): the pieces that
//! [`EffectMoments`](super::EffectMoments) sums at every right-hand side.

use std::sync::Arc;

use nalgebra::Vector3;

use super::law::UserMoment;
use super::torque_sum::TorqueSum;
use crate::frames::Axes;

/// Uniform gravity g_s acting at C, which sits at ρ_C from the moment center (body axes).
#[derive(Debug, Clone, Copy, PartialEq)]
pub(super) struct UniformGravity {
    pub(super) g_s: Vector3<f64>,
    pub(super) rho_c_b: Vector3<f64>,
}

/// A moment that depends on the attitude only through one vector given in space axes (an environment's effect):
/// M_b = f(Rᵀ v_s(t)), the vector v_s(t) ([`vector_s`](Self::vector_s)) rotated into the body by the caller, so
/// that the rotation stays inlined in the right-hand side.
pub trait AttitudeLaw: std::fmt::Debug + Send + Sync {
    /// v_s(t): the space-axis vector the moment depends on.
    fn vector_s(&self, t: f64) -> Vector3<f64>;

    /// M_b from v_b = Rᵀ v_s(t).
    fn moment_b(&self, v_b: &Vector3<f64>) -> Vector3<f64>;
}

/// What an effect kind adds itself to: the pieces [`EffectMoments`](super::EffectMoments) sums.
#[derive(Debug, Default)]
pub struct Compiling {
    pub(super) torques_b: TorqueSum,
    pub(super) torques_s: TorqueSum,
    pub(super) gravity: Option<UniformGravity>,
    pub(super) attitude_laws: Vec<Arc<dyn AttitudeLaw>>,
    pub(super) damping_c: f64,
    pub(super) laws: Vec<UserMoment>,
}

impl Compiling {
    /// The torques given in `frame`, to add to.
    pub(crate) fn torques(&mut self, frame: Axes) -> &mut TorqueSum {
        match frame {
            Axes::Body => &mut self.torques_b,
            Axes::Space => &mut self.torques_s,
        }
    }

    /// Uniform gravity `g_s` (space axes) acting at C, at `rho_c_b` from the moment center (body axes).
    pub(crate) fn uniform_gravity(&mut self, g_s: Vector3<f64>, rho_c_b: Vector3<f64>) {
        self.gravity = Some(UniformGravity { g_s, rho_c_b });
    }

    /// A moment of the attitude through space-axis vectors.
    pub(crate) fn attitude_law(&mut self, law: Arc<dyn AttitudeLaw>) {
        self.attitude_laws.push(law);
    }

    /// Viscous damping −c ω, added to the total c.
    pub(crate) fn damping(&mut self, c: f64) {
        self.damping_c += c;
    }

    /// A law of (t, q, ω).
    pub(crate) fn rate_law(&mut self, law: UserMoment) {
        self.laws.push(law);
    }
}
