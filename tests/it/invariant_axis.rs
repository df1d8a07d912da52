//! Rotation about an invariant axis: the support's loads (F_sup, M_drive, the two bearings) of prescribed
//! fixed-axis motion and of the driven hinge, against closed forms.
//!
//! Closed forms, each from Meghdari's *Rigid Body Dynamics* notes (eqs. 8.4, 8.7, 8.9) or a textbook:
//! - the skewed thin disk's couple |M| = ¼ m R² ω² sin θ cos θ (the notes' tilted-disk example), carried by the
//!   bearings as ±M/(b − a), constant in body axes and turning at ω in space;
//! - an offset mass's rotating force m e ω² (F = m a_C, eq. 8.7, with a_C = ω² e centripetal);
//! - lever-rule static loads W b/(b − a), −W a/(b − a) (statics of a beam on two supports);
//! - spin-up M_drive = I_uu α (eq. 8.9 about the axis);
//! - a hinge under a constant axial torque: θ̇ = M/I_uu t, θ = ½ M/I_uu t² (eq. 8.9), M_drive = 0;
//! - the compound pendulum's period 4 K(sin(θ₀/2)) √(I_A/(m g d)): Landau & Lifshitz, *Mechanics*, §11,
//!   problem 1, T = 4 √(l/g) K(sin(θ₀/2)) for the simple pendulum, with the compound pendulum's equivalent length
//!   l = I_A/(m d); and its support force m(a_C − g) at every row (eq. 8.7).

use crate::common::{assert_refused_writing_nothing, dir_entries, eulerdyn, write_file};
use eulerdyn::sample::Sample;
use eulerdyn::scene::{
    BodySpec, EffectSpec, FixedAxisSpec, HingeSpec, MotionSpec, SceneSpec, ShapeSpec, TorqueSpec,
};
use eulerdyn::{Axes, Form, Method, simulate};
use nalgebra::Vector3;

const M: f64 = 2.0;
const R: f64 = 0.3;
const OMEGA: f64 = 10.0;
const BEARINGS: (f64, f64) = (-0.1, 0.15);

fn rows(spec: &SceneSpec) -> Vec<Sample> {
    let scene = spec.build().unwrap_or_else(|e| panic!("{e}"));
    simulate::samples(&scene)
        .unwrap_or_else(|e| panic!("{e}"))
        .0
}

/// The notes' disk on an axis tilted `tilt_deg` from its symmetry axis, with bearings.
fn tilted_disk(tilt_deg: f64, form: Form) -> SceneSpec {
    SceneSpec::new(BodySpec::shape(M, ShapeSpec::thin_disk(R)), 1.0, 0.01)
        .with_motion(FixedAxisSpec::tilted(tilt_deg, OMEGA).with_bearings(BEARINGS.0, BEARINGS.1))
        .with_form(form)
}

/// |a − b| ≤ tol·scale, with a message.
fn close(a: f64, b: f64, tol: f64, what: &str) {
    assert!(
        (a - b).abs() <= tol * b.abs().max(1.0),
        "{what}: {a} vs {b}"
    );
}

