//! What a field's type says of its key: optional, a list, an array of exactly N numbers, a number.

use syn::{Expr, GenericArgument, PathArguments, Type};

/// `T` of `Wrapper<T>` when `ty` is `Wrapper<T>` (`Option`, `Vec`), by the last segment of its path.
pub fn inner<'a>(ty: &'a Type, wrapper: &str) -> Option<&'a Type> {
    let Type::Path(path) = ty else { return None };
    let last = path.path.segments.last()?;
    if last.ident != wrapper {
        return None;
    }
    let PathArguments::AngleBracketed(args) = &last.arguments else {
        return None;
    };
    match args.args.first()? {
        GenericArgument::Type(t) if args.args.len() == 1 => Some(t),
        _ => None,
    }
}

/// Whether `ty` is the plain type named `name` (`f64`, `String`, `PathBuf`…), by its path's last segment.
pub fn is_named(ty: &Type, name: &str) -> bool {
    matches!(ty, Type::Path(p) if p.qself.is_none()
        && p.path.segments.last().is_some_and(|s| s.ident == name && s.arguments.is_none()))
}

/// N when `ty` is `[f64; N]`.
pub fn f64_array_len(ty: &Type) -> Option<&Expr> {
    match ty {
        Type::Array(array) if is_named(&array.elem, "f64") => Some(&array.len),
        _ => None,
    }
}

/// Whether a value of `ty` is a number or numbers, whose key must give its unit.
pub fn is_numeric(ty: &Type) -> bool {
    is_named(ty, "f64") || f64_array_len(ty).is_some()
}

/// The reference's kind of a value of `ty`, when the type says it: `number`, `[x, y, z]`, `string`, `bool`, `path`.
pub fn kind_of(ty: &Type) -> Option<String> {
    if let Some(len) = f64_array_len(ty) {
        let three = matches!(len, Expr::Lit(syn::ExprLit { lit: syn::Lit::Int(n), .. }) if n.base10_digits() == "3");
        return three.then(|| "[x, y, z]".to_string());
    }
    [
        ("f64", "number"),
        ("String", "string"),
        ("bool", "bool"),
        ("PathBuf", "path"),
    ]
    .into_iter()
    .find(|(name, _)| is_named(ty, name))
    .map(|(_, kind)| kind.to_string())
}

#[cfg(test)]
mod tests {
    use super::*;
    use syn::parse_quote;

    #[test]
    fn wrappers_arrays_and_kinds_are_read_from_the_type() {
        let option: Type = parse_quote!(Option<[f64; 3]>);
        let array = inner(&option, "Option").unwrap();
        assert!(f64_array_len(array).is_some());
        assert_eq!(kind_of(array).as_deref(), Some("[x, y, z]"));
        assert!(inner(&option, "Vec").is_none());
        let path: Type = parse_quote!(std::path::PathBuf);
        assert_eq!(kind_of(&path).as_deref(), Some("path"));
        let two: Type = parse_quote!([f64; 2]);
        assert!(is_numeric(&two) && kind_of(&two).is_none());
        let other: Type = parse_quote!(Axes);
        assert!(!is_numeric(&other) && kind_of(&other).is_none());
    }
}
