//! A gyrostat: a body with rotors — wheels spinning inside it about axes a_k fixed in the body — turning freely
//! about its moment center (C, or a gravity pivot). The body's inertia I is the whole body with its wheels locked;
//! each wheel adds only its spin Ω_k relative to the body (Hughes, *Spacecraft Attitude Dynamics*, §3.5;
//! Wittenburg, *Dynamics of Multibody Systems*, §6.3):
//!
//! ```text
//!   H = I ω + Σ J_k Ω_k a_k                         (the wheel's J_k (a_k·ω) is already in I ω)
//!   I ω̇ + Σ J_k Ω̇_k a_k = M − ω × H                (body axes; in space axes Ḣ_s = M_s)
//!   J_k (a_k·ω̇ + Ω̇_k) = τ_k                         (each wheel about its axis; the body feels −τ_k)
//! ```
//!
//! A wheel's spin is prescribed (Ω̇_k = α_k, 0 for a constant spin; τ_k is then an output) or driven by its motor
//! torque τ_k(t). Eliminating the driven wheels' Ω̇_k gives ω̇ = I_D⁻¹ (M − ω × H − Σ_P J_k α_k a_k − Σ_D τ_k a_k),
//! I_D = I − Σ_D J_k a_k a_kᵀ. State: (ω_b or H_s, q, Ω_1 … Ω_4, φ_1 … φ_4), unused entries zero, with φ_k the
//! wheel's angle relative to the body (φ̇_k = Ω_k). Kinetic energy T = ½ ωᵀ I ω + Σ (J_k Ω_k (a_k·ω) + ½ J_k Ω_k²).
//!
//! A wheel's imbalance acts on the body as the moment of a force and a couple turning with the wheel (the "simple
//! jitter" model of Alcorn, Allard & Schaub, *Fully coupled reaction wheel static and dynamic imbalance for
//! spacecraft jitter modeling*, JGCD 41(6), 2018, and Basilisk's reaction-wheel effector):
//!
//! ```text
//!   d_k = cos φ_k w2_k + sin φ_k w3_k,    M_k = r_k × (U_s Ω_k² d_k) + U_d Ω_k² d_k,
//! ```
//!
//! U_s = m e the static and U_d the dynamic imbalance, r_k the wheel centre from the moment center; the force's
//! effect on the motion of C is not simulated (rotation only).

use nalgebra::{Matrix3, Quaternion, SVector, SymmetricEigen, Unit, UnitQuaternion, Vector3};

use std::sync::Arc;

use super::{MAX_ROTORS, RotorRows};
use super::{Wheel, WheelControl, WheelInputs, WheelSolve, WheelTorqueLaw};
use crate::effects::{AppliedMoment, TorqueSum, TorqueTable};
use crate::frames::{BodyAxes, Form, StateRotation, Vector};
use crate::integrate::OdeSystem;
use crate::motion::free::{self, FreeBody};
use crate::panel::Panel;
use crate::sample::Sample;

/// State of both forms: (ω_b or H_s, q_w, q_x, q_y, q_z, Ω_1, …, Ω_4, φ_1, …, φ_4).
pub type State = SVector<f64, 15>;

/// Where the wheel angles φ_k start in the state.
const ANGLES: usize = 7 + MAX_ROTORS;

/// What drives a rotor, validated.
#[derive(Debug, Clone, PartialEq)]
pub enum Drive {
    /// Ω̇ = α (rad/s²), prescribed (0: a constant relative spin).
    Accel(f64),
    /// The motor torque τ(t) on the wheel (N·m): the `x` component of the sum.
    Torque(TorqueSum),
    /// The motor torque commanded by a table (`torque_table`): its `x` component.
    Table(Arc<TorqueTable>),
    /// The motor torque commanded by the body's wheel law (this wheel's entry).
    Law,
    /// No motor (`mode = "free"`): friction only.
    Free,
}

impl Drive {
    /// Whether the wheel's spin follows its torques (not prescribed).
    pub fn is_driven(&self) -> bool {
        !matches!(self, Drive::Accel(_))
    }
}

