//! Moments from the user's own laws: a tabulated torque (`type = "torque_table"`), a Rust closure
//! (`Scene::with_moment`), and their errors.

use eulerdyn::Sample;
use eulerdyn::frames::Axes;
use eulerdyn::scene::{BodySpec, Overrides, SceneSpec, TorqueSpec, TorqueTableSpec, load};
use eulerdyn::simulate;
use nalgebra::{UnitQuaternion, Vector3};

use crate::common::{dir_entries, eulerdyn, write_file};

/// A scene file with one torque table, `file` and `interpolation` as given.
fn table_scene(file: &str, interpolation: &str, t_end: f64) -> String {
    format!(
        "[body]\nmass = 1.0\ninertia = [1.0, 2.0, 3.0]\n\n[[effect]]\ntype = \"torque_table\"\nfile = \"{file}\"\n\
         interpolation = \"{interpolation}\"\n\n[solver]\nt_end = {t_end}\n\n[output]\nevery = 0.25\n"
    )
}

fn rows(scene: &eulerdyn::Scene) -> Vec<Sample> {
    simulate::samples(scene).expect("the run").0
}

/// The largest difference of two runs' rows in ω_b, q and H_s.
fn largest_difference(a: &[Sample], b: &[Sample]) -> f64 {
    assert_eq!(a.len(), b.len());
    (a.iter().zip(b))
        .map(|(x, y)| {
            assert_eq!(x.t, y.t);
            let dq = (x.q.coords - y.q.coords).norm();
            (x.omega_b - y.omega_b)
                .norm()
                .max(dq)
                .max((x.h_o_s - y.h_o_s).norm())
        })
        .fold(0.0, f64::max)
}

/// A body at rest spun up about its principal axis z by M_z = k t: Euler's equation about a principal axis with
/// ω_x = ω_y = 0 is I_z ω̇_z = M_z (notes, eq. 8.9 in principal axes), so ω_z = k t²/(2 I_z). Both interpolations
/// reproduce the ramp (a natural cubic spline through collinear points is that line), so the run does too.
#[test]
fn a_ramp_table_spins_the_body_up_as_the_integral_of_eulers_equation() {
    let dir = tempfile::tempdir().unwrap();
    let k = 0.4;
    let table: String = (0..=8)
        .map(|i| format!("{},0,0,{}\n", i as f64 * 0.5, k * i as f64 * 0.5))
        .collect();
    write_file(dir.path(), "ramp.csv", format!("t,M_x,M_y,M_z\n{table}"));
    for interpolation in ["linear", "cubic"] {
        let scene_path = write_file(
            dir.path(),
            "ramp.toml",
            table_scene("ramp.csv", interpolation, 4.0),
        );
        let scene = load(&scene_path, &Overrides::default()).unwrap();
        let samples = rows(&scene);
        assert_eq!(samples.len(), 17);
        for s in samples.iter().skip(1) {
            let expected = k * s.t * s.t / (2.0 * 3.0);
            let rel = (s.omega_b.z - expected).abs() / expected;
            assert!(
                rel < 1e-12,
                "{interpolation}: t = {}: {} vs {expected} ({rel:e})",
                s.t,
                s.omega_b.z
            );
            assert_eq!((s.omega_b.x, s.omega_b.y), (0.0, 0.0));
        }
    }
}

/// A table holding one value over the whole run is the constant torque of that value.
#[test]
fn a_constant_table_is_the_built_in_constant_torque() {
    let dir = tempfile::tempdir().unwrap();
    let csv = write_file(
        dir.path(),
        "c.csv",
        "t,M_x,M_y,M_z\n0,0.2,-0.1,0.3\n10,0.2,-0.1,0.3\n",
    );
    for axes in [Axes::Body, Axes::Space] {
        let base = SceneSpec::new(BodySpec::principal(1.0, [1.0, 2.0, 3.0]), 5.0, 0.25)
            .with_omega([0.3, 1.0, -0.2]);
        let table = base
            .clone()
            .with_effect(TorqueTableSpec::new(&csv).in_axes(axes))
            .build()
            .unwrap();
        let constant = base
            .with_effect(TorqueSpec::new(axes, [0.2, -0.1, 0.3]))
            .build()
            .unwrap();
        let diff = largest_difference(&rows(&table), &rows(&constant));
        assert!(diff < 1e-12, "{axes:?}: {diff:e}");
    }
}

/// A Rust closure that computes the built-in sine torque value·sin(2π f t + φ) gives the built-in's rows.
#[test]
fn a_closure_computing_the_sine_torque_gives_the_built_in_rows() {
    let (value, freq_hz, phase_deg) = ([0.3, -0.2, 0.5], 0.7, 30.0);
    for axes in [Axes::Body, Axes::Space] {
        let base = SceneSpec::new(BodySpec::principal(2.0, [1.0, 2.0, 3.0]), 3.0, 0.1)
            .with_omega([0.1, 1.5, 0.2])
            .with_tolerances(1e-11, 1e-13);
        let builtin = (base.clone())
            .with_effect(TorqueSpec::new(axes, value).sine(freq_hz, phase_deg))
            .build()
            .unwrap();
        let sine = move |t: f64, _q: &UnitQuaternion<f64>, _omega_b: &Vector3<f64>| {
            Vector3::from(value)
                * (2.0 * std::f64::consts::PI * freq_hz * t + phase_deg.to_radians()).sin()
        };
        let user = base
            .build()
            .unwrap()
            .with_moment("sine", axes, sine)
            .unwrap();
        let diff = largest_difference(&rows(&user), &rows(&builtin));
        assert!(diff < 1e-12, "{axes:?}: {diff:e}");
    }
}

