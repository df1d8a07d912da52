//! `#[derive(Keys)]`: a file form's serde reading and writing, its reference keys, `given()`, either/or checks,
//! `kind_given()` and its parts, from a struct ([`derive`]) or from the model a typed spec builds ([`generate`]).

use proc_macro2::TokenStream;
use quote::quote;
use syn::{Data, DeriveInput, Expr, Fields};

use crate::attrs::{Either, KeyAttr};
use crate::model::{FileField, FileForm, KeyDoc, Store, store_of};

/// The struct's file form read from its attributes, and its code.
pub fn derive(input: &DeriveInput) -> syn::Result<TokenStream> {
    generate(&read(input)?)
}

/// `#[keys(…)]` and each field's `#[key(…)]`.
fn read(input: &DeriveInput) -> syn::Result<FileForm> {
    let Data::Struct(data) = &input.data else {
        return Err(syn::Error::new_spanned(
            &input.ident,
            "#[derive(Keys)] is for a struct of named fields",
        ));
    };
    let Fields::Named(named) = &data.fields else {
        return Err(syn::Error::new_spanned(
            &input.ident,
            "#[derive(Keys)] is for a struct of named fields",
        ));
    };
    let mut form = FileForm {
        ident: input.ident.clone(),
        table: None,
        fields: Vec::new(),
        eithers: Vec::new(),
        parts: None,
        own_spec: false,
    };
    let (mut header, mut about) = (None, None);
    for a in input.attrs.iter().filter(|a| a.path().is_ident("keys")) {
        a.parse_nested_meta(|meta| {
            if meta.path.is_ident("header") {
                header = Some(meta.value()?.parse::<Expr>()?);
            } else if meta.path.is_ident("about") {
                about = Some(meta.value()?.parse::<Expr>()?);
            } else if meta.path.is_ident("either") {
                form.eithers.push(Either::parse(meta.input)?);
            } else if meta.path.is_ident("parts") {
                form.parts = Some(meta.value()?.parse()?);
            } else if meta.path.is_ident("spec") {
                form.own_spec = true;
            } else {
                return Err(meta.error(
                    "unknown `keys` attribute; expected header, about, either, parts or spec",
                ));
            }
            Ok(())
        })?;
    }
    form.table = match (header, about) {
        (Some(h), Some(a)) => Some((h, a)),
        (None, None) => None,
        _ => {
            return Err(syn::Error::new_spanned(
                &input.ident,
                "a table gives both `header` and `about`",
            ));
        }
    };
    for field in &named.named {
        form.fields.push(read_field(field)?);
    }
    Ok(form)
}

