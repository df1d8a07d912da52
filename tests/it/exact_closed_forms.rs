//! Tests of the closed-form solutions in `eulerdyn::exact` against the equations of motion
//! (central differences), conservation laws, and an independent brute-force RK4 integration.

use eulerdyn::exact::{
    AxialTorqueSymmetric, ExactError, HeavySymmetricTop, PrecessionRoots, SteadyPrecession,
    SymmetricTorqueFree, TorqueFreeBody, TorqueFreeCase,
};
use nalgebra::{Quaternion, UnitQuaternion, Vector3};

// ---------------------------------------------------------------------------------------------
// Helpers
// ---------------------------------------------------------------------------------------------

fn v(x: f64, y: f64, z: f64) -> Vector3<f64> {
    Vector3::new(x, y, z)
}

fn q_initial() -> UnitQuaternion<f64> {
    UnitQuaternion::from_euler_angles(0.3, -1.1, 2.4)
}

/// Rotation angle between two attitudes, `2 atan2(|vec|, |w|)` of `q1⁻¹ q2` (sign-blind and
/// accurate for tiny angles, unlike `acos`).
fn rot_angle(q1: &UnitQuaternion<f64>, q2: &UnitQuaternion<f64>) -> f64 {
    let d = q1.inverse() * q2;
    2.0 * d.imag().norm().atan2(d.w.abs())
}

/// Quaternion distance respecting sign (for continuity checks).
fn quat_dist(q1: &UnitQuaternion<f64>, q2: &UnitQuaternion<f64>) -> f64 {
    (q1.coords - q2.coords).norm()
}

/// Right-hand side of Euler's equations plus kinematics: `I ω̇ = τ − ω × Iω`,
/// `q̇ = ½ q ⊗ (0, ω)`.
fn rhs(
    moments: &Vector3<f64>,
    w: &Vector3<f64>,
    q: &Quaternion<f64>,
    torque: &dyn Fn(&UnitQuaternion<f64>) -> Vector3<f64>,
) -> (Vector3<f64>, Quaternion<f64>) {
    let iw = moments.component_mul(w);
    let tau = torque(&UnitQuaternion::from_quaternion(*q));
    let wdot = (tau - w.cross(&iw)).component_div(moments);
    let qdot = q * Quaternion::from_imag(*w) * 0.5;
    (wdot, qdot)
}

/// Classic RK4 with a fixed step from `(w, q)` at 0 to each time in `times` (increasing).
/// The state is accumulated with Kahan compensation so that rounding does not random-walk
/// over the ~10⁶ steps (this matters near the separatrix, where errors are amplified ~10⁴×).
fn rk4(
    moments: &Vector3<f64>,
    w0: Vector3<f64>,
    q0: UnitQuaternion<f64>,
    times: &[f64],
    max_step: f64,
    torque: &dyn Fn(&UnitQuaternion<f64>) -> Vector3<f64>,
) -> Vec<(Vector3<f64>, UnitQuaternion<f64>)> {
    let mut w = w0;
    let mut q = q0.into_inner();
    let mut w_comp = Vector3::zeros();
    let mut q_comp = Quaternion::new(0.0, 0.0, 0.0, 0.0);
    let mut t = 0.0;
    let mut out = Vec::new();
    for &t_end in times {
        let n = ((t_end - t) / max_step).ceil().max(1.0) as usize;
        let h = (t_end - t) / n as f64;
        for _ in 0..n {
            let (k1w, k1q) = rhs(moments, &w, &q, torque);
            let (k2w, k2q) = rhs(
                moments,
                &(w + k1w * (0.5 * h)),
                &(q + k1q * (0.5 * h)),
                torque,
            );
            let (k3w, k3q) = rhs(
                moments,
                &(w + k2w * (0.5 * h)),
                &(q + k2q * (0.5 * h)),
                torque,
            );
            let (k4w, k4q) = rhs(moments, &(w + k3w * h), &(q + k3q * h), torque);
            let dw = (k1w + k2w * 2.0 + k3w * 2.0 + k4w) * (h / 6.0) - w_comp;
            let w_new = w + dw;
            w_comp = (w_new - w) - dw;
            w = w_new;
            let dq = (k1q + k2q * 2.0 + k3q * 2.0 + k4q) * (h / 6.0) - q_comp;
            let q_new = q + dq;
            q_comp = (q_new - q) - dq;
            q = q_new;
        }
        t = t_end;
        out.push((w, UnitQuaternion::from_quaternion(q)));
    }
    out
}

fn no_torque(_: &UnitQuaternion<f64>) -> Vector3<f64> {
    Vector3::zeros()
}

