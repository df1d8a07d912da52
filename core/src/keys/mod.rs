//! The vocabulary of a scene file's keys, below every capability that declares some: the path that names a key
//! ([`KeyPath`]), the error that names it ([`InvalidScene`]) and the checks that produce it, and a table's keys
//! declared once (`file_table!`: the flat serde form, the reference's [`Table`], the keys a file gives).

mod checks;
mod declare;
mod part;
mod path;

pub use checks::InvalidScene;
pub(crate) use checks::{Checked, Invalid, finite, invalid, only_keys, positive, required, vector};
pub use declare::{Key, Table};
pub(crate) use declare::{exactly_n, file_table, key, position, profile};
pub(crate) use part::{Attach, Either, Group, Part};
pub use path::KeyPath;
pub(crate) use path::Segment;
