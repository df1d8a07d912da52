//! Euler's equation for a body whose mass moves, M = d/dt(I·ω) in full, about the system's instantaneous centre
//! of mass C(t) ([`super::history`]): H = I(t) ω + h(t), with h the moment of momentum of the motion relative to
//! the body. Its rate seen in the body is
//!
//! ```text
//!   (dH/dt)_b + ω × H = M,   i.e.   I ω̇ = M − İ ω − ḣ − ω × (I ω + h)
//! ```
//!
//! (Schaub & Junkins, *Analytical Mechanics of Space Systems*, 4th ed., §4.2–4.3; Hughes, *Spacecraft Attitude
//! Dynamics*, §3.3; for C fixed and h = 0 it is eq. 8.9 of the lecture notes with I depending on t). Both forms
//! integrate the moment of momentum and take ω from it, ω = I(t)⁻¹ (H_b − h), so that a mass that starts or stops
//! at once (a `linear` profile, a table's row) changes ω by a jump, H staying continuous, instead of asking for
//! the impulse r̈ that the expanded form would need:
//!
//! - body form, state (H_b, q): Ḣ_b = M_b − ω × H_b;
//! - space form, state (H_s, q): Ḣ_s = M_s, H_b = Rᵀ H_s;
//!
//! and q̇ = ½ q ⊗ (0, ω_b) in both. The kinetic energy about C is T = ½ ωᵀ I ω + ω·h + T_rel; it is not conserved:
//! the internal drives put in P_internal = dT/dt − M·ω = −½ ωᵀ İ ω + ω̇·h + Ṫ_rel (from the equation above).

use std::cell::Cell;

use nalgebra::{Matrix3, Quaternion, UnitQuaternion, Vector3};

use super::ShapeChange;
use super::history::MassState;
use super::path::Side;
use crate::effects::AppliedMoment;
use crate::frames::{BodyAxes, Form, StateRotation, Vector};
use crate::integrate::OdeSystem;
use crate::motion::free::{self, State};
use crate::sample::Sample;

/// ω_b = I⁻¹ (H_b − h) by the Cholesky factor of I (NaN when I is not positive definite, which stops the run).
pub(super) fn omega_b(s: &MassState, h_total_b: &Vector3<f64>) -> Vector3<f64> {
    match s.inertia_b.cholesky() {
        Some(c) => c.solve(&(h_total_b - s.h_b)),
        None => Vector3::repeat(f64::NAN),
    }
}

/// T = ½ ωᵀ I ω + ω·h + T_rel (J).
pub(super) fn kinetic_energy(s: &MassState, omega_b: &Vector3<f64>) -> f64 {
    0.5 * omega_b.dot(&(s.inertia_b * omega_b)) + omega_b.dot(&s.h_b) + s.energy_rel
}

/// P_internal = −½ ωᵀ İ ω + ω̇·h + Ṫ_rel with I ω̇ = M − İ ω − ḣ − ω × H (W).
pub(super) fn internal_power(
    s: &MassState,
    omega_b: &Vector3<f64>,
    h_total_b: &Vector3<f64>,
    m_b: &Vector3<f64>,
) -> f64 {
    let rhs = m_b - s.inertia_dot_b * omega_b - s.h_dot_b - omega_b.cross(h_total_b);
    let omega_dot_b = (s.inertia_b.cholesky()).map_or(Vector3::repeat(f64::NAN), |c| c.solve(&rhs));
    -0.5 * omega_b.dot(&(s.inertia_dot_b * omega_b)) + omega_dot_b.dot(&s.h_b) + s.energy_rel_dot
}

/// The body's moment of momentum in the state's form: H_b (body form) or H_s (space form).
fn h_total_b(form: Form, first: &Vector3<f64>, rotation: &StateRotation) -> Vector3<f64> {
    match form {
        Form::Body => *first,
        Form::Space => rotation.to_body(first),
    }
}

/// The module's equations as a system of 7 states, (H_b or H_s, q), with the applied moment `M`.
#[derive(Debug)]
pub struct ChangingForm<'a, M: AppliedMoment> {
    /// The body's mass distribution in time.
    pub shape: &'a ShapeChange,
    /// The applied moment M(t, q, ω).
    pub moment: M,
    /// Which form: body (H_b) or space (H_s).
    pub form: Form,
    /// The start of the step being taken (from [`OdeSystem::next_breakpoint`]): at a corner, a stage at a later
    /// time is the step's end and takes the rates from before it.
    step_start: Cell<f64>,
}