/// Relative residual of Euler's equations `I ω̇ + ω × Iω − τ` by central differences.
fn euler_residual(
    moments: &Vector3<f64>,
    omega: &dyn Fn(f64) -> Vector3<f64>,
    torque: &dyn Fn(f64) -> Vector3<f64>,
    t: f64,
    h: f64,
) -> f64 {
    let wdot = (omega(t + h) - omega(t - h)) / (2.0 * h);
    let w = omega(t);
    let iw = moments.component_mul(&w);
    let lhs = moments.component_mul(&wdot) + w.cross(&iw);
    let tau = torque(t);
    let scale = w.cross(&iw).norm() + tau.norm() + moments.component_mul(&wdot).norm();
    (lhs - tau).norm() / scale.max(f64::MIN_POSITIVE)
}

/// Relative residual of `q̇ = ½ q ⊗ (0, ω_p)` by central differences.
fn kinematic_residual(
    q: &dyn Fn(f64) -> UnitQuaternion<f64>,
    omega: &dyn Fn(f64) -> Vector3<f64>,
    t: f64,
    h: f64,
) -> f64 {
    let qdot = (q(t + h).into_inner() - q(t - h).into_inner()) / (2.0 * h);
    let want = q(t).into_inner() * Quaternion::from_imag(omega(t)) * 0.5;
    (qdot - want).norm() / (0.5 * omega(t).norm()).max(f64::MIN_POSITIVE)
}

/// Everything every torque-free case must satisfy. Returns (max Euler residual, max kinematic
/// residual, max relative H_s drift, max RK4 ω error / |ω|, max RK4 attitude angle error).
fn check_torque_free(moments: Vector3<f64>, w0: Vector3<f64>, t_end: f64) -> [f64; 5] {
    check_torque_free_h(moments, w0, t_end, None)
}

/// As [`check_torque_free`], with the central-difference step for Euler's equations given
/// explicitly (for motions whose ω changes on a time scale far longer than 1/|ω|, where the
/// default step would measure only rounding noise).
fn check_torque_free_h(
    moments: Vector3<f64>,
    w0: Vector3<f64>,
    t_end: f64,
    h_euler: Option<f64>,
) -> [f64; 5] {
    let q0 = q_initial();
    let body = TorqueFreeBody::new(moments, w0, q0).expect("valid body");
    let wn = w0.norm();
    let scale = wn.max(1e-300);

    // Initial conditions to rounding.
    assert!(
        (body.omega_p(0.0) - w0).norm() <= 8.0 * f64::EPSILON * scale,
        "omega_p(0) = {:?} != {:?}",
        body.omega_p(0.0),
        w0
    );
    assert!(
        quat_dist(&body.attitude(0.0), &q0) <= 1e-15,
        "attitude(0) != q0"
    );

    let h_s = body.h_s();
    let energy = body.energy();
    let omega = |t: f64| body.omega_p(t);
    let att = |t: f64| body.attitude(t);
    let mut res = [0.0f64; 5];
    let n = 200;
    let h = 1e-5 / wn.max(1e-3);
    let h_e = h_euler.unwrap_or(h);
    for k in 0..=n {
        let t = t_end * f64::from(k) / f64::from(n) + 0.0123;
        if wn > 0.0 {
            res[0] = res[0].max(euler_residual(
                &moments,
                &omega,
                &|_| Vector3::zeros(),
                t,
                h_e,
            ));
            res[1] = res[1].max(kinematic_residual(&att, &omega, t, h));
        }
        let h_t = body.attitude(t) * moments.component_mul(&body.omega_p(t));
        res[2] = res[2].max((h_t - h_s).norm() / h_s.norm().max(1e-300));
        let w = body.omega_p(t);
        let e_t = 0.5 * w.dot(&moments.component_mul(&w));
        assert!(
            (e_t - energy).abs() <= 1e-13 * energy.max(1e-300),
            "energy drift at t={t}"
        );
        // Unit quaternion stays unit and continuous.
        assert!((body.attitude(t).norm() - 1.0).abs() <= 1e-15);
    }
    for k in 0..2000 {
        let t = t_end * f64::from(k) / 2000.0;
        let dt = t_end / 2000.0;
        assert!(
            quat_dist(&body.attitude(t), &body.attitude(t + dt)) <= 1.5 * wn * dt + 1e-12,
            "attitude quaternion jumps between t={t} and t+dt"
        );
    }

    // Period of ω.
    if let Some(p) = body.period_omega() {
        assert!(matches!(body.case(), TorqueFreeCase::Circulating { .. }));
        let f = body.flip_interval().expect("periodic");
        assert!((2.0 * f - p).abs() <= 1e-15 * p);
        for k in 0..20 {
            let t = 0.37 * f64::from(k);
            let d = (body.omega_p(t + p) - body.omega_p(t)).norm();
            assert!(d <= 1e-12 * scale, "omega not periodic: {d}");
        }
    }

    // Brute-force RK4 comparison.
    if wn > 0.0 {
        let times: Vec<f64> = (1..=10).map(|k| t_end * f64::from(k) / 10.0).collect();
        let step = 2e-4 / wn.max(0.1);
        let sol = rk4(&moments, w0, q0, &times, step, &no_torque);
        for (&t, (w, q)) in times.iter().zip(&sol) {
            res[3] = res[3].max((body.omega_p(t) - w).norm() / wn);
            res[4] = res[4].max(rot_angle(&body.attitude(t), q));
        }
    }
    res
}

