//! Free rotation — torque-free, under torques, gravity about a pivot, damping — in both forms of Euler's
//! equation, with every method and backend, against the closed forms of `eulerdyn::exact`.
//!
//! Error bounds are scaled by the method's accuracy parameter and the horizon: for the adaptive methods a global
//! error of `K_ADAPTIVE · rtol` per unit of |ω|·t_end (local errors of size rtol·|y| per step, accumulated about
//! linearly over the run); for RK4 the global error of an order-4 method, `K_RK4 · (|ω| dt)⁴ · |ω| t_end`.

use std::convert::Infallible;

use eulerdyn::analysis::compare::attitude_angle;
use eulerdyn::exact::{
    AxialTorqueSymmetric, HeavySymmetricTop, PrecessionRoots, SteadyPrecession, TorqueFreeBody,
};
use eulerdyn::named::Named;
use eulerdyn::sample::Sample;
use eulerdyn::scene::Overrides;
use eulerdyn::scene::Scene;
use eulerdyn::simulate;
use nalgebra::{Matrix3, Rotation3, UnitQuaternion, Vector3};

use crate::common::{scene_from, sign_changes};

/// Global-error constant of the adaptive methods relative to rtol per unit of |ω|·t. Measured on the asymmetric
/// torque-free body: 0.0004–0.15 (dopri5 in the space form is the largest); a tolerance that is not honoured, e.g.
/// a wrong tableau node, exceeds it by orders of magnitude.
const K_ADAPTIVE: f64 = 1.0;
/// Global-error constant of RK4 relative to (|ω| dt)⁴·|ω| t. Measured on the asymmetric torque-free body: ≤ 4e-6.
const K_RK4: f64 = 0.01;

fn rows(scene: &Scene) -> Vec<Sample> {
    let mut out = Vec::new();
    simulate::run(scene, |s| {
        out.push(*s);
        Ok::<(), Infallible>(())
    })
    .unwrap();
    out
}

/// Every method × backend × frame, with its accuracy parameter.
fn configurations() -> Vec<Overrides> {
    let mut out = Vec::new();
    for (method, rtol, dt) in [
        ("rk4", None, Some(2e-3)),
        ("dopri5", Some(1e-9), None),
        ("dop853", Some(1e-10), None),
    ] {
        for backend in ["own", "ode_solvers"] {
            for frame in ["body", "space"] {
                out.push(Overrides {
                    method: Some(Named::parse(method).unwrap()),
                    backend: Some(Named::parse(backend).unwrap()),
                    form: Some(Named::parse(frame).unwrap()),
                    rtol,
                    atol: rtol.map(|r| r * 1e-2),
                    dt,
                    ..Overrides::default()
                });
            }
        }
    }
    out
}

/// The error bound of a configuration for a run whose angular speed is at most `omega_max` over `t_end`.
fn bound(o: &Overrides, omega_max: f64, t_end: f64) -> f64 {
    match (o.rtol, o.dt) {
        (Some(rtol), _) => K_ADAPTIVE * rtol * (1.0 + omega_max * t_end),
        (None, Some(dt)) => K_RK4 * (omega_max * dt).powi(4) * (1.0 + omega_max * t_end),
        _ => unreachable!(),
    }
}

fn label(o: &Overrides) -> String {
    format!(
        "{} {} {}",
        o.method.map_or("", |m| m.name()),
        o.backend.map_or("", |b| b.name()),
        o.form.map_or("", |f| f.name())
    )
}

