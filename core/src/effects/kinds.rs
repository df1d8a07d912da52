//! The effect kinds, registered: the one place that names them all, one line a kind. Each kind's folder holds its
//! keys, its spec ([`KindSpec`]: read from its keys, written back, validated onto the body) and its validated form,
//! which answers [`EffectKind`]. From a kind's line, `Variant("type", takes(keys…)): Spec => Effect`, `effect_kinds!`
//! makes its `type` with the keys it takes ([`EffectType`]), its keys in the `[[effect]]` table ([`EffectFile`]),
//! its variant of [`EffectSpec`] and of [`Effect`], and its arm in each dispatch.

use std::path::Path;

use super::b_dot::{BDot, BDotSpec};
use super::damping::{Damping, DampingSpec};
use super::gravity::{Gravity, GravitySpec};
use super::gravity_gradient::{GravityGradient, GravityGradientSpec};
use super::kind::{EffectKind, KindSpec, Placement, SharedKeys};
use super::law::UserMoment;
use super::magnetic::{MagneticDipole, MagneticSpec};
use super::torque::{TorqueGiven, TorqueSpec};
use super::torque_table::{TabulatedTorque, TorqueTableSpec};
use crate::frames::Axes;
use crate::keys::{Checked, KeyPath, Keys, Kind, Part, Table};
use crate::orbit::FieldKeys;