fn assert_accuracy(name: &str, r: [f64; 5]) {
    eprintln!(
        "{name}: euler {:.1e} kinematic {:.1e} H_s drift {:.1e} rk4 omega {:.1e} rk4 angle {:.1e}",
        r[0], r[1], r[2], r[3], r[4]
    );
    assert!(r[0] <= 1e-7, "{name}: Euler residual {}", r[0]);
    assert!(r[1] <= 1e-7, "{name}: kinematic residual {}", r[1]);
    assert!(r[2] <= 1e-12, "{name}: H_s drift {}", r[2]);
    assert!(r[3] <= 1e-9, "{name}: RK4 omega difference {}", r[3]);
    assert!(r[4] <= 1e-9, "{name}: RK4 attitude difference {}", r[4]);
}

// ---------------------------------------------------------------------------------------------
// Torque-free body: the case types
// ---------------------------------------------------------------------------------------------

#[test]
fn asymmetric_circulating_about_largest_axis() {
    // Moments deliberately out of order: (3, 1, 2). M² > 2E·I₂ → ω circulates about index 0.
    let moments = v(3.0, 1.0, 2.0);
    let w0 = v(1.2, -0.8, 0.9);
    let body = TorqueFreeBody::new(moments, w0, q_initial()).expect("valid");
    assert_eq!(body.case(), TorqueFreeCase::Circulating { axis: 0 });
    let m = body.elliptic_parameter().expect("elliptic");
    assert!(m > 0.05 && m < 0.95, "m = {m}");
    assert_accuracy(
        "asym M2>2EI2",
        check_torque_free(moments, w0, 3.0 * body.period_omega().expect("periodic")),
    );
    // Negative ω along the circulation axis works too.
    let w0 = v(-1.2, 0.8, -0.9);
    let body = TorqueFreeBody::new(moments, w0, q_initial()).expect("valid");
    assert_accuracy(
        "asym M2>2EI2 (neg)",
        check_torque_free(moments, w0, 2.0 * body.period_omega().expect("periodic")),
    );
}

#[test]
fn asymmetric_circulating_about_smallest_axis() {
    let moments = v(2.0, 1.0, 2.7);
    let w0 = v(0.4, 2.1, -0.5);
    let body = TorqueFreeBody::new(moments, w0, q_initial()).expect("valid");
    assert_eq!(body.case(), TorqueFreeCase::Circulating { axis: 1 });
    assert_accuracy(
        "asym M2<2EI2",
        check_torque_free(moments, w0, 3.0 * body.period_omega().expect("periodic")),
    );
    // All sign combinations of the initial ω (the initial phase must be recovered).
    for sx in [-1.0, 1.0] {
        for sy in [-1.0, 1.0] {
            for sz in [-1.0, 1.0] {
                let w0 = v(0.4 * sx, 2.1 * sy, 0.5 * sz);
                let body = TorqueFreeBody::new(moments, w0, q_initial()).expect("valid");
                assert!((body.omega_p(0.0) - w0).norm() <= 1e-15 * 4.0);
                assert!(quat_dist(&body.attitude(0.0), &q_initial()) <= 1e-15);
                let p = body.period_omega().expect("periodic");
                assert!((body.omega_p(p) - w0).norm() <= 1e-13);
            }
        }
    }
}

