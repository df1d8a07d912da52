//! One row of a run: the kinetic state and moment at a time, and which optional columns a run writes.

use std::borrow::Cow;
use std::sync::Arc;

use nalgebra::UnitQuaternion;

use crate::frames::{BodyAxes, SpaceAxes, Vector};

/// The state of the body at one output time. Vectors carry their axes in their type and their name: `_b` body
/// axes ([`BodyAxes`]), `_s` space axes ([`SpaceAxes`]). H and M are about the moment center O, named by `_o_`:
/// the mass center C of a free body, the fixed pivot, or the fixed axis's point.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Sample {
    /// Time (s).
    pub t: f64,
    /// Attitude, body → space.
    pub q: UnitQuaternion<f64>,
    /// Angular velocity (rad/s).
    pub omega_b: Vector<BodyAxes>,
    /// Angular velocity in space axes (rad/s).
    pub omega_s: Vector<SpaceAxes>,
    /// Moment of momentum H_O about the moment center O (kg·m²/s).
    pub h_o_b: Vector<BodyAxes>,
    /// H_O in space axes.
    pub h_o_s: Vector<SpaceAxes>,
    /// Resultant external moment M_O about the moment center O (N·m).
    pub m_o_b: Vector<BodyAxes>,
    /// M_O in space axes.
    pub m_o_s: Vector<SpaceAxes>,
    /// Kinetic energy T (J): ½ ω·H for a rigid body; with wheels or moving masses, theirs included.
    pub energy: f64,
    /// Prescribed motion: angle turned about the fixed axis (rad).
    pub theta: Option<f64>,
    /// Prescribed motion with C off the axis: the required force F = m a_C (N, space axes).
    pub f_s: Option<Vector<SpaceAxes>>,
    /// Prescribed motion: H_O obtained by integrating Ḣ_O = M_O numerically (kg·m²/s, space axes).
    pub h_o_s_integrated: Option<Vector<SpaceAxes>>,
    /// Rotation about a fixed axis: what the support (bearings and drive) supplies.
    pub support: Option<SupportLoads>,
    /// With gravity: the potential energy V = −m g·r_C, r_C from the moment center in space axes (J).
    pub potential: Option<f64>,
    /// What a capability with state of its own adds to the row (a body's wheels: each one's spin, momentum and
    /// torques), in the order its column group reads them; its folder gives the typed view
    /// (`wheels::RotorRows::of`).
    pub capability_values: Option<CapabilityValues>,
}

impl Sample {
    /// The row of a body that only turns, from its attitude q (body → space), ω_b, H_O about the moment center O in
    /// both axes and the applied moment M_O in both axes: ω_s = R ω_b, energy T = ½ ω·H_O; no optional column.
    pub fn rigid(
        t: f64,
        q: UnitQuaternion<f64>,
        omega_b: Vector<BodyAxes>,
        (h_o_b, h_o_s): (Vector<BodyAxes>, Vector<SpaceAxes>),
        (m_o_b, m_o_s): (Vector<BodyAxes>, Vector<SpaceAxes>),
    ) -> Self {
        Sample {
            t,
            q,
            omega_b,
            omega_s: omega_b.in_space(&q),
            h_o_b,
            h_o_s,
            m_o_b,
            m_o_s,
            energy: 0.5 * omega_b.dot(&h_o_b),
            theta: None,
            f_s: None,
            h_o_s_integrated: None,
            support: None,
            potential: None,
            capability_values: None,
        }
    }
}

/// The values a capability with state of its own adds to one row: at most [`CapabilityValues::CAPACITY`] numbers,
/// written by the capability's row and read back by its column group (a fixed-size array, so a row stays `Copy`
/// and costs no allocation).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct CapabilityValues {
    len: usize,
    values: [f64; CapabilityValues::CAPACITY],
}

impl CapabilityValues {
    /// The most values a row holds (five for each of four wheels).
    pub const CAPACITY: usize = 20;

    /// The values `values`, or `None` when there are more than [`Self::CAPACITY`].
    ///
    /// ```
    /// use eulerdyn::sample::CapabilityValues;
    /// let v = CapabilityValues::new(&[1.0, 2.0]).unwrap();
    /// assert_eq!(v.as_slice(), &[1.0, 2.0]);
    /// assert!(CapabilityValues::new(&[0.0; 21]).is_none());
    /// ```
    pub fn new(values: &[f64]) -> Option<Self> {
        let mut all = [0.0; Self::CAPACITY];
        all.get_mut(..values.len())?.copy_from_slice(values);
        Some(Self {
            len: values.len(),
            values: all,
        })
    }

