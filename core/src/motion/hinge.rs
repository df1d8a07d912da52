//! The driven hinge: rotation about an axis fixed in the body and in space whose angle is not prescribed but
//! follows from the effects' moment about the axis (eqs. 8.9 and 8.10 projected on the axis u):
//!
//! ```text
//!   d/dt (I_uu θ̇) = M_eff · u,          I_uu = u · I_A u (constant),
//! ```
//!
//! integrated in body axes as θ̈ = u_b·M_eff,b / I_uu (state θ, θ̇) and in space axes as the axial part of
//! d/dt(I_s(θ) ω_s) = M_s, i.e. L̇ = u_s·M_eff,s with L = u_s·H_s = I_uu θ̇ (state θ, L). The bearings supply the
//! part of dH/dt − M_eff across the axis, the drive nothing (see [`crate::motion::support`]).
//!
//! In a turning carrier (ω = Ω_c + θ̇ u, [`crate::motion::carrier`]) the drive still supplies nothing about u:
//! u·(dH/dt − M_eff) = 0 gives θ̈ with the carrier's inertial terms, and in space axes L = u·H_s obeys
//! L̇ = (Ω_c × u)·H_s + u·M_eff,s since u turns with the carrier.
//!
//! In a vehicle the axis point A accelerates at a_A ([`crate::motion::carrier::vehicle`]) and the moment about A
//! is dH_A/dt + ρ × m a_A: the d'Alembert force −m a_A at C acts like more weight, so θ̈ and L̇ gain
//! −u·(ρ × m a_A) (a pendulum in a vehicle accelerating at a hangs along g − a).

use nalgebra::{SVector, Vector3};

use crate::effects::{AppliedMoment, EffectMoments};
use crate::frames::{Form, Vector};
use crate::integrate::OdeSystem;
use crate::motion::fixed_axis::{AxisAngle, AxisRotation, FixedAxis};
use crate::sample::Sample;

/// State of a hinge: (θ, θ̇) in the body form, (θ, L = u·H_s) in the space form (L = I_uu θ̇ without a carrier).
pub type HingeState = SVector<f64, 2>;

/// A body on a hinge: the axis geometry (with gravity and bearings), the moment of inertia about the axis and
/// the effects' moments about the axis point.
#[derive(Debug, Clone, PartialEq)]
pub struct Hinge {
    axis: FixedAxis,
    i_uu: f64,
    moments: EffectMoments,
    theta0: f64,
    rate0: f64,
}

impl Hinge {
    /// A hinge about `axis` (its rate and acceleration are not used), starting at θ = `theta0` (rad), θ̇ =
    /// `rate0` (rad/s), driven by `moments` (gravity's pivot the axis point).
    pub fn new(axis: FixedAxis, moments: EffectMoments, theta0: f64, rate0: f64) -> Self {
        let i_uu = axis.i_uu();
        Self {
            axis,
            i_uu,
            moments,
            theta0,
            rate0,
        }
    }

    /// The initial rate θ̇(0) (rad/s).
    pub fn rate0(&self) -> f64 {
        self.rate0
    }

    /// The axis geometry.
    pub fn axis(&self) -> &FixedAxis {
        &self.axis
    }

    /// I_uu = u·I_A u, the moment of inertia about the axis (kg·m²).
    pub fn i_uu(&self) -> f64 {
        self.i_uu
    }

    /// The effects.
    pub fn moments(&self) -> &EffectMoments {
        &self.moments
    }

    /// θ at t = 0 (rad).
    pub fn theta0(&self) -> f64 {
        self.theta0
    }

    /// The state at t = 0 in `form`: L = u·H_s = u_b·I_A ω_b (= I_uu θ̇ without a carrier).
    pub fn initial_state(&self, form: Form) -> HingeState {
        match (form, self.axis.moving_support()) {
            (Form::Body, _) => HingeState::new(self.theta0, self.rate0),
            (Form::Space, None) => HingeState::new(self.theta0, self.i_uu * self.rate0),
            (Form::Space, Some(_)) => {
                let rotation = self.axis.rotation(0.0, self.theta0, self.rate0);
                let u_b = self.axis.axis_b().into_inner();
                let l = u_b.dot(&(self.axis.inertia_a_b() * *rotation.omega_b));
                HingeState::new(self.theta0, l)
            }
        }
    }

    /// θ̇ and the rotation at t from the state of `form`; in the space form θ̇ = (L − u_b·I_A ω_c,b)/I_uu, with
    /// ω_c,b the carrier's rate in body axes (zero without one).
    fn rotation(&self, t: f64, form: Form, y: &HingeState) -> (f64, AxisRotation) {
        let u_b = self.axis.axis_b().into_inner();
        let placed = self.axis.placed(t, y[0]);
        let theta_dot = match (form, self.axis.moving_support()) {
            (Form::Body, _) => y[1],
            (Form::Space, None) => y[1] / self.i_uu,
            (Form::Space, Some(_)) => {
                let carried = u_b.dot(&(self.axis.inertia_a_b() * *placed.omega_b));
                (y[1] - carried) / self.i_uu
            }
        };
        (theta_dot, placed.turning(&Vector::new(u_b), theta_dot))
    }

