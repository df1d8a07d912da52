//! Wheels under control (core/src/wheels): torque and speed limits, friction, free wheels, wheel laws and tables,
//! against closed forms. Every closed form follows in a line from the gyrostat's equations about one axis x with
//! no external moment (Hughes, *Spacecraft Attitude Dynamics*, 1986, the gyrostat; core/src/wheels/gyrostat.rs):
//! I ω̇ + J Ω̇ = 0 (H_s conserved) and J (ω̇ + Ω̇) = τ_m + τ_f, hence (I − J) ω̇ = −(τ_m + τ_f) and
//! Ω̇ = I (τ_m + τ_f) / (J (I − J)). Tolerances: dop853 at rtol 1e-12 and atol 1e-14 reaches about 1e-11 relative
//! on these smooth motions (as tests/it/rotors.rs); 1e-9 is asserted, except where a switch (a limit, a stop)
//! is crossed inside a step, whose tolerance is stated beside it.

use crate::common::{assert_refused_writing_nothing, eulerdyn, write_file};
use eulerdyn::profile::Profile;
use eulerdyn::sample::Sample;
use eulerdyn::scene::{BodySpec, RotorDrive, RotorSpec, SceneSpec};
use eulerdyn::wheels::{FrictionKeys, RotorRows, STICK_SPEED, WheelKeys};
use eulerdyn::{Form, Method, simulate};
use nalgebra::{UnitQuaternion, Vector3};

const I_XX: f64 = 2.0;
const J: f64 = 0.05;

fn rows(scene: &eulerdyn::Scene) -> Vec<Sample> {
    simulate::samples(scene).unwrap_or_else(|e| panic!("{e}")).0
}

/// A body at rest (I_xx = 2, about x) with `wheel` along x, tight dop853, `form`, rows every `every` to `t_end`.
fn scene(wheel: RotorSpec, form: Form, t_end: f64, every: f64) -> eulerdyn::Scene {
    let body = BodySpec::principal(10.0, [I_XX, 3.0, 4.0]).with_rotor(wheel);
    SceneSpec::new(body, t_end, every)
        .with_method(Method::Dop853)
        .with_tolerances(1e-12, 1e-14)
        .with_form(form)
        .build()
        .unwrap_or_else(|e| panic!("{e}"))
}

fn close(a: f64, b: f64, tol: f64, what: &str) {
    assert!(
        (a - b).abs() <= tol * b.abs().max(1.0),
        "{what}: {a} vs {b} (difference {:e})",
        a - b
    );
}

fn motor(tau: f64) -> RotorDrive {
    RotorDrive::Torque {
        value: tau,
        profile: Profile::Constant,
    }
}

fn limits(max_torque: Option<f64>, max_speed_rpm: Option<f64>) -> WheelKeys {
    WheelKeys {
        max_torque,
        max_speed_rpm,
        friction: None,
    }
}

fn friction(coulomb: Option<f64>, viscous: Option<f64>) -> WheelKeys {
    WheelKeys {
        friction: Some(FrictionKeys {
            coulomb,
            viscous,
            stribeck: None,
        }),
        ..WheelKeys::default()
    }
}

#[test]
fn a_clipped_command_exchanges_momentum_at_the_limit() {
    // τ_cmd = 1 N·m clipped to τ_max = 0.1 N·m: ω_x = −τ_max t / (I − J) (module doc), Ω = τ_max t I / (J (I − J)).
    let tau_max = 0.1;
    let wheel = RotorSpec::new([1.0, 0.0, 0.0], J, 0.0)
        .with_drive(motor(1.0))
        .with_wheel(limits(Some(tau_max), None));
    for form in Form::ALL {
        for s in rows(&scene(wheel.clone(), form, 10.0, 0.5)) {
            close(s.omega_b.x, -tau_max * s.t / (I_XX - J), 1e-9, "ω_x");
            let r = RotorRows::of(&s).expect("rotor columns");
            close(
                r.spin[0],
                tau_max * s.t * I_XX / (J * (I_XX - J)),
                1e-9,
                "Ω",
            );
            assert_eq!(
                (r.torque[0], r.torque_cmd[0]),
                (tau_max, 1.0),
                "applied and commanded"
            );
            assert!(s.h_o_s.norm() <= 1e-12, "{form:?}: H_s = {}", s.h_o_s);
        }
    }
}

