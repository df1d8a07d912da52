//! A table of the scene file, declared once ([`file_table!`]): each key's field, its storage and what the reference
//! says of it. From that one declaration come the flat serde struct (every optional key an `Option`, unknown keys
//! refused), its [`Table`] for the book's key reference, and `given()`, the keys a file gives — which the "takes no
//! `X`" and "either X or Y" checks read instead of listing the keys again.

use serde::de::Error as _;
use serde::{Deserialize, Deserializer};

/// One key of a table.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Key {
    /// The key as written in the file.
    pub name: &'static str,
    /// What the value is: `number`, `[x, y, z]`, a string from a list, a table…
    pub kind: &'static str,
    /// SI unit (`1` dimensionless, `–` none).
    pub unit: &'static str,
    /// The value when the key is absent (`required` when it may not be).
    pub default: &'static str,
    /// For a position: the point it is measured from and its axes; else empty.
    pub origin: &'static str,
    /// What it means, its bounds.
    pub doc: &'static str,
    /// The table the key holds (a `[section]`, an inline table or an array of tables), listed after its table in
    /// the reference.
    pub table: Option<&'static Table>,
}

/// One table of a scene file and its keys.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Table {
    /// As written in the file (`[body]`, `[[effect]]`; the top level is empty).
    pub header: &'static str,
    /// What the table is.
    pub about: &'static str,
    /// Its keys, in the order of the file form.
    pub keys: &'static [Key],
    /// The tables of its parts (`part` keys, `keys::Part`), each listed after it in the reference.
    pub parts: &'static [Table],
}

/// A key's description without its name (the declaration names it): kind, unit, default, origin, meaning.
pub(crate) const fn key(
    kind: &'static str,
    unit: &'static str,
    default: &'static str,
    origin: &'static str,
    doc: &'static str,
) -> Key {
    Key {
        name: "",
        kind,
        unit,
        default,
        origin,
        doc,
        table: None,
    }
}

impl Key {
    /// The same key, named.
    pub(crate) const fn named(self, name: &'static str) -> Key {
        Key { name, ..self }
    }

    /// The same key, which the reading requires: its declared default must say `required` (checked when the table
    /// is compiled).
    pub(crate) const fn required_by_reading(self) -> Key {
        let (given, want) = (self.default.as_bytes(), b"required");
        let mut same = given.len() == want.len();
        let mut i = 0;
        while same && i < want.len() {
            same = given[i] == want[i];
            i += 1;
        }
        assert!(
            same,
            "a key the reading requires must give `required` as its default"
        );
        self
    }

    /// The same key, holding the table `table`: the one line that registers a table in the one holding it.
    pub(crate) const fn holding(self, table: &'static Table) -> Key {
        Key {
            table: Some(table),
            ..self
        }
    }
}

/// Where a position in body axes is measured from.
const FROM_REFERENCE: &str =
    "the reference origin (the shape's center, or the point `inertia` is about), body axes";

/// A position in body axes (m), measured from the reference origin: default, meaning.
pub(crate) const fn position(default: &'static str, doc: &'static str) -> Key {
    key("[x, y, z]", "m", default, FROM_REFERENCE, doc)
}

/// The `profile` of a time profile (`constant`, `sine` or `step`), and what it means where it stands.
pub(crate) const fn profile(doc: &'static str) -> Key {
    key(
        "\"constant\" | \"sine\" | \"step\"",
        "–",
        "\"constant\"",
        "",
        doc,
    )
}

/// An array of exactly `N` numbers. (serde's `[f64; N]` ignores extra elements when TOML drives it, so
/// `omega = [1, 2, 3, 4]` would pass silently.)
pub(crate) fn exactly_n<'de, D: Deserializer<'de>, const N: usize>(
    deserializer: D,
) -> Result<Option<[f64; N]>, D::Error> {
    let items = Vec::<f64>::deserialize(deserializer)?;
    <[f64; N]>::try_from(items.as_slice())
        .map(Some)
        .map_err(|_| {
            D::Error::invalid_length(items.len(), &format!("an array of {N} numbers").as_str())
        })
}

