//! `[[body.rotor]]`: wheels spinning inside a freely turning body (a gyrostat).

use nalgebra::{Unit, Vector3};

use super::super::spec::{BodySpec, RotorDrive, RotorSpec};
use super::effect::validate_profile;
use super::{Checked, Invalid, KeyPath, finite, invalid, positive, vector};
use crate::effects::TorqueSum;
use crate::motion::free::FreeBody;
use crate::motion::gyrostat::{Drive, Gyrostat, Rotor};
use crate::sample::MAX_ROTORS;

/// The gyrostat of a free `body` about its moment center with the scene's rotors; `None` without rotors.
pub(super) fn validate_rotors(doc: &BodySpec, body: &FreeBody) -> Checked<Option<Box<Gyrostat>>> {
    if doc.rotor.is_empty() {
        return Ok(None);
    }
    let table = || KeyPath::root().key("body").key("rotor");
    if doc.rotor.len() > MAX_ROTORS {
        return invalid(
            table().index(MAX_ROTORS),
            format!("at most {MAX_ROTORS} rotors, got {}", doc.rotor.len()),
        );
    }
    let mut rotors: Vec<Rotor> = Vec::with_capacity(doc.rotor.len());
    for (index, spec) in doc.rotor.iter().enumerate() {
        let rotor = validate_rotor(index, spec)?;
        if rotors.iter().any(|r| r.name == rotor.name) {
            return invalid(
                table().index(index).key("name"),
                format!(
                    "the rotor name `{}` is used twice: its columns would repeat",
                    rotor.name
                ),
            );
        }
        rotors.push(rotor);
    }
    Gyrostat::new(*body, rotors)
        .map(|g| Some(Box::new(g)))
        .map_err(|e| Invalid {
            key: table(),
            problem: e.to_string(),
        })
}

fn validate_rotor(index: usize, spec: &RotorSpec) -> Checked<Rotor> {
    let table = KeyPath::root().key("body").key("rotor").index(index);
    let key = |name: &str| table.clone().key(name);
    let name = spec.name.clone().unwrap_or_else(|| format!("rotor{index}"));
    if name.is_empty() || !name.chars().all(|c| c.is_ascii_alphanumeric() || c == '_') {
        return invalid(
            key("name"),
            format!("`{name}` is not a column prefix: use letters, digits and _"),
        );
    }
    let axis = vector(key("axis"), spec.axis, "direction")?;
    let norm = axis.norm();
    if !(norm > 1e-300 && norm.is_finite()) {
        return invalid(
            key("axis"),
            "the axis is the zero vector; give the wheel's spin axis in body axes",
        );
    }
    vector(key("at"), spec.at, "m")?;
    Ok(Rotor {
        name,
        axis_b: Unit::new_unchecked(axis / norm),
        inertia: positive(key("inertia"), spec.inertia, "kg*m^2")?,
        spin0: finite(key("spin"), spec.spin, "rad/s")?,
        drive: match spec.drive {
            RotorDrive::ConstantSpin => Drive::Accel(0.0),
            RotorDrive::SpinAccel(alpha) => {
                Drive::Accel(finite(key("spin_accel"), alpha, "rad/s^2")?)
            }
            RotorDrive::Torque { value, profile } => {
                let value = finite(key("torque"), value, "N*m")?;
                let mut tau = TorqueSum::default();
                tau.add(
                    &Vector3::new(value, 0.0, 0.0),
                    &validate_profile(&table, &profile)?,
                );
                Drive::Torque(tau)
            }
        },
    })
}
