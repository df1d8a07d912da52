//! The vocabulary of a scene file's keys, below every capability that declares some: the path that names a key
//! ([`KeyPath`]), the error that names it ([`InvalidScene`]) and the checks that produce it, and a table's keys
//! declared once by the derives of eulerdyn-derive (`Table` on a typed spec, `Keys` on a file form, `Kind` on a
//! table's `type`): the serde form, the reference's [`Table`](struct@Table), the keys a file gives, `Part` and `Group`.

mod checks;
mod form;
mod part;
mod path;
mod table;

pub use checks::InvalidScene;
pub(crate) use checks::{Checked, Invalid, finite, invalid, only_keys, positive, required, vector};
pub(crate) use eulerdyn_derive::{Keys, Kind, Table};
pub(crate) use form::{Exactly, FROM_REFERENCE, Keys, TableVisitor, concat, serialize_keys};
pub(crate) use part::{Attach, Either, Group, Part};
pub use path::KeyPath;
pub(crate) use path::Segment;
pub use table::{Key, Table};
