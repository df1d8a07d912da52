//! The columns of a body that changes shape: its inertia about C(t) (`I_b_xx` … `I_b_yz`), C itself when it moves
//! (`C_b_x` … `C_b_z`), the internal drives' power `P_internal`, and each moving mass's position
//! (`<name>_x`, `<name>_y`, `<name>_z`) — all functions of the row's time and state.

use std::borrow::Cow;
use std::sync::Arc;

use super::ShapeChange;
use super::path::Side;
use super::system::{internal_power, six_entries};
use crate::sample::{Column, ColumnGroup, Sample};

const INERTIA: [Column; 6] = [
    Column::fixed(
        "I_b_xx",
        "kg*m^2",
        "inertia about the system's C, body axes",
    ),
    Column::fixed(
        "I_b_yy",
        "kg*m^2",
        "inertia about the system's C, body axes",
    ),
    Column::fixed(
        "I_b_zz",
        "kg*m^2",
        "inertia about the system's C, body axes",
    ),
    Column::fixed(
        "I_b_xy",
        "kg*m^2",
        "product of inertia (tensor entry, -sum m x y), body axes",
    ),
    Column::fixed(
        "I_b_xz",
        "kg*m^2",
        "product of inertia (tensor entry, -sum m x z), body axes",
    ),
    Column::fixed(
        "I_b_yz",
        "kg*m^2",
        "product of inertia (tensor entry, -sum m y z), body axes",
    ),
];

const CENTER: [Column; 3] = [
    Column::fixed(
        "C_b_x",
        "m",
        "the system's centre of mass from the reference origin, body axes",
    ),
    Column::fixed(
        "C_b_y",
        "m",
        "the system's centre of mass from the reference origin, body axes",
    ),
    Column::fixed(
        "C_b_z",
        "m",
        "the system's centre of mass from the reference origin, body axes",
    ),
];

const POSITION: [(&str, &str); 3] = [
    (
        "x",
        "the moving mass's position from the reference origin, body x",
    ),
    (
        "y",
        "the moving mass's position from the reference origin, body y",
    ),
    (
        "z",
        "the moving mass's position from the reference origin, body z",
    ),
];

const POWER: Column = Column::fixed(
    "P_internal",
    "W",
    "power the internal drives put into the motion, d(energy)/dt - M.omega",
);

impl ShapeChange {
    /// The column group: the inertia, C when it moves, `P_internal`, the masses' positions.
    pub fn columns(self: &Arc<Self>) -> ColumnGroup {
        let mut columns = INERTIA.to_vec();
        if self.center_moves() {
            columns.extend(CENTER);
        }
        columns.push(POWER);
        for mass in self.masses() {
            for (axis, meaning) in POSITION {
                columns.push(Column {
                    name: Cow::Owned(format!("{}_{axis}", mass.name)),
                    unit: "m",
                    meaning,
                });
            }
        }
        let shape = Arc::clone(self);
        ColumnGroup {
            name: "shape_change",
            columns,
            values: Arc::new(move |s, _, out| shape.row_values(s, out)),
        }
    }

    /// One row's values of [`Self::columns`].
    fn row_values(&self, s: &Sample, out: &mut Vec<f64>) {
        let state = self.at(s.t, Side::After);
        out.extend(six_entries(&state.inertia_b));
        if self.center_moves() {
            out.extend(state.c_b.iter());
        }
        out.push(internal_power(&state, &s.omega_b, &s.h_o_b, &s.m_o_b));
        for mass in self.masses() {
            out.extend(mass.path.at(s.t, Side::After).r.iter());
        }
    }
}
