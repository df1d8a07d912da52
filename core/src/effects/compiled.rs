//! The scene's effects compiled for the right-hand side: [`AppliedMoment`] is the moment a motion's equation
//! asks for at (t, q, ω); [`TorqueFree`] is none (the compiler removes it, so a torque-free run pays nothing), and
//! [`EffectMoments`] sums a scene's torques, gravity and damping.

use std::sync::Arc;

use nalgebra::{Quaternion, UnitQuaternion, Vector3};

use super::compiling::{AttitudeLaw, Compiling, UniformGravity};
use super::kinds::Effect;
use super::law::UserMoment;
use super::torque_sum::TorqueSum;
use crate::frames::StateRotation;

/// The external moment acting on the body, about the moment center.
pub trait AppliedMoment {
    /// Whether the moment is identically zero. The forms then skip the arithmetic that applies it, which the
    /// compiler cannot drop by itself (in IEEE arithmetic 0·x is not 0 for every x).
    const ZERO: bool = false;

    /// The moment in body axes at time t, attitude q (body → space) and angular velocity ω_b.
    fn moment_b(&self, t: f64, q: &UnitQuaternion<f64>, omega_b: &Vector3<f64>) -> Vector3<f64>;

    /// [`Self::moment_b`] at the attitude held in a state, `q_state` = (q_w, q_x, q_y, q_z) of norm near but not
    /// exactly 1: the moment at q = q_state / |q_state|. `rotation` gives [`StateRotation::of`]`(q_state)`, called
    /// only by a moment that needs the attitude, so that a form which has computed it already passes it on instead
    /// of having it computed twice. A moment that does not depend on the attitude skips both.
    #[inline(always)]
    fn moment_b_at_state(
        &self,
        t: f64,
        q_state: &Quaternion<f64>,
        _rotation: impl FnOnce() -> StateRotation,
        omega_b: &Vector3<f64>,
    ) -> Vector3<f64> {
        self.moment_b(t, &UnitQuaternion::new_normalize(*q_state), omega_b)
    }

    /// The first time later than `t` at which the moment has a corner (a tabulated moment's row time), where an
    /// adaptive method ends a step; `None`: no corner ahead.
    #[inline(always)]
    fn corner_after(&self, _t: f64) -> Option<f64> {
        None
    }
}

/// No effects: M = 0.
#[derive(Debug, Clone, Copy, Default)]
pub struct TorqueFree;

impl AppliedMoment for TorqueFree {
    const ZERO: bool = true;

    #[inline(always)]
    fn moment_b(&self, _t: f64, _q: &UnitQuaternion<f64>, _omega_b: &Vector3<f64>) -> Vector3<f64> {
        Vector3::zeros()
    }
}

/// The sum of a scene's effects, about the moment center:
/// torque `value·f(t)` (rotated into the body when given in space axes); gravity about the pivot
/// M = ρ_C × m Rᵀg with ρ_C = −pivot the position of C relative to the pivot; the environment's moments
/// ([`AttitudeLaw`]); damping M = −c ω; the laws that depend on ω (B-dot, the user's).
///
/// Split as M_b(t, q, ω) = [`EffectMoments::rest_moment_b`](t, q) − c·ω + Σ laws: the part that does not depend on
/// ω (torques, gravity, the environment's) and the total damping coefficient c = Σ c_k, which the splitting methods
/// apply as exact kicks.
///
/// The effects are compiled once (each kind adds itself, [`EffectKind::compile`](super::EffectKind::compile)): the body-axis torques into one
/// [`TorqueSum`], the space-axis torques into another (rotated into the body once per evaluation), so that only
/// space torques, gravity and the environment's moments need the attitude.
///
/// The laws ([`UserMoment`]) are added to M_b after the rest; they depend on ω, so they are not part of
/// `rest_moment_b` and a splitting method cannot apply them (a scene with one refuses split2/split4).
#[derive(Debug, Clone)]
pub struct EffectMoments {
    effects: Vec<Effect>,
    mass: f64,
    torques_b: TorqueSum,
    torques_s: TorqueSum,
    /// Boxed, one word: the scene's `Motion` holds a hinge's compiled effects and stays small.
    gravity: Option<Box<UniformGravity>>,
    attitude_laws: Box<[Arc<dyn AttitudeLaw>]>,
    pub(crate) needs_attitude: bool,
    damping_c: f64,
    laws: Box<[UserMoment]>,
}

impl PartialEq for EffectMoments {
    /// Equal when compiled from equal effects on equal masses.
    fn eq(&self, other: &Self) -> bool {
        self.effects == other.effects && self.mass == other.mass
    }
}

