//! `split2` and `split4` for a body that changes shape: the Strang step of [`crate::motion::lie_poisson`] with the
//! inertia and the relative moment of momentum frozen at the middle of each stage, and Suzuki's composition of it.
//!
//! ```text
//!   E(H, t) = ½ (H − h)ᵀ I⁻¹ (H − h) = ½ Hᵀ I⁻¹ H − a·H + const,   a = I⁻¹ h        (I, h at t_m = t_s + τ/2)
//!   L(τ): the linear part's exact flow, ω = −a: q_b ← q_b ⊗ exp(−a τ), H_b ← exp(a τ) H_b (H_s stays)
//!   D(τ) = L(τ/2) R(τ) L(τ/2),  R the rigid drift of I(t_m) (McLachlan 1993's splitting, as for a rigid body)
//!   S(τ) = K(τ/2) at t_s, D(τ), K(τ/2) at t_s + τ;   K: H ← H + M_rest(t, q) τ
//! ```
//!
//! Freezing a time-dependent Hamiltonian at the middle of the stage keeps the Strang step symmetric in (t, y), so
//! it is of order 2 and Suzuki's composition of order 4 (Blanes & Casas, *A Concise Introduction to Geometric
//! Numerical Integration*, 2016, §3.3: non-autonomous problems by the midpoint freezing). H_s is conserved by every
//! sub-flow but the kick. A corner of the shape change (a `linear` start, a table's row) inside a step lowers the
//! order there, as for `rk4`.

use nalgebra::{UnitQuaternion, Vector3};

use super::ShapeChange;
use super::path::Side;
use crate::body::RigidBody;
use crate::frames::{Form, Vector};
use crate::integrate::FixedStep;
use crate::motion::free::{self, FreeBody, State};
use crate::motion::lie_poisson::{KickMoment, Scheme, drift_body_state};

/// The splitting of a body that changes shape, on the state of [`super::system`]: (H_b or H_s, q).
#[derive(Debug, Clone)]
pub struct ChangingSplit<'a, K: KickMoment> {
    shape: &'a ShapeChange,
    kick: K,
    form: Form,
    weights: Vec<f64>,
    /// The system's mass (kg): the frozen rigid body's (it does not enter the drift).
    mass: f64,
}

impl<'a, K: KickMoment> ChangingSplit<'a, K> {
    /// The splitting of `shape` (a system of mass `mass`, kg) in `form`, composed by `scheme`, with the applied
    /// moment `kick` (without damping: validation refuses it here).
    pub fn new(shape: &'a ShapeChange, mass: f64, form: Form, scheme: Scheme, kick: K) -> Self {
        Self {
            shape,
            kick,
            form,
            weights: scheme.weights(),
            mass,
        }
    }

    /// K(τ) at t: H ← H + M_rest(t, q) τ, in the form's axes.
    fn kick(&self, t: f64, tau: f64, h: &mut Vector3<f64>, q_b: &UnitQuaternion<f64>) {
        let m_b = self.kick.rest_moment_b(t, q_b);
        *h += match self.form {
            Form::Body => m_b * tau,
            Form::Space => q_b * m_b * tau,
        };
    }

    /// D(τ) with I and h frozen at t_m; `None` when I(t_m) is not a body's (a run then stops as non-finite).
    fn drift(
        &self,
        t_m: f64,
        tau: f64,
        h: &mut Vector3<f64>,
        q_b: &mut UnitQuaternion<f64>,
    ) -> Option<u64> {
        let s = self.shape.at(t_m, Side::After);
        let a_b = s.inertia_b.cholesky()?.solve(&s.h_b);
        let frozen = RigidBody::new(self.mass, s.inertia_b).ok()?;
        let body = FreeBody::new(&frozen, &Vector::zeros()).ok()?;
        let linear = |tau: f64, h: &mut Vector3<f64>, q_b: &mut UnitQuaternion<f64>| {
            let turn = UnitQuaternion::from_scaled_axis(a_b * tau);
            *q_b *= turn.inverse();
            if self.form == Form::Body {
                *h = turn * *h;
            }
        };
        linear(0.5 * tau, h, q_b);
        let evals = drift_body_state(&body, self.form, tau, h, q_b);
        linear(0.5 * tau, h, q_b);
        Some(evals + 2)
    }
}

impl<K: KickMoment> FixedStep for ChangingSplit<'_, K> {
    type State = State;

    /// One step of the composition: for each stage weight w (start t_s): K(wh/2) at t_s, D(wh) frozen at
    /// t_s + wh/2, K(wh/2) at t_s + wh (t_next for the last stage). Returns the sub-flows done.
    fn step(&mut self, t: f64, t_next: f64, h: f64, y: &mut State) -> u64 {
        let mut first = Vector3::new(y[0], y[1], y[2]);
        let mut q_b = free::attitude(y);
        let (mut evals, mut elapsed, mut t_s) = (0, 0.0, t);
        let stages = self.weights.len();
        for (n, &w) in self.weights.iter().enumerate() {
            let tau = w * h;
            self.kick(t_s, 0.5 * tau, &mut first, &q_b);
            match self.drift(t_s + 0.5 * tau, tau, &mut first, &mut q_b) {
                Some(done) => evals += done + 2,
                None => first = Vector3::repeat(f64::NAN),
            }
            elapsed += w;
            t_s = if n + 1 == stages {
                t_next
            } else {
                t + elapsed * h
            };
            self.kick(t_s, 0.5 * tau, &mut first, &q_b);
        }
        *y = State::from([first.x, first.y, first.z, q_b.w, q_b.i, q_b.j, q_b.k]);
        evals
    }

    fn is_finite(&self, y: &State) -> bool {
        y.iter().all(|v| v.is_finite())
    }
}
