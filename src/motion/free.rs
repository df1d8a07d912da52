//! Free rotation: Euler's equation integrated in body axes, state (ω_b, q), or in space axes, state (H_s, q),
//! about the moment center (C, or the fixed pivot of a gravity effect).
//!
//! The applied moment is a type parameter: a torque-free run uses [`TorqueFree`], whose zero moment the compiler
//! removes, so an absent effect costs nothing per step; otherwise [`EffectMoments`] sums the scene's effects.

use nalgebra::{Matrix3, Rotation3, SVector, UnitQuaternion, Vector3};

use crate::body::RigidBody;
use crate::effects::Effect;
use crate::integrate::OdeSystem;
use crate::kinetics::kinetic_energy;
use crate::model::Frame;
use crate::output::Sample;

/// State vector of both forms: (ω_b or H_s, q_w, q_x, q_y, q_z).
pub type State = SVector<f64, 7>;

/// The external moment acting on the body, about the moment center.
pub trait AppliedMoment {
    /// Whether the moment is identically zero. The forms then skip the arithmetic that applies it, which the
    /// compiler cannot drop by itself (in IEEE arithmetic 0·x is not 0 for every x).
    const ZERO: bool = false;

    /// The moment in body axes at time t, attitude q (body → space) and angular velocity ω_b.
    fn moment_b(&self, t: f64, q: &UnitQuaternion<f64>, omega_b: &Vector3<f64>) -> Vector3<f64>;
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
/// M = ρ_C × m g with ρ_C = −pivot the position of C relative to the pivot; damping M = −c ω.
///
/// Split as M_b(t, q, ω) = [`EffectMoments::rest_moment_b`](t, q) − c·ω: the part that does not depend on ω
/// (torques, gravity) and the total damping coefficient c = Σ c_k, which the splitting methods apply as exact kicks.
#[derive(Debug, Clone)]
pub struct EffectMoments {
    effects: Vec<Effect>,
    mass: f64,
    damping_c: f64,
}

impl EffectMoments {
    /// The moments of `effects` on a body of mass `mass` (kg).
    pub fn new(effects: &[Effect], mass: f64) -> Self {
        let damping_c = effects
            .iter()
            .map(|e| match e {
                Effect::Damping { c } => *c,
                _ => 0.0,
            })
            .sum();
        Self {
            effects: effects.to_vec(),
            mass,
            damping_c,
        }
    }

    /// The effects summed.
    pub fn effects(&self) -> &[Effect] {
        &self.effects
    }

    /// The part of the moment that does not depend on ω, body axes: Σ torques + ρ_C × m (Rᵀ g_s).
    pub fn rest_moment_b(&self, t: f64, q: &UnitQuaternion<f64>) -> Vector3<f64> {
        let mut m_b = Vector3::zeros();
        for effect in &self.effects {
            match effect {
                Effect::Torque {
                    frame,
                    value,
                    profile,
                } => {
                    let v = value * profile.factor(t);
                    m_b += match frame {
                        Frame::Body => v,
                        Frame::Space => q.inverse_transform_vector(&v),
                    };
                }
                Effect::Gravity { g_s, pivot_b } => {
                    let weight_b = q.inverse_transform_vector(g_s) * self.mass;
                    m_b += (-pivot_b).cross(&weight_b);
                }
                Effect::Damping { .. } => {}
            }
        }
        m_b
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
            .map(|e| match e {
                Effect::Torque { value, .. } => value.norm(),
                Effect::Gravity { g_s, pivot_b } => self.mass * g_s.norm() * pivot_b.norm(),
                Effect::Damping { .. } => 0.0,
            })
            .sum()
    }
}

impl AppliedMoment for EffectMoments {
    /// M_b = M_rest_b(t, q) − c ω_b.
    fn moment_b(&self, t: f64, q: &UnitQuaternion<f64>, omega_b: &Vector3<f64>) -> Vector3<f64> {
        let rest = self.rest_moment_b(t, q);
        if self.damping_c == 0.0 {
            rest
        } else {
            rest - omega_b * self.damping_c
        }
    }
}

/// The body about its moment center A: I_A and its inverse from the principal decomposition
/// I_A⁻¹ = P diag(1/I_k) Pᵀ (never a numerical inverse of I).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct FreeBody {
    inertia_b: Matrix3<f64>,
    inertia_inv_b: Matrix3<f64>,
    /// Principal moments about A (kg·m²), in the order of the columns of `axes_b`.
    moments_p: Vector3<f64>,
    /// Principal axes about A: columns in body axes, a proper rotation, v_b = P v_p.
    axes_b: Rotation3<f64>,
    /// Position of C relative to A, body axes.
    rho_c_b: Vector3<f64>,
    mass: f64,
}