/// R_A + R_B = F_sup and r_A × R_A + r_B × R_B = M_sup⊥ (M_sup = M − M_eff) at every row, to round-off of the
/// loads' size; `axis_s` gives each row's axis in space (it turns in a carrier).
pub(crate) fn assert_equilibrium(
    rows: &[Sample],
    (a, b): (f64, f64),
    axis_s: impl Fn(&Sample) -> Vector3<f64>,
    m_eff_s: impl Fn(&Sample) -> Vector3<f64>,
) {
    for s in rows {
        let u_s = &axis_s(s);
        let support = s.support.expect("support loads");
        let r = support.bearings.expect("bearing loads");
        let scale = 1.0 + support.f_sup_s.norm() + s.m_o_s.norm();
        let force = r.r_a_s + r.r_b_s - support.f_sup_s;
        assert!(
            force.norm() <= 1e-14 * scale,
            "t = {}: ΣR − F_sup = {force}",
            s.t
        );
        let m_sup = *s.m_o_s - m_eff_s(s);
        let m_perp = m_sup - u_s * m_sup.dot(u_s);
        let couple = (u_s * a).cross(&r.r_a_s) + (u_s * b).cross(&r.r_b_s);
        assert!(
            (couple - m_perp).norm() <= 1e-14 * scale,
            "t = {}: r × R − M_sup⊥ = {}",
            s.t,
            couple - m_perp
        );
        // To round-off of the loads' size, as the two checks above (a 3 g turn's loads are thousands of N).
        let drive = support.m_drive - m_sup.dot(u_s);
        assert!(
            drive.abs() <= 1e-14 * scale,
            "t = {}: M_drive − M_sup·u = {drive}",
            s.t
        );
        // The M_sup_s columns (CONTRACT, third round): the support's moment itself, M_sup = dH/dt − Σ M_effects.
        assert!(
            (*support.m_sup_s - m_sup).norm() <= 1e-14 * scale,
            "t = {}: M_sup_s − (M − M_eff) = {}",
            s.t,
            *support.m_sup_s - m_sup
        );
    }
}

#[test]
fn the_skewed_disk_bearings_carry_the_notes_couple() {
    for form in Form::ALL {
        for tilt in [10.0, 30.0, 45.0, 80.0] {
            let rows = rows(&tilted_disk(tilt, form));
            let theta = f64::to_radians(tilt);
            // The notes' couple ¼ m R² ω² sin θ cos θ, carried by the bearings as a pair of opposite forces.
            let couple = 0.25 * M * R * R * OMEGA * OMEGA * theta.sin() * theta.cos();
            let expected = couple / (BEARINGS.1 - BEARINGS.0);
            let first = rows[0].support.unwrap().bearings.unwrap();
            for s in &rows {
                let b = s.support.unwrap().bearings.unwrap();
                close(b.r_a_s.norm(), expected, 1e-9, "|R_A|");
                close(b.r_b_s.norm(), expected, 1e-9, "|R_B|");
                assert!(
                    (b.r_a_s + b.r_b_s).norm() <= 1e-12 * expected,
                    "a pure couple"
                );
                // Constant in body axes ...
                assert!(
                    (b.r_a_b - first.r_a_b).norm() <= 1e-9 * expected,
                    "t = {}",
                    s.t
                );
                // ... and turning at ω in space: R_A(t) = Rot(u, ω t) R_A(0).
                let u_s = *s.omega_s / OMEGA;
                let turned = nalgebra::UnitQuaternion::from_axis_angle(
                    &nalgebra::Unit::new_normalize(u_s),
                    OMEGA * s.t,
                ) * *first.r_a_s;
                assert!((*b.r_a_s - turned).norm() <= 1e-9 * expected, "t = {}", s.t);
                close(
                    s.support.unwrap().m_drive,
                    0.0,
                    1e-12,
                    "no drive at constant rate",
                );
            }
            let u_s = *rows[0].omega_s / OMEGA;
            assert_equilibrium(&rows, BEARINGS, |_| u_s, |_| Vector3::zeros());
        }
    }
}

#[test]
fn an_offset_mass_needs_a_rotating_force_m_e_omega_squared() {
    let e = 0.02;
    for form in Form::ALL {
        // A sphere on a vertical axis through a point e from C: C runs on a circle of radius e.
        let spec = SceneSpec::new(BodySpec::shape(M, ShapeSpec::sphere(0.1)), 1.0, 0.05)
            .with_motion(
                FixedAxisSpec::new([0.0, 0.0, 1.0], OMEGA)
                    .with_point([e, 0.0, 0.0])
                    .with_bearings(BEARINGS.0, BEARINGS.1),
            )
            .with_form(form);
        let rows = rows(&spec);
        for s in &rows {
            let f_sup = s.support.unwrap().f_sup_s;
            close(
                f_sup.norm(),
                M * e * OMEGA * OMEGA,
                1e-12,
                "|F_sup| = m e ω²",
            );
            assert!(f_sup.z.abs() <= 1e-12, "radial, across the axis");
        }
        assert_equilibrium(&rows, BEARINGS, |_| Vector3::z(), |_| Vector3::zeros());
    }
}

