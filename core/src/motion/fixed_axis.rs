//! Prescribed rotation about an axis fixed in the body and in space (the reference notes' tilted disk and thin
//! rod): the angle θ(t) is known in closed form, and the moment the motion requires is inverse dynamics —
//! computed in body axes (Euler's equation with constant I) and, independently, in space axes with the
//! coordinate-dependent inertia I_s(θ) (eq. 8.10). In a turning carrier ([`crate::motion::carrier`]) the axis is
//! fixed in the carrier and the methods taking an [`AxisAngle`] alone describe the rotation relative to it, their
//! vectors in body axes or in the carrier's ([`SupportAxes`], `_c`: space axes when nothing moves the support);
//! [`FixedAxis::rotation`] and [`FixedAxis::sample`] give the motion in space, ω = Ω_c + θ̇ u. In a vehicle
//! ([`crate::motion::carrier::vehicle`]) A accelerates at a_A: the rotation is the same, C's acceleration gains a_A
//! and the moment about A gains ρ × m a_A; every moment here is about A.

use std::sync::Arc;

use nalgebra::{Matrix3, Unit, UnitQuaternion, Vector3};

use crate::body::RigidBody;
use crate::frames::{BodyAxes, Form, SpaceAxes, SupportAxes, Vector};
use crate::kinetics::kinetic_energy;
use crate::motion::moving_support::{MovingSupport, SupportMotion};
use crate::motion::support::Bearings;
use crate::sample::{BearingLoads, Sample, SupportLoads};

