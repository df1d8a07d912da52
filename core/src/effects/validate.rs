//! `[[effect]]` validated: torques (with their time profiles), gravity about a pivot, viscous damping, tabulated
//! torques.

use std::sync::Arc;

use nalgebra::{Matrix3, Vector3};

use super::spec::{EffectSpec, MagneticSpec, TorqueSpec};
use super::{Effect, TorqueTable};
use crate::body::RigidBody;
use crate::keys::{Checked, KeyPath, finite, invalid, vector};
use crate::orbit::{CircularOrbit, DipoleField};

/// Every `[[effect]]` of `specs`, in order, and at most one gravity (its pivot is the body's one fixed point) on
/// `body`. `axis_point_b` is the axis point of a fixed-axis or hinge motion from the mass center, gravity's moment
/// center there; other positions are turned from the reference origin to the mass center `center_b`. The
/// environment's effects take the body along `orbit`.
pub(crate) fn validate_effects(
    specs: &[EffectSpec],
    axis_point_b: Option<&Vector3<f64>>,
    body: &RigidBody,
    center_b: &Vector3<f64>,
    orbit: Option<&CircularOrbit>,
) -> Checked<Vec<Effect>> {
    let on = Placement {
        axis_point_b,
        center_b,
        inertia_c_b: body.inertia_c(),
        orbit,
    };
    let effects = (specs.iter().enumerate())
        .map(|(i, e)| validate_effect(i, e, &on))
        .collect::<Checked<Vec<_>>>()?;
    let gradient = (effects.iter()).position(|e| matches!(e, Effect::GravityGradient { .. }));
    if let (Some(index), true) = (gradient, effects.iter().any(|e| e.gravity().is_some())) {
        return invalid(
            KeyPath::root().key("effect").index(index).key("type"),
            "a gravity gradient acts on a free body in orbit, about C: it does not combine with uniform `gravity` \
             about a pivot",
        );
    }
    let second_gravity = (specs.iter().enumerate())
        .filter(|(_, e)| matches!(e, EffectSpec::Gravity { .. }))
        .nth(1);
    if let Some((second, _)) = second_gravity {
        return invalid(
            KeyPath::root().key("effect").index(second),
            "only one gravity effect is allowed: its pivot is the single fixed point of the body",
        );
    }
    effect_moments_in_range(&effects, body.mass())?;
    Ok(effects)
}

/// The largest moments of the effects ([`Effect::largest_moment`]) and their sum must be numbers: the divergence
/// guard bounds the work the effects can do by that sum (the free motion's `EffectMoments::rest_moment_bound`).
fn effect_moments_in_range(effects: &[Effect], mass: f64) -> Checked<()> {
    let mut sum = 0.0;
    for (index, effect) in effects.iter().enumerate() {
        let Some(largest) = effect.largest_moment(mass) else {
            continue;
        };
        let name = match effect {
            Effect::Gravity { .. } => "g",
            Effect::TorqueTable { .. } => "file",
            _ => "value",
        };
        sum += largest;
        if !sum.is_finite() {
            let problem = if largest.is_finite() {
                format!(
                    "too large: the moment of this effect (up to {largest:e} N*m), added to the others', is beyond \
                     the range of double precision"
                )
            } else {
                "too large: the moment of this effect is beyond the range of double precision"
                    .to_string()
            };
            return invalid(
                KeyPath::root().key("effect").index(index).key(name),
                problem,
            );
        }
    }
    Ok(())
}

/// Where the effects act: an axis motion's axis point (gravity's moment center there), the mass center from the
/// reference origin, the body's inertia about C and the orbit.
struct Placement<'a> {
    axis_point_b: Option<&'a Vector3<f64>>,
    center_b: &'a Vector3<f64>,
    inertia_c_b: &'a Matrix3<f64>,
    orbit: Option<&'a CircularOrbit>,
}