#[test]
fn a_resting_rotor_under_gravity_loads_its_bearings_by_the_lever_rule() {
    let (a, b) = (-0.2, 0.6);
    // A disk on a horizontal axis (space x) through C, at rest: the bearings carry the weight W = m g.
    let spec = SceneSpec::new(BodySpec::shape(M, ShapeSpec::thin_disk(R)), 0.5, 0.1)
        .with_motion(FixedAxisSpec::new([1.0, 0.0, 0.0], 0.0).with_bearings(a, b))
        .with_effect(EffectSpec::weight([0.0, 0.0, -9.81]));
    let weight = M * 9.81;
    for s in rows(&spec) {
        let loads = s.support.unwrap();
        let r = loads.bearings.unwrap();
        close(loads.f_sup_s.z, weight, 1e-15, "F_sup carries the weight");
        close(r.r_a_s.z, weight * b / (b - a), 1e-14, "R_A = W b/(b − a)");
        close(
            r.r_b_s.z,
            -weight * a / (b - a),
            1e-14,
            "R_B = −W a/(b − a)",
        );
    }
}

#[test]
fn spin_up_needs_a_drive_moment_i_alpha() {
    let alpha = 3.0;
    for form in Form::ALL {
        let spec = SceneSpec::new(BodySpec::shape(M, ShapeSpec::thin_disk(R)), 1.0, 0.1)
            .with_motion(FixedAxisSpec::tilted(30.0, 0.0).with_accel(alpha))
            .with_form(form);
        // I_uu = u·I u for u = (0, −sin θ, cos θ): ¼ m R² sin²θ + ½ m R² cos²θ.
        let theta = 30f64.to_radians();
        let i_uu = M * R * R * (0.25 * theta.sin().powi(2) + 0.5 * theta.cos().powi(2));
        for s in rows(&spec) {
            close(
                s.support.unwrap().m_drive,
                i_uu * alpha,
                1e-12,
                "M_drive = I_uu α",
            );
            close(s.support.unwrap().theta_ddot, alpha, 0.0, "θ̈");
        }
    }
}

#[test]
fn a_hinge_under_a_constant_axial_torque_accelerates_uniformly() {
    let torque = 0.5;
    for form in Form::ALL {
        for method in [Method::Rk4, Method::Dopri5, Method::Dop853] {
            let spec = SceneSpec::new(BodySpec::shape(M, ShapeSpec::thin_disk(R)), 2.0, 0.1)
                .with_motion(HingeSpec::new([0.0, 0.0, 1.0], 1.0).with_bearings(-0.1, 0.1))
                .with_effect(TorqueSpec::new(Axes::Body, [0.0, 0.0, torque]))
                .with_method(method)
                .with_form(form)
                .with_dt(1e-3);
            let i_uu = 0.5 * M * R * R;
            let alpha = torque / i_uu;
            for s in rows(&spec) {
                let loads = s.support.unwrap();
                close(loads.theta_dot, 1.0 + alpha * s.t, 1e-9, "θ̇ linear");
                close(
                    s.theta.unwrap(),
                    s.t + 0.5 * alpha * s.t * s.t,
                    1e-9,
                    "θ quadratic",
                );
                close(loads.m_drive, 0.0, 1e-12, "a hinge has no drive");
                assert!(
                    loads.bearings.unwrap().r_a_s.norm() <= 1e-12,
                    "a balanced rotor"
                );
            }
        }
    }
}

/// The rod pendulum of scenarios/rod_pendulum.toml in code: a thin rod hinged at one end about body z, released
/// from rest `amplitude_deg` from the hanging position (gravity −y in space).
fn rod_pendulum(amplitude_deg: f64, form: Form) -> SceneSpec {
    let h = std::f64::consts::FRAC_1_SQRT_2;
    SceneSpec::new(BodySpec::shape(1.0, ShapeSpec::thin_rod(1.0)), 4.0, 0.001)
        .with_motion(
            HingeSpec::new([0.0, 0.0, 1.0], 0.0)
                .with_point([-0.5, 0.0, 0.0])
                .with_angle_deg(amplitude_deg)
                .with_bearings(-0.05, 0.05),
        )
        .with_attitude([h, 0.0, 0.0, -h])
        .with_effect(EffectSpec::weight([0.0, -9.81, 0.0]))
        .with_tolerances(1e-12, 1e-14)
        .with_form(form)
}