#[test]
fn the_speed_limit_holds_the_spin_at_the_limit() {
    // τ = 0.1 N·m spins the wheel up as above until Ω reaches Ω_max at t_lim = Ω_max J (I − J) / (τ I); then the
    // motor applies only what holds Ω there: with nothing else acting that is 0, and ω_x = −J Ω_max / I (H_s = 0).
    let (tau, rpm) = (0.1, 30.0);
    let omega_max = rpm * std::f64::consts::PI / 30.0;
    let t_lim = omega_max * J * (I_XX - J) / (tau * I_XX);
    let wheel = RotorSpec::new([1.0, 0.0, 0.0], J, 0.0)
        .with_drive(motor(tau))
        .with_wheel(limits(None, Some(rpm)));
    for form in Form::ALL {
        let samples = rows(&scene(wheel.clone(), form, 2.0 * t_lim, t_lim / 8.0));
        assert!(
            samples.iter().any(|s| s.t > t_lim),
            "the run passes the limit"
        );
        for s in samples {
            let r = RotorRows::of(&s).expect("rotor columns");
            let spin = (tau * s.t * I_XX / (J * (I_XX - J))).min(omega_max);
            // Reaching the limit inside a step: the step's error control keeps the overshoot to the local
            // tolerance, 1e-12 relative and 1e-14 absolute, far below 1e-9.
            close(r.spin[0], spin, 1e-9, "Ω");
            close(
                s.omega_b.x,
                -J * r.spin[0] / I_XX,
                1e-12,
                "ω_x = −J Ω / I (H_s = 0)",
            );
            assert!(
                r.spin[0] <= omega_max * (1.0 + 1e-9),
                "Ω never passes the limit"
            );
            if s.t > t_lim {
                assert!(
                    r.torque[0].abs() <= 1e-12,
                    "held: τ = {} at {}",
                    r.torque[0],
                    s.t
                );
                assert_eq!(r.torque_cmd[0], tau, "the command is kept");
            }
        }
    }
}

#[test]
fn a_free_wheel_under_viscous_friction_decays_exponentially() {
    // τ_f = −c Ω: Ω = Ω₀ exp(−c I t / (J (I − J))) (module doc) with I ω + J Ω = J Ω₀ (H conserved, ω₀ = 0).
    let (c, spin0) = (2e-3, 100.0);
    let wheel = RotorSpec::new([1.0, 0.0, 0.0], J, spin0)
        .with_drive(RotorDrive::Free)
        .with_wheel(friction(None, Some(c)));
    for form in Form::ALL {
        let samples = rows(&scene(wheel.clone(), form, 20.0, 0.5));
        let mut energy = f64::INFINITY;
        for s in samples {
            let r = RotorRows::of(&s).expect("rotor columns");
            let spin = spin0 * (-c * I_XX * s.t / (J * (I_XX - J))).exp();
            close(r.spin[0], spin, 1e-9, "Ω");
            close(
                I_XX * s.omega_b.x + J * r.spin[0],
                J * spin0,
                1e-12,
                "I ω + J Ω",
            );
            close(r.friction[0], -c * r.spin[0], 1e-15, "τ_f = −c Ω");
            assert_eq!(r.torque[0], 0.0, "a free wheel has no motor");
            assert!(s.energy < energy || s.t == 0.0, "the energy falls");
            energy = s.energy;
        }
    }
}

