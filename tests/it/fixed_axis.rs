//! Prescribed rotation about a fixed axis against the reference notes' worked examples
//! (../shared/reference/rigid-body-dynamics-notes.md): the thin disk on a tilted axis (eqs. 8.2, 8.3 and the
//! transformation eq. 7.25), the thin rod's coordinate-dependent inertia (eq. 8.10), Euler's equation (8.9) in both
//! forms, and the required force f = m a_C (8.7).

use std::convert::Infallible;
use std::f64::consts::{FRAC_PI_2, PI};

use approx::assert_relative_eq;
use eulerdyn::body::{RigidBody, Shape};
use eulerdyn::frames::{Form, Vector};
use eulerdyn::method::{Backend, Method};
use eulerdyn::motion::fixed_axis::FixedAxis;
use eulerdyn::named::Named;
use eulerdyn::sample::Sample;
use eulerdyn::scene::Motion;
use eulerdyn::scene::{self, Overrides};
use eulerdyn::simulate;
use nalgebra::{Matrix3, Unit, UnitQuaternion, Vector3};

const MASS: f64 = 2.0;
const RADIUS: f64 = 0.3;
const OMEGA: f64 = 10.0;

fn disk() -> RigidBody {
    RigidBody::from_shape(MASS, Shape::ThinDisk { radius: RADIUS }).unwrap()
}

/// The notes' spin axis for tilt θ: ω = ω (0, −sin θ, cos θ) in principal axes.
fn tilted_axis(theta: f64) -> Vector3<f64> {
    Vector3::new(0.0, -theta.sin(), theta.cos())
}

/// The notes' disk spinning at the constant rate OMEGA about its axis tilted θ, through C, starting from the
/// identity attitude.
fn disk_motion(theta: f64) -> FixedAxis {
    FixedAxis::new(
        &disk(),
        Vector::new(tilted_axis(theta)),
        OMEGA,
        0.0,
        Vector::zeros(),
        UnitQuaternion::identity(),
    )
}

fn tilts() -> impl Iterator<Item = f64> {
    (0..=36).map(|k| k as f64 * FRAC_PI_2 / 36.0)
}

/// Relative error of a vector, with a floor of `scale` for vectors that are zero in exact arithmetic.
fn rel_err(a: &Vector3<f64>, b: &Vector3<f64>, scale: f64) -> f64 {
    (a - b).norm() / b.norm().max(scale)
}

#[test]
fn disk_part_a_central_moment_of_momentum_in_principal_axes() {
    // Notes, disk example (a): H_C = I_C·ω = (0, −¼mR²ω sinθ, ½mR²ω cosθ) (eq. 8.2).
    let mr2 = MASS * RADIUS * RADIUS;
    for theta in tilts() {
        let motion = disk_motion(theta);
        let h_b = motion.h_a_b(&motion.angle(0.37)).into_inner();
        let expected = Vector3::new(
            0.0,
            -0.25 * mr2 * OMEGA * theta.sin(),
            0.5 * mr2 * OMEGA * theta.cos(),
        );
        // Two roundings per component (the products); 4 ulp of the largest component.
        for k in 0..3 {
            assert!(
                (h_b[k] - expected[k]).abs() <= 4.0 * f64::EPSILON * expected.amax(),
                "θ = {theta}: H_C[{k}] = {} vs {}",
                h_b[k],
                expected[k]
            );
        }
    }
}