#[test]
fn the_compound_pendulum_swings_with_the_elliptic_period() {
    let theta0 = 75f64.to_radians();
    let (m, g, d, i_a): (f64, f64, f64, f64) = (1.0, 9.81, 0.5, 1.0 / 3.0);
    let k = (theta0 / 2.0).sin();
    let period = 4.0 * ellip::ellipk(k * k).unwrap() * (i_a / (m * g * d)).sqrt();
    for form in Form::ALL {
        let rows = rows(&rod_pendulum(75.0, form));
        // Downward crossings of θ = 0, by inverse linear interpolation between rows 1 ms apart: the crossing time
        // is then off by about θ̈ Δt²/(8 θ̇) ~ 1e-7 s, well inside the 2e-6 asked.
        let crossings: Vec<f64> = rows
            .windows(2)
            .filter(|w| w[0].theta.unwrap() > 0.0 && w[1].theta.unwrap() <= 0.0)
            .map(|w| {
                let (a, b) = (w[0].theta.unwrap(), w[1].theta.unwrap());
                w[0].t + a / (a - b) * (w[1].t - w[0].t)
            })
            .collect();
        assert!(crossings.len() >= 2, "{crossings:?}");
        let measured = crossings[1] - crossings[0];
        assert!(
            (measured - period).abs() <= 2e-6 * period,
            "{form:?}: period {measured} vs 4K√(I/mgd) = {period}"
        );
        // The support force is m(a_C − g) at every row, a_C from the rows' own θ, θ̇, θ̈.
        for s in &rows {
            let loads = s.support.unwrap();
            let rho_s = s.q * Vector3::new(0.5, 0.0, 0.0);
            let (w, alpha) = (
                Vector3::z() * loads.theta_dot,
                Vector3::z() * loads.theta_ddot,
            );
            let a_c = alpha.cross(&rho_s) + w.cross(&w.cross(&rho_s));
            let expected = (a_c - Vector3::new(0.0, -g, 0.0)) * m;
            assert!(
                (*loads.f_sup_s - expected).norm() <= 1e-12 * (m * g),
                "t = {}",
                s.t
            );
            close(loads.m_drive, 0.0, 1e-12, "no drive");
        }
        let weight_moment =
            |s: &Sample| (s.q * Vector3::new(0.5, 0.0, 0.0)).cross(&Vector3::new(0.0, -g, 0.0));
        assert_equilibrium(&rows, (-0.05, 0.05), |_| Vector3::z(), weight_moment);
    }
}

#[test]
fn the_hinge_forms_agree() {
    let body = rows(&rod_pendulum(75.0, Form::Body));
    let space = rows(&rod_pendulum(75.0, Form::Space));
    for (b, s) in body.iter().zip(&space) {
        // Both integrate the same θ to rtol 1e-12 over ~2 swings.
        assert!(
            (b.theta.unwrap() - s.theta.unwrap()).abs() <= 1e-9,
            "t = {}",
            b.t
        );
        assert!((b.h_o_s - s.h_o_s).norm() <= 1e-9, "t = {}", b.t);
    }
}