#[test]
fn separatrix() {
    // Sorted I = (1.3, 2.1, 2.9) placed as (2.1, 2.9, 1.3).
    // Separatrix: I₁(I₂−I₁)ω₁² = I₃(I₃−I₂)ω₃².
    let (i1, i2, i3): (f64, f64, f64) = (1.3, 2.1, 2.9);
    let w3 = 0.6;
    let w1 = (i3 * (i3 - i2) / (i1 * (i2 - i1))).sqrt() * w3;
    let moments = v(i2, i3, i1);
    let w0 = v(0.7, w3, w1);
    let body = TorqueFreeBody::new(moments, w0, q_initial()).expect("valid");
    assert_eq!(body.case(), TorqueFreeCase::Separatrix);
    assert_eq!(body.period_omega(), None);
    assert_eq!(body.elliptic_parameter(), Some(1.0));
    assert_accuracy("separatrix", check_torque_free(moments, w0, 12.0));
    // ω tends to the intermediate axis: ω₁, ω₃ → 0 like sech.
    let w_late = body.omega_p(60.0);
    assert!(w_late.x.abs() > 0.99 * w_late.norm());
    // Starting on the other side (ω₁ω₃ < 0, ω₂ < 0).
    let w0 = v(-0.7, -w3, w1);
    assert_accuracy("separatrix (signs)", check_torque_free(moments, w0, 12.0));
    // Just off the separatrix on either side: elliptic with m′ ≈ 1e-9, circulating about the
    // largest (index 1) or the smallest (index 2) axis.
    for (f, axis) in [(1.0 - 1e-9, 1), (1.0 + 1e-9, 2)] {
        let w0 = v(0.7, w3, w1 * f);
        let body = TorqueFreeBody::new(moments, w0, q_initial()).expect("valid");
        assert_eq!(body.case(), TorqueFreeCase::Circulating { axis });
        let m = body.elliptic_parameter().expect("elliptic");
        assert!(1.0 - m < 1e-7, "m = {m}");
        assert_accuracy("near separatrix", check_torque_free(moments, w0, 12.0));
    }
}

#[test]
fn tennis_racket_near_separatrix() {
    // Spin mostly about the intermediate axis: the Dzhanibekov flip.
    let moments = v(2.0, 1.0, 3.0);
    let w0 = v(5.0, 1e-3, 1e-3);
    let body = TorqueFreeBody::new(moments, w0, q_initial()).expect("valid");
    let m = body.elliptic_parameter().expect("elliptic");
    assert!(m > 0.999_999 && m < 1.0, "m = {m}");
    let flip = body.flip_interval().expect("periodic");
    // The intermediate component changes sign once per flip interval.
    let t0 = 0.0;
    let mut signs = 0;
    let mut prev = body.omega_p(t0).x;
    let n = 20_000;
    let span = 4.0 * flip;
    for k in 1..=n {
        let x = body.omega_p(span * f64::from(k) / f64::from(n)).x;
        if x.signum() != prev.signum() {
            signs += 1;
        }
        prev = x;
    }
    assert_eq!(
        signs, 4,
        "intermediate-axis sign changes over 4 flip intervals"
    );
    // The local time step of RK4 must resolve the fast flips; horizon = two flips.
    assert_accuracy("tennis racket", check_torque_free(moments, w0, 2.0 * flip));
}

#[test]
fn symmetric_bodies_exact_equal_moments() {
    // Oblate (I₁ = I₂ < I₃), symmetry axis at index 0.
    let moments = v(2.0, 1.5, 1.5);
    let w0 = v(0.9, 0.7, -0.4);
    let body = TorqueFreeBody::new(moments, w0, q_initial()).expect("valid");
    assert_eq!(body.case(), TorqueFreeCase::Circulating { axis: 0 });
    assert_eq!(body.elliptic_parameter(), Some(0.0));
    // Body precession rate (I₃−I₁)/I₁·ω₃ → period 2π/|Ω_b|.
    let omega_b = (2.0 - 1.5) / 1.5 * 0.9;
    let p = body.period_omega().expect("periodic");
    assert!((p - 2.0 * std::f64::consts::PI / omega_b).abs() <= 1e-14 * p);
    assert_accuracy("oblate symmetric", check_torque_free(moments, w0, 2.0 * p));

    // Prolate (I₁ < I₂ = I₃), symmetry axis at index 1.
    let moments = v(2.0, 1.0, 2.0);
    let w0 = v(0.5, -1.5, 0.8);
    let body = TorqueFreeBody::new(moments, w0, q_initial()).expect("valid");
    assert_eq!(body.case(), TorqueFreeCase::Circulating { axis: 1 });
    assert_eq!(body.elliptic_parameter(), Some(0.0));
    let omega_b: f64 = (1.0 - 2.0) / 2.0 * -1.5;
    let p = body.period_omega().expect("periodic");
    assert!((p - 2.0 * std::f64::consts::PI / omega_b.abs()).abs() <= 1e-14 * p);
    assert_accuracy("prolate symmetric", check_torque_free(moments, w0, 2.0 * p));

    // Agreement with the dedicated symmetric solution (symmetry axis = z).
    let (it, ia) = (1.5, 2.0);
    let w0 = v(0.7, -0.4, 0.9);
    let general = TorqueFreeBody::new(v(it, it, ia), w0, q_initial()).expect("valid");
    let sym = SymmetricTorqueFree::new(it, ia, w0, q_initial()).expect("valid");
    for k in 0..50 {
        let t = 0.77 * f64::from(k);
        assert!((general.omega_p(t) - sym.omega_p(t)).norm() <= 1e-14);
        assert!(rot_angle(&general.attitude(t), &sym.attitude(t)) <= 1e-13);
    }
}