    /// The values, in the order they were given.
    pub fn as_slice(&self) -> &[f64] {
        &self.values[..self.len]
    }
}

/// What the support of a body turning about a fixed axis supplies: the force F_sup = m a_C − Σ F_effects, the
/// moment about the axis M_drive = M_sup·u (M_sup = dH/dt − Σ M_effects), and, with two bearings, the force each
/// applies to the body.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SupportLoads {
    /// θ̇ (rad/s).
    pub theta_dot: f64,
    /// θ̈ (rad/s²).
    pub theta_ddot: f64,
    /// Force the support applies to the body (N, space axes).
    pub f_sup_s: Vector<SpaceAxes>,
    /// Moment the support (bearings and drive) applies about the axis point, M_sup = dH/dt − Σ M_effects (N·m,
    /// space axes): with `f_sup_s`, the support's share of the resultant.
    pub m_sup_s: Vector<SpaceAxes>,
    /// Moment about the axis that the drive supplies, M_sup·u (N·m).
    pub m_drive: f64,
    /// The bearings' forces on the body, where the scene places two bearings.
    pub bearings: Option<BearingLoads>,
    /// The carrier's rate Ω_c (rad/s, space axes), when the axis is in a turning carrier.
    pub omega_c_s: Option<Vector<SpaceAxes>>,
}

/// The forces bearings A and B apply to the body (N): R_A + R_B = F_sup, r_A × R_A + r_B × R_B = M_sup⊥.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct BearingLoads {
    /// R_A in space axes.
    pub r_a_s: Vector<SpaceAxes>,
    /// R_B in space axes.
    pub r_b_s: Vector<SpaceAxes>,
    /// R_A in body axes.
    pub r_a_b: Vector<BodyAxes>,
    /// R_B in body axes.
    pub r_b_b: Vector<BodyAxes>,
}

/// Which optional columns a run writes (fixed for the whole run): groups of columns after the base ones, each
/// built by the capability that writes it — an axis motion's (`crate::motion::axis_columns`), gravity's potential
/// (`crate::effects::potential_columns`), a carrier's rate (`crate::motion::carrier::columns`), a body's wheels
/// (`crate::wheels::columns`) — in the order the scene composes them (`crate::scene::Scene::run_columns`).
#[derive(Debug, Clone, PartialEq, Eq, Default)]
pub struct ColumnSet {
    /// The groups, in the order of their columns.
    pub groups: Vec<ColumnGroup>,
}

/// Columns a capability adds to a run ([`ColumnSet::groups`]), and how their values are read from a row:
/// `values(sample, columns, out)` appends one value per column, NaN where the sample lacks one. Two groups are
/// equal when they write the same columns.
#[derive(Clone)]
pub struct ColumnGroup {
    /// What adds it, as the book's column reference names it (`theta`, `support`, `potential`, `rotors`…).
    pub name: &'static str,
    /// The columns, in order.
    pub columns: Vec<Column>,
    /// Appends one row's values of `columns` (a function of the row, and of what the group was made with: an
    /// orbit's LVLH frame).
    pub values: RowValues,
}

/// How a [`ColumnGroup`] reads one row's values.
pub type RowValues = Arc<dyn Fn(&Sample, &[Column], &mut Vec<f64>) + Send + Sync>;

impl std::fmt::Debug for ColumnGroup {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        (f.debug_struct("ColumnGroup"))
            .field("name", &self.name)
            .field("columns", &self.columns)
            .finish_non_exhaustive()
    }
}

impl PartialEq for ColumnGroup {
    fn eq(&self, other: &Self) -> bool {
        self.columns == other.columns
    }
}

impl Eq for ColumnGroup {}

/// A column's name, unit and meaning.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Column {
    /// The header: fixed, or made from a rotor's name.
    pub name: Cow<'static, str>,
    /// SI unit.
    pub unit: &'static str,
    /// What it is (frame, point).
    pub meaning: &'static str,
}

impl Column {
    /// A column whose name is fixed.
    ///
    /// ```
    /// use eulerdyn::sample::Column;
    /// const THETA: Column = Column::fixed("theta", "rad", "angle turned about the fixed axis");
    /// assert_eq!(THETA.name, "theta");
    /// ```
    pub const fn fixed(name: &'static str, unit: &'static str, meaning: &'static str) -> Self {
        Column {
            name: Cow::Borrowed(name),
            unit,
            meaning,
        }
    }
}

