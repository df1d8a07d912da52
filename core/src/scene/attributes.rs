//! A free body's attributes, registered: the one place that names them all, one line each. Each attribute's
//! folder holds its physics, keys, validation, columns and `check` lines, and answers the doors of
//! [`crate::motion::attribute`]; from its line, `Variant(Held) = field,` (`field`: its keys' field of
//! [`BodySpec`]), `body_attributes!` makes its variant of [`Attribute`] and its arm in each dispatch: its
//! validation ([`Attribute::on_free_body`], [`Attribute::refuse_on_axis`]), the door ([`Attribute::door`]) and the
//! run's ([`Attribute::drive`]).

use std::sync::Arc;

use super::spec::BodySpec;
use crate::keys::Checked;
use crate::motion::attribute::{AttributeSpec, BodyAttribute, DriveVisitor, Mounting};
use crate::shape_change::ShapeChange;
use crate::wheels::gyrostat::Gyrostat;

/// The registry's expansion: the enum and its dispatches, from one line an attribute.
macro_rules! body_attributes {
    ($($(#[doc = $doc:literal])* $variant:ident($held:ty) = $field:ident,)*) => {
        /// A free body's attribute, validated (at most one a body).
        #[derive(Debug, Clone, PartialEq)]
        pub enum Attribute {
            $($(#[doc = $doc])* $variant($held),)*
        }

        impl Attribute {
            /// The attribute `body` gives a free body in its scene, if any: each validated in the registry's order,
            /// told whether one before it was given (at most one a body: the later refuses).
            pub(crate) fn on_free_body(body: &BodySpec, on: &Mounting) -> Checked<Option<Attribute>> {
                let mut attribute = None;
                $(
                    if let Some(held) = body.$field.on_free_body(on, attribute.is_some())? {
                        attribute = attribute.or(Some(Attribute::$variant(held)));
                    }
                )*
                Ok(attribute)
            }

            /// Refuses any attribute `body` gives, on a fixed axis or hinge.
            pub(crate) fn refuse_on_axis(body: &BodySpec) -> Checked<()> {
                $(body.$field.refuse_on_axis()?;)*
                Ok(())
            }

            /// The attribute's door: everything the facts, the method's rules, `check` and the columns ask.
            pub fn door(&self) -> &dyn BodyAttribute {
                match self {
                    $(Attribute::$variant(attribute) => attribute,)*
                }
            }

            /// Its motion handed to `visitor` (the run), at its state's size.
            pub fn drive<V: DriveVisitor>(&self, visitor: V) -> V::Output {
                match self {
                    $(Attribute::$variant(attribute) => visitor.visit(attribute),)*
                }
            }
        }
    };
}

body_attributes! {
    /// The body's wheels (`[[body.rotor]]`).
    Rotors(Box<Gyrostat>) = rotor,
    /// The body's mass distribution in time (`[[body.moving_mass]]`, `inertia_table`).
    ShapeChange(Arc<ShapeChange>) = shape_change,
}

impl Attribute {
    /// The body's wheels, when this is them (what the wheel law, the symmetric gyrostat's closed form and `fit`
    /// need of them).
    pub fn gyrostat(&self) -> Option<&Gyrostat> {
        match self {
            Attribute::Rotors(gyrostat) => Some(gyrostat),
            _ => None,
        }
    }

    /// The body's wheels, to change (a wheel law).
    pub(crate) fn gyrostat_mut(&mut self) -> Option<&mut Gyrostat> {
        match self {
            Attribute::Rotors(gyrostat) => Some(gyrostat),
            _ => None,
        }
    }
}