/// Why a body cannot turn freely.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[error(
    "the inertia about the moment center has a zero principal moment ({moments:?} kg*m^2): rotation about that axis (e.g. a thin rod's own axis) is undefined, so free rotation is refused; give the body a thickness (shape = \"cylinder\" or principal moments > 0) or use a fixed-axis motion"
)]
pub struct SingularInertia {
    pub moments: [f64; 3],
}

impl FreeBody {
    /// The body about the point `center_b` (relative to C, body axes): C itself, or a fixed pivot.
    ///
    /// Refuses ([`SingularInertia`]) a principal moment ≤ 1e-12 × the largest: the inertia tensor of a body with a
    /// zero principal moment (a thin rod) does not determine the rotation about that axis, see the README's
    /// "Numerical stability" section.
    pub fn new(body: &RigidBody, center_b: &Vector3<f64>) -> Result<Self, SingularInertia> {
        let rho_c_b = -center_b;
        let inertia_b = body.inertia_about(&rho_c_b);
        let principal = crate::body::Principal::of(&inertia_b);
        let largest = principal.moments.amax();
        if principal.moments.iter().any(|&m| m <= 1e-12 * largest) {
            return Err(SingularInertia {
                moments: principal.moments.into(),
            });
        }
        let p = principal.axes_b.matrix();
        let inertia_inv_b =
            p * Matrix3::from_diagonal(&principal.moments.map(|m| 1.0 / m)) * p.transpose();
        Ok(Self {
            inertia_b,
            inertia_inv_b,
            moments_p: principal.moments,
            axes_b: principal.axes_b,
            rho_c_b,
            mass: body.mass(),
        })
    }

    /// I_A in body axes.
    pub fn inertia_b(&self) -> &Matrix3<f64> {
        &self.inertia_b
    }

    /// I_A⁻¹ in body axes.
    pub fn inertia_inv_b(&self) -> &Matrix3<f64> {
        &self.inertia_inv_b
    }

    /// Principal moments of I_A (kg·m²), in the order of the columns of [`Self::principal_axes_b`]: body-axis order
    /// when I_A is diagonal in body axes, else ascending. I_A = P diag(moments) Pᵀ.
    pub fn principal_moments(&self) -> &Vector3<f64> {
        &self.moments_p
    }

    /// The principal axes P of I_A: its columns are the principal axes in body axes, det P = +1, so a vector in
    /// principal axes maps to body axes as v_b = P v_p, and the attitude of the principal axes is q_p = q_b ⊗ P.
    pub fn principal_axes_b(&self) -> &Rotation3<f64> {
        &self.axes_b
    }

    /// Position of C relative to the moment center, body axes.
    pub fn rho_c_b(&self) -> &Vector3<f64> {
        &self.rho_c_b
    }

    /// Mass (kg).
    pub fn mass(&self) -> f64 {
        self.mass
    }
}

/// Kinematics of the attitude: q̇ = ½ q ⊗ (0, ω_b).
#[inline(always)]
pub fn quaternion_rate(q: &[f64; 4], omega_b: &Vector3<f64>) -> [f64; 4] {
    let [w, x, y, z] = *q;
    let (a, b, c) = (omega_b[0], omega_b[1], omega_b[2]);
    [
        -0.5 * (x * a + y * b + z * c),
        0.5 * (w * a + y * c - z * b),
        0.5 * (w * b + z * a - x * c),
        0.5 * (w * c + x * b - y * a),
    ]
}

/// The attitude held in a state vector, normalised.
#[inline(always)]
pub fn attitude(y: &State) -> UnitQuaternion<f64> {
    UnitQuaternion::new_normalize(nalgebra::Quaternion::new(y[3], y[4], y[5], y[6]))
}

/// Renormalises the quaternion part of a state.
#[inline(always)]
fn normalise_quaternion(y: &mut State) {
    let n = (y[3] * y[3] + y[4] * y[4] + y[5] * y[5] + y[6] * y[6]).sqrt();
    for k in 3..7 {
        y[k] /= n;
    }
}

#[inline(always)]
fn with_attitude_rate(first: Vector3<f64>, y: &State, omega_b: &Vector3<f64>) -> State {
    let dq = quaternion_rate(&[y[3], y[4], y[5], y[6]], omega_b);
    State::from([first[0], first[1], first[2], dq[0], dq[1], dq[2], dq[3]])
}