#[test]
fn torque_free_asymmetric_body_matches_the_jacobi_elliptic_solution() {
    // Landau & Lifshitz §37: ω(t) by sn, cn, dn; attitude by the elliptic integral of the third kind. Both classes
    // of motion: M² > 2E·I2 (circulating about the major axis) and M² < 2E·I2 (about the minor axis). The body axes
    // are not principal in the second case (a rotated tensor), so the principal mapping is exercised too.
    let axes = Rotation3::from_euler_angles(0.3, -0.5, 1.2);
    let rotated = axes.matrix()
        * Matrix3::from_diagonal(&Vector3::new(1.0, 2.0, 3.0))
        * axes.matrix().transpose();
    let full = |m: &Matrix3<f64>| {
        format!(
            "[[{:?}, {:?}, {:?}], [{:?}, {:?}, {:?}], [{:?}, {:?}, {:?}]]",
            m[(0, 0)],
            m[(0, 1)],
            m[(0, 2)],
            m[(1, 0)],
            m[(1, 1)],
            m[(1, 2)],
            m[(2, 0)],
            m[(2, 1)],
            m[(2, 2)]
        )
    };
    let cases = [
        ("[1.0, 2.0, 3.0]".to_string(), Vector3::new(0.3, 0.0, 2.0)),
        (full(&rotated), axes * Vector3::new(2.0, 0.2, 0.3)),
    ];
    let t_end = 20.0;
    for (inertia, omega0_b) in cases {
        let text = format!(
            "[body]\nmass = 1.0\ninertia = {inertia}\n[initial]\nomega = [{:?}, {:?}, {:?}]\nattitude = [0.9, 0.1, -0.3, 0.2]\n[solver]\nt_end = {t_end}\n[output]\nevery = 0.25\n",
            omega0_b[0], omega0_b[1], omega0_b[2]
        );
        for o in configurations() {
            let scene = scene_from(&text, &o);
            let principal = scene.body.principal();
            let p_b = UnitQuaternion::from_rotation_matrix(&principal.axes_b);
            let exact = TorqueFreeBody::new(
                principal.moments,
                p_b.inverse_transform_vector(&omega0_b),
                scene.attitude0 * p_b,
            )
            .unwrap();
            let omega_max = omega0_b.norm() * 2.0;
            let limit = bound(&o, omega_max, t_end);
            let (mut err_w, mut err_q) = (0.0f64, 0.0f64);
            for row in rows(&scene) {
                let w = p_b * exact.omega_p(row.t);
                err_w = err_w.max((*row.omega_b - w).norm() / omega0_b.norm());
                err_q = err_q.max(attitude_angle(
                    &row.q,
                    &(exact.attitude(row.t) * p_b.inverse()),
                ));
            }
            assert!(
                err_w <= limit,
                "{}: ω error {err_w:e} > {limit:e}",
                label(&o)
            );
            assert!(
                err_q <= limit,
                "{}: attitude error {err_q:e} > {limit:e}",
                label(&o)
            );
        }
    }
}

#[test]
fn torque_free_invariants_and_body_space_agreement() {
    // Torque-free: energy ½ω·Iω and H_s are constants of the motion (Euler's equation with M = 0). In the space form
    // H_s is the state with zero derivative, so every Runge–Kutta method keeps it exactly.
    let text = "[body]\nmass = 1.0\ninertia = [1.0, 2.0, 3.0]\n[initial]\nomega = [0.3, 0.0, 2.0]\n[solver]\nt_end = 50.0\n[output]\nevery = 0.5\n";
    for o in configurations() {
        let scene = scene_from(text, &o);
        let rows = rows(&scene);
        let (e0, h0) = (rows[0].energy, rows[0].h_o_s);
        let limit = bound(&o, 2.1, 50.0);
        for row in &rows {
            assert!(
                (row.energy - e0).abs() <= limit * e0,
                "{}: energy drift",
                label(&o)
            );
            assert!(
                (row.h_o_s - h0).norm() <= limit * h0.norm(),
                "{}: H_s drift",
                label(&o)
            );
            assert!((row.q.into_inner().norm() - 1.0).abs() <= 4.0 * f64::EPSILON);
            if o.form == Some(eulerdyn::Form::Space) {
                assert_eq!(
                    row.h_o_s,
                    h0,
                    "{}: H_s is the exact invariant of the space form",
                    label(&o)
                );
            }
        }
    }
    // Body and space forms agree row by row (both converge to the same solution).
    let body = rows(&scene_from(
        text,
        &Overrides {
            form: Some(Named::parse("body").unwrap()),
            ..Overrides::default()
        },
    ));
    let space = rows(&scene_from(
        text,
        &Overrides {
            form: Some(Named::parse("space").unwrap()),
            ..Overrides::default()
        },
    ));
    for (b, s) in body.iter().zip(&space) {
        assert_eq!(b.t, s.t);
        assert!((b.omega_b - s.omega_b).norm() <= 1e-8 * 2.0, "t = {}", b.t);
        assert!(attitude_angle(&b.q, &s.q) <= 1e-8);
    }
}

