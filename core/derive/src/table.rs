//! `#[derive(Table)]`: a table's typed spec and, from its fields, its file form (a struct with `Keys`), both
//! conversions (`keys::Part`), `S::of(…)` (the values the table must give, every other key at its default) and the
//! files the spec names taken relative to a directory.
//!
//! A field of the spec is, by its type and `#[key(…)]`: `Option<T>` (the key as given); `T` with `default = E`
//! (`E` when absent); `T` without a default (required: the table's `what` names it in the message); with `table`,
//! `P`, `Option<P>` or `Vec<P>` of a `keys::Part` (its own table, required, optional or an array of them); with
//! `flatten = K`, a group read from the keys `K` declares (`keys::Group<K>`).

use proc_macro2::TokenStream;
use quote::quote;
use syn::{Data, DeriveInput, Expr, Fields, Ident, Type};

use crate::attrs::KeyAttr;
use crate::model::{FileField, FileForm, KeyDoc, Store, store_of};
use crate::types;

/// `#[table(…)]` on the spec.
#[derive(Default)]
struct TableAttr {
    file: Option<Ident>,
    header: Option<Expr>,
    about: Option<Expr>,
    what: Option<Expr>,
    derives: Vec<syn::Path>,
    eithers: Vec<crate::attrs::Either>,
}

/// One spec field's code: its file field, its reading, writing and files; its parameter of `of` when required.
struct FieldCode {
    file: FileField,
    read: TokenStream,
    write: TokenStream,
    files: TokenStream,
    /// `(parameter, None)` for a value `of` takes, `(field, Some(init))` for one it sets itself.
    init: (TokenStream, Option<TokenStream>),
}

