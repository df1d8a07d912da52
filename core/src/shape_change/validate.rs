//! A body that changes shape, validated: each moving mass's name, mass and path (its table read), or the
//! inertia table read and each row checked to be a body's inertia.

use nalgebra::{Matrix3, Vector3};

use super::ShapeChange;
use super::history::{Distribution, InertiaHistory, MovingMass};
use super::keys::{MovingMassSpec, PathSpec, ShapeChangeSpec};
use super::path::{MassPath, Side};
use crate::body::{Principal, RigidBody};
use crate::effects::read_rows;
use crate::keys::{Checked, KeyPath, finite, invalid, positive, vector};

/// The header of a moving mass's table: t (s) and its position (m, body axes).
pub const PATH_TABLE_HEADER: [&str; 4] = ["t", "x", "y", "z"];

/// The header of an inertia table: t (s) and the tensor's entries about C (kg·m², body axes).
pub const INERTIA_TABLE_HEADER: [&str; 7] = ["t", "I_xx", "I_yy", "I_zz", "I_xy", "I_xz", "I_yz"];

/// The shape change of `body` (the rest of the body, its centre `c_b` from the reference origin) as `spec` gives
/// it; `None` when it gives none. `point_masses`: whether `[body]` has rigidly attached point masses (which an
/// inertia table, the whole body's inertia, cannot take).
pub(crate) fn validate_shape_change(
    spec: &ShapeChangeSpec,
    body: &RigidBody,
    c_b: &Vector3<f64>,
    point_masses: bool,
) -> Checked<Option<ShapeChange>> {
    let key = |name: &str| KeyPath::root().key("body").key(name);
    match (&spec.inertia_table, spec.moving_mass.is_empty()) {
        (None, true) => Ok(None),
        (Some(_), false) => invalid(
            key("inertia_table"),
            "give either moving masses (`[[body.moving_mass]]`) or an inertia table, not both: the table is \
             the whole body's inertia",
        ),
        (Some(_), true) if point_masses => invalid(
            key("inertia_table"),
            "the inertia table is the whole body's inertia about C: fold the point masses into it and remove \
             `[[body.point_mass]]`",
        ),
        (Some(path), true) => {
            let history = read_inertia_table(path).map_err(|problem| crate::keys::Invalid {
                key: key("inertia_table"),
                problem,
            })?;
            let shape = ShapeChange::new(Distribution::Table { c_b: *c_b, history });
            finite_throughout(shape, key("inertia_table")).map(Some)
        }
        (None, false) => {
            let mut masses: Vec<MovingMass> = Vec::with_capacity(spec.moving_mass.len());
            for (index, m) in spec.moving_mass.iter().enumerate() {
                let mass = moving_mass(index, m)?;
                if masses.iter().any(|other| other.name == mass.name) {
                    return invalid(
                        key("moving_mass").index(index).key("name"),
                        format!(
                            "the name `{}` is used twice: its columns would repeat",
                            mass.name
                        ),
                    );
                }
                masses.push(mass);
            }
            let shape = ShapeChange::new(Distribution::Masses {
                rest_mass: body.mass(),
                rest_c_b: *c_b,
                rest_inertia_b: *body.inertia_c(),
                masses,
            });
            finite_throughout(shape, key("moving_mass")).map(Some)
        }
    }
}