#[test]
fn symmetric_body_precesses_in_the_body_at_the_closed_form_rate() {
    // Goldstein §5.6: for I1 = I2, Euler's equations give ω̇1 = −Ω_b ω2, ω̇2 = Ω_b ω1 with Ω_b = (I3 − I1)/I1·ω3: the
    // transverse ω turns in the body at Ω_b (counter-clockwise seen from +z when I3 > I1):
    // ω_b(t) = (w cos Ω_b t, w sin Ω_b t, ω3) for ω_b(0) = (w, 0, ω3).
    let text = std::fs::read_to_string("scenarios/symmetric_top_free.toml").unwrap();
    let (i1, i3, w, w3) = (0.5, 0.8, 0.4, 3.0);
    let rate = (i3 - i1) / i1 * w3;
    for o in configurations() {
        let scene = scene_from(&text, &o);
        let limit = bound(&o, 3.1, 20.0);
        for row in rows(&scene) {
            let expected = Vector3::new(w * (rate * row.t).cos(), w * (rate * row.t).sin(), w3);
            assert!(
                (*row.omega_b - expected).norm() <= limit * w3,
                "{} t = {}: {} vs {expected}",
                label(&o),
                row.t,
                row.omega_b
            );
        }
    }
}

#[test]
fn constant_axial_torque_on_a_symmetric_body() {
    // ω3(t) = ω3(0) + M3 t / I3; the transverse part turns by (I3 − I1)/I1·∫ω3 dt (closed form in
    // eulerdyn::exact::AxialTorqueSymmetric).
    let text = "[body]\nmass = 1.0\ninertia = [0.5, 0.5, 0.8]\n[initial]\nomega = [0.4, 0.0, 3.0]\n[[effect]]\ntype = \"torque\"\nvalue = [0.0, 0.0, 0.2]\n[solver]\nt_end = 10.0\n[output]\nevery = 0.1\n";
    let exact = AxialTorqueSymmetric::new(0.5, 0.8, 0.2, Vector3::new(0.4, 0.0, 3.0)).unwrap();
    for o in configurations() {
        let scene = scene_from(text, &o);
        let limit = bound(&o, 5.6, 10.0);
        for row in rows(&scene) {
            let w = exact.omega_p(row.t);
            assert!(
                (*row.omega_b - w).norm() <= limit * w.norm(),
                "{} t = {}",
                label(&o),
                row.t
            );
        }
    }
}

#[test]
fn heavy_top_in_steady_precession_and_energy_conservation() {
    // Goldstein §5.7: steady precession at tilt θ when m g l = Ω(I3 ω3 − I_t Ω cos θ); the run started on it stays on
    // it (ω and attitude), and T + V is conserved (V = −m g·r_C, r_C from the pivot) for any start.
    let (mass, radius, height, l, g) = (0.5, 0.04, 0.02, 0.05, 9.81);
    let i_tc = mass * (3.0 * radius * radius + height * height) / 12.0;
    let i_a = mass * radius * radius / 2.0;
    let top = HeavySymmetricTop::new(i_tc + mass * l * l, i_a, mass, g, l).unwrap();
    let (theta, omega3) = (20f64.to_radians(), 150.0);
    let PrecessionRoots::Two { slow, .. } = top.steady_precession_rates(theta, omega3).unwrap()
    else {
        panic!("a fast top has two steady precession rates")
    };
    let steady = SteadyPrecession::new(top, theta, omega3, slow, 0.0, 0.0).unwrap();
    let q0 = steady.attitude(0.0);
    let w0 = steady.omega0_p();
    let text = format!(
        "[body]\nmass = {mass}\nshape = {{ type = \"cylinder\", radius = {radius}, height = {height} }}\n[initial]\nomega = [{:?}, {:?}, {:?}]\nattitude = [{:?}, {:?}, {:?}, {:?}]\n[[effect]]\ntype = \"gravity\"\ng = [0.0, 0.0, -{g}]\npivot = [0.0, 0.0, -{l}]\n[solver]\nt_end = 2.0\n[output]\nevery = 0.01\n",
        w0[0], w0[1], w0[2], q0.w, q0.i, q0.j, q0.k
    );
    for o in configurations() {
        let scene = scene_from(&text, &o);
        let limit = bound(&o, omega3, 2.0);
        for row in rows(&scene) {
            let w = steady.omega_p(row.t);
            assert!(
                (*row.omega_b - w).norm() <= limit * omega3,
                "{} t = {}: ω",
                label(&o),
                row.t
            );
            assert!(
                attitude_angle(&row.q, &steady.attitude(row.t)) <= limit,
                "{} t = {}: attitude",
                label(&o),
                row.t
            );
        }
    }
    // Energy conservation on the nutating scenario.
    let text = std::fs::read_to_string("scenarios/heavy_top.toml").unwrap();
    let scene = scene_from(&text, &Overrides::default());
    let rho_c_b = Vector3::new(0.0, 0.0, l);
    let g_s = Vector3::new(0.0, 0.0, -g);
    let total = |r: &Sample| r.energy - mass * g_s.dot(&(r.q * rho_c_b));
    let rows = rows(&scene);
    let e0 = total(&rows[0]);
    for row in &rows {
        assert!(
            (total(row) - e0).abs()
                <= bound(
                    &Overrides {
                        rtol: Some(1e-11),
                        ..Overrides::default()
                    },
                    150.0,
                    5.0
                ) * e0,
            "t = {}: T + V = {} vs {e0}",
            row.t,
            total(row)
        );
    }
}

