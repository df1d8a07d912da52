//! `[[effect]]` validated: each effect by its kind (`EffectSpec::validate`), then what only the list
//! as a whole can say: at most one gravity, no gravity gradient beside it, one Earth field, moments in range.

use nalgebra::Vector3;

use super::kind::Placement;
use super::kinds::{Effect, EffectSpec};
use crate::body::RigidBody;
use crate::keys::{Checked, KeyPath, invalid};
use crate::orbit::CircularOrbit;

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
    let table = |index: usize| KeyPath::root().key("effect").index(index);
    let effects = (specs.iter().enumerate())
        .map(|(i, e)| e.validate(&table(i), &on))
        .collect::<Checked<Vec<_>>>()?;
    let gravities: Vec<usize> = (effects.iter().enumerate())
        .filter(|(_, e)| e.gravity().is_some())
        .map(|(i, _)| i)
        .collect();
    if let Some(&second) = gravities.get(1) {
        return invalid(
            table(second),
            "only one gravity effect is allowed: its pivot is the single fixed point of the body",
        );
    }
    let gradient = (effects.iter()).position(|e| e.door().is_orbit_gravity());
    if let (Some(index), false) = (gradient, gravities.is_empty()) {
        return invalid(
            table(index).key("type"),
            "a gravity gradient acts on a free body in orbit, about C: it does not combine with uniform `gravity` \
             about a pivot",
        );
    }
    one_field(&effects)?;
    effect_moments_in_range(&effects, body.mass())?;
    Ok(effects)
}

/// The effects that act in the Earth's field (`magnetic`, `b_dot`) must give the same field: there is one Earth.
fn one_field(effects: &[Effect]) -> Checked<()> {
    let mut fields = (effects.iter().enumerate()).filter_map(|(i, e)| Some((i, e.field()?.1)));
    let Some((_, first)) = fields.next() else {
        return Ok(());
    };
    match fields.find(|(_, field)| *field != first) {
        Some((index, _)) => invalid(
            KeyPath::root().key("effect").index(index).key("field_b0"),
            "the effects that act in the Earth's field give different fields (field_tilt_deg, field_lon_deg, \
             field_b0): give the same values, there is one Earth",
        ),
        None => Ok(()),
    }
}

/// The largest moments of the effects ([`Effect::largest_moment`]) and their sum must be numbers: the divergence
/// guard bounds the work the effects can do by that sum (the free motion's `EffectMoments::rest_moment_bound`).
fn effect_moments_in_range(effects: &[Effect], mass: f64) -> Checked<()> {
    let mut sum = 0.0;
    for (index, effect) in effects.iter().enumerate() {
        let Some(largest) = effect.largest_moment(mass) else {
            continue;
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
                KeyPath::root()
                    .key("effect")
                    .index(index)
                    .key(effect.door().size_key()),
                problem,
            );
        }
    }
    Ok(())
}