/// One rotor, validated.
#[derive(Debug, Clone, PartialEq)]
pub struct Rotor {
    /// Its columns' prefix.
    pub name: String,
    /// Spin axis a, body axes.
    pub axis_b: Unit<Vector3<f64>>,
    /// J about the spin axis (kg·m²).
    pub inertia: f64,
    /// Ω at t = 0, relative to the body (rad/s).
    pub spin0: f64,
    /// What drives its relative spin.
    pub drive: Drive,
    /// Its imbalance, if any.
    pub imbalance: Option<Imbalance>,
    /// Its torque and speed limits and friction (`crate::wheels`).
    pub control: WheelControl,
}

impl Rotor {
    /// Whether its relative spin stays constant of itself where a·ω does: a balanced wheel without limits or
    /// friction, at a constant prescribed spin, or driven by no torque (J (a·ω̇ + Ω̇) = 0).
    pub fn spins_steadily(&self) -> bool {
        let constant = match &self.drive {
            Drive::Accel(alpha) => *alpha == 0.0,
            Drive::Torque(tau) => tau.is_zero(),
            Drive::Free => true,
            Drive::Table(_) | Drive::Law => false,
        };
        constant && self.imbalance.is_none() && self.control == WheelControl::default()
    }
}

/// A wheel's imbalance (module doc): U_s (kg·m), U_d (kg·m²), the wheel centre r from the moment center and the
/// directions w2 (where the imbalance points at φ = 0) and w3 = a × w2, body axes.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Imbalance {
    /// U_s (kg·m).
    pub static_kgm: f64,
    /// U_d (kg·m²).
    pub dynamic_kgm2: f64,
    /// r, the wheel centre from the moment center (m).
    pub r_b: Vector<BodyAxes>,
    /// w2.
    pub w2_b: Vector<BodyAxes>,
    /// w3 = a × w2.
    pub w3_b: Vector<BodyAxes>,
}

impl Imbalance {
    /// The imbalance `static_kgm` (kg·m) and `dynamic_kgm2` (kg·m²) of a wheel about `axis_b` centred at `r_b`
    /// from the moment center; w2 is the body axis least aligned with the spin axis (x, then y, then z on ties),
    /// made normal to it.
    ///
    /// ```
    /// use eulerdyn::frames::Vector;
    /// use eulerdyn::wheels::gyrostat::Imbalance;
    /// use nalgebra::{Unit, Vector3};
    /// let wheel = Imbalance::new(1e-6, 0.0, Vector::zeros(), &Unit::new_normalize(Vector3::z()));
    /// assert_eq!((*wheel.w2_b, *wheel.w3_b), (Vector3::x(), Vector3::y()));
    /// ```
    pub fn new(
        static_kgm: f64,
        dynamic_kgm2: f64,
        r_b: Vector<BodyAxes>,
        axis_b: &Unit<Vector3<f64>>,
    ) -> Self {
        let a = axis_b.into_inner();
        let least = (0..3)
            .min_by(|&i, &j| a[i].abs().total_cmp(&a[j].abs()))
            .unwrap_or(0);
        let e = Vector3::ith(least, 1.0);
        let w2_b = (e - a * a.dot(&e)).normalize();
        Self {
            static_kgm,
            dynamic_kgm2,
            r_b,
            w2_b: Vector::new(w2_b),
            w3_b: Vector::new(a.cross(&w2_b)),
        }
    }

    /// M = r × (U_s Ω² d) + U_d Ω² d, d = cos φ w2 + sin φ w3 (body axes) at the relative spin Ω and angle φ.
    pub fn moment_b(&self, spin: f64, phi: f64) -> Vector<BodyAxes> {
        let (sin, cos) = phi.sin_cos();
        let d = *self.w2_b * cos + *self.w3_b * sin;
        let spin2 = spin * spin;
        Vector::new(
            self.r_b.cross(&(d * (self.static_kgm * spin2))) + d * (self.dynamic_kgm2 * spin2),
        )
    }
}

/// The rotors cannot be inside this body: with the driven wheels free, I_D = I − Σ_D J_k a_k a_kᵀ must stay
/// positive definite (it is when `[body]` includes the wheels, whose own inertia about a_k is at least J_k).
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[error(
    "the body's inertia about the moment center without the wheels' axial inertia, I − Σ J_k a_k a_kᵀ, has the \
     principal moment {smallest:e} kg*m^2 <= 0: [body] is the whole body with its wheels locked, so its inertia \
     about each wheel axis must exceed the wheels' J"
)]
pub struct WheelsOutsideBody {
    /// The smallest principal moment left (kg·m²).
    pub smallest: f64,
}

