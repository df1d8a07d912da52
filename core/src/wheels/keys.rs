//! `[[body.rotor]]`'s keys, declared once by the typed [`RotorSpec`] (its file form `RotorFile`, the reference's
//! table, both conversions): its required keys, and at most one drive with the motor's
//! profile keys only with `torque` (the [`RotorDrive`]). `[body]` registers it with one field, `rotor: Vec<RotorSpec>`.

use std::path::Path;

use super::WheelKeys;
use super::limits::WheelMode;
use super::spec::RotorDrive;
use crate::keys::{Checked, Group, KeyPath, Keys, Table, invalid};
use crate::profile::{Profile, ProfileKeys};

/// One `[[body.rotor]]`: a wheel of moment of inertia J about its axis a (fixed in the body), spinning at Ω relative
/// to the body; its momentum adds J Ω a to H (H = I ω + Σ J_k Ω_k a_k).
#[derive(Debug, Clone, PartialEq, Table)]
#[table(
    file = RotorFile,
    header = "[[body.rotor]]",
    about = "a wheel spinning inside the body about an axis fixed in it (free motion or a pivot only)",
    what = "a rotor"
)]
pub struct RotorSpec {
    /// the prefix of its columns: letters, digits, `_`; unique
    #[key(shown = "rotor0, rotor1, …")]
    pub name: Option<String>,
    /// spin axis in body axes (normalised, not zero)
    #[key(unit = "–")]
    pub axis: [f64; 3],
    /// J about the spin axis, > 0; `[body]` already holds J a aᵀ (wheels locked)
    #[key(unit = "kg·m²")]
    pub inertia: f64,
    /// Ω at t = 0, relative to the body
    #[key(unit = "rad/s", default = 0.0)]
    pub spin: f64,
    /// What drives it: `spin_accel`, `torque` (with its profile), `torque_table` or `mode`.
    #[key(flatten = DriveKeys)]
    pub drive: RotorDrive,
    /// `max_torque`, `max_speed_rpm`, `friction`: the wheel's limits and friction ([`crate::wheels`]).
    #[key(flatten = WheelKeys)]
    pub wheel: WheelKeys,
    /// the wheel's centre
    #[key(position, default = [0.0; 3])]
    pub at: [f64; 3],
    /// ≥ 0: U_s = m·e, a force U_s Ω² at `at` turning with the wheel
    #[key(unit = "g·mm", default = 0.0)]
    pub imbalance_static_gmm: f64,
    /// ≥ 0: U_d, a couple U_d Ω² turning with the wheel
    #[key(unit = "g·mm²", default = 0.0)]
    pub imbalance_dynamic_gmm2: f64,
}

/// A rotor's drive keys, read as its [`RotorDrive`].
#[derive(Debug, Clone, Default, PartialEq, Keys)]
pub(crate) struct DriveKeys {
    /// Ω(t) = spin + spin_accel·t prescribed; the motor torque is an output
    #[key(unit = "rad/s²")]
    spin_accel: Option<f64>,
    /// instead of `spin_accel`: the motor torque on the wheel (the body feels its opposite); neither: Ω stays constant
    #[key(unit = "N·m")]
    torque: Option<f64>,
    /// the motor torque's profile: torque·p(t)
    #[key(flatten)]
    profile: ProfileKeys,
    /// instead of `torque`: the motor torque commanded by a table (header `t,torque`; linear between rows), relative to the scene file
    torque_table: Option<std::path::PathBuf>,
    /// `"free"`: no motor, the wheel spins freely (friction only); without a driver a wheel holds its relative spin
    #[key(kind = "\"free\"", shown = "held")]
    mode: Option<WheelMode>,
}

/// The limits and friction as given (each absent: none).
impl Group<WheelKeys> for WheelKeys {
    fn read(keys: &WheelKeys, _at: &KeyPath) -> Checked<Self> {
        Ok(*keys)
    }

    fn write(&self, keys: &mut WheelKeys) {
        *keys = *self;
    }
}

/// At most one of `spin_accel`, `torque`, `torque_table` and `mode = "free"`; the motor's profile keys only with
/// `torque`.
impl Group<DriveKeys> for RotorDrive {
    fn read(doc: &DriveKeys, at: &KeyPath) -> Checked<Self> {
        let drive = drive(at, doc)?;
        if !matches!(drive, RotorDrive::Torque { .. }) {
            if let Some(name) = doc.profile.given().into_iter().next() {
                return invalid(
                    at.clone().key(name),
                    format!(
                        "`{name}` is the motor torque's profile: it applies with `torque` only"
                    ),
                );
            }
        }
        Ok(drive)
    }

    fn write(&self, file: &mut DriveKeys) {
        match self {
            RotorDrive::ConstantSpin => {}
            RotorDrive::Table(path) => file.torque_table = Some(path.clone()),
            RotorDrive::Free => file.mode = Some(WheelMode::Free),
            RotorDrive::SpinAccel(accel) => file.spin_accel = Some(*accel),
            RotorDrive::Torque { value, profile } => {
                file.torque = Some(*value);
                file.profile = profile.keys();
            }
        }
    }

    /// Its torque table's relative path taken relative to `dir` (a scene file's directory).
    fn take_files_in(&mut self, dir: &Path) {
        if let RotorDrive::Table(file) = self {
            *file = dir.join(&*file);
        }
    }
}

/// A rotor's drive: at most one of `spin_accel`, `torque`, `torque_table` and `mode = "free"`.
fn drive(table: &KeyPath, doc: &DriveKeys) -> Checked<RotorDrive> {
    let profile = doc.profile.given();
    let mut present = (doc.given().into_iter()).filter(|k| !profile.contains(k));
    if let (Some(first), Some(second)) = (present.next(), present.next()) {
        let message = match (first, second) {
            ("spin_accel", "torque") => {
                "give either `spin_accel` (a prescribed spin) or `torque` (a motor torque), not both".to_string()
            }
            _ => format!(
                "give at most one of `spin_accel`, `torque`, `torque_table` and `mode = \"free\"`: `{first}` and \
                 `{second}` both drive the wheel"
            ),
        };
        return invalid(table.clone().key(second), message);
    }
    Ok(
        match (doc.spin_accel, doc.torque, &doc.torque_table, doc.mode) {
            (Some(accel), ..) => RotorDrive::SpinAccel(accel),
            (_, Some(value), ..) => RotorDrive::Torque {
                value,
                profile: Profile::read(table, &doc.profile, "a sine torque")?,
            },
            (_, _, Some(file), _) => RotorDrive::Table(file.clone()),
            (_, _, _, Some(WheelMode::Free)) => RotorDrive::Free,
            _ => RotorDrive::ConstantSpin,
        },
    )
}