#[test]
fn coulomb_friction_stops_a_free_wheel_at_the_closed_form_time_without_chatter() {
    // τ_f = −c sign(Ω): Ω = Ω₀ − c I t / (J (I − J)) until t_stop = Ω₀ J (I − J) / (c I); then the wheel sticks
    // (the torque that holds it, J ω̇ = 0, is within c) at Ω = 0 exactly and ω = J Ω₀ / I; H_s = J Ω₀ throughout
    // (the stop moves the last ≤ STICK_SPEED of Ω into ω, keeping H: 1e-15 relative is a few roundings of H).
    let (c, spin0) = (2e-3, 10.0);
    let t_stop = spin0 * J * (I_XX - J) / (c * I_XX);
    let wheel = RotorSpec::new([1.0, 0.0, 0.0], J, spin0)
        .with_drive(RotorDrive::Free)
        .with_wheel(friction(Some(c), None));
    for form in Form::ALL {
        let samples = rows(&scene(wheel.clone(), form, 2.0 * t_stop, t_stop / 16.0));
        for s in &samples {
            let r = RotorRows::of(s).expect("rotor columns");
            let spin = (spin0 - c * I_XX * s.t / (J * (I_XX - J))).max(0.0);
            // The stop: the spin is taken as at rest below STICK_SPEED, so it may end up to that above zero.
            assert!(
                (r.spin[0] - spin).abs() <= 1e-9 * spin0 + STICK_SPEED,
                "Ω = {} vs {spin} at {}",
                r.spin[0],
                s.t
            );
            assert!(
                r.spin[0] >= -STICK_SPEED,
                "no chatter through zero: Ω = {}",
                r.spin[0]
            );
            close(s.h_o_s.x, J * spin0, 1e-15, "H_s, kept by the stop");
            if s.t > t_stop {
                assert_eq!(r.spin[0], 0.0, "a stuck wheel rests at exactly 0");
                assert!(
                    r.friction[0].abs() <= 1e-12,
                    "stuck, no torque needed: {}",
                    r.friction[0]
                );
                close(s.omega_b.x, J * spin0 / I_XX, 1e-9, "ω after the stop");
            }
        }
        // Stopped exactly once: after the stop the spin no longer changes.
        let after: Vec<f64> = (samples.iter().filter(|s| s.t > t_stop * 1.01))
            .map(|s| RotorRows::of(s).unwrap().spin[0])
            .collect();
        assert!(
            after.len() > 4 && after.windows(2).all(|w| w[0] == w[1]),
            "{after:?}"
        );
    }
}

#[test]
fn a_pd_law_through_one_wheel_gives_the_second_order_step_response() {
    // One wheel along z, τ = −(k_p (θ_t − θ) − k_d θ̇) so that (I − J) θ̈ = −τ (module doc) is
    // θ̈ + 2ζω_n θ̇ + ω_n² θ = ω_n² θ_t, ω_n² = k_p/(I − J), 2ζω_n = k_d/(I − J): the underdamped step response
    // θ = θ_t (1 − e^{−ζω_n t}(cos ω_d t + ζω_n/ω_d sin ω_d t)), ω_d = ω_n √(1 − ζ²) (Ogata, *Modern Control
    // Engineering*, 5th ed., §5-3, eq. 5-10).
    let (i_zz, j, theta_t, k_p, k_d): (f64, f64, f64, f64, f64) = (4.0, 0.1, 0.3, 1.0, 0.8);
    let (wn, zeta) = {
        let wn = (k_p / (i_zz - j)).sqrt();
        (wn, k_d / (i_zz - j) / (2.0 * wn))
    };
    let wd = wn * (1.0 - zeta * zeta).sqrt();
    let law = move |_t: f64, q: &UnitQuaternion<f64>, omega_b: &Vector3<f64>, _spins: &[f64]| {
        let theta = 2.0 * q.k.atan2(q.w);
        vec![-(k_p * (theta_t - theta) - k_d * omega_b.z)]
    };
    for form in Form::ALL {
        let body = BodySpec::principal(10.0, [3.0, 3.5, i_zz]).with_rotor(RotorSpec::new(
            [0.0, 0.0, 1.0],
            j,
            0.0,
        ));
        let scene = SceneSpec::new(body, 30.0, 0.5)
            .with_method(Method::Dop853)
            .with_tolerances(1e-12, 1e-14)
            .with_form(form)
            .build()
            .unwrap()
            .with_wheel_law("pd", law)
            .unwrap();
        for s in rows(&scene) {
            let t = s.t;
            let theta = 2.0 * s.q.k.atan2(s.q.w);
            let decay = (-zeta * wn * t).exp();
            let expected =
                theta_t * (1.0 - decay * ((wd * t).cos() + zeta * wn / wd * (wd * t).sin()));
            close(theta, expected, 1e-9, "θ");
            let r = RotorRows::of(&s).unwrap();
            assert_eq!(
                r.torque[0], r.torque_cmd[0],
                "no limit: applied = commanded"
            );
            assert!(s.h_o_s.norm() <= 1e-12, "H_s = 0");
        }
    }
}

