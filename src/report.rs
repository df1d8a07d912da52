//! What a scene will simulate, in a form a person reads at a glance (`eulerdyn check`).

use std::fmt::Write;

use nalgebra::Vector3;

use crate::effects::{Effect, TorqueProfile};
use crate::model::{Frame, MotionSpec, Scene};

fn vec3(v: &Vector3<f64>) -> String {
    format!("({:.6}, {:.6}, {:.6})", v[0], v[1], v[2])
}

/// A multi-line description of the scene: body, principal moments and axes, motion and moment center, effects,
/// method and tolerances, rows and an estimate of the steps.
pub fn describe(scene: &Scene) -> String {
    let mut out = String::new();
    let w = &mut out;
    let name = if scene.name.is_empty() {
        "(unnamed)"
    } else {
        &scene.name
    };
    let _ = writeln!(w, "scene      {name}");
    if !scene.description.is_empty() {
        let _ = writeln!(w, "           {}", scene.description);
    }
    let body = &scene.body;
    let _ = writeln!(w, "body       mass {} kg", body.mass());
    let i = body.inertia_c();
    let _ = writeln!(w, "           inertia about C, body axes (kg*m^2):");
    for r in 0..3 {
        let _ = writeln!(
            w,
            "             [{:>12.6e} {:>12.6e} {:>12.6e}]",
            i[(r, 0)],
            i[(r, 1)],
            i[(r, 2)]
        );
    }
    let p = body.principal();
    for k in 0..3 {
        let axis = p.axes_b.matrix().column(k).into_owned();
        let _ = writeln!(
            w,
            "           principal moment {} = {:.6e} kg*m^2 about body axis {}",
            k + 1,
            p.moments[k],
            vec3(&axis)
        );
    }
    match &scene.motion {
        MotionSpec::Free { omega0_b, .. } => {
            let _ = writeln!(
                w,
                "motion     free rotation, omega(0) = {} rad/s (body axes)",
                vec3(omega0_b)
            );
            let center = scene.effects.iter().find_map(|e| match e {
                Effect::Gravity { pivot_b, .. } => Some(*pivot_b),
                _ => None,
            });
            match center {
                Some(pivot) => {
                    let _ = writeln!(
                        w,
                        "center     the fixed pivot at {} m from C (body axes)",
                        vec3(&pivot)
                    );
                }
                None => {
                    let _ = writeln!(w, "center     the mass center C");
                }
            }
        }
        MotionSpec::FixedAxis(motion) => {
            let (axis_b, rate, accel, point_b) = (
                motion.axis_b().into_inner(),
                motion.rate(),
                motion.accel(),
                motion.point_b(),
            );
            let _ = writeln!(
                w,
                "motion     prescribed rotation about the fixed axis {} (body axes)",
                vec3(&axis_b)
            );
            let _ = writeln!(
                w,
                "           rate {rate} rad/s at t = 0, acceleration {accel} rad/s^2"
            );
            if point_b == Vector3::zeros() {
                let _ = writeln!(w, "center     the mass center C (on the axis)");
            } else {
                let _ = writeln!(
                    w,
                    "center     the axis point {} m from C (body axes); C moves on a circle, the bearing force is reported",
                    vec3(&point_b)
                );
            }
        }
    }
    if scene.effects.is_empty() {
        let _ = writeln!(w, "effects    none (torque-free)");
    }
    for (k, e) in scene.effects.iter().enumerate() {
        let label = if k == 0 { "effects   " } else { "          " };
        let text = match e {
            Effect::Torque {
                frame,
                value,
                profile,
            } => {
                let profile = match profile {
                    TorqueProfile::Constant => "constant".to_string(),
                    TorqueProfile::Sine { freq_hz, phase_rad } => {
                        format!("sine at {freq_hz} Hz, phase {} deg", phase_rad.to_degrees())
                    }
                    TorqueProfile::Step { t_on, t_off } => {
                        format!("step on for {t_on} <= t < {t_off} s")
                    }
                };
                format!(
                    "torque {} N*m in {} axes, {profile}",
                    vec3(value),
                    frame.name()
                )
            }
            Effect::Gravity { g_s, pivot_b } => format!(
                "gravity g = {} m/s^2 (space axes), pivot {} m from C (body axes)",
                vec3(g_s),
                vec3(pivot_b)
            ),
            Effect::Damping { c } => format!("viscous damping M = -{c} * omega"),
        };
        let _ = writeln!(w, "{label} {text}");
    }
    let s = &scene.solver;
    let form = match s.frame {
        Frame::Body => "body axes: I*omega' + omega x I*omega = M",
        Frame::Space => "space axes: dH_s/dt = M_s with I_s(theta)",
    };
    let _ = writeln!(w, "equation   {form}");
    if s.method.is_fixed_step() {
        let _ = writeln!(
            w,
            "method     {} ({}), fixed step dt = {} s",
            s.method.name(),
            s.backend.name(),
            s.dt
        );
    } else {
        let _ = writeln!(
            w,
            "method     {} ({}), adaptive, rtol = {:e}, atol = {:e}",
            s.method.name(),
            s.backend.name(),
            s.rtol,
            s.atol
        );
    }
    let rows = scene.schedule.len();
    let _ = writeln!(
        w,
        "output     t = 0 .. {} s, a row every {} s: {rows} rows",
        s.t_end,
        scene.schedule.every()
    );
    let steps = if s.method.is_fixed_step() {
        format!("{} steps", (s.t_end / s.dt).ceil().max(rows as f64 - 1.0))
    } else {
        format!(
            "at least {} steps (one per row interval; more as the tolerance requires)",
            rows.saturating_sub(1)
        )
    };
    let _ = writeln!(w, "estimate   {steps}");
    out
}
