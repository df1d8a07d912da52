//! A free body's attributes, registered: the one place that names them all, one line each. Each attribute's
//! folder holds its physics, keys, validation, columns and `check` lines, and answers the door of
//! [`crate::motion::attribute`]; from its line, `Variant(Held),`, `body_attributes!` makes its variant of
//! [`Attribute`] and its arm in the two dispatches: the door ([`Attribute::door`]) and the run's
//! ([`Attribute::drive`]).

use std::sync::Arc;

use crate::motion::attribute::{BodyAttribute, DriveVisitor};
use crate::shape_change::ShapeChange;
use crate::wheels::gyrostat::Gyrostat;

/// The registry's expansion: the enum and its dispatches, from one line an attribute.
macro_rules! body_attributes {
    ($($(#[doc = $doc:literal])* $variant:ident($held:ty),)*) => {
        /// A free body's attribute, validated (at most one a body).
        #[derive(Debug, Clone, PartialEq)]
        pub enum Attribute {
            $($(#[doc = $doc])* $variant($held),)*
        }

        impl Attribute {
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

        $(
            impl From<$held> for Attribute {
                fn from(attribute: $held) -> Self {
                    Attribute::$variant(attribute)
                }
            }
        )*
    };
}

body_attributes! {
    /// The body's wheels (`[[body.rotor]]`).
    Rotors(Box<Gyrostat>),
    /// The body's mass distribution in time (`[[body.moving_mass]]`, `inertia_table`).
    ShapeChange(Arc<ShapeChange>),
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