#[test]
fn a_law_is_refused_beside_a_wheel_with_its_own_driver_and_with_a_wrong_count() {
    let body = |drive: RotorDrive| {
        BodySpec::principal(10.0, [1.0, 1.0, 1.0])
            .with_rotor(RotorSpec::new([0.0, 0.0, 1.0], 0.1, 0.0))
            .with_rotor(
                RotorSpec::new([1.0, 0.0, 0.0], 0.1, 0.0)
                    .with_name("x")
                    .with_drive(drive),
            )
    };
    let law = |_t: f64, _q: &UnitQuaternion<f64>, _w: &Vector3<f64>, _s: &[f64]| vec![0.0, 0.0];
    let scene = SceneSpec::new(body(RotorDrive::Free), 1.0, 0.5)
        .build()
        .unwrap();
    let e = scene.with_wheel_law("pd", law).unwrap_err();
    assert_eq!(e.key.to_string(), "body.rotor[1].mode", "{e}");
    assert!(e.problem.contains("`x`"), "names the wheel: {e}");
    let scene = SceneSpec::new(body(RotorDrive::ConstantSpin), 1.0, 0.5)
        .build()
        .unwrap();
    let one = |_t: f64, _q: &UnitQuaternion<f64>, _w: &Vector3<f64>, _s: &[f64]| vec![0.0];
    let e = scene.with_wheel_law("pd", one).unwrap_err();
    assert!(
        e.problem
            .contains("gives 1 torque(s), the body has 2 wheel(s)"),
        "{e}"
    );
}

const WHEEL_SCENE: &str = r#"name = "wheel"
[body]
mass = 10.0
inertia = [2.0, 3.0, 4.0]
[[body.rotor]]
name = "wx"
axis = [1.0, 0.0, 0.0]
inertia = 0.05
torque_table = "cmd.csv"
max_torque = 0.1
friction = { viscous = 1e-4 }
[solver]
t_end = 2.0
[output]
every = 0.5
"#;

#[test]
fn a_torque_table_drives_a_wheel_and_its_columns_are_written() {
    // A table at 1 N·m (with a byte-order mark and CRLF) clipped to 0.1 N·m: the command and the applied torque
    // are the table's and the limit's, and the friction column is −c Ω.
    let dir = tempfile::tempdir().unwrap();
    write_file(dir.path(), "cmd.csv", "\u{feff}t,torque\r\n0,1\r\n10,1\r\n");
    let scene = write_file(dir.path(), "scene.toml", WHEEL_SCENE);
    let out_csv = dir.path().join("out.csv");
    let out = eulerdyn([
        "run",
        scene.to_str().unwrap(),
        "-o",
        out_csv.to_str().unwrap(),
    ]);
    assert_eq!(out.code, Some(0), "{}", out.stderr);
    let text = std::fs::read_to_string(&out_csv).unwrap();
    let mut lines = text.lines();
    let header: Vec<&str> = lines.next().unwrap().split(',').collect();
    let tail = &header[header.len() - 5..];
    assert_eq!(
        tail,
        [
            "wx_spin",
            "wx_h",
            "wx_torque",
            "wx_torque_cmd",
            "wx_friction"
        ]
    );
    for line in lines {
        let v: Vec<f64> = line.split(',').map(|x| x.parse().unwrap()).collect();
        let n = v.len();
        assert_eq!((v[n - 3], v[n - 2]), (0.1, 1.0), "applied and commanded");
        close(v[n - 1], -1e-4 * v[n - 5], 1e-15, "τ_f = −c Ω");
    }
}

