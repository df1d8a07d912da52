//! Rigid bodies: shape inertias, principal decomposition, parallel-axis theorem, validation, kinetic states.

use approx::assert_relative_eq;
use eulerdyn::body::{Principal, RigidBody, Shape};
use eulerdyn::kinetics;
use nalgebra::{Matrix3, Rotation3, Vector3};

fn diag(m: &Matrix3<f64>) -> [f64; 3] {
    [m[(0, 0)], m[(1, 1)], m[(2, 2)]]
}

#[test]
fn shape_inertias_match_the_standard_formulas() {
    // Meriam & Kraige, Dynamics, Appendix B (homogeneous bodies about their mass center).
    let m = 3.0;
    let i = |s: Shape| diag(&s.inertia_c(m).unwrap());
    assert_eq!(
        i(Shape::ThinDisk { radius: 0.5 }),
        [m * 0.25 / 4.0, m * 0.25 / 4.0, m * 0.25 / 2.0]
    );
    let disk = i(Shape::Disk {
        radius: 0.5,
        thickness: 0.2,
    });
    assert_relative_eq!(disk[0], m * (3.0 * 0.25 + 0.04) / 12.0);
    assert_relative_eq!(disk[2], m * 0.25 / 2.0);
    assert_eq!(
        i(Shape::ThinRod { length: 2.0 }),
        [0.0, m * 4.0 / 12.0, m * 4.0 / 12.0]
    );
    assert_relative_eq!(i(Shape::Sphere { radius: 0.5 })[1], 0.4 * m * 0.25);
    let b = i(Shape::Box {
        size: [1.0, 2.0, 3.0],
    });
    assert_relative_eq!(b[0], m * (4.0 + 9.0) / 12.0);
    assert_relative_eq!(b[1], m * (1.0 + 9.0) / 12.0);
    assert_relative_eq!(b[2], m * (1.0 + 4.0) / 12.0);
    let c = i(Shape::Cylinder {
        radius: 0.5,
        height: 2.0,
    });
    assert_relative_eq!(c[0], m * (0.75 + 4.0) / 12.0);
    assert_relative_eq!(c[2], m * 0.25 / 2.0);
}

#[test]
fn principal_decomposition_recovers_moments_and_axes_of_a_rotated_tensor() {
    let rotation = Rotation3::from_euler_angles(0.4, -1.1, 2.3);
    let moments = Vector3::new(1.0, 2.0, 2.5);
    let tensor =
        rotation.matrix() * Matrix3::from_diagonal(&moments) * rotation.matrix().transpose();
    let p = Principal::of(&tensor);
    assert_relative_eq!(p.moments, moments, epsilon = 1e-14);
    assert_relative_eq!(p.axes_b.matrix().determinant(), 1.0, epsilon = 1e-14);
    // I = P diag P^T.
    let rebuilt =
        p.axes_b.matrix() * Matrix3::from_diagonal(&p.moments) * p.axes_b.matrix().transpose();
    assert_relative_eq!(rebuilt, tensor, epsilon = 1e-14);
    // A diagonal tensor is returned exactly, in body order.
    let d = Principal::of(&Matrix3::from_diagonal(&Vector3::new(3.0, 1.0, 2.0)));
    assert_eq!(d.moments, Vector3::new(3.0, 1.0, 2.0));
    assert_eq!(d.axes_b, Rotation3::identity());
}

#[test]
fn parallel_axis_theorem_matches_the_integral_definition_for_point_masses() {
    // I_A = Σ m_k (|ρ_k|² E − ρ_k ρ_kᵀ) computed directly for a set of point masses, against I_C + m(|d|²E − d dᵀ).
    let points = [
        (1.0, Vector3::new(0.3, 0.1, -0.2)),
        (2.0, Vector3::new(-0.1, 0.4, 0.2)),
        (0.5, Vector3::new(0.2, -0.3, 0.5)),
        (1.5, Vector3::new(-0.4, -0.1, -0.1)),
    ];
    let mass: f64 = points.iter().map(|p| p.0).sum();
    let center = points.iter().map(|p| p.1 * p.0).sum::<Vector3<f64>>() / mass;
    let about = |origin: Vector3<f64>| {
        points.iter().fold(Matrix3::zeros(), |acc, (m, r)| {
            let rho = r - origin;
            acc + (Matrix3::identity() * rho.norm_squared() - rho * rho.transpose()) * *m
        })
    };
    let body = RigidBody::new(mass, about(center)).unwrap();
    let a = Vector3::new(0.7, -0.2, 0.4);
    let rho_c = center - a;
    assert_relative_eq!(body.inertia_about(&rho_c), about(a), epsilon = 1e-14);
}