#[test]
fn disk_part_b_inertia_and_moment_of_momentum_in_axes_along_the_spin_axis() {
    // Notes, disk example (b): with T = [[1,0,0],[0,c,−s],[0,s,c]], Ī = Tᵗ I T (eq. 7.25) and
    // H̄_C = Ī·(0, 0, ω) = (0, ¼mR²ω sinθ cosθ, ¼mR²ω(1 + cos²θ)). The tool's space axes are the notes' barred
    // axes when the attitude (body → space) is Tᵗ, a rotation of −θ about x1.
    let q = MASS * RADIUS * RADIUS / 4.0;
    for theta in tilts() {
        let (s, c) = theta.sin_cos();
        let attitude = UnitQuaternion::from_axis_angle(&Vector3::x_axis(), -theta);
        let motion = FixedAxis::new(
            &disk(),
            Vector::new(tilted_axis(theta)),
            OMEGA,
            0.0,
            Vector::zeros(),
            attitude,
        );
        assert_relative_eq!(motion.axis_c().into_inner(), Vector3::z(), epsilon = 1e-15);
        let i_bar = motion.inertia_a_c(0.0);
        let expected = Matrix3::new(
            q,
            0.0,
            0.0,
            0.0,
            q * (1.0 + s * s),
            q * s * c,
            0.0,
            q * s * c,
            q * (1.0 + c * c),
        );
        for r in 0..3 {
            for k in 0..3 {
                assert!(
                    (i_bar[(r, k)] - expected[(r, k)]).abs() <= 8.0 * f64::EPSILON * 2.0 * q,
                    "θ = {theta}: Ī[{r}][{k}] = {} vs {}",
                    i_bar[(r, k)],
                    expected[(r, k)]
                );
            }
        }
        let sample = motion.sample(0.0, Form::Space);
        let h_bar = Vector3::new(0.0, q * OMEGA * s * c, q * OMEGA * (1.0 + c * c));
        for k in 0..3 {
            assert!(
                (sample.h_o_s[k] - h_bar[k]).abs() <= 8.0 * f64::EPSILON * 2.0 * q * OMEGA,
                "θ = {theta}: H̄[{k}] = {} vs {}",
                sample.h_o_s[k],
                h_bar[k]
            );
        }
    }
}

#[test]
fn thin_rod_inertia_depends_on_the_angle_as_in_the_notes() {
    // Notes, eq. 8.10 example: I(θ) = (ml²/12)[[s², sc, 0], [sc, c², 0], [0, 0, 1]] for the rod along x1 turning
    // about x3 (the notes' θ turns the rod to −θ from x1: axis −x3 here).
    let (m, l) = (1.2, 0.8);
    let rod = RigidBody::from_shape(m, Shape::ThinRod { length: l }).unwrap();
    let motion = FixedAxis::new(
        &rod,
        Vector::new(-Vector3::z()),
        3.0,
        0.0,
        Vector::zeros(),
        UnitQuaternion::identity(),
    );
    let k = m * l * l / 12.0;
    for step in 0..=72 {
        let theta = step as f64 * 2.0 * PI / 72.0;
        let (s, c) = theta.sin_cos();
        let expected = Matrix3::new(s * s, s * c, 0.0, s * c, c * c, 0.0, 0.0, 0.0, 1.0) * k;
        let i_s = motion.inertia_a_c(theta);
        assert!(
            (i_s - expected).amax() <= 8.0 * f64::EPSILON * k,
            "θ = {theta}: {i_s} vs {expected}"
        );
    }
}