#[test]
fn balancing_the_skewed_disk_takes_the_notes_two_equal_opposite_masses() {
    use eulerdyn::analysis::balance::{Planes, balance};
    let planes = Planes {
        a: -0.1,
        b: 0.12,
        radius: 0.25,
    };
    for tilt in [5.0, 30.0, 60.0] {
        let spec = tilted_disk(tilt, Form::Body);
        let result = balance(&spec, &planes).unwrap();
        let theta = f64::to_radians(tilt);
        // The notes' skewed disk: m_c = ¼ m R² sin θ cos θ / (R_c (b − a)), on opposite sides.
        let expected =
            0.25 * M * R * R * theta.sin() * theta.cos() / (planes.radius * (planes.b - planes.a));
        let [c_a, c_b] = result.corrections;
        close(c_a.mass, expected, 1e-12, "m_A");
        close(c_b.mass, expected, 1e-12, "m_B");
        let apart = (c_a.angle_deg - c_b.angle_deg).rem_euclid(360.0);
        close(apart, 180.0, 1e-12, "opposite sides");
        // The balanced rotor's bearings carry nothing at any rate: below 1e-9 of the unbalanced loads.
        let before = rows(&spec);
        let after = rows(&result.balanced);
        let scale = before[0].support.unwrap().bearings.unwrap().r_a_s.norm();
        for s in &after {
            let b = s.support.unwrap().bearings.unwrap();
            assert!(
                b.r_a_s.norm().max(b.r_b_s.norm()) <= 1e-9 * scale,
                "t = {}",
                s.t
            );
        }
        assert!(result.largest_reaction[1] <= 1e-9 * result.largest_reaction[0]);
    }
}

#[test]
fn balancing_an_offset_sphere_puts_half_its_static_imbalance_in_each_plane() {
    use eulerdyn::analysis::balance::{Planes, balance};
    let e = 0.01;
    // A sphere whose axis (body z) passes e from C: static imbalance m e only.
    let spec = SceneSpec::new(BodySpec::shape(M, ShapeSpec::sphere(0.1)), 1.0, 0.1).with_motion(
        FixedAxisSpec::new([0.0, 0.0, 1.0], OMEGA)
            .with_point([e, 0.0, 0.0])
            .with_bearings(-0.2, 0.2),
    );
    let planes = Planes {
        a: -0.05,
        b: 0.05,
        radius: 0.08,
    };
    let result = balance(&spec, &planes).unwrap();
    for c in result.corrections {
        close(
            c.mass,
            M * e / (2.0 * planes.radius),
            1e-12,
            "m e / (2 R_c)",
        );
    }
    let after = rows(&result.balanced);
    for s in &after {
        let f_sup = s.support.unwrap().f_sup_s;
        assert!(
            f_sup.norm() <= 1e-9 * M * e * OMEGA * OMEGA,
            "C on the axis: {f_sup}"
        );
    }
}

#[test]
fn point_masses_move_the_mass_center_and_positions_stay_from_the_reference_origin() {
    // A point mass outside a sphere: C moves to m_p p / (m + m_p); the axis through the
    // reference origin then has C off it by that much, and needs the force (m + m_p) |c| ω².
    let (m_p, p) = (0.5, 0.1);
    let spec = SceneSpec::new(
        BodySpec::shape(M, ShapeSpec::sphere(0.1)).with_point_mass(m_p, [p, 0.0, 0.0]),
        0.5,
        0.1,
    )
    .with_motion(FixedAxisSpec::new([0.0, 0.0, 1.0], OMEGA));
    let scene = spec.build().unwrap();
    let c = m_p * p / (M + m_p);
    assert!((scene.center_b - Vector3::new(c, 0.0, 0.0)).norm() <= 1e-16);
    for s in rows(&spec) {
        close(
            s.support.unwrap().f_sup_s.norm(),
            (M + m_p) * c * OMEGA * OMEGA,
            1e-12,
            "F",
        );
    }
}

/// A hinge scene with the lines `extra` appended to `[motion]`, and `tail` after it.
fn hinge_text(extra: &str, tail: &str) -> String {
    format!(
        "[body]\nmass = 1.0\nshape = {{ type = \"thin_disk\", radius = 0.3 }}\n\
         [motion]\ntype = \"hinge\"\naxis = [0.0, 0.0, 1.0]\nrate = 1.0\n{extra}\n\
         {tail}\n[solver]\nt_end = 1.0\n[output]\nevery = 0.1\n"
    )
}