/// A free body with its rotors.
#[derive(Debug, Clone, PartialEq)]
pub struct Gyrostat {
    body: FreeBody,
    rotors: Vec<Rotor>,
    /// Whether some wheel has an imbalance (else its moment is not evaluated).
    imbalanced: bool,
    /// I_D⁻¹, body axes.
    inertia_driven_inv_b: Matrix3<f64>,
    /// The law of the wheels driven by [`Drive::Law`].
    law: Option<WheelTorqueLaw>,
}

impl Gyrostat {
    /// The body with `rotors` (at most [`MAX_ROTORS`]); refuses a body whose inertia cannot hold its wheels.
    pub fn new(body: FreeBody, rotors: Vec<Rotor>) -> Result<Self, WheelsOutsideBody> {
        assert!(rotors.len() <= MAX_ROTORS, "validation bounds the rotors");
        let wheels = |driven_only: bool| {
            (rotors.iter())
                .filter(|r| !driven_only || r.drive.is_driven())
                .fold(*body.inertia_b(), |i, r| {
                    i - r.axis_b.into_inner() * r.axis_b.transpose() * r.inertia
                })
        };
        let smallest = SymmetricEigen::new(wheels(false)).eigenvalues.min();
        let largest = body.principal_moments().max();
        if smallest <= 1e-12 * largest {
            return Err(WheelsOutsideBody { smallest });
        }
        let inertia_driven_inv_b = wheels(true)
            .try_inverse()
            .ok_or(WheelsOutsideBody { smallest })?;
        Ok(Self {
            body,
            imbalanced: rotors.iter().any(|r| r.imbalance.is_some()),
            rotors,
            inertia_driven_inv_b,
            law: None,
        })
    }

    /// The gyrostat with the wheel law `law` driving every wheel (each drive becomes [`Drive::Law`]).
    ///
    /// ```
    /// use eulerdyn::Form;
    /// use eulerdyn::body::RigidBody;
    /// use eulerdyn::effects::TorqueFree;
    /// use eulerdyn::frames::Vector;
    /// use eulerdyn::integrate::OdeSystem;
    /// use eulerdyn::motion::free::FreeBody;
    /// use eulerdyn::wheels::gyrostat::{Drive, Gyrostat, GyrostatForm, Rotor};
    /// use eulerdyn::wheels::{WheelControl, WheelTorqueLaw};
    /// use nalgebra::{UnitQuaternion, Vector3};
    /// let body = FreeBody::new(&RigidBody::from_principal(1.0, [1.0, 2.0, 3.0])?, &Vector::zeros())?;
    /// let wheel = Rotor {
    ///     name: "w".into(),
    ///     axis_b: Vector3::z_axis(),
    ///     inertia: 0.1,
    ///     spin0: 0.0,
    ///     drive: Drive::Accel(0.0),
    ///     imbalance: None,
    ///     control: WheelControl::default(),
    /// };
    /// let law = |_: f64, _: &UnitQuaternion<f64>, _: &Vector3<f64>, _: &[f64]| vec![0.1];
    /// let g = Gyrostat::new(body, vec![wheel])?.with_law(WheelTorqueLaw::new("spin-up", law))?;
    /// assert_eq!((g.law().unwrap().name.as_str(), &g.rotors()[0].drive), ("spin-up", &Drive::Law));
    /// // At rest the wheel's 0.1 N·m turns the body back through I_z − J = 2.9 kg·m²: ω̇_z = −0.1/2.9.
    /// let y = g.initial_state(Form::Body, &Vector::zeros(), &UnitQuaternion::identity());
    /// let dy = GyrostatForm { gyrostat: &g, moment: TorqueFree, form: Form::Body }.rhs(0.0, &y);
    /// assert!((dy[2] + 0.1 / 2.9).abs() < 1e-15);
    /// # Ok::<(), Box<dyn std::error::Error>>(())
    /// ```
    pub fn with_law(self, law: WheelTorqueLaw) -> Result<Self, WheelsOutsideBody> {
        let mut rotors = self.rotors;
        for r in &mut rotors {
            r.drive = Drive::Law;
        }
        let mut g = Self::new(self.body, rotors)?;
        g.law = Some(law);
        Ok(g)
    }

    /// The wheel law, if any.
    pub fn law(&self) -> Option<&WheelTorqueLaw> {
        self.law.as_ref()
    }

