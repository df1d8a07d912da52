//! `[body]`: the mass and a shape or an inertia tensor.

use nalgebra::{Matrix3, Vector3};

use super::super::spec::{BodySpec, Distribution, InertiaSpec};
use super::{Checked, Invalid, KeyPath, positive, vector};
use crate::body::{InvalidBody, RigidBody};

/// The whole body — the shape or inertia and its point masses — and the position of its mass center C from the
/// reference origin (body axes).
pub(super) fn validate_body(doc: &BodySpec) -> Checked<(RigidBody, Vector3<f64>)> {
    let base = validate_base(doc)?;
    if doc.point_mass.is_empty() {
        return Ok((base, Vector3::zeros()));
    }
    let mut masses = Vec::with_capacity(doc.point_mass.len());
    for (index, point_mass) in doc.point_mass.iter().enumerate() {
        let table = KeyPath::root().key("body").key("point_mass").index(index);
        let mass = positive(table.clone().key("mass"), point_mass.mass, "kg")?;
        masses.push((mass, vector(table.key("at"), point_mass.at, "m")?));
    }
    base.with_point_masses(&masses).map_err(|e| Invalid {
        key: KeyPath::root().key("body").key("point_mass"),
        problem: e.problem,
    })
}

/// The body's shape or inertia tensor, without point masses.
fn validate_base(doc: &BodySpec) -> Checked<RigidBody> {
    let body_key = || KeyPath::root().key("body");
    let located = |e: InvalidBody| {
        let mut key = body_key();
        for part in e.key.split('.') {
            key = key.key(part);
        }
        Invalid {
            key,
            problem: e.problem,
        }
    };
    match &doc.distribution {
        Distribution::Shape(shape) => RigidBody::from_shape(doc.mass, *shape).map_err(located),
        Distribution::Inertia(inertia) => {
            let tensor = match inertia {
                InertiaSpec::Principal(m) => Matrix3::from_diagonal(&Vector3::from(*m)),
                InertiaSpec::Full(rows) => Matrix3::from_fn(|r, c| rows[r][c]),
            };
            RigidBody::new(doc.mass, tensor).map_err(located)
        }
    }
}
