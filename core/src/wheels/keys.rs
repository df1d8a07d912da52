//! `[[body.rotor]]`'s keys, declared once ([`RotorFile`]: the file form, the reference's table and the typed
//! [`RotorSpec`], read from it and written back): its required keys, and at most one drive with the motor's
//! profile keys only with `torque` (the [`RotorDrive`]). `[body]` registers it with one line, `each rotor: RotorSpec`.

use std::path::Path;

use super::limits::WheelMode;
use super::spec::RotorDrive;
use super::{FrictionKeys, WheelKeys};
use crate::keys::{Checked, Group, KeyPath, file_table, invalid, key, position, profile};
use crate::profile::{Profile, ProfileKind, profile_keys};

file_table! {
    /// One `[[body.rotor]]`.
    pub(crate) struct RotorFile(pub(super)) "[[body.rotor]]",
        "a wheel spinning inside the body about an axis fixed in it (free motion or a pivot only)" {
        /// `name`: the prefix of its columns (absent: `rotor0`, `rotor1`, … in order).
        opt name: String = key("string", "–", "rotor0, rotor1, …", "", "the prefix of its columns: letters, digits, `_`; unique");
        /// `axis`: spin axis, body axes (normalised by validation).
        arr(required) axis: [f64; 3] = key("[x, y, z]", "–", "required", "", "spin axis in body axes (normalised, not zero)");
        /// `inertia`: J, kg·m², > 0.
        opt(required) inertia: f64 = key("number", "kg·m²", "required", "", "J about the spin axis, > 0; `[body]` already holds J a aᵀ (wheels locked)");
        /// `spin`: Ω at t = 0 relative to the body (rad/s; absent: 0).
        opt(0.0) spin: f64 = key("number", "rad/s", "0", "", "Ω at t = 0, relative to the body");
        /// What drives it: `spin_accel`, `torque` (with its profile), `torque_table` or `mode`.
        group drive: RotorDrive {
            opt spin_accel: f64 = key("number", "rad/s²", "none", "", "Ω(t) = spin + spin_accel·t prescribed; the motor torque is an output");
            opt torque: f64 = key("number", "N·m", "none", "", "instead of `spin_accel`: the motor torque on the wheel (the body feels its opposite); neither: Ω stays constant");
            opt profile: ProfileKind = profile("the motor torque's profile, as a torque effect's");
            @sine;
            @step;
            opt torque_table: std::path::PathBuf = key("path", "–", "none", "", "instead of `torque`: the motor torque commanded by a table (header `t,torque`; linear between rows), relative to the scene file");
            opt mode: WheelMode = key("\"free\"", "–", "held", "", "`\"free\"`: no motor, the wheel spins freely (friction only); without a driver a wheel holds its relative spin");
        }
        /// `max_torque`, `max_speed_rpm`, `friction`: the wheel's limits and friction ([`crate::wheels`]).
        group wheel: WheelKeys {
            opt max_torque: f64 = key("number", "N·m", "none", "", "> 0: the motor torque is clipped to ±max_torque (`<name>_torque_cmd` keeps the command)");
            opt max_speed_rpm: f64 = key("number", "rpm", "none", "", "> 0: the relative spin's limit (the initial spin must be within it); at it the motor can only slow the wheel");
            opt friction: FrictionKeys = key("{ coulomb, viscous, stribeck = { torque, speed } }", "N·m, N·m·s, (N·m, rad/s)", "none", "", "friction opposing the relative spin: τ_f = −(coulomb + stribeck.torque·exp(−(Ω/stribeck.speed)²))·sign(Ω) − viscous·Ω");
        }
        /// `at`: the wheel's centre from the reference origin, body axes (m; absent: the origin).
        arr([0.0; 3]) at: [f64; 3] = position("[0, 0, 0]", "the wheel's centre");
        /// `imbalance_static_gmm`: the static imbalance m·e (g·mm, ≥ 0; absent: 0).
        opt(0.0) imbalance_static_gmm: f64 = key("number", "g·mm", "0", "", "≥ 0: U_s = m·e, a force U_s Ω² at `at` turning with the wheel");
        /// `imbalance_dynamic_gmm2`: the dynamic imbalance (g·mm², ≥ 0; absent: 0).
        opt(0.0) imbalance_dynamic_gmm2: f64 = key("number", "g·mm²", "0", "", "≥ 0: U_d, a couple U_d Ω² turning with the wheel");
    }
    spec {
        /// One `[[body.rotor]]`: a wheel of moment of inertia J about its axis a (fixed in the body), spinning at Ω
        /// relative to the body; its momentum adds J Ω a to H (H = I ω + Σ J_k Ω_k a_k).
        #[derive(Debug, Clone, PartialEq)]
        pub struct RotorSpec("a rotor");
    }
}

profile_keys!(RotorFile);

/// At most one of `spin_accel`, `torque`, `torque_table` and `mode = "free"`; the motor's profile keys only with
/// `torque`.
impl Group<RotorFile> for RotorDrive {
    fn read(doc: &RotorFile, at: &KeyPath) -> Checked<Self> {
        let drive = drive(at, doc)?;
        if !matches!(drive, RotorDrive::Torque { .. }) {
            const PROFILE: [&str; 5] = ["profile", "freq_hz", "phase_deg", "t_on", "t_off"];
            if let Some(name) = doc.given().into_iter().find(|k| PROFILE.contains(k)) {
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

    fn write(&self, file: &mut RotorFile) {
        match self {
            RotorDrive::ConstantSpin => {}
            RotorDrive::Table(path) => file.torque_table = Some(path.clone()),
            RotorDrive::Free => file.mode = Some(WheelMode::Free),
            RotorDrive::SpinAccel(accel) => file.spin_accel = Some(*accel),
            RotorDrive::Torque { value, profile } => {
                file.torque = Some(*value);
                file.set_profile_keys(profile.keys());
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

/// The limits and friction as given (each absent: none).
impl Group<RotorFile> for WheelKeys {
    fn read(doc: &RotorFile, _at: &KeyPath) -> Checked<Self> {
        Ok(WheelKeys {
            max_torque: doc.max_torque,
            max_speed_rpm: doc.max_speed_rpm,
            friction: doc.friction,
        })
    }

    fn write(&self, file: &mut RotorFile) {
        file.max_torque = self.max_torque;
        file.max_speed_rpm = self.max_speed_rpm;
        file.friction = self.friction;
    }
}

/// A rotor's drive: at most one of `spin_accel`, `torque`, `torque_table` and `mode = "free"`.
fn drive(table: &KeyPath, doc: &RotorFile) -> Checked<RotorDrive> {
    const DRIVES: [&str; 4] = ["spin_accel", "torque", "torque_table", "mode"];
    let given = doc.given();
    let mut present = given.into_iter().filter(|k| DRIVES.contains(k));
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
                profile: Profile::read(table, &doc.profile_keys(), "a sine torque")?,
            },
            (_, _, Some(file), _) => RotorDrive::Table(file.clone()),
            (_, _, _, Some(WheelMode::Free)) => RotorDrive::Free,
            _ => RotorDrive::ConstantSpin,
        },
    )
}
