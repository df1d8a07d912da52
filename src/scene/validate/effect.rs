//! `[[effect]]`: torques (with their time profiles), gravity about a pivot, viscous damping, tabulated torques.

use std::sync::Arc;

use super::super::spec::{EffectSpec, MotionSpec, SceneSpec, TorqueSpec};
use super::{Checked, KeyPath, finite, invalid, vector};
use crate::body::RigidBody;
use crate::effects::{Effect, TorqueTable};
use nalgebra::Vector3;

/// Every `[[effect]]`, in order; a fixed-axis motion takes gravity only, and at most one gravity (its pivot is the
/// body's one fixed point). Positions are turned from the reference origin to the mass center `center_b`.
pub(super) fn validate_effects(
    doc: &SceneSpec,
    body: &RigidBody,
    center_b: &Vector3<f64>,
) -> Checked<Vec<Effect>> {
    let axis_point = match doc.motion.as_ref().and_then(MotionSpec::axis) {
        Some(axis) => {
            Some(vector(KeyPath::root().key("motion").key("point"), axis.point, "m")? - center_b)
        }
        None => None,
    };
    let effects = doc
        .effect
        .iter()
        .enumerate()
        .map(|(i, e)| validate_effect(i, e, axis_point.as_ref(), center_b))
        .collect::<Checked<Vec<_>>>()?;
    let not_gravity = effects
        .iter()
        .position(|e| !matches!(e, Effect::Gravity { .. }));
    if let (Some(MotionSpec::FixedAxis(_)), Some(index)) = (&doc.motion, not_gravity) {
        return invalid(
            KeyPath::root().key("effect").index(index),
            "a fixed-axis motion is prescribed: its moment is computed from the motion (M = dH/dt), so it takes no torque or damping (only gravity, whose weight its bearings carry); remove the effect, or use type = \"hinge\" to let the effects drive the rotation",
        );
    }
    let second_gravity = doc
        .effect
        .iter()
        .enumerate()
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

/// One effect; `axis_point` is the axis point of a fixed-axis or hinge motion, which is gravity's moment center.
fn validate_effect(
    index: usize,
    doc: &EffectSpec,
    axis_point: Option<&Vector3<f64>>,
    center_b: &Vector3<f64>,
) -> Checked<Effect> {
    let table = KeyPath::root().key("effect").index(index);
    let key = |name: &str| table.clone().key(name);
    Ok(match *doc {
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