/// The columns every run writes, in the contract's order.
pub const BASE_COLUMNS: [Column; 25] = [
    Column::fixed("t", "s", "time"),
    Column::fixed("q_w", "1", "attitude quaternion body->space, scalar part"),
    Column::fixed("q_x", "1", "attitude quaternion, x"),
    Column::fixed("q_y", "1", "attitude quaternion, y"),
    Column::fixed("q_z", "1", "attitude quaternion, z"),
    Column::fixed("omega_b_x", "rad/s", "angular velocity, body axes"),
    Column::fixed("omega_b_y", "rad/s", "angular velocity, body axes"),
    Column::fixed("omega_b_z", "rad/s", "angular velocity, body axes"),
    Column::fixed("omega_s_x", "rad/s", "angular velocity, space axes"),
    Column::fixed("omega_s_y", "rad/s", "angular velocity, space axes"),
    Column::fixed("omega_s_z", "rad/s", "angular velocity, space axes"),
    Column::fixed(
        "H_b_x",
        "kg*m^2/s",
        "moment of momentum about the moment center, body axes",
    ),
    Column::fixed(
        "H_b_y",
        "kg*m^2/s",
        "moment of momentum about the moment center, body axes",
    ),
    Column::fixed(
        "H_b_z",
        "kg*m^2/s",
        "moment of momentum about the moment center, body axes",
    ),
    Column::fixed(
        "H_s_x",
        "kg*m^2/s",
        "moment of momentum about the moment center, space axes",
    ),
    Column::fixed(
        "H_s_y",
        "kg*m^2/s",
        "moment of momentum about the moment center, space axes",
    ),
    Column::fixed(
        "H_s_z",
        "kg*m^2/s",
        "moment of momentum about the moment center, space axes",
    ),
    Column::fixed(
        "M_b_x",
        "N*m",
        "external moment about the moment center, body axes",
    ),
    Column::fixed(
        "M_b_y",
        "N*m",
        "external moment about the moment center, body axes",
    ),
    Column::fixed(
        "M_b_z",
        "N*m",
        "external moment about the moment center, body axes",
    ),
    Column::fixed(
        "M_s_x",
        "N*m",
        "external moment about the moment center, space axes",
    ),
    Column::fixed(
        "M_s_y",
        "N*m",
        "external moment about the moment center, space axes",
    ),
    Column::fixed(
        "M_s_z",
        "N*m",
        "external moment about the moment center, space axes",
    ),
    Column::fixed(
        "energy",
        "J",
        "kinetic energy T (1/2 omega.H for a rigid body; wheels and moving masses included)",
    ),
    Column::fixed("H_norm", "kg*m^2/s", "|H|"),
];

impl ColumnSet {
    /// All columns of a run, in order: the base columns, then the groups'.
    pub fn columns(&self) -> Vec<Column> {
        let mut cols = BASE_COLUMNS.to_vec();
        for group in &self.groups {
            cols.extend_from_slice(&group.columns);
        }
        cols
    }

    /// The values of one row, in column order. A sample lacking a value its column set asks for writes NaN there
    /// (the simulation never produces such a sample; the writer refuses rows with non-finite values).
    pub fn values(&self, s: &Sample, out: &mut Vec<f64>) {
        out.clear();
        out.push(s.t);
        out.extend([s.q.w, s.q.i, s.q.j, s.q.k]);
        for v in [
            *s.omega_b, *s.omega_s, *s.h_o_b, *s.h_o_s, *s.m_o_b, *s.m_o_s,
        ] {
            out.extend(v.iter());
        }
        out.push(s.energy);
        out.push(s.h_o_s.norm());
        for group in &self.groups {
            (group.values)(s, &group.columns, out);
        }
    }

    /// The values of one row, in column order, refusing a non-finite one (the CSV writer and the Python module
    /// write only finite rows: the simulation must stop before it produces another).
    pub fn finite_values(&self, s: &Sample, out: &mut Vec<f64>) -> Result<(), NonFinite> {
        self.values(s, out);
        match out.iter().position(|v| !v.is_finite()) {
            None => Ok(()),
            Some(i) => Err(NonFinite {
                column: self.columns()[i].name.to_string(),
                value: out[i],
                t: s.t,
            }),
        }
    }
}

/// A row with a non-finite value: its column, the value and the row's time.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[error("non-finite value {value} in column {column} at t = {t}")]
pub struct NonFinite {
    /// The column's name.
    pub column: String,
    /// The value (NaN or infinite).
    pub value: f64,
    /// The row's time (s).
    pub t: f64,
}
