//! What a scene will simulate, in a form a person reads at a glance (`eulerdyn check`, `eulerdyn.check` in Python):
//! the body with its principal moments and axes, the motion (for a fixed axis, its tilt from the nearest principal
//! axis), the moment center that H and M are taken about, the state at t = 0, the effects, the equation, method and
//! tolerances, the rows and an estimate of the steps. [`describe`] gives it as labelled items ([`Description`]),
//! [`Description::text`] as the command line prints it.

use nalgebra::Vector3;

use crate::effects::Effect;
use crate::frames::Form;
use crate::method::Method;
use crate::profile::Profile;
use crate::sample::BASE_COLUMNS;
use crate::scene::{
    AxisNumbers, CheckNumbers, MomentCenter, MotionKind, MotionNumbers, Scene, StartNumbers,
};
use crate::simulate;
pub use crate::text::{Description, for_people};
use crate::text::{fixed, line, plain, turns, vec3};

/// A rough estimate of the steps an adaptive method takes to reach t_end: its step h follows from
/// |ω|·h ≈ C·rtol^(1/(p+1)) (p the order; C measured on the shipped scenarios: 4 for dopri5, 5 for dop853), and it
/// takes at least one step per row interval. `None` for methods that are not adaptive.
pub fn adaptive_steps_estimate(scene: &Scene, rate: f64) -> Option<f64> {
    let s = &scene.solver;
    let (order, c) = match s.method {
        Method::Dopri5 => (5.0, 4.0),
        Method::Dop853 => (8.0, 5.0),
        _ => return None,
    };
    let intervals = scene.schedule.len().saturating_sub(1) as f64;
    let by_tolerance = if rate > 0.0 {
        (s.t_end * rate / (c * s.rtol.powf(1.0 / (order + 1.0)))).ceil()
    } else {
        0.0
    };
    Some(by_tolerance.max(intervals))
}

/// The fastest rate (rad/s) in the scene: |ω| at the start (and end, for a spin-up), or a sine torque's angular
/// frequency. Sets the step an adaptive method needs.
fn characteristic_rate(scene: &Scene) -> f64 {
    let motion_rate = scene.motion.largest_rate(scene.solver.t_end);
    scene
        .effects
        .iter()
        .filter_map(|e| match e.torque()?.profile {
            Profile::Sine { freq_hz, .. } => Some(2.0 * std::f64::consts::PI * freq_hz),
            _ => None,
        })
        .fold(motion_rate, f64::max)
}

/// What the scene will simulate: body, principal moments and axes, motion and moment center, the state at t = 0,
/// effects, method and tolerances, rows and an estimate of the steps; then `warnings` and a fixed step too coarse
/// for the motion ([`simulate::CoarseStep`]), one `warning` item each.
pub fn describe(scene: &Scene, warnings: &[String]) -> Description {
    let mut out = Description::default();
    let w = &mut out;
    scene_lines(w, scene);
    if let Some(numbers) = &scene.facts().check {
        body_lines(w, numbers);
        if let Some(motion) = &numbers.motion_numbers {
            motion_lines(w, scene, numbers, motion);
            support_lines(w, numbers, motion.axis.as_ref());
        }
    }
    attitude_line(w, scene);
    if let Some(orbit) = &scene.orbit {
        line(w, "orbit", &orbit.describe());
    }
    effect_lines(w, scene);
    conserved_line(w, scene);
    let steps = method_lines(w, scene);
    output_lines(w, scene);
    // A long estimate continues on the lines below its label.
    for (k, text) in steps.lines().enumerate() {
        line(w, if k == 0 { "estimate" } else { "" }, text);
    }
    let coarse = simulate::CoarseStep::of(scene).map(|c| c.to_string());
    for warning in warnings.iter().chain(&coarse) {
        line(w, "warning", warning);
    }
    out
}

/// The scene's name and description.
fn scene_lines(w: &mut Description, scene: &Scene) {
    let name = if scene.name.is_empty() {
        "(unnamed)"
    } else {
        &scene.name
    };
    line(w, "scene", name);
    if !scene.description.is_empty() {
        line(w, "", &scene.description);
    }
}

