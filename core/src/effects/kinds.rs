//! The effect kinds, registered: the one place that names them all. Each kind's folder holds its keys, its spec
//! (read from its keys, written back, validated) and its validated form, which answers [`EffectKind`]; here each
//! gets its `type` and the keys it takes ([`EffectType`]), its keys in the `[[effect]]` table ([`EffectFile`]), its
//! variant of [`EffectSpec`] and of [`Effect`], and its arm in the dispatches below.

use std::path::Path;

use super::b_dot::{BDot, BDotKeys, BDotSpec};
use super::damping::{Damping, DampingKeys, DampingSpec};
use super::gravity::{Gravity, GravityKeys, GravitySpec};
use super::gravity_gradient::{GravityGradient, GravityGradientSpec};
use super::kind::{EffectKind, Placement};
use super::law::UserMoment;
use super::magnetic::{MagneticDipole, MagneticKeys, MagneticSpec};
use super::torque::{TorqueGiven, TorqueKeys, TorqueSpec};
use super::torque_table::{TabulatedTorque, TorqueTableKeys, TorqueTableSpec};
use crate::frames::Axes;
use crate::keys::{Checked, KeyPath, Keys, Kind, Part, Table};
use crate::orbit::FieldKeys;

/// One `[[effect]]`.
#[derive(Debug, Clone, Default, PartialEq, Keys)]
#[keys(
    header = "[[effect]]",
    about = "a moment on the body; any number, at most one gravity"
)]
pub(crate) struct EffectFile {
    /// the effect
    #[key(rename = "type", kinds, shown = "required")]
    pub(crate) kind: Option<EffectType>,
    /// torque and torque_table: the axes of the moment
    #[key(kind = "\"body\" | \"space\"", shown = "\"body\"")]
    pub(crate) frame: Option<Axes>,
    /// `torque`
    #[key(flatten)]
    pub(crate) torque: TorqueKeys,
    /// `gravity`
    #[key(flatten)]
    pub(crate) gravity: GravityKeys,
    /// `damping`
    #[key(flatten)]
    pub(crate) damping: DampingKeys,
    /// `torque_table`
    #[key(flatten)]
    pub(crate) table: TorqueTableKeys,
    /// `magnetic`
    #[key(flatten)]
    pub(crate) magnetic: MagneticKeys,
    /// `b_dot`
    #[key(flatten)]
    pub(crate) b_dot: BDotKeys,
    /// the Earth's field, for `magnetic` and `b_dot`
    #[key(flatten)]
    pub(crate) field: FieldKeys,
}

/// The `type` of an effect.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Kind)]
#[kind(
    what = "effect type",
    missing = "missing: an effect needs `type` = \"torque\", \"gravity\", \"damping\", \"torque_table\", \"gravity_gradient\", \"magnetic\" or \"b_dot\""
)]
pub(crate) enum EffectType {
    #[kind(
        "torque",
        takes(frame, value, profile, freq_hz, phase_deg, t_on, t_off)
    )]
    Torque,
    #[kind("gravity", takes(g, pivot))]
    Gravity,
    #[kind("damping", takes(c))]
    Damping,
    #[kind("torque_table", takes(file, frame, interpolation))]
    TorqueTable,
    #[kind("gravity_gradient")]
    GravityGradient,
    #[kind("magnetic", takes(dipole, field_tilt_deg, field_lon_deg, field_b0))]
    Magnetic,
    #[kind(
        "b_dot",
        takes(gain, max_dipole, field_tilt_deg, field_lon_deg, field_b0)
    )]
    BDot,
}

/// One `[[effect]]`, by its `type`.
#[derive(Debug, Clone, PartialEq)]
pub enum EffectSpec {
    /// `type = "torque"`.
    Torque(TorqueSpec),
    /// `type = "gravity"`: uniform gravity acting at C.
    Gravity(GravitySpec),
    /// `type = "damping"`: M = −c ω.
    Damping(DampingSpec),
    /// `type = "torque_table"`: a moment tabulated in a CSV file.
    TorqueTable(TorqueTableSpec),
    /// `type = "gravity_gradient"`: the gravity gradient of the scene's `[orbit]` on a free body.
    GravityGradient(GravityGradientSpec),
    /// `type = "magnetic"`: the moment m × B of the body's residual dipole in the Earth's field along the orbit.
    Magnetic(MagneticSpec),
    /// `type = "b_dot"`: magnetorquers under the B-dot law.
    BDot(BDotSpec),
}

/// One effect of the scene's `[[effect]]` list, validated.
#[derive(Debug, Clone, PartialEq)]
pub enum Effect {
    /// An applied torque (N·m), given in body or space axes, with a time profile.
    Torque(TorqueGiven),
    /// Uniform gravity acting at C about a fixed pivot.
    Gravity(Gravity),
    /// Viscous damping M = −c ω.
    Damping(Damping),
    /// A tabulated moment, read from its file when the scene was validated.
    TorqueTable(TabulatedTorque),
    /// The gravity gradient of a circular orbit.
    GravityGradient(GravityGradient),
    /// A residual dipole in the Earth's field.
    Magnetic(MagneticDipole),
    /// Magnetorquers under the B-dot law.
    BDot(BDot),
    /// The user's own law ([`super::MomentLaw`]), named; added to a built scene by
    /// [`Scene::with_moment`](crate::scene::Scene::with_moment).
    User(UserMoment),
}

impl Effect {
    /// The effect's kind, the door every question about it goes through.
    pub fn door(&self) -> &dyn EffectKind {
        match self {
            Effect::Torque(e) => e,
            Effect::Gravity(e) => e,
            Effect::Damping(e) => e,
            Effect::TorqueTable(e) => e,
            Effect::GravityGradient(e) => e,
            Effect::Magnetic(e) => e,
            Effect::BDot(e) => e,
            Effect::User(e) => e,
        }
    }