#[test]
fn near_symmetric_stays_elliptic_and_accurate() {
    // I₂ − I₁ = 1e-10·I₁: elliptic formulas with m ~ 1e-10, not the symmetric shortcut.
    let i1 = 1.0;
    let moments = v(1.6, i1, i1 * (1.0 + 1e-10));
    let w0 = v(0.8, 0.6, -0.5);
    let body = TorqueFreeBody::new(moments, w0, q_initial()).expect("valid");
    assert_eq!(body.case(), TorqueFreeCase::Circulating { axis: 0 });
    let m = body.elliptic_parameter().expect("elliptic");
    assert!(m > 0.0 && m < 1e-9, "m = {m}");
    assert_accuracy(
        "near-symmetric (circulating about the unique axis)",
        check_torque_free(moments, w0, 2.0 * body.period_omega().expect("periodic")),
    );
    // Compared with the exactly symmetric body the difference is O(1e-10), not O(1).
    let sym = TorqueFreeBody::new(v(1.6, i1, i1), w0, q_initial()).expect("valid");
    for k in 0..20 {
        let t = 1.3 * f64::from(k);
        assert!((body.omega_p(t) - sym.omega_p(t)).norm() <= 1e-8);
        assert!(rot_angle(&body.attitude(t), &sym.attitude(t)) <= 1e-8);
    }
    // The other regime of a near-symmetric body: ω about the nearly degenerate pair
    // (circulation about the smallest axis needs ω₂, ω₃ ≪ ω₁ here).
    let moments = v(1.0, 1.0 + 1e-10, 1.6);
    let w0 = v(0.9, 3e-6, 1e-6);
    let body = TorqueFreeBody::new(moments, w0, q_initial()).expect("valid");
    assert!(matches!(body.case(), TorqueFreeCase::Circulating { .. }));
    // Here ω₂, ω₃ turn at λ ≈ 5.5e-6 rad/s: difference Euler's equations on that time scale.
    let t_end = 40.0;
    assert_accuracy(
        "near-symmetric (degenerate pair)",
        check_torque_free_h(moments, w0, t_end, Some(0.1)),
    );
}

#[test]
fn spherical_zero_and_principal_axis_rotations() {
    let r = check_torque_free(v(2.0, 2.0, 2.0), v(0.3, -0.4, 1.2), 10.0);
    assert_accuracy("spherical", r);
    let body =
        TorqueFreeBody::new(v(2.0, 2.0, 2.0), v(0.3, -0.4, 1.2), q_initial()).expect("valid");
    assert_eq!(body.case(), TorqueFreeCase::Stationary);

    // Zero ω: nothing moves.
    let body = TorqueFreeBody::new(v(1.0, 2.0, 2.5), Vector3::zeros(), q_initial()).expect("ok");
    assert_eq!(body.case(), TorqueFreeCase::Stationary);
    assert_eq!(body.omega_p(5.0), Vector3::zeros());
    assert_eq!(body.attitude(5.0), q_initial());
    assert_eq!(body.h_s(), Vector3::zeros());
    assert_eq!(body.energy(), 0.0);

    // Pure rotation about each principal axis, including the (unstable) intermediate one.
    let moments = v(2.0, 1.0, 2.5);
    for axis in 0..3 {
        let mut w0 = Vector3::zeros();
        w0[axis] = -1.7;
        let body = TorqueFreeBody::new(moments, w0, q_initial()).expect("valid");
        assert_eq!(body.case(), TorqueFreeCase::Stationary);
        assert_eq!(body.omega_p(3.3), w0);
        let expected = q_initial() * UnitQuaternion::from_scaled_axis(w0 * 3.3);
        assert!(rot_angle(&body.attitude(3.3), &expected) <= 1e-14);
        assert_accuracy(
            &format!("pure axis {axis}"),
            check_torque_free(moments, w0, 10.0),
        );
    }
    // ω in the degenerate plane of a symmetric body is also a stationary rotation.
    let body = TorqueFreeBody::new(v(1.5, 1.5, 2.0), v(0.3, 0.4, 0.0), q_initial()).expect("ok");
    assert_eq!(body.case(), TorqueFreeCase::Stationary);
}