/// Declares a table of the scene file once:
///
/// ```text
/// file_table! {
///     /// The struct's doc.
///     pub(super) struct MotionFile(pub(super)) "[motion]", "what the table is" {
///         arr axis: [f64; 3] = key("[x, y, z]", "–", "required", "", "body axes");
///         opt profile: ProfileKind = profile("…");
///         @sine;
///         /// `carrier`: …
///         part carrier: CarrierSpec = key("inline table", "–", "none", "", "…");
///     }
///     either { axis, tilt_deg => AxisDirection::{Body, TiltDeg}: "…"; }
///     parts { #[derive(Debug, Clone, Copy, Default, PartialEq)] pub struct AxisParts; }
///     kinds {
///         /// The `type` of a motion.
///         pub enum MotionKind("motion type", "missing: the motion needs `type` = …") {
///             /// `free`.
///             Free = "free": [];
///             /// `fixed_axis`.
///             FixedAxis = "fixed_axis": [axis, tilt_deg, rate, ..parts, accel];
///         }
///     }
/// }
/// ```
///
/// Each key is `STORAGE FIELD [as "NAME"]: TYPE = KEY;` — `opt` (an `Option<TYPE>`, left out when absent), `arr`
/// (an `Option` of an array of exactly N numbers), `req` (a plain `TYPE` serde requires), `list` (a `Vec<TYPE>`,
/// an array of tables), `part` (a capability's inline table: `TYPE` is its typed spec, a [`Part`](super::Part)),
/// `one`, `maybe`, `each` (a [`Part`](super::Part)'s table: required, optional, an array of them; the key holds
/// its table), `opt(required)`/`arr(required)` (a value the typed spec requires; `one` and these must declare
/// `required` as their default, a compile-time check), `opt(DEFAULT)`/`arr(DEFAULT)` (a value with its default) — or a splice of shared keys: `@sine` (`freq_hz`, `phase_deg`), `@step` (`t_on`, `t_off`).
/// `group FIELD: TYPE { keys }` declares keys that the typed spec reads together as one [`Group`](super::Group).
/// It makes the struct (`Debug, Clone, Default, PartialEq`, serde, unknown keys refused), its `TABLE` ([`Table`],
/// with its parts' tables), and `given()`: the names of the keys the file gives, in order. An optional
/// `either { A, B: "message"; … }` after the keys declares keys that exclude each other: `exclusive()` refuses
/// both, naming `B`; `A, B => T::{VA, VB}: "message";` also reads the pair as the typed choice `T` (`VA(a)` or
/// `VB(b)`) and writes it back ([`Either`](super::Either)). An optional `parts { … struct NAME; }` makes the
/// typed struct of the `part` keys (a field `Option<SPEC>` each) with `NAMES`, `read` and `write` (the file form
/// and back), `refuse_unattached` and `attach` (each part [`Attach`](super::Attach)ed to the validated value, in
/// order): a capability with its own table is registered by its one `part` line. An optional
/// `spec { … struct NAME; }` makes the table's typed spec and its [`Part`](super::Part) impl: a `pub` field per key
/// (of the key's type; a `one`/`maybe`/`each` key's typed `Part`, read at `KEY`/`KEY[i]`; a group's type), read in
/// the declaration's order after `exclusive()`, written back, its parts' files taken relative to a directory —
/// and `S::of(…)`, the spec of the values a table must give (in order), every other key at its default, so that a
/// key added to the table needs no constructor changed. An optional `kinds { … enum KIND("WHAT", "MISSING") { … } }`
/// declares the table's `type` (its field `kind`) once: each variant, the name a file gives it and the keys it
/// takes (`..parts`: the table's parts). It makes the enum (serde by those names), `KIND::CHOICES` (`"a" | "b"`, for
/// the `type` key's reference), `name()`, and the table's `kind_given()`: the `type` (else `MISSING`, at `type`)
/// with every key given checked against the ones it takes (`WHAT = "NAME" takes no …`). `enum KIND(…) for SPEC`
/// also reads and writes the enum `SPEC` whose variant of each kind holds exactly the keys it takes, each required
/// (`body.shape`'s `ShapeSpec`).
macro_rules! file_table {
    (@munch $head:tt [$($done:tt)*] $parts:tt $specs:tt) => { file_table!(@emit $head $parts $specs $($done)*); };
    (@munch $head:tt $done:tt $parts:tt $specs:tt @sine; $($rest:tt)*) => {
        file_table!(@munch $head $done $parts $specs
            opt freq_hz: f64 = $crate::keys::key("number", "Hz", "required for `sine`", "", "≥ 0");
            opt phase_deg: f64 = $crate::keys::key("number", "deg", "0", "", "`sine` only");
            $($rest)*);
    };
    (@munch $head:tt $done:tt $parts:tt $specs:tt @step; $($rest:tt)*) => {
        file_table!(@munch $head $done $parts $specs
            opt t_on: f64 = $crate::keys::key("number", "s", "0", "", "`step` only");
            opt t_off: f64 = $crate::keys::key("number", "s", "never", "", "`step` only; > t_on");
            $($rest)*);
    };
    (@munch $head:tt $done:tt $parts:tt [$($specs:tt)*] @end; $($rest:tt)*) => {
        file_table!(@munch $head $done $parts [$($specs)* (end)] $($rest)*);
    };
    (@munch $head:tt $done:tt $parts:tt [$($specs:tt)*] $(#[$m:meta])* group $field:ident: $ty:ty { $($inner:tt)* } $($rest:tt)*) => {
        file_table!(@munch $head $done $parts [$($specs)* (group [$(#[$m])*] $field $ty)] $($inner)* @end; $($rest)*);
    };
    (@munch $head:tt [$($done:tt)*] $parts:tt [$($specs:tt)*] $(#[$m:meta])* opt(required) $field:ident: $ty:ty = $key:expr; $($rest:tt)*) => {
        file_table!(@munch $head [$($done)* (opt [$(#[$m])*] [skip_serializing_if = "Option::is_none"]
            $field [] Option<$ty>; $key.required_by_reading())] $parts [$($specs)* (need [$(#[$m])*] $field $ty)] $($rest)*);
    };
    (@munch $head:tt [$($done:tt)*] $parts:tt [$($specs:tt)*] $(#[$m:meta])* opt($default:expr) $field:ident: $ty:ty = $key:expr; $($rest:tt)*) => {
        file_table!(@munch $head [$($done)* (opt [$(#[$m])*] [skip_serializing_if = "Option::is_none"]
            $field [] Option<$ty>; $key)] $parts [$($specs)* (dflt [$(#[$m])*] $field ($default) $ty)] $($rest)*);
    };
    (@munch $head:tt [$($done:tt)*] $parts:tt [$($specs:tt)*] $(#[$m:meta])* arr(required) $field:ident: $ty:ty = $key:expr; $($rest:tt)*) => {
        file_table!(@munch $head [$($done)* (arr [$(#[$m])*] [default, deserialize_with = "crate::keys::exactly_n",
            skip_serializing_if = "Option::is_none"] $field [] Option<$ty>; $key.required_by_reading())] $parts
            [$($specs)* (need [$(#[$m])*] $field $ty)] $($rest)*);
    };
    (@munch $head:tt [$($done:tt)*] $parts:tt [$($specs:tt)*] $(#[$m:meta])* arr($default:expr) $field:ident: $ty:ty = $key:expr; $($rest:tt)*) => {
        file_table!(@munch $head [$($done)* (arr [$(#[$m])*] [default, deserialize_with = "crate::keys::exactly_n",
            skip_serializing_if = "Option::is_none"] $field [] Option<$ty>; $key)] $parts
            [$($specs)* (dflt [$(#[$m])*] $field ($default) $ty)] $($rest)*);
    };
    (@munch $head:tt [$($done:tt)*] $parts:tt [$($specs:tt)*] $(#[$m:meta])* opt $field:ident $(as $rename:literal)?: $ty:ty = $key:expr; $($rest:tt)*) => {
        file_table!(@munch $head [$($done)* (opt [$(#[$m])*] [$(rename = $rename,)? skip_serializing_if = "Option::is_none"]
            $field [$($rename)?] Option<$ty>; $key)] $parts [$($specs)* (same [$(#[$m])*] $field Option<$ty>)] $($rest)*);
    };
    (@munch $head:tt [$($done:tt)*] $parts:tt [$($specs:tt)*] $(#[$m:meta])* arr $field:ident $(as $rename:literal)?: $ty:ty = $key:expr; $($rest:tt)*) => {
        file_table!(@munch $head [$($done)* (arr [$(#[$m])*] [$(rename = $rename,)? default, deserialize_with = "crate::keys::exactly_n",
            skip_serializing_if = "Option::is_none"] $field [$($rename)?] Option<$ty>; $key)] $parts
            [$($specs)* (same [$(#[$m])*] $field Option<$ty>)] $($rest)*);
    };
    (@munch $head:tt [$($done:tt)*] $parts:tt [$($specs:tt)*] $(#[$m:meta])* req $field:ident $(as $rename:literal)?: $ty:ty = $key:expr; $($rest:tt)*) => {
        file_table!(@munch $head [$($done)* (req [$(#[$m])*] [$(rename = $rename)?] $field [$($rename)?] $ty; $key)] $parts
            [$($specs)* (plain [$(#[$m])*] $field $ty)] $($rest)*);
    };
    (@munch $head:tt [$($done:tt)*] $parts:tt [$($specs:tt)*] $(#[$m:meta])* list $field:ident $(as $rename:literal)?: $ty:ty = $key:expr; $($rest:tt)*) => {
        file_table!(@munch $head [$($done)* (list [$(#[$m])*] [$(rename = $rename,)? default, skip_serializing_if = "Vec::is_empty"]
            $field [$($rename)?] Vec<$ty>; $key)] $parts [$($specs)* (same [$(#[$m])*] $field Vec<$ty>)] $($rest)*);
    };
    (@munch $head:tt [$($done:tt)*] [$($parts:tt)*] [$($specs:tt)*] $(#[$m:meta])* part $field:ident: $spec:ty = $key:expr; $($rest:tt)*) => {
        file_table!(@munch $head [$($done)* (part [$(#[$m])*] [default, skip_serializing_if = "Option::is_none"]
            $field [] Option<<$spec as $crate::keys::Part>::File>; $key)] [$($parts)* ([$(#[$m])*] $field $spec)]
            [$($specs)* (maybe [$(#[$m])*] $field $spec)] $($rest)*);
    };
    (@munch $head:tt [$($done:tt)*] $parts:tt [$($specs:tt)*] $(#[$m:meta])* one $field:ident: $spec:ty = $key:expr; $($rest:tt)*) => {
        file_table!(@munch $head [$($done)* (req [$(#[$m])*] [] $field [] <$spec as $crate::keys::Part>::File;
            $key.required_by_reading().holding(&<$spec as $crate::keys::Part>::TABLE))] $parts
            [$($specs)* (one [$(#[$m])*] $field $spec)] $($rest)*);
    };
    (@munch $head:tt [$($done:tt)*] $parts:tt [$($specs:tt)*] $(#[$m:meta])* maybe $field:ident: $spec:ty = $key:expr; $($rest:tt)*) => {
        file_table!(@munch $head [$($done)* (opt [$(#[$m])*] [default, skip_serializing_if = "Option::is_none"] $field []
            Option<<$spec as $crate::keys::Part>::File>; $key.holding(&<$spec as $crate::keys::Part>::TABLE))] $parts
            [$($specs)* (maybe [$(#[$m])*] $field $spec)] $($rest)*);
    };
    (@munch $head:tt [$($done:tt)*] $parts:tt [$($specs:tt)*] $(#[$m:meta])* each $field:ident: $spec:ty = $key:expr; $($rest:tt)*) => {
        file_table!(@munch $head [$($done)* (list [$(#[$m])*] [default, skip_serializing_if = "Vec::is_empty"] $field []
            Vec<<$spec as $crate::keys::Part>::File>; $key.holding(&<$spec as $crate::keys::Part>::TABLE))] $parts
            [$($specs)* (each [$(#[$m])*] $field $spec)] $($rest)*);
    };
    (@name $field:ident) => { stringify!($field) };
    (@given $value:expr, req) => { true };
    (@given $value:expr, list) => { !$value.is_empty() };
    (@given $value:expr, $optional:ident) => { $value.is_some() };
    (@name $field:ident $rename:literal) => { $rename };
    (@either $name:ident []) => {};
    (@either $name:ident [$(($a:ident $b:ident [$($typed:tt)*] $message:literal))+]) => {
        impl $name {
            /// Refuses keys given together that exclude each other (the declaration's `either`), naming the second.
            pub(crate) fn exclusive(&self, table: &$crate::keys::KeyPath) -> $crate::keys::Checked<()> {
                $(if self.$a.is_some() && self.$b.is_some() {
                    return $crate::keys::invalid(table.clone().key(stringify!($b)), $message);
                })+
                Ok(())
            }
        }
        $(file_table!(@either_typed $name $a $b [$($typed)*]);)+
    };
    (@either_typed $name:ident $a:ident $b:ident []) => {};
    (@either_typed $name:ident $a:ident $b:ident [$ty:ident $va:ident $vb:ident]) => {
        impl $crate::keys::Either<$ty> for $name {
            fn either(&self) -> Option<$ty> {
                match (self.$a, self.$b) {
                    (Some(a), _) => Some($ty::$va(a)),
                    (None, Some(b)) => Some($ty::$vb(b)),
                    (None, None) => None,
                }
            }

            fn set_either(&mut self, choice: Option<$ty>) {
                match choice {
                    Some($ty::$va(a)) => self.$a = Some(a),
                    Some($ty::$vb(b)) => self.$b = Some(b),
                    None => {}
                }
            }
        }
    };
    (@parts $vis:vis $name:ident [] $parts:tt) => {};
    (@parts $vis:vis $name:ident [$(#[$pm:meta])* $pvis:vis $pname:ident] [$(([$(#[$m:meta])*] $field:ident $spec:ty))*]) => {
        $(#[$pm])*
        $pvis struct $pname {
            $($(#[$m])* pub $field: Option<$spec>,)*
        }

        impl $pname {
            /// The parts' names: the keys of the enclosing table that hold them.
            $vis const NAMES: &[&str] = &[$(stringify!($field)),*];

            /// The parts the file gives, read (each one's table at `at`.NAME).
            $vis fn read(file: &$name, at: &$crate::keys::KeyPath) -> $crate::keys::Checked<Self> {
                Ok(Self {
                    $($field: (file.$field.as_ref())
                        .map(|f| <$spec as $crate::keys::Part>::read(f, &at.clone().key(stringify!($field))))
                        .transpose()?,)*
                })
            }

            /// The parts written into `file`.
            $vis fn write(&self, file: &mut $name) {
                $(file.$field = self.$field.as_ref().map($crate::keys::Part::write);)*
            }

            /// Parts the file gives where the enclosing table takes none: each part's own message, if it has one.
            $vis fn refuse_unattached(file: &$name, at: &$crate::keys::KeyPath) -> $crate::keys::Checked<()> {
                $(if let Some(f) = &file.$field {
                    <$spec as $crate::keys::Part>::refuse_unattached(f, &at.clone().key(stringify!($field)))?;
                })*
                Ok(())
            }

            /// `to` with every part given attached, in the declaration's order.
            $vis fn attach<T>(&self, to: T, at: &$crate::keys::KeyPath) -> $crate::keys::Checked<T>
            where
                $($spec: $crate::keys::Attach<T>,)*
            {
                let mut to = to;
                $(if let Some(p) = &self.$field {
                    to = $crate::keys::Attach::attach(p, to, &at.clone().key(stringify!($field)))?;
                })*
                Ok(to)
            }
        }
    };
    (@kinds $name:ident $partsdecl:tt []) => {};
    (@kinds $name:ident $partsdecl:tt [$(#[$km:meta])* $kvis:vis enum $kind:ident ($what:literal, $missing:literal) for $spec:ident {
        $($(#[$vm:meta])* $variant:ident = $vname:literal: [$($key:ident),*];)+
    }]) => {
        file_table!(@kinds $name $partsdecl [$(#[$km])* $kvis enum $kind ($what, $missing) {
            $($(#[$vm])* $variant = $vname: [$($key),*];)+
        }]);

        impl $crate::keys::Part for $spec {
            type File = $name;
            const TABLE: $crate::keys::Table = $name::TABLE;

            fn read(file: &$name, at: &$crate::keys::KeyPath) -> $crate::keys::Checked<Self> {
                let (kind, text) = file.kind_given(at)?;
                Ok(match kind {
                    $($kind::$variant => $spec::$variant {
                        $($key: $crate::keys::required(at.clone().key(stringify!($key)), file.$key, &text)?,)*
                    },)+
                })
            }

            fn write(&self) -> $name {
                match *self {
                    $($spec::$variant { $($key),* } => $name {
                        kind: Some($kind::$variant),
                        $($key: Some($key),)*
                        ..$name::default()
                    },)+
                }
            }
        }
    };
    (@kinds $name:ident $partsdecl:tt [$(#[$km:meta])* $kvis:vis enum $kind:ident ($what:literal, $missing:literal) {
        $($(#[$vm:meta])* $variant:ident = $vname:literal: [$($takes:tt)*];)+
    }]) => {
        $(#[$km])*
        #[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, serde::Serialize, serde::Deserialize)]
        $kvis enum $kind {
            $($(#[$vm])* #[serde(rename = $vname)] $variant,)+
        }

        impl $kind {
            /// The names a scene file gives, `"a" | "b" | …`, as the `type` key's reference lists them.
            pub(crate) const CHOICES: &str = file_table!(@join $($vname)+);

            /// The name a scene file gives this kind.
            pub(crate) fn name(self) -> &'static str {
                match self {
                    $(Self::$variant => $vname,)+
                }
            }
        }

        impl $name {
            /// The table's `type`, with every key given one that type takes (the table at `at`); with it the
            /// text that messages about its keys begin with, `WHAT = "NAME"`.
            pub(crate) fn kind_given(
                &self,
                at: &$crate::keys::KeyPath,
            ) -> $crate::keys::Checked<($kind, String)> {
                let Some(kind) = self.kind else {
                    return $crate::keys::invalid(at.clone().key("type"), $missing);
                };
                let text = format!("{} = \"{}\"", $what, kind.name());
                let takes: Vec<&str> = match kind {
                    $($kind::$variant => file_table!(@takes $partsdecl [] $($takes)*),)+
                };
                $crate::keys::only_keys(at, &text, &takes, &self.given())?;
                Ok((kind, text))
            }
        }
    };
    (@join $first:literal $($rest:literal)*) => { concat!("\"", $first, "\"", $(" | \"", $rest, "\""),*) };
    (@takes $parts:tt [$($acc:tt)*]) => {{
        let slices: &[&[&str]] = &[$($acc)*];
        slices.concat()
    }};
    (@takes [$(#[$pm:meta])* $pvis:vis $pname:ident] [$($acc:tt)*] ..parts $(, $($rest:tt)*)?) => {
        file_table!(@takes [$pname] [$($acc)* $pname::NAMES,] $($($rest)*)?)
    };
    (@takes $parts:tt [$($acc:tt)*] $key:ident $(, $($rest:tt)*)?) => {
        file_table!(@takes $parts [$($acc)* &[stringify!($key)],] $($($rest)*)?)
    };
    (@spec $name:ident $either:tt [] $specs:tt) => {};
    (@spec $name:ident $either:tt [$(#[$sm:meta])* $svis:vis $sname:ident $what:tt] [$($specs:tt)*]) => {
        file_table!(@spec_walk {$name $either [$(#[$sm])*] $svis $sname $what} [file at self dir] [] [] [] [] [] [] $($specs)*);
    };
    (@spec_walk $head:tt $ids:tt $fields:tt $reads:tt $writes:tt $files:tt $params:tt $inits:tt) => {
        file_table!(@spec_emit $head $ids $fields $reads $writes $files $params $inits);
    };
    (@spec_walk $head:tt [$file:ident $at:ident $me:tt $dir:ident] [$($fields:tt)*] [$($reads:tt)*] [$($writes:tt)*] $files:tt $params:tt [$($inits:tt)*]
        (same [$($m:tt)*] $field:ident $ty:ty) $($rest:tt)*) => {
        file_table!(@spec_walk $head [$file $at $me $dir] [$($fields)* $($m)* pub $field: $ty,]
            [$($reads)* $field: ::core::clone::Clone::clone(&$file.$field),]
            [$($writes)* $file.$field = ::core::clone::Clone::clone(&$me.$field);] $files $params
            [$($inits)* $field: ::core::default::Default::default(),] $($rest)*);
    };
    (@spec_walk $head:tt [$file:ident $at:ident $me:tt $dir:ident] [$($fields:tt)*] [$($reads:tt)*] [$($writes:tt)*] $files:tt [$($params:tt)*] [$($inits:tt)*]
        (plain [$($m:tt)*] $field:ident $ty:ty) $($rest:tt)*) => {
        file_table!(@spec_walk $head [$file $at $me $dir] [$($fields)* $($m)* pub $field: $ty,]
            [$($reads)* $field: ::core::clone::Clone::clone(&$file.$field),]
            [$($writes)* $file.$field = ::core::clone::Clone::clone(&$me.$field);] $files
            [$($params)* $field: $ty,] [$($inits)* $field,] $($rest)*);
    };
    (@spec_walk {$name:ident $either:tt $sm:tt $svis:vis $sname:ident [$what:literal]} [$file:ident $at:ident $me:tt $dir:ident] [$($fields:tt)*] [$($reads:tt)*] [$($writes:tt)*] $files:tt [$($params:tt)*] [$($inits:tt)*]
        (need [$($m:tt)*] $field:ident $ty:ty) $($rest:tt)*) => {
        file_table!(@spec_walk {$name $either $sm $svis $sname [$what]} [$file $at $me $dir] [$($fields)* $($m)* pub $field: $ty,]
            [$($reads)* $field: $crate::keys::required($at.clone().key(stringify!($field)), ::core::clone::Clone::clone(&$file.$field), $what)?,]
            [$($writes)* $file.$field = Some(::core::clone::Clone::clone(&$me.$field));] $files
            [$($params)* $field: $ty,] [$($inits)* $field,] $($rest)*);
    };
    (@spec_walk $head:tt [$file:ident $at:ident $me:tt $dir:ident] [$($fields:tt)*] [$($reads:tt)*] [$($writes:tt)*] $files:tt $params:tt [$($inits:tt)*]
        (dflt [$($m:tt)*] $field:ident ($default:expr) $ty:ty) $($rest:tt)*) => {
        file_table!(@spec_walk $head [$file $at $me $dir] [$($fields)* $($m)* pub $field: $ty,]
            [$($reads)* $field: ::core::clone::Clone::clone(&$file.$field).unwrap_or($default),]
            [$($writes)* $file.$field = Some(::core::clone::Clone::clone(&$me.$field));] $files $params
            [$($inits)* $field: $default,] $($rest)*);
    };
    (@spec_walk $head:tt [$file:ident $at:ident $me:tt $dir:ident] [$($fields:tt)*] [$($reads:tt)*] [$($writes:tt)*] [$($files:tt)*] $params:tt [$($inits:tt)*]
        (maybe [$($m:tt)*] $field:ident $spec:ty) $($rest:tt)*) => {
        file_table!(@spec_walk $head [$file $at $me $dir] [$($fields)* $($m)* pub $field: Option<$spec>,]
            [$($reads)* $field: ($file.$field.as_ref())
                .map(|f| <$spec as $crate::keys::Part>::read(f, &$at.clone().key(stringify!($field))))
                .transpose()?,]
            [$($writes)* $file.$field = $me.$field.as_ref().map($crate::keys::Part::write);]
            [$($files)* if let Some(part) = &mut $me.$field { $crate::keys::Part::take_files_in(part, $dir); }] $params
            [$($inits)* $field: None,] $($rest)*);
    };
    (@spec_walk $head:tt [$file:ident $at:ident $me:tt $dir:ident] [$($fields:tt)*] [$($reads:tt)*] [$($writes:tt)*] [$($files:tt)*] $params:tt [$($inits:tt)*]
        (each [$($m:tt)*] $field:ident $spec:ty) $($rest:tt)*) => {
        file_table!(@spec_walk $head [$file $at $me $dir] [$($fields)* $($m)* pub $field: Vec<$spec>,]
            [$($reads)* $field: ($file.$field.iter().enumerate())
                .map(|(i, f)| <$spec as $crate::keys::Part>::read(f, &$at.clone().key(stringify!($field)).index(i)))
                .collect::<$crate::keys::Checked<_>>()?,]
            [$($writes)* $file.$field = $me.$field.iter().map($crate::keys::Part::write).collect();]
            [$($files)* for part in &mut $me.$field { $crate::keys::Part::take_files_in(part, $dir); }] $params
            [$($inits)* $field: Vec::new(),] $($rest)*);
    };
    (@spec_walk $head:tt [$file:ident $at:ident $me:tt $dir:ident] [$($fields:tt)*] [$($reads:tt)*] [$($writes:tt)*] [$($files:tt)*] [$($params:tt)*] [$($inits:tt)*]
        (one [$($m:tt)*] $field:ident $spec:ty) $($rest:tt)*) => {
        file_table!(@spec_walk $head [$file $at $me $dir] [$($fields)* $($m)* pub $field: $spec,]
            [$($reads)* $field: <$spec as $crate::keys::Part>::read(&$file.$field, &$at.clone().key(stringify!($field)))?,]
            [$($writes)* $file.$field = $crate::keys::Part::write(&$me.$field);]
            [$($files)* $crate::keys::Part::take_files_in(&mut $me.$field, $dir);]
            [$($params)* $field: $spec,] [$($inits)* $field,] $($rest)*);
    };
    (@spec_walk {$name:ident $($head:tt)*} [$file:ident $at:ident $me:tt $dir:ident] [$($fields:tt)*] [$($reads:tt)*] [$($writes:tt)*] [$($files:tt)*] [$($params:tt)*] [$($inits:tt)*]
        (group [$($m:tt)*] $field:ident $ty:ty) $($rest:tt)*) => {
        file_table!(@spec_skip {$name $($head)*} [$file $at $me $dir] [$($fields)* $($m)* pub $field: $ty,]
            [$($reads)* $field: <$ty as $crate::keys::Group<$name>>::read($file, $at)?,]
            [$($writes)* $crate::keys::Group::write(&$me.$field, &mut $file);]
            [$($files)* $crate::keys::Group::<$name>::take_files_in(&mut $me.$field, $dir);]
            [$($params)* $field: $ty,] [$($inits)* $field,] $($rest)*);
    };
    (@spec_skip $head:tt $ids:tt $fields:tt $reads:tt $writes:tt $files:tt $params:tt $inits:tt (end) $($rest:tt)*) => {
        file_table!(@spec_walk $head $ids $fields $reads $writes $files $params $inits $($rest)*);
    };
    (@spec_skip $head:tt $ids:tt $fields:tt $reads:tt $writes:tt $files:tt $params:tt $inits:tt $skipped:tt $($rest:tt)*) => {
        file_table!(@spec_skip $head $ids $fields $reads $writes $files $params $inits $($rest)*);
    };
    (@spec_emit {$name:ident $either:tt [$($sm:tt)*] $svis:vis $sname:ident $what:tt} [$file:ident $at:ident $me:tt $dir:ident]
        [$($fields:tt)*] [$($reads:tt)*] [$($writes:tt)*] [$($files:tt)*] [$($params:tt)*] [$($inits:tt)*]) => {
        $($sm)*
        $svis struct $sname {
            $($fields)*
        }

        impl $sname {
            /// The spec of the values a table must give (each key the reading requires, each group of keys), every
            /// other key at its default.
            #[allow(dead_code)]
            pub fn of($($params)*) -> Self {
                Self { $($inits)* }
            }
        }

        impl $crate::keys::Part for $sname {
            type File = $name;
            const TABLE: $crate::keys::Table = $name::TABLE;

            fn read($file: &$name, $at: &$crate::keys::KeyPath) -> $crate::keys::Checked<Self> {
                file_table!(@exclusive $either $file $at);
                Ok(Self { $($reads)* })
            }

            #[allow(clippy::field_reassign_with_default)]
            fn write(&$me) -> $name {
                let mut $file = $name::default();
                $($writes)*
                $file
            }

            fn take_files_in(&mut $me, $dir: &::std::path::Path) {
                let _ = $dir;
                $($files)*
            }
        }
    };
    (@exclusive [] $file:ident $at:ident) => {};
    (@exclusive [$($either:tt)+] $file:ident $at:ident) => { $file.exclusive($at)?; };
    (@emit {[$($meta:tt)*] $vis:vis struct $name:ident ($fvis:vis) $header:literal, $about:literal $either:tt $partsdecl:tt $specdecl:tt $kindsdecl:tt}
        [$(($pm:tt $pfield:ident $pspec:ty))*] $specs:tt
        $(($store:ident [$($m:tt)*] [$($serde:tt)*] $field:ident [$($rename:literal)?] $ty:ty; $key:expr))*) => {
        $($meta)*
        #[derive(Debug, Clone, Default, PartialEq, serde::Serialize, serde::Deserialize)]
        #[serde(deny_unknown_fields)]
        $vis struct $name {
            $($($m)* #[serde($($serde)*)] $fvis $field: $ty,)*
        }

        impl $name {
            /// The table's keys, as the book's reference lists them.
            pub(crate) const TABLE: $crate::keys::Table = $crate::keys::Table {
                header: $header,
                about: $about,
                keys: &[$($key.named(file_table!(@name $field $($rename)?)),)*],
                parts: &[$(<$pspec as $crate::keys::Part>::TABLE,)*],
            };

            /// The keys this table gives, in the declaration's order.
            #[allow(dead_code)]
            pub(crate) fn given(&self) -> Vec<&'static str> {
                let mut given = Vec::new();
                $(if file_table!(@given self.$field, $store) {
                    given.push(file_table!(@name $field $($rename)?));
                })*
                given
            }
        }

        file_table!(@either $name $either);
        file_table!(@parts $vis $name $partsdecl [$(($pm $pfield $pspec))*]);
        file_table!(@kinds $name $partsdecl $kindsdecl);
        file_table!(@spec $name $either $specdecl $specs);
    };
    ($(#[$meta:meta])* $vis:vis struct $name:ident ($fvis:vis) $header:literal, $about:literal { $($body:tt)* }
        $(either { $($a:ident, $b:ident $(=> $ty:ident::{$va:ident, $vb:ident})?: $message:literal;)+ })?
        $(parts { $(#[$pmeta:meta])* $pvis:vis struct $pname:ident; })?
        $(spec { $(#[$smeta:meta])* $svis:vis struct $sname:ident $(($what:literal))?; })?
        $(kinds { $($kinds:tt)* })?) => {
        file_table!(@munch {[$(#[$meta])*] $vis struct $name ($fvis) $header, $about [$($(($a $b [$($ty $va $vb)?] $message))+)?]
            [$($(#[$pmeta])* $pvis $pname)?] [$($(#[$smeta])* $svis $sname [$($what)?])?] [$($($kinds)*)?]} [] [] [] $($body)*);
    };
}

pub(crate) use file_table;