/// One effect, placed `on` the body.
fn validate_effect(index: usize, doc: &EffectSpec, on: &Placement) -> Checked<Effect> {
    let table = KeyPath::root().key("effect").index(index);
    let key = |name: &str| table.clone().key(name);
    let (axis_point, center_b) = (on.axis_point_b, on.center_b);
    Ok(match *doc {
        EffectSpec::GravityGradient => match (on.orbit, axis_point) {
            (None, _) => {
                return invalid(
                    key("type"),
                    "effect type = \"gravity_gradient\" needs an `[orbit]` (altitude_km or radius_km)",
                );
            }
            (Some(_), Some(_)) => {
                return invalid(
                    key("type"),
                    "a gravity gradient acts on a free body about C; a fixed axis or hinge is not in orbit",
                );
            }
            (Some(orbit), None) => Effect::GravityGradient {
                orbit: *orbit,
                inertia_c_b: *on.inertia_c_b,
            },
        },
        EffectSpec::Magnetic(ref magnetic) => validate_magnetic(&table, magnetic, on)?,
        EffectSpec::Torque(torque) => validate_torque(&table, &torque)?,
        // The table is read here, once: its errors name the file and the row.
        EffectSpec::TorqueTable(ref spec) => Effect::TorqueTable {
            frame: spec.frame,
            table: Arc::new(
                TorqueTable::read(&spec.file, spec.interpolation)
                    .or_else(|problem| invalid(key("file"), problem))?,
            ),
        },
        EffectSpec::Gravity { g, pivot } => Effect::Gravity {
            g_s: vector(key("g"), g, "m/s^2")?,
            pivot_b: match (axis_point, pivot) {
                (Some(_), Some(_)) => {
                    return invalid(
                        key("pivot"),
                        "with a fixed axis or a hinge the moment center is the axis point (`motion.point`): remove `pivot`",
                    );
                }
                (Some(point_b), None) => *point_b,
                (None, Some(pivot)) => vector(key("pivot"), pivot, "m")? - center_b,
                (None, None) => {
                    return invalid(
                        key("pivot"),
                        "missing: effect type = \"gravity\" needs `pivot`",
                    );
                }
            },
        },
        EffectSpec::Damping { c } => {
            let c = finite(key("c"), c, "N*m*s")?;
            if c < 0.0 {
                return invalid(
                    key("c"),
                    format!("must be >= 0 (N*m*s): a negative damping adds energy, got {c:?}"),
                );
            }
            Effect::Damping { c }
        }
    })
}

/// A residual dipole in the Earth's field: an orbit and a free body, a finite dipole (A·m²), finite angles and a
/// field B₀ > 0 (T).
fn validate_magnetic(table: &KeyPath, doc: &MagneticSpec, on: &Placement) -> Checked<Effect> {
    let key = |name: &str| table.clone().key(name);
    let orbit = match (on.orbit, on.axis_point_b) {
        (None, _) => {
            return invalid(
                key("type"),
                "effect type = \"magnetic\" needs an `[orbit]` (altitude_km or radius_km): the field is the Earth's along it",
            );
        }
        (Some(_), Some(_)) => {
            return invalid(
                key("type"),
                "a magnetic moment acts on a free body in orbit; a fixed axis or hinge is not in orbit",
            );
        }
        (Some(orbit), None) => *orbit,
    };
    let b0 = finite(key("field_b0"), doc.field_b0, "T")?;
    if b0 <= 0.0 {
        return invalid(key("field_b0"), format!("must be > 0 (T), got {b0:?}"));
    }
    let angle = |name: &str, value: f64| finite(key(name), value, "degrees").map(f64::to_radians);
    Ok(Effect::Magnetic {
        orbit,
        field: DipoleField::new(
            b0,
            angle("field_tilt_deg", doc.field_tilt_deg)?,
            angle("field_lon_deg", doc.field_lon_deg)?,
        ),
        dipole_b: vector(key("dipole"), doc.dipole, "A*m^2")?,
    })
}

/// A torque: its axes, value and time profile.
fn validate_torque(table: &KeyPath, doc: &TorqueSpec) -> Checked<Effect> {
    let key = |name: &str| table.clone().key(name);
    let profile = doc.profile.checked(table)?;
    Ok(Effect::Torque {
        frame: doc.frame,
        value: vector(key("value"), doc.value, "N*m")?,
        profile,
    })
}
