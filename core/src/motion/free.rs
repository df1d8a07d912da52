//! Free rotation: Euler's equation integrated in body axes, state (ω_b, q), or in space axes, state (H_s, q),
//! about the moment center (C, or the fixed pivot of a gravity effect).
//!
//! The applied moment is a type parameter ([`AppliedMoment`]): a torque-free run uses
//! [`TorqueFree`](crate::effects::TorqueFree), whose zero moment the compiler removes, so an absent effect costs
//! nothing per step; otherwise [`EffectMoments`](crate::effects::EffectMoments) sums the scene's effects.

use nalgebra::{Matrix3, Quaternion, Rotation3, SVector, UnitQuaternion, Vector3};

use crate::body::RigidBody;
use crate::effects::AppliedMoment;
use crate::frames::{BodyAxes, Form, SpaceAxes, StateRotation, Vector};
use crate::integrate::OdeSystem;
use crate::kinetics::kinetic_energy;
use crate::sample::Sample;

/// State vector of both forms: (ω_b or H_s, q_w, q_x, q_y, q_z).
pub type State = SVector<f64, 7>;

/// How Euler's equation is evaluated for a body: in principal form when I_A is diagonal in body axes, else with
/// the full tensor.
#[derive(Debug, Clone, Copy, PartialEq)]
enum EulerForm {
    /// I_A = diag(I_1, I_2, I_3) in body axes: ω̇_k = e_k ω_{k+1} ω_{k+2} + M_k / I_k (k cyclic), the reciprocals
    /// 1/I_k and the coefficients e_k = (I_{k+1} − I_{k+2}) / I_k computed once.
    Principal {
        inertia_recip_b: Vector3<f64>,
        euler_coefficients: Vector3<f64>,
    },
    /// A general tensor: ω̇ = I⁻¹ (M − ω × I ω) with the 3×3 products.
    General,
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
    rho_c_b: Vector<BodyAxes>,
    mass: f64,
    euler: EulerForm,
}

/// Why a body cannot turn freely.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[error(
    "the inertia about the moment center has a zero principal moment ({moments:?} kg*m^2): rotation about that axis (e.g. a thin rod's own axis) is undefined, so free rotation is refused; give the body a thickness (shape = \"cylinder\" or principal moments > 0) or use a fixed-axis motion"
)]
pub struct SingularInertia {
    /// The principal moments about the moment center (kg·m²).
    pub moments: [f64; 3],
}

impl FreeBody {
    /// The body about the point `center_b` (relative to C, body axes): C itself, or a fixed pivot.
    ///
    /// Refuses ([`SingularInertia`]) a principal moment ≤ 1e-12 × the largest: the inertia tensor of a body with a
    /// zero principal moment (a thin rod) does not determine the rotation about that axis, see the README's
    /// "Numerical stability" section.
    pub fn new(body: &RigidBody, center_b: &Vector<BodyAxes>) -> Result<Self, SingularInertia> {
        let rho_c_b = -*center_b;
        Self::of(body.inertia_about(&rho_c_b), rho_c_b, body.mass())
    }

    /// The same body about the same center with the inertia about C replaced by `inertia_c_b` (body axes), which
    /// need only be positive definite (a fit steps through tensors no mass distribution has): I_A = I_C +
    /// m (|ρ|² 1 − ρ ρᵀ) with ρ = ρ_C the position of C relative to A (eq. 8.12's parallel axes).
    ///
    /// ```
    /// use eulerdyn::body::RigidBody;
    /// use eulerdyn::frames::Vector;
    /// use eulerdyn::motion::free::FreeBody;
    /// use nalgebra::{Matrix3, Vector3};
    /// let body = RigidBody::from_principal(2.0, [1.0, 2.0, 3.0]).unwrap();
    /// let free = FreeBody::new(&body, &Vector::new(Vector3::zeros())).unwrap();
    /// let other = free.with_inertia_c(&Matrix3::from_diagonal(&Vector3::new(1.0, 1.0, 2.5))).unwrap();
    /// assert_eq!(other.inertia_b()[(2, 2)], 2.5);
    /// ```
    pub fn with_inertia_c(&self, inertia_c_b: &Matrix3<f64>) -> Result<Self, SingularInertia> {
        let rho = *self.rho_c_b;
        let parallel =
            (Matrix3::identity() * rho.norm_squared() - rho * rho.transpose()) * self.mass;
        Self::of(inertia_c_b + parallel, self.rho_c_b, self.mass)
    }