#[test]
fn moment_of_momentum_about_a_body_point_theorem_25() {
    // H_A = m ρ_C × v_A + I_A·ω (eq. 8.4) equals Σ m_k ρ_k × v_k over point masses with v_k = v_A + ω × ρ_k.
    let points = [
        (1.0, Vector3::new(0.3, 0.1, -0.2)),
        (2.0, Vector3::new(-0.1, 0.4, 0.2)),
        (0.5, Vector3::new(0.2, -0.3, 0.5)),
        (1.5, Vector3::new(-0.4, -0.1, -0.1)),
    ];
    let a = Vector3::new(0.1, 0.2, 0.3);
    let v_a = Vector3::new(1.0, -2.0, 0.5);
    let omega = Vector3::new(0.3, -1.2, 2.0);
    let mass: f64 = points.iter().map(|p| p.0).sum();
    let rho_c = points.iter().map(|p| (p.1 - a) * p.0).sum::<Vector3<f64>>() / mass;
    let inertia_a = points.iter().fold(Matrix3::zeros(), |acc, (m, r)| {
        let rho = r - a;
        acc + (Matrix3::identity() * rho.norm_squared() - rho * rho.transpose()) * *m
    });
    let direct = points.iter().fold(Vector3::zeros(), |acc, (m, r)| {
        let rho = r - a;
        acc + rho.cross(&((v_a + omega.cross(&rho)) * *m))
    });
    let h_a = kinetics::moment_of_momentum_a(mass, &rho_c, &v_a, &inertia_a, &omega);
    assert_relative_eq!(h_a, direct, epsilon = 1e-13);
    // Theorem 23: P = m v_C with v_C = v_A + ω × ρ_C equals Σ m_k v_k.
    let p_direct = points.iter().fold(Vector3::zeros(), |acc, (m, r)| {
        acc + (v_a + omega.cross(&(r - a))) * *m
    });
    assert_relative_eq!(
        kinetics::momentum(mass, &(v_a + omega.cross(&rho_c))),
        p_direct,
        epsilon = 1e-13
    );
    // Energy (König) equals Σ ½ m_k |v_k|².
    let t_direct: f64 = points
        .iter()
        .map(|(m, r)| 0.5 * m * (v_a + omega.cross(&(r - a))).norm_squared())
        .sum();
    let inertia_c =
        inertia_a - (Matrix3::identity() * rho_c.norm_squared() - rho_c * rho_c.transpose()) * mass;
    let t = kinetics::kinetic_energy_c(mass, &(v_a + omega.cross(&rho_c)), &inertia_c, &omega);
    assert_relative_eq!(t, t_direct, epsilon = 1e-13);
}

#[test]
fn validation_names_the_key_and_the_problem() {
    let err = |r: Result<RigidBody, eulerdyn::body::InvalidBody>| r.unwrap_err();
    let e = err(RigidBody::from_principal(0.0, [1.0, 1.0, 1.0]));
    assert_eq!(e.key, "mass");
    let e = err(RigidBody::from_principal(f64::NAN, [1.0, 1.0, 1.0]));
    assert_eq!(e.key, "mass");
    let e = err(RigidBody::from_principal(1.0, [1.0, 1.0, 3.0]));
    assert_eq!(e.key, "inertia");
    assert!(e.problem.contains("triangle"), "{}", e.problem);
    let e = err(RigidBody::from_principal(1.0, [1.0, 1.0, -0.5]));
    assert!(
        e.problem.contains("positive semi-definite"),
        "{}",
        e.problem
    );
    let e = err(RigidBody::new(
        1.0,
        Matrix3::new(1.0, 0.1, 0.0, 0.2, 1.0, 0.0, 0.0, 0.0, 1.0),
    ));
    assert!(e.problem.contains("symmetric"), "{}", e.problem);
    let e = err(RigidBody::new(
        1.0,
        Matrix3::new(1.0, 0.0, 0.0, 0.0, f64::INFINITY, 0.0, 0.0, 0.0, 1.0),
    ));
    assert!(e.problem.contains("finite"), "{}", e.problem);
    let e = err(RigidBody::from_principal(1.0, [0.0, 0.0, 0.0]));
    assert!(e.problem.contains("zero"), "{}", e.problem);
    let e = err(RigidBody::from_shape(1.0, Shape::ThinDisk { radius: -1.0 }));
    assert_eq!(e.key, "shape.radius");
    // Limits that are valid: a planar body (I1 + I2 = I3) and a thin rod (a zero moment).
    RigidBody::from_shape(1.0, Shape::ThinDisk { radius: 1.0 }).unwrap();
    RigidBody::from_shape(1.0, Shape::ThinRod { length: 1.0 }).unwrap();
}
