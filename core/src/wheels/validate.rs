//! `[[body.rotor]]` validated: each wheel's name, axis, J, spin, drive, imbalance, limits and friction, and the
//! gyrostat they make with a freely turning body.

use std::sync::Arc;

use nalgebra::{Unit, Vector3};

use super::RotorSpec;
use super::gyrostat::{Drive, Gyrostat, Imbalance, Rotor};
use super::read_wheel_table;
use super::spec::RotorDrive;
use super::{MAX_ROTORS, RPM};
use crate::effects::TorqueSum;
use crate::frames::Vector;
use crate::keys::{Checked, Invalid, KeyPath, finite, invalid, positive, vector};
use crate::motion::free::FreeBody;

/// The gyrostat of a free `body` about its moment center (at `center_b` from the reference origin, body axes)
/// with the scene's rotors `specs` (`[[body.rotor]]`); `None` without rotors.
pub(crate) fn validate_rotors(
    specs: &[RotorSpec],
    body: &FreeBody,
    center_b: &Vector3<f64>,
) -> Checked<Option<Box<Gyrostat>>> {
    if specs.is_empty() {
        return Ok(None);
    }
    let table = || KeyPath::root().key("body").key("rotor");
    if specs.len() > MAX_ROTORS {
        return invalid(
            table().index(MAX_ROTORS),
            format!("at most {MAX_ROTORS} rotors, got {}", specs.len()),
        );
    }
    let mut rotors: Vec<Rotor> = Vec::with_capacity(specs.len());
    for (index, spec) in specs.iter().enumerate() {
        let rotor = validate_rotor(index, spec, center_b)?;
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

/// One g·mm in kg·m, one g·mm² in kg·m².
const GRAM_MM: f64 = 1e-6;
const GRAM_MM2: f64 = 1e-9;

fn validate_rotor(index: usize, spec: &RotorSpec, center_b: &Vector3<f64>) -> Checked<Rotor> {
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
    let at_b = vector(key("at"), spec.at, "m")?;
    let axis_b = Unit::new_unchecked(axis / norm);
    let not_negative = |name: &str, v: f64, unit: &str| -> Checked<f64> {
        let v = finite(key(name), v, unit)?;
        if v < 0.0 {
            return invalid(key(name), format!("must be >= 0 ({unit}), got {v}"));
        }
        Ok(v)
    };
    let static_gmm = not_negative("imbalance_static_gmm", spec.imbalance_static_gmm, "g*mm")?;
    let dynamic_gmm2 = not_negative(
        "imbalance_dynamic_gmm2",
        spec.imbalance_dynamic_gmm2,
        "g*mm^2",
    )?;
    let imbalance = (static_gmm > 0.0 || dynamic_gmm2 > 0.0).then(|| {
        Imbalance::new(
            static_gmm * GRAM_MM,
            dynamic_gmm2 * GRAM_MM2,
            Vector::new(at_b - center_b),
            &axis_b,
        )
    });
    let spin0 = finite(key("spin"), spec.spin, "rad/s")?;
    let control = spec.wheel.validate(&table, motorless(&spec.drive))?;
    if spin0.abs() > control.max_speed * (1.0 + 1e-12) {
        // The limit holds the spin at ±max_speed; a wheel that starts beyond it would be kept there silently.
        return invalid(
            key("spin"),
            format!(
                "the initial spin {spin0} rad/s ({:.1} rpm) is beyond max_speed_rpm = {}: start the wheel within \
                 its limit",
                spin0 / RPM,
                spec.wheel.max_speed_rpm.unwrap_or(f64::INFINITY)
            ),
        );
    }
    Ok(Rotor {
        name,
        axis_b,
        imbalance,
        inertia: positive(key("inertia"), spec.inertia, "kg*m^2")?,
        spin0,
        control,
        drive: match spec.drive {
            RotorDrive::ConstantSpin => Drive::Accel(0.0),
            RotorDrive::Free => Drive::Free,
            // The table is read here, once: its errors name the file and the row.
            RotorDrive::Table(ref file) => {
                Drive::Table(Arc::new(read_wheel_table(file).map_err(|problem| {
                    Invalid {
                        key: key("torque_table"),
                        problem,
                    }
                })?))
            }
            RotorDrive::SpinAccel(alpha) => {
                Drive::Accel(finite(key("spin_accel"), alpha, "rad/s^2")?)
            }
            RotorDrive::Torque { value, ref profile } => {
                let value = finite(key("torque"), value, "N*m")?;
                let mut tau = TorqueSum::default();
                tau.add(&Vector3::new(value, 0.0, 0.0), &profile.checked(&table)?);
                Drive::Torque(tau)
            }
        },
    })
}

/// Why a wheel with this drive has no motor that a limit could act on, if it has none.
fn motorless(drive: &RotorDrive) -> Option<&'static str> {
    match drive {
        RotorDrive::SpinAccel(_) => Some("its spin is prescribed by `spin_accel`"),
        RotorDrive::Free => Some("`mode = \"free\"` has no motor"),
        _ => None,
    }
}
