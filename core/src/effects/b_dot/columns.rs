//! B-dot's columns: the commanded dipole m_b (A·m²), clipped.

use std::sync::Arc;

use super::BDot;
use crate::sample::{Column, ColumnGroup};

/// `m_b_x`, `m_b_y`, `m_b_z` (A·m²): the magnetorquers' dipole at each row ([`BDot::field_and_dipole_b`]).
pub(super) fn dipole_columns(b_dot: BDot) -> ColumnGroup {
    ColumnGroup {
        name: "b_dot",
        columns: DIPOLE_COLUMNS.to_vec(),
        values: Arc::new(move |s, _, out| {
            let (_, m_b) = b_dot.field_and_dipole_b(s.t, &s.q, &s.omega_b);
            out.extend(m_b.iter())
        }),
    }
}

const DIPOLE_COLUMNS: [Column; 3] = [
    Column::fixed(
        "m_b_x",
        "A*m^2",
        "the magnetorquers' dipole, body axes (B-dot, clipped)",
    ),
    Column::fixed(
        "m_b_y",
        "A*m^2",
        "the magnetorquers' dipole, body axes (B-dot, clipped)",
    ),
    Column::fixed(
        "m_b_z",
        "A*m^2",
        "the magnetorquers' dipole, body axes (B-dot, clipped)",
    ),
];