    /// Whether the run writes each wheel's command and friction: some wheel has a law, a table, no motor, a
    /// limit or friction.
    pub fn controlled(&self) -> bool {
        (self.rotors.iter()).any(|r| {
            matches!(r.drive, Drive::Table(_) | Drive::Law | Drive::Free)
                || r.control != WheelControl::default()
        })
    }

    /// The body about its moment center.
    pub fn body(&self) -> &FreeBody {
        &self.body
    }

    /// The rotors.
    pub fn rotors(&self) -> &[Rotor] {
        &self.rotors
    }

    /// Whether no motor does work: every wheel is driven by a zero torque (spinning freely). Only then is the
    /// kinetic energy conserved where no effect acts; a prescribed or constant relative spin takes motor work.
    pub fn wheels_spin_freely(&self) -> bool {
        (self.rotors.iter()).all(|r| {
            let motorless = match &r.drive {
                Drive::Torque(tau) => tau.is_zero(),
                Drive::Free => true,
                _ => false,
            };
            motorless && !r.control.friction.is_some()
        })
    }

    /// The plot panels of its runs: spin, momentum and torque, and friction when the wheels are under control
    /// ([`Panel::wheel_panels`]).
    pub fn panels(&self) -> Vec<Panel> {
        Panel::wheel_panels(true, self.controlled())
    }

    /// Whether some wheel has friction (which dissipates kinetic energy and keeps H).
    pub fn has_friction(&self) -> bool {
        (self.rotors.iter()).any(|r| r.control.friction.is_some())
    }

    /// Whether some wheel has an imbalance, whose moment changes H and T.
    pub fn imbalanced(&self) -> bool {
        self.imbalanced
    }

    /// The external moment `m_b` plus the wheels' imbalance moments at the state `y` (module doc).
    fn with_imbalance(&self, m_b: Vector3<f64>, y: &State) -> Vector3<f64> {
        if !self.imbalanced {
            return m_b;
        }
        (self.rotors.iter().enumerate()).fold(m_b, |m, (k, r)| match &r.imbalance {
            Some(imbalance) => m + *imbalance.moment_b(y[7 + k], y[ANGLES + k]),
            None => m,
        })
    }

    /// Σ J_k Ω_k(0) a_k, body axes: the rotors' share of H at t = 0.
    pub fn initial_rotor_momentum_b(&self) -> Vector<BodyAxes> {
        let spins: Vec<f64> = self.rotors.iter().map(|r| r.spin0).collect();
        Vector::new(self.rotor_momentum_b(&spins))
    }

    /// The kinetic energy at ω_b with the wheels' relative spins `spins`: T = ½ ωᵀ I ω + Σ (J_k Ω_k (a_k·ω) +
    /// ½ J_k Ω_k²).
    pub fn kinetic_energy(&self, omega_b: &Vector<BodyAxes>, spins: &[f64]) -> f64 {
        (self.rotors.iter().zip(spins)).fold(
            0.5 * omega_b.dot(&(self.body.inertia_b() * **omega_b)),
            |t, (r, &spin)| t + r.inertia * spin * (r.axis_b.dot(omega_b) + 0.5 * spin),
        )
    }

    /// Σ J_k Ω_k a_k, body axes.
    fn rotor_momentum_b(&self, spins: &[f64]) -> Vector3<f64> {
        (self.rotors.iter().zip(spins)).fold(Vector3::zeros(), |h, (r, &spin)| {
            h + r.axis_b.into_inner() * (r.inertia * spin)
        })
    }