#[test]
fn bad_invariant_axis_input_is_refused_with_the_file_and_key_and_writes_nothing() {
    let cases = [
        (
            "pivot with a hinge",
            hinge_text(
                "",
                "[[effect]]\ntype = \"gravity\"\npivot = [0.0, 0.0, 0.1]",
            ),
            "effect[0].pivot",
        ),
        (
            "equal bearing positions",
            hinge_text("bearings = [0.1, 0.1]", ""),
            "motion.bearings",
        ),
        (
            "a hinge with a splitting method",
            hinge_text("", "").replace("t_end = 1.0", "t_end = 1.0\nmethod = \"split2\""),
            "solver.method",
        ),
        (
            "a fixed axis with a torque",
            hinge_text("", "[[effect]]\ntype = \"torque\"\nvalue = [0.0, 0.0, 1.0]")
                .replace("\"hinge\"", "\"fixed_axis\""),
            "effect[0]",
        ),
        (
            "a hinge with accel",
            hinge_text("accel = 1.0", ""),
            "motion.accel",
        ),
        (
            "a point mass of zero mass",
            hinge_text("", "").replace(
                "[motion]",
                "[[body.point_mass]]\nmass = 0.0\nat = [0.1, 0.0, 0.0]\n[motion]",
            ),
            "body.point_mass[0].mass",
        ),
        (
            "a point mass at infinity",
            hinge_text("", "").replace(
                "[motion]",
                "[[body.point_mass]]\nmass = 0.1\nat = [inf, 0.0, 0.0]\n[motion]",
            ),
            "body.point_mass[0].at",
        ),
    ];
    assert_refused_writing_nothing(&cases);
}

#[test]
fn balance_refuses_what_it_cannot_balance_and_writes_nothing() {
    let dir = tempfile::tempdir().unwrap();
    let free = write_file(
        dir.path(),
        "free.toml",
        "[body]\nmass = 1.0\ninertia = [1.0, 2.0, 3.0]\n[solver]\nt_end = 1.0\n[output]\nevery = 0.1\n",
    );
    let disk = write_file(dir.path(), "disk.toml", hinge_text("", ""));
    let out = dir.path().join("balanced.toml");
    let out = out.to_str().unwrap();
    for (name, scene, planes, radius, expect) in [
        (
            "a free body",
            &free,
            "-0.1,0.1",
            "0.2",
            "fixed_axis or a hinge",
        ),
        ("A = B", &disk, "0.1,0.1", "0.2", "A != B"),
        ("R = 0", &disk, "-0.1,0.1", "0", "radius"),
        ("R < 0", &disk, "-0.1,0.1", "-1", "radius"),
        ("one plane", &disk, "0.1", "0.2", "--planes"),
    ] {
        let result = eulerdyn([
            "balance",
            scene.to_str().unwrap(),
            "--planes",
            planes,
            "--radius",
            radius,
            "-o",
            out,
        ]);
        assert_eq!(result.code, Some(2), "{name}: {}", result.stderr);
        assert!(result.stderr.contains(expect), "{name}: {}", result.stderr);
        assert_eq!(
            dir_entries(dir.path()),
            ["disk.toml", "free.toml"],
            "{name}"
        );
    }
}

#[test]
fn balance_writes_a_scene_whose_run_shows_no_rotating_reaction() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("balanced.toml");
    let result = eulerdyn([
        "balance",
        crate::common::repo_path("scenarios/rotor_bearings.toml")
            .to_str()
            .unwrap(),
        "--planes",
        "-0.1,0.1",
        "--radius",
        "0.2",
        "-o",
        out.to_str().unwrap(),
    ]);
    result.expect_code(0);
    assert!(result.stdout.contains("plane A") && result.stdout.contains("before"));
    let run = eulerdyn(["run", out.to_str().unwrap()]);
    run.expect_code(0);
    let (head, records) = crate::common::read_csv(&run.stdout);
    // With gravity the bearings still carry the weight, the same at every row: nothing rotates.
    for name in [
        "R_A_s_x", "R_A_s_y", "R_A_s_z", "R_B_s_x", "R_B_s_y", "R_B_s_z",
    ] {
        let column = crate::common::column(&head, &records, name);
        let spread = column
            .iter()
            .fold(0f64, |m, v| m.max((v - column[0]).abs()));
        assert!(spread <= 1e-9 * 19.62, "{name} varies by {spread}");
    }
}