#[test]
fn disk_required_moment_is_omega_cross_h_along_x1_constant_in_body_turning_in_space() {
    // M = ω × H (eq. 8.9 with ω constant): M_1 = ω₂H₃ − ω₃H₂ = −¼mR²ω² sinθ cosθ along body x1, so the magnitude is
    // ¼mR²ω² sinθ cosθ and the sign is negative in the notes' setup (ω = ω(0, −sinθ, cosθ)).
    let q = MASS * RADIUS * RADIUS / 4.0;
    for theta in tilts() {
        let motion = disk_motion(theta);
        let magnitude = q * OMEGA * OMEGA * theta.sin() * theta.cos();
        let scale = q * OMEGA * OMEGA;
        let m_b0 = motion.moment_a_b(&motion.angle(0.0)).into_inner();
        assert!((m_b0 - Vector3::new(-magnitude, 0.0, 0.0)).amax() <= 8.0 * f64::EPSILON * scale);
        for t in [0.05, 0.3, 1.7, 12.0] {
            let angle = motion.angle(t);
            // Constant in body axes.
            assert!(
                (motion.moment_a_b(&angle).into_inner() - m_b0).amax()
                    <= 8.0 * f64::EPSILON * scale
            );
            // In space it turns about the axis at rate ω: M_s(t) = Rot(a_s, ωt)·M_s(0).
            // Without a carrier the support's axes are space axes (`_c` = `_s`).
            let turned =
                UnitQuaternion::from_axis_angle(&Unit::new_unchecked(*motion.axis_c()), OMEGA * t)
                    * motion.moment_a_c(&motion.angle(0.0)).into_inner();
            let m_s = motion.moment_a_c(&angle).into_inner();
            assert!(
                (m_s - turned).amax() <= 64.0 * f64::EPSILON * scale,
                "θ = {theta}, t = {t}: {m_s} vs {turned}"
            );
            // Both forms agree to round-off (the 1e-12 relative).
            let m_s_from_body =
                motion.attitude(angle.theta) * motion.moment_a_b(&angle).into_inner();
            assert!(rel_err(&m_s, &m_s_from_body, scale) <= 1e-12);
        }
    }
    // Zero at θ = 0 and 90°: the axis is principal, H ∥ ω.
    for theta in [0.0, FRAC_PI_2] {
        let motion = disk_motion(theta);
        let angle = motion.angle(0.4);
        assert!(motion.moment_a_b(&angle).norm() <= 8.0 * f64::EPSILON * q * OMEGA * OMEGA);
        assert!(motion.moment_a_c(&angle).norm() <= 8.0 * f64::EPSILON * q * OMEGA * OMEGA);
    }
}

#[test]
fn required_moment_is_the_rate_of_change_of_h_s() {
    // M_s = dH_s/dt (eq. 8.9), checked against a central difference of the closed-form H_s(t) — independent of both
    // moment formulas. Fourth-order difference with h = 1e-3: truncation ~ h⁴ |H⁽⁵⁾| ~ 1e-12·ω⁵|H|, round-off
    // ~ ε|H|/h ~ 1e-13|H|; bound 1e-8 relative to ω|H|.
    let mut axis = Vector3::new(0.3, -0.5, 0.8);
    axis.normalize_mut();
    let body = RigidBody::new(
        1.5,
        Matrix3::new(0.4, 0.05, -0.02, 0.05, 0.6, 0.03, -0.02, 0.03, 0.7),
    )
    .unwrap();
    let attitude = UnitQuaternion::from_euler_angles(0.3, -0.2, 1.1);
    for point in [Vector3::zeros(), Vector3::new(0.1, 0.2, -0.05)] {
        let motion = FixedAxis::new(
            &body,
            Vector::new(axis),
            2.0,
            3.0,
            Vector::new(point),
            attitude,
        );
        let h_s = |t: f64| motion.sample(t, Form::Body).h_o_s;
        let h = 1e-3;
        for t in [0.0, 0.4, 1.3] {
            let derivative = (h_s(t - 2.0 * h) - 8.0 * h_s(t - h) + 8.0 * h_s(t + h)
                - h_s(t + 2.0 * h))
                / (12.0 * h);
            let angle = motion.angle(t);
            let scale = h_s(t).norm() * angle.theta_dot.abs().max(1.0);
            for frame in [Form::Body, Form::Space] {
                let m_s = motion.sample(t, frame).m_o_s;
                assert!(
                    (m_s - derivative).norm() <= 1e-8 * scale,
                    "{frame:?} t = {t}: M_s = {m_s}, dH_s/dt = {derivative}"
                );
            }
            let rel = rel_err(
                &motion.moment_a_c(&angle).into_inner(),
                &(motion.attitude(angle.theta) * motion.moment_a_b(&angle).into_inner()),
                scale,
            );
            assert!(rel <= 1e-12, "body and space forms differ by {rel}");
        }
    }
}

fn run_scene(path: &str, overrides: &Overrides) -> Vec<Sample> {
    let scene = scene::load(std::path::Path::new(path), overrides).unwrap();
    let mut rows = Vec::new();
    simulate::run(&scene, |s| {
        rows.push(*s);
        Ok::<(), Infallible>(())
    })
    .unwrap();
    rows
}