/// Rotation about a fixed axis through the fixed point A: θ(t) = θ̇₀ t + ½ θ̈ t², attitude
/// R(t) = Rot(a_c, θ(t))·R₀ with a_c = R₀ a_b, so that the axis a_b is fixed in the body and in the support (space, or
/// a carrier's axes).
#[derive(Debug, Clone, PartialEq)]
pub struct FixedAxis {
    mass: f64,
    /// Unit axis in body axes.
    axis_b: Unit<Vector3<f64>>,
    /// Unit axis in the support's axes, a_c = R₀ a_b (space axes when the support does not move).
    axis_c: Unit<Vector3<f64>>,
    /// θ̇ at t = 0 (rad/s).
    rate: f64,
    /// θ̈, constant (rad/s²).
    accel: f64,
    /// Attitude at t = 0 (body → space).
    q0: UnitQuaternion<f64>,
    /// Position of C relative to the moment center A, in body axes (ρ_C = −point).
    rho_c_b: Vector<BodyAxes>,
    /// Inertia about A in body axes (parallel-axis theorem).
    inertia_a_b: Matrix3<f64>,
    /// Uniform gravity acting at C (m/s², space axes); zero without a gravity effect.
    g_s: Vector<SpaceAxes>,
    /// The two bearings, where the scene places them.
    bearings: Option<Bearings>,
    /// What moves the axis's support in space (a carrier); `None`: the axis is fixed in space.
    support: Option<Arc<dyn MovingSupport>>,
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
        axis_b: Vector<BodyAxes>,
        rate: f64,
        accel: f64,
        point_b: Vector<BodyAxes>,
        q0: UnitQuaternion<f64>,
    ) -> Self {
        let axis_b = Unit::new_normalize(axis_b.into_inner());
        let rho_c_b = -point_b;
        Self {
            mass: body.mass(),
            axis_b,
            axis_c: Unit::new_normalize(q0 * axis_b.into_inner()),
            rate,
            accel,
            q0,
            rho_c_b,
            inertia_a_b: body.inertia_about(&rho_c_b),
            g_s: Vector::zeros(),
            bearings: None,
            support: None,
        }
    }

    /// The same body, axis, point and initial attitude turning at the constant `rate` (rad/s), without gravity,
    /// bearings or carrier.
    pub fn new_like(other: &FixedAxis, rate: f64) -> Self {
        Self {
            rate,
            accel: 0.0,
            g_s: Vector::zeros(),
            bearings: None,
            support: None,
            ..other.clone()
        }
    }

    /// With the axis, its point and its bearings fixed in a `support` that moves in space, such as a turning
    /// carrier (the motion's other methods then describe the rotation relative to the support; [`Self::sample`]
    /// the motion in space).
    ///
    /// ```
    /// use eulerdyn::Form;
    /// use eulerdyn::body::RigidBody;
    /// use eulerdyn::motion::carrier::Carrier;
    /// use eulerdyn::profile::Profile;
    /// use eulerdyn::motion::fixed_axis::FixedAxis;
    /// use eulerdyn::frames::Vector;
    /// use nalgebra::{UnitQuaternion, Vector3};
    /// // A rotor (I_x = 2 kg·m²) spinning at 10 rad/s about x in a carrier yawing at 0.5 rad/s about z.
    /// let body = RigidBody::from_principal(1.0, [2.0, 1.0, 1.0])?;
    /// let rotor = FixedAxis::new(&body, Vector::new(Vector3::x()), 10.0, 0.0, Vector::zeros(), UnitQuaternion::identity())
    ///     .with_support(Carrier::new(Vector3::new(0.0, 0.0, 0.5), Profile::Constant));
    /// assert!(rotor.moving_support().is_some());
    /// // The gyroscopic couple Ω_c × H = I_x θ̇ Ω_c = 10 N·m about y.
    /// let m_a_s = rotor.required_moment_a_s(0.0, Form::Body);
    /// assert!((*m_a_s - Vector3::new(0.0, 10.0, 0.0)).norm() < 1e-12);
    /// # Ok::<(), Box<dyn std::error::Error>>(())
    /// ```
    pub fn with_support(mut self, support: impl MovingSupport) -> Self {
        self.support = Some(Arc::new(support));
        self
    }

    /// What moves the support, if anything does.
    pub fn moving_support(&self) -> Option<&dyn MovingSupport> {
        self.support.as_deref()
    }

    /// With uniform gravity `g_s` (m/s², space axes) acting at C: the support then carries the weight.
    ///
    /// ```
    /// use eulerdyn::Form;
    /// use eulerdyn::body::RigidBody;
    /// use eulerdyn::motion::fixed_axis::FixedAxis;
    /// use eulerdyn::frames::Vector;
    /// use nalgebra::{UnitQuaternion, Vector3};
    /// // 2 kg spinning about an axis through C: C does not accelerate, so the support force is −m g.
    /// let body = RigidBody::from_principal(2.0, [2.0, 1.0, 1.0])?;
    /// let rotor = FixedAxis::new(&body, Vector::new(Vector3::x()), 10.0, 0.0, Vector::zeros(), UnitQuaternion::identity())
    ///     .with_gravity(Vector::new(Vector3::new(0.0, 0.0, -9.81)));
    /// let support = rotor.sample(0.3, Form::Body).support.unwrap();
    /// assert!((*support.f_sup_s - Vector3::new(0.0, 0.0, 19.62)).norm() < 1e-12);
    /// # Ok::<(), Box<dyn std::error::Error>>(())
    /// ```
    pub fn with_gravity(mut self, g_s: Vector<SpaceAxes>) -> Self {
        self.g_s = g_s;
        self
    }

    /// With two bearings on the axis.
    ///
    /// ```
    /// use eulerdyn::Form;
    /// use eulerdyn::body::RigidBody;
    /// use eulerdyn::motion::fixed_axis::FixedAxis;
    /// use eulerdyn::motion::support::Bearings;
    /// use eulerdyn::frames::Vector;
    /// use nalgebra::{UnitQuaternion, Vector3};
    /// // A balanced rotor of 10 N weight between bearings at −1 m and +3 m: the lever rule, 7.5 N and 2.5 N.
    /// let body = RigidBody::from_principal(1.0, [2.0, 1.0, 1.0])?;
    /// let rotor = FixedAxis::new(&body, Vector::new(Vector3::x()), 10.0, 0.0, Vector::zeros(), UnitQuaternion::identity())
    ///     .with_gravity(Vector::new(Vector3::new(0.0, 0.0, -10.0)))
    ///     .with_bearings(Bearings { a: -1.0, b: 3.0 });
    /// let loads = rotor.sample(0.3, Form::Body).support.unwrap().bearings.unwrap();
    /// assert!((*loads.r_a_s - Vector3::new(0.0, 0.0, 7.5)).norm() < 1e-12);
    /// assert!((*loads.r_b_s - Vector3::new(0.0, 0.0, 2.5)).norm() < 1e-12);
    /// # Ok::<(), Box<dyn std::error::Error>>(())
    /// ```
    pub fn with_bearings(mut self, bearings: Bearings) -> Self {
        self.bearings = Some(bearings);
        self
    }

    /// The bearings, where the scene places them.
    pub fn bearings(&self) -> Option<&Bearings> {
        self.bearings.as_ref()
    }

    /// Gravity acting at C (m/s², space axes; zero when the scene has none).
    pub fn g_s(&self) -> &Vector<SpaceAxes> {
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
    pub fn point_b(&self) -> Vector<BodyAxes> {
        -self.rho_c_b
    }

    /// The unit axis a_c in the support's axes: a carrier's, or space's when the support does not move.
    pub fn axis_c(&self) -> Vector<SupportAxes> {
        Vector::new(self.axis_c.into_inner())
    }

    /// Inertia about the moment center A, in body axes: I_A = I_C + m(|ρ|²E − ρρᵀ).
    pub fn inertia_a_b(&self) -> &Matrix3<f64> {
        &self.inertia_a_b
    }

    /// Position of C relative to A in body axes.
    pub fn rho_c_b(&self) -> &Vector<BodyAxes> {
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
    pub fn imbalance(&self) -> (Vector<BodyAxes>, Vector<BodyAxes>) {
        let u_b = self.axis_b.into_inner();
        let rho = *self.rho_c_b;
        let i_u = self.inertia_a_b * u_b;
        (
            Vector::new((rho - u_b * rho.dot(&u_b)) * self.mass),
            Vector::new(i_u - u_b * i_u.dot(&u_b)),
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

    /// Attitude R(θ) = Rot(a_c, θ)·R₀, body → the support's axes (body → space when the support does not move).
    pub fn attitude(&self, theta: f64) -> UnitQuaternion<f64> {
        UnitQuaternion::from_axis_angle(&self.axis_c, theta) * self.q0
    }

    /// ω_b = θ̇ a_b, relative to the support.
    pub fn omega_b(&self, angle: &AxisAngle) -> Vector<BodyAxes> {
        Vector::new(self.axis_b.into_inner() * angle.theta_dot)
    }

    /// ω_c = θ̇ a_c, relative to the support, in its axes.
    pub fn omega_c(&self, angle: &AxisAngle) -> Vector<SupportAxes> {
        Vector::new(self.axis_c.into_inner() * angle.theta_dot)
    }

    /// Moment of momentum about the axis point A in body axes, H_A = I_A · ω (eq. 8.6), ω relative to the support.
    pub fn h_a_b(&self, angle: &AxisAngle) -> Vector<BodyAxes> {
        Vector::new(self.inertia_a_b * *self.omega_b(angle))
    }

    /// Required moment about A in body axes, Euler's equation with the constant body inertia:
    /// M_b = I_A · α + ω × (I_A · ω), with α = θ̈ a_b (eq. 8.9 in body axes), the support at rest.
    pub fn moment_a_b(&self, angle: &AxisAngle) -> Vector<BodyAxes> {
        let omega_b = self.omega_b(angle).into_inner();
        let alpha_b = self.axis_b.into_inner() * angle.theta_ddot;
        Vector::new(self.inertia_a_b * alpha_b + omega_b.cross(&(self.inertia_a_b * omega_b)))
    }

    /// The coordinate-dependent inertia about A in the support's axes, I_c(θ) = R(θ) I_A Rᵀ(θ) (eq. 8.10 in space
    /// axes; the notes' rod example I(θ) = Tᵗ I T).
    pub fn inertia_a_c(&self, theta: f64) -> Matrix3<f64> {
        let r = self.attitude(theta).to_rotation_matrix();
        r.matrix() * self.inertia_a_b * r.matrix().transpose()
    }

    /// dI_c/dθ = â_c I_c − I_c â_c, since dR/dθ = â_c R (â the cross-product matrix of a_c).
    pub fn inertia_a_c_derivative(&self, theta: f64) -> Matrix3<f64> {
        let a_hat = self.axis_c.into_inner().cross_matrix();
        let i_c = self.inertia_a_c(theta);
        a_hat * i_c - i_c * a_hat
    }

    /// Required moment about A in the support's axes, Euler's equation with the coordinate-dependent inertia
    /// (eq. 8.10), the support at rest: M_c = d/dt[I_c(θ) ω_c] = (dI_c/dθ) θ̇ ω_c + I_c(θ) ω̇_c, with ω̇_c = θ̈ a_c.
    /// Without a moving support these are space axes.
    pub fn moment_a_c(&self, angle: &AxisAngle) -> Vector<SupportAxes> {
        let omega_c = self.omega_c(angle).into_inner();
        let omega_dot_c = self.axis_c.into_inner() * angle.theta_ddot;
        Vector::new(
            self.inertia_a_c_derivative(angle.theta) * omega_c * angle.theta_dot
                + self.inertia_a_c(angle.theta) * omega_dot_c,
        )
    }
}

/// The body's rotation at one time, in space: its attitude, the axis in space, ω in both axes and the part of ω̇
/// that does not come from θ̈. Without a carrier R = Rot(a_c, θ)·R₀, u = a_c (the carrier's axes are space's),
/// ω = θ̇ u and ω̇ = θ̈ u; in a carrier R = R_c·Rot(a_c, θ)·R₀, u = R_c a_c, ω_s = Ω_c + θ̇ u and
/// ω̇_s = θ̈ u + Ω̇_c + θ̇ Ω_c × u (u turns with the carrier: u̇ = Ω_c × u).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct AxisRotation {
    /// Attitude, body → space.
    pub q: UnitQuaternion<f64>,
    /// The unit axis u in space axes.
    pub u_s: Vector<SpaceAxes>,
    /// ω in body axes (rad/s).
    pub omega_b: Vector<BodyAxes>,
    /// ω in space axes (rad/s).
    pub omega_s: Vector<SpaceAxes>,
    /// ω̇_s − θ̈ u = Ω̇_c + θ̇ Ω_c × u (space axes; zero without a carrier).
    pub bias_s: Vector<SpaceAxes>,
    /// The support's motion at this time, if it moves.
    pub support: Option<SupportMotion>,
}

impl AxisRotation {
    /// The axis point's acceleration a_A in a vehicle (space axes); `None` when A is fixed in space.
    pub fn accel_a_s(&self) -> Option<Vector<SpaceAxes>> {
        self.support.and_then(|c| c.accel_a_s)
    }

    /// ω̇_s = θ̈ u + (Ω̇_c + θ̇ Ω_c × u).
    pub fn alpha_s(&self, theta_ddot: f64) -> Vector<SpaceAxes> {
        match self.support {
            None => self.u_s * theta_ddot,
            Some(_) => self.bias_s + self.u_s * theta_ddot,
        }
    }

    /// The same placement turning at θ̇ = `theta_dot` about `axis_b` more: ω += θ̇ u, and in a carrier ω̇ gains
    /// θ̇ Ω_c × u.
    pub fn turning(mut self, axis_b: &Vector<BodyAxes>, theta_dot: f64) -> Self {
        self.omega_b += *axis_b * theta_dot;
        self.omega_s += self.u_s * theta_dot;
        if let Some(c) = self.support {
            self.bias_s += Vector::new(c.omega_c_s.cross(&*self.u_s)) * theta_dot;
        }
        self
    }
}

impl FixedAxis {
    /// The body at angle θ relative to the carrier (in space without one), at rest.
    fn relative(&self, theta: f64) -> AxisRotation {
        AxisRotation {
            q: self.attitude(theta),
            u_s: Vector::new(self.axis_c.into_inner()),
            omega_b: Vector::zeros(),
            omega_s: Vector::zeros(),
            bias_s: Vector::zeros(),
            support: None,
        }
    }

    /// The body at angle θ and time t, not turning about the axis (θ̇ = 0): only the carrier's rate.
    pub fn placed(&self, t: f64, theta: f64) -> AxisRotation {
        match self.moving_support() {
            None => self.relative(theta),
            Some(support) => {
                let c = support.at(t);
                let q = c.q_c * self.attitude(theta);
                AxisRotation {
                    q,
                    u_s: Vector::new(c.q_c * self.axis_c.into_inner()),
                    omega_b: Vector::new(q.inverse_transform_vector(&c.omega_c_s)),
                    omega_s: c.omega_c_s,
                    bias_s: c.omega_c_dot_s,
                    support: Some(c),
                }
            }
        }
    }

    /// The body at angle θ, rate θ̇ and time t ([`AxisRotation`]).
    pub fn rotation(&self, t: f64, theta: f64, theta_dot: f64) -> AxisRotation {
        self.placed(t, theta)
            .turning(&Vector::new(self.axis_b.into_inner()), theta_dot)
    }

    /// a_C = a_A + ω̇ × ρ + ω × (ω × ρ), space axes, ρ = R ρ_C, where a_A is the axis point's acceleration in a
    /// vehicle ([`crate::motion::carrier::vehicle`]) and is absent otherwise (A fixed in space).
    fn accel_c_at(&self, rotation: &AxisRotation, theta_ddot: f64) -> Vector3<f64> {
        let rho_s = *self.rho_c_b.in_space(&rotation.q);
        let omega_s = *rotation.omega_s;
        let relative =
            rotation.alpha_s(theta_ddot).cross(&rho_s) + omega_s.cross(&omega_s.cross(&rho_s));
        match rotation.accel_a_s() {
            None => relative,
            Some(a_a_s) => *a_a_s + relative,
        }
    }

    /// In a vehicle, the moment about A of the d'Alembert force at C, ρ × m a_A (space axes; `None` without a
    /// vehicle): the resultant moment about the accelerating point A is M = dH_A/dt + ρ × m a_A, with H_A = I_A ω
    /// the moment of momentum relative to A (Rigid-body dynamics, lecture notes: moments about a moving point).
    pub fn transport_moment_s(&self, rotation: &AxisRotation) -> Option<Vector<SpaceAxes>> {
        let a_a_s = rotation.accel_a_s()?;
        Some(Vector::new(
            self.rho_c_b
                .in_space(&rotation.q)
                .cross(&(*a_a_s * self.mass)),
        ))
    }

    /// M = dH_A/dt in a carrier, in the form `frame` selects, returned in (body, space) axes. Body form:
    /// M_b = I_A ω̇_b + ω_b × I_A ω_b; space form, with I_s = R I_A Rᵀ, which now depends on θ and t:
    /// M_s = İ_s ω_s + I_s ω̇_s with İ_s = ω̂_s I_s − I_s ω̂_s (Ṙ = ω̂_s R). In a vehicle A accelerates and both
    /// add ρ × m a_A ([`Self::transport_moment_s`]; body form: ρ_b × m Rᵀ a_A), so that M stays the resultant
    /// moment about A.
    fn moment_in_carrier(
        &self,
        rotation: &AxisRotation,
        theta_ddot: f64,
        form: Form,
    ) -> (Vector3<f64>, Vector3<f64>) {
        let q = rotation.q;
        let alpha_s = rotation.alpha_s(theta_ddot);
        match form {
            Form::Body => {
                let (omega_b, alpha_b) = (*rotation.omega_b, q.inverse_transform_vector(&alpha_s));
                let m_b = self.inertia_a_b * alpha_b + omega_b.cross(&(self.inertia_a_b * omega_b));
                let m_b = match rotation.accel_a_s() {
                    None => m_b,
                    Some(a_a_s) => {
                        let a_a_b = q.inverse_transform_vector(&a_a_s);
                        m_b + self.rho_c_b.cross(&(a_a_b * self.mass))
                    }
                };
                (m_b, q * m_b)
            }
            Form::Space => {
                let r = q.to_rotation_matrix().into_inner();
                let i_s = r * self.inertia_a_b * r.transpose();
                let w_hat = rotation.omega_s.cross_matrix();
                let i_s_dot = w_hat * i_s - i_s * w_hat;
                let m_s = i_s_dot * *rotation.omega_s + i_s * *alpha_s;
                let m_s = match self.transport_moment_s(rotation) {
                    None => m_s,
                    Some(transport_s) => m_s + *transport_s,
                };
                (q.inverse_transform_vector(&m_s), m_s)
            }
        }
    }
}

impl FixedAxis {
    /// The moment about A the prescribed motion requires at time t, space axes, computed in the form `frame`
    /// selects: R(θ)·(I_A α + ω × I_A ω) (body form) or d/dt[I_s ω_s] (space form, eq. 8.10), in a carrier with
    /// ω = Ω_c + θ̇ u.
    pub fn required_moment_a_s(&self, t: f64, form: Form) -> Vector<SpaceAxes> {
        let angle = self.angle(t);
        Vector::new(match (self.moving_support(), form) {
            (None, Form::Space) => self.moment_a_c(&angle).into_inner(),
            (None, Form::Body) => self.attitude(angle.theta) * *self.moment_a_b(&angle),
            (Some(_), _) => {
                let rotation = self.rotation(t, angle.theta, angle.theta_dot);
                self.moment_in_carrier(&rotation, angle.theta_ddot, form).1
            }
        })
    }

    /// The full kinetic state at time t, with the required moment computed in the form `frame` selects (the other
    /// frame's components by rotation): body form [`FixedAxis::moment_a_b`], space form [`FixedAxis::moment_a_c`] (in
    /// a carrier, their generalisations with ω = Ω_c + θ̇ u). Energy is ½ ω·H_A, the body's whole kinetic energy
    /// since A is fixed (in a vehicle, where A accelerates, the kinetic energy of the motion relative to A).
    pub fn sample(&self, t: f64, form: Form) -> Sample {
        let angle = self.angle(t);
        let rotation = self.rotation(t, angle.theta, angle.theta_dot);
        let weight_moment_s = (self.rho_c_b.in_space(&rotation.q)).cross(&(*self.g_s * self.mass));
        self.sample_at(t, &angle, &rotation, form, &weight_moment_s)
    }

    /// The kinetic state and the support's loads at time t and the angle `angle` (see [`Self::sample`] and
    /// [`crate::motion::support`]), where the effects apply the moment `m_eff_s` about A (space axes) and
    /// gravity its weight at C; `rotation` is [`Self::rotation`] at t, θ and θ̇, which the caller has computed.
    pub fn sample_at(
        &self,
        t: f64,
        angle: &AxisAngle,
        rotation: &AxisRotation,
        form: Form,
        m_eff_s: &Vector3<f64>,
    ) -> Sample {
        let (angle, q) = (*angle, rotation.q);
        let omega_b = *rotation.omega_b;
        let h_b = self.inertia_a_b * omega_b;
        let (m_b, m_s) = match (rotation.support, form) {
            (Some(_), _) => self.moment_in_carrier(rotation, angle.theta_ddot, form),
            (None, Form::Body) => {
                let m_b = self.moment_a_b(&angle).into_inner();
                (m_b, q * m_b)
            }
            (None, Form::Space) => {
                let m_s = self.moment_a_c(&angle).into_inner();
                (q.inverse() * m_s, m_s)
            }
        };
        Sample {
            t,
            q,
            omega_b: Vector::new(omega_b),
            omega_s: rotation.omega_s,
            h_o_b: Vector::new(h_b),
            h_o_s: Vector::new(q * h_b),
            m_o_b: Vector::new(m_b),
            m_o_s: Vector::new(m_s),
            energy: kinetic_energy(&omega_b, &h_b),
            theta: Some(angle.theta),
            f_s: (self.center_off_axis())
                .then(|| Vector::new(self.accel_c_at(rotation, angle.theta_ddot) * self.mass)),
            h_o_s_integrated: None,
            support: Some(self.support(&angle, rotation, &m_s, m_eff_s)),
            potential: None,
            capability_values: None,
        }
    }
}

impl FixedAxis {
    /// What the support supplies when the resultant moment about A is `m_s` and the effects' is `m_eff_s` (space
    /// axes): F_sup = m a_C − m g (a_C including a vehicle's a_A), M_sup = m_s − m_eff_s (both about A), the drive's M_sup·u and, with bearings, their split (see
    /// [`crate::motion::support`]; u and the bearings turn with the carrier).
    fn support(
        &self,
        angle: &AxisAngle,
        rotation: &AxisRotation,
        m_s: &Vector3<f64>,
        m_eff_s: &Vector3<f64>,
    ) -> SupportLoads {
        let q = rotation.q;
        let f_sup_s =
            self.accel_c_at(rotation, angle.theta_ddot) * self.mass - *self.g_s * self.mass;
        let m_sup_s = m_s - m_eff_s;
        let u_s = rotation.u_s;
        SupportLoads {
            theta_dot: angle.theta_dot,
            theta_ddot: angle.theta_ddot,
            f_sup_s: Vector::new(f_sup_s),
            m_sup_s: Vector::new(m_sup_s),
            m_drive: m_sup_s.dot(&*u_s),
            bearings: self.bearings.map(|bearings| {
                let (r_a_s, r_b_s) = bearings.split(&f_sup_s, &m_sup_s, &u_s);
                BearingLoads {
                    r_a_s: Vector::new(r_a_s),
                    r_b_s: Vector::new(r_b_s),
                    r_a_b: Vector::new(q.inverse_transform_vector(&r_a_s)),
                    r_b_b: Vector::new(q.inverse_transform_vector(&r_b_s)),
                }
            }),
            omega_c_s: rotation.support.map(|c| c.omega_c_s),
        }
    }
}
