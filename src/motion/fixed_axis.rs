//! Prescribed rotation about an axis fixed in the body and in space (the reference notes' tilted disk and thin
//! rod): the angle θ(t) is known in closed form, and the moment the motion requires is inverse dynamics —
//! computed in body axes (Euler's equation with constant I) and, independently, in space axes with the
//! coordinate-dependent inertia I_s(θ) (eq. 8.10).

use nalgebra::{Matrix3, Unit, UnitQuaternion, Vector3};

use crate::body::RigidBody;
use crate::frames::Form;
use crate::kinetics::kinetic_energy;
use crate::motion::support::Bearings;
use crate::sample::{BearingLoads, Sample, SupportLoads};

/// Rotation about a fixed axis through the fixed point A: θ(t) = θ̇₀ t + ½ θ̈ t², attitude
/// R(t) = Rot(a_s, θ(t))·R₀ with a_s = R₀ a_b, so that the axis a_b is fixed in the body and in space.
#[derive(Debug, Clone, PartialEq)]
pub struct FixedAxis {
    mass: f64,
    /// Unit axis in body axes.
    axis_b: Unit<Vector3<f64>>,
    /// Unit axis in space axes, a_s = R₀ a_b.
    axis_s: Unit<Vector3<f64>>,
    /// θ̇ at t = 0 (rad/s).
    rate: f64,
    /// θ̈, constant (rad/s²).
    accel: f64,
    /// Attitude at t = 0 (body → space).
    q0: UnitQuaternion<f64>,
    /// Position of C relative to the moment center A, in body axes (ρ_C = −point).
    rho_c_b: Vector3<f64>,
    /// Inertia about A in body axes (parallel-axis theorem).
    inertia_a_b: Matrix3<f64>,
    /// Uniform gravity acting at C (m/s², space axes); zero without a gravity effect.
    g_s: Vector3<f64>,
    /// The two bearings, where the scene places them.
    bearings: Option<Bearings>,
}

/// The angle turned about the axis and its derivatives at one time.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct AxisAngle {
    /// θ (rad).
    pub theta: f64,
    /// θ̇ (rad/s).
    pub theta_dot: f64,
    /// θ̈ (rad/s²).
    pub theta_ddot: f64,
}

impl FixedAxis {
    /// `point_b` is the point A on the axis (the moment center), relative to C, in body axes.
    /// `axis_b` must be nonzero (the scene validates it); it is normalised here.
    pub fn new(
        body: &RigidBody,
        axis_b: Vector3<f64>,
        rate: f64,
        accel: f64,
        point_b: Vector3<f64>,
        q0: UnitQuaternion<f64>,
    ) -> Self {
        let axis_b = Unit::new_normalize(axis_b);
        let rho_c_b = -point_b;
        Self {
            mass: body.mass(),
            axis_b,
            axis_s: Unit::new_normalize(q0 * axis_b.into_inner()),
            rate,
            accel,
            q0,
            rho_c_b,
            inertia_a_b: body.inertia_about(&rho_c_b),
            g_s: Vector3::zeros(),
            bearings: None,
        }
    }

    /// The same body, axis, point and initial attitude turning at the constant `rate` (rad/s), without gravity or
    /// bearings.
    pub fn new_like(other: &FixedAxis, rate: f64) -> Self {
        Self {
            rate,
            accel: 0.0,
            g_s: Vector3::zeros(),
            bearings: None,
            ..other.clone()
        }
    }

    /// With uniform gravity `g_s` (m/s², space axes) acting at C: the support then carries the weight.
    pub fn with_gravity(mut self, g_s: Vector3<f64>) -> Self {
        self.g_s = g_s;
        self
    }

    /// With two bearings on the axis.
    pub fn with_bearings(mut self, bearings: Bearings) -> Self {
        self.bearings = Some(bearings);
        self
    }

    /// The bearings, where the scene places them.
    pub fn bearings(&self) -> Option<&Bearings> {
        self.bearings.as_ref()
    }

    /// Gravity acting at C (m/s², space axes; zero when the scene has none).
    pub fn g_s(&self) -> &Vector3<f64> {
        &self.g_s
    }

    /// Mass (kg).
    pub fn mass(&self) -> f64 {
        self.mass
    }

    /// Unit axis in body axes.
    pub fn axis_b(&self) -> &Unit<Vector3<f64>> {
        &self.axis_b
    }

    /// θ̇ at t = 0 (rad/s).
    pub fn rate(&self) -> f64 {
        self.rate
    }

    /// θ̈ (rad/s²).
    pub fn accel(&self) -> f64 {
        self.accel
    }

    /// The moment center A on the axis, relative to C, body axes.
    pub fn point_b(&self) -> Vector3<f64> {
        -self.rho_c_b
    }