#[test]
fn a_motor_runs_the_hinge_up_to_the_steady_speed_against_viscous_friction() {
    // I_uu θ̈ = M − c θ̇ from rest: θ̇(t) = (M/c)(1 − exp(−c t / I_uu)) (the first-order linear ODE's solution).
    let text =
        std::fs::read_to_string(crate::common::repo_path("scenarios/motor_runup.toml")).unwrap();
    let scene =
        eulerdyn::scene::parse_spec(std::path::Path::new("motor_runup.toml"), &text).unwrap();
    let theta = 30f64.to_radians();
    let i_uu = M * R * R * (0.25 * theta.sin().powi(2) + 0.5 * theta.cos().powi(2));
    let (torque, c) = (0.5, 0.05);
    for form in Form::ALL {
        for s in rows(&scene.clone().with_form(form)) {
            let expected = torque / c * (1.0 - (-c * s.t / i_uu).exp());
            close(s.support.unwrap().theta_dot, expected, 1e-9, "θ̇");
            close(
                s.support.unwrap().m_drive,
                0.0,
                1e-12,
                "no drive: the motor is an effect",
            );
        }
    }
}

#[test]
fn attitudes_can_be_written_as_euler_angles_or_by_the_axis_in_space() {
    use nalgebra::UnitQuaternion;
    // Intrinsic z-y'-x'': R = R_z(ψ) R_y(θ) R_x(φ), for [ψ, θ, φ] = [30, 20, 10] degrees.
    let body = BodySpec::principal(1.0, [1.0, 2.0, 3.0]);
    let mut spec = SceneSpec::new(body, 1.0, 0.5);
    spec.initial = Some(eulerdyn::scene::InitialSpec {
        attitude: Some(eulerdyn::scene::AttitudeSpec::EulerDeg([30.0, 20.0, 10.0])),
        ..Default::default()
    });
    let expected = UnitQuaternion::from_axis_angle(&Vector3::z_axis(), 30f64.to_radians())
        * UnitQuaternion::from_axis_angle(&Vector3::y_axis(), 20f64.to_radians())
        * UnitQuaternion::from_axis_angle(&Vector3::x_axis(), 10f64.to_radians());
    assert!(spec.build().unwrap().attitude0.angle_to(&expected) <= 1e-15);
    // The notes' disk with its shaft put on space z by `axis_in_space`: the attitude of tilted_disk.toml, written
    // there as a quaternion (−30° about x).
    let mut disk = tilted_disk(30.0, Form::Body);
    let Some(MotionSpec::FixedAxis(axis)) = disk.motion.as_mut() else {
        panic!("the tilted disk is on a fixed axis")
    };
    axis.axis.axis_in_space = Some([0.0, 0.0, 1.0]);
    let by_axis = rows(&disk);
    let by_quaternion = rows(&tilted_disk(30.0, Form::Body).with_attitude([
        0.9659258262890683,
        -0.25881904510252074,
        0.0,
        0.0,
    ]));
    for (a, b) in by_axis.iter().zip(&by_quaternion) {
        assert!(
            a.q.angle_to(&b.q) <= 1e-15 && (a.h_o_s - b.h_o_s).norm() <= 1e-15,
            "t = {}",
            a.t
        );
    }
    // Both ways at once is refused.
    let both = disk
        .with_attitude([1.0, 0.0, 0.0, 0.0])
        .build()
        .unwrap_err();
    assert_eq!(both.key.to_string(), "motion.axis_in_space");
}

