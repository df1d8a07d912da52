//! Gravity's columns: its potential energy V = −m g·r_C and the total T + V, after an axis motion's leading
//! columns (`crate::motion::axis_columns`).

use std::sync::Arc;

use crate::sample::{Column, ColumnGroup, Sample};

/// The columns a run under gravity writes, `potential` and `energy_total`.
///
/// ```
/// let group = eulerdyn::effects::potential_columns();
/// assert_eq!(group.columns[1].name, "energy_total");
/// ```
pub fn potential_columns() -> ColumnGroup {
    ColumnGroup {
        name: "potential",
        columns: POTENTIAL_COLUMNS.to_vec(),
        values: Arc::new(potential),
    }
}

/// V and T + V of the row (NaN where the sample has no V).
fn potential(s: &Sample, _: &[Column], out: &mut Vec<f64>) {
    let v = s.potential.unwrap_or(f64::NAN);
    out.push(v);
    out.push(s.energy + v);
}

const POTENTIAL_COLUMNS: [Column; 2] = [
    Column::fixed(
        "potential",
        "J",
        "potential energy of gravity -m g.r_C, r_C from the moment center",
    ),
    Column::fixed("energy_total", "J", "kinetic plus potential energy"),
];