    /// ω̇_b, each Ω̇_k and the wheels' commanded, motor and friction torques at ω_b, H_b, the external moment M_b,
    /// the attitude q (unnormalised) and the spins, time t (module doc; `crate::wheels` for the limits).
    fn rates(
        &self,
        t: f64,
        q: &Quaternion<f64>,
        omega_b: &Vector3<f64>,
        h_b: &Vector3<f64>,
        m_b: &Vector3<f64>,
        spins: &[f64],
    ) -> (WheelSolve, [f64; MAX_ROTORS]) {
        let law = (self.law.as_ref()).map(|law| {
            let q = UnitQuaternion::new_normalize(*q);
            let spins = &spins[..self.rotors.len()];
            law.commands(&WheelInputs {
                t,
                q: &q,
                omega_b,
                spins,
            })
        });
        let mut commands = [0.0; MAX_ROTORS];
        let mut wheels = [Wheel::default(); MAX_ROTORS];
        for (k, r) in self.rotors.iter().enumerate() {
            commands[k] = match &r.drive {
                Drive::Accel(_) | Drive::Free => 0.0,
                Drive::Torque(tau) => tau.at(t).x,
                Drive::Table(table) => table.at(t).x,
                Drive::Law => law.as_ref().map_or(f64::NAN, |c| c[k]),
            };
            wheels[k] = Wheel {
                axis_b: r.axis_b.into_inner(),
                inertia: r.inertia,
                spin: spins[k],
                accel: match r.drive {
                    Drive::Accel(alpha) => Some(alpha),
                    _ => None,
                },
                motor: r.control.clip(commands[k]),
                control: r.control,
            };
        }
        let rhs0_b = m_b - omega_b.cross(h_b);
        let solved = super::solve(
            self.body.inertia_b(),
            &self.inertia_driven_inv_b,
            &rhs0_b,
            &wheels[..self.rotors.len()],
        );
        (solved, commands)
    }

    /// The initial state of the form `form` from ω_b(0), q(0) and the rotors' initial spins.
    pub fn initial_state(
        &self,
        form: Form,
        omega0_b: &Vector<BodyAxes>,
        q0: &UnitQuaternion<f64>,
    ) -> State {
        let first = form.first_states(omega0_b, || {
            q0 * (self.body.inertia_b() * **omega0_b + *self.initial_rotor_momentum_b())
        });
        let mut y = State::zeros();
        y.fixed_rows_mut::<3>(0).copy_from(&first);
        y.fixed_rows_mut::<4>(3)
            .copy_from(&nalgebra::Vector4::new(q0.w, q0.i, q0.j, q0.k));
        for (k, r) in self.rotors.iter().enumerate() {
            y[7 + k] = r.spin0;
        }
        y
    }

    /// ω_b and H_b held in a state of the form `form`, with `to_body` turning a space vector into body axes.
    fn omega_and_momentum(
        &self,
        form: Form,
        y: &State,
        to_body: impl Fn(&Vector3<f64>) -> Vector3<f64>,
    ) -> (Vector3<f64>, Vector3<f64>) {
        let first = Vector3::new(y[0], y[1], y[2]);
        let h_rotors_b = self.rotor_momentum_b(&y.as_slice()[7..ANGLES]);
        match form {
            Form::Body => (first, self.body.inertia_b() * first + h_rotors_b),
            Form::Space => {
                let h_b = to_body(&first);
                (*self.body.omega_b_of(&Vector::new(h_b - h_rotors_b)), h_b)
            }
        }
    }

    /// Sets to exactly 0 the relative spin of each wheel with Coulomb or Stribeck friction that has come to rest
    /// (0 < |Ω_k| ≤ [`super::STICK_SPEED`], not prescribed), keeping H = I ω + Σ J Ω a: in the body form ω_b
    /// gains I⁻¹ J_k Ω_k a_k, in the space form H_s is the state and stays. A wheel that slips on (its holding
    /// torque beyond breakaway) leaves the band at once, from 0 instead of from within 1e-8 rad/s of it.
    fn stop_stuck_wheels(&self, form: Form, y: &mut State) {
        for (k, r) in self.rotors.iter().enumerate() {
            let spin = y[7 + k];
            let stuck = spin != 0.0 && spin.abs() <= super::STICK_SPEED;
            if !stuck || matches!(r.drive, Drive::Accel(_)) || r.control.friction.breakaway() == 0.0
            {
                continue;
            }
            if form == Form::Body {
                let h_b = Vector::<BodyAxes>::new(r.axis_b.into_inner() * (r.inertia * spin));
                let d_omega_b = self.body.omega_b_of(&h_b);
                for i in 0..3 {
                    y[i] += d_omega_b[i];
                }
            }
            y[7 + k] = 0.0;
        }
    }