#[test]
fn bad_wheel_keys_are_refused_naming_the_key() {
    let with = |extra: &str| WHEEL_SCENE.replace("[solver]", &format!("{extra}\n[solver]"));
    // Without the table (not written beside the scene here), so that the second wheel is the one at fault.
    let untabled = |extra: &str| with(extra).replace("torque_table = \"cmd.csv\"", "torque = 1.0");
    let free = "[[body.rotor]]\naxis = [0.0, 1.0, 0.0]\ninertia = 0.05\nmode = \"free\"";
    let cases = [
        (
            "a negative torque limit",
            WHEEL_SCENE.replace("max_torque = 0.1", "max_torque = -0.1"),
            "body.rotor[0].max_torque",
        ),
        (
            "a negative speed limit",
            with("max_speed_rpm = -100.0"),
            "max_speed_rpm",
        ),
        (
            "an unknown friction key",
            WHEEL_SCENE.replace("viscous = 1e-4", "viscus = 1e-4"),
            "viscus",
        ),
        (
            "a negative Coulomb friction",
            WHEEL_SCENE.replace("viscous = 1e-4", "coulomb = -1e-3"),
            "body.rotor[0].friction.coulomb",
        ),
        (
            "a zero Stribeck speed",
            WHEEL_SCENE.replace(
                "viscous = 1e-4",
                "stribeck = { torque = 1e-3, speed = 0.0 }",
            ),
            "body.rotor[0].friction.stribeck.speed",
        ),
        (
            "free with spin_accel",
            untabled(&format!("{free}\nspin_accel = 1.0")),
            "body.rotor[1].mode",
        ),
        (
            "free with a torque limit",
            untabled(&format!("{free}\nmax_torque = 1.0")),
            "body.rotor[1].max_torque",
        ),
        (
            "a missing table",
            WHEEL_SCENE.replace("cmd.csv", "missing.csv"),
            "body.rotor[0].torque_table",
        ),
        (
            // Issue 57: the limit held a wheel that started beyond it there, silently.
            "an initial spin beyond the speed limit (200 rad/s, 1910 rpm, against 1000 rpm)",
            untabled(
                "[[body.rotor]]\naxis = [0.0, 1.0, 0.0]\ninertia = 0.05\nspin = 200.0\ntorque = 0.0\nmax_speed_rpm = 1000.0",
            ),
            "body.rotor[1].spin",
        ),
    ];
    assert_refused_writing_nothing(&cases);
}

#[test]
fn stribeck_friction_adds_its_breakaway_torque_at_low_speed() {
    // τ_f = −(c + s exp(−(Ω/Ω_s)²)) sign(Ω) − v Ω (Basilisk's reaction wheel friction model).
    let f = eulerdyn::wheels::Friction {
        coulomb: 1e-3,
        viscous: 1e-5,
        stribeck_torque: 2e-3,
        stribeck_speed: 0.5,
    };
    assert_eq!(f.torque(0.0), 0.0);
    close(
        f.torque(0.5),
        -(1e-3 + 2e-3 * (-1.0f64).exp()) - 0.5e-5,
        1e-15,
        "at Ω_s",
    );
    close(
        f.torque(-100.0),
        1e-3 + 1e-3,
        1e-15,
        "the Stribeck term has faded",
    );
    assert_eq!(f.breakaway(), 3e-3);
}

