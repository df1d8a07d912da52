//! The attributes the derives read: `#[key(…)]` on a field, the doc comment that is its reference text, and the
//! either/or pairs of a table.

use syn::punctuated::Punctuated;
use syn::spanned::Spanned;
use syn::{Attribute, Expr, Field, Ident, LitStr, Path, Token, Type};

/// `#[key(…)]` on a field:
/// - `rename = "type"`: the name in the file, when not the field's;
/// - `kind = EXPR`, `unit = EXPR`, `origin = EXPR` (the reference's columns; `kind` follows from the type for a
///   number, `[x, y, z]`, a string, a bool or a path; `unit` is required for numbers, else `–`);
/// - `shown = EXPR`: the default as the reference writes it (else `none` for an optional key, `required`, or the
///   typed `default` written out when it is a number, a bool or an array of numbers);
/// - `default = EXPR` (typed spec only): the value when the key is absent;
/// - `position`: a position in body axes (m) from the reference origin;
/// - `table`: the key holds a table (its type's `TABLE`; in a typed spec, the type is a `keys::Part`);
/// - `part = SPEC` (file form only): a capability's table that attaches to the validated value;
/// - `kinds`: the table's `type`, an enum with `#[derive(Kind)]`;
/// - `flatten` (file form) or `flatten = KEYS` (typed spec): keys of this table read together as one group.
#[derive(Default)]
pub struct KeyAttr {
    pub rename: Option<LitStr>,
    pub kind: Option<Expr>,
    pub unit: Option<Expr>,
    pub origin: Option<Expr>,
    pub shown: Option<Expr>,
    pub default: Option<Expr>,
    pub position: bool,
    pub table: bool,
    pub part: Option<Type>,
    pub kinds: bool,
    pub flatten: Option<Option<Type>>,
}

impl KeyAttr {
    /// The field's `#[key(…)]` attributes, merged.
    pub fn of(field: &Field) -> syn::Result<Self> {
        let mut attr = KeyAttr::default();
        for a in field.attrs.iter().filter(|a| a.path().is_ident("key")) {
            a.parse_nested_meta(|meta| {
                let name = meta.path.get_ident().map(Ident::to_string);
                match name.as_deref() {
                    Some("rename") => attr.rename = Some(meta.value()?.parse()?),
                    Some("kind") => attr.kind = Some(meta.value()?.parse()?),
                    Some("unit") => attr.unit = Some(meta.value()?.parse()?),
                    Some("origin") => attr.origin = Some(meta.value()?.parse()?),
                    Some("shown") => attr.shown = Some(meta.value()?.parse()?),
                    Some("default") => attr.default = Some(meta.value()?.parse()?),
                    Some("part") => attr.part = Some(meta.value()?.parse()?),
                    Some("position") => attr.position = true,
                    Some("table") => attr.table = true,
                    Some("kinds") => attr.kinds = true,
                    Some("flatten") if meta.input.peek(Token![=]) => {
                        attr.flatten = Some(Some(meta.value()?.parse()?))
                    }
                    Some("flatten") => attr.flatten = Some(None),
                    _ => {
                        return Err(meta.error(
                            "unknown `key` attribute; expected one of: rename, kind, unit, origin, shown, default, \
                             position, table, part, kinds, flatten",
                        ));
                    }
                }
                Ok(())
            })?;
        }
        Ok(attr)
    }
}

/// The doc comment of an item, its lines trimmed and joined by spaces: a key's reference text.
pub fn doc_text(attrs: &[Attribute]) -> Option<String> {
    let lines: Vec<String> = attrs
        .iter()
        .filter(|a| a.path().is_ident("doc"))
        .filter_map(|a| match &a.meta {
            syn::Meta::NameValue(nv) => match &nv.value {
                Expr::Lit(syn::ExprLit {
                    lit: syn::Lit::Str(s),
                    ..
                }) => Some(s.value().trim().to_string()),
                _ => None,
            },
            _ => None,
        })
        .collect();
    let text = lines.join(" ").trim().to_string();
    (!text.is_empty()).then_some(text)
}

/// `either(a, b, …, "message")` or `either(a, b, "message", T::VA, T::VB)`: keys that exclude each other, the later
/// of two given named by the message; with the variants, a pair also read and written as the choice `T`.
pub struct Either {
    pub keys: Vec<Ident>,
    pub message: LitStr,
    pub choice: Option<(Path, Path)>,
}

impl Either {
    /// The keys from the content of `either(…)`.
    pub fn parse(input: syn::parse::ParseStream) -> syn::Result<Self> {
        let content;
        syn::parenthesized!(content in input);
        let items = Punctuated::<Expr, Token![,]>::parse_terminated(&content)?;
        let span = items.span();
        let mut keys = Vec::new();
        let mut rest = items.into_iter().peekable();
        while let Some(Expr::Path(p)) = rest.peek() {
            let Some(ident) = p.path.get_ident().cloned() else {
                break;
            };
            keys.push(ident);
            rest.next();
        }
        let message = match rest.next() {
            Some(Expr::Lit(syn::ExprLit {
                lit: syn::Lit::Str(s),
                ..
            })) if keys.len() >= 2 => s,
            _ => {
                return Err(syn::Error::new(
                    span,
                    "either(a, b, …, \"message\"): two keys or more, then the message",
                ));
            }
        };
        let path = |e: Option<Expr>| match e {
            Some(Expr::Path(p)) => Some(p.path),
            _ => None,
        };
        let choice = match (path(rest.next()), path(rest.next())) {
            (Some(va), Some(vb)) if keys.len() == 2 => Some((va, vb)),
            (None, None) => None,
            _ => {
                return Err(syn::Error::new(
                    span,
                    "either(a, b, \"message\", T::A, T::B): a pair's two variants, or none",
                ));
            }
        };
        Ok(Either {
            keys,
            message,
            choice,
        })
    }
}