#[test]
fn relabelled_axes_give_the_same_physical_motion() {
    // Relabel the principal axes by a proper signed permutation P (v' = P v): moments
    // permuted, ω' = P ω, q0' = q0 ⊗ P⁻¹. The physical motion must not change:
    // ω'(t) = P ω(t), q'(t) = q(t) ⊗ P⁻¹ (as rotations).
    use nalgebra::{Matrix3, Rotation3};
    let moments = v(1.0, 2.0, 2.6);
    for w0 in [v(0.5, 1.1, -0.3), v(1.5, 0.2, 0.3), v(0.1, -0.2, 1.4)] {
        let base = TorqueFreeBody::new(moments, w0, q_initial()).expect("valid");
        let perms = [
            Matrix3::new(0.0, 1.0, 0.0, 0.0, 0.0, 1.0, 1.0, 0.0, 0.0),
            Matrix3::new(0.0, 0.0, 1.0, 1.0, 0.0, 0.0, 0.0, 1.0, 0.0),
            Matrix3::new(0.0, 1.0, 0.0, 1.0, 0.0, 0.0, 0.0, 0.0, -1.0),
            Matrix3::new(-1.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 1.0, 0.0),
        ];
        for p in perms {
            let qp = UnitQuaternion::from_rotation_matrix(&Rotation3::from_matrix_unchecked(p));
            let moments2 = p.abs() * moments;
            let body =
                TorqueFreeBody::new(moments2, p * w0, q_initial() * qp.inverse()).expect("valid");
            for k in 0..30 {
                let t = 0.61 * f64::from(k);
                assert!((body.omega_p(t) - p * base.omega_p(t)).norm() <= 1e-13);
                let want = base.attitude(t) * qp.inverse();
                assert!(rot_angle(&body.attitude(t), &want) <= 1e-13);
            }
        }
    }
}

#[test]
fn large_time_accuracy() {
    // φ over one period of ω by the trapezoidal rule (exponentially accurate for a periodic
    // analytic integrand): dφ/dt = M (Σ' I_i ω_i²)/(Σ' I_i² ω_i²), Σ' over the two axes other
    // than the circulation axis (L&L §37). Then q(N P + s) = Rot(Ĥ, N Δφ) q(s).
    for (moments, w0) in [
        (v(3.0, 1.0, 2.0), v(1.2, -0.8, 0.9)),
        (v(2.0, 1.0, 2.7), v(0.4, 2.1, -0.5)),
        (v(2.0, 1.0, 3.0), v(5.0, 1e-2, 1e-2)),
    ] {
        let body = TorqueFreeBody::new(moments, w0, q_initial()).expect("valid");
        let TorqueFreeCase::Circulating { axis } = body.case() else {
            panic!("expected circulating")
        };
        let p = body.period_omega().expect("periodic");
        let h = body.h_s();
        let hn = h.norm();
        let n_quad = 4000;
        let mut dphi = 0.0;
        for k in 0..n_quad {
            let w = body.omega_p(p * f64::from(k) / f64::from(n_quad));
            let (mut num, mut den) = (0.0, 0.0);
            for i in (0..3).filter(|&i| i != axis) {
                num += moments[i] * w[i] * w[i];
                den += moments[i] * moments[i] * w[i] * w[i];
            }
            dphi += hn * num / den;
        }
        dphi *= p / f64::from(n_quad);
        // Check one period first.
        let q_p = UnitQuaternion::from_axis_angle(&nalgebra::Unit::new_normalize(h), dphi)
            * body.attitude(0.0);
        assert!(rot_angle(&body.attitude(p), &q_p) <= 1e-12);

        let t_big = 1e6;
        let n = (t_big / p).floor();
        let s = t_big - n * p;
        let q_pred = UnitQuaternion::from_axis_angle(
            &nalgebra::Unit::new_normalize(h),
            (n * dphi) % (2.0 * std::f64::consts::PI),
        ) * body.attitude(s);
        let err = rot_angle(&body.attitude(t_big), &q_pred);
        let total_angle = w0.norm() * t_big;
        eprintln!("t = 1e6: attitude error {err:.2e} rad (rotation {total_angle:.1e} rad)");
        // A few ε relative to the accumulated rotation (the rates are known to rounding).
        assert!(
            err <= 1e-13 * total_angle,
            "attitude at t = 1e6: error {err}"
        );
        let dw = (body.omega_p(t_big) - body.omega_p(s)).norm() / w0.norm();
        assert!(dw <= 1e-9, "omega at t = 1e6: error {dw}");
        // H_s still conserved.
        let h_t = body.attitude(t_big) * moments.component_mul(&body.omega_p(t_big));
        assert!((h_t - h).norm() <= 1e-12 * hn);
    }
}