/// The body: mass, inertia tensor about C, principal moments and axes (the scene's facts, rounded for reading).
fn body_lines(w: &mut Description, numbers: &CheckNumbers) {
    line(w, "body", &format!("mass {} kg", plain(numbers.mass)));
    line(w, "", "inertia about C, body axes (kg*m^2):");
    for row in &numbers.inertia_c_b {
        let [a, b, c] = row;
        line(w, "", &format!("  [{a:>12.6e} {b:>12.6e} {c:>12.6e}]"));
    }
    let axes = &numbers.principal_axes_b;
    for (k, moment) in numbers.principal_moments_c.iter().enumerate() {
        let axis = Vector3::new(axes[0][k], axes[1][k], axes[2][k]);
        line(
            w,
            "",
            &format!(
                "principal moment {} = {moment:.6e} kg*m^2 about body axis {}",
                k + 1,
                vec3(&axis)
            ),
        );
    }
}

/// The motion, its moment center and the state at t = 0, from the scene's numbers; the capabilities that modify
/// it (wheels, a carrier) add their own lines.
fn motion_lines(
    w: &mut Description,
    scene: &Scene,
    numbers: &CheckNumbers,
    motion: &MotionNumbers,
) {
    match (scene.motion.kind(), &motion.axis) {
        (MotionKind::Free, _) => {
            free_motion_lines(w, numbers, motion);
            if let Some(attribute) = scene.motion.attribute() {
                attribute.door().describe(w, scene.body.mass());
            }
        }
        (MotionKind::FixedAxis, Some(axis)) => fixed_axis_lines(w, scene, numbers, axis),
        (MotionKind::Hinge, Some(axis)) => hinge_lines(w, numbers, axis),
        _ => {}
    }
    if let Some(axis) = scene.motion.axis() {
        axis_point_lines(w, motion.moment_center, &numbers.moment_center_from_c_b);
        if let Some(support) = axis.moving_support() {
            support.describe(axis.mass(), w);
        }
    }
    if let Some(start) = &motion.at_start {
        start_lines(w, start);
    }
}

/// Free motion: its moment center (C, or the pivot of a gravity effect).
fn free_motion_lines(w: &mut Description, numbers: &CheckNumbers, motion: &MotionNumbers) {
    line(
        w,
        "motion",
        "free rotation from omega(0), under the effects listed below",
    );
    if motion.moment_center == MomentCenter::Pivot {
        line(
            w,
            "moment center",
            &format!(
                "the fixed pivot, {} m from C (body axes): H and M are about it",
                vec3(&numbers.moment_center_from_c_b.into())
            ),
        );
        let [a, b, c] = motion.principal_moments_o;
        line(
            w,
            "",
            &format!("principal moments about the pivot: {a:.6e}, {b:.6e}, {c:.6e} kg*m^2"),
        );
    } else {
        line(
            w,
            "moment center",
            "C, the mass center: H and M are about it",
        );
    }
}

/// Prescribed fixed-axis motion: the axis and its tilt from the nearest principal axis, the rate.
fn fixed_axis_lines(
    w: &mut Description,
    scene: &Scene,
    numbers: &CheckNumbers,
    axis: &AxisNumbers,
) {
    line(
        w,
        "motion",
        "prescribed rotation about an axis fixed in the body and in space; M is the moment it requires (M = dH/dt)",
    );
    let (tilt, nearest) = (axis.tilt_deg, axis.nearest_principal);
    line(
        w,
        "",
        &format!(
            "axis {} (body axes), {tilt:.3} deg from principal axis {nearest}{}",
            vec3(&numbers.axis_b.unwrap_or_default().into()),
            if tilt < 1e-6
                && numbers.moment_center_from_c_b == [0.0; 3]
                && !scene.facts().moving_support
            {
                ": a principal axis, no moment is needed at a constant rate"
            } else {
                ""
            }
        ),
    );
    let (rate, accel, t_end) = (axis.rate, axis.accel, scene.solver.t_end);
    let turned = rate * t_end + 0.5 * accel * t_end * t_end;
    line(
        w,
        "",
        &format!(
            "rate {} rad/s at t = 0, acceleration {} rad/s^2: {} turns by t_end",
            plain(rate),
            plain(accel),
            turns(turned / std::f64::consts::TAU)
        ),
    );
}

/// The moment center of an axis motion: C on the axis, or the axis point (C then moves on a circle).
fn axis_point_lines(w: &mut Description, center: MomentCenter, point_b: &[f64; 3]) {
    if center != MomentCenter::AxisPoint {
        line(
            w,
            "moment center",
            "C, the mass center, on the axis: H and M are about it",
        );
    } else {
        line(
            w,
            "moment center",
            &format!(
                "the axis point {} m from C (body axes): H and M are about it",
                vec3(&(*point_b).into())
            ),
        );
        line(
            w,
            "",
            "C moves on a circle about the axis; the bearing force F = m a_C is in the F_s columns",
        );
    }
}