    /// θ̈ from u·(dH/dt + ρ × m a_A − M_eff) = 0: θ̈ = u_b·(M_eff,b − ρ_b × m a_A,b − I_A β_b − ω_b × I_A ω_b)/I_uu
    /// with β = ω̇ − θ̈ u the carrier's part (a_A only in a vehicle); without a carrier the last three terms vanish
    /// (β = 0, ω ∥ u) and θ̈ = u_b·M_eff,b/I_uu.
    fn theta_ddot(&self, rotation: &AxisRotation, m_eff_b: &Vector3<f64>) -> f64 {
        let u_b = self.axis.axis_b().into_inner();
        match rotation.support {
            None => u_b.dot(m_eff_b) / self.i_uu,
            Some(_) => {
                let i_a = self.axis.inertia_a_b();
                let (omega_b, beta_b) = (
                    *rotation.omega_b,
                    rotation.q.inverse_transform_vector(&rotation.bias_s),
                );
                let inertial = i_a * beta_b + omega_b.cross(&(i_a * omega_b));
                let inertial = match rotation.accel_a_s() {
                    None => inertial,
                    Some(a_a_s) => {
                        let a_a_b = rotation.q.inverse_transform_vector(&a_a_s);
                        inertial + self.axis.rho_c_b().cross(&(a_a_b * self.axis.mass()))
                    }
                };
                u_b.dot(&(m_eff_b - inertial)) / self.i_uu
            }
        }
    }

    /// The row at time t from the state of `form`: the kinematics at (θ, θ̇, θ̈ from the hinge condition),
    /// M = dH/dt in the form's own way, and the support's loads.
    pub fn sample(&self, t: f64, y: &HingeState, form: Form) -> Sample {
        let (theta_dot, rotation) = self.rotation(t, form, y);
        let m_eff_b = self.moments.moment_b(t, &rotation.q, &rotation.omega_b);
        let angle = AxisAngle {
            theta: y[0],
            theta_dot,
            theta_ddot: self.theta_ddot(&rotation, &m_eff_b),
        };
        self.axis
            .sample_at(t, &angle, &rotation, form, &(rotation.q * m_eff_b))
    }
}

/// The hinge's equation in body axes: θ̇' = θ̈ from the hinge condition ([`Hinge`]'s `theta_ddot`).
pub struct HingeBodyForm<'a>(pub &'a Hinge);

impl OdeSystem<2> for HingeBodyForm<'_> {
    fn rhs(&mut self, t: f64, y: &HingeState) -> HingeState {
        let hinge = self.0;
        let rotation = hinge.axis.rotation(t, y[0], y[1]);
        let m_eff_b = hinge.moments.moment_b(t, &rotation.q, &rotation.omega_b);
        HingeState::new(y[1], hinge.theta_ddot(&rotation, &m_eff_b))
    }

    fn next_breakpoint(&self, t: f64) -> Option<f64> {
        self.0.moments.corner_after(t)
    }
}

/// The hinge's equation in space axes: L = u·H_s, L' = u̇·H_s + u·Ḣ_s = (Ω_c × u)·H_s + u·(M_eff,s − ρ × m a_A)
/// (the first term only in a carrier, a_A only in a vehicle), θ' = θ̇.
pub struct HingeSpaceForm<'a>(pub &'a Hinge);

impl OdeSystem<2> for HingeSpaceForm<'_> {
    fn rhs(&mut self, t: f64, y: &HingeState) -> HingeState {
        let hinge = self.0;
        let (theta_dot, rotation) = hinge.rotation(t, Form::Space, y);
        let m_eff_s = rotation.q * hinge.moments.moment_b(t, &rotation.q, &rotation.omega_b);
        let axial = rotation.u_s.dot(&m_eff_s);
        let l_dot = match rotation.support {
            None => axial,
            Some(c) => {
                let h_s = rotation.q * (hinge.axis.inertia_a_b() * *rotation.omega_b);
                let l_dot = c.omega_c_s.cross(&*rotation.u_s).dot(&h_s) + axial;
                match hinge.axis.transport_moment_s(&rotation) {
                    None => l_dot,
                    Some(transport_s) => l_dot - rotation.u_s.dot(&*transport_s),
                }
            }
        };
        HingeState::new(theta_dot, l_dot)
    }

    fn next_breakpoint(&self, t: f64) -> Option<f64> {
        self.0.moments.corner_after(t)
    }
}
