//! The columns an axis motion (a prescribed fixed axis, a hinge) writes after the base ones: θ; the force
//! m a_C the axis must supply when C is off it; H_s integrated from dH_s/dt = M_s (a prescribed motion's check of
//! eq. 8.10); the support's θ̇, θ̈, force and drive moment; the bearings' forces; and, after gravity's potential
//! (appended in the third round, so that earlier columns keep their places), the support's moment about A.

use std::sync::Arc;

use nalgebra::Vector3;

use crate::frames::Vector;
use crate::sample::{Column, ColumnGroup, Sample};

/// Which of an axis motion's optional columns a run writes (θ and the support's are always written).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct AxisColumns {
    /// `F_s_*`: C is off the axis.
    pub force: bool,
    /// `H_s_int_*`: a prescribed motion.
    pub h_s_integrated: bool,
    /// `R_A_s_*` … `R_B_b_*`: the scene places two bearings.
    pub bearings: bool,
}

impl AxisColumns {
    /// Every one of them (the columns a sweep may summarise when no scene of it builds).
    pub const ALL: AxisColumns = AxisColumns {
        force: true,
        h_s_integrated: true,
        bearings: true,
    };

    /// The groups written before gravity's potential: θ, the force, H_s integrated, the support, the bearings.
    ///
    /// ```
    /// use eulerdyn::motion::axis_columns::AxisColumns;
    /// let names: Vec<&str> = AxisColumns::ALL.leading().iter().map(|g| g.name).collect();
    /// assert_eq!(names, ["theta", "force", "h_s_integrated", "support", "bearings"]);
    /// ```
    pub fn leading(self) -> Vec<ColumnGroup> {
        let mut groups = vec![group("theta", &[THETA_COLUMN], theta)];
        if self.force {
            groups.push(group("force", &FORCE_COLUMNS, force));
        }
        if self.h_s_integrated {
            groups.push(group("h_s_integrated", &H_INT_COLUMNS, h_s_integrated));
        }
        groups.push(group("support", &SUPPORT_COLUMNS, support));
        if self.bearings {
            groups.push(group("bearings", &BEARING_COLUMNS, bearings));
        }
        groups
    }

    /// The group written after gravity's potential: the support's moment about A, `M_sup_s_*`.
    pub fn trailing(self) -> ColumnGroup {
        group("support", &SUPPORT_MOMENT_COLUMNS, support_moment)
    }
}

/// A group of fixed columns.
fn group(
    name: &'static str,
    columns: &[Column],
    values: fn(&Sample, &[Column], &mut Vec<f64>),
) -> ColumnGroup {
    ColumnGroup {
        name,
        columns: columns.to_vec(),
        values: Arc::new(values),
    }
}

/// Three NaN where a sample lacks a vector its columns ask for.
const NAN3: Vector3<f64> = Vector3::new(f64::NAN, f64::NAN, f64::NAN);

fn theta(s: &Sample, _: &[Column], out: &mut Vec<f64>) {
    out.push(s.theta.unwrap_or(f64::NAN));
}

fn force(s: &Sample, _: &[Column], out: &mut Vec<f64>) {
    out.extend(s.f_s.map_or(NAN3, Vector::into_inner).iter());
}

fn h_s_integrated(s: &Sample, _: &[Column], out: &mut Vec<f64>) {
    out.extend(s.h_o_s_integrated.map_or(NAN3, Vector::into_inner).iter());
}

fn support(s: &Sample, _: &[Column], out: &mut Vec<f64>) {
    let support = s.support;
    out.push(support.map_or(f64::NAN, |l| l.theta_dot));
    out.push(support.map_or(f64::NAN, |l| l.theta_ddot));
    out.extend(support.map_or(NAN3, |l| *l.f_sup_s).iter());
    out.push(support.map_or(f64::NAN, |l| l.m_drive));
}

