//! The carrier's columns: its rate Ω_c (rad/s, space axes), written after the support's moment `M_sup_s_*`.

use std::sync::Arc;

use nalgebra::Vector3;

use crate::sample::{Column, ColumnGroup, Sample};

const CARRIER_COLUMNS: [Column; 3] = [
    Column::fixed(
        "Omega_c_s_x",
        "rad/s",
        "the carrier's angular velocity, space axes",
    ),
    Column::fixed(
        "Omega_c_s_y",
        "rad/s",
        "the carrier's angular velocity, space axes",
    ),
    Column::fixed(
        "Omega_c_s_z",
        "rad/s",
        "the carrier's angular velocity, space axes",
    ),
];

/// `Omega_c_s_x,Omega_c_s_y,Omega_c_s_z`: Ω_c from the support's loads of each row
/// ([`crate::sample::SupportLoads`]).
///
/// ```
/// let group = eulerdyn::motion::carrier::columns();
/// assert_eq!(group.columns[2].name, "Omega_c_s_z");
/// ```
pub fn columns() -> ColumnGroup {
    ColumnGroup {
        name: "carrier",
        columns: CARRIER_COLUMNS.to_vec(),
        values: Arc::new(omega_c_s),
    }
}

/// Ω_c of the row, NaN where it has none.
fn omega_c_s(s: &Sample, _: &[Column], out: &mut Vec<f64>) {
    let omega_c_s = s.support.and_then(|l| l.omega_c_s);
    out.extend(omega_c_s.map_or(Vector3::repeat(f64::NAN), |w| *w).iter());
}
