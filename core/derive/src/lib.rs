//! The derives of eulerdyn-core's scene tables, in the shape of serde's and clap's: attributes on an ordinary
//! struct or enum, a key's doc comment as the book's reference text, its default written once.
//!
//! - [`Keys`] on a table's *file form* (every key an `Option`, a `Vec` or a required value): its serde reading
//!   (unknown keys refused, arrays of exactly N numbers, `#[key(flatten)]` groups spliced in by the derive itself,
//!   since serde's `flatten` and `deny_unknown_fields` do not combine) and writing, the reference's `Key`s and
//!   `TABLE`, `given()`, the either/or pairs, the table's `type` (`kind_given`) and its attachable parts.
//! - [`Table`] on a table's *typed spec*: its file form (a struct with [`Keys`]), both conversions (`keys::Part`),
//!   `S::of(…)` and the files it names taken relative to a directory.
//! - [`Kind`] on the enum of a table's `type`: the names a file gives, the keys each kind takes, serde by name, and
//!   optionally the `Part` of a spec enum whose variants hold exactly the keys their kind takes.
//!
//! The generated code names `crate::keys` and `crate::scene`: the derives are eulerdyn-core's own. Misuse is a
//! compile error on the field or attribute at fault (the tests of each module).

use proc_macro::TokenStream;
use syn::{DeriveInput, parse_macro_input};

mod attrs;
mod keys;
mod kind;
mod model;
mod parts;
mod table;
mod types;

#[cfg(test)]
mod tests;

/// A table's file form: `#[keys(header = "[x]", about = "…", either(a, b, "message"), parts = P, spec)]` on the
/// struct, `#[key(…)]` on its fields (see `attrs::KeyAttr`).
#[proc_macro_derive(Keys, attributes(key, keys))]
pub fn derive_keys(input: TokenStream) -> TokenStream {
    expand(input, keys::derive)
}

/// A table's typed spec: `#[table(file = F, header = "[x]", about = "…", what = "a thing", either(a, b, "…"),
/// derive(Copy))]` on the struct, `#[key(…)]` on its fields.
#[proc_macro_derive(Table, attributes(key, table))]
pub fn derive_table(input: TokenStream) -> TokenStream {
    expand(input, table::derive)
}

/// A table's `type`: `#[kind(what = "effect type", missing = "…", spec = S, file = F)]` on the enum (or
/// `needs = "an effect"` for the message "missing: an effect needs `type` = "a", "b" or "c""),
/// `#[kind("name", takes(a, b, ..))]` on each variant (`..`: the table's parts).
#[proc_macro_derive(Kind, attributes(kind))]
pub fn derive_kind(input: TokenStream) -> TokenStream {
    expand(input, kind::derive)
}

fn expand(
    input: TokenStream,
    derive: fn(&DeriveInput) -> syn::Result<proc_macro2::TokenStream>,
) -> TokenStream {
    let input = parse_macro_input!(input as DeriveInput);
    derive(&input)
        .unwrap_or_else(syn::Error::into_compile_error)
        .into()
}
