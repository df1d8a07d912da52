//! The wheels through the door of a body attribute ([`BodyAttribute`], [`AttributeDrive`]): a state of 15 numbers,
//! the Runge–Kutta methods only. The motion holds it boxed (`scene::Attribute::Rotors`), and so it implements them.

use nalgebra::{UnitQuaternion, Vector3};

use super::RotorSpec;
use super::gyrostat::{Gyrostat, GyrostatForm, State};
use super::validate::validate_rotors;
use crate::effects::{Effect, EffectMoments};
use crate::frames::{BodyAxes, Form, Vector};
use crate::integrate::NoSplit;
use crate::keys::{Checked, KeyPath, invalid};
use crate::method::Method;
use crate::motion::attribute::{AttributeDrive, AttributeSpec, BodyAttribute, Mounting, StartRow};
use crate::motion::lie_poisson::Scheme;
use crate::panel::Panel;
use crate::sample::{ColumnGroup, Sample};
use crate::text::Description;

impl AttributeSpec for Vec<RotorSpec> {
    type Held = Box<Gyrostat>;

    fn refuse_on_axis(&self) -> Checked<()> {
        if self.is_empty() {
            return Ok(());
        }
        invalid(
            KeyPath::root().key("body").key("rotor"),
            "rotors are simulated in a freely turning body (free motion, or about a gravity pivot); a fixed-axis \
             or hinge motion with rotors is not supported",
        )
    }

    /// The gyrostat of the body about its moment center ([`validate_rotors`]).
    fn on_free_body(&self, on: &Mounting, _: bool) -> Checked<Option<Box<Gyrostat>>> {
        validate_rotors(self, on.free_body.0, on.free_body.1)
    }
}

impl BodyAttribute for Box<Gyrostat> {
    fn columns(&self) -> ColumnGroup {
        Gyrostat::columns(self)
    }

    fn panels(&self) -> Vec<Panel> {
        Gyrostat::panels(self)
    }

    fn does_work(&self) -> bool {
        !self.wheels_spin_freely()
    }

    fn turns_momentum(&self) -> bool {
        self.imbalanced()
    }

    fn refuses(&self, method: Method, _: &[Effect]) -> Option<String> {
        (!method.is_runge_kutta()).then(|| {
            format!(
                "method \"{}\" cannot take rotors: split2/split4 split the rigid body's rotation into planar \
                 rotations and exact is the rigid body's closed form, neither has the wheels' momentum; use rk4, \
                 dopri5 or dop853",
                method.name()
            )
        })
    }

    /// H_O = I_O ω + Σ J_k Ω_k a_k, H_O,s = R₀ H_O, T of [`Gyrostat::kinetic_energy`].
    fn start(&self, omega0_b: &Vector<BodyAxes>, q0: &UnitQuaternion<f64>) -> StartRow {
        let h_b: Vector3<f64> =
            self.body().inertia_b() * **omega0_b + *self.initial_rotor_momentum_b();
        let spins: Vec<f64> = self.rotors().iter().map(|r| r.spin0).collect();
        StartRow {
            omega_b: **omega0_b,
            h_o_b: h_b,
            h_o_s: q0 * h_b,
            energy: self.kinetic_energy(omega0_b, &spins),
        }
    }

    fn equation(&self, form: Form) -> &'static str {
        match form {
            Form::Body => {
                "body axes: I*omega' + sum J Omega' a + omega x H = M, H = I*omega + sum J Omega a (the wheels' momentum)"
            }
            Form::Space => {
                "space axes: dH_s/dt = M_s, H = I*omega + sum J Omega a (the wheels' momentum) with I_s(theta)"
            }
        }
    }

    fn describe(&self, w: &mut Description, _: f64) {
        Gyrostat::describe(self, w);
    }

    fn moments(&self) -> Vec<String> {
        self.imbalance_effects()
    }
}

impl AttributeDrive<15> for Box<Gyrostat> {
    type System<'a> = GyrostatForm<'a, EffectMoments>;
    type Split<'a> = NoSplit<15>;

    fn initial_state(
        &self,
        form: Form,
        omega0_b: &Vector<BodyAxes>,
        q0: &UnitQuaternion<f64>,
    ) -> State {
        Gyrostat::initial_state(self, form, omega0_b, q0)
    }

    fn system(&self, moment: EffectMoments, form: Form) -> Self::System<'_> {
        GyrostatForm {
            gyrostat: self,
            moment,
            form,
        }
    }

    fn sample(&self, moment: &EffectMoments, form: Form, t: f64, y: &State) -> Sample {
        Gyrostat::sample(self, moment, form, t, y)
    }

    fn split(&self, _: f64, _: Form, _: Scheme, _: EffectMoments) -> Option<NoSplit<15>> {
        None
    }
}
