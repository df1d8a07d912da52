//! `[motion]` and `[initial]`: free rotation from an initial ω, or prescribed rotation about a fixed axis.

use nalgebra::{UnitQuaternion, Vector3};

use super::super::attributes::Attribute;
use super::super::motion::Motion;
use super::super::spec::{AxisDirection, AxisSpec, Distribution, MotionSpec, RateSpec, SceneSpec};
use super::{Checked, Invalid, KeyPath, finite, invalid, vector};
use crate::body::RigidBody;
use crate::effects::Effect;
use crate::effects::EffectMoments;
use crate::frames::Vector;
use crate::motion::attribute::Mounting;
use crate::motion::fixed_axis::FixedAxis;
use crate::motion::free::FreeBody;
use crate::motion::hinge::Hinge;
use crate::motion::support::Bearings;
use crate::orbit::CircularOrbit;

/// `initial.omega`, or `initial.omega_lvlh` (ω relative to the LVLH frame of `orbit`, body axes) plus the frame's
/// rate n ĥ seen in the body at `attitude0`: ω_b = ω_rel + Rᵀ n ĥ; with the key it was given by.
pub(super) fn initial_omega(
    doc: &SceneSpec,
    orbit: Option<&CircularOrbit>,
    attitude0: &UnitQuaternion<f64>,
) -> Checked<Option<([f64; 3], &'static str)>> {
    let Some(initial) = &doc.initial else {
        return Ok(None);
    };
    match (initial.omega, initial.omega_lvlh, orbit) {
        (Some(omega), ..) => Ok(Some((omega, "omega"))),
        (None, Some(relative), Some(orbit)) => {
            let relative_b = vector(
                KeyPath::root().key("initial").key("omega_lvlh"),
                relative,
                "rad/s",
            )?;
            let omega_b = relative_b + attitude0.inverse_transform_vector(&orbit.lvlh_rate_s());
            Ok(Some((omega_b.into(), "omega_lvlh")))
        }
        (None, Some(_), None) => invalid(
            KeyPath::root().key("initial").key("omega_lvlh"),
            "a rate relative to the LVLH frame needs an `[orbit]` (altitude_km or radius_km)",
        ),
        (None, None, _) => Ok(None),
    }
}