    /// The body of inertia `inertia_b` about A, C at `rho_c_b` from A, of `mass`.
    fn of(
        inertia_b: Matrix3<f64>,
        rho_c_b: Vector<BodyAxes>,
        mass: f64,
    ) -> Result<Self, SingularInertia> {
        let principal = crate::body::Principal::of(&inertia_b);
        let largest = principal.moments.amax();
        if principal.moments.iter().any(|&m| m <= 1e-12 * largest) {
            return Err(SingularInertia {
                moments: principal.moments.into(),
            });
        }
        let p = principal.axes_b.matrix();
        let inertia_recip_p = principal.moments.map(|m| 1.0 / m);
        let inertia_inv_b = p * Matrix3::from_diagonal(&inertia_recip_p) * p.transpose();
        let diagonal = (0..3).all(|r| (0..3).all(|c| r == c || inertia_b[(r, c)] == 0.0));
        let euler = if diagonal {
            let i = inertia_b.diagonal();
            EulerForm::Principal {
                inertia_recip_b: i.map(|m| 1.0 / m),
                euler_coefficients: Vector3::new(
                    (i[1] - i[2]) / i[0],
                    (i[2] - i[0]) / i[1],
                    (i[0] - i[1]) / i[2],
                ),
            }
        } else {
            EulerForm::General
        };
        Ok(Self {
            inertia_b,
            inertia_inv_b,
            moments_p: principal.moments,
            axes_b: principal.axes_b,
            rho_c_b,
            mass,
            euler,
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

    /// The moment of momentum about the moment center A and the kinetic energy at the angular velocity `omega_b`:
    /// H_A = I_A ω_b (eq. 8.6: A fixed or A = C) and T = ½ ω_b·H_A.
    pub fn momentum_and_energy(&self, omega_b: &Vector<BodyAxes>) -> (Vector<BodyAxes>, f64) {
        let h_a_b = self.inertia_b * **omega_b;
        (Vector::new(h_a_b), kinetic_energy(omega_b, &h_a_b))
    }

    /// Position of C relative to the moment center A, body axes.
    pub fn rho_c_b(&self) -> &Vector<BodyAxes> {
        &self.rho_c_b
    }

    /// Mass (kg).
    pub fn mass(&self) -> f64 {
        self.mass
    }

    /// ω̇_b from Euler's equation about A in body axes, I_A ω̇ = M_A − ω × I_A ω, with M_A = 0 when `m_a_b` is `None`. When I_A is
    /// diagonal in body axes, in principal form: I_1 ω̇_1 = M_1 − (I_3 − I_2) ω_2 ω_3 (and cyclic), evaluated as
    /// ω̇_k = e_k ω_{k+1} ω_{k+2} + M_k / I_k with e_k = (I_{k+1} − I_{k+2}) / I_k; else ω̇ = I⁻¹ (M − ω × I ω).
    #[inline(always)]
    pub fn omega_dot_b(
        &self,
        omega_b: &Vector<BodyAxes>,
        m_a_b: Option<&Vector<BodyAxes>>,
    ) -> Vector<BodyAxes> {
        Vector::new(self.omega_dot(omega_b, m_a_b.map(|m| &**m)))
    }

    /// [`Self::omega_dot_b`] on the coordinates.
    #[inline(always)]
    fn omega_dot(&self, omega_b: &Vector3<f64>, m_b: Option<&Vector3<f64>>) -> Vector3<f64> {
        match &self.euler {
            EulerForm::Principal {
                inertia_recip_b,
                euler_coefficients: e,
            } => {
                let (w1, w2, w3) = (omega_b[0], omega_b[1], omega_b[2]);
                let gyroscopic = Vector3::new(e[0] * w2 * w3, e[1] * w3 * w1, e[2] * w1 * w2);
                match m_b {
                    None => gyroscopic,
                    Some(m_b) => gyroscopic + inertia_recip_b.component_mul(m_b),
                }
            }
            EulerForm::General => {
                let gyroscopic_b = omega_b.cross(&(self.inertia_b * omega_b));
                match m_b {
                    None => self.inertia_inv_b * -gyroscopic_b,
                    Some(m_b) => self.inertia_inv_b * (m_b - gyroscopic_b),
                }
            }
        }
    }

    /// ω_b = I_A⁻¹ H_A: diag(1/I_k) H_A when I_A is diagonal in body axes, else the 3×3 product with I_A⁻¹.
    #[inline(always)]
    pub fn omega_b_of(&self, h_a_b: &Vector<BodyAxes>) -> Vector<BodyAxes> {
        Vector::new(match &self.euler {
            EulerForm::Principal {
                inertia_recip_b, ..
            } => inertia_recip_b.component_mul(h_a_b),
            EulerForm::General => self.inertia_inv_b * **h_a_b,
        })
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
pub(crate) fn normalise_quaternion(y: &mut State) {
    let n = (y[3] * y[3] + y[4] * y[4] + y[5] * y[5] + y[6] * y[6]).sqrt();
    for k in 3..7 {
        y[k] /= n;
    }
}

#[inline(always)]
pub(crate) fn with_attitude_rate(first: Vector3<f64>, y: &State, omega_b: &Vector3<f64>) -> State {
    let dq = quaternion_rate(&[y[3], y[4], y[5], y[6]], omega_b);
    State::from([first[0], first[1], first[2], dq[0], dq[1], dq[2], dq[3]])
}

/// Body form, state (ω_b, q): I ω̇ = M_b − ω × I ω (Euler's equation in body axes, eq. 8.9 with constant I; in
/// principal form when I_A is diagonal in body axes, [`FreeBody::omega_dot_b`]), q̇ = ½ q ⊗ (0, ω_b).
#[derive(Debug, Clone)]
pub struct BodyForm<M: AppliedMoment> {
    /// The body about its moment center.
    pub body: FreeBody,
    /// The applied moment M(t, q, ω).
    pub moment: M,
}

impl<M: AppliedMoment> OdeSystem<7> for BodyForm<M> {
    #[inline(always)]
    fn rhs(&mut self, t: f64, y: &State) -> State {
        let omega_b = Vector::new(Vector3::new(y[0], y[1], y[2]));
        let omega_dot_b = if M::ZERO {
            self.body.omega_dot_b(&omega_b, None)
        } else {
            let q_state = Quaternion::new(y[3], y[4], y[5], y[6]);
            let m_b = self.moment.moment_b_at_state(
                t,
                &q_state,
                || StateRotation::of(&q_state),
                &omega_b,
            );
            self.body.omega_dot_b(&omega_b, Some(&Vector::new(m_b)))
        };
        with_attitude_rate(*omega_dot_b, y, &omega_b)
    }

    fn project(&self, y: &mut State) {
        normalise_quaternion(y);
    }

    fn next_breakpoint(&self, t: f64) -> Option<f64> {
        self.moment.corner_after(t)
    }
}

/// Space form, state (H_s, q): Ḣ_s = M_s (eq. 8.9 in axes fixed in space), with
/// ω_b = I⁻¹ (Rᵀ H_s) — rotated into the body and divided by the principal moments, I_s(θ) never inverted;
/// diag(1/I_k) Rᵀ H_s when I_A is diagonal in body axes, [`FreeBody::omega_b_of`] —
/// and q̇ = ½ q ⊗ (0, ω_b). R is the rotation of the state's quaternion normalised, [`StateRotation`].
#[derive(Debug, Clone)]
pub struct SpaceForm<M: AppliedMoment> {
    /// The body about its moment center.
    pub body: FreeBody,
    /// The applied moment M(t, q, ω).
    pub moment: M,
}

impl<M: AppliedMoment> OdeSystem<7> for SpaceForm<M> {
    #[inline(always)]
    fn rhs(&mut self, t: f64, y: &State) -> State {
        let q_state = Quaternion::new(y[3], y[4], y[5], y[6]);
        let rotation = StateRotation::of(&q_state);
        let h_s = Vector3::new(y[0], y[1], y[2]);
        let omega_b = *self.body.omega_b_of(&Vector::new(rotation.to_body(&h_s)));
        let m_s = if M::ZERO {
            Vector3::zeros()
        } else {
            rotation.to_space(
                &self
                    .moment
                    .moment_b_at_state(t, &q_state, || rotation, &omega_b),
            )
        };
        with_attitude_rate(m_s, y, &omega_b)
    }

    fn project(&self, y: &mut State) {
        normalise_quaternion(y);
    }

    fn next_breakpoint(&self, t: f64) -> Option<f64> {
        self.moment.corner_after(t)
    }
}

/// The initial state of the form `form` from ω_b(0) and q(0): (ω_b, q) or (H_A,s = R I_A ω_b, q).
pub fn initial_state(
    body: &FreeBody,
    form: Form,
    omega0_b: &Vector<BodyAxes>,
    q0: &UnitQuaternion<f64>,
) -> State {
    let first = form.first_states(omega0_b, || q0 * (body.inertia_b * **omega0_b));
    State::from([first[0], first[1], first[2], q0.w, q0.i, q0.j, q0.k])
}

/// The row of a state of the form `frame` at time t.
pub fn sample<M: AppliedMoment>(
    body: &FreeBody,
    moment: &M,
    form: Form,
    t: f64,
    y: &State,
) -> Sample {
    let q = attitude(y);
    let first = Vector3::new(y[0], y[1], y[2]);
    let (omega_b, h_a_b, h_a_s) = match form {
        Form::Body => {
            let h_a_b = Vector::<BodyAxes>::new(body.inertia_b * first);
            (Vector::new(first), h_a_b, h_a_b.in_space(&q))
        }
        Form::Space => {
            let h_a_s = Vector::<SpaceAxes>::new(first);
            let h_a_b = h_a_s.in_body(&q);
            (body.omega_b_of(&h_a_b), h_a_b, h_a_s)
        }
    };
    let m_a_b = Vector::new(moment.moment_b(t, &q, &omega_b));
    free_sample(t, q, omega_b, (h_a_b, h_a_s), m_a_b)
}

/// The row of a freely turning body from its attitude q, ω_b, H_A in both axes and the applied moment M_A in
/// body axes (A the moment center): ω_s = R ω_b, M_A,s = R M_A,b, energy ½ ω·H_A.
pub fn free_sample(
    t: f64,
    q: UnitQuaternion<f64>,
    omega_b: Vector<BodyAxes>,
    h_a: (Vector<BodyAxes>, Vector<SpaceAxes>),
    m_a_b: Vector<BodyAxes>,
) -> Sample {
    Sample::rigid(t, q, omega_b, h_a, (m_a_b, m_a_b.in_space(&q)))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::effects::{Effect, EffectMoments, TorqueGiven};
    use crate::frames::Axes;
    use crate::profile::Profile;
    use proptest::prelude::*;

    const U: f64 = f64::EPSILON / 2.0;

    fn principal_body(moments: [f64; 3]) -> FreeBody {
        FreeBody::new(
            &RigidBody::from_principal(2.0, moments).unwrap(),
            &Vector::zeros(),
        )
        .unwrap()
    }

    /// The same body evaluated through the 3×3 products.
    fn general(body: &FreeBody) -> FreeBody {
        FreeBody {
            euler: EulerForm::General,
            ..*body
        }
    }

    fn v(x: f64, y: f64, z: f64) -> Vector3<f64> {
        Vector3::new(x, y, z)
    }

    #[test]
    fn the_principal_form_is_chosen_exactly_when_the_tensor_is_diagonal_in_body_axes() {
        let diagonal = principal_body([1.0, 2.0, 3.0]);
        assert!(matches!(diagonal.euler, EulerForm::Principal { .. }));
        // A pivot on a body axis shifts the tensor by m(|ρ|²E − ρρᵀ), still diagonal.
        let on_axis = FreeBody::new(
            &RigidBody::from_principal(2.0, [1.0, 2.0, 3.0]).unwrap(),
            &Vector::new(v(0.0, 0.0, -0.5)),
        )
        .unwrap();
        assert!(matches!(on_axis.euler, EulerForm::Principal { .. }));
        assert_eq!(on_axis.inertia_b().diagonal(), v(1.5, 2.5, 3.0));
        // Off the axes it is not.
        let off_axis = FreeBody::new(
            &RigidBody::from_principal(2.0, [1.0, 2.0, 3.0]).unwrap(),
            &Vector::new(v(0.1, 0.0, -0.5)),
        )
        .unwrap();
        assert_eq!(off_axis.euler, EulerForm::General);
        let tensor = Matrix3::new(2.0, 0.3, -0.2, 0.3, 2.5, 0.1, -0.2, 0.1, 3.0);
        let full = FreeBody::new(&RigidBody::new(1.0, tensor).unwrap(), &Vector::zeros()).unwrap();
        assert_eq!(full.euler, EulerForm::General);
    }

    proptest! {
        /// Both evaluations of I ω̇ = M − ω × I ω agree to rounding. The principal form rounds
        /// e_k = (I_{k+1} − I_{k+2})/I_k, two products, M_k/I_k and a sum; the matrix form rounds I ω, the two
        /// products of the cross product and their difference (absolute error ≈ u (I_{k+1} + I_{k+2}) |ω_{k+1} ω_{k+2}|,
        /// not relative to the difference I_{k+1} − I_{k+2}), then I⁻¹(M − …). So per component
        /// |Δω̇_k| ≤ 8u [(I_{k+1} + I_{k+2}) |ω_{k+1} ω_{k+2}| + |M_k|] / I_k.
        #[test]
        fn principal_and_matrix_forms_agree(
            i1 in 0.1f64..10.0, i2 in 0.1f64..10.0, i3 in 0.1f64..10.0,
            w in prop::array::uniform3(-50.0f64..50.0),
            m in prop::array::uniform3(-20.0f64..20.0),
        ) {
            let [i1, i2, i3] = [i1, i2, i3];
            prop_assume!(i1 + i2 >= i3 && i2 + i3 >= i1 && i3 + i1 >= i2);
            let body = principal_body([i1, i2, i3]);
            let matrix = general(&body);
            let (omega_b, m_b) = (Vector::new(Vector3::from(w)), Vector::new(Vector3::from(m)));
            let i = [i1, i2, i3];
            for torque in [None, Some(&m_b)] {
                let fast = body.omega_dot_b(&omega_b, torque);
                let slow = matrix.omega_dot_b(&omega_b, torque);
                for k in 0..3 {
                    let (a, b) = ((k + 1) % 3, (k + 2) % 3);
                    let m_k = torque.map_or(0.0, |m| m[k]);
                    let bound = 8.0 * U * ((i[a] + i[b]) * (omega_b[a] * omega_b[b]).abs() + m_k.abs()) / i[k];
                    prop_assert!((fast[k] - slow[k]).abs() <= bound, "k={k}: {fast} vs {slow}, bound {bound}");
                }
            }
            // ω_b = I⁻¹ H_b: I⁻¹ = P diag(1/I) Pᵀ with P = identity is exactly diag(1/I), and the zero entries add
            // exact zeros, so the two agree to the bit.
            let h_b = Vector::new(Vector3::from(m));
            prop_assert_eq!(body.omega_b_of(&h_b), matrix.omega_b_of(&h_b));
        }
    }

    #[test]
    fn both_forms_right_hand_sides_agree_with_the_matrix_path() {
        let body = principal_body([1.0, 2.0, 3.0]);
        let effects = [Effect::from(TorqueGiven {
            frame: Axes::Body,
            value: v(0.5, 0.0, 0.0),
            profile: Profile::Sine {
                freq_hz: 0.5,
                phase_deg: 0.0,
            },
        })];
        let moments = EffectMoments::new(&effects, 2.0);
        let q = UnitQuaternion::from_euler_angles(0.3, -0.2, 1.1);
        let y = State::from([0.3, -0.7, 2.0, q.w, q.i, q.j, q.k]);
        let mut fast = BodyForm {
            body,
            moment: moments.clone(),
        };
        let mut slow = BodyForm {
            body: general(&body),
            moment: moments.clone(),
        };
        let (a, b) = (fast.rhs(0.7, &y), slow.rhs(0.7, &y));
        // |ω| ≤ 2.2, I ≤ 3, |M| ≤ 0.5: the bound of principal_and_matrix_forms_agree is below 8u·(5·1.4 + 0.5).
        assert!((a - b).amax() <= 8.0 * U * 7.5, "{a} vs {b}");
        assert_eq!(a.fixed_rows::<4>(3), b.fixed_rows::<4>(3));
        let mut fast = SpaceForm {
            body,
            moment: moments.clone(),
        };
        let mut slow = SpaceForm {
            body: general(&body),
            moment: moments,
        };
        assert_eq!(fast.rhs(0.7, &y), slow.rhs(0.7, &y));
    }

    #[test]
    fn the_state_rotation_is_the_rotation_of_the_normalised_quaternion() {
        let v_b = v(0.3, -1.2, 2.0);
        for q_state in [
            nalgebra::Quaternion::new(0.9, 0.2, -0.3, 0.25),
            nalgebra::Quaternion::new(-0.1, 0.7, 0.7, -0.2) * 1.000_001,
            nalgebra::Quaternion::new(1.0, 0.0, 0.0, 0.0),
        ] {
            let q = UnitQuaternion::new_normalize(q_state);
            let rotation = StateRotation::of(&q_state);
            // A(q)/|q|² is R(q/|q|) up to the rounding of ~10 products and sums per entry: 8u |v|.
            let bound = 8.0 * U * v_b.norm();
            assert!((rotation.to_space(&v_b) - q * v_b).amax() <= bound);
            assert!((rotation.to_body(&v_b) - q.inverse_transform_vector(&v_b)).amax() <= bound);
        }
    }
}
