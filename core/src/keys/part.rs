//! A capability's own table inside a table of the scene (`carrier = { … }` in `[motion]`, each `[[effect]]`),
//! declared in the capability's folder. The enclosing table registers it with one field (`#[key(table)]` in a typed
//! spec with `#[derive(Table)]`: `P`, `Option<P>` or `Vec<P>`; `#[key(part = SPEC)]` in a file form with
//! `#[derive(Keys)]`): the file field, the reference's table, the typed field, reading, writing and attaching come
//! from that line and [`Part`] (with [`Attach`]); [`Either`] and [`Group`] read keys of one table together.

use std::path::Path;

use super::{Checked, KeyPath, Table};

/// A part's keys: its declared file form, read into its typed spec and written back.
pub(crate) trait Part: Sized {
    /// The declared file form (a struct with `#[derive(Keys)]`).
    type File;
    /// Its keys, for the book's reference (the file form's `TABLE`).
    const TABLE: Table;
    /// The file form (the table at `at`) read into the typed spec: the checks that need no other key.
    fn read(file: &Self::File, at: &KeyPath) -> Checked<Self>;
    /// The typed spec written back into the file form (the sidecar's scene, `read` gives it back).
    fn write(&self) -> Self::File;
    /// The part given where the enclosing table takes none (a carrier's vehicle keys on a free motion): a
    /// message naming its own key, else `Ok` and the enclosing table refuses the part by its name.
    fn refuse_unattached(_file: &Self::File, _at: &KeyPath) -> Checked<()> {
        Ok(())
    }
    /// The part with each file it names (a torque table) taken relative to `dir`, a scene file's directory.
    fn take_files_in(&mut self, _dir: &Path) {}
}

/// A part attached to the validated value it modifies (a carrier to a fixed axis or hinge): its values checked.
pub(crate) trait Attach<T>: Part {
    /// `to` with this part (its table at `at`).
    fn attach(&self, to: T, at: &KeyPath) -> Checked<T>;
}

/// Two keys of a table that exclude each other, read as the typed choice between them (a table's `either` pair
/// declared `A, B => T::{VA, VB}`).
pub(crate) trait Either<T> {
    /// The choice the file gives: `VA(a)` when `A` is given, else `VB(b)`, else `None` (`exclusive()` has
    /// refused both).
    fn either(&self) -> Option<T>;
    /// `choice` written back into its key.
    fn set_either(&mut self, choice: Option<T>);
}

/// Keys of a table read together into one value of its typed spec (`#[key(flatten = F)]` on a field of a
/// `#[derive(Table)]` spec, `F` the keys' own `#[derive(Keys)]` struct): the body's `shape` or `inertia` as its `Distribution`.
pub(crate) trait Group<F>: Sized {
    /// The value the keys of `file` (the table at `at`) give.
    fn read(file: &F, at: &KeyPath) -> Checked<Self>;
    /// The value written back into its keys.
    fn write(&self, file: &mut F);
    /// The value with each file it names (a torque table) taken relative to `dir`, a scene file's directory.
    fn take_files_in(&mut self, _dir: &Path) {}
}

/// An `either` pair declared with its typed choice is a group: the choice, or `None` when neither key is given.
impl<F: Either<T>, T: Copy> Group<F> for Option<T> {
    fn read(file: &F, _at: &KeyPath) -> Checked<Self> {
        Ok(file.either())
    }

    fn write(&self, file: &mut F) {
        file.set_either(*self);
    }
}
