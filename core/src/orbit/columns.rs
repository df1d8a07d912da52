//! The columns of a scene with an orbit: the body's attitude as 3-2-1 angles from the LVLH frame.

use std::sync::Arc;

use super::{CircularOrbit, DipoleField};
use crate::sample::{Column, ColumnGroup};

/// `roll_lvlh`, `pitch_lvlh`, `yaw_lvlh` (rad): R_LVLH←body = R_z(yaw) R_y(pitch) R_x(roll) on `orbit`.
///
/// ```
/// use eulerdyn::orbit::{CircularOrbit, R_EARTH, lvlh_columns};
/// let group = lvlh_columns(CircularOrbit::new(R_EARTH + 500e3, 0.0, 0.0, 0.0));
/// assert_eq!(group.columns[1].name, "pitch_lvlh");
/// ```
pub fn lvlh_columns(orbit: CircularOrbit) -> ColumnGroup {
    ColumnGroup {
        name: "lvlh",
        columns: LVLH_COLUMNS.to_vec(),
        values: Arc::new(move |s, _, out| out.extend(orbit.lvlh_angles(s.t, &s.q))),
    }
}

/// `B_b_x`, `B_b_y`, `B_b_z` (T): the field of `field` where `orbit` has the body, in body axes.
///
/// ```
/// use eulerdyn::orbit::{CircularOrbit, DipoleField, R_EARTH, field_columns};
/// let group = field_columns(CircularOrbit::new(R_EARTH + 500e3, 0.0, 0.0, 0.0), DipoleField::new(3.12e-5, 0.0, 0.0));
/// assert_eq!(group.columns[2].name, "B_b_z");
/// ```
pub fn field_columns(orbit: CircularOrbit, field: DipoleField) -> ColumnGroup {
    ColumnGroup {
        name: "magnetic",
        columns: FIELD_COLUMNS.to_vec(),
        values: Arc::new(move |s, _, out| {
            let b_b =
                s.q.inverse_transform_vector(&field.b_s(&orbit.position_s(s.t), s.t));
            out.extend(b_b.iter())
        }),
    }
}

const FIELD_COLUMNS: [Column; 3] = [
    Column::fixed(
        "B_b_x",
        "T",
        "the Earth's magnetic field at the body, body axes",
    ),
    Column::fixed(
        "B_b_y",
        "T",
        "the Earth's magnetic field at the body, body axes",
    ),
    Column::fixed(
        "B_b_z",
        "T",
        "the Earth's magnetic field at the body, body axes",
    ),
];

const LVLH_COLUMNS: [Column; 3] = [
    Column::fixed(
        "roll_lvlh",
        "rad",
        "3-2-1 angle of the body from LVLH about x (along the velocity)",
    ),
    Column::fixed(
        "pitch_lvlh",
        "rad",
        "3-2-1 angle of the body from LVLH about y (against the orbit normal)",
    ),
    Column::fixed(
        "yaw_lvlh",
        "rad",
        "3-2-1 angle of the body from LVLH about z (to nadir)",
    ),
];