/// The state at t = 0: ω, H (free motion: in both axes), the moment a prescribed axis's bearings supply and its
/// force, the energy.
fn start_lines(w: &mut Description, start: &StartNumbers) {
    let v = |a: &[f64; 3]| Vector3::from(*a);
    let (omega_b, h_b) = (v(&start.omega_b), v(&start.h_o_b));
    line(
        w,
        "at t = 0",
        &format!("omega = {} rad/s (body axes)", vec3(&omega_b)),
    );
    let h_text = match start.m_o_b {
        None => format!(
            "H = {} kg*m^2/s (body axes), {} (space axes), |H| = {:.6e}",
            vec3(&h_b),
            vec3(&v(&start.h_o_s)),
            h_b.norm()
        ),
        Some(_) => format!(
            "H = {} kg*m^2/s (body axes), |H| = {:.6e}",
            vec3(&h_b),
            h_b.norm()
        ),
    };
    line(w, "", &h_text);
    if let Some(m_b) = &start.m_o_b {
        let m_b = v(m_b);
        line(
            w,
            "",
            &format!(
                "M = {} N*m (body axes), |M| = {:.6e}: the moment the bearings supply",
                vec3(&m_b),
                m_b.norm()
            ),
        );
    }
    if let Some(f) = &start.f_s {
        let f = v(f);
        line(
            w,
            "",
            &format!("F = {} N (space axes), |F| = {:.6e}", vec3(&f), f.norm()),
        );
    }
    line(w, "", &format!("kinetic energy {:.6e} J", start.energy));
}

/// The initial attitude, when it is not the identity.
fn attitude_line(w: &mut Description, scene: &Scene) {
    if scene.attitude0.angle() == 0.0 {
        return;
    }
    let (axis, angle) = scene
        .attitude0
        .axis_angle()
        .map_or((Vector3::z(), 0.0), |(a, angle)| (a.into_inner(), angle));
    line(
        w,
        "",
        &format!(
            "attitude: body axes turned {:.3} deg about {} from space axes",
            angle.to_degrees(),
            vec3(&axis)
        ),
    );
}

/// A hinge: its axis, I_uu and initial angle and rate.
fn hinge_lines(w: &mut Description, numbers: &CheckNumbers, axis: &AxisNumbers) {
    line(
        w,
        "motion",
        "a hinge: rotation about an axis fixed in the body and in space, theta from d/dt(I_uu theta') = M.u",
    );
    line(
        w,
        "",
        &format!(
            "axis {} (body axes); I_uu = {:.6e} kg*m^2; theta(0) = {} rad, rate {} rad/s at t = 0",
            vec3(&numbers.axis_b.unwrap_or_default().into()),
            axis.i_uu,
            plain(axis.theta0.unwrap_or_default()),
            plain(axis.rate)
        ),
    );
}

/// Where C is (with point masses), and for an axis motion its bearings and its imbalance: static m·e (e the
/// distance of C from the axis) and dynamic |I_A u − (u·I_A u) u| (the product of inertia about the axis).
fn support_lines(w: &mut Description, numbers: &CheckNumbers, axis: Option<&AxisNumbers>) {
    if numbers.center_b != [0.0; 3] {
        line(
            w,
            "mass center",
            &format!(
                "C at {} m from the reference origin (body axes), the point masses included",
                vec3(&numbers.center_b.into())
            ),
        );
    }
    let Some(axis) = axis else {
        return;
    };
    if let Some(b) = &axis.bearings {
        line(
            w,
            "bearings",
            &format!(
                "A at {} m along the axis ({} m from the reference origin), B at {} m ({})",
                plain(b.a),
                vec3(&b.a_b.into()),
                plain(b.b),
                vec3(&b.b_b.into())
            ),
        );
    }
    line(
        w,
        "imbalance",
        &format!(
            "static m*e = {:.6e} kg*m (C {:.6e} m from the axis); dynamic |I_A u - (u.I_A u) u| = {:.6e} kg*m^2",
            axis.imbalance_static_kgm, axis.imbalance_offset_m, axis.imbalance_dynamic_kgm2
        ),
    );
}