fn read_field(field: &syn::Field) -> syn::Result<FileField> {
    let attr = KeyAttr::of(field)?;
    let ident = field.ident.clone().expect("named fields");
    if attr.default.is_some() {
        return Err(syn::Error::new_spanned(
            &ident,
            "a file form stores what the file gives: `default` belongs on the typed spec (#[derive(Table)])",
        ));
    }
    if attr.flatten.is_some() {
        return Ok(FileField {
            ident,
            ty: field.ty.clone(),
            store: Store::Flatten,
            key: None,
            part: None,
            kinds: None,
        });
    }
    let (store, value) = store_of(&field.ty);
    let shown = matches!(store, Store::Required).then(|| quote!("required"));
    let mut key = KeyDoc::new(field, &attr, value, shown)?;
    if attr.table {
        key.holds = Some(quote!(<#value>::TABLE));
    }
    Ok(FileField {
        ident,
        ty: field.ty.clone(),
        store,
        key: Some(key),
        part: attr.part.clone(),
        kinds: attr.kinds.then(|| value.clone()),
    })
}

/// The code of a file form: `keys::Keys`, serde, `given()`, `TABLE`, and what its attributes ask for.
pub fn generate(form: &FileForm) -> syn::Result<TokenStream> {
    let name = &form.ident;
    let segments = form.fields.iter().map(|f| match (&f.store, &f.key) {
        (Store::Flatten, _) => {
            let ty = &f.ty;
            (
                quote!(<#ty as crate::keys::Keys>::KEYS),
                quote!(<#ty as crate::keys::Keys>::NAMES),
                quote!(<#ty as crate::keys::Keys>::KEYS.len()),
            )
        }
        (_, Some(key)) => {
            let (k, n) = (key.tokens(), &key.name);
            (quote!(&[#k]), quote!(&[#n]), quote!(1))
        }
        (_, None) => unreachable!("a stored key has its reference"),
    });
    let (keys, names, lens): (Vec<_>, Vec<_>, Vec<_>) = segments.fold(
        (Vec::new(), Vec::new(), Vec::new()),
        |(mut k, mut n, mut l), (a, b, c)| {
            k.push(a);
            n.push(b);
            l.push(c);
            (k, n, l)
        },
    );
    let len = quote!(0 #(+ #lens)*);
    let required: Vec<&String> = form
        .fields
        .iter()
        .filter(|f| matches!(f.store, Store::Required))
        .filter_map(|f| f.key.as_ref().map(|k| &k.name))
        .collect();
    let take = form.fields.iter().map(take_arm);
    let flattened: Vec<&FileField> = form
        .fields
        .iter()
        .filter(|f| matches!(f.store, Store::Flatten))
        .collect();
    let take_flat = flattened.iter().map(|f| {
        let (ident, ty) = (&f.ident, &f.ty);
        quote!(if <#ty as crate::keys::Keys>::take(&mut self.#ident, key, map)? { return Ok(true); })
    });
    let write = form.fields.iter().map(write_entry);
    let given = form.fields.iter().map(given_entry);
    let (exclusive, choices) = exclusive(form);
    let name_text = name.to_string();
    let expecting = format!("struct {name}");
    let table = table_const(form);
    let parts = crate::parts::generate(form);
    let kinds = kind_given(form)?;
    let own = form.own_spec.then(|| own_spec(form));
    Ok(quote! {
        impl crate::keys::Keys for #name {
            const KEYS: &'static [crate::keys::Key] = &crate::keys::concat::<crate::keys::Key, { #len }>(&[#(#keys),*], crate::keys::Key::BLANK);
            const NAMES: &'static [&'static str] = &crate::keys::concat::<&'static str, { #len }>(&[#(#names),*], "");
            const REQUIRED: &'static [&'static str] = &[#(#required),*];

            // A group without keys of its own (`NoKeys`) has only the fall-through arm.
            #[allow(unreachable_code)]
            fn take<'de, A: ::serde::de::MapAccess<'de>>(&mut self, key: &str, map: &mut A) -> ::core::result::Result<bool, A::Error> {
                match key {
                    #(#take)*
                    _ => {
                        #(#take_flat)*
                        return Ok(false);
                    }
                }
                Ok(true)
            }

            fn write_into<M: ::serde::ser::SerializeMap>(&self, map: &mut M) -> ::core::result::Result<(), M::Error> {
                #(#write)*
                Ok(())
            }

            fn given_into(&self, given: &mut ::std::vec::Vec<&'static str>) {
                #(#given)*
            }

            fn exclusive(&self, at: &crate::keys::KeyPath) -> crate::keys::Checked<()> {
                let _ = at;
                #exclusive
                Ok(())
            }
        }

        impl #name {
            /// The keys this table gives, in the declaration's order.
            #[allow(dead_code)]
            pub(crate) fn given(&self) -> ::std::vec::Vec<&'static str> {
                let mut given = ::std::vec::Vec::new();
                crate::keys::Keys::given_into(self, &mut given);
                given
            }
            #table
        }

        impl<'de> ::serde::Deserialize<'de> for #name {
            fn deserialize<D: ::serde::Deserializer<'de>>(deserializer: D) -> ::core::result::Result<Self, D::Error> {
                deserializer.deserialize_struct(#name_text, <Self as crate::keys::Keys>::NAMES, crate::keys::TableVisitor::<Self>::new(#expecting))
            }
        }

        impl ::serde::Serialize for #name {
            fn serialize<S: ::serde::Serializer>(&self, serializer: S) -> ::core::result::Result<S::Ok, S::Error> {
                crate::keys::serialize_keys(self, serializer)
            }
        }

        #choices
        #parts
        #kinds
        #own
    })
}

/// The reading of one key of the file (`key` matched against its name).
fn take_arm(field: &FileField) -> TokenStream {
    let ident = &field.ident;
    let Some(key) = &field.key else {
        return quote!();
    };
    let name = &key.name;
    match &field.store {
        Store::Optional => quote!(#name => self.#ident = Some(map.next_value()?),),
        Store::Exactly(n) => {
            quote!(#name => self.#ident = Some(map.next_value::<crate::keys::Exactly<{ #n }>>()?.0),)
        }
        Store::List | Store::Required => quote!(#name => self.#ident = map.next_value()?,),
        Store::Flatten => quote!(),
    }
}

/// The writing of one key (left out when absent).
fn write_entry(field: &FileField) -> TokenStream {
    let ident = &field.ident;
    let ty = &field.ty;
    match (&field.store, &field.key) {
        (Store::Flatten, _) => quote!(<#ty as crate::keys::Keys>::write_into(&self.#ident, map)?;),
        (Store::Optional | Store::Exactly(_), Some(k)) => {
            let name = &k.name;
            quote!(if let Some(value) = &self.#ident { map.serialize_entry(#name, value)?; })
        }
        (Store::List, Some(k)) => {
            let name = &k.name;
            quote!(if !self.#ident.is_empty() { map.serialize_entry(#name, &self.#ident)?; })
        }
        (Store::Required, Some(k)) => {
            let name = &k.name;
            quote!(map.serialize_entry(#name, &self.#ident)?;)
        }
        (_, None) => quote!(),
    }
}

/// Whether the key is given, pushed onto `given`.
fn given_entry(field: &FileField) -> TokenStream {
    let ident = &field.ident;
    let ty = &field.ty;
    match (&field.store, &field.key) {
        (Store::Flatten, _) => quote!(<#ty as crate::keys::Keys>::given_into(&self.#ident, given);),
        (Store::Optional | Store::Exactly(_), Some(k)) => {
            let name = &k.name;
            quote!(if self.#ident.is_some() { given.push(#name); })
        }
        (Store::List, Some(k)) => {
            let name = &k.name;
            quote!(if !self.#ident.is_empty() { given.push(#name); })
        }
        (Store::Required, Some(k)) => {
            let name = &k.name;
            quote!(given.push(#name);)
        }
        (_, None) => quote!(),
    }
}

/// The either/or checks (each pair refused naming its second key), then each group's; and the pairs read as a
/// typed choice (`keys::Either`).
fn exclusive(form: &FileForm) -> (TokenStream, TokenStream) {
    let pairs = form.eithers.iter().map(|e| {
        let message = &e.message;
        let checks = e.keys.iter().enumerate().skip(1).map(|(j, later)| {
            let earlier = &e.keys[..j];
            let name = later.to_string();
            quote!(if self.#later.is_some() && (false #(|| self.#earlier.is_some())*) {
                return crate::keys::invalid(at.clone().key(#name), #message);
            })
        });
        quote!(#(#checks)*)
    });
    let groups = form
        .fields
        .iter()
        .filter(|f| matches!(f.store, Store::Flatten))
        .map(|f| {
            let (ident, ty) = (&f.ident, &f.ty);
            quote!(<#ty as crate::keys::Keys>::exclusive(&self.#ident, at)?;)
        });
    let name = &form.ident;
    let choices = form.eithers.iter().filter_map(|e| {
        let (va, vb) = e.choice.as_ref()?;
        let (a, b) = (&e.keys[0], &e.keys[1]);
        let enum_path: Vec<_> = va
            .segments
            .iter()
            .take(va.segments.len().saturating_sub(1))
            .collect();
        let ty = quote!(#(#enum_path)::*);
        Some(quote! {
            impl crate::keys::Either<#ty> for #name {
                fn either(&self) -> Option<#ty> {
                    match (self.#a, self.#b) {
                        (Some(a), _) => Some(#va(a)),
                        (None, Some(b)) => Some(#vb(b)),
                        (None, None) => None,
                    }
                }

                fn set_either(&mut self, choice: Option<#ty>) {
                    match choice {
                        Some(#va(a)) => self.#a = Some(a),
                        Some(#vb(b)) => self.#b = Some(b),
                        None => {}
                    }
                }
            }
        })
    });
    let choices: Vec<TokenStream> = choices.collect();
    (quote!(#(#pairs)* #(#groups)*), quote!(#(#choices)*))
}

/// `TABLE`, when the form is a table of the reference.
fn table_const(form: &FileForm) -> TokenStream {
    let Some((header, about)) = &form.table else {
        return quote!();
    };
    let parts = form.fields.iter().filter_map(|f| f.part.as_ref());
    quote! {
        /// The table's keys, as the book's reference lists them.
        pub(crate) const TABLE: crate::keys::Table = crate::keys::Table {
            header: #header,
            about: #about,
            keys: <Self as crate::keys::Keys>::KEYS,
            parts: &[#(<#parts as crate::keys::Part>::TABLE),*],
        };
    }
}

/// `kind_given()`, when a field is the table's `type`.
fn kind_given(form: &FileForm) -> syn::Result<TokenStream> {
    let Some(field) = form.fields.iter().find(|f| f.kinds.is_some()) else {
        return Ok(quote!());
    };
    let (ident, kind) = (&field.ident, field.kinds.as_ref().unwrap());
    let name = &form.ident;
    let parts = match &form.parts {
        Some(p) => quote!(#p::NAMES),
        None => quote!(&[]),
    };
    Ok(quote! {
        impl #name {
            /// The table's `type`, with every key given one that type takes (the table at `at`); with it the text
            /// that messages about its keys begin with, `WHAT = "NAME"`.
            pub(crate) fn kind_given(&self, at: &crate::keys::KeyPath) -> crate::keys::Checked<(#kind, String)> {
                let Some(kind) = self.#ident else {
                    return crate::keys::invalid(at.clone().key("type"), <#kind>::MISSING);
                };
                let text = format!("{} = \"{}\"", <#kind>::WHAT, kind.name());
                crate::keys::only_keys(at, &text, &kind.takes(#parts), &self.given())?;
                Ok((kind, text))
            }
        }
    })
}

/// `keys::Part` with `File = Self`: a table whose keys depend on no other is its own typed spec.
fn own_spec(form: &FileForm) -> TokenStream {
    let name = &form.ident;
    quote! {
        impl crate::keys::Part for #name {
            type File = #name;
            const TABLE: crate::keys::Table = #name::TABLE;

            fn read(file: &#name, _at: &crate::keys::KeyPath) -> crate::keys::Checked<Self> {
                Ok(::core::clone::Clone::clone(file))
            }

            fn write(&self) -> #name {
                ::core::clone::Clone::clone(self)
            }
        }
    }
}