impl EffectMoments {
    /// The moments of `effects` on a body of mass `mass` (kg).
    pub fn new(effects: &[Effect], mass: f64) -> Self {
        let mut parts = Compiling::default();
        for effect in effects {
            effect.door().compile(&mut parts);
        }
        Self {
            effects: effects.to_vec(),
            mass,
            needs_attitude: !parts.torques_s.is_zero()
                || parts.gravity.is_some()
                || !parts.attitude_laws.is_empty(),
            torques_b: parts.torques_b,
            torques_s: parts.torques_s,
            gravity: parts.gravity.map(Box::new),
            attitude_laws: parts.attitude_laws.into_boxed_slice(),
            damping_c: parts.damping_c,
            laws: parts.laws.into_boxed_slice(),
        }
    }

    /// The effects summed.
    pub fn effects(&self) -> &[Effect] {
        &self.effects
    }

    /// The part of the moment that does not depend on ω, body axes: Σ torques + ρ_C × m (Rᵀ g_s).
    #[inline]
    pub fn rest_moment_b(&self, t: f64, q: &UnitQuaternion<f64>) -> Vector3<f64> {
        self.rest_moment_b_with(t, || {
            self.attitude_moment_b(t, |v_s| q.inverse_transform_vector(v_s))
        })
    }

    /// [`Self::rest_moment_b`]: the body-axis torques M_b(t), plus `attitude_part()` only if an effect depends on
    /// the attitude.
    #[inline(always)]
    fn rest_moment_b_with(
        &self,
        t: f64,
        attitude_part: impl FnOnce() -> Vector3<f64>,
    ) -> Vector3<f64> {
        let m_b = self.torques_b.at(t);
        if self.needs_attitude {
            m_b + attitude_part()
        } else {
            m_b
        }
    }

    /// The moments that depend on the attitude, body axes, given the rotation `to_body`: v_s ↦ Rᵀ v_s:
    /// Rᵀ M_s(t) for the space-axis torques, ρ_C × m (Rᵀ g_s) for gravity, 3n² n̂_b × (I n̂_b) with
    /// n̂_b = Rᵀ n̂_s(t) for an orbit's gravity gradient and m × Rᵀ B_s(r(t), t) for a dipole in the Earth's field.
    #[inline(always)]
    fn attitude_moment_b(
        &self,
        t: f64,
        to_body: impl Fn(&Vector3<f64>) -> Vector3<f64>,
    ) -> Vector3<f64> {
        let mut m_b = if self.torques_s.is_zero() {
            Vector3::zeros()
        } else {
            to_body(&self.torques_s.at(t))
        };
        if let Some(gravity) = &self.gravity {
            let UniformGravity { g_s, rho_c_b } = gravity.as_ref();
            m_b += rho_c_b.cross(&(to_body(g_s) * self.mass));
        }
        for law in &self.attitude_laws {
            m_b += law.moment_b(&to_body(&law.vector_s(t)));
        }
        m_b
    }

    /// [`Self::attitude_moment_b`] at the attitude held in a state ([`StateRotation`]). Out of line: only scenes
    /// with space torques or gravity call it, and the right-hand sides, inlined at every stage of an integrator,
    /// stay small.
    #[inline(never)]
    fn attitude_moment_at_state_b(
        &self,
        t: f64,
        rotation: impl FnOnce() -> StateRotation,
    ) -> Vector3<f64> {
        let rotation = rotation();
        self.attitude_moment_b(t, |v_s| rotation.to_body(v_s))
    }

    /// The user's laws' moments summed, body axes. Out of line, as [`Self::attitude_moment_at_state_b`].
    #[inline(never)]
    fn laws_moment_b(
        &self,
        t: f64,
        q: &UnitQuaternion<f64>,
        omega_b: &Vector3<f64>,
    ) -> Vector3<f64> {
        (self.laws.iter()).fold(Vector3::zeros(), |m_b, user| {
            m_b + user.moment_b(t, q, omega_b)
        })
    }

    /// Whether a user's law is among the effects.
    pub fn has_laws(&self) -> bool {
        !self.laws.is_empty()
    }

    /// Whether the moment depends on the attitude (space-axis torques, gravity, the environment's, a law) and on
    /// ω (damping, a law): where it depends on neither, ∂M/∂(q, ω) = 0.
    pub fn depends_on_state(&self) -> (bool, bool) {
        let laws = !self.laws.is_empty();
        (self.needs_attitude || laws, self.damping_c != 0.0 || laws)
    }

    /// M_b = M_rest_b − c ω_b from the part M_rest_b that does not depend on ω.
    #[inline(always)]
    fn with_damping(&self, rest_b: Vector3<f64>, omega_b: &Vector3<f64>) -> Vector3<f64> {
        if self.damping_c == 0.0 {
            rest_b
        } else {
            rest_b - omega_b * self.damping_c
        }
    }

    /// The total viscous damping coefficient c = Σ c_k (N·m·s): the damping moment is −c ω.
    pub fn damping_c(&self) -> f64 {
        self.damping_c
    }