    /// Whether this is an orbit's gravity gradient (which does not combine with uniform gravity).
    pub(crate) fn is_gravity_gradient(&self) -> bool {
        matches!(self, Effect::GravityGradient(_))
    }

    /// The torque as given, when this effect is an applied torque (not a table).
    pub fn torque(&self) -> Option<TorqueGiven> {
        match self {
            Effect::Torque(torque) => Some(*torque),
            _ => None,
        }
    }
}

impl EffectSpec {
    /// The effect's `type`.
    fn effect_type(&self) -> EffectType {
        match self {
            EffectSpec::Torque(_) => EffectType::Torque,
            EffectSpec::Gravity(_) => EffectType::Gravity,
            EffectSpec::Damping(_) => EffectType::Damping,
            EffectSpec::TorqueTable(_) => EffectType::TorqueTable,
            EffectSpec::GravityGradient(_) => EffectType::GravityGradient,
            EffectSpec::Magnetic(_) => EffectType::Magnetic,
            EffectSpec::BDot(_) => EffectType::BDot,
        }
    }

    /// The effect's `type` in a scene file.
    pub fn kind(&self) -> &'static str {
        self.effect_type().name()
    }

    /// The effect validated, its table at `at`, placed `on` the body.
    pub(crate) fn validate(&self, at: &KeyPath, on: &Placement) -> Checked<Effect> {
        Ok(match self {
            EffectSpec::Torque(spec) => Effect::Torque(spec.validate(at, on)?),
            EffectSpec::Gravity(spec) => Effect::Gravity(spec.validate(at, on)?),
            EffectSpec::Damping(spec) => Effect::Damping(spec.validate(at, on)?),
            EffectSpec::TorqueTable(spec) => Effect::TorqueTable(spec.validate(at, on)?),
            EffectSpec::GravityGradient(spec) => Effect::GravityGradient(spec.validate(at, on)?),
            EffectSpec::Magnetic(spec) => Effect::Magnetic(spec.validate(at, on)?),
            EffectSpec::BDot(spec) => Effect::BDot(spec.validate(at, on)?),
        })
    }
}

impl Part for EffectSpec {
    type File = EffectFile;
    const TABLE: Table = EffectFile::TABLE;

    /// One `[[effect]]` (its table at `at`): its `type` and the keys that type takes.
    fn read(doc: &EffectFile, at: &KeyPath) -> Checked<Self> {
        let (kind, text) = doc.kind_given(at)?;
        let frame = doc.frame.unwrap_or(Axes::Body);
        Ok(match kind {
            EffectType::Torque => {
                EffectSpec::Torque(TorqueSpec::read(frame, &doc.torque, at, &text)?)
            }
            EffectType::Gravity => EffectSpec::Gravity(GravitySpec::read(&doc.gravity)),
            EffectType::Damping => EffectSpec::Damping(DampingSpec::read(&doc.damping, at, &text)?),
            EffectType::TorqueTable => {
                EffectSpec::TorqueTable(TorqueTableSpec::read(frame, &doc.table, at, &text)?)
            }
            EffectType::GravityGradient => EffectSpec::GravityGradient(GravityGradientSpec),
            EffectType::Magnetic => {
                EffectSpec::Magnetic(MagneticSpec::read(&doc.magnetic, &doc.field))
            }
            EffectType::BDot => {
                EffectSpec::BDot(BDotSpec::read(&doc.b_dot, &doc.field, at, &text)?)
            }
        })
    }

    fn write(&self) -> EffectFile {
        let mut file = EffectFile {
            kind: Some(self.effect_type()),
            ..EffectFile::default()
        };
        match self {
            EffectSpec::Torque(spec) => (file.frame, file.torque) = (Some(spec.frame), spec.keys()),
            EffectSpec::Gravity(spec) => file.gravity = spec.keys(),
            EffectSpec::Damping(spec) => file.damping = spec.keys(),
            EffectSpec::TorqueTable(spec) => {
                (file.frame, file.table) = (Some(spec.frame), spec.keys())
            }
            EffectSpec::GravityGradient(_) => {}
            EffectSpec::Magnetic(spec) => {
                (file.magnetic, file.field) = (spec.keys(), spec.field.keys())
            }
            EffectSpec::BDot(spec) => (file.b_dot, file.field) = (spec.keys(), spec.field.keys()),
        }
        file
    }

    /// Its torque table's relative path taken relative to `dir` (a scene file's directory).
    fn take_files_in(&mut self, dir: &Path) {
        if let EffectSpec::TorqueTable(table) = self {
            table.file = dir.join(&table.file);
        }
    }
}

/// Each kind's spec as an [`EffectSpec`], and its validated form, the torque and the user's law, as an [`Effect`].
macro_rules! into_variants {
    ($($enum:ident :: $variant:ident ($kind:ty)),* $(,)?) => {$(
        impl From<$kind> for $enum {
            fn from(kind: $kind) -> Self {
                $enum::$variant(kind)
            }
        }
    )*};
}

into_variants!(
    EffectSpec::Torque(TorqueSpec),
    EffectSpec::Gravity(GravitySpec),
    EffectSpec::Damping(DampingSpec),
    EffectSpec::TorqueTable(TorqueTableSpec),
    EffectSpec::GravityGradient(GravityGradientSpec),
    EffectSpec::Magnetic(MagneticSpec),
    EffectSpec::BDot(BDotSpec),
    Effect::Torque(TorqueGiven),
    Effect::User(UserMoment),
);
