//! A table's file form as the derives make it (`#[derive(Keys)]`, `#[derive(Table)]`, `#[derive(Kind)]` from the
//! crate eulerdyn-derive): [`Keys`], what each one implements — its keys for the reference, serde reading and
//! writing key by key (so that a group of keys is spliced into its table and unknown keys are still refused),
//! the keys a file gives, the either/or checks — and the pieces its generated code calls.

use std::fmt;
use std::marker::PhantomData;

use serde::de::{DeserializeSeed, Error as _, MapAccess, Visitor};
use serde::ser::SerializeMap;
use serde::{Deserialize, Deserializer, Serializer};

use super::{Checked, Key, KeyPath};

/// A table's file form, or a group of keys spliced into one (`#[key(flatten)]`): every key the file may give.
pub(crate) trait Keys: Default {
    /// The keys for the reference, a group's in its place.
    const KEYS: &'static [Key];
    /// The names a file may give, a group's in its place (serde's "expected one of").
    const NAMES: &'static [&'static str];
    /// The names serde requires.
    const REQUIRED: &'static [&'static str];
    /// Reads the value of `key` from `map` into its field: `false` when the key is not this form's.
    fn take<'de, A: MapAccess<'de>>(&mut self, key: &str, map: &mut A) -> Result<bool, A::Error>;
    /// Writes each key given into `map`, in order.
    fn write_into<M: SerializeMap>(&self, map: &mut M) -> Result<(), M::Error>;
    /// Pushes the name of each key given, in order.
    fn given_into(&self, given: &mut Vec<&'static str>);
    /// Refuses keys given together that exclude each other (the table at `at`), naming the second.
    fn exclusive(&self, at: &KeyPath) -> Checked<()>;
}

/// The visitor of a file form: each key read by [`Keys::take`], an unknown or repeated one refused as serde's own
/// derive refuses it, then each required one checked.
pub(crate) struct TableVisitor<K> {
    expecting: &'static str,
    form: PhantomData<K>,
}

impl<K> TableVisitor<K> {
    /// The visitor; `expecting` is what a value of the wrong type is told it should be.
    pub(crate) fn new(expecting: &'static str) -> Self {
        Self {
            expecting,
            form: PhantomData,
        }
    }
}

impl<'de, K: Keys> Visitor<'de> for TableVisitor<K> {
    type Value = K;

    fn expecting(&self, f: &mut fmt::Formatter) -> fmt::Result {
        f.write_str(self.expecting)
    }

    fn visit_map<A: MapAccess<'de>>(self, mut map: A) -> Result<K, A::Error> {
        let mut form = K::default();
        let mut seen: Vec<&'static str> = Vec::new();
        while let Some(name) = map.next_key_seed(Name(K::NAMES))? {
            if seen.contains(&name) {
                return Err(A::Error::duplicate_field(name));
            }
            seen.push(name);
            form.take(name, &mut map)?;
        }
        match K::REQUIRED.iter().find(|name| !seen.contains(name)) {
            Some(name) => Err(A::Error::missing_field(name)),
            None => Ok(form),
        }
    }
}

/// A key of a table, one of its names: an unknown one is refused while the key is read, so that the message
/// points at the key.
struct Name(&'static [&'static str]);

impl<'de> DeserializeSeed<'de> for Name {
    type Value = &'static str;

    fn deserialize<D: Deserializer<'de>>(self, deserializer: D) -> Result<&'static str, D::Error> {
        deserializer.deserialize_identifier(self)
    }
}

impl<'de> Visitor<'de> for Name {
    type Value = &'static str;

    fn expecting(&self, f: &mut fmt::Formatter) -> fmt::Result {
        f.write_str("a key")
    }

    fn visit_str<E: serde::de::Error>(self, key: &str) -> Result<&'static str, E> {
        match self.0.iter().find(|n| **n == key) {
            Some(name) => Ok(name),
            None => Err(E::unknown_field(key, self.0)),
        }
    }
}

/// A file form written as a map of the keys it gives.
pub(crate) fn serialize_keys<K: Keys, S: Serializer>(
    form: &K,
    serializer: S,
) -> Result<S::Ok, S::Error> {
    let mut map = serializer.serialize_map(None)?;
    form.write_into(&mut map)?;
    map.end()
}

/// An array of exactly `N` numbers. (serde's `[f64; N]` ignores extra elements when TOML drives it, so
/// `omega = [1, 2, 3, 4]` would pass silently.)
pub(crate) struct Exactly<const N: usize>(pub [f64; N]);

impl<'de, const N: usize> Deserialize<'de> for Exactly<N> {
    fn deserialize<D: Deserializer<'de>>(deserializer: D) -> Result<Self, D::Error> {
        let items = Vec::<f64>::deserialize(deserializer)?;
        <[f64; N]>::try_from(items.as_slice())
            .map(Exactly)
            .map_err(|_| {
                D::Error::invalid_length(items.len(), &format!("an array of {N} numbers").as_str())
            })
    }
}

/// The items of `parts` in order, `N` of them in all (`blank` fills the array first): a table's own keys or names
/// and its groups' spliced.
pub(crate) const fn concat<T: Copy, const N: usize>(parts: &[&[T]], blank: T) -> [T; N] {
    let mut out = [blank; N];
    let (mut i, mut p) = (0, 0);
    while p < parts.len() {
        let mut j = 0;
        while j < parts[p].len() {
            out[i] = parts[p][j];
            (i, j) = (i + 1, j + 1);
        }
        p += 1;
    }
    assert!(i == N, "the count of a table's keys");
    out
}

/// Where a position in body axes is measured from (`#[key(position)]`).
pub(crate) const FROM_REFERENCE: &str =
    "the reference origin (the shape's center, or the point `inertia` is about), body axes";