    /// An upper bound of |M_rest| over all times and attitudes (N·m): Σ |torque value| (every profile factor is
    /// at most 1 in magnitude) + m |g| |ρ_C| for gravity. Damping is left out: its power −c|ω|² is never positive.
    pub fn rest_moment_bound(&self) -> f64 {
        self.effects
            .iter()
            .filter_map(|e| e.largest_moment(self.mass))
            .sum()
    }
}

impl AppliedMoment for EffectMoments {
    /// M_b = M_rest_b(t, q) − c ω_b + Σ the user's laws.
    #[inline]
    fn moment_b(&self, t: f64, q: &UnitQuaternion<f64>, omega_b: &Vector3<f64>) -> Vector3<f64> {
        let m_b = self.with_damping(self.rest_moment_b(t, q), omega_b);
        if self.laws.is_empty() {
            m_b
        } else {
            m_b + self.laws_moment_b(t, q, omega_b)
        }
    }

    /// M_b = M_rest_b(t, q) − c ω_b + Σ the user's laws, rotating by q = q_state / |q_state| ([`StateRotation`])
    /// only for space torques and gravity (the laws are given q itself).
    #[inline(always)]
    fn moment_b_at_state(
        &self,
        t: f64,
        q_state: &Quaternion<f64>,
        rotation: impl FnOnce() -> StateRotation,
        omega_b: &Vector3<f64>,
    ) -> Vector3<f64> {
        let rest_b = self.rest_moment_b_with(t, || self.attitude_moment_at_state_b(t, rotation));
        let m_b = self.with_damping(rest_b, omega_b);
        if self.laws.is_empty() {
            m_b
        } else {
            m_b + self.laws_moment_b(t, &UnitQuaternion::new_normalize(*q_state), omega_b)
        }
    }

