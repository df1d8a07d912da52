//! Rotors inside the body (gyrostats), against closed forms. H = I ω + Σ J_k Ω_k a_k with I the body with its
//! wheels locked; I ω̇ + Σ J_k Ω̇_k a_k = M − ω × H; J_k (a_k·ω̇ + Ω̇_k) = τ_k (Hughes, *Spacecraft Attitude
//! Dynamics*, 1986, the gyrostat's equations of motion; core/src/wheels/gyrostat.rs). Each closed form below follows from
//! these in a line, written beside it. Tolerances: dop853 at rtol 1e-12 reaches 1e-11 relative on these smooth,
//! slow motions; the issue's criterion 1e-9 is asserted.

use crate::common::{assert_refused_writing_nothing, eulerdyn, write_file};
use eulerdyn::profile::Profile;
use eulerdyn::sample::Sample;
use eulerdyn::scene::{BodySpec, EffectSpec, RotorDrive, RotorSpec, SceneSpec};
use eulerdyn::wheels::RotorRows;
use eulerdyn::{Form, Method, simulate};

fn rows(spec: &SceneSpec) -> Vec<Sample> {
    let scene = spec.build().unwrap_or_else(|e| panic!("{e}"));
    simulate::samples(&scene)
        .unwrap_or_else(|e| panic!("{e}"))
        .0
}

