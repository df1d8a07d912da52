//! A table's attachable parts (`#[key(part = SPEC)]` fields, `#[keys(parts = NAME)]`): the typed struct of them,
//! read, written, refused where the table takes none, and attached to the validated value in order.

use proc_macro2::TokenStream;
use quote::quote;

use crate::model::FileForm;

/// The parts' struct and its methods, when the form declares one.
pub fn generate(form: &FileForm) -> TokenStream {
    let Some(parts) = &form.parts else {
        return quote!();
    };
    let file = &form.ident;
    let fields: Vec<_> = form
        .fields
        .iter()
        .filter_map(|f| Some((&f.ident, f.part.as_ref()?, f.key.as_ref()?)))
        .collect();
    let idents: Vec<_> = fields.iter().map(|(i, _, _)| *i).collect();
    let specs: Vec<_> = fields.iter().map(|(_, s, _)| *s).collect();
    let names: Vec<_> = fields.iter().map(|(_, _, k)| &k.name).collect();
    let docs: Vec<_> = fields.iter().map(|(_, _, k)| &k.doc).collect();
    quote! {
        /// The capabilities with a table of their own in this table that modify the validated value (each a
        /// `keys::Part` with `keys::Attach`, registered by its `#[key(part = …)]` field).
        #[derive(Debug, Clone, Copy, Default, PartialEq)]
        pub struct #parts {
            #(#[doc = #docs] pub #idents: Option<#specs>,)*
        }

        impl #parts {
            /// The parts' names: the keys of the enclosing table that hold them.
            pub(crate) const NAMES: &[&str] = &[#(#names),*];

            /// The parts the file gives, read (each one's table at `at`.NAME).
            pub(crate) fn read(file: &#file, at: &crate::keys::KeyPath) -> crate::keys::Checked<Self> {
                Ok(Self {
                    #(#idents: (file.#idents.as_ref())
                        .map(|f| <#specs as crate::keys::Part>::read(f, &at.clone().key(#names)))
                        .transpose()?,)*
                })
            }

            /// The parts written into `file`.
            pub(crate) fn write(&self, file: &mut #file) {
                #(file.#idents = self.#idents.as_ref().map(crate::keys::Part::write);)*
            }

            /// Parts the file gives where the enclosing table takes none: each part's own message, if it has one.
            pub(crate) fn refuse_unattached(file: &#file, at: &crate::keys::KeyPath) -> crate::keys::Checked<()> {
                #(if let Some(f) = &file.#idents {
                    <#specs as crate::keys::Part>::refuse_unattached(f, &at.clone().key(#names))?;
                })*
                Ok(())
            }

            /// `to` with every part given attached, in the declaration's order.
            pub(crate) fn attach<T>(&self, to: T, at: &crate::keys::KeyPath) -> crate::keys::Checked<T>
            where
                #(#specs: crate::keys::Attach<T>,)*
            {
                let mut to = to;
                #(if let Some(p) = &self.#idents {
                    to = crate::keys::Attach::attach(p, to, &at.clone().key(#names))?;
                })*
                Ok(to)
            }
        }
    }
}