    /// Unit axis in space axes.
    pub fn axis_s(&self) -> &Unit<Vector3<f64>> {
        &self.axis_s
    }

    /// Inertia about the moment center A, in body axes: I_A = I_C + m(|ρ|²E − ρρᵀ).
    pub fn inertia_a_b(&self) -> &Matrix3<f64> {
        &self.inertia_a_b
    }

    /// Position of C relative to A in body axes.
    pub fn rho_c_b(&self) -> &Vector3<f64> {
        &self.rho_c_b
    }

    /// I_uu = u·I_A u, the moment of inertia about the axis (kg·m²).
    pub fn i_uu(&self) -> f64 {
        let u_b = self.axis_b.into_inner();
        u_b.dot(&(self.inertia_a_b * u_b))
    }

    /// The imbalance about the axis, body axes: static s = m ρ_C⊥ (kg·m; C's offset from the axis times the mass)
    /// and dynamic d = I_A u − (u·I_A u) u (kg·m², the product of inertia about the axis). Both vanish for a
    /// balanced rotor, whose bearings then carry no rotating load.
    pub fn imbalance(&self) -> (Vector3<f64>, Vector3<f64>) {
        let u_b = self.axis_b.into_inner();
        let rho = self.rho_c_b;
        let i_u = self.inertia_a_b * u_b;
        (
            (rho - u_b * rho.dot(&u_b)) * self.mass,
            i_u - u_b * i_u.dot(&u_b),
        )
    }

    /// Whether C lies off the axis (then C moves on a circle and a force is required).
    pub fn center_off_axis(&self) -> bool {
        self.rho_c_b.cross(&self.axis_b).norm() > 1e-12 * self.rho_c_b.norm()
    }

    /// θ(t) = θ̇₀ t + ½ θ̈ t², θ̇(t) = θ̇₀ + θ̈ t, θ̈ constant.
    pub fn angle(&self, t: f64) -> AxisAngle {
        AxisAngle {
            theta: self.rate * t + 0.5 * self.accel * t * t,
            theta_dot: self.rate + self.accel * t,
            theta_ddot: self.accel,
        }
    }

    /// Attitude R(θ) = Rot(a_s, θ)·R₀ (body → space).
    pub fn attitude(&self, theta: f64) -> UnitQuaternion<f64> {
        UnitQuaternion::from_axis_angle(&self.axis_s, theta) * self.q0
    }

    /// ω_b = θ̇ a_b.
    pub fn omega_b(&self, angle: &AxisAngle) -> Vector3<f64> {
        self.axis_b.into_inner() * angle.theta_dot
    }

    /// ω_s = θ̇ a_s.
    pub fn omega_s(&self, angle: &AxisAngle) -> Vector3<f64> {
        self.axis_s.into_inner() * angle.theta_dot
    }

    /// Moment of momentum about the fixed point A in body axes, H_A = I_A · ω (eq. 8.6).
    pub fn h_b(&self, angle: &AxisAngle) -> Vector3<f64> {
        self.inertia_a_b * self.omega_b(angle)
    }

    /// Required moment about A in body axes, Euler's equation with the constant body inertia:
    /// M_b = I_A · α + ω × (I_A · ω), with α = θ̈ a_b (eq. 8.9 in body axes).
    pub fn moment_b(&self, angle: &AxisAngle) -> Vector3<f64> {
        let omega_b = self.omega_b(angle);
        let alpha_b = self.axis_b.into_inner() * angle.theta_ddot;
        self.inertia_a_b * alpha_b + omega_b.cross(&(self.inertia_a_b * omega_b))
    }

    /// The coordinate-dependent inertia in space axes, I_s(θ) = R(θ) I_A Rᵀ(θ) (eq. 8.10; the notes' rod example
    /// I(θ) = Tᵗ I T).
    pub fn inertia_s(&self, theta: f64) -> Matrix3<f64> {
        let r = self.attitude(theta).to_rotation_matrix();
        r.matrix() * self.inertia_a_b * r.matrix().transpose()
    }

    /// dI_s/dθ = â_s I_s − I_s â_s, since dR/dθ = â_s R (â the cross-product matrix of a_s).
    pub fn inertia_s_derivative(&self, theta: f64) -> Matrix3<f64> {
        let a_hat = self.axis_s.into_inner().cross_matrix();
        let i_s = self.inertia_s(theta);
        a_hat * i_s - i_s * a_hat
    }