fn tight(spec: SceneSpec, form: Form) -> SceneSpec {
    spec.with_method(Method::Dop853)
        .with_tolerances(1e-12, 1e-14)
        .with_form(form)
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

#[test]
fn a_motor_torque_exchanges_momentum_between_wheel_and_body() {
    // A body at rest, a wheel along x spun up by a constant motor torque τ: H_s = 0 throughout (no external
    // moment), so I_xx ω_x + J Ω = 0, and the wheel's equation J (ω̇_x + Ω̇) = τ gives
    // ω_x = −τ t / (I_xx − J), Ω = τ t I_xx / (J (I_xx − J)).
    let (i_xx, j, tau) = (2.0, 0.05, 0.1);
    let wheel = RotorSpec::new([1.0, 0.0, 0.0], j, 0.0).with_drive(motor(tau));
    for form in Form::ALL {
        let body = BodySpec::principal(10.0, [i_xx, 3.0, 4.0]).with_rotor(wheel.clone());
        for s in rows(&tight(SceneSpec::new(body, 10.0, 0.5), form)) {
            let t = s.t;
            close(s.omega_b.x, -tau * t / (i_xx - j), 1e-9, "ω_x");
            assert!(s.omega_b.yz().norm() <= 1e-15, "ω stays on x");
            let r = RotorRows::of(&s).expect("rotor columns");
            close(r.spin[0], tau * t * i_xx / (j * (i_xx - j)), 1e-9, "Ω");
            close(
                r.h[0],
                tau * t,
                1e-9,
                "the wheel's momentum J(ω_x + Ω) = τ t",
            );
            close(r.torque[0], tau, 0.0, "τ");
            assert!(
                s.h_o_s.norm() <= 1e-12,
                "{form:?}: H_s = {} at t = {t}",
                s.h_o_s
            );
        }
    }
}

#[test]
fn a_prescribed_spin_up_reports_the_motor_torque_it_takes() {
    // Ω = α t prescribed, body at rest: H_s = 0 gives ω_x = −J α t / I_xx, so ω̇_x = −J α / I_xx and the motor
    // torque is τ = J (ω̇_x + α) = J α (I_xx − J) / I_xx.
    let (i_xx, j, alpha) = (2.0, 0.05, 3.0);
    let wheel = RotorSpec::new([1.0, 0.0, 0.0], j, 0.0).with_drive(RotorDrive::SpinAccel(alpha));
    for form in Form::ALL {
        let body = BodySpec::principal(10.0, [i_xx, 3.0, 4.0]).with_rotor(wheel.clone());
        for s in rows(&tight(SceneSpec::new(body, 5.0, 0.5), form)) {
            close(s.omega_b.x, -j * alpha * s.t / i_xx, 1e-9, "ω_x");
            let r = RotorRows::of(&s).unwrap();
            close(r.spin[0], alpha * s.t, 1e-9, "Ω");
            close(r.torque[0], j * alpha * (i_xx - j) / i_xx, 1e-9, "τ");
        }
    }
}

#[test]
fn the_torque_free_symmetric_gyrostat_turns_its_transverse_rate_at_lambda() {
    // A = I₁ = I₂, C = I₃, a wheel on the symmetry axis with h = J Ω constant: Euler's equation gives ω₃ constant and
    // ω̇₁ = −λ ω₂, ω̇₂ = λ ω₁ with λ = ((C − A) ω₃ + h) / A (the axisymmetric gyrostat, Hughes 1986), so from
    // ω(0) = (w, 0, ω₃): ω₁ = w cos λt, ω₂ = w sin λt.
    let (a, c, j, spin) = (2.0, 3.0, 0.1, 20.0);
    let (w, w3) = (0.3, 1.5);
    let lambda = ((c - a) * w3 + j * spin) / a;
    let wheel = RotorSpec::new([0.0, 0.0, 1.0], j, spin);
    for form in Form::ALL {
        let body = BodySpec::principal(5.0, [a, a, c]).with_rotor(wheel.clone());
        let spec = tight(
            SceneSpec::new(body, 20.0, 0.25).with_omega([w, 0.0, w3]),
            form,
        );
        for s in rows(&spec) {
            let t = s.t;
            close(s.omega_b.x, w * (lambda * t).cos(), 1e-9, "ω₁");
            close(s.omega_b.y, w * (lambda * t).sin(), 1e-9, "ω₂");
            close(s.omega_b.z, w3, 1e-9, "ω₃");
        }
    }
}

/// Kelvin's gyrostat: the body (1, 2, 3) spinning at ω₀ about its intermediate axis y, perturbed by `dw` about x,
/// with a wheel of momentum `h` along y. Returns the rows.
fn kelvin(h: f64, dw: f64, form: Form) -> Vec<Sample> {
    let j = 0.1;
    let mut body = BodySpec::principal(5.0, [1.0, 2.0, 3.0]);
    if h != 0.0 {
        body = body.with_rotor(RotorSpec::new([0.0, 1.0, 0.0], j, h / j));
    }
    rows(&tight(
        SceneSpec::new(body, 40.0, 0.01).with_omega([dw, 1.0, 0.0]),
        form,
    ))
}

#[test]
fn kelvins_gyrostat_holds_the_intermediate_axis_that_the_bare_body_flips_from() {
    // Linearised about ω = (0, ω₀, 0), H = (I₁ω₁, I₂ω₀ + h, I₃ω₃): I₁ ω̇₁ = ((I₂ − I₃)ω₀ + h) ω₃ and
    // I₃ ω̇₃ = −((I₂ − I₁)ω₀ + h) ω₁, so ω̈₁ = −((I₂ − I₃)ω₀ + h)((I₂ − I₁)ω₀ + h)/(I₁ I₃) ω₁ — Kelvin's gyrostat
    // (Hughes 1986, stability of gyrostats): stable when the product is > 0. Here I = (1, 2, 3), ω₀ = 1: with h = 0 the product is −1 (the Dzhanibekov
    // flip), with h = 2 it is (−1 + 2)(1 + 2) = 3, an oscillation at √(3/3) = 1 rad/s.
    for form in Form::ALL {
        let bare = kelvin(0.0, 1e-6, form);
        let flipped = bare.iter().any(|s| s.omega_b.y < 0.0);
        assert!(flipped, "{form:?}: the bare body flips within 40 s");
        let held = kelvin(2.0, 1e-6, form);
        let largest = held.iter().map(|s| s.omega_b.x.abs()).fold(0.0, f64::max);
        assert!(
            largest < 2e-6,
            "{form:?}: with the wheel ω_x stays at the perturbation's size, got {largest:e}"
        );
        // The frequency from the zero crossings of ω_x (rows every 0.01 s, crossings interpolated linearly: a
        // crossing time to ~1e-5 s, averaged over ~12 half periods).
        let crossings: Vec<f64> = held
            .windows(2)
            .filter(|w| w[0].omega_b.x.signum() != w[1].omega_b.x.signum())
            .map(|w| {
                let (a, b) = (w[0].omega_b.x, w[1].omega_b.x);
                w[0].t + (w[1].t - w[0].t) * a / (a - b)
            })
            .collect();
        let half_periods = (crossings.len() - 1) as f64;
        let frequency =
            std::f64::consts::PI * half_periods / (crossings.last().unwrap() - crossings[0]);
        close(frequency, 1.0, 1e-3, "Kelvin's frequency");
    }
}

#[test]
fn free_wheels_keep_h_s_and_the_energy_and_both_forms_agree() {
    // Nothing acts (no effect, every motor torque zero): H_s and T = ½ ωᵀIω + Σ (J Ω (a·ω) + ½ J Ω²) are conserved.
    let wheels = [
        RotorSpec::new([1.0, 0.0, 0.0], 0.05, 30.0).with_drive(motor(0.0)),
        RotorSpec::new([0.0, 0.6, 0.8], 0.02, -50.0).with_drive(motor(0.0)),
    ];
    let body = wheels
        .into_iter()
        .fold(BodySpec::principal(5.0, [1.0, 2.0, 3.0]), |b, w| {
            b.with_rotor(w)
        });
    let spec = SceneSpec::new(body, 30.0, 0.5).with_omega([0.4, -0.2, 0.9]);
    let by_form: Vec<Vec<Sample>> = Form::ALL
        .iter()
        .map(|&form| rows(&tight(spec.clone(), form)))
        .collect();
    for rows in &by_form {
        let (h0, e0) = (rows[0].h_o_s, rows[0].energy);
        for s in rows {
            assert!(
                (s.h_o_s - h0).norm() <= 1e-9 * h0.norm(),
                "H_s at t = {}",
                s.t
            );
            close(s.energy, e0, 1e-9, "T");
        }
    }
    for (b, s) in by_form[0].iter().zip(&by_form[1]) {
        assert!(
            (b.omega_b - s.omega_b).norm() <= 1e-9 * b.omega_b.norm(),
            "the forms agree at t = {}",
            b.t
        );
    }
}

#[test]
fn about_a_pivot_free_wheels_keep_t_plus_v_and_the_vertical_momentum() {
    // A top with a free wheel on its symmetry axis, about a pivot under vertical gravity: the moment r_C × m g is
    // horizontal, so H_s,z is conserved, and T + V is (no motor work).
    let wheel = RotorSpec::new([0.0, 0.0, 1.0], 0.01, 100.0).with_drive(motor(0.0));
    let body = BodySpec::principal(1.0, [0.02, 0.02, 0.03]).with_rotor(wheel);
    let spec = SceneSpec::new(body, 5.0, 0.05)
        .with_omega([0.5, 0.0, 10.0])
        .with_attitude([0.9659258262890683, 0.25881904510252074, 0.0, 0.0])
        .with_effect(EffectSpec::gravity([0.0, 0.0, -9.81], [0.0, 0.0, -0.05]));
    for form in Form::ALL {
        let rows = rows(&tight(spec.clone(), form));
        let (hz0, e0) = (rows[0].h_o_s.z, rows[0].energy + rows[0].potential.unwrap());
        for s in &rows {
            close(s.h_o_s.z, hz0, 1e-9, "H_s,z");
            close(s.energy + s.potential.unwrap(), e0, 1e-9, "T + V");
        }
    }
}

#[test]
fn rotor_columns_follow_all_others_and_the_sidecar_keeps_the_rotors() {
    let dir = tempfile::tempdir().unwrap();
    let scene = write_file(dir.path(), "sat.toml", ROTOR_SCENE);
    let csv = dir.path().join("sat.csv");
    let out = eulerdyn(["run", scene.to_str().unwrap(), "-o", csv.to_str().unwrap()]);
    out.expect_code(0);
    let text = std::fs::read_to_string(&csv).unwrap();
    let head: Vec<&str> = text.lines().next().unwrap().split(',').collect();
    assert_eq!(
        head[head.len() - 6..],
        [
            "wheel_x_spin",
            "wheel_x_h",
            "wheel_x_torque",
            "rotor1_spin",
            "rotor1_h",
            "rotor1_torque"
        ]
    );
    let sidecar = eulerdyn::output::Sidecar::read(&csv).unwrap();
    assert_eq!(sidecar.scene.spec.body.rotor.len(), 2);
    assert_eq!(sidecar.scene.spec.build().unwrap().spec, sidecar.scene.spec);
}

const ROTOR_SCENE: &str = r#"name = "two wheels"
[body]
mass = 10.0
inertia = [2.0, 3.0, 4.0]
[[body.rotor]]
name = "wheel_x"
axis = [1.0, 0.0, 0.0]
inertia = 0.05
spin = 10.0
torque = 0.1
profile = "step"
t_on = 0.5
t_off = 1.0
[[body.rotor]]
axis = [0.0, 0.0, 2.0]
inertia = 0.02
spin_accel = 1.0
[initial]
omega = [0.0, 0.1, 0.0]
[solver]
t_end = 2.0
[output]
every = 0.5
"#;

#[test]
fn compare_knows_the_symmetric_gyrostat() {
    // A = I₁ = I₂ = 2, C = 3, a wheel on z with h = J Ω = 2 N·m·s: the closed form (transverse ω turning at
    // λ = ((C − A)ω₃ + h)/A, attitude Rot(Ĥ_s, |H| t/A) q₀ Rot(z, −λ t); Hughes §3.5) against both forms, in ω,
    // the attitude, H_s and T, to the issue's 1e-9.
    let wheel = RotorSpec::new([0.0, 0.0, 1.0], 0.05, 40.0);
    let body = BodySpec::principal(10.0, [2.0, 2.0, 3.0]).with_rotor(wheel);
    let spec = tight(SceneSpec::new(body, 20.0, 0.1), Form::Body).with_omega([0.3, -0.1, 1.0]);
    let scene = spec.build().unwrap();
    let comparison = eulerdyn::analysis::compare::compare(&scene).unwrap_or_else(|e| panic!("{e}"));
    let (name, body_form, space_form) = comparison.exact.as_ref().expect("a closed form applies");
    assert!(name.contains("symmetric gyrostat"), "{name}");
    for row in comparison.table() {
        for exact in [row.body_vs_exact, row.space_vs_exact]
            .into_iter()
            .flatten()
        {
            assert!(
                exact <= 1e-9,
                "{}: {exact:e} from the closed form",
                row.quantity
            );
        }
    }
    assert!(body_form.worst() <= 1e-9 && space_form.worst() <= 1e-9);
    let quantities: Vec<&str> = comparison.table().iter().map(|r| r.quantity).collect();
    for wanted in ["omega", "H_s", "energy"] {
        assert!(quantities.contains(&wanted), "{quantities:?}");
    }
    // An imbalanced or off-axis wheel has no such closed form: compare runs the forms against each other only.
    let tilted = RotorSpec::new([0.0, 0.6, 0.8], 0.05, 40.0);
    let body = BodySpec::principal(10.0, [2.0, 2.0, 3.0]).with_rotor(tilted);
    let scene = (SceneSpec::new(body, 1.0, 0.1).with_omega([0.3, -0.1, 1.0]))
        .build()
        .unwrap();
    assert!(
        eulerdyn::analysis::compare::compare(&scene)
            .unwrap()
            .exact
            .is_none()
    );
}

#[test]
fn an_imbalanced_wheel_turns_its_force_and_couple_with_it() {
    // A wheel on body z at r = (0.1, 0, 0) from C, static imbalance U_s = 2 g·mm, dynamic U_d = 50 g·mm², its
    // relative spin Ω(t) = Ω₀ + α t, so its angle is φ = Ω₀ t + ½ α t². The simple jitter model (Alcorn, Allard &
    // Schaub, JGCD 41(6), 2018; Basilisk's reaction-wheel effector) puts the force F = U_s Ω² d and the couple
    // L = U_d Ω² d on the body, d = cos φ x + sin φ y turning with the wheel (w2 = x, the body axis least aligned
    // with z), so M_b = r × F + L: its in-plane part is U_d Ω² d, its z part 0.1 U_s Ω² sin φ — the force m e Ω².
    let (u_s, u_d, r) = (2.0e-6, 50.0e-9, 0.1);
    for (spin0, alpha) in [(600.0, 0.0), (300.0, 100.0)] {
        let drive = RotorDrive::SpinAccel(alpha);
        let wheel = (RotorSpec::new([0.0, 0.0, 1.0], 0.01, spin0).with_drive(drive))
            .with_imbalance([r, 0.0, 0.0], 2.0, 50.0);
        let mut by_form = Vec::new();
        for form in Form::ALL {
            let body = BodySpec::principal(50.0, [5.0, 6.0, 7.0]).with_rotor(wheel.clone());
            let spec = tight(SceneSpec::new(body, 1.0, 0.01), form);
            let rows = rows(&spec);
            for s in &rows {
                let (spin, phi) = (spin0 + alpha * s.t, spin0 * s.t + 0.5 * alpha * s.t * s.t);
                let scale = u_s * spin * spin;
                let d = nalgebra::Vector3::new(phi.cos(), phi.sin(), 0.0);
                let expected =
                    nalgebra::Vector3::z() * (r * scale * phi.sin()) + d * (u_d * spin * spin);
                assert!(
                    (*s.m_o_b - expected).norm() <= 1e-9 * expected.norm().max(r * scale),
                    "Ω₀ = {spin0}, α = {alpha}, t = {}: M_b = {} vs {expected}",
                    s.t,
                    s.m_o_b
                );
                close(RotorRows::of(s).unwrap().spin[0], spin, 1e-12, "Ω");
            }
            by_form.push(rows);
        }
        for (b, s) in by_form[0].iter().zip(&by_form[1]) {
            assert!(
                (b.omega_b - s.omega_b).norm() <= 1e-9 * b.omega_b.norm().max(1e-9),
                "the forms agree at t = {}",
                b.t
            );
        }
    }
}

#[test]
fn bad_rotors_are_refused_with_the_file_and_key_and_nothing_is_written() {
    let wheel = "[[body.rotor]]\naxis = [1.0, 0.0, 0.0]\ninertia = 0.05\n";
    let with = |extra: &str| ROTOR_SCENE.replace("[initial]", &format!("{extra}\n[initial]"));
    let cases = [
        (
            "zero inertia",
            ROTOR_SCENE.replace("inertia = 0.05", "inertia = 0.0"),
            "body.rotor[0].inertia",
        ),
        (
            "zero axis",
            ROTOR_SCENE.replace("[1.0, 0.0, 0.0]", "[0.0, 0.0, 0.0]"),
            "body.rotor[0].axis",
        ),
        (
            "both drives",
            ROTOR_SCENE.replace("spin_accel = 1.0", "spin_accel = 1.0\ntorque = 0.1"),
            "body.rotor[1].torque",
        ),
        (
            "duplicate names",
            with(&format!("{wheel}name = \"wheel_x\"")),
            "body.rotor[2].name",
        ),
        (
            "a bad name",
            ROTOR_SCENE.replace("\"wheel_x\"", "\"wheel x\""),
            "body.rotor[0].name",
        ),
        (
            "an unknown profile",
            ROTOR_SCENE.replace("\"step\"", "\"ramp\""),
            "profile",
        ),
        (
            "a profile without torque",
            ROTOR_SCENE.replace("spin_accel = 1.0", "spin_accel = 1.0\nfreq_hz = 1.0"),
            "body.rotor[1].freq_hz",
        ),
        (
            "too many rotors",
            with(&[wheel; 3].concat()),
            "body.rotor[4]",
        ),
        (
            "a negative static imbalance",
            with(&format!("{wheel}imbalance_static_gmm = -3.0")),
            "body.rotor[2].imbalance_static_gmm",
        ),
        (
            "a dynamic imbalance that is not a number",
            with(&format!("{wheel}imbalance_dynamic_gmm2 = nan")),
            "body.rotor[2].imbalance_dynamic_gmm2",
        ),
        (
            "a wheel bigger than the body",
            ROTOR_SCENE.replace("inertia = 0.05", "inertia = 2.5"),
            "body.rotor",
        ),
        (
            "a splitting method",
            ROTOR_SCENE.replace("t_end = 2.0", "t_end = 2.0\nmethod = \"split2\""),
            "solver.method",
        ),
        (
            "exact",
            ROTOR_SCENE.replace("t_end = 2.0", "t_end = 2.0\nmethod = \"exact\""),
            "solver.method",
        ),
        (
            "a fixed axis",
            ROTOR_SCENE.replace(
                "[initial]\nomega = [0.0, 0.1, 0.0]",
                "[motion]\ntype = \"fixed_axis\"\naxis = [0.0, 0.0, 1.0]",
            ),
            "body.rotor",
        ),
    ];
    assert_refused_writing_nothing(&cases);
}

#[test]
fn a_body_without_rotors_writes_no_rotor_columns() {
    let spec = SceneSpec::new(BodySpec::principal(1.0, [1.0, 2.0, 3.0]), 1.0, 0.5)
        .with_omega([0.1, 0.2, 0.3]);
    let scene = spec.build().unwrap();
    assert!(scene.facts().columns().groups.is_empty());
    assert!(rows(&spec).iter().all(|s| RotorRows::of(s).is_none()));
}