/// The registry's expansion: the file form, the `type`, the two enums and their dispatches, from one line a kind.
macro_rules! effect_kinds {
    ($(
        $(#[doc = $doc:literal])*
        $variant:ident($name:literal, takes($($key:ident),*)): $spec:ty => $effect:ty,
    )*) => {
        /// One `[[effect]]`: its `type`, the keys kinds share, and each kind's own (named by its variant).
        #[derive(Debug, Clone, Default, PartialEq, Keys)]
        #[keys(
            header = "[[effect]]",
            about = "a moment on the body; any number, at most one gravity"
        )]
        #[allow(non_snake_case)]
        pub(crate) struct EffectFile {
            /// the effect
            #[key(rename = "type", kinds, shown = "required")]
            pub(crate) kind: Option<EffectType>,
            /// torque and torque_table: the axes of the moment
            #[key(kind = "\"body\" | \"space\"", shown = "\"body\"")]
            pub(crate) frame: Option<Axes>,
            $(
                #[key(flatten)]
                pub(crate) $variant: <$spec as KindSpec>::Keys,
            )*
            /// the Earth's field, for `magnetic` and `b_dot`
            #[key(flatten)]
            pub(crate) field: FieldKeys,
        }

        /// The `type` of an effect.
        #[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Kind)]
        #[kind(what = "effect type", needs = "an effect")]
        pub(crate) enum EffectType {
            $(#[kind($name, takes($($key),*))] $variant,)*
        }

        /// One `[[effect]]`, by its `type`.
        #[derive(Debug, Clone, PartialEq)]
        pub enum EffectSpec {
            $(
                #[doc = concat!("`type = \"", $name, "\"`:")]
                $(#[doc = $doc])*
                $variant($spec),
            )*
        }

        /// One effect of the scene's `[[effect]]` list, validated.
        #[derive(Debug, Clone, PartialEq)]
        pub enum Effect {
            $(
                $(#[doc = $doc])*
                $variant($effect),
            )*
            /// The user's own law ([`super::MomentLaw`]), named; added to a built scene by
            /// [`Scene::with_moment`](crate::scene::Scene::with_moment).
            User(UserMoment),
        }

        impl Effect {
            /// The effect's kind, the door every question about it goes through.
            pub fn door(&self) -> &dyn EffectKind {
                match self {
                    $(Effect::$variant(e) => e,)*
                    Effect::User(e) => e,
                }
            }
        }

        impl EffectSpec {
            /// The effect's `type`.
            fn effect_type(&self) -> EffectType {
                match self {
                    $(EffectSpec::$variant(_) => EffectType::$variant,)*
                }
            }

            /// The effect validated, its table at `at`, placed `on` the body.
            pub(crate) fn validate(&self, at: &KeyPath, on: &Placement) -> Checked<Effect> {
                Ok(match self {
                    $(EffectSpec::$variant(spec) => Effect::$variant(spec.validate(at, on)?),)*
                })
            }

            /// The spec of type `kind` from its keys in `doc` and the `shared` ones.
            fn read_kind(
                kind: EffectType,
                doc: &EffectFile,
                shared: &SharedKeys,
                at: &KeyPath,
                text: &str,
            ) -> Checked<Self> {
                Ok(match kind {
                    $(EffectType::$variant => {
                        EffectSpec::$variant(<$spec>::read(&doc.$variant, shared, at, text)?)
                    })*
                })
            }

            /// Its own keys into `file`, the shared ones into `shared`.
            fn write_kind(&self, file: &mut EffectFile, shared: &mut SharedKeys) {
                match self {
                    $(EffectSpec::$variant(spec) => file.$variant = spec.write(shared),)*
                }
            }

            /// The files it names taken relative to `dir`.
            fn take_kind_files_in(&mut self, dir: &Path) {
                match self {
                    $(EffectSpec::$variant(spec) => spec.take_files_in(dir),)*
                }
            }
        }

        $(
            impl From<$spec> for EffectSpec {
                fn from(spec: $spec) -> Self {
                    EffectSpec::$variant(spec)
                }
            }
        )*
    };
}

effect_kinds! {
    /// An applied torque (N·m), given in body or space axes, with a time profile.
    Torque("torque", takes(frame, value, profile, freq_hz, phase_deg, t_on, t_off)): TorqueSpec => TorqueGiven,
    /// Uniform gravity acting at C about a fixed pivot.
    Gravity("gravity", takes(g, pivot)): GravitySpec => Gravity,
    /// Viscous damping M = −c ω.
    Damping("damping", takes(c)): DampingSpec => Damping,
    /// A moment tabulated in a CSV file, read when the scene is validated.
    TorqueTable("torque_table", takes(file, frame, interpolation)): TorqueTableSpec => TabulatedTorque,
    /// The gravity gradient of the scene's circular `[orbit]` on a free body.
    GravityGradient("gravity_gradient", takes()): GravityGradientSpec => GravityGradient,
    /// The moment m × B of the body's residual dipole in the Earth's field along the orbit.
    Magnetic("magnetic", takes(dipole, field_tilt_deg, field_lon_deg, field_b0)): MagneticSpec => MagneticDipole,
    /// Magnetorquers under the B-dot law in the Earth's field.
    BDot("b_dot", takes(gain, max_dipole, field_tilt_deg, field_lon_deg, field_b0)): BDotSpec => BDot,
}

impl Effect {
    /// The torque as given, when this effect is an applied torque (not a table).
    pub fn torque(&self) -> Option<TorqueGiven> {
        match self {
            Effect::Torque(torque) => Some(*torque),
            _ => None,
        }
    }
}

impl EffectSpec {
    /// The effect's `type` in a scene file.
    pub fn kind(&self) -> &'static str {
        self.effect_type().name()
    }
}

impl Part for EffectSpec {
    type File = EffectFile;
    const TABLE: Table = EffectFile::TABLE;

    /// One `[[effect]]` (its table at `at`): its `type` and the keys that type takes.
    fn read(doc: &EffectFile, at: &KeyPath) -> Checked<Self> {
        let (kind, text) = doc.kind_given(at)?;
        let shared = SharedKeys {
            frame: doc.frame,
            field: doc.field,
        };
        EffectSpec::read_kind(kind, doc, &shared, at, &text)
    }

    fn write(&self) -> EffectFile {
        let mut file = EffectFile {
            kind: Some(self.effect_type()),
            ..EffectFile::default()
        };
        let mut shared = SharedKeys::default();
        self.write_kind(&mut file, &mut shared);
        (file.frame, file.field) = (shared.frame, shared.field);
        file
    }

    /// Its files' relative paths taken relative to `dir` (a scene file's directory).
    fn take_files_in(&mut self, dir: &Path) {
        self.take_kind_files_in(dir);
    }
}

impl From<TorqueGiven> for Effect {
    fn from(torque: TorqueGiven) -> Self {
        Effect::Torque(torque)
    }
}

impl From<UserMoment> for Effect {
    fn from(law: UserMoment) -> Self {
        Effect::User(law)
    }
}
