//! A shape change in its scene ([`AttributeSpec`]): the rules that need the rest of it (a free body, no rotors, no
//! effect acting through the mass distribution; H(0) and T(0) numbers), then [`super::validate_shape_change`].

use std::sync::Arc;

use nalgebra::UnitQuaternion;

use super::keys::ShapeChangeSpec;
use super::{ShapeChange, validate_shape_change};
use crate::effects::Effect;
use crate::keys::{Checked, KeyPath, invalid};
use crate::motion::attribute::{AttributeSpec, BodyAttribute, Mounting};

impl ShapeChangeSpec {
    /// The key a message about the shape change names: `moving_mass` or `inertia_table`.
    fn key(&self) -> KeyPath {
        KeyPath::root()
            .key("body")
            .key(match self.moving_mass.is_empty() {
                true => "inertia_table",
                false => "moving_mass",
            })
    }
}

impl AttributeSpec for ShapeChangeSpec {
    type Held = Arc<ShapeChange>;

    /// Refuses a shape change on a fixed axis or hinge.
    fn refuse_on_axis(&self) -> Checked<()> {
        if !self.is_some() {
            return Ok(());
        }
        invalid(
            self.key(),
            "a body that changes shape turns freely (free motion): on a fixed axis or hinge its moving masses \
             would load the support in ways this model does not compute",
        )
    }

    /// The shape change of a free body about C, `None` when `[body]` gives none: without rotors, without an
    /// effect whose moment depends on the mass distribution (gravity about a pivot, the gravity gradient), and
    /// with H(0) and T(0) of the system numbers.
    fn on_free_body(&self, on: &Mounting, others: bool) -> Checked<Option<Arc<ShapeChange>>> {
        if !self.is_some() {
            return Ok(None);
        }
        if others {
            return invalid(
                self.key(),
                "a body that changes shape cannot carry rotors yet: remove `[[body.rotor]]` or the shape change",
            );
        }
        if let Some(index) = on.effects.iter().position(Effect::uses_mass_distribution) {
            return invalid(
                self.key(),
                format!(
                    "effect[{index}] ({}) acts through the mass distribution, which this body changes; its moment \
                     is not modelled for a changing body",
                    on.effects[index].kind()
                ),
            );
        }
        let Some(shape) = validate_shape_change(self, on.body.0, on.body.1, on.point_masses)?
        else {
            return Ok(None);
        };
        // As for a rigid body: H(0) and T(0) of the system must be numbers.
        let shape = Arc::new(shape);
        let (omega0_b, name) = on.omega0_b;
        let s = shape.start(omega0_b, &UnitQuaternion::identity());
        if !(s.energy.is_finite() && s.h_o_b.norm().is_finite()) {
            return invalid(
                KeyPath::root().key("initial").key(name),
                "ω₀ is too large for this body: the system's moment of momentum I(0)·ω₀ + h or its kinetic energy is \
                 beyond the range of double precision",
            );
        }
        Ok(Some(shape))
    }
}