pub fn derive(input: &DeriveInput) -> syn::Result<TokenStream> {
    let mut attr = table_attr(input)?;
    let (Some(file), Some(header), Some(about)) = (&attr.file, &attr.header, &attr.about) else {
        return Err(syn::Error::new_spanned(
            &input.ident,
            "give #[table(file = NameFile, header = \"[name]\", about = \"…\")]",
        ));
    };
    let (Data::Struct(data), spec) = (&input.data, &input.ident) else {
        return Err(syn::Error::new_spanned(
            &input.ident,
            "#[derive(Table)] is for a struct of named fields",
        ));
    };
    let Fields::Named(named) = &data.fields else {
        return Err(syn::Error::new_spanned(
            spec,
            "#[derive(Table)] is for a struct of named fields",
        ));
    };
    let codes = (named.named.iter())
        .map(|f| field_code(f, attr.what.as_ref()))
        .collect::<syn::Result<Vec<_>>>()?;
    let form = FileForm {
        ident: file.clone(),
        table: Some((header.clone(), about.clone())),
        fields: Vec::new(),
        eithers: std::mem::take(&mut attr.eithers),
        parts: None,
        own_spec: false,
    };
    let mut form = form;
    let mut file_fields = Vec::new();
    let (mut reads, mut writes, mut files, mut params, mut inits) =
        (Vec::new(), Vec::new(), Vec::new(), Vec::new(), Vec::new());
    for code in codes {
        let (ident, ty) = (&code.file.ident, &code.file.ty);
        let doc = code.file.key.as_ref().map(|k| k.doc.clone());
        let doc = doc.map(|d| quote!(#[doc = #d]));
        file_fields.push(quote!(#doc pub(crate) #ident: #ty,));
        reads.push(code.read);
        writes.push(code.write);
        files.push(code.files);
        match code.init {
            (param, None) => {
                params.push(param);
                inits.push(quote!(#ident,));
            }
            (_, Some(init)) => inits.push(quote!(#ident: #init,)),
        }
        form.fields.push(code.file);
    }
    let keys = crate::keys::generate(&form)?;
    let derives = &attr.derives;
    let doc = format!("The file form of [`{spec}`]: each key as the file gives it.");
    Ok(quote! {
        #[doc = #doc]
        #[derive(Debug, Clone, Default, PartialEq #(, #derives)*)]
        pub(crate) struct #file {
            #(#file_fields)*
        }

        #keys

        impl #spec {
            /// The spec of the values a table must give (each key the reading requires, each group of keys), every
            /// other key at its default.
            #[allow(dead_code)]
            pub fn of(#(#params),*) -> Self {
                Self { #(#inits)* }
            }
        }

        impl crate::keys::Part for #spec {
            type File = #file;
            const TABLE: crate::keys::Table = #file::TABLE;

            fn read(file: &#file, at: &crate::keys::KeyPath) -> crate::keys::Checked<Self> {
                crate::keys::Keys::exclusive(file, at)?;
                Ok(Self { #(#reads)* })
            }

            #[allow(clippy::field_reassign_with_default)]
            fn write(&self) -> #file {
                let mut file = <#file as ::core::default::Default>::default();
                #(#writes)*
                file
            }

            fn take_files_in(&mut self, dir: &::std::path::Path) {
                let _ = dir;
                #(#files)*
            }
        }
    })
}

fn table_attr(input: &DeriveInput) -> syn::Result<TableAttr> {
    let mut attr = TableAttr::default();
    for a in input.attrs.iter().filter(|a| a.path().is_ident("table")) {
        a.parse_nested_meta(|meta| {
            if meta.path.is_ident("file") {
                attr.file = Some(meta.value()?.parse()?);
            } else if meta.path.is_ident("header") {
                attr.header = Some(meta.value()?.parse()?);
            } else if meta.path.is_ident("about") {
                attr.about = Some(meta.value()?.parse()?);
            } else if meta.path.is_ident("what") {
                attr.what = Some(meta.value()?.parse()?);
            } else if meta.path.is_ident("either") {
                attr.eithers.push(crate::attrs::Either::parse(meta.input)?);
            } else if meta.path.is_ident("derive") {
                meta.parse_nested_meta(|d| {
                    attr.derives.push(d.path);
                    Ok(())
                })?;
            } else {
                return Err(meta.error(
                    "unknown `table` attribute; expected file, header, about, what, either or derive",
                ));
            }
            Ok(())
        })?;
    }
    Ok(attr)
}

/// A spec field's file field and code, by its type and attributes.
fn field_code(field: &syn::Field, what: Option<&Expr>) -> syn::Result<FieldCode> {
    let attr = KeyAttr::of(field)?;
    let ident = field.ident.clone().expect("named fields");
    let ty = &field.ty;
    if attr.part.is_some() || attr.kinds {
        return Err(syn::Error::new_spanned(
            &ident,
            "`part` and `kinds` belong on a file form (#[derive(Keys)]); a typed spec holds its table with `table`",
        ));
    }
    if let Some(keys) = &attr.flatten {
        let Some(keys) = keys else {
            return Err(syn::Error::new_spanned(
                &ident,
                "a typed spec's group names the keys it is read from: `flatten = GroupKeys`",
            ));
        };
        return Ok(group(ident, ty, keys, attr.default.as_ref()));
    }
    let name = attr
        .rename
        .as_ref()
        .map_or_else(|| ident.to_string(), |r| r.value());
    if attr.table {
        return table_field(field, &attr, ident, name);
    }
    let (store, value) = store_of(ty);
    let file_ty: Type = match &store {
        Store::Optional | Store::Exactly(_) => ty.clone(),
        _ => syn::parse_quote!(Option<#ty>),
    };
    let (store, _) = store_of(&file_ty);
    let value = if matches!(store_of(ty).0, Store::Optional | Store::Exactly(_)) {
        value
    } else {
        ty
    };
    let (read, init, shown) = if types::inner(ty, "Option").is_some() {
        (
            quote!(::core::clone::Clone::clone(&file.#ident)),
            (quote!(), Some(quote!(::core::option::Option::None))),
            None,
        )
    } else if let Some(default) = &attr.default {
        let shown = shown_of(default).map(|s| quote!(#s));
        if shown.is_none() && attr.shown.is_none() {
            return Err(syn::Error::new_spanned(
                default,
                format!(
                    "`{name}`: give `shown = \"…\"`, the default as the reference writes it (only numbers, bools \
                     and arrays of numbers are written out)"
                ),
            ));
        }
        (
            quote!(::core::clone::Clone::clone(&file.#ident).unwrap_or(#default)),
            (quote!(), Some(quote!(#default))),
            shown,
        )
    } else {
        let Some(what) = what else {
            return Err(syn::Error::new_spanned(
                &ident,
                format!(
                    "`{name}` is required: give the table's `what` (#[table(what = \"a thing\")]), which its \
                     message names, or a `default`"
                ),
            ));
        };
        (
            quote!(crate::keys::required(at.clone().key(#name), ::core::clone::Clone::clone(&file.#ident), #what)?),
            (quote!(#ident: #ty), None),
            Some(quote!("required")),
        )
    };
    let key = KeyDoc::new(field, &attr, value, shown)?;
    let write = if types::inner(ty, "Option").is_some() {
        quote!(file.#ident = ::core::clone::Clone::clone(&self.#ident);)
    } else {
        quote!(file.#ident = Some(::core::clone::Clone::clone(&self.#ident));)
    };
    Ok(FieldCode {
        file: FileField::key(ident.clone(), file_ty, store, key),
        read: quote!(#ident: #read,),
        write,
        files: quote!(),
        init,
    })
}

/// `flatten = K`: the group's keys spliced into the file form; the field read from them as a `keys::Group<K>`;
/// with `default = E`, `S::of(…)` sets it to E instead of taking it.
fn group(ident: Ident, ty: &Type, keys: &Type, default: Option<&Expr>) -> FieldCode {
    FieldCode {
        file: FileField {
            ident: ident.clone(),
            ty: keys.clone(),
            store: Store::Flatten,
            key: None,
            part: None,
            kinds: None,
        },
        read: quote!(#ident: <#ty as crate::keys::Group<#keys>>::read(&file.#ident, at)?,),
        write: quote!(crate::keys::Group::<#keys>::write(&self.#ident, &mut file.#ident);),
        files: quote!(crate::keys::Group::<#keys>::take_files_in(&mut self.#ident, dir);),
        init: match default {
            Some(default) => (quote!(), Some(quote!(#default))),
            None => (quote!(#ident: #ty), None),
        },
    }
}

/// `table`: a `keys::Part`'s own table, required (`P`), optional (`Option<P>`) or an array of them (`Vec<P>`).
fn table_field(
    field: &syn::Field,
    attr: &KeyAttr,
    ident: Ident,
    name: String,
) -> syn::Result<FieldCode> {
    let ty = &field.ty;
    let (store, part) = store_of(ty);
    let file_of = quote!(<#part as crate::keys::Part>::File);
    let at = quote!(&at.clone().key(#name));
    let (file_ty, kind, shown, read, write, files, init) = match store {
        Store::Optional => (
            quote!(Option<#file_of>),
            "table",
            None,
            quote!((file.#ident.as_ref()).map(|f| <#part as crate::keys::Part>::read(f, #at)).transpose()?),
            quote!(file.#ident = self.#ident.as_ref().map(crate::keys::Part::write);),
            quote!(if let Some(part) = &mut self.#ident { crate::keys::Part::take_files_in(part, dir); }),
            (quote!(), Some(quote!(None))),
        ),
        Store::List => (
            quote!(Vec<#file_of>),
            "array of tables",
            None,
            quote!((file.#ident.iter().enumerate())
                .map(|(i, f)| <#part as crate::keys::Part>::read(f, &at.clone().key(#name).index(i)))
                .collect::<crate::keys::Checked<_>>()?),
            quote!(file.#ident = self.#ident.iter().map(crate::keys::Part::write).collect();),
            quote!(for part in &mut self.#ident { crate::keys::Part::take_files_in(part, dir); }),
            (quote!(), Some(quote!(::std::vec::Vec::new()))),
        ),
        _ => (
            file_of.clone(),
            "table",
            Some(quote!("required")),
            quote!(<#ty as crate::keys::Part>::read(&file.#ident, #at)?),
            quote!(file.#ident = crate::keys::Part::write(&self.#ident);),
            quote!(crate::keys::Part::take_files_in(&mut self.#ident, dir);),
            (quote!(#ident: #ty), None),
        ),
    };
    let file_ty: Type = syn::parse2(file_ty)?;
    let (store, _) = store_of(&file_ty);
    let mut key = KeyDoc::new(field, &with_kind(attr, kind), part, shown)?;
    key.holds = Some(quote!(<#part as crate::keys::Part>::TABLE));
    Ok(FieldCode {
        file: FileField::key(ident.clone(), file_ty, store, key),
        read: quote!(#ident: #read,),
        write,
        files,
        init,
    })
}

/// The attributes with `kind` set when they do not give one.
fn with_kind(attr: &KeyAttr, kind: &str) -> KeyAttr {
    KeyAttr {
        rename: attr.rename.clone(),
        kind: attr.kind.clone().or_else(|| Some(syn::parse_quote!(#kind))),
        unit: attr.unit.clone(),
        origin: attr.origin.clone(),
        shown: attr.shown.clone(),
        default: None,
        position: false,
        table: true,
        part: None,
        kinds: false,
        flatten: None,
    }
}

/// The default as the reference writes it, when it is a number, a bool or an array of numbers: `0.0` → `0`,
/// `[0.0; 3]` → `[0, 0, 0]`.
fn shown_of(default: &Expr) -> Option<String> {
    match default {
        Expr::Lit(lit) => match &lit.lit {
            syn::Lit::Float(f) => f.base10_parse::<f64>().ok().map(|v| format!("{v}")),
            syn::Lit::Int(i) => Some(i.base10_digits().to_string()),
            syn::Lit::Bool(b) => Some(b.value.to_string()),
            _ => None,
        },
        Expr::Unary(syn::ExprUnary {
            op: syn::UnOp::Neg(_),
            expr,
            ..
        }) => shown_of(expr).map(|s| format!("-{s}")),
        Expr::Repeat(r) => {
            let item = shown_of(&r.expr)?;
            let Expr::Lit(syn::ExprLit {
                lit: syn::Lit::Int(n),
                ..
            }) = &*r.len
            else {
                return None;
            };
            let n: usize = n.base10_parse().ok()?;
            Some(format!("[{}]", vec![item; n].join(", ")))
        }
        Expr::Array(a) => {
            let items: Option<Vec<String>> = a.elems.iter().map(shown_of).collect();
            Some(format!("[{}]", items?.join(", ")))
        }
        _ => None,
    }
}
