//! `[[effect]]`'s keys, declared once ([`EffectFile`]: the file form and the reference's table; its `type`,
//! [`EffectKind`], with the keys each type takes), and [`EffectSpec`] as a [`Part`]: read from that table (its `type` and the keys that type
//! takes) and written back. The scene registers it with one line, `each effect: EffectSpec`.

use std::path::Path;

use super::spec::{EffectSpec, MagneticSpec, TorqueSpec, TorqueTableSpec};
use super::{DEFAULT_GRAVITY, Interpolation};
use crate::frames::Axes;
use crate::keys::{Checked, KeyPath, Keys, Kind, Part, Table, required};
use crate::orbit::DEFAULT_B0;
use crate::profile::{Profile, ProfileKeys};

/// One `[[effect]]`.
#[derive(Debug, Clone, Default, PartialEq, Keys)]
#[keys(
    header = "[[effect]]",
    about = "a moment on the body; any number, at most one gravity"
)]
pub(crate) struct EffectFile {
    /// the effect
    #[key(rename = "type", kinds, shown = "required")]
    pub(super) kind: Option<EffectKind>,
    /// torque and torque_table: the axes of the moment
    #[key(kind = "\"body\" | \"space\"", shown = "\"body\"")]
    pub(super) frame: Option<Axes>,
    /// the torque (amplitude for `sine`)
    #[key(unit = "N·m", shown = "required for `torque`")]
    pub(super) value: Option<[f64; 3]>,
    /// torque: value·p(t)
    #[key(flatten)]
    pub(super) profile: ProfileKeys,
    /// gravity: uniform, space axes, acting at C
    #[key(unit = "m/s²", shown = "[0, 0, -9.81]")]
    pub(super) g: Option<[f64; 3]>,
    /// gravity: the fixed point, which becomes the moment center (an error with a fixed axis or hinge)
    #[key(position, shown = "required for free motion")]
    pub(super) pivot: Option<[f64; 3]>,
    /// viscous M = −c·ω, ≥ 0
    #[key(unit = "N·m·s", shown = "required for `damping`")]
    pub(super) c: Option<f64>,
    /// CSV with header t,M_x,M_y,M_z (s, N·m), relative to the scene file; zero outside its rows
    #[key(shown = "required for `torque_table`")]
    pub(super) file: Option<std::path::PathBuf>,
    /// torque_table: between rows (cubic: the natural spline)
    #[key(kind = "\"linear\" | \"cubic\"", shown = "\"linear\"")]
    pub(super) interpolation: Option<Interpolation>,
    /// magnetic: the body's residual magnetic dipole, body axes; the moment is m × B
    #[key(unit = "A·m²", shown = "[0, 0, 0]")]
    pub(super) dipole: Option<[f64; 3]>,
    /// magnetic: the field dipole's tilt from the Earth's axis (0: aligned); a tilted dipole turns with the Earth
    #[key(unit = "deg", shown = "0")]
    pub(super) field_tilt_deg: Option<f64>,
    /// magnetic: the longitude the tilted dipole leans toward at t = 0, from space x
    #[key(unit = "deg", shown = "0")]
    pub(super) field_lon_deg: Option<f64>,
    /// magnetic: the field on the equator at the Earth's surface, > 0; B ∝ (R/r)³
    #[key(unit = "T", shown = "3.12e-5")]
    pub(super) field_b0: Option<f64>,
}

/// The `type` of an effect.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Kind)]
#[kind(
    what = "effect type",
    missing = "missing: an effect needs `type` = \"torque\", \"gravity\", \"damping\", \"torque_table\", \"gravity_gradient\" or \"magnetic\""
)]
pub(crate) enum EffectKind {
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
}

impl Part for EffectSpec {
    type File = EffectFile;
    const TABLE: Table = EffectFile::TABLE;

    /// One `[[effect]]` (its table at `at`): its `type` and the keys that type takes.
    fn read(doc: &EffectFile, at: &KeyPath) -> Checked<Self> {
        let key = |name: &str| at.clone().key(name);
        let (kind, kind_text) = doc.kind_given(at)?;
        Ok(match kind {
            EffectKind::Torque => EffectSpec::Torque(TorqueSpec {
                frame: doc.frame.unwrap_or(Axes::Body),
                value: required(key("value"), doc.value, &kind_text)?,
                profile: Profile::read(at, &doc.profile, "a sine torque")?,
            }),
            EffectKind::Gravity => EffectSpec::Gravity {
                g: doc.g.unwrap_or(DEFAULT_GRAVITY),
                pivot: doc.pivot,
            },
            EffectKind::Damping => EffectSpec::Damping {
                c: required(key("c"), doc.c, &kind_text)?,
            },
            EffectKind::GravityGradient => EffectSpec::GravityGradient,
            EffectKind::Magnetic => EffectSpec::Magnetic(MagneticSpec {
                dipole: doc.dipole.unwrap_or([0.0; 3]),
                field_tilt_deg: doc.field_tilt_deg.unwrap_or(0.0),
                field_lon_deg: doc.field_lon_deg.unwrap_or(0.0),
                field_b0: doc.field_b0.unwrap_or(DEFAULT_B0),
            }),
            EffectKind::TorqueTable => EffectSpec::TorqueTable(TorqueTableSpec {
                file: required(key("file"), doc.file.clone(), &kind_text)?,
                frame: doc.frame.unwrap_or(Axes::Body),
                interpolation: doc.interpolation.unwrap_or_default(),
            }),
        })
    }

    fn write(&self) -> EffectFile {
        match self {
            EffectSpec::Torque(torque) => EffectFile {
                kind: Some(EffectKind::Torque),
                frame: Some(torque.frame),
                value: Some(torque.value),
                profile: torque.profile.keys(),
                ..EffectFile::default()
            },
            EffectSpec::Gravity { g, pivot } => EffectFile {
                kind: Some(EffectKind::Gravity),
                g: Some(*g),
                pivot: *pivot,
                ..EffectFile::default()
            },
            EffectSpec::Damping { c } => EffectFile {
                kind: Some(EffectKind::Damping),
                c: Some(*c),
                ..EffectFile::default()
            },
            EffectSpec::Magnetic(m) => EffectFile {
                kind: Some(EffectKind::Magnetic),
                dipole: Some(m.dipole),
                field_tilt_deg: Some(m.field_tilt_deg),
                field_lon_deg: Some(m.field_lon_deg),
                field_b0: Some(m.field_b0),
                ..EffectFile::default()
            },
            EffectSpec::GravityGradient => EffectFile {
                kind: Some(EffectKind::GravityGradient),
                ..EffectFile::default()
            },
            EffectSpec::TorqueTable(table) => EffectFile {
                kind: Some(EffectKind::TorqueTable),
                file: Some(table.file.clone()),
                frame: Some(table.frame),
                interpolation: Some(table.interpolation),
                ..EffectFile::default()
            },
        }
    }

    /// Its torque table's relative path taken relative to `dir` (a scene file's directory).
    fn take_files_in(&mut self, dir: &Path) {
        if let EffectSpec::TorqueTable(table) = self {
            table.file = dir.join(&table.file);
        }
    }
}