#[test]
fn invalid_inputs_are_rejected() {
    let q = q_initial();
    assert!(matches!(
        TorqueFreeBody::new(v(1.0, -2.0, 2.5), v(1.0, 0.0, 0.0), q),
        Err(ExactError::NonPositive { .. })
    ));
    assert!(matches!(
        TorqueFreeBody::new(v(1.0, 1.0, 2.5), v(1.0, 0.0, 0.0), q),
        Err(ExactError::TriangleInequality(..))
    ));
    assert!(matches!(
        TorqueFreeBody::new(v(1.0, f64::NAN, 1.5), v(1.0, 0.0, 0.0), q),
        Err(ExactError::NonFinite(_))
    ));
    assert!(matches!(
        TorqueFreeBody::new(v(1.0, 1.2, 1.5), v(1.0, f64::INFINITY, 0.0), q),
        Err(ExactError::NonFinite(_))
    ));
    // A lamina (I₃ = I₁ + I₂) is allowed.
    assert!(TorqueFreeBody::new(v(1.0, 2.0, 3.0), v(1.0, 1.0, 1.0), q).is_ok());
    assert!(SymmetricTorqueFree::new(1.0, 2.5, v(0.0, 0.0, 1.0), q).is_err());
    assert!(HeavySymmetricTop::new(1.0, 0.5, 0.0, 9.81, 0.1).is_err());
}

// ---------------------------------------------------------------------------------------------
// Symmetric bodies
// ---------------------------------------------------------------------------------------------

#[test]
fn symmetric_torque_free() {
    let (it, ia) = (1.2, 0.7); // prolate
    let w0 = v(0.8, -0.3, 2.5);
    let q0 = q_initial();
    let body = SymmetricTorqueFree::new(it, ia, w0, q0).expect("valid");
    let moments = v(it, it, ia);
    let omega_b = (ia - it) / it * w0.z;
    assert!((body.body_precession_rate() - omega_b).abs() <= 1e-15);
    let h = body.h_s();
    assert!((body.space_precession_rate() - h.norm() / it).abs() <= 1e-15);
    assert!(quat_dist(&body.attitude(0.0), &q0) <= 1e-15);
    assert_eq!(body.omega_p(0.0), w0);

    let omega = |t: f64| body.omega_p(t);
    let att = |t: f64| body.attitude(t);
    let mut worst = [0.0f64; 3];
    for k in 0..200 {
        let t = 0.05 * f64::from(k) + 0.01;
        worst[0] = worst[0].max(euler_residual(
            &moments,
            &omega,
            &|_| Vector3::zeros(),
            t,
            1e-5,
        ));
        worst[1] = worst[1].max(kinematic_residual(&att, &omega, t, 1e-5));
        let h_t = body.attitude(t) * moments.component_mul(&body.omega_p(t));
        worst[2] = worst[2].max((h_t - h).norm() / h.norm());
        // Space cone: ω_s stays at a fixed angle from H_s.
        let ws = body.omega_s(t);
        let ang = ws.cross(&h).norm().atan2(ws.dot(&h));
        assert!((ang - body.space_cone_half_angle()).abs() <= 1e-13);
        // Body cone: ω_p at a fixed angle from e₃; symmetry axis at a fixed angle from H.
        let wp = body.omega_p(t);
        assert!((wp.xy().norm().atan2(wp.z) - body.body_cone_half_angle()).abs() <= 1e-14);
        let e3_s = body.attitude(t) * Vector3::z();
        let nut = e3_s.cross(&h).norm().atan2(e3_s.dot(&h));
        assert!((nut - body.nutation_angle()).abs() <= 1e-13);
    }
    eprintln!(
        "symmetric torque-free: euler {:.1e} kinematic {:.1e} H_s drift {:.1e}",
        worst[0], worst[1], worst[2]
    );
    assert!(worst[0] <= 1e-7 && worst[1] <= 1e-7 && worst[2] <= 1e-13);
    // ω_s precesses about H at |H|/I₁: after one space period ω_s returns.
    let ps = 2.0 * std::f64::consts::PI / body.space_precession_rate();
    let e3 = |t: f64| body.attitude(t) * Vector3::z();
    // The symmetry axis returns after one space period.
    assert!((e3(ps) - e3(0.0)).norm() <= 1e-13);

    // Brute force.
    let times = [2.0, 5.0, 10.0];
    let sol = rk4(&moments, w0, q0, &times, 1e-4, &no_torque);
    for (&t, (w, q)) in times.iter().zip(&sol) {
        assert!((body.omega_p(t) - w).norm() <= 1e-10);
        assert!(rot_angle(&body.attitude(t), q) <= 1e-10);
    }
}

