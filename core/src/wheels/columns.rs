//! A body's wheels' columns, written after all others: per wheel `<name>_spin` (rad/s), `<name>_h` (N·m·s) and
//! `<name>_torque` (N·m), and under control `<name>_torque_cmd` and `<name>_friction` (N·m).

use std::sync::Arc;

use std::borrow::Cow;

use super::gyrostat::Gyrostat;
use super::rows::PER_WHEEL;
use crate::sample::{Column, ColumnGroup, Sample};

/// The columns' suffixes, units and meanings: the first three for every rotor, all five under control.
const SUFFIXES: [(&str, &str, &str); 5] = [
    ("spin", "rad/s", "rotor spin relative to the body"),
    (
        "h",
        "N*m*s",
        "rotor's axial moment of momentum J (a.omega + spin)",
    ),
    ("torque", "N*m", "motor torque on the rotor"),
    (
        "torque_cmd",
        "N*m",
        "motor torque commanded (before the limits)",
    ),
    ("friction", "N*m", "friction torque on the rotor"),
];

/// The columns of rotors named `names`, in order: `<name>_spin`, `<name>_h`, `<name>_torque`, and with
/// `controlled` `<name>_torque_cmd` and `<name>_friction`.
///
/// ```
/// let columns = eulerdyn::wheels::rotor_columns(&["wheel".to_string()], true);
/// assert_eq!(columns[0].name, "wheel_spin");
/// assert_eq!(columns.len(), 5);
/// ```
pub fn rotor_columns(names: &[String], controlled: bool) -> Vec<Column> {
    let per_rotor = if controlled { 5 } else { 3 };
    (names.iter())
        .flat_map(|name| {
            SUFFIXES[..per_rotor]
                .iter()
                .map(move |&(suffix, unit, meaning)| Column {
                    name: Cow::Owned(format!("{name}_{suffix}")),
                    unit,
                    meaning,
                })
        })
        .collect()
}

/// The wheels' column group ([`rotor_columns`]), whose values come from each row's wheel values
/// ([`super::RotorRows`]).
///
/// ```
/// let group = eulerdyn::wheels::columns(&["a".to_string(), "b".to_string()], false);
/// assert_eq!(group.columns[3].name, "b_spin");
/// ```
pub fn columns(names: &[String], controlled: bool) -> ColumnGroup {
    ColumnGroup {
        name: "rotors",
        columns: rotor_columns(names, controlled),
        values: if controlled {
            Arc::new(wheel_values::<5>)
        } else {
            Arc::new(wheel_values::<3>)
        },
    }
}

impl Gyrostat {
    /// The wheels' columns ([`columns`]): with each wheel's command and friction when some wheel is under
    /// control ([`Gyrostat::controlled`]).
    pub fn columns(&self) -> ColumnGroup {
        let names: Vec<String> = self.rotors().iter().map(|r| r.name.clone()).collect();
        columns(&names, self.controlled())
    }
}

/// `WIDTH` values for each wheel the columns name (the first `WIDTH` of its [`PER_WHEEL`]), NaN for a wheel the
/// row lacks.
fn wheel_values<const WIDTH: usize>(s: &Sample, columns: &[Column], out: &mut Vec<f64>) {
    let values = s
        .capability_values
        .as_ref()
        .map_or(&[][..], |v| v.as_slice());
    for k in 0..columns.len() / WIDTH {
        match values.get(k * PER_WHEEL..k * PER_WHEEL + WIDTH) {
            Some(wheel) => out.extend_from_slice(wheel),
            None => out.extend([f64::NAN; WIDTH]),
        }
    }
}