#[test]
fn damping_decays_a_principal_axis_spin_exponentially() {
    // I3 ω̇3 = −c ω3 ⇒ ω3(t) = ω3(0) exp(−c t / I3).
    let text = std::fs::read_to_string("scenarios/damped_spin.toml").unwrap();
    for o in configurations() {
        let scene = scene_from(&text, &o);
        let limit = bound(&o, 5.0, 30.0);
        for row in rows(&scene) {
            let expected = 5.0 * (-0.3 * row.t / 3.0).exp();
            assert!(
                (row.omega_b[2] - expected).abs() <= limit * 5.0,
                "{} t = {}",
                label(&o),
                row.t
            );
            assert!(row.omega_b.xy().norm() == 0.0);
        }
    }
}

#[test]
fn sine_torque_matches_a_fine_rk4_reference_with_every_method() {
    // No closed form: the reference is RK4 with dt = 1e-4 (global error ~ (|ω| dt)⁴·|ω| t ~ 1e-14). The torque depends
    // on t, so DOP853 with ode_solvers' wrong nodes c12 = c13 = 0 would miss it by orders of magnitude more than its
    // tolerance; the ode_solvers path carries t in the state instead.
    let text = std::fs::read_to_string("scenarios/sine_torque.toml").unwrap();
    let reference = rows(&scene_from(
        &text,
        &Overrides {
            method: Some(Named::parse("rk4").unwrap()),
            dt: Some(1e-4),
            ..Overrides::default()
        },
    ));
    for o in configurations() {
        let scene = scene_from(&text, &o);
        let limit = bound(&o, 2.5, 20.0);
        for (row, r) in rows(&scene).iter().zip(&reference) {
            assert_eq!(row.t, r.t);
            assert!(
                (row.omega_b - r.omega_b).norm() <= limit * 2.5,
                "{} t = {}",
                label(&o),
                row.t
            );
            assert!(
                attitude_angle(&row.q, &r.q) <= limit,
                "{} t = {}",
                label(&o),
                row.t
            );
        }
    }
}

#[test]
fn tennis_racket_flips_at_the_closed_form_interval() {
    // Landau & Lifshitz §37: near the intermediate axis, ω_y ∝ sn(λt) changes sign every 2K/λ. Rows every 0.05 s and
    // linear interpolation across the fast transition locate a crossing to ~1e-4 s; bound 1e-3 of the interval.
    let text = std::fs::read_to_string("scenarios/tennis_racket.toml").unwrap();
    let exact = TorqueFreeBody::new(
        Vector3::new(1.0, 2.0, 3.0),
        Vector3::new(0.001, 2.0, 0.001),
        UnitQuaternion::identity(),
    )
    .unwrap();
    let interval = exact.flip_interval().unwrap();
    assert!(
        interval > 5.0 && interval < 60.0 / 3.5,
        "at least three flips in the scene: {interval}"
    );
    for o in configurations() {
        let scene = scene_from(&text, &o);
        let flips = sign_changes(&rows(&scene), 1);
        assert!(flips.len() >= 3, "{}: {} flips", label(&o), flips.len());
        for pair in flips.windows(2) {
            let measured = pair[1] - pair[0];
            assert!(
                (measured - interval).abs() <= 1e-3 * interval,
                "{}: flip interval {measured} vs 2K/λ = {interval}",
                label(&o)
            );
        }
    }
}