#[test]
fn wheel_keys_are_sweepable_and_the_plot_has_wheel_panels() {
    let dir = tempfile::tempdir().unwrap();
    write_file(dir.path(), "cmd.csv", "t,torque\n0,1\n10,1\n");
    let scene = write_file(dir.path(), "scene.toml", WHEEL_SCENE);
    let sweep = write_file(
        dir.path(),
        "sweep.toml",
        "scene = \"scene.toml\"\n[[vary]]\nkey = \"body.rotor.0.max_torque\"\nvalues = [0.02]\n\
         [[vary]]\nkey = \"body.rotor.0.friction.viscous\"\nvalues = [3e-3]\n",
    );
    let plan = eulerdyn::analysis::sweep::Sweep::load(&sweep).unwrap_or_else(|e| panic!("{e}"));
    let run = plan.scene(&plan.values(0)).unwrap();
    for s in rows(&run) {
        let r = RotorRows::of(&s).unwrap();
        assert_eq!(r.torque[0], 0.02, "the swept limit");
        assert_eq!(
            r.friction[0],
            -3e-3 * r.spin[0],
            "the swept friction, τ_f = −c Ω"
        );
    }
    let out_csv = dir.path().join("out.csv");
    let out = eulerdyn([
        "run",
        scene.to_str().unwrap(),
        "-o",
        out_csv.to_str().unwrap(),
    ]);
    assert_eq!(out.code, Some(0), "{}", out.stderr);
    let svg = dir.path().join("out.svg");
    let out = eulerdyn([
        "plot",
        out_csv.to_str().unwrap(),
        "-o",
        svg.to_str().unwrap(),
    ]);
    assert_eq!(out.code, Some(0), "{}", out.stderr);
    let text = std::fs::read_to_string(&svg).unwrap();
    for title in [
        "Wheel spins relative to the body",
        "Wheel axial momentum J (a·ω + Ω)",
        "Wheel torques: τ, τ_cmd, τ_f",
        "τ_cmd wx",
        "τ_f wx",
        "Wheel friction torques",
    ] {
        assert!(
            text.contains(title),
            "the default figure of a rotor run draws `{title}`"
        );
    }
    // `--panels all` is every panel the run has: the same figure as the default.
    let all = dir.path().join("all.svg");
    let out = eulerdyn([
        "plot",
        out_csv.to_str().unwrap(),
        "-o",
        all.to_str().unwrap(),
        "--panels",
        "all",
    ]);
    assert_eq!(out.code, Some(0), "{}", out.stderr);
    assert_eq!(std::fs::read_to_string(&all).unwrap(), text);
}

#[test]
fn the_sidecar_names_the_wheel_law_that_commanded_the_wheels() {
    let dir = tempfile::tempdir().unwrap();
    let body = || {
        BodySpec::principal(10.0, [3.0, 3.5, 4.0]).with_rotor(RotorSpec::new(
            [0.0, 0.0, 1.0],
            0.1,
            0.0,
        ))
    };
    let law = |_t: f64, _q: &UnitQuaternion<f64>, _w: &Vector3<f64>, _s: &[f64]| vec![0.01];
    let with_law = SceneSpec::new(body(), 1.0, 0.5)
        .build()
        .unwrap()
        .with_wheel_law("hold_then_turn", law)
        .unwrap();
    let without = SceneSpec::new(body(), 1.0, 0.5).build().unwrap();
    for (scene, name, expected) in [
        (&with_law, "law.csv", Some("hold_then_turn")),
        (&without, "plain.csv", None),
    ] {
        let out = dir.path().join(name);
        eulerdyn::output::write_run(scene, &out).unwrap();
        let sidecar =
            std::fs::read_to_string(eulerdyn::output::sidecar::sidecar_path(&out)).unwrap();
        let json: serde_json::Value = serde_json::from_str(&sidecar).unwrap();
        assert_eq!(json["scene"]["wheel_law"].as_str(), expected, "{name}");
    }
}

/// Issue 57: `check`'s equation line for a wheel scene is the gyrostat's (core/src/wheels/gyrostat.rs, Hughes §3.5),
/// with the wheels' momentum in H, in each form.
#[test]
fn check_states_the_gyrostat_equation_with_the_wheels_momentum() {
    let dir = tempfile::tempdir().unwrap();
    write_file(dir.path(), "cmd.csv", "t,torque\n0,1\n10,1\n");
    for (form, equation) in [
        (
            "body",
            "body axes: I*omega' + sum J Omega' a + omega x H = M, H = I*omega + sum J Omega a",
        ),
        (
            "space",
            "space axes: dH_s/dt = M_s, H = I*omega + sum J Omega a",
        ),
    ] {
        let text = WHEEL_SCENE.replace("[solver]\n", &format!("[solver]\nframe = \"{form}\"\n"));
        let scene = write_file(dir.path(), "scene.toml", &text);
        let out = eulerdyn(["check", scene.to_str().unwrap()]);
        assert_eq!(out.code, Some(0), "{}", out.stderr);
        let line = (out.stdout.lines())
            .find(|l| l.trim_start().starts_with("equation"))
            .unwrap_or_else(|| panic!("no equation line:\n{}", out.stdout));
        assert!(line.contains(equation), "{form}: {line}");
    }
}

