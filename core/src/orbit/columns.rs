//! The columns of a scene with an orbit: the body's attitude as 3-2-1 angles from the LVLH frame.

use std::sync::Arc;

use super::CircularOrbit;
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