#[test]
fn symmetric_constant_axial_torque() {
    let (it, ia, m3) = (1.1, 1.8, 0.35);
    let w0 = v(0.6, -0.2, 0.9);
    let body = AxialTorqueSymmetric::new(it, ia, m3, w0).expect("valid");
    let moments = v(it, it, ia);
    assert_eq!(body.omega_p(0.0), w0);
    let omega = |t: f64| body.omega_p(t);
    let torque = |_: f64| body.torque_p();
    let mut worst: f64 = 0.0;
    for k in 0..200 {
        let t = 0.05 * f64::from(k) - 3.0;
        worst = worst.max(euler_residual(&moments, &omega, &torque, t, 1e-5));
    }
    eprintln!("axial torque: euler {worst:.1e}");
    assert!(worst <= 1e-7);
    // ω₃ linear in time, |ω⊥| constant.
    let w = body.omega_p(7.0);
    assert!((w.z - (0.9 + m3 * 7.0 / ia)).abs() <= 1e-15);
    assert!((w.xy().norm() - w0.xy().norm()).abs() <= 1e-15);
    // Brute force (the torque is fixed in the body).
    let times = [1.0, 4.0, 8.0];
    let tau = body.torque_p();
    let sol = rk4(
        &moments,
        w0,
        UnitQuaternion::identity(),
        &times,
        1e-4,
        &|_| tau,
    );
    for (&t, (w, _)) in times.iter().zip(&sol) {
        let d = (body.omega_p(t) - w).norm() / w.norm();
        eprintln!("axial torque RK4 t={t}: {d:.1e}");
        assert!(d <= 1e-11, "t={t}");
    }
}

#[test]
fn heavy_top_steady_precession() {
    // Pivot moments: I_t about the pivot, I₃ axial; m g l.
    let top = HeavySymmetricTop::new(0.045, 0.02, 0.5, 9.81, 0.04).expect("valid");
    let theta = 0.6;
    let omega3 = 120.0;
    let PrecessionRoots::Two { slow, fast } =
        top.steady_precession_rates(theta, omega3).expect("valid")
    else {
        panic!("a fast top has two roots")
    };
    // Slow ≈ mgl/(I₃ω₃), fast ≈ I₃ω₃/(I_t cos θ).
    assert!((slow - top.mgl() / (0.02 * omega3)).abs() / slow < 0.01);
    assert!((fast - 0.02 * omega3 / (0.045 * theta.cos())).abs() / fast < 0.01);
    for rate in [slow, fast] {
        let r = top.steady_precession_residual(theta, omega3, rate);
        assert!(r.abs() <= 1e-14 * top.mgl().max(rate * 0.02 * omega3));
        let motion = SteadyPrecession::new(top, theta, omega3, rate, 0.4, -1.0).expect("steady");
        let moments = v(top.i_t(), top.i_t(), top.i_a());
        // Initial state reproduces the requested tilt, spin and Euler angles.
        let w0 = motion.omega0_p();
        assert!((w0.z - omega3).abs() <= 1e-15 * omega3);
        let e3_s = motion.attitude(0.0) * Vector3::z();
        assert!((e3_s.z - theta.cos()).abs() <= 1e-15);
        let omega = |t: f64| motion.omega_p(t);
        let att = |t: f64| motion.attitude(t);
        let torque = |t: f64| motion.torque_p(t);
        let mut worst = [0.0f64; 2];
        let h = 1e-6;
        for k in 0..200 {
            let t = 0.013 * f64::from(k);
            worst[0] = worst[0].max(euler_residual(&moments, &omega, &torque, t, h));
            worst[1] = worst[1].max(kinematic_residual(&att, &omega, t, h));
            // Tilt constant, vertical-axis precession uniform.
            let e3 = motion.attitude(t) * Vector3::z();
            assert!((e3.z - theta.cos()).abs() <= 1e-14);
        }
        eprintln!(
            "heavy top Ω = {rate:.4}: euler {:.1e} kinematic {:.1e}",
            worst[0], worst[1]
        );
        assert!(worst[0] <= 1e-7 && worst[1] <= 1e-7);
        // Brute force over a few precession periods (slow root) or spin periods (fast).
        let t_end = if rate == slow { 2.0 } else { 0.3 };
        let times: Vec<f64> = (1..=4).map(|k| t_end * f64::from(k) / 4.0).collect();
        let sol = rk4(&moments, w0, motion.attitude(0.0), &times, 2e-6, &|q| {
            top.torque_p(q)
        });
        for (&t, (w, q)) in times.iter().zip(&sol) {
            let dw = (motion.omega_p(t) - w).norm() / w.norm();
            let da = rot_angle(&motion.attitude(t), q);
            eprintln!("  RK4 t={t}: omega {dw:.1e} angle {da:.1e}");
            assert!(dw <= 1e-9 && da <= 1e-9);
        }
    }
    // Not enough spin for an upright top → no steady precession.
    assert_eq!(
        top.steady_precession_rates(theta, 1.0).expect("valid"),
        PrecessionRoots::None
    );
    // Hanging below the pivot (θ > π/2): roots of opposite signs always exist.
    match top.steady_precession_rates(2.5, 1.0).expect("valid") {
        PrecessionRoots::Two { slow, fast } => assert!(slow * fast < 0.0),
        other => panic!("expected two roots, got {other:?}"),
    }
    assert!(top.steady_precession_rates(0.0, 10.0).is_err());
    assert!(SteadyPrecession::new(top, theta, omega3, 1.0, 0.0, 0.0).is_err());
}