/// Issue 57: the friction panel of a run whose wheels have no friction columns, and `all` beside other names, are
/// refused naming the panel (exit 2, nothing written); a held wheel's default figure has no friction panel.
#[test]
fn the_friction_panel_is_refused_where_the_run_has_no_friction_columns() {
    let dir = tempfile::tempdir().unwrap();
    let held = WHEEL_SCENE.replace(
        "torque_table = \"cmd.csv\"\nmax_torque = 0.1\nfriction = { viscous = 1e-4 }\n",
        "spin = 10.0\n",
    );
    let scene = write_file(dir.path(), "scene.toml", &held);
    let csv = dir.path().join("held.csv");
    let out = eulerdyn(["run", scene.to_str().unwrap(), "-o", csv.to_str().unwrap()]);
    assert_eq!(out.code, Some(0), "{}", out.stderr);
    let svg = dir.path().join("held.svg");
    let plot = |panels: &str| {
        eulerdyn([
            "plot",
            csv.to_str().unwrap(),
            "-o",
            svg.to_str().unwrap(),
            "--panels",
            panels,
        ])
    };
    for (panels, says) in [
        ("wheel_friction", "no wheel friction columns"),
        ("all,wheel_h", "stands alone"),
    ] {
        let out = plot(panels);
        assert_eq!(out.code, Some(2), "{panels}: {}", out.stderr);
        assert!(out.stderr.contains(says), "{panels}: {}", out.stderr);
        assert!(!svg.exists(), "{panels}: a figure was written");
    }
    let out = plot("all");
    assert_eq!(out.code, Some(0), "{}", out.stderr);
    let text = std::fs::read_to_string(&svg).unwrap();
    assert!(text.contains("Wheel motor torques τ") && !text.contains("Wheel friction torques"));
}

#[test]
fn explorer1_a_minor_axis_spinner_with_a_damper_ends_spinning_about_its_major_axis() {
    // scenarios/explorer1.toml: I = 2, 1.8, 1 (body axes principal, the wheel locked), spun about z (minor) with a
    // free wheel under viscous friction inside. No external moment: H_s is conserved (to the 1e-9 of the module
    // doc), the friction only dissipates (the energy never rises beyond that rounding), and the energy sink ends
    // at its least energy for the given |H|, T_min = |H|²/(2 I_max), spinning about the major axis x — the
    // major-axis rule (Hughes 1986, ch. 5; Explorer 1: Bracewell & Garriott, Nature 182, 760, 1958).
    let path = crate::common::repo_path("scenarios/explorer1.toml");
    for form in Form::ALL {
        let overrides = eulerdyn::scene::Overrides {
            form: Some(form),
            rtol: Some(1e-12),
            atol: Some(1e-14),
            ..Default::default()
        };
        let scene = eulerdyn::scene::load(&path, &overrides).unwrap_or_else(|e| panic!("{e}"));
        let samples = rows(&scene);
        let (first, last) = (&samples[0], samples.last().unwrap());
        let h = first.h_o_s.norm();
        let t_min = h * h / (2.0 * 2.0);
        assert!(
            first.energy > 1.9 * t_min,
            "it starts near the minor axis: {}",
            first.energy
        );
        let mut energy = first.energy;
        for s in &samples {
            assert!(
                (s.h_o_s - first.h_o_s).norm() <= 1e-9 * h,
                "H_s at t = {}",
                s.t
            );
            assert!(
                s.energy <= energy + 1e-9 * first.energy,
                "energy rose at t = {}",
                s.t
            );
            energy = s.energy;
        }
        // The last wobble about x decays exponentially; after 1000 s the energy is within 1e-6 of T_min (measured
        // 7.3e-8, both forms), ω lies along ±x (1 − |ω_x|/|ω| measured 2.6e-7) and |ω_x| is |H|/I_max (measured
        // 1.6e-7 below it): 1e-6 each, a decade above what is left of the wobble.
        assert!(
            (last.energy - t_min) / t_min <= 1e-6,
            "{} vs T_min {t_min}",
            last.energy
        );
        let along_x = last.omega_b.x.abs() / last.omega_b.norm();
        assert!(1.0 - along_x <= 1e-6, "ω = {:?}", last.omega_b);
        close(last.omega_b.x.abs(), h / 2.0, 1e-6, "|ω_x| = |H| / I_max");
    }
}