/// The effects, one a line, then each wheel's imbalance (a moment on the body turning with the wheel), or why
/// there are none.
fn effect_lines(w: &mut Description, scene: &Scene) {
    let imbalances = (scene.motion.attribute()).map_or_else(Vec::new, |a| a.door().moments());
    if scene.effects.is_empty() && imbalances.is_empty() {
        let none = match scene.motion.kind() {
            MotionKind::FixedAxis => "none: the motion is prescribed",
            MotionKind::Hinge => "none: the hinge turns at its initial rate",
            MotionKind::Free => "none: torque-free",
        };
        line(w, "effects", none);
    }
    let texts = scene.effects.iter().map(Effect::describe).chain(imbalances);
    for (k, text) in texts.enumerate() {
        line(w, if k == 0 { "effects" } else { "" }, &text);
    }
}

/// What the run keeps constant (the facts' invariants, by their columns), or that it keeps nothing: with an orbit's,
/// a law's or a drive's moments neither H nor the energy is an invariant.
fn conserved_line(w: &mut Description, scene: &Scene) {
    let invariants = &scene.facts().invariants;
    let text = if invariants.is_empty() {
        "nothing: the scene's moments change both H and the energy".to_string()
    } else {
        let columns: Vec<&str> = invariants.iter().map(|i| i.column()).collect();
        format!("{} (the drift panel shows their error)", columns.join(", "))
    };
    line(w, "conserved", &text);
}

/// The equation and the method with its step or tolerances; returns the estimate of the steps (one line or more).
fn method_lines(w: &mut Description, scene: &Scene) -> String {
    let s = &scene.solver;
    let form = match (scene.motion.attribute(), s.form) {
        (Some(attribute), form) => attribute.door().equation(form),
        (None, Form::Body) => "body axes: I*omega' + omega x I*omega = M",
        (None, Form::Space) => "space axes: dH_s/dt = M_s with I_s(theta)",
    };
    line(w, "equation", form);
    let runge_kutta = matches!(s.method, Method::Rk4 | Method::Dopri5 | Method::Dop853);
    let backend = if runge_kutta {
        format!(" ({} backend)", s.backend.name())
    } else {
        String::new()
    };
    let intervals = scene.schedule.len().saturating_sub(1);
    let rate = characteristic_rate(scene);
    if s.method.is_fixed_step() {
        line(
            w,
            "method",
            &format!(
                "{}{backend}, fixed step dt = {} s",
                s.method.name(),
                plain(s.dt)
            ),
        );
        let h = scene.fixed_step().unwrap_or(s.dt);
        if h < s.dt {
            line(
                w,
                "",
                &format!(
                    "steps of {} s are taken: each row interval in equal steps of at most dt",
                    plain(h)
                ),
            );
        }
        let steps = (s.t_end / h).round().max(intervals as f64);
        if h < s.dt {
            format!("{} steps of {} s", plain(steps), plain(h))
        } else {
            format!("{} steps of dt (t_end / dt)", plain(steps))
        }
    } else if let Some(estimate) = adaptive_steps_estimate(scene, rate) {
        line(
            w,
            "method",
            &format!(
                "{}{backend}, adaptive: rtol = {:e}, atol = {:e}",
                s.method.name(),
                s.rtol,
                s.atol
            ),
        );
        if estimate.is_finite() {
            format!(
                "about {} steps (adaptive: at least one per row interval, and about\nt_end*|omega|/(C*rtol^(1/(p+1))) by a rule of thumb good to a factor of 2, |omega| = {} rad/s)",
                plain(estimate),
                fixed(rate)
            )
        } else {
            "too many steps to estimate (|omega| * t_end is not a finite number)".to_string()
        }
    } else {
        line(
            w,
            "method",
            &format!(
                "{}{backend}: every row evaluated at its time",
                s.method.name()
            ),
        );
        "no time steps".to_string()
    }
}

/// The rows and columns of the output.
fn output_lines(w: &mut Description, scene: &Scene) {
    let s = &scene.solver;
    let rows = scene.schedule.len();
    let columns = scene.facts().columns().columns();
    let extra: Vec<&str> = (columns.iter().skip(BASE_COLUMNS.len()))
        .map(|c| c.name.as_ref())
        .collect();
    line(
        w,
        "output",
        &format!(
            "t = 0 .. {} s, a row every {} s: {rows} rows",
            plain(s.t_end),
            plain(scene.schedule.every())
        ),
    );
    line(
        w,
        "",
        &if extra.is_empty() {
            format!(
                "{} columns (t, q, omega, H, M, energy, H_norm)",
                BASE_COLUMNS.len()
            )
        } else {
            format!(
                "{} columns (t, q, omega, H, M, energy, H_norm), then {}",
                BASE_COLUMNS.len(),
                extra.join(", ")
            )
        },
    );
}
