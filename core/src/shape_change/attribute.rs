//! A changing shape through the door of a body attribute ([`BodyAttribute`], [`AttributeDrive`]): the state of
//! [`super::system`], 7 numbers; the Runge–Kutta methods and split2/split4 ([`ChangingSplit`]).

use std::sync::Arc;

use nalgebra::UnitQuaternion;

use super::ShapeChange;
use super::splitting::ChangingSplit;
use super::system::{self, ChangingForm};
use crate::effects::{Effect, EffectMoments, TorqueFree};
use crate::frames::{BodyAxes, Form, Vector};
use crate::method::Method;
use crate::motion::attribute::{AttributeDrive, BodyAttribute, StartRow};
use crate::motion::free::State;
use crate::motion::lie_poisson::Scheme;
use crate::sample::{ColumnGroup, Sample};
use crate::text::Description;

impl BodyAttribute for Arc<ShapeChange> {
    fn columns(&self) -> ColumnGroup {
        ShapeChange::columns(self)
    }

    /// Its drives do work (`P_internal`): M = d/dt(I·ω) keeps H, not T.
    fn does_work(&self) -> bool {
        true
    }

    /// Not `exact` (the rigid body's closed form), and not split2/split4 with damping (their kicks solve it for a
    /// constant inertia).
    fn refuses(&self, method: Method, effects: &[Effect]) -> Option<String> {
        if method == Method::Exact {
            return Some(
                "method \"exact\" cannot run a body that changes shape: it is the rigid body's torque-free closed \
                 form, its inertia constant; use split2, split4, rk4, dopri5 or dop853"
                    .into(),
            );
        }
        let damped = effects.iter().position(|e| e.damping().is_some());
        match (method.is_runge_kutta(), damped) {
            (false, Some(index)) => Some(format!(
                "method \"{}\" cannot damp a body that changes shape (effect[{index}]): its kicks solve the \
                 damping with a constant inertia; use rk4, dopri5 or dop853",
                method.name()
            )),
            _ => None,
        }
    }

    /// Its row at t = 0: H = I(0) ω + h(0) about C(0), T of [`super::system`].
    fn start(&self, omega0_b: &Vector<BodyAxes>, q0: &UnitQuaternion<f64>) -> StartRow {
        let y0 = system::initial_state(self, Form::Body, omega0_b, q0);
        let s = system::sample(self, &TorqueFree, Form::Body, 0.0, &y0);
        StartRow {
            omega_b: *s.omega_b,
            h_o_b: *s.h_o_b,
            h_o_s: *s.h_o_s,
            energy: s.energy,
        }
    }

    fn equation(&self, form: Form) -> &'static str {
        match form {
            Form::Body => {
                "body axes: dH_b/dt + omega x H_b = M, H = I(t)*omega + h (so I*omega' = M - I'*omega - h' - omega x H)"
            }
            Form::Space => "space axes: dH_s/dt = M_s, omega = I(t)^-1 (R^T H_s - h)",
        }
    }

    fn describe(&self, w: &mut Description, body_mass: f64) {
        ShapeChange::describe(self, w, body_mass);
    }
}

impl AttributeDrive<7> for Arc<ShapeChange> {
    type System<'a> = ChangingForm<'a, EffectMoments>;
    type Split<'a> = ChangingSplit<'a, EffectMoments>;

    fn initial_state(
        &self,
        form: Form,
        omega0_b: &Vector<BodyAxes>,
        q0: &UnitQuaternion<f64>,
    ) -> State {
        system::initial_state(self, form, omega0_b, q0)
    }

    fn system(&self, moment: EffectMoments, form: Form) -> Self::System<'_> {
        ChangingForm::new(self, moment, form)
    }

    fn sample(&self, moment: &EffectMoments, form: Form, t: f64, y: &State) -> Sample {
        system::sample(self, moment, form, t, y)
    }

    fn split(
        &self,
        body_mass: f64,
        form: Form,
        scheme: Scheme,
        moment: EffectMoments,
    ) -> Option<Self::Split<'_>> {
        let mass = self.distribution().mass(body_mass);
        Some(ChangingSplit::new(self, mass, form, scheme, moment))
    }
}