/// Body form, state (ω_b, q): I ω̇ = M_b − ω × I ω (Euler's equation in body axes, eq. 8.9 with constant I),
/// q̇ = ½ q ⊗ (0, ω_b).
#[derive(Debug, Clone)]
pub struct BodyForm<M: AppliedMoment> {
    pub body: FreeBody,
    pub moment: M,
}

impl<M: AppliedMoment> OdeSystem<7> for BodyForm<M> {
    #[inline]
    fn rhs(&mut self, t: f64, y: &State) -> State {
        let omega_b = Vector3::new(y[0], y[1], y[2]);
        let h_b = self.body.inertia_b * omega_b;
        let gyroscopic_b = omega_b.cross(&h_b);
        let omega_dot_b = if M::ZERO {
            self.body.inertia_inv_b * -gyroscopic_b
        } else {
            let m_b = self.moment.moment_b(t, &attitude(y), &omega_b);
            self.body.inertia_inv_b * (m_b - gyroscopic_b)
        };
        with_attitude_rate(omega_dot_b, y, &omega_b)
    }

    fn project(&self, y: &mut State) {
        normalise_quaternion(y);
    }
}

/// Space form, state (H_s, q): Ḣ_s = M_s (eq. 8.9 in axes fixed in space), with
/// ω_b = I⁻¹ (Rᵀ H_s) — rotated into the body and divided by the principal moments, I_s(θ) never inverted —
/// and q̇ = ½ q ⊗ (0, ω_b).
#[derive(Debug, Clone)]
pub struct SpaceForm<M: AppliedMoment> {
    pub body: FreeBody,
    pub moment: M,
}

impl<M: AppliedMoment> OdeSystem<7> for SpaceForm<M> {
    #[inline]
    fn rhs(&mut self, t: f64, y: &State) -> State {
        let q = attitude(y);
        let h_s = Vector3::new(y[0], y[1], y[2]);
        let omega_b = self.body.inertia_inv_b * q.inverse_transform_vector(&h_s);
        let m_s = if M::ZERO {
            Vector3::zeros()
        } else {
            q * self.moment.moment_b(t, &q, &omega_b)
        };
        with_attitude_rate(m_s, y, &omega_b)
    }

    fn project(&self, y: &mut State) {
        normalise_quaternion(y);
    }
}

/// The initial state of the form `frame` from ω_b(0) and q(0).
pub fn initial_state(
    body: &FreeBody,
    frame: Frame,
    omega0_b: &Vector3<f64>,
    q0: &UnitQuaternion<f64>,
) -> State {
    let first = match frame {
        Frame::Body => *omega0_b,
        Frame::Space => q0 * (body.inertia_b * omega0_b),
    };
    State::from([first[0], first[1], first[2], q0.w, q0.i, q0.j, q0.k])
}

/// The row of a state of the form `frame` at time t.
pub fn sample<M: AppliedMoment>(
    body: &FreeBody,
    moment: &M,
    frame: Frame,
    t: f64,
    y: &State,
) -> Sample {
    let q = attitude(y);
    let first = Vector3::new(y[0], y[1], y[2]);
    let (omega_b, h_b) = match frame {
        Frame::Body => (first, body.inertia_b * first),
        Frame::Space => {
            let h_b = q.inverse_transform_vector(&first);
            (body.inertia_inv_b * h_b, h_b)
        }
    };
    let h_s = match frame {
        Frame::Body => q * h_b,
        Frame::Space => first,
    };
    let m_b = moment.moment_b(t, &q, &omega_b);
    free_sample(t, q, omega_b, h_b, h_s, m_b)
}

/// The row of a freely turning body from its attitude q, ω_b, H_b, H_s and the applied moment M_b:
/// ω_s = R ω_b, M_s = R M_b, energy ½ ω·H.
pub fn free_sample(
    t: f64,
    q: UnitQuaternion<f64>,
    omega_b: Vector3<f64>,
    h_b: Vector3<f64>,
    h_s: Vector3<f64>,
    m_b: Vector3<f64>,
) -> Sample {
    Sample {
        t,
        q,
        omega_b,
        omega_s: q * omega_b,
        h_b,
        h_s,
        m_b,
        m_s: q * m_b,
        energy: kinetic_energy(&omega_b, &h_b),
        theta: None,
        f_s: None,
        h_s_integrated: None,
    }
}
