//! Vehicles around rotors (`motion.carrier`'s `center`, `accel`, `accel_profile`): the axis point A accelerates
//! at a_A = a_v + Ω̇_c × r + Ω_c × (Ω_c × r), and the support carries m a_C − m g, against closed forms.
//!
//! - Load factor: a shaft on two bearings whose mass centre C sits at s along the axis from A, in a vehicle
//!   accelerating at a (no turn): F_sup = m (a − g), its part across the axis split by the lever rule about C,
//!   R_A⊥ = F⊥ (b − s)/(b − a), R_B⊥ = F⊥ (s − a)/(b − a), the thrust F·u on A (statics of a shaft on two supports;
//!   the bearing split of `motion::support`).
//! - A steady turn at Ω about a centre D at distance R: A moves on a circle and a_A = Ω² R toward D (the
//!   centripetal acceleration, Meriam & Kraige, *Engineering Mechanics: Dynamics*, art. 2/5); a rotor spinning at ω
//!   about the direction of flight u carries besides the gyroscopic couple C ω Ω (ẑ × u) (art. 7/10), as vertical
//!   forces ±C ω Ω/(b − a).
//! - A pendulum on a hinge in a vehicle accelerating at a (horizontal, across the hinge) with gravity g: in the
//!   vehicle C feels g − a (d'Alembert), so the pendulum hangs at θ = −atan(a/g) and swings about it as a pendulum of
//!   ω₀² = m |g − a| d / I_A, period 4 K(sin(θ₀/2))/ω₀ for the amplitude θ₀ (Landau & Lifshitz, *Mechanics*, §11,
//!   problem 1; I_A = I_C + m d², the parallel-axis theorem).

use eulerdyn::Form;
use eulerdyn::events::Occurrence;
use eulerdyn::exact::JacobiElliptic;
use eulerdyn::sample::Sample;
use eulerdyn::scene::Overrides;
use eulerdyn::simulate;
use nalgebra::Vector3;

use crate::common::{
    DISK_BEARINGS as BEARINGS, DISK_M as M, assert_close_1e9 as close,
    assert_refused_writing_nothing, disk_on_bearings, eulerdyn, repo_path, rows_of as rows,
    scene_from,
};
use crate::invariant_axis::assert_equilibrium;

const G: f64 = 9.81;
/// The axis point A from C along the axis (body z): C sits at s = −0.05 m on the axis from A.
const POINT_Z: f64 = 0.05;

/// The disk of [`disk_on_bearings`] (radius 0.3 m), its axis point 0.05 m from C along the axis, with gravity, in
/// the carrier `carrier` (a TOML inline table).
fn disk_in_vehicle(carrier: &str, form: Form) -> String {
    let point = format!("point = [0.0, 0.0, {POINT_Z}]\n");
    let gravity = "[[effect]]\ntype = \"gravity\"\n";
    disk_on_bearings("disk-in-vehicle", 0.3, carrier, (&point, gravity), form)
}

/// The gravity moment about A, ρ × m g (ρ = C from A), the effects' whole moment in these scenes.
fn weight_moment_s(s: &Sample) -> Vector3<f64> {
    (s.q * Vector3::new(0.0, 0.0, -POINT_Z)).cross(&Vector3::new(0.0, 0.0, -G * M))
}

/// The lever rule about C at s on the axis from A: F_sup = m (a_v − g) on bearings at a and b.
fn assert_lever_rule(rows: &[Sample], a_v: impl Fn(f64) -> Vector3<f64>) {
    let (a, b, s_c) = (BEARINGS.0, BEARINGS.1, -POINT_Z);
    for s in rows {
        let u = s.q * Vector3::z();
        let support = s.support.unwrap();
        let f = (a_v(s.t) - Vector3::new(0.0, 0.0, -G)) * M;
        close(&support.f_sup_s, &f, M * G, "F_sup", s.t);
        let (thrust, f_perp) = (u * f.dot(&u), f - u * f.dot(&u));
        let r = support.bearings.unwrap();
        let r_a = f_perp * ((b - s_c) / (b - a)) + thrust;
        close(&r.r_a_s, &r_a, M * G, "R_A", s.t);
        close(
            &r.r_b_s,
            &(f_perp * ((s_c - a) / (b - a))),
            M * G,
            "R_B",
            s.t,
        );
    }
    assert_equilibrium(rows, BEARINGS, |s| s.q * Vector3::z(), weight_moment_s);
}

