//! The doors a free body's attribute goes through (its wheels, its changing shape): how `[body]`'s keys become it
//! (`AttributeSpec`, on a free body in its scene, `Mounting`), what the facts, the method's rules, `check` and
//! the columns ask of it ([`BodyAttribute`]), and its motion for the run to integrate ([`AttributeDrive`]: its
//! state of N numbers, right-hand side, rows and splitting). Each attribute answers in its own folder;
//! `scene/attributes.rs` registers it.

use nalgebra::{SVector, UnitQuaternion, Vector3};

use super::free::FreeBody;
use super::lie_poisson::Scheme;
use crate::body::RigidBody;
use crate::effects::{Effect, EffectMoments};
use crate::frames::{BodyAxes, Form, Vector};
use crate::integrate::{FixedStep, OdeSystem};
use crate::keys::Checked;
use crate::method::Method;
use crate::panel::Panel;
use crate::sample::{ColumnGroup, Sample};
use crate::text::Description;

/// An attribute as `[body]` gives it (its field of `BodySpec`): validated onto a free body, refused on an axis.
pub(crate) trait AttributeSpec {
    /// The attribute as the motion holds it.
    type Held;

    /// Refuses the attribute, when `[body]` gives it, on a fixed axis or hinge.
    fn refuse_on_axis(&self) -> Checked<()>;

    /// The attribute of a free body in its scene, `None` when `[body]` does not give it; `others`: whether an
    /// attribute registered before it was given.
    fn on_free_body(&self, on: &Mounting, others: bool) -> Checked<Option<Self::Held>>;
}

/// What the scene around a free body's attribute holds.
pub(crate) struct Mounting<'a> {
    /// The rest of the body, and its centre C from the reference origin (m, body axes).
    pub body: (&'a RigidBody, &'a Vector3<f64>),
    /// The body about its moment center, and that center from the reference origin (m, body axes).
    pub free_body: (&'a FreeBody, &'a Vector3<f64>),
    /// Whether `[body]` has rigidly attached point masses.
    pub point_masses: bool,
    /// The scene's effects.
    pub effects: &'a [Effect],
    /// ω₀ (body axes, rad/s) and the `[initial]` key that gave it.
    pub omega0_b: (&'a Vector<BodyAxes>, &'a str),
}

/// A free body's attribute, as the rest of the library asks it.
pub trait BodyAttribute: std::fmt::Debug + Send + Sync {
    /// Its columns, written after all others.
    fn columns(&self) -> ColumnGroup;

    /// The panels it adds to the figure.
    fn panels(&self) -> Vec<Panel> {
        Vec::new()
    }

    /// Whether its drives do work on the body: the kinetic energy is then no invariant.
    fn does_work(&self) -> bool;

    /// Whether it turns H itself (an imbalanced wheel's moment): then nothing is conserved.
    fn turns_momentum(&self) -> bool {
        false
    }

    /// Why `method` cannot run it (with the scene's `effects`), if it cannot.
    fn refuses(&self, method: Method, effects: &[Effect]) -> Option<String>;

    /// ω, H about O (body and space axes) and T at t = 0, from ω₀ and the attitude `q0`.
    fn start(&self, omega0_b: &Vector<BodyAxes>, q0: &UnitQuaternion<f64>) -> StartRow;

    /// The equation integrated in `form`, as `check` prints it.
    fn equation(&self, form: Form) -> &'static str;

    /// Its `check` lines, on a body of mass `body_mass` (kg).
    fn describe(&self, w: &mut Description, body_mass: f64);

    /// The moments it puts on the body, in words, listed with the effects (a wheel's imbalance).
    fn moments(&self) -> Vec<String> {
        Vec::new()
    }
}

/// The state at t = 0 as `check` prints it.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct StartRow {
    /// ω (body axes, rad/s).
    pub omega_b: Vector3<f64>,
    /// H about O, body axes (kg·m²/s).
    pub h_o_b: Vector3<f64>,
    /// H about O, space axes (kg·m²/s).
    pub h_o_s: Vector3<f64>,
    /// T (J).
    pub energy: f64,
}

/// An attribute's motion, a state of `N` numbers: what `simulate` integrates.
pub trait AttributeDrive<const N: usize>: BodyAttribute {
    /// Its right-hand side under the scene's moments.
    type System<'a>: OdeSystem<N>
    where
        Self: 'a;
    /// Its split2/split4 step ([`crate::integrate::NoSplit`] when it has none).
    type Split<'a>: FixedStep<State = SVector<f64, N>>
    where
        Self: 'a;

    /// The state at t = 0 in `form`.
    fn initial_state(
        &self,
        form: Form,
        omega0_b: &Vector<BodyAxes>,
        q0: &UnitQuaternion<f64>,
    ) -> SVector<f64, N>;

    /// The right-hand side in `form` under `moment`.
    fn system(&self, moment: EffectMoments, form: Form) -> Self::System<'_>;

    /// The row of the state `y` at `t`.
    fn sample(&self, moment: &EffectMoments, form: Form, t: f64, y: &SVector<f64, N>) -> Sample;

    /// Its splitting by `scheme` on a body of mass `body_mass`, when it has one (validation refuses the others).
    fn split(
        &self,
        body_mass: f64,
        form: Form,
        scheme: Scheme,
        moment: EffectMoments,
    ) -> Option<Self::Split<'_>>;
}

/// What is done with an attribute's motion, whatever its state's size (the run: `simulate`).
pub trait DriveVisitor {
    /// The result.
    type Output;
    /// Does it with `attribute`.
    fn visit<const N: usize, A: AttributeDrive<N>>(self, attribute: &A) -> Self::Output;
}