/// `shape` when its distribution is finite at t = 0, on both sides of every corner and between corners (where a
/// smooth move is fastest): else the masses' sizes, paths or speeds are beyond double precision (the key `key`).
fn finite_throughout(shape: ShapeChange, key: KeyPath) -> Checked<ShapeChange> {
    let corners = shape.distribution().corners();
    let middles = corners.windows(2).map(|w| 0.5 * (w[0] + w[1]));
    let times = std::iter::once(0.0)
        .chain(corners.iter().copied())
        .chain(middles);
    for t in times {
        for side in [Side::Before, Side::After] {
            let s = shape.at(t, side);
            let values = (s.inertia_b.iter().chain(&s.inertia_dot_b).chain(&s.c_b))
                .chain(s.h_b.iter().chain(&s.h_dot_b))
                .chain([&s.energy_rel, &s.energy_rel_dot]);
            if !values.into_iter().all(|v| v.is_finite()) {
                return invalid(
                    key,
                    format!(
                        "at t = {t} s the system's inertia, the masses' relative moment of momentum or their \
                         speeds are beyond the range of double precision: give masses, positions and durations \
                         of a body's size"
                    ),
                );
            }
        }
    }
    Ok(shape)
}

/// One moving mass: its name (a column prefix), mass > 0 and path.
fn moving_mass(index: usize, spec: &MovingMassSpec) -> Checked<MovingMass> {
    let table = KeyPath::root().key("body").key("moving_mass").index(index);
    let key = |name: &str| table.clone().key(name);
    let name = spec.name.clone().unwrap_or_else(|| format!("mass{index}"));
    if name.is_empty() || !name.chars().all(|c| c.is_ascii_alphanumeric() || c == '_') {
        return invalid(
            key("name"),
            format!("`{name}` is not a column prefix: use letters, digits and _"),
        );
    }
    let mass = positive(key("mass"), spec.mass, "kg")?;
    let path = match &spec.path {
        PathSpec::Move {
            from,
            to,
            start,
            duration,
            profile,
        } => MassPath::Move {
            from: vector(key("from"), *from, "m")?,
            to: vector(key("to"), *to, "m")?,
            start: finite(key("start"), *start, "s")?,
            duration: positive(key("duration"), *duration, "s")?,
            profile: *profile,
        },
        PathSpec::Table(path) => {
            let (t, rows) = read_rows(path, &PATH_TABLE_HEADER, "t in s, the position in m")
                .map_err(|problem| crate::keys::Invalid {
                    key: key("table"),
                    problem,
                })?;
            let r = rows
                .iter()
                .map(|v| Vector3::new(v[0], v[1], v[2]))
                .collect();
            MassPath::Table { t, r }
        }
    };
    Ok(MovingMass { name, mass, path })
}

/// The inertia table at `path`: each row a body's inertia (positive definite, the triangle inequality
/// I_1 + I_2 ≥ I_3 of its principal moments, to round-off); errors name the file and the row.
fn read_inertia_table(path: &std::path::Path) -> Result<InertiaHistory, String> {
    let (t, rows) = read_rows(
        path,
        &INERTIA_TABLE_HEADER,
        "t in s, the inertia about C in kg*m^2, body axes",
    )?;
    let mut inertia_b = Vec::with_capacity(rows.len());
    for (row, v) in rows.iter().enumerate() {
        let i = Matrix3::new(v[0], v[3], v[4], v[3], v[1], v[5], v[4], v[5], v[2]);
        let moments = Principal::of(&i).moments;
        let largest = moments.amax();
        let sorted = {
            let mut m: Vec<f64> = moments.iter().copied().collect();
            m.sort_by(f64::total_cmp);
            m
        };
        if moments.iter().any(|&m| m <= 1e-12 * largest) || largest <= 0.0 {
            return Err(format!(
                "{}: row {} (t = {}): the inertia is not positive definite (principal moments {:?} kg*m^2)",
                path.display(),
                row + 1,
                t[row],
                sorted
            ));
        }
        if sorted[0] + sorted[1] < sorted[2] * (1.0 - 1e-12) {
            return Err(format!(
                "{}: row {} (t = {}): the principal moments {:?} kg*m^2 break the triangle inequality \
                 I_1 + I_2 >= I_3: no body has them",
                path.display(),
                row + 1,
                t[row],
                sorted
            ));
        }
        inertia_b.push(i);
    }
    Ok(InertiaHistory {
        path: path.to_path_buf(),
        t,
        inertia_b,
    })
}