#[test]
fn tilted_disk_h_s_turns_about_the_axis_at_rate_omega() {
    // Notes' observation: with ω constant, H is constant in body axes but turns about the spin axis at rate ω in
    // space: H_s(t) = Rot(a_s, ωt)·H_s(0), |H_s| and H_s·a_s constant.
    let rows = run_scene("scenarios/tilted_disk.toml", &Overrides::default());
    let first = rows[0];
    let axis_s = first.omega_s.normalize();
    let scale = first.h_o_s.norm();
    for row in &rows {
        assert!((row.h_o_b - first.h_o_b).amax() <= 4.0 * f64::EPSILON * scale);
        let turned =
            UnitQuaternion::from_axis_angle(&nalgebra::Unit::new_unchecked(axis_s), OMEGA * row.t)
                * *first.h_o_s;
        assert!(
            (*row.h_o_s - turned).norm() <= 1e-13 * scale,
            "t = {}: {} vs {turned}",
            row.t,
            row.h_o_s
        );
        assert!((row.h_o_s.norm() - scale).abs() <= 1e-14 * scale);
        assert!((row.h_o_s.dot(&axis_s) - first.h_o_s.dot(&axis_s)).abs() <= 1e-14 * scale);
    }
}

#[test]
fn integrating_h_s_dot_equals_m_s_tracks_i_s_omega_s() {
    // Euler's equation in space axes integrated numerically, Ḣ_s = M_s(t), from H_s(0), reproduces
    // H_s = I_s(θ(t))·ω_s(t). The right-hand side depends on t, so this also guards ode_solvers' DOP853 c12/c13
    // defect on its path. Measured largest errors relative to max|H_s| (every scenario, method, backend, frame):
    // dop853 ≤ 4e-15, dopri5 (rtol 1e-10) ≤ 2e-12, rk4 (dt = 1e-3) ≤ 1.5e-11 (the spin-up, ω up to 20 rad/s).
    // Bound 1e-10: a 7× margin over the worst; a wrong node or a lost step costs orders of magnitude more.
    for path in [
        "scenarios/tilted_disk.toml",
        "scenarios/disk_spin_up.toml",
        "scenarios/offset_disk.toml",
        "scenarios/thin_rod.toml",
    ] {
        for method in ["rk4", "dopri5", "dop853"] {
            for backend in ["own", "ode_solvers"] {
                for frame in ["body", "space"] {
                    let overrides = Overrides {
                        method: Some(Named::parse(method).unwrap()),
                        backend: Some(Named::parse(backend).unwrap()),
                        form: Some(Named::parse(frame).unwrap()),
                        ..Overrides::default()
                    };
                    let rows = run_scene(path, &overrides);
                    let scale = rows.iter().map(|r| r.h_o_s.norm()).fold(0.0, f64::max);
                    for row in &rows {
                        let integrated = row.h_o_s_integrated.unwrap();
                        assert!(
                            (integrated - row.h_o_s).norm() <= 1e-10 * scale,
                            "{path} {method} {backend} {frame} t = {}: {integrated} vs {}",
                            row.t,
                            row.h_o_s
                        );
                    }
                }
            }
        }
    }
}