impl<'a, M: AppliedMoment> ChangingForm<'a, M> {
    /// The system of `shape` in `form` under `moment`.
    pub fn new(shape: &'a ShapeChange, moment: M, form: Form) -> Self {
        Self {
            shape,
            moment,
            form,
            step_start: Cell::new(f64::NEG_INFINITY),
        }
    }
}

impl<M: AppliedMoment> OdeSystem<7> for ChangingForm<'_, M> {
    fn rhs(&mut self, t: f64, y: &State) -> State {
        let side = match t > self.step_start.get() {
            true => Side::Before,
            false => Side::After,
        };
        let s = self.shape.at(t, side);
        let q_state = Quaternion::new(y[3], y[4], y[5], y[6]);
        let rotation = StateRotation::of(&q_state);
        let first = Vector3::new(y[0], y[1], y[2]);
        let h_b = h_total_b(self.form, &first, &rotation);
        let omega_b = omega_b(&s, &h_b);
        let m_b = match M::ZERO {
            true => Vector3::zeros(),
            false => (self.moment).moment_b_at_state(t, &q_state, || rotation, &omega_b),
        };
        let first_dot = match self.form {
            Form::Body => m_b - omega_b.cross(&h_b),
            Form::Space => rotation.to_space(&m_b),
        };
        free::with_attitude_rate(first_dot, y, &omega_b)
    }

    fn project(&self, y: &mut State) {
        free::normalise_quaternion(y);
    }

    fn next_breakpoint(&self, t: f64) -> Option<f64> {
        self.step_start.set(t);
        match (self.shape.corner_after(t), self.moment.corner_after(t)) {
            (Some(a), Some(b)) => Some(a.min(b)),
            (a, b) => a.or(b),
        }
    }
}

/// The initial state of `form` from ω_b(0) and q(0): H_b = I(0) ω₀ + h(0), or H_s = R H_b.
pub fn initial_state(
    shape: &ShapeChange,
    form: Form,
    omega0_b: &Vector<BodyAxes>,
    q0: &UnitQuaternion<f64>,
) -> State {
    let s = shape.at(0.0, Side::After);
    let h_b = s.inertia_b * **omega0_b + s.h_b;
    let first = match form {
        Form::Body => h_b,
        Form::Space => q0 * h_b,
    };
    State::from([first[0], first[1], first[2], q0.w, q0.i, q0.j, q0.k])
}

/// The row of a state of `form` at t: ω from H, H about C(t) in both axes, M, and the energy T of the module's
/// equations (the rates after a corner at t).
pub fn sample<M: AppliedMoment>(
    shape: &ShapeChange,
    moment: &M,
    form: Form,
    t: f64,
    y: &State,
) -> Sample {
    let s = shape.at(t, Side::After);
    let q = free::attitude(y);
    let q_state = Quaternion::new(y[3], y[4], y[5], y[6]);
    let h_b = h_total_b(
        form,
        &Vector3::new(y[0], y[1], y[2]),
        &StateRotation::of(&q_state),
    );
    let omega_b = omega_b(&s, &h_b);
    let m_b = moment.moment_b(t, &q, &omega_b);
    let h_b = Vector::new(h_b);
    let h_s = match form {
        Form::Body => h_b.in_space(&q),
        Form::Space => Vector::new(Vector3::new(y[0], y[1], y[2])),
    };
    let row = free::free_sample(t, q, Vector::new(omega_b), (h_b, h_s), Vector::new(m_b));
    Sample {
        energy: kinetic_energy(&s, &omega_b),
        ..row
    }
}

/// I about C(t) as the six entries of the columns: I_xx, I_yy, I_zz, I_xy, I_xz, I_yz (tensor entries).
pub(super) fn six_entries(i: &Matrix3<f64>) -> [f64; 6] {
    [
        i[(0, 0)],
        i[(1, 1)],
        i[(2, 2)],
        i[(0, 1)],
        i[(0, 2)],
        i[(1, 2)],
    ]
}
