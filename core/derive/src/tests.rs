//! Misuse of the derives is a compile error that says what to write, on the field or attribute at fault; a
//! well-formed declaration expands to the pieces the core names.

use proc_macro2::TokenStream;
use syn::{DeriveInput, parse_quote};

/// The error message of a derive that must fail. (Its span is the field's or attribute's by construction,
/// `syn::Error::new_spanned`; outside a compiler, proc-macro2's spans carry no position to compare.)
fn refused(derive: fn(&DeriveInput) -> syn::Result<TokenStream>, input: DeriveInput) -> String {
    derive(&input)
        .expect_err("the derive must refuse this input")
        .to_string()
}

#[test]
fn a_number_without_its_unit_is_refused_on_its_field() {
    let message = refused(
        crate::table::derive,
        parse_quote! {
            #[table(file = RodFile, header = "[rod]", about = "a rod", what = "a rod")]
            struct Rod {
                /// > 0
                length: f64,
            }
        },
    );
    assert!(
        message.contains("`length` is a number: give `#[key(unit"),
        "{message}"
    );
}

#[test]
fn a_required_key_needs_the_table_s_what() {
    let message = refused(
        crate::table::derive,
        parse_quote! {
            #[table(file = RodFile, header = "[rod]", about = "a rod")]
            struct Rod {
                /// > 0
                #[key(unit = "m")]
                length: f64,
            }
        },
    );
    assert!(
        message.contains("`length` is required: give the table's `what`"),
        "{message}"
    );
}

#[test]
fn a_default_the_reference_cannot_write_out_needs_shown() {
    let message = refused(
        crate::table::derive,
        parse_quote! {
            #[table(file = RodFile, header = "[rod]", about = "a rod")]
            struct Rod {
                /// the axes
                #[key(kind = "\"body\" | \"space\"", default = Axes::Body)]
                frame: Axes,
            }
        },
    );
    assert!(
        message.contains("`frame`: give `shown = \"…\"`"),
        "{message}"
    );
}

#[test]
fn a_key_without_a_doc_comment_is_refused() {
    let message = refused(
        crate::keys::derive,
        parse_quote! {
            #[keys(header = "[rod]", about = "a rod")]
            struct RodFile {
                #[key(unit = "m")]
                length: Option<f64>,
            }
        },
    );
    assert!(
        message.contains("`length` needs a doc comment"),
        "{message}"
    );
}

#[test]
fn a_misspelt_attribute_names_the_valid_ones() {
    let message = refused(
        crate::keys::derive,
        parse_quote! {
            struct RodFile {
                /// > 0
                #[key(units = "m")]
                length: Option<f64>,
            }
        },
    );
    assert!(
        message.contains("unknown `key` attribute; expected one of: rename, kind, unit"),
        "{message}"
    );
}

#[test]
fn a_kind_type_the_type_does_not_say_must_be_given() {
    let message = refused(
        crate::keys::derive,
        parse_quote! {
            struct RodFile {
                /// the axes
                frame: Option<Axes>,
            }
        },
    );
    assert!(
        message.contains("`frame`: give `#[key(kind = \"…\")]`"),
        "{message}"
    );
}

#[test]
fn a_default_on_a_file_form_belongs_on_the_spec() {
    let message = refused(
        crate::keys::derive,
        parse_quote! {
            struct RodFile {
                /// > 0
                #[key(unit = "m", default = 1.0)]
                length: Option<f64>,
            }
        },
    );
    assert!(
        message.contains("`default` belongs on the typed spec"),
        "{message}"
    );
}

#[test]
fn a_kind_variant_without_its_name_is_refused() {
    let message = refused(
        crate::kind::derive,
        parse_quote! {
            #[kind(what = "rod type", missing = "missing: a rod needs `type`")]
            enum RodKind {
                #[kind("short", takes(length))]
                Short,
                Long,
            }
        },
    );
    assert!(
        message.contains("give #[kind(\"name\", takes(…))]"),
        "{message}"
    );
}

#[test]
fn a_spec_declares_its_file_form_reading_writing_and_constructor() {
    let input: DeriveInput = parse_quote! {
        #[table(file = RodFile, header = "[rod]", about = "a rod", what = "a rod")]
        struct Rod {
            /// > 0
            #[key(unit = "m")]
            length: f64,
            /// where it sits
            #[key(position, default = [0.0; 3])]
            at: [f64; 3],
        }
    };
    let code = crate::table::derive(&input).unwrap().to_string();
    for piece in [
        "pub (crate) struct RodFile",
        "length : Option < f64 >",
        "at : Option < [f64 ; 3] >",
        "pub fn of (length : f64)",
        "impl crate :: keys :: Part for Rod",
        "crate :: keys :: required (at . clone () . key (\"length\")",
        "default : \"[0, 0, 0]\"",
        "Exactly < { 3 } >",
    ] {
        assert!(code.contains(piece), "`{piece}` not in {code}");
    }
}

#[test]
fn a_kind_splices_the_table_s_parts_where_its_list_says() {
    let input: DeriveInput = parse_quote! {
        #[kind(what = "motion type", missing = "missing")]
        enum MotionKind {
            #[kind("fixed_axis", takes(axis, .., accel))]
            FixedAxis,
        }
    };
    let code = crate::kind::derive(&input).unwrap().to_string();
    assert!(
        code.contains("[& [\"axis\"] [..] , parts , & [\"accel\"] [..]] . concat ()"),
        "{code}"
    );
    assert!(
        code.contains("CHOICES : & str = \"\\\"fixed_axis\\\"\""),
        "{code}"
    );
}

#[test]
fn a_kind_says_what_is_missing_in_the_usual_words_from_needs() {
    let input: DeriveInput = parse_quote! {
        #[kind(what = "rod type", needs = "a rod")]
        enum RodKind {
            #[kind("short", takes(length))]
            Short,
            #[kind("long")]
            Long,
            #[kind("bent", takes())]
            Bent,
        }
    };
    let code = crate::kind::derive(&input).unwrap().to_string();
    let message = "missing: a rod needs `type` = \\\"short\\\", \\\"long\\\" or \\\"bent\\\"";
    assert!(code.contains(message), "`{message}` not in {code}");
    let neither = refused(
        crate::kind::derive,
        parse_quote! {
            #[kind(what = "rod type")]
            enum RodKind {
                #[kind("short")]
                Short,
            }
        },
    );
    assert!(neither.contains("or `needs"), "{neither}");
}
