//! `#[derive(Kind)]`: the enum of a table's `type` — each variant's name in the file and the keys it takes — and,
//! with `spec = S, file = F`, the `keys::Part` of the spec enum `S` whose variant of each kind holds exactly the
//! keys it takes, each required.

use proc_macro2::TokenStream;
use quote::quote;
use syn::{Data, DeriveInput, Expr, Ident, LitStr, Token, Type};

/// One variant: its name in the file and the keys it takes (`None` marks where the table's parts go).
struct Variant {
    ident: Ident,
    name: LitStr,
    takes: Vec<Option<Ident>>,
}

/// The enum's attributes: what the messages call it and say when it is missing (or whose `type` it is, `needs`, to
/// say it in the usual words); the spec it reads.
#[derive(Default)]
struct KindAttr {
    what: Option<Expr>,
    missing: Option<Expr>,
    needs: Option<LitStr>,
    spec: Option<Type>,
    file: Option<Type>,
}

pub fn derive(input: &DeriveInput) -> syn::Result<TokenStream> {
    let Data::Enum(data) = &input.data else {
        return Err(syn::Error::new_spanned(
            &input.ident,
            "#[derive(Kind)] is for an enum of unit variants",
        ));
    };
    let mut attr = KindAttr::default();
    for a in input.attrs.iter().filter(|a| a.path().is_ident("kind")) {
        a.parse_nested_meta(|meta| {
            let value = meta.value()?;
            if meta.path.is_ident("what") {
                attr.what = Some(value.parse()?);
            } else if meta.path.is_ident("missing") {
                attr.missing = Some(value.parse()?);
            } else if meta.path.is_ident("needs") {
                attr.needs = Some(value.parse()?);
            } else if meta.path.is_ident("spec") {
                attr.spec = Some(value.parse()?);
            } else if meta.path.is_ident("file") {
                attr.file = Some(value.parse()?);
            } else {
                return Err(meta.error(
                    "unknown `kind` attribute; expected what, missing, needs, spec or file",
                ));
            }
            Ok(())
        })?;
    }
    let variants = data
        .variants
        .iter()
        .map(variant)
        .collect::<syn::Result<Vec<_>>>()?;
    let ident = &input.ident;
    let names: Vec<&LitStr> = variants.iter().map(|v| &v.name).collect();
    let missing = match (&attr.missing, &attr.needs) {
        (Some(missing), None) => quote!(#missing),
        (None, Some(needs)) => {
            let message = format!(
                "missing: {} needs `type` = {}",
                needs.value(),
                listed(&names)
            );
            quote!(#message)
        }
        _ => quote!(),
    };
    let (Some(what), false) = (&attr.what, missing.is_empty()) else {
        return Err(syn::Error::new_spanned(
            &input.ident,
            "give #[kind(what = \"…\", missing = \"…\")] (or `needs = \"a table\"` for \"missing: a table needs `type` = …\"): what messages call the type, and what they say when it is absent",
        ));
    };
    let idents: Vec<&Ident> = variants.iter().map(|v| &v.ident).collect();
    let indices = 0..variants.len() as u32;
    let choices = names
        .iter()
        .map(|n| format!("\"{}\"", n.value()))
        .collect::<Vec<_>>()
        .join(" | ");
    let takes = variants.iter().map(|v| {
        let pieces = v.takes.split(Option::is_none).map(|run| {
            let keys = run.iter().flatten().map(Ident::to_string);
            quote!(&[#(#keys),*][..])
        });
        let pieces: Vec<TokenStream> = pieces.collect();
        let mut joined = Vec::new();
        for (i, piece) in pieces.iter().enumerate() {
            if i > 0 {
                joined.push(quote!(parts));
            }
            joined.push(piece.clone());
        }
        quote!([#(#joined),*].concat())
    });
    let part = match (&attr.spec, &attr.file) {
        (Some(spec), Some(file)) => spec_part(ident, spec, file, &variants)?,
        (None, None) => quote!(),
        _ => {
            return Err(syn::Error::new_spanned(
                ident,
                "give both `spec` and `file`, or neither",
            ));
        }
    };
    let ident_text = ident.to_string();
    Ok(quote! {
        impl #ident {
            /// The names a scene file gives, `"a" | "b" | …`, as the `type` key's reference lists them.
            pub(crate) const CHOICES: &str = #choices;
            /// What messages call the type.
            pub(crate) const WHAT: &str = #what;
            /// The message when a table gives no `type`.
            pub(crate) const MISSING: &str = #missing;
            const NAMES: &[&str] = &[#(#names),*];

            /// The name a scene file gives this kind.
            pub(crate) fn name(self) -> &'static str {
                match self {
                    #(Self::#idents => #names,)*
                }
            }

            /// The keys this kind takes, with `parts` (the table's parts' names) where it takes them.
            pub(crate) fn takes(self, parts: &[&'static str]) -> ::std::vec::Vec<&'static str> {
                let _ = parts;
                match self {
                    #(Self::#idents => #takes,)*
                }
            }
        }

        impl ::serde::Serialize for #ident {
            fn serialize<S: ::serde::Serializer>(&self, serializer: S) -> ::core::result::Result<S::Ok, S::Error> {
                match self {
                    #(Self::#idents => serializer.serialize_unit_variant(#ident_text, #indices, #names),)*
                }
            }
        }

        impl<'de> ::serde::Deserialize<'de> for #ident {
            fn deserialize<D: ::serde::Deserializer<'de>>(deserializer: D) -> ::core::result::Result<Self, D::Error> {
                struct Visitor;
                impl<'de> ::serde::de::Visitor<'de> for Visitor {
                    type Value = #ident;

                    fn expecting(&self, f: &mut ::core::fmt::Formatter) -> ::core::fmt::Result {
                        f.write_str(#choices)
                    }

                    fn visit_str<E: ::serde::de::Error>(self, v: &str) -> ::core::result::Result<#ident, E> {
                        match v {
                            #(#names => Ok(#ident::#idents),)*
                            _ => {
                                let listed: ::std::vec::Vec<::std::string::String> = #ident::NAMES.iter().map(|n| ::std::format!("`{n}`")).collect();
                                Err(E::custom(::std::format!(
                                    "unknown variant `{v}`, expected one of {}{}",
                                    listed.join(", "),
                                    crate::named::nearest_hint(v, #ident::NAMES)
                                )))
                            }
                        }
                    }
                }
                deserializer.deserialize_str(Visitor)
            }
        }

        #part
    })
}

/// `"a", "b" or "c"`: the names as a message lists them.
fn listed(names: &[&LitStr]) -> String {
    let quoted: Vec<String> = names.iter().map(|n| format!("\"{}\"", n.value())).collect();
    match quoted.split_last() {
        Some((last, rest)) if !rest.is_empty() => format!("{} or {last}", rest.join(", ")),
        _ => quoted.concat(),
    }
}

/// `#[kind("name", takes(a, b, ..))]` on a unit variant.
fn variant(v: &syn::Variant) -> syn::Result<Variant> {
    if !matches!(v.fields, syn::Fields::Unit) {
        return Err(syn::Error::new_spanned(
            v,
            "a kind is a unit variant; its keys are listed in `takes(…)`",
        ));
    }
    let Some(attr) = v.attrs.iter().find(|a| a.path().is_ident("kind")) else {
        return Err(syn::Error::new_spanned(
            &v.ident,
            "give #[kind(\"name\", takes(…))]: the name a scene file gives this kind and the keys it takes",
        ));
    };
    attr.parse_args_with(|input: syn::parse::ParseStream| {
        let name: LitStr = input.parse()?;
        let mut takes = Vec::new();
        if input.parse::<Option<Token![,]>>()?.is_some() && !input.is_empty() {
            let word: Ident = input.parse()?;
            if word != "takes" {
                return Err(syn::Error::new(word.span(), "expected `takes(…)`"));
            }
            let content;
            syn::parenthesized!(content in input);
            while !content.is_empty() {
                if content.parse::<Option<Token![..]>>()?.is_some() {
                    takes.push(None);
                } else {
                    takes.push(Some(content.parse()?));
                }
                if content.parse::<Option<Token![,]>>()?.is_none() {
                    break;
                }
            }
        }
        Ok(Variant {
            ident: v.ident.clone(),
            name,
            takes,
        })
    })
}

/// The spec enum `spec` read from and written to `file`, each variant's fields the keys its kind takes.
fn spec_part(
    kind: &Ident,
    spec: &Type,
    file: &Type,
    variants: &[Variant],
) -> syn::Result<TokenStream> {
    let mut reads = Vec::new();
    let mut writes = Vec::new();
    for v in variants {
        let keys: Vec<&Ident> = v.takes.iter().flatten().collect();
        if keys.len() != v.takes.len() {
            return Err(syn::Error::new_spanned(
                &v.ident,
                "a spec's variant holds its keys: `..` (the table's parts) is for a kind without `spec`",
            ));
        }
        let names = keys.iter().map(|k| k.to_string());
        let ident = &v.ident;
        reads.push(quote!(#kind::#ident => #spec::#ident {
            #(#keys: crate::keys::required(at.clone().key(#names), file.#keys, &text)?,)*
        },));
        writes.push(quote!(#spec::#ident { #(#keys),* } => #file {
            kind: Some(#kind::#ident),
            #(#keys: Some(#keys),)*
            ..<#file as ::core::default::Default>::default()
        },));
    }
    Ok(quote! {
        impl crate::keys::Part for #spec {
            type File = #file;
            const TABLE: crate::keys::Table = <#file>::TABLE;

            fn read(file: &#file, at: &crate::keys::KeyPath) -> crate::keys::Checked<Self> {
                let (kind, text) = file.kind_given(at)?;
                Ok(match kind {
                    #(#reads)*
                })
            }

            fn write(&self) -> #file {
                match *self {
                    #(#writes)*
                }
            }
        }
    })
}