/// The motion, a free body's from `omega0` (ω at t = 0 and the key that gave it).
pub(super) fn validate_motion(
    doc: &SceneSpec,
    body: &RigidBody,
    attitude0: &UnitQuaternion<f64>,
    (omega0, effects): (Option<([f64; 3], &'static str)>, &[Effect]),
    center_b: &Vector3<f64>,
) -> Checked<Motion> {
    let initial_omega = omega0;
    let (axis_spec, accel, angle_deg) = match &doc.motion {
        None | Some(MotionSpec::Free) => {
            return free_motion(doc, body, initial_omega, effects, center_b);
        }
        Some(MotionSpec::FixedAxis(m)) => (&m.axis, m.accel, None),
        Some(MotionSpec::Hinge(m)) => (&m.axis, 0.0, Some(m.angle_deg)),
    };
    Attribute::refuse_on_axis(&doc.body)?;
    if let Some((_, name)) = initial_omega {
        return invalid(
            KeyPath::root().key("initial").key(name),
            format!(
                "a fixed-axis or hinge motion sets ω from `motion.rate`; remove initial.{name}"
            ),
        );
    }
    let axis = axis_geometry(axis_spec, accel, body, attitude0, effects, center_b)?;
    match angle_deg {
        Some(angle_deg) => hinge_motion(angle_deg, axis, body, effects),
        None => Ok(Motion::FixedAxis(axis)),
    }
}

/// Free rotation from `initial.omega` about C, or about the pivot of a gravity effect; `c_b` is C from the
/// reference origin.
fn free_motion(
    doc: &SceneSpec,
    body: &RigidBody,
    initial_omega: Option<([f64; 3], &'static str)>,
    effects: &[Effect],
    c_b: &Vector3<f64>,
) -> Checked<Motion> {
    let omega0_b = Vector::new(match initial_omega {
        None => Vector3::zeros(),
        Some((w, name)) => vector(KeyPath::root().key("initial").key(name), w, "rad/s")?,
    });
    let center_b =
        crate::effects::gravity(effects).map_or_else(Vector3::zeros, |(_, pivot_b)| pivot_b);
    let body_key = match doc.body.distribution {
        Distribution::Shape(_) => "shape",
        Distribution::Inertia(_) => "inertia",
    };
    let free_body = FreeBody::new(body, &Vector::new(center_b)).map_err(|e| Invalid {
        key: KeyPath::root().key("body").key(body_key),
        problem: e.to_string(),
    })?;
    // H = I_A ω₀ and T = ½ ω₀·H must be numbers: every row reports them, and the divergence guard measures
    // the run by T.
    let (h0_b, energy0) = free_body.momentum_and_energy(&omega0_b);
    if !(energy0.is_finite() && h0_b.norm().is_finite()) {
        let name = initial_omega.map_or("omega", |(_, name)| name);
        return invalid(
            KeyPath::root().key("initial").key(name),
            format!(
                "ω₀ = ({:e}, {:e}, {:e}) rad/s is too large: the moment of momentum I·ω₀ or the kinetic \
                 energy ½ ω₀·I·ω₀ is beyond the range of double precision",
                omega0_b.x, omega0_b.y, omega0_b.z
            ),
        );
    }
    let attribute = Attribute::on_free_body(
        &doc.body,
        &Mounting {
            body: (body, c_b),
            free_body: (&free_body, &(c_b + center_b)),
            point_masses: !doc.body.point_mass.is_empty(),
            effects,
            omega0_b: (&omega0_b, initial_omega.map_or("omega", |(_, name)| name)),
        },
    )?;
    Ok(Motion::Free {
        omega0_b,
        body: free_body,
        attribute,
    })
}

/// The axis of a fixed-axis or hinge motion: its direction, rate, acceleration, point, bearings and the gravity
/// its support carries.
fn axis_geometry(
    m: &AxisSpec,
    accel: f64,
    body: &RigidBody,
    attitude0: &UnitQuaternion<f64>,
    effects: &[Effect],
    center_b: &Vector3<f64>,
) -> Checked<FixedAxis> {
    let motion = || KeyPath::root().key("motion");
    let axis_b = axis_direction(m)?;
    let attitude0 = axis_attitude(m, &axis_b, attitude0)?;
    let rate = axis_rate(m)?;
    let accel = finite(motion().key("accel"), accel, "rad/s^2")?;
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
    let point_b = vector(motion().key("point"), m.point, "m")? - center_b;
    let (axis_b, point_b) = (Vector::new(axis_b), Vector::new(point_b));
    let mut axis = FixedAxis::new(body, axis_b, rate, accel, point_b, attitude0);
    if let Some((g_s, _)) = crate::effects::gravity(effects) {
        axis = axis.with_gravity(Vector::new(g_s));
    }
    if let Some([a, b]) = m.bearings {
        let key = motion().key("bearings");
        if !(a.is_finite() && b.is_finite()) || a == b {
            return invalid(
                key,
                format!(
                    "bearings = [{a}, {b}]: give two different finite positions (m) along the axis from `point`"
                ),
            );
        }
        axis = axis.with_bearings(Bearings { a, b });
    }
    m.parts.attach(axis, &motion())
}

/// θ̇ at t = 0 (rad/s): `rate`, or `rate_rpm` · 2π/60 (revolutions per minute, as rotor engineers give it).
fn axis_rate(m: &AxisSpec) -> Checked<f64> {
    let motion = || KeyPath::root().key("motion");
    match m.rate {
        RateSpec::Rpm(rpm) => {
            finite(motion().key("rate_rpm"), rpm, "rpm").map(|_| m.rate.rad_per_second())
        }
        RateSpec::RadPerSecond(rate) => finite(motion().key("rate"), rate, "rad/s"),
    }
}

/// A hinge on the axis: θ from `angle_deg`, θ̇ from `rate`, driven by the effects about the axis point.
fn hinge_motion(
    angle_deg: f64,
    axis: FixedAxis,
    body: &RigidBody,
    effects: &[Effect],
) -> Checked<Motion> {
    let key = KeyPath::root().key("motion").key("angle_deg");
    let theta0 = finite(key, angle_deg, "degrees")?.to_radians();
    let i_uu = axis.i_uu();
    if i_uu.is_nan() || i_uu <= 0.0 {
        return invalid(
            KeyPath::root().key("motion").key("axis"),
            "the body's moment of inertia about this axis is zero (a thin rod about its own line): a hinge cannot turn it",
        );
    }
    let rate = axis.rate();
    Ok(Motion::Hinge(Hinge::new(
        axis,
        EffectMoments::new(effects, body.mass()),
        theta0,
        rate,
    )))
}

/// The unit axis in body axes, from `axis` or `tilt_deg`.
fn axis_direction(m: &AxisSpec) -> Checked<Vector3<f64>> {
    let motion = || KeyPath::root().key("motion");
    Ok(match m.direction {
        AxisDirection::Body(a) => {
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
        AxisDirection::TiltDeg(tilt) => {
            let tilt = finite(motion().key("tilt_deg"), tilt, "degrees")?.to_radians();
            Vector3::new(0.0, -tilt.sin(), tilt.cos())
        }
    })
}

/// The attitude at t = 0: with `axis_in_space`, the smallest rotation that puts the body axis `axis_b` on that
/// space direction (a half turn about a body direction across the axis when they are opposite); else the
/// scene's `initial.attitude`.
fn axis_attitude(
    m: &AxisSpec,
    axis_b: &Vector3<f64>,
    attitude0: &UnitQuaternion<f64>,
) -> Checked<UnitQuaternion<f64>> {
    let Some(direction) = m.axis_in_space else {
        return Ok(*attitude0);
    };
    let key = KeyPath::root().key("motion").key("axis_in_space");
    let axis_s = vector(key.clone(), direction, "direction")?;
    if axis_s.norm() <= 1e-300 {
        return invalid(
            key,
            "the zero vector is no direction; give the axis in space axes",
        );
    }
    Ok(
        UnitQuaternion::rotation_between(axis_b, &axis_s).unwrap_or_else(|| {
            let across = if axis_b.x.abs() < 0.9 {
                Vector3::x()
            } else {
                Vector3::y()
            };
            let half_turn_axis = nalgebra::Unit::new_normalize(axis_b.cross(&across));
            UnitQuaternion::from_axis_angle(&half_turn_axis, std::f64::consts::PI)
        }),
    )
}
