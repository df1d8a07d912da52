//! `[[effect]]`: torques (with their time profiles), gravity about a pivot, viscous damping.

use super::super::spec::{EffectKind, EffectSpec, MotionKind, ProfileKind, SceneSpec};
use super::{Checked, KeyPath, finite, invalid, only_keys, required, vector};
use crate::body::RigidBody;
use crate::effects::{DEFAULT_GRAVITY, Effect, TorqueProfile};
use crate::frames::Axes;
use nalgebra::Vector3;

/// Every `[[effect]]`, in order; a fixed-axis motion takes gravity only, and at most one gravity (its pivot is the
/// body's one fixed point). Positions are turned from the reference origin to the mass center `center_b`.
pub(super) fn validate_effects(
    doc: &SceneSpec,
    body: &RigidBody,
    center_b: &Vector3<f64>,
) -> Checked<Vec<Effect>> {
    let kind = doc.motion.as_ref().and_then(|m| m.kind);
    let axis_point = match doc.motion.as_ref() {
        Some(m) if matches!(kind, Some(MotionKind::FixedAxis | MotionKind::Hinge)) => Some(
            m.point.map_or(Ok(Vector3::zeros()), |p| {
                vector(KeyPath::root().key("motion").key("point"), p, "m")
            })? - center_b,
        ),
        _ => None,
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
    if let (Some(MotionKind::FixedAxis), Some(index)) = (kind, not_gravity) {
        return invalid(
            KeyPath::root().key("effect").index(index),
            "a fixed-axis motion is prescribed: its moment is computed from the motion (M = dH/dt), so it takes no torque or damping (only gravity, whose weight its bearings carry); remove the effect, or use type = \"hinge\" to let the effects drive the rotation",
        );
    }
    let second_gravity = doc
        .effect
        .iter()
        .enumerate()
        .filter(|(_, e)| e.kind == Some(EffectKind::Gravity))
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
    let Some(kind) = doc.kind else {
        return invalid(
            key("type"),
            "missing: an effect needs `type` = \"torque\", \"gravity\" or \"damping\"",
        );
    };
    let (name, takes): (&str, &[&str]) = match kind {
        EffectKind::Torque => (
            "torque",
            &[
                "frame",
                "value",
                "profile",
                "freq_hz",
                "phase_deg",
                "t_on",
                "t_off",
            ],
        ),
        EffectKind::Gravity => ("gravity", &["g", "pivot"]),
        EffectKind::Damping => ("damping", &["c"]),
    };
    let kind_text = format!("effect type = \"{name}\"");
    only_keys(
        &table,
        &kind_text,
        takes,
        &[
            ("frame", doc.frame.is_some()),
            ("value", doc.value.is_some()),
            ("profile", doc.profile.is_some()),
            ("freq_hz", doc.freq_hz.is_some()),
            ("phase_deg", doc.phase_deg.is_some()),
            ("t_on", doc.t_on.is_some()),
            ("t_off", doc.t_off.is_some()),
            ("g", doc.g.is_some()),
            ("pivot", doc.pivot.is_some()),
            ("c", doc.c.is_some()),
        ],
    )?;
    Ok(match kind {
        EffectKind::Torque => validate_torque(&table, doc, &kind_text)?,
        EffectKind::Gravity => Effect::Gravity {
            g_s: vector(key("g"), doc.g.unwrap_or(DEFAULT_GRAVITY), "m/s^2")?,
            pivot_b: match (axis_point, doc.pivot) {
                (Some(_), Some(_)) => {
                    return invalid(
                        key("pivot"),
                        "with a fixed axis or a hinge the moment center is the axis point (`motion.point`): remove `pivot`",
                    );
                }
                (Some(point_b), None) => *point_b,
                (None, pivot) => {
                    vector(
                        key("pivot"),
                        required(key("pivot"), pivot, &kind_text)?,
                        "m",
                    )? - center_b
                }
            },
        },
        EffectKind::Damping => {
            let c = finite(key("c"), required(key("c"), doc.c, &kind_text)?, "N*m*s")?;
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
fn validate_torque(table: &KeyPath, doc: &EffectSpec, kind_text: &str) -> Checked<Effect> {
    let key = |name: &str| table.clone().key(name);
    let misplaced = |name: &str, present: bool, kind: &str| -> Checked<()> {
        if present {
            invalid(
                key(name),
                format!("`{name}` applies to profile = \"{kind}\" only"),
            )
        } else {
            Ok(())
        }
    };
    let profile = match doc.profile.as_ref().unwrap_or(&ProfileKind::Constant) {
        ProfileKind::Constant => {
            misplaced("freq_hz", doc.freq_hz.is_some(), "sine")?;
            misplaced("phase_deg", doc.phase_deg.is_some(), "sine")?;
            misplaced("t_on", doc.t_on.is_some(), "step")?;
            misplaced("t_off", doc.t_off.is_some(), "step")?;
            TorqueProfile::Constant
        }
        ProfileKind::Sine => {
            misplaced("t_on", doc.t_on.is_some(), "step")?;
            misplaced("t_off", doc.t_off.is_some(), "step")?;
            let Some(f) = doc.freq_hz else {
                return invalid(
                    key("freq_hz"),
                    "a sine torque needs `freq_hz` (Hz, finite, >= 0)",
                );
            };
            let f = finite(key("freq_hz"), f, "Hz")?;
            if f < 0.0 {
                return invalid(key("freq_hz"), format!("must be >= 0 (Hz), got {f:?}"));
            }
            TorqueProfile::Sine {
                freq_hz: f,
                phase_rad: finite(key("phase_deg"), doc.phase_deg.unwrap_or(0.0), "degrees")?
                    .to_radians(),
            }
        }
        ProfileKind::Step => {
            misplaced("freq_hz", doc.freq_hz.is_some(), "sine")?;
            misplaced("phase_deg", doc.phase_deg.is_some(), "sine")?;
            let t_on = finite(key("t_on"), doc.t_on.unwrap_or(0.0), "s")?;
            let t_off = doc.t_off.unwrap_or(f64::INFINITY);
            if t_off.is_nan() || t_off <= t_on {
                return invalid(
                    key("t_off"),
                    format!("must be later than t_on = {t_on:?} s, got {t_off:?}"),
                );
            }
            TorqueProfile::Step { t_on, t_off }
        }
    };
    Ok(Effect::Torque {
        frame: doc.frame.unwrap_or(Axes::Body),
        value: vector(
            key("value"),
            required(key("value"), doc.value, kind_text)?,
            "N*m",
        )?,
        profile,
    })
}