fn bearings(s: &Sample, _: &[Column], out: &mut Vec<f64>) {
    let loads = s.support.and_then(|l| l.bearings);
    for v in [
        loads.map_or(NAN3, |b| *b.r_a_s),
        loads.map_or(NAN3, |b| *b.r_b_s),
        loads.map_or(NAN3, |b| *b.r_a_b),
        loads.map_or(NAN3, |b| *b.r_b_b),
    ] {
        out.extend(v.iter());
    }
}

fn support_moment(s: &Sample, _: &[Column], out: &mut Vec<f64>) {
    out.extend(s.support.map_or(NAN3, |l| *l.m_sup_s).iter());
}

const THETA_COLUMN: Column = Column::fixed("theta", "rad", "angle turned about the fixed axis");
const FORCE_COLUMNS: [Column; 3] = [
    Column::fixed("F_s_x", "N", "required force m a_C, space axes"),
    Column::fixed("F_s_y", "N", "required force m a_C, space axes"),
    Column::fixed("F_s_z", "N", "required force m a_C, space axes"),
];
const H_INT_COLUMNS: [Column; 3] = [
    Column::fixed(
        "H_s_int_x",
        "kg*m^2/s",
        "H_s integrated from dH_s/dt = M_s, space axes",
    ),
    Column::fixed(
        "H_s_int_y",
        "kg*m^2/s",
        "H_s integrated from dH_s/dt = M_s, space axes",
    ),
    Column::fixed(
        "H_s_int_z",
        "kg*m^2/s",
        "H_s integrated from dH_s/dt = M_s, space axes",
    ),
];

const SUPPORT_COLUMNS: [Column; 6] = [
    Column::fixed("theta_dot", "rad/s", "rate about the fixed axis"),
    Column::fixed(
        "theta_ddot",
        "rad/s^2",
        "angular acceleration about the fixed axis",
    ),
    Column::fixed(
        "F_sup_s_x",
        "N",
        "force of the support on the body, space axes",
    ),
    Column::fixed(
        "F_sup_s_y",
        "N",
        "force of the support on the body, space axes",
    ),
    Column::fixed(
        "F_sup_s_z",
        "N",
        "force of the support on the body, space axes",
    ),
    Column::fixed(
        "M_drive",
        "N*m",
        "moment about the axis that the drive supplies",
    ),
];

/// One bearing force column: `R_{bearing}_{axes}_{component}`.
const fn bearing(name: &'static str, meaning: &'static str) -> Column {
    Column::fixed(name, "N", meaning)
}

const BEARING_COLUMNS: [Column; 12] = [
    bearing("R_A_s_x", "force of bearing A on the body, space axes"),
    bearing("R_A_s_y", "force of bearing A on the body, space axes"),
    bearing("R_A_s_z", "force of bearing A on the body, space axes"),
    bearing("R_B_s_x", "force of bearing B on the body, space axes"),
    bearing("R_B_s_y", "force of bearing B on the body, space axes"),
    bearing("R_B_s_z", "force of bearing B on the body, space axes"),
    bearing("R_A_b_x", "force of bearing A on the body, body axes"),
    bearing("R_A_b_y", "force of bearing A on the body, body axes"),
    bearing("R_A_b_z", "force of bearing A on the body, body axes"),
    bearing("R_B_b_x", "force of bearing B on the body, body axes"),
    bearing("R_B_b_y", "force of bearing B on the body, body axes"),
    bearing("R_B_b_z", "force of bearing B on the body, body axes"),
];

const SUPPORT_MOMENT_COLUMNS: [Column; 3] = [
    Column::fixed(
        "M_sup_s_x",
        "N*m",
        "moment of the support (bearings and drive) about the axis point, space axes",
    ),
    Column::fixed(
        "M_sup_s_y",
        "N*m",
        "moment of the support (bearings and drive) about the axis point, space axes",
    ),
    Column::fixed(
        "M_sup_s_z",
        "N*m",
        "moment of the support (bearings and drive) about the axis point, space axes",
    ),
];