#[test]
fn spin_up_moment_is_i_alpha_plus_gyroscopic_term_with_omega_growing() {
    // Disk spun up from rest, α = 20 rad/s²: ω(t) = αt along the axis; M_b = I·α a + (αt)² a × I a (eq. 8.9 in body
    // axes), checked per row against this closed form written out for the thin disk (I = ¼mR² diag(1, 1, 2)).
    let rows = run_scene("scenarios/disk_spin_up.toml", &Overrides::default());
    let alpha = 20.0;
    let theta = 30f64.to_radians();
    let a = tilted_axis(theta);
    let q = MASS * RADIUS * RADIUS / 4.0;
    let i_a = Vector3::new(q * a[0], q * a[1], 2.0 * q * a[2]);
    let mut previous = -1.0;
    for row in &rows {
        let w = alpha * row.t;
        assert!(row.omega_b.norm() > previous || row.t == 0.0);
        previous = row.omega_b.norm();
        assert_relative_eq!(row.omega_b.norm(), w, max_relative = 1e-15, epsilon = 1e-15);
        let expected = i_a * alpha + a.cross(&i_a) * (w * w);
        let scale = expected.norm().max(q * alpha);
        assert!(
            (*row.m_o_b - expected).norm() <= 1e-14 * scale,
            "t = {}: {} vs {expected}",
            row.t,
            row.m_o_b
        );
        // The gyroscopic part is along body x1 and grows as ω²: −¼mR²ω² sinθ cosθ.
        assert_relative_eq!(
            a.cross(&i_a)[0] * w * w,
            -q * w * w * theta.sin() * theta.cos(),
            max_relative = 1e-14,
            epsilon = 1e-300
        );
    }
}

#[test]
fn offset_point_force_is_m_a_c_and_h_about_the_fixed_point_is_i_a_omega() {
    // Shaft through A, 2 cm from C. f = m a_C (eq. 8.7) with a_C = α × ρ + ω × (ω × ρ) (ρ from A to C, ⟂ axis):
    // centripetal part m ω² e toward the axis, tangential part m α e. H_A = I_A·ω (eq. 8.6, A fixed), which must
    // equal H_C + ρ × m v_C (transport of H, independent of the parallel-axis theorem).
    let scene = scene::load(
        std::path::Path::new("scenarios/offset_disk.toml"),
        &Overrides::default(),
    )
    .unwrap();
    let Motion::FixedAxis(motion) = &scene.motion else {
        panic!("offset_disk is a fixed-axis scene")
    };
    let e = 0.02;
    let (alpha, rate) = (5.0, 10.0);
    let rows = run_scene("scenarios/offset_disk.toml", &Overrides::default());
    for row in &rows {
        let w = rate + alpha * row.t;
        let f = row.f_s.unwrap();
        let rho_s = motion.rho_c_b().in_space(&row.q);
        assert_relative_eq!(rho_s.norm(), e, max_relative = 1e-14);
        let inward = -rho_s / e;
        let axis_s = motion.axis_c().into_inner();
        let tangent = axis_s.cross(&(rho_s / e));
        let scale = MASS * w * w * e;
        assert!((f.dot(&inward) - MASS * w * w * e).abs() <= 1e-13 * scale);
        assert!((f.dot(&tangent) - MASS * alpha * e).abs() <= 1e-13 * scale);
        assert!(f.dot(&axis_s).abs() <= 1e-13 * scale);
        // H about A by transport from C.
        let omega_s = row.omega_s;
        let h_c_s = row.q * (disk().inertia_c() * *row.omega_b);
        let v_c = omega_s.cross(&rho_s);
        let h_a_transport = h_c_s + rho_s.cross(&(v_c * MASS));
        assert!((*row.h_o_s - h_a_transport).norm() <= 1e-14 * row.h_o_s.norm());
        // Energy: whole kinetic energy ½ m v_C² + ½ ω·I_C ω equals ½ ω·H_A.
        let t_c = 0.5 * MASS * v_c.norm_squared() + 0.5 * omega_s.dot(&h_c_s);
        assert_relative_eq!(row.energy, t_c, max_relative = 1e-14);
    }
}

#[test]
fn scene_backend_and_method_names_round_trip() {
    for m in Method::ALL {
        let overrides = Overrides {
            method: Some(m),
            ..Overrides::default()
        };
        let scene = scene::load(
            std::path::Path::new("scenarios/tilted_disk.toml"),
            &overrides,
        )
        .unwrap();
        assert_eq!(scene.solver.method, m);
    }
    let scene = scene::load(
        std::path::Path::new("scenarios/tilted_disk.toml"),
        &Overrides {
            backend: Some(Named::parse("ode_solvers").unwrap()),
            ..Overrides::default()
        },
    )
    .unwrap();
    assert_eq!(scene.solver.backend, Backend::OdeSolvers);
}
