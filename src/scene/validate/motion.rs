//! `[motion]` and `[initial]`: free rotation from an initial ω, or prescribed rotation about a fixed axis.

use nalgebra::{UnitQuaternion, Vector3};

use super::super::model::Motion;
use super::super::spec::{MotionKind, MotionSpec, SceneSpec};
use super::{Checked, Invalid, KeyPath, finite, invalid, only_keys, vector};
use crate::body::RigidBody;
use crate::effects::Effect;
use crate::motion::fixed_axis::FixedAxis;
use crate::motion::free::FreeBody;

pub(super) fn validate_motion(
    doc: &SceneSpec,
    body: &RigidBody,
    attitude0: &UnitQuaternion<f64>,
    effects: &[Effect],
) -> Checked<Motion> {
    let initial_omega = doc.initial.as_ref().and_then(|i| i.omega);
    let motion = || KeyPath::root().key("motion");
    // The fixed-axis table, or `None` for free motion (no [motion] table, or type = "free").
    let fixed_axis = match &doc.motion {
        None => None,
        Some(m) => match m.kind {
            None => {
                return invalid(
                    motion().key("type"),
                    "missing: the motion needs `type` = \"free\" or \"fixed_axis\"",
                );
            }
            Some(MotionKind::Free) => {
                only_keys(
                    &motion(),
                    "motion type = \"free\"",
                    &[],
                    &[
                        ("axis", m.axis.is_some()),
                        ("tilt_deg", m.tilt_deg.is_some()),
                        ("rate", m.rate.is_some()),
                        ("accel", m.accel.is_some()),
                        ("point", m.point.is_some()),
                    ],
                )?;
                None
            }
            Some(MotionKind::FixedAxis) => Some(m),
        },
    };
    match fixed_axis {
        None => free_motion(doc, body, initial_omega, effects),
        Some(m) => fixed_axis_motion(m, body, initial_omega.is_some(), attitude0),
    }
}

/// Free rotation from `initial.omega` about C, or about the pivot of a gravity effect.
fn free_motion(
    doc: &SceneSpec,
    body: &RigidBody,
    initial_omega: Option<[f64; 3]>,
    effects: &[Effect],
) -> Checked<Motion> {
    let omega0_b = match initial_omega {
        None => Vector3::zeros(),
        Some(w) => vector(KeyPath::root().key("initial").key("omega"), w, "rad/s")?,
    };
    let center_b = effects
        .iter()
        .find_map(|e| match e {
            Effect::Gravity { pivot_b, .. } => Some(*pivot_b),
            _ => None,
        })
        .unwrap_or_else(Vector3::zeros);
    let body_key = if doc.body.shape.is_some() {
        "shape"
    } else {
        "inertia"
    };
    let free_body = FreeBody::new(body, &center_b).map_err(|e| Invalid {
        key: KeyPath::root().key("body").key(body_key),
        problem: e.to_string(),
    })?;
    // H = I_A ω₀ and T = ½ ω₀·H must be numbers: every row reports them, and the divergence guard measures
    // the run by T.
    let (h0_b, energy0) = free_body.momentum_and_energy(&omega0_b);
    if !(energy0.is_finite() && h0_b.norm().is_finite()) {
        return invalid(
            KeyPath::root().key("initial").key("omega"),
            format!(
                "ω₀ = ({:e}, {:e}, {:e}) rad/s is too large: the moment of momentum I·ω₀ or the kinetic \
                 energy ½ ω₀·I·ω₀ is beyond the range of double precision",
                omega0_b.x, omega0_b.y, omega0_b.z
            ),
        );
    }
    Ok(Motion::Free {
        omega0_b,
        body: free_body,
    })
}

/// Prescribed rotation about the axis of `[motion]`.
fn fixed_axis_motion(
    m: &MotionSpec,
    body: &RigidBody,
    initial_omega_given: bool,
    attitude0: &UnitQuaternion<f64>,
) -> Checked<Motion> {
    let motion = || KeyPath::root().key("motion");
    if initial_omega_given {
        return invalid(
            KeyPath::root().key("initial").key("omega"),
            "a fixed-axis motion sets ω from `motion.rate`; remove initial.omega",
        );
    }
    let axis_b = match (m.axis, m.tilt_deg) {
        (Some(_), Some(_)) => {
            return invalid(
                motion().key("tilt_deg"),
                "give either `axis` or `tilt_deg`, not both",
            );
        }
        (None, None) => {
            return invalid(
                motion(),
                "a fixed-axis motion needs `axis = [x, y, z]` (body axes) or `tilt_deg`",
            );
        }
        (Some(a), None) => {
            let a = vector(motion().key("axis"), a, "direction")?;
            let norm = a.norm();
            if !(norm > 1e-300 && norm.is_finite()) {
                return invalid(
                    motion().key("axis"),
                    "the axis is the zero vector; give a nonzero direction in body axes",
                );
            }
            a / norm
        }
        (None, Some(tilt)) => {
            let tilt = finite(motion().key("tilt_deg"), tilt, "degrees")?.to_radians();
            Vector3::new(0.0, -tilt.sin(), tilt.cos())
        }
    };
    let rate = finite(motion().key("rate"), m.rate.unwrap_or(0.0), "rad/s")?;
    let accel = finite(motion().key("accel"), m.accel.unwrap_or(0.0), "rad/s^2")?;
    // The required moment M = I α + ω × I ω is of order I_max (ω² + |α|): it must be a number at t = 0.
    let inertia_max = body.inertia_c().abs().max();
    if !(inertia_max * (rate * rate + accel.abs())).is_finite() {
        return invalid(
            motion().key("rate"),
            format!(
                "rate {rate:e} rad/s with accel {accel:e} rad/s^2 is too large: the moment that keeps the \
                 body on its axis, of order I·(ω² + |α|), is beyond the range of double precision"
            ),
        );
    }
    Ok(Motion::FixedAxis(FixedAxis::new(
        body,
        axis_b,
        rate,
        accel,
        match m.point {
            None => Vector3::zeros(),
            Some(p) => vector(motion().key("point"), p, "m")?,
        },
        *attitude0,
    )))
}