#[test]
fn a_constant_load_factor_splits_m_a_minus_g_by_the_lever_rule() {
    // 2 g upward and 3 m/s² along the axis: F_sup = m (a − g), 3 g across the axis and a thrust on A.
    let accel = Vector3::new(3.0, 0.0, 2.0 * G);
    for form in Form::ALL {
        let carrier = format!(
            "{{ rate = [0.0, 0.0, 0.0], accel = [{}, {}, {}] }}",
            accel.x, accel.y, accel.z
        );
        let rows = rows(&disk_in_vehicle(&carrier, form));
        assert_eq!(rows.len(), 81);
        assert_lever_rule(&rows, |_| accel);
    }
}

#[test]
fn a_sine_heave_is_carried_by_the_lever_rule() {
    // A ship's heave: a_v = 4 sin(2π 0.5 t + 30°) ẑ m/s².
    let (amp, omega_f, phase) = (4.0, std::f64::consts::PI, 30f64.to_radians());
    for form in Form::ALL {
        let carrier = r#"{ rate = [0.0, 0.0, 0.0], accel = [0.0, 0.0, 4.0], accel_profile = "sine", freq_hz = 0.5, phase_deg = 30.0 }"#;
        let rows = rows(&disk_in_vehicle(carrier, form));
        assert_lever_rule(&rows, |t| {
            Vector3::z() * (amp * (omega_f * t + phase).sin())
        });
    }
}

/// The bundled turn's text in the form `form`.
fn turbine_turn(form: Form) -> String {
    let text = std::fs::read_to_string(repo_path("scenarios/turbine_turn_3g.toml")).unwrap();
    text.replace(
        "[solver]\n",
        &format!("[solver]\nframe = \"{}\"\n", form.name()),
    )
}

#[test]
fn the_turbine_in_a_3g_turn_carries_the_load_factor_and_the_gyroscopic_couple() {
    // scenarios/turbine_turn_3g.toml: m = 120 kg, C = ½ m r² = 5.4 kg·m², ω = 10 000 rpm, Ω = 0.2 rad/s about a
    // centre R = 693.67 m to the left, bearings at ∓0.45 m from C (= A).
    let (m, omega, yaw, radius) = (120.0, 10_000.0 * std::f64::consts::TAU / 60.0, 0.2, 693.67);
    let couple = 0.5 * m * 0.09 * omega * yaw;
    let mut by_form = Vec::new();
    for form in Form::ALL {
        let rows = rows(&turbine_turn(form));
        assert_eq!(rows.len(), 1601);
        for s in &rows {
            let u = Vector3::new((yaw * s.t).cos(), (yaw * s.t).sin(), 0.0);
            let toward_centre = Vector3::z().cross(&u);
            let support = s.support.unwrap();
            let f = (toward_centre * (yaw * yaw * radius) + Vector3::z() * G) * m;
            close(&support.f_sup_s, &f, 0.0, "F_sup", s.t);
            // 3 g along the apparent vertical: |a − g| = g √(1 + 8) to the numbers' 5 digits (693.67 m).
            assert!((support.f_sup_s.norm() / (m * G) - 3.0).abs() < 1e-5);
            close(&s.m_o_s, &(toward_centre * couple), 0.0, "M_s", s.t);
            let r = support.bearings.unwrap();
            let lift = Vector3::z() * (couple / 0.9);
            close(&r.r_a_s, &(f * 0.5 + lift), 0.0, "R_A", s.t);
            close(&r.r_b_s, &(f * 0.5 - lift), 0.0, "R_B", s.t);
        }
        assert_equilibrium(
            &rows,
            (-0.45, 0.45),
            |s| s.q * Vector3::z(),
            |_| Vector3::zeros(),
        );
        by_form.push(rows);
    }
    assert_forms_agree(&by_form);
}

/// Body and space forms give the same moment and bearing loads to 1e-9 of their scale.
fn assert_forms_agree(by_form: &[Vec<Sample>]) {
    for (b, s) in by_form[0].iter().zip(&by_form[1]) {
        let scale = b.m_o_s.norm() + b.support.unwrap().f_sup_s.norm();
        close(&b.m_o_s, &s.m_o_s, scale, "M_s, body vs space form", b.t);
        let (rb, rs) = (
            b.support.unwrap().bearings.unwrap(),
            s.support.unwrap().bearings.unwrap(),
        );
        close(&rb.r_a_s, &rs.r_a_s, scale, "R_A, body vs space form", b.t);
        close(&rb.r_b_s, &rs.r_b_s, scale, "R_B, body vs space form", b.t);
    }
}

