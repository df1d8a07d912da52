//! `[body]`: the mass and a shape or an inertia tensor.

use nalgebra::{Matrix3, Vector3};

use super::super::spec::{BodySpec, InertiaSpec, ShapeKind, ShapeSpec};
use super::{Checked, Invalid, KeyPath, invalid, only_keys, positive, required, vector};
use crate::body::{InvalidBody, RigidBody, Shape};

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
        let kind = "a point mass";
        let at = required(table.clone().key("at"), point_mass.at, kind)?;
        masses.push((mass, vector(table.key("at"), at, "m")?));
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
    match (&doc.shape, &doc.inertia) {
        (Some(_), Some(_)) => invalid(
            body_key().key("inertia"),
            "give either `shape` or `inertia`, not both",
        ),
        (None, None) => invalid(
            body_key(),
            "the body needs `shape` (e.g. { type = \"thin_disk\", radius = 0.3 }) or `inertia` ([I1, I2, I3] or a 3x3 tensor)",
        ),
        (Some(shape), None) => {
            RigidBody::from_shape(doc.mass, validate_shape(shape)?).map_err(located)
        }
        (None, Some(inertia)) => {
            let tensor = match inertia {
                InertiaSpec::Principal(m) => Matrix3::from_diagonal(&Vector3::from(*m)),
                InertiaSpec::Full(rows) => Matrix3::from_fn(|r, c| rows[r][c]),
            };
            RigidBody::new(doc.mass, tensor).map_err(located)
        }
    }
}

/// The shape a `body.shape` table describes: its `type` and the keys that type takes.
fn validate_shape(doc: &ShapeSpec) -> Checked<Shape> {
    let table = KeyPath::root().key("body").key("shape");
    let Some(kind) = doc.kind else {
        return invalid(
            table.key("type"),
            "missing: the shape needs `type` = \"thin_disk\" | \"disk\" | \"thin_rod\" | \"sphere\" | \"box\" | \"cylinder\"",
        );
    };
    let (name, takes): (&str, &[&str]) = match kind {
        ShapeKind::ThinDisk => ("thin_disk", &["radius"]),
        ShapeKind::Disk => ("disk", &["radius", "thickness"]),
        ShapeKind::ThinRod => ("thin_rod", &["length"]),
        ShapeKind::Sphere => ("sphere", &["radius"]),
        ShapeKind::Box => ("box", &["size"]),
        ShapeKind::Cylinder => ("cylinder", &["radius", "height"]),
    };
    let kind_text = format!("shape type = \"{name}\"");
    only_keys(
        &table,
        &kind_text,
        takes,
        &[
            ("radius", doc.radius.is_some()),
            ("thickness", doc.thickness.is_some()),
            ("length", doc.length.is_some()),
            ("size", doc.size.is_some()),
            ("height", doc.height.is_some()),
        ],
    )?;
    let need = |name: &str, v: Option<f64>| required(table.clone().key(name), v, &kind_text);
    Ok(match kind {
        ShapeKind::ThinDisk => Shape::ThinDisk {
            radius: need("radius", doc.radius)?,
        },
        ShapeKind::Disk => Shape::Disk {
            radius: need("radius", doc.radius)?,
            thickness: need("thickness", doc.thickness)?,
        },
        ShapeKind::ThinRod => Shape::ThinRod {
            length: need("length", doc.length)?,
        },
        ShapeKind::Sphere => Shape::Sphere {
            radius: need("radius", doc.radius)?,
        },
        ShapeKind::Box => Shape::Box {
            size: required(table.clone().key("size"), doc.size, &kind_text)?,
        },
        ShapeKind::Cylinder => Shape::Cylinder {
            radius: need("radius", doc.radius)?,
            height: need("height", doc.height)?,
        },
    })
}
