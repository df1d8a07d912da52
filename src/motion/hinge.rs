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

use nalgebra::{SVector, UnitQuaternion, Vector3};

use crate::effects::{AppliedMoment, EffectMoments};
use crate::frames::Form;
use crate::integrate::OdeSystem;
use crate::motion::fixed_axis::{AxisAngle, FixedAxis};
use crate::sample::Sample;

/// State of a hinge: (θ, θ̇) in the body form, (θ, L = I_uu θ̇) in the space form.
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

    /// The state at t = 0 in `form`.
    pub fn initial_state(&self, form: Form) -> HingeState {
        match form {
            Form::Body => HingeState::new(self.theta0, self.rate0),
            Form::Space => HingeState::new(self.theta0, self.i_uu * self.rate0),
        }
    }

    /// θ̇ from the state of `form`.
    fn theta_dot(&self, form: Form, y: &HingeState) -> f64 {
        match form {
            Form::Body => y[1],
            Form::Space => y[1] / self.i_uu,
        }
    }

    /// The effects' moment about the axis point, body axes, at t, θ and θ̇.
    fn effect_moment_b(&self, t: f64, q: &UnitQuaternion<f64>, theta_dot: f64) -> Vector3<f64> {
        let omega_b = self.axis.axis_b().into_inner() * theta_dot;
        self.moments.moment_b(t, q, &omega_b)
    }

    /// The row at time t from the state of `form`: the kinematics at (θ, θ̇, θ̈ = u·M_eff/I_uu), M = dH/dt in the
    /// form's own way, and the support's loads.
    pub fn sample(&self, t: f64, y: &HingeState, form: Form) -> Sample {
        let theta_dot = self.theta_dot(form, y);
        let q = self.axis.attitude(y[0]);
        let m_eff_b = self.effect_moment_b(t, &q, theta_dot);
        let angle = AxisAngle {
            theta: y[0],
            theta_dot,
            theta_ddot: self.axis.axis_b().dot(&m_eff_b) / self.i_uu,
        };
        self.axis.sample_at(t, &angle, &q, form, &(q * m_eff_b))
    }
}

/// The hinge's equation in body axes: θ̇' = u_b·M_eff,b(t, θ, θ̇) / I_uu.
pub struct HingeBodyForm<'a>(pub &'a Hinge);

impl OdeSystem<2> for HingeBodyForm<'_> {
    fn rhs(&mut self, t: f64, y: &HingeState) -> HingeState {
        let hinge = self.0;
        let q = hinge.axis.attitude(y[0]);
        let m_eff_b = hinge.effect_moment_b(t, &q, y[1]);
        HingeState::new(y[1], hinge.axis.axis_b().dot(&m_eff_b) / hinge.i_uu)
    }

    fn next_breakpoint(&self, t: f64) -> Option<f64> {
        self.0.moments.corner_after(t)
    }
}

/// The hinge's equation in space axes: L' = u_s·M_eff,s(t, θ, θ̇), θ' = L / I_uu.
pub struct HingeSpaceForm<'a>(pub &'a Hinge);

impl OdeSystem<2> for HingeSpaceForm<'_> {
    fn rhs(&mut self, t: f64, y: &HingeState) -> HingeState {
        let hinge = self.0;
        let theta_dot = y[1] / hinge.i_uu;
        let q = hinge.axis.attitude(y[0]);
        let m_eff_s = q * hinge.effect_moment_b(t, &q, theta_dot);
        HingeState::new(theta_dot, hinge.axis.axis_s().dot(&m_eff_s))
    }

    fn next_breakpoint(&self, t: f64) -> Option<f64> {
        self.0.moments.corner_after(t)
    }
}