#[test]
fn gravity_scenes_write_a_conserved_total_energy() {
    // T + V with V = −m g·r_C is conserved when only gravity acts (eq. 8.7's work–energy consequence); T is not.
    for form in Form::ALL {
        let rows = rows(&rod_pendulum(75.0, form));
        let total0 = rows[0].energy + rows[0].potential.unwrap();
        // Released from rest at 75°: V(0) = −m g d cos 75°, T(0) = 0.
        close(
            total0,
            -9.81 * 0.5 * 75f64.to_radians().cos(),
            1e-15,
            "V(0)",
        );
        let kinetic_swing = rows.iter().map(|s| s.energy).fold(0f64, f64::max);
        assert!(kinetic_swing > 1.0, "T changes: {kinetic_swing}");
        for s in &rows {
            let total = s.energy + s.potential.unwrap();
            assert!(
                (total - total0).abs() <= 1e-10 * kinetic_swing,
                "t = {}",
                s.t
            );
        }
    }
}

#[test]
fn plot_draws_the_bearings_panel_of_a_run_with_bearings() {
    let dir = tempfile::tempdir().unwrap();
    let csv = dir.path().join("rotor.csv");
    let svg = dir.path().join("rotor.svg");
    eulerdyn([
        "run",
        crate::common::repo_path("scenarios/rotor_bearings.toml")
            .to_str()
            .unwrap(),
        "-o",
        csv.to_str().unwrap(),
    ])
    .expect_code(0);
    let out = eulerdyn([
        "plot",
        csv.to_str().unwrap(),
        "-o",
        svg.to_str().unwrap(),
        "--panels",
        "bearings",
    ]);
    out.expect_code(0);
    let text = std::fs::read_to_string(&svg).unwrap();
    for label in ["|R_A|", "|R_B|", "R_A,x", "R_B,z"] {
        assert!(text.contains(label), "{label} in the legend");
    }
    // A free run has no bearings: the panel is refused with the columns it lacks.
    let free_csv = dir.path().join("free.csv");
    eulerdyn([
        "run",
        crate::common::repo_path("scenarios/asymmetric_free.toml")
            .to_str()
            .unwrap(),
        "-o",
        free_csv.to_str().unwrap(),
    ])
    .expect_code(0);
    let refused = eulerdyn([
        "plot",
        free_csv.to_str().unwrap(),
        "-o",
        svg.to_str().unwrap(),
        "--panels",
        "bearings",
    ]);
    assert_eq!(refused.code, Some(2), "{}", refused.stderr);
    assert!(refused.stderr.contains("R_A_b_x"), "{}", refused.stderr);
}

#[test]
fn a_hinge_follows_a_sine_torque_given_in_space_axes() {
    // I_uu θ̈ = M sin(2π f t) about the axis (space z = body z here) from rest:
    // θ̇ = M/(I_uu ω_f) (1 − cos ω_f t), ω_f = 2π f (integrating the sine once). The torque's part across the axis
    // (along space x) goes to the bearings.
    let (torque, freq) = (0.3, 0.5);
    let w_f = 2.0 * std::f64::consts::PI * freq;
    let i_uu = 0.5 * M * R * R;
    for form in Form::ALL {
        let spec = SceneSpec::new(BodySpec::shape(M, ShapeSpec::thin_disk(R)), 3.0, 0.05)
            .with_motion(HingeSpec::new([0.0, 0.0, 1.0], 0.0).with_bearings(-0.1, 0.1))
            .with_effect(TorqueSpec::new(Axes::Space, [0.2, 0.0, torque]).sine(freq, 0.0))
            .with_tolerances(1e-12, 1e-14)
            .with_form(form);
        for s in rows(&spec) {
            let loads = s.support.unwrap();
            let expected = torque / (i_uu * w_f) * (1.0 - (w_f * s.t).cos());
            close(loads.theta_dot, expected, 1e-9, "θ̇");
            close(loads.m_drive, 0.0, 1e-12, "no drive");
            // The bearings carry the cross-axis torque 0.2 sin(ω_f t) along space x as a couple.
            let b = loads.bearings.unwrap();
            let couple =
                (Vector3::z() * -0.1).cross(&b.r_a_s) + (Vector3::z() * 0.1).cross(&b.r_b_s);
            close(
                couple.x,
                -0.2 * (w_f * s.t).sin(),
                1e-9,
                "the bearings' couple",
            );
        }
    }
}