    /// Required moment about A in space axes, Euler's equation with the coordinate-dependent inertia (eq. 8.10):
    /// M_s = d/dt[I_s(θ) ω_s] = (dI_s/dθ) θ̇ ω_s + I_s(θ) ω̇_s, with ω̇_s = θ̈ a_s.
    pub fn moment_s(&self, angle: &AxisAngle) -> Vector3<f64> {
        let omega_s = self.omega_s(angle);
        let omega_dot_s = self.axis_s.into_inner() * angle.theta_ddot;
        self.inertia_s_derivative(angle.theta) * omega_s * angle.theta_dot
            + self.inertia_s(angle.theta) * omega_dot_s
    }

    /// Position of C relative to A in space axes.
    pub fn rho_c_s(&self, angle: &AxisAngle) -> Vector3<f64> {
        self.attitude(angle.theta) * self.rho_c_b
    }

    /// Acceleration of C: a_C = α × ρ + ω × (ω × ρ), space axes (tangential and centripetal parts; A is fixed).
    pub fn accel_c_s(&self, angle: &AxisAngle) -> Vector3<f64> {
        let rho_s = self.rho_c_s(angle);
        let omega_s = self.omega_s(angle);
        let alpha_s = self.axis_s.into_inner() * angle.theta_ddot;
        alpha_s.cross(&rho_s) + omega_s.cross(&omega_s.cross(&rho_s))
    }

    /// Required force on the body, F = m a_C (eq. 8.7), space axes.
    pub fn force_s(&self, angle: &AxisAngle) -> Vector3<f64> {
        self.accel_c_s(angle) * self.mass
    }
}

impl FixedAxis {
    /// The full kinetic state at time t, with the required moment computed in the form `frame` selects (the other
    /// frame's components by rotation): body form [`FixedAxis::moment_b`], space form [`FixedAxis::moment_s`].
    /// Energy is ½ ω·H_A, the body's whole kinetic energy since A is fixed.
    pub fn sample(&self, t: f64, frame: Form) -> Sample {
        let angle = self.angle(t);
        let q = self.attitude(angle.theta);
        let weight_moment_s = (q * self.rho_c_b).cross(&(self.g_s * self.mass));
        self.sample_at(t, &angle, &q, frame, &weight_moment_s)
    }

    /// The kinetic state and the support's loads at time t and the angle `angle` (see [`Self::sample`] and
    /// [`crate::motion::support`]), where the effects apply the moment `m_eff_s` about A (space axes) and
    /// gravity its weight at C; `q` is [`Self::attitude`] at `angle.theta`, which the caller has computed.
    pub fn sample_at(
        &self,
        t: f64,
        angle: &AxisAngle,
        q: &UnitQuaternion<f64>,
        frame: Form,
        m_eff_s: &Vector3<f64>,
    ) -> Sample {
        let (angle, q) = (*angle, *q);
        let omega_b = self.omega_b(&angle);
        let h_b = self.h_b(&angle);
        let (m_b, m_s) = match frame {
            Form::Body => {
                let m_b = self.moment_b(&angle);
                (m_b, q * m_b)
            }
            Form::Space => {
                let m_s = self.moment_s(&angle);
                (q.inverse() * m_s, m_s)
            }
        };
        Sample {
            t,
            q,
            omega_b,
            omega_s: self.omega_s(&angle),
            h_b,
            h_s: q * h_b,
            m_b,
            m_s,
            energy: kinetic_energy(&omega_b, &h_b),
            theta: Some(angle.theta),
            f_s: self.center_off_axis().then(|| self.force_s(&angle)),
            h_s_integrated: None,
            support: Some(self.support(&angle, &q, &m_s, m_eff_s)),
            potential: None,
            rotors: None,
        }
    }
}

impl FixedAxis {
    /// What the support supplies when the resultant moment about A is `m_s` and the effects' is `m_eff_s` (space
    /// axes): F_sup = m a_C − m g, M_sup = m_s − m_eff_s, the drive's M_sup·u and, with bearings, their split (see
    /// [`crate::motion::support`]).
    fn support(
        &self,
        angle: &AxisAngle,
        q: &UnitQuaternion<f64>,
        m_s: &Vector3<f64>,
        m_eff_s: &Vector3<f64>,
    ) -> SupportLoads {
        let f_sup_s = self.force_s(angle) - self.g_s * self.mass;
        let m_sup_s = m_s - m_eff_s;
        let u_s = self.axis_s.into_inner();
        SupportLoads {
            theta_dot: angle.theta_dot,
            theta_ddot: angle.theta_ddot,
            f_sup_s,
            m_sup_s,
            m_drive: m_sup_s.dot(&u_s),
            bearings: self.bearings.map(|bearings| {
                let (r_a_s, r_b_s) = bearings.split(&f_sup_s, &m_sup_s, &u_s);
                BearingLoads {
                    r_a_s,
                    r_b_s,
                    r_a_b: q.inverse_transform_vector(&r_a_s),
                    r_b_b: q.inverse_transform_vector(&r_b_s),
                }
            }),
        }
    }
}