    /// The row of a state of the form `form` at time t under the external moment `moment`.
    pub fn sample<M: AppliedMoment>(&self, moment: &M, form: Form, t: f64, y: &State) -> Sample {
        let q = UnitQuaternion::new_normalize(Quaternion::new(y[3], y[4], y[5], y[6]));
        let (omega_b, h_b) = self.omega_and_momentum(form, y, |v| q.inverse_transform_vector(v));
        let m_b = self.with_imbalance(moment.moment_b(t, &q, &omega_b), y);
        let spins = &y.as_slice()[7..ANGLES];
        let (solved, commands) = self.rates(t, q.quaternion(), &omega_b, &h_b, &m_b, spins);
        let mut rows = RotorRows {
            n: self.rotors.len(),
            ..RotorRows::default()
        };
        for (k, r) in self.rotors.iter().enumerate() {
            let spin = y[7 + k];
            rows.spin[k] = spin;
            rows.h[k] = r.inertia * (r.axis_b.dot(&omega_b) + spin);
            rows.torque[k] = solved.motor[k];
            rows.torque_cmd[k] = match r.drive {
                Drive::Accel(_) => solved.motor[k],
                _ => commands[k],
            };
            rows.friction[k] = solved.friction[k];
        }
        let h_b = Vector::<BodyAxes>::new(h_b);
        let omega_b = Vector::new(omega_b);
        let mut sample =
            free::free_sample(t, q, omega_b, (h_b, h_b.in_space(&q)), Vector::new(m_b));
        sample.energy = self.kinetic_energy(&omega_b, &y.as_slice()[7..ANGLES]);
        sample.capability_values = Some(rows.values());
        sample
    }
}

/// The state's rates: (ω̇_b or Ḣ_s, q̇, Ω̇_k, φ̇_k = Ω_k).
#[inline(always)]
fn state_rate(first: Vector3<f64>, y: &State, omega_b: &Vector3<f64>, spin_dot: &[f64]) -> State {
    let dq = free::quaternion_rate(&[y[3], y[4], y[5], y[6]], omega_b);
    let mut dy = State::zeros();
    dy.fixed_rows_mut::<3>(0).copy_from(&first);
    dy.fixed_rows_mut::<4>(3)
        .copy_from(&nalgebra::Vector4::from(dq));
    let n = spin_dot.len();
    dy.as_mut_slice()[7..7 + n].copy_from_slice(spin_dot);
    dy.as_mut_slice()[ANGLES..ANGLES + n].copy_from_slice(&y.as_slice()[7..7 + n]);
    dy
}

/// Renormalises the quaternion part of a state.
fn normalise_quaternion(y: &mut State) {
    let n = (y[3] * y[3] + y[4] * y[4] + y[5] * y[5] + y[6] * y[6]).sqrt();
    for k in 3..7 {
        y[k] /= n;
    }
}

/// Euler's equation of the gyrostat in the form `form` (module doc) under the external moment `moment`.
#[derive(Debug, Clone)]
pub struct GyrostatForm<'a, M: AppliedMoment> {
    /// The body with its wheels.
    pub gyrostat: &'a Gyrostat,
    /// The external moment.
    pub moment: M,
    /// The form integrated.
    pub form: Form,
}

impl<M: AppliedMoment> OdeSystem<15> for GyrostatForm<'_, M> {
    fn rhs(&mut self, t: f64, y: &State) -> State {
        let q_state = Quaternion::new(y[3], y[4], y[5], y[6]);
        let rotation = StateRotation::of(&q_state);
        let g = self.gyrostat;
        let (omega_b, h_b) = g.omega_and_momentum(self.form, y, |v| rotation.to_body(v));
        let m_b = g.with_imbalance(
            (self.moment).moment_b_at_state(t, &q_state, || rotation, &omega_b),
            y,
        );
        let (solved, _) = g.rates(t, &q_state, &omega_b, &h_b, &m_b, &y.as_slice()[7..ANGLES]);
        let (omega_dot_b, spin_dot) = (solved.omega_dot_b, solved.spin_dot);
        let first = match self.form {
            Form::Body => omega_dot_b,
            Form::Space => rotation.to_space(&m_b),
        };
        state_rate(first, y, &omega_b, &spin_dot[..g.rotors.len()])
    }

    fn project(&self, y: &mut State) {
        normalise_quaternion(y);
        self.gyrostat.stop_stuck_wheels(self.form, y);
    }

    /// The moment's next corner, or a wheel's torque table's next row.
    fn next_breakpoint(&self, t: f64) -> Option<f64> {
        let tables = (self.gyrostat.rotors.iter()).filter_map(|r| match &r.drive {
            Drive::Table(table) => table.corner_after(t),
            _ => None,
        });
        self.moment
            .corner_after(t)
            .into_iter()
            .chain(tables)
            .reduce(f64::min)
    }
}
