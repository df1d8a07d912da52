//! `[[effect]]` validated: torques (with their time profiles), gravity about a pivot, viscous damping, tabulated
//! torques.

use std::sync::Arc;

use nalgebra::Vector3;

use super::spec::{EffectSpec, TorqueSpec};
use super::{Effect, TorqueTable};
use crate::keys::{Checked, KeyPath, finite, invalid, vector};

/// Every `[[effect]]` of `specs`, in order, and at most one gravity (its pivot is the body's one fixed point) on a
/// body of `mass` (kg). `axis_point_b` is the axis point of a fixed-axis or hinge motion from the mass center,
/// gravity's moment center there; other positions are turned from the reference origin to the mass center
/// `center_b`.
pub(crate) fn validate_effects(
    specs: &[EffectSpec],
    axis_point_b: Option<&Vector3<f64>>,
    mass: f64,
    center_b: &Vector3<f64>,
) -> Checked<Vec<Effect>> {
    let effects = (specs.iter().enumerate())
        .map(|(i, e)| validate_effect(i, e, axis_point_b, center_b))
        .collect::<Checked<Vec<_>>>()?;
    let second_gravity = (specs.iter().enumerate())
        .filter(|(_, e)| matches!(e, EffectSpec::Gravity { .. }))
        .nth(1);
    if let Some((second, _)) = second_gravity {
        return invalid(
            KeyPath::root().key("effect").index(second),
            "only one gravity effect is allowed: its pivot is the single fixed point of the body",
        );
    }
    effect_moments_in_range(&effects, mass)?;
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