/// A PD attitude controller M = −k_p θ_err·axis − k_d ω slewing a body about its principal axis z to θ_t: the
/// remaining rotation vector is exactly (θ_t − θ)·z, so I θ̈ + k_d θ̇ + k_p θ = k_p θ_t, whose unit-step response with
/// ω_n = √(k_p/I), ζ = k_d/(2√(k_p I)) < 1 is θ_t [1 − e^{−ζω_n t}(cos ω_d t + ζ/√(1−ζ²) sin ω_d t)],
/// ω_d = ω_n√(1 − ζ²) (Ogata, Modern Control Engineering, 5th ed., §5-3, eq. 5-10).
#[test]
fn a_pd_slew_follows_the_second_order_step_response() {
    let (i_z, k_p, k_d, theta_t) = (2.0, 8.0, 4.0, 0.05);
    let target = UnitQuaternion::from_axis_angle(&Vector3::z_axis(), theta_t);
    let pd = move |_t: f64, q: &UnitQuaternion<f64>, omega_b: &Vector3<f64>| {
        q.inverse_transform_vector(&q.rotation_to(&target).scaled_axis()) * k_p - omega_b * k_d
    };
    let scene = SceneSpec::new(BodySpec::principal(1.0, [1.0, 1.5, i_z]), 8.0, 0.25)
        .build()
        .unwrap()
        .with_moment("pd", Axes::Body, pd)
        .unwrap();
    let (omega_n, zeta) = ((k_p / i_z).sqrt(), k_d / (2.0 * (k_p * i_z).sqrt()));
    let omega_d = omega_n * (1.0 - zeta * zeta).sqrt();
    for s in rows(&scene) {
        let theta = 2.0 * s.q.k.atan2(s.q.w);
        let decay = (-zeta * omega_n * s.t).exp();
        let shape =
            (omega_d * s.t).cos() + zeta / (1.0 - zeta * zeta).sqrt() * (omega_d * s.t).sin();
        let expected = theta_t * (1.0 - decay * shape);
        assert!(
            (theta - expected).abs() < 1e-6 * theta_t,
            "t = {}: {theta} vs {expected}",
            s.t
        );
    }
}

#[test]
fn a_law_needs_a_free_body_and_a_runge_kutta_method() {
    let law = |_t: f64, _q: &UnitQuaternion<f64>, _w: &Vector3<f64>| Vector3::zeros();
    let split = SceneSpec::new(BodySpec::principal(1.0, [1.0, 2.0, 3.0]), 1.0, 0.5)
        .with_method(eulerdyn::Method::Split2)
        .build()
        .unwrap();
    let e = split.with_moment("zero", Axes::Body, law).unwrap_err();
    assert_eq!(e.key.to_string(), "solver.method");
    let free = SceneSpec::new(BodySpec::principal(1.0, [1.0, 2.0, 3.0]), 1.0, 0.5)
        .build()
        .unwrap();
    let e = free.with_moment(" ", Axes::Body, law).unwrap_err();
    assert!(e.to_string().contains("needs a name"), "{e}");
}

/// Bad tables: exit 2 naming the scene key, the table file and its row, and nothing written.
#[test]
fn bad_tables_are_refused_naming_the_file_and_row() {
    let cases = [
        (
            "t,Mx,My,Mz\n0,0,0,0\n1,0,0,0\n",
            "row 0 (the header): expected `t,M_x,M_y,M_z`",
        ),
        (
            "t,M_x,M_y,M_z\n0,0,0,0\n1,0,inf,0\n",
            "row 2 (line 3): M_y must be a finite number, got `inf`",
        ),
        (
            "t,M_x,M_y,M_z\n0,0,0,0\n1,0,0,0\n1,0,0,0\n",
            "row 3 (line 4): t = 1 is not later",
        ),
        (
            "t,M_x,M_y,M_z\n0,0,0,0\n",
            "the table has 1 row(s) after its header; it needs at least 2 to interpolate",
        ),
    ];
    for (text, problem) in cases {
        let dir = tempfile::tempdir().unwrap();
        write_file(dir.path(), "m.csv", text);
        let scene = write_file(dir.path(), "s.toml", table_scene("m.csv", "cubic", 1.0));
        let out = dir.path().join("out.csv");
        let outcome = eulerdyn([
            "run".as_ref(),
            scene.as_os_str(),
            "-o".as_ref(),
            out.as_os_str(),
        ]);
        outcome.expect_code(2);
        let csv = dir.path().join("m.csv");
        let expected = format!("key `effect[0].file`: {}: {problem}", csv.display());
        assert!(
            outcome.stderr.contains(&expected),
            "{}\nexpected: {expected}",
            outcome.stderr
        );
        assert_eq!(dir_entries(dir.path()), ["m.csv", "s.toml"]);
    }
    let dir = tempfile::tempdir().unwrap();
    let scene = write_file(
        dir.path(),
        "s.toml",
        table_scene("absent.csv", "linear", 1.0),
    );
    let outcome = eulerdyn(["check".as_ref(), scene.as_os_str()]);
    outcome.expect_code(2);
    assert!(
        outcome.stderr.contains("absent.csv: cannot read the table"),
        "{}",
        outcome.stderr
    );
    let scene = write_file(
        dir.path(),
        "s.toml",
        table_scene("absent.csv", "quintic", 1.0),
    );
    let outcome = eulerdyn(["check".as_ref(), scene.as_os_str()]);
    outcome.expect_code(2);
    assert!(
        outcome.stderr.contains("expected one of: linear, cubic"),
        "{}",
        outcome.stderr
    );
}
