//! A wheel's `torque_table = "FILE.csv"`: the commanded motor torque at the rows' times, header `t,torque`,
//! interpolated linearly and zero outside the table (the torque effect's table reader, one component).

use std::path::Path;

use crate::effects::{Interpolation, TorqueTable};

/// The header of a wheel's torque table: t (s) and the commanded motor torque (N·m).
pub const WHEEL_TABLE_HEADER: [&str; 2] = ["t", "torque"];

/// Reads the wheel's table at `path`; the torque is the `x` component of the table's moment. Its errors name the
/// file and the row.
pub fn read_wheel_table(path: &Path) -> Result<TorqueTable, String> {
    TorqueTable::read_columns(path, Interpolation::Linear, &WHEEL_TABLE_HEADER)
}