#[test]
fn an_unbalanced_rotor_in_a_rolling_heaving_turning_vehicle_agrees_in_both_forms() {
    // C off the axis and off A: every term of a_A and ρ × m a_A in play; the forms agree and the bearings balance
    // F_sup and M_sup (ΣR = F_sup, r × R = M_sup⊥, M_sup = M − ρ × m g).
    let text = disk_in_vehicle(
        r#"{ rate = [0.1, 0.2, 0.3], profile = "sine", freq_hz = 0.5, center = [1.0, 2.0, 3.0], accel = [0.0, 0.0, 4.0], accel_profile = "sine" }"#,
        Form::Body,
    )
    .replace("point = [0.0, 0.0, 0.05]", "point = [0.02, 0.0, 0.05]");
    let by_form: Vec<Vec<Sample>> = (Form::ALL.iter())
        .map(|form| {
            rows(&text.replace("frame = \"body\"", &format!("frame = \"{}\"", form.name())))
        })
        .collect();
    assert!(by_form[0][3].f_s.is_some(), "C off the axis: F = m a_C");
    for rows in &by_form {
        let m_eff = |s: &Sample| {
            (s.q * Vector3::new(-0.02, 0.0, -POINT_Z)).cross(&Vector3::new(0.0, 0.0, -G * M))
        };
        assert_equilibrium(rows, BEARINGS, |s| s.q * Vector3::z(), m_eff);
        for s in rows {
            let f_sup = s.support.unwrap().f_sup_s;
            close(
                &(*s.f_s.unwrap() - Vector3::new(0.0, 0.0, -G * M)),
                &f_sup,
                0.0,
                "F − m g",
                s.t,
            );
        }
    }
    assert_forms_agree(&by_form);
}

/// A ball (radius 0.05 m, 2 kg) hanging 0.3 m below a hinge along body x = space x, in a vehicle accelerating at
/// `accel` m/s² along space y, released from rest at θ = 0 (C straight below A).
fn pendulum_in_vehicle(accel: f64, form: Form, crossing: f64) -> String {
    format!(
        r#"name = "pendulum-in-vehicle"
[body]
mass = {M}
shape = {{ type = "sphere", radius = 0.05 }}
[motion]
type = "hinge"
axis = [1.0, 0.0, 0.0]
point = [0.0, 0.0, 0.3]
bearings = [-0.05, 0.05]
carrier = {{ rate = [0.0, 0.0, 0.0], accel = [0.0, {accel}, 0.0] }}
[[effect]]
type = "gravity"
[solver]
method = "dop853"
frame = "{}"
t_end = 10.0
rtol = 1e-12
atol = 1e-14
[output]
every = 0.05
[[event]]
name = "up"
when = "theta"
crosses = {crossing}
direction = "up"
"#,
        form.name()
    )
}

#[test]
fn a_pendulum_in_an_accelerating_vehicle_swings_about_atan_a_over_g() {
    let (accel, d) = (6.0, 0.3);
    let theta_eq = -(accel / G).atan();
    let i_a = 0.4 * M * 0.05 * 0.05 + M * d * d;
    let omega0 = (M * accel.hypot(G) * d / i_a).sqrt();
    let amplitude = -theta_eq;
    let k = (0.5 * amplitude).sin();
    let period = 4.0 * JacobiElliptic::new(k * k).unwrap().quarter_period() / omega0;
    let mut theta_by_form = Vec::new();
    for form in Form::ALL {
        let scene = scene_from(
            &pendulum_in_vehicle(accel, form, theta_eq),
            &Overrides::default(),
        );
        let mut rows: Vec<Sample> = Vec::new();
        let (_, events) = simulate::run_with_events(&scene, |s| {
            rows.push(*s);
            Ok::<(), std::convert::Infallible>(())
        })
        .unwrap();
        assert!(events.len() >= 4, "{form:?}: {} crossings", events.len());
        let worst = (events.windows(2))
            .map(|w: &[Occurrence]| (w[1].t - w[0].t - period).abs())
            .fold(0.0, f64::max);
        // dop853 at rtol 1e-12 and the event's root to round-off: 1e-9 of the period.
        assert!(
            worst <= 1e-9 * period,
            "{form:?}: period off by {worst:e} s of {period} s"
        );
        for s in &rows {
            let theta = s.theta.unwrap();
            // It swings symmetrically about θ_eq: within [2 θ_eq, 0] (to the integration's 1e-9).
            assert!(
                theta <= 1e-9 && theta >= 2.0 * theta_eq - 1e-9,
                "t = {}: θ = {theta}",
                s.t
            );
            assert!(s.support.unwrap().m_drive.abs() <= 1e-12 * (s.m_o_s.norm() + M * G * d));
        }
        let weight =
            |s: &Sample| (s.q * Vector3::new(0.0, 0.0, -d)).cross(&Vector3::new(0.0, 0.0, -G * M));
        assert_equilibrium(&rows, (-0.05, 0.05), |s| s.q * Vector3::x(), weight);
        theta_by_form.push(rows);
    }
    for (b, s) in theta_by_form[0].iter().zip(&theta_by_form[1]) {
        assert!(
            (b.theta.unwrap() - s.theta.unwrap()).abs() <= 1e-9,
            "t = {}: the forms agree",
            b.t
        );
    }
}