    /// The tables' next row time after `t`, in either axes.
    #[inline]
    fn corner_after(&self, t: f64) -> Option<f64> {
        match (
            self.torques_b.corner_after(t),
            self.torques_s.corner_after(t),
        ) {
            (Some(b), Some(s)) => Some(b.min(s)),
            (b, s) => b.or(s),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::effects::{
        Damping, Effect, Gravity, GravityGradient, MagneticDipole, TabulatedTorque, TorqueGiven,
    };
    use crate::frames::{Axes, StateRotation};
    use crate::orbit::{CircularOrbit, DipoleField};
    use crate::profile::Profile;
    use nalgebra::{UnitQuaternion, Vector3};

    /// The unit roundoff.
    const U: f64 = f64::EPSILON / 2.0;

    fn v(x: f64, y: f64, z: f64) -> Vector3<f64> {
        Vector3::new(x, y, z)
    }

    /// The moment as summed before the effects were compiled: every effect in turn, starting from zero.
    fn moment_as_listed(
        effects: &[Effect],
        mass: f64,
        t: f64,
        q: &UnitQuaternion<f64>,
        omega_b: &Vector3<f64>,
    ) -> Vector3<f64> {
        let mut m_b = Vector3::zeros();
        for effect in effects {
            m_b += match *effect {
                Effect::Torque(TorqueGiven {
                    frame,
                    value,
                    profile,
                }) => {
                    let factor = match profile {
                        Profile::Constant => 1.0,
                        // The crate's inline sine (within an ulp of the library's, tested in `trig`).
                        Profile::Sine { freq_hz, phase_deg } => crate::trig::sin(
                            2.0 * std::f64::consts::PI * freq_hz * t + phase_deg.to_radians(),
                        ),
                        Profile::Step { t_on, t_off } => {
                            if t_on <= t && t < t_off {
                                1.0
                            } else {
                                0.0
                            }
                        }
                    };
                    match frame {
                        Axes::Body => value * factor,
                        Axes::Space => q.inverse_transform_vector(&(value * factor)),
                    }
                }
                Effect::Gravity(Gravity { g_s, pivot_b }) => {
                    (-pivot_b).cross(&(q.inverse_transform_vector(&g_s) * mass))
                }
                Effect::Damping(Damping { c }) => -omega_b * c,
                Effect::TorqueTable(TabulatedTorque { frame, ref table }) => match frame {
                    Axes::Body => table.at(t),
                    Axes::Space => q.inverse_transform_vector(&table.at(t)),
                },
                Effect::GravityGradient(GravityGradient { orbit, inertia_c_b }) => orbit
                    .gravity_gradient_b(
                        &q.inverse_transform_vector(&orbit.nadir_s(t)),
                        &inertia_c_b,
                    ),
                Effect::Magnetic(MagneticDipole {
                    orbit,
                    field,
                    dipole_b,
                }) => {
                    dipole_b.cross(&q.inverse_transform_vector(&field.b_s(&orbit.position_s(t), t)))
                }
                Effect::BDot(ref b_dot) => crate::effects::MomentLaw::moment(b_dot, t, q, omega_b),
                Effect::User(ref user) => user.moment_b(t, q, omega_b),
            };
        }
        m_b
    }

    fn every_kind() -> Vec<Effect> {
        let sine = Profile::Sine {
            freq_hz: 0.7,
            phase_deg: 23.0,
        };
        let step = Profile::Step {
            t_on: 1.0,
            t_off: 2.5,
        };
        let mut effects = Vec::new();
        for frame in [Axes::Body, Axes::Space] {
            for (value, profile) in [
                (v(0.2, -0.1, 0.3), Profile::Constant),
                (v(0.5, 0.25, -0.4), sine),
                (v(-0.3, 0.6, 0.1), step),
            ] {
                effects.push(Effect::Torque(TorqueGiven {
                    frame,
                    value,
                    profile,
                }));
            }
        }
        effects.push(Effect::Gravity(Gravity {
            g_s: v(0.0, 0.0, -9.81),
            pivot_b: v(0.01, -0.02, -0.05),
        }));
        effects.push(Effect::Damping(Damping { c: 0.3 }));
        // A close orbit (r = 7000 km) and a large body, so that the gradient's moment is of the others' order.
        effects.push(Effect::Magnetic(MagneticDipole {
            orbit: CircularOrbit::new(7.0e6, 0.9, 0.4, 1.1),
            field: DipoleField::new(3.12e-5, 0.2, 0.7),
            dipole_b: v(2.0e4, -1.0e4, 3.0e4),
        }));
        effects.push(Effect::GravityGradient(GravityGradient {
            orbit: CircularOrbit::new(7.0e6, 0.9, 0.4, 1.1),
            inertia_c_b: nalgebra::Matrix3::new(
                9.0e5, 1.0e4, -2.0e4, 1.0e4, 6.0e5, 3.0e4, -2.0e4, 3.0e4, 3.0e5,
            ),
        }));
        effects
    }

    #[test]
    fn every_effect_kind_gives_the_moment_it_gave_before() {
        let mass = 1.5;
        let q_state = nalgebra::Quaternion::new(0.9, 0.2, -0.3, 0.25);
        let q = UnitQuaternion::new_normalize(q_state);
        let omega_b = v(0.3, -1.2, 2.0);
        let all = every_kind();
        for t in [0.0, 0.4, 1.0, 1.7, 2.5, 3.1] {
            for effects in all.chunks(1).chain([&all[..]]) {
                let moments = EffectMoments::new(effects, mass);
                let before = moment_as_listed(effects, mass, t, &q, &omega_b);
                // The moments are summed in another order, and the state's attitude is rotated as A(q)/|q|²
                // rather than normalised first: equal to the rounding of the sum and of a rotation, 8u times the
                // largest possible moment Σ|torque| + m|g||ρ_C| + c|ω|.
                let scale = moments.rest_moment_bound() + moments.damping_c() * omega_b.norm();
                for after in [
                    moments.moment_b(t, &q, &omega_b),
                    moments.moment_b_at_state(
                        t,
                        &q_state,
                        || StateRotation::of(&q_state),
                        &omega_b,
                    ),
                    moments.rest_moment_b(t, &q) - omega_b * moments.damping_c(),
                ] {
                    assert!(
                        (after - before).amax() <= 8.0 * U * scale,
                        "{effects:?} at t = {t}: {after} vs {before}"
                    );
                }
                // Alone, an effect given the unit quaternion is computed with the same operations as before.
                if effects.len() == 1 {
                    assert_eq!(
                        moments.moment_b(t, &q, &omega_b),
                        before,
                        "{effects:?}, t = {t}"
                    );
                }
            }
        }
    }

    #[test]
    fn only_space_torques_and_gravity_need_the_attitude() {
        let needs = |effects: &[Effect]| EffectMoments::new(effects, 1.0).needs_attitude;
        let all = every_kind();
        let (body_torques, rest) = all.split_at(3);
        assert!(!needs(body_torques));
        assert!(!needs(&[Effect::Damping(Damping { c: 0.1 })]));
        assert!(needs(&rest[..1]));
        assert!(needs(&rest[3..4]));
        // Without them, the attitude is never normalised: a state quaternion of any norm gives the same moment.
        let moments = EffectMoments::new(body_torques, 1.0);
        let omega_b = v(0.1, 0.2, 0.3);
        let unit = nalgebra::Quaternion::new(1.0, 0.0, 0.0, 0.0);
        let zero = nalgebra::Quaternion::new(0.0, 0.0, 0.0, 0.0);
        assert_eq!(
            moments.moment_b_at_state(1.2, &zero, || StateRotation::of(&zero), &omega_b),
            moments.moment_b_at_state(1.2, &unit, || StateRotation::of(&unit), &omega_b)
        );
    }
}
