//! `[[effect]]`'s keys, declared once ([`EffectFile`]: the file form and the reference's table; its `type`,
//! [`EffectKind`]), and [`EffectSpec`] as a [`Part`]: read from that table (its `type` and the keys that type
//! takes) and written back. The scene registers it with one line, `each effect: EffectSpec`.

use std::path::Path;

use super::spec::{EffectSpec, TorqueSpec, TorqueTableSpec};
use super::{DEFAULT_GRAVITY, Interpolation};
use crate::frames::Axes;
use crate::keys::{Checked, KeyPath, Part, Table, file_table, key, position, profile, required};
use crate::profile::{Profile, ProfileKind, profile_keys};

profile_keys!(EffectFile);

file_table! {
    /// One `[[effect]]`.
    pub(crate) struct EffectFile(pub(super)) "[[effect]]",
        "a moment on the body; any number, at most one gravity" {
        opt kind as "type": EffectKind = key(EffectKind::CHOICES, "–", "required", "", "the effect");
        opt frame: Axes = key("\"body\" | \"space\"", "–", "\"body\"", "", "torque and torque_table: the axes of the moment");
        arr value: [f64; 3] = key("[x, y, z]", "N·m", "required for `torque`", "", "the torque (amplitude for `sine`)");
        opt profile: ProfileKind = profile("torque: value, value·sin(2π freq_hz t + phase), or value for t_on ≤ t < t_off");
        @sine;
        @step;
        arr g: [f64; 3] = key("[x, y, z]", "m/s²", "[0, 0, -9.81]", "", "gravity: uniform, space axes, acting at C");
        arr pivot: [f64; 3] = position("required for free motion", "gravity: the fixed point, which becomes the moment center (an error with a fixed axis or hinge)");
        opt c: f64 = key("number", "N·m·s", "required for `damping`", "", "viscous M = −c·ω, ≥ 0");
        opt file: std::path::PathBuf = key("path", "–", "required for `torque_table`", "", "CSV with header t,M_x,M_y,M_z (s, N·m), relative to the scene file; zero outside its rows");
        opt interpolation: Interpolation = key("\"linear\" | \"cubic\"", "–", "\"linear\"", "", "torque_table: between rows (cubic: the natural spline)");
    }
    kinds {
        /// The `type` of an effect.
        pub(crate) enum EffectKind("effect type", "missing: an effect needs `type` = \"torque\", \"gravity\", \"damping\" or \"torque_table\"") {
            Torque = "torque": [frame, value, profile, freq_hz, phase_deg, t_on, t_off];
            Gravity = "gravity": [g, pivot];
            Damping = "damping": [c];
            TorqueTable = "torque_table": [file, frame, interpolation];
        }
    }
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
                profile: Profile::read(at, &doc.profile_keys(), "a sine torque")?,
            }),
            EffectKind::Gravity => EffectSpec::Gravity {
                g: doc.g.unwrap_or(DEFAULT_GRAVITY),
                pivot: doc.pivot,
            },
            EffectKind::Damping => EffectSpec::Damping {
                c: required(key("c"), doc.c, &kind_text)?,
            },
            EffectKind::TorqueTable => EffectSpec::TorqueTable(TorqueTableSpec {
                file: required(key("file"), doc.file.clone(), &kind_text)?,
                frame: doc.frame.unwrap_or(Axes::Body),
                interpolation: doc.interpolation.unwrap_or_default(),
            }),
        })
    }

    fn write(&self) -> EffectFile {
        match self {
            EffectSpec::Torque(torque) => {
                let mut file = EffectFile {
                    kind: Some(EffectKind::Torque),
                    frame: Some(torque.frame),
                    value: Some(torque.value),
                    ..EffectFile::default()
                };
                file.set_profile_keys(torque.profile.keys());
                file
            }
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