#[test]
fn bad_vehicles_are_refused_naming_the_key() {
    let disk = |carrier: &str| disk_in_vehicle(carrier, Form::Body);
    let free = |carrier: &str| {
        format!(
            r#"[body]
mass = 1.0
shape = {{ type = "sphere", radius = 0.1 }}
[motion]
type = "free"
carrier = {carrier}
[solver]
t_end = 1.0
[output]
every = 0.1
"#
        )
    };
    let cases = [
        (
            "accel of two numbers",
            disk("{ rate = [0.0, 0.0, 1.0], accel = [0.0, 1.0] }"),
            "accel",
        ),
        (
            "center of four numbers",
            disk("{ rate = [0.0, 0.0, 1.0], center = [0.0, 1.0, 2.0, 3.0] }"),
            "center",
        ),
        (
            "unknown accel_profile",
            disk(r#"{ rate = [0.0, 0.0, 1.0], accel = [0.0, 0.0, 1.0], accel_profile = "step" }"#),
            "accel_profile",
        ),
        (
            "a step rate profile",
            disk(r#"{ rate = [0.0, 0.0, 1.0], profile = "step" }"#),
            "carrier.profile",
        ),
        (
            "accel_profile without accel",
            disk(r#"{ rate = [0.0, 0.0, 1.0], accel_profile = "constant" }"#),
            "accel_profile",
        ),
        (
            "a sine accel without freq_hz",
            disk(r#"{ rate = [0.0, 0.0, 1.0], accel = [0.0, 0.0, 1.0], accel_profile = "sine" }"#),
            "freq_hz",
        ),
        (
            "a non-finite accel",
            disk("{ rate = [0.0, 0.0, 1.0], accel = [0.0, 0.0, inf] }"),
            "accel",
        ),
        (
            "center on free motion",
            free("{ rate = [0.0, 0.0, 1.0], center = [0.0, 1.0, 0.0] }"),
            "carrier.center",
        ),
        (
            "accel on free motion",
            free("{ rate = [0.0, 0.0, 1.0], accel = [0.0, 0.0, 1.0] }"),
            "carrier.accel",
        ),
    ];
    assert_refused_writing_nothing(&cases);
}

/// FNV-1a, 64 bits (Fowler, Noll, Vo): a fingerprint of a file's bytes.
fn fnv1a(bytes: &[u8]) -> u64 {
    (bytes.iter()).fold(0xcbf2_9ce4_8422_2325, |h, b| {
        (h ^ u64::from(*b)).wrapping_mul(0x0000_0100_0000_01b3)
    })
}

#[test]
fn the_carrier_scene_without_a_vehicle_writes_the_csv_it_wrote_before() {
    // The fingerprint of scenarios/turbine_yawing_aircraft.toml's CSV as main wrote it (83964dc), before vehicles.
    let dir = tempfile::tempdir().unwrap();
    let csv = dir.path().join("turbine.csv");
    let scene = repo_path("scenarios/turbine_yawing_aircraft.toml");
    eulerdyn(["run", scene.to_str().unwrap(), "-o", csv.to_str().unwrap()]).expect_code(0);
    let bytes = std::fs::read(&csv).unwrap();
    assert_eq!((bytes.len(), fnv1a(&bytes)), MAIN_TURBINE_CSV);
}

/// (length, FNV-1a) of the turbine's CSV from main at 83964dc.
const MAIN_TURBINE_CSV: (usize, u64) = (1_511_367, 0x282b_0258_9aea_6b3a);

#[test]
fn check_and_the_sidecar_describe_the_vehicle() {
    let scene = repo_path("scenarios/turbine_turn_3g.toml");
    let check = eulerdyn(["check", scene.to_str().unwrap()]);
    check.expect_code(0);
    assert!(
        check.stdout.contains("vehicle") && check.stdout.contains("693.67"),
        "{}",
        check.stdout
    );
    let dir = tempfile::tempdir().unwrap();
    let csv = dir.path().join("turn.csv");
    eulerdyn(["run", scene.to_str().unwrap(), "-o", csv.to_str().unwrap()]).expect_code(0);
    let meta = std::fs::read_to_string(dir.path().join("turn.csv.meta.json")).unwrap();
    let json: serde_json::Value = serde_json::from_str(&meta).unwrap();
    let carrier = &json["scene"]["spec"]["motion"]["carrier"];
    assert_eq!(
        carrier["center"],
        serde_json::json!([0.0, 693.67, 0.0]),
        "{meta}"
    );
}
