//! A table's file form as the [`Keys`](crate::keys) code is generated from it: what [`crate::keys::derive`] reads
//! from a struct and [`crate::table::derive`] builds from a typed spec.

use proc_macro2::TokenStream;
use quote::{ToTokens, quote};
use syn::spanned::Spanned;
use syn::{Expr, Ident, Type};

use crate::attrs::{Either, KeyAttr};
use crate::types;

/// A file form: its struct, its keys in order, its either/or pairs, its attachable parts.
pub struct FileForm {
    pub ident: Ident,
    /// `header` and `about`: the form is a table of the reference (else a group, spliced into one).
    pub table: Option<(Expr, Expr)>,
    pub fields: Vec<FileField>,
    pub eithers: Vec<Either>,
    /// The struct of the parts (`#[key(part = SPEC)]` fields), when there are any.
    pub parts: Option<Ident>,
    /// Whether the form is its own typed spec (`keys::Part` with `File = Self`).
    pub own_spec: bool,
}

/// One field of a file form.
pub struct FileField {
    pub ident: Ident,
    pub ty: Type,
    pub store: Store,
    /// The reference's key (none for a flattened group).
    pub key: Option<KeyDoc>,
    /// `part = SPEC`: the field is a capability's table that attaches to the validated value.
    pub part: Option<Type>,
    /// `kinds`: the field is the table's `type`, of this enum.
    pub kinds: Option<Type>,
}

impl FileField {
    /// A field that stores one key.
    pub fn key(ident: Ident, ty: Type, store: Store, key: KeyDoc) -> Self {
        FileField {
            ident,
            ty,
            store,
            key: Some(key),
            part: None,
            kinds: None,
        }
    }
}

/// How a field stores its key.
pub enum Store {
    /// `Option<T>`: absent is `None`.
    Optional,
    /// `Option<[f64; N]>`: exactly N numbers.
    Exactly(Expr),
    /// `Vec<T>`: absent is empty.
    List,
    /// `T`: serde refuses a file without it.
    Required,
    /// A group of keys (a struct with `Keys`) spliced into this table.
    Flatten,
}

/// A key as the reference lists it.
pub struct KeyDoc {
    pub name: String,
    pub kind: TokenStream,
    pub unit: TokenStream,
    pub shown: TokenStream,
    pub origin: TokenStream,
    pub doc: String,
    /// The table the key holds: an expression of type `keys::Table`.
    pub holds: Option<TokenStream>,
}

impl KeyDoc {
    /// The reference's key for a value of type `value` (the field's, without its `Option` or `Vec`), from the
    /// field's attributes and doc comment; `shown` is the default's text when the attributes do not give one.
    pub fn new(
        field: &syn::Field,
        attr: &KeyAttr,
        value: &Type,
        shown: Option<TokenStream>,
    ) -> syn::Result<Self> {
        let ident = field.ident.as_ref().expect("named fields");
        let name = attr
            .rename
            .as_ref()
            .map_or_else(|| ident.to_string(), |r| r.value());
        let doc = crate::attrs::doc_text(&field.attrs).ok_or_else(|| {
            syn::Error::new(
                ident.span(),
                format!(
                    "`{name}` needs a doc comment: it is the key's text in the book's reference"
                ),
            )
        })?;
        let tokens = |e: &Option<Expr>| e.as_ref().map(ToTokens::to_token_stream);
        let kind = if attr.position {
            Some(quote!("[x, y, z]"))
        } else if attr.kinds {
            Some(quote!(<#value>::CHOICES))
        } else {
            tokens(&attr.kind).or_else(|| types::kind_of(value).map(|k| quote!(#k)))
        };
        let kind = kind.ok_or_else(|| {
            syn::Error::new(
                field.ty.span(),
                format!(
                    "`{name}`: give `#[key(kind = \"…\")]`, what a value is (the type does not say it)"
                ),
            )
        })?;
        let unit = if attr.position {
            Some(quote!("m"))
        } else {
            tokens(&attr.unit)
        };
        let unit = match unit {
            Some(unit) => unit,
            None if types::is_numeric(value) => {
                return Err(syn::Error::new(
                    ident.span(),
                    format!(
                        "`{name}` is a number: give `#[key(unit = \"…\")]`, its SI unit (\"1\" when dimensionless)"
                    ),
                ));
            }
            None => quote!("–"),
        };
        let origin = if attr.position && attr.origin.is_none() {
            quote!(crate::keys::FROM_REFERENCE)
        } else {
            tokens(&attr.origin).unwrap_or_else(|| quote!(""))
        };
        Ok(KeyDoc {
            name,
            kind,
            unit,
            shown: tokens(&attr.shown)
                .or(shown)
                .unwrap_or_else(|| quote!("none")),
            origin,
            doc,
            holds: None,
        })
    }

    /// The key as a `keys::Key` expression.
    pub fn tokens(&self) -> TokenStream {
        let KeyDoc {
            name,
            kind,
            unit,
            shown,
            origin,
            doc,
            holds,
        } = self;
        let table = match holds {
            Some(t) => quote!(::core::option::Option::Some(&#t)),
            None => quote!(::core::option::Option::None),
        };
        quote!(crate::keys::Key {
            name: #name, kind: #kind, unit: #unit, default: #shown, origin: #origin, doc: #doc, table: #table,
        })
    }
}

/// How the field's type stores its key: `Option<[f64; N]>`, `Option<T>`, `Vec<T>` or `T`; and `T`.
pub fn store_of(ty: &Type) -> (Store, &Type) {
    if let Some(value) = types::inner(ty, "Option") {
        match types::f64_array_len(value) {
            Some(len) => (Store::Exactly(len.clone()), value),
            None => (Store::Optional, value),
        }
    } else if let Some(value) = types::inner(ty, "Vec") {
        (Store::List, value)
    } else {
        (Store::Required, ty)
    }
}
