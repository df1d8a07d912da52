//! Bearings in a moving carrier (`motion.carrier`): ω = Ω_c + θ̇ u, against closed forms.
//!
//! - A disk (polar moment C, transverse A) spinning at ω about an axis perpendicular to a carrier's constant yaw
//!   rate Ω: H = C ω u + A Ω ẑ turns with u, so the bearings carry the gyroscopic couple M = C ω Ω (ẑ × u) —
//!   Meriam & Kraige, *Engineering Mechanics: Dynamics*, art. 7/10 (steady precession with the spin axis normal to
//!   the precession axis, M = I Ω p) — as forces ±C ω Ω/(b − a) (the bearing split, statics of a shaft on two
//!   supports).
//! - The same disk in a rolling carrier, Ω_c = r sin(ω_f t), r ⊥ u: H = C ω u + A Ω_c, so
//!   M = C ω Ω_c × u + A Ω̇_c (the derivative of H with u̇ = Ω_c × u).
//! - A free hinge (no drive about u) perpendicular to a constant carrier rate Ω ẑ, principal moments A (about u), B,
//!   C: Euler's equation about u (the notes' eq. 8.9 projected on the axis) gives A θ̈ = −½ (C − B) Ω² sin 2θ, a
//!   pendulum in φ = 2θ with ω₀² = (C − B) Ω²/A, so θ's period is 4 K(sin θ₀)/ω₀ (Landau & Lifshitz, *Mechanics*,
//!   §11, problem 1), and the Jacobi integral ½ A θ̇² − ½ Ω² (B sin²θ + C cos²θ) is constant.

use eulerdyn::Form;
use eulerdyn::events::Occurrence;
use eulerdyn::exact::JacobiElliptic;
use eulerdyn::sample::Sample;
use eulerdyn::scene::Overrides;
use eulerdyn::simulate;
use nalgebra::Vector3;

use crate::common::{
    DISK_BEARINGS as BEARINGS, DISK_M as M, DISK_SPIN as SPIN, assert_close_1e9 as close,
    assert_refused_writing_nothing, disk_on_bearings, eulerdyn, rows_of as rows, scene_from,
};
use crate::invariant_axis::assert_equilibrium;

const R: f64 = 0.3;

/// The disk of [`disk_on_bearings`] (radius `R`) in the carrier `carrier`.
fn disk_in_carrier(carrier: &str, form: Form) -> String {
    disk_on_bearings("disk-in-carrier", R, carrier, ("", ""), form)
}

/// The disk's axis (body z) in space.
fn disk_axis_s(s: &Sample) -> Vector3<f64> {
    s.q * Vector3::z()
}

/// The box's hinge axis (body x) in space.
fn box_axis_s(s: &Sample) -> Vector3<f64> {
    s.q * Vector3::x()
}

#[test]
fn a_disk_in_a_yawing_carrier_carries_the_gyroscopic_couple() {
    let yaw = 0.5;
    let (c, a) = (0.5 * M * R * R, 0.25 * M * R * R);
    let couple = c * SPIN * yaw;
    for form in Form::ALL {
        let rows = rows(&disk_in_carrier(
            &format!("{{ rate = [0.0, 0.0, {yaw}] }}"),
            form,
        ));
        assert_eq!(rows.len(), 81);
        for s in &rows {
            let u = Vector3::new((yaw * s.t).cos(), (yaw * s.t).sin(), 0.0);
            let support = s.support.unwrap();
            close(
                &support.omega_c_s.unwrap(),
                &Vector3::new(0.0, 0.0, yaw),
                0.0,
                "Ω_c",
                s.t,
            );
            close(
                &s.omega_s,
                &(Vector3::z() * yaw + u * SPIN),
                0.0,
                "ω_s",
                s.t,
            );
            close(
                &s.h_o_s,
                &(u * (c * SPIN) + Vector3::z() * (a * yaw)),
                0.0,
                "H_s",
                s.t,
            );
            close(
                &s.m_o_s,
                &(Vector3::z().cross(&u) * couple),
                0.0,
                "M_s",
                s.t,
            );
            let bearings = support.bearings.unwrap();
            let expected = couple / (BEARINGS.1 - BEARINGS.0);
            assert!((bearings.r_a_s.norm() - expected).abs() <= 1e-9 * expected);
            assert!((bearings.r_b_s.norm() - expected).abs() <= 1e-9 * expected);
            assert!((bearings.r_a_s + bearings.r_b_s).norm() <= 1e-12 * expected);
            // H_s integrated from dH_s/dt = M_s by dop853 reproduces the closed form's H_s.
            close(&s.h_o_s_integrated.unwrap(), &s.h_o_s, 0.0, "H_s_int", s.t);
            assert!(
                support.m_drive.abs() <= 1e-12 * couple,
                "no drive at constant spin"
            );
        }
        assert_equilibrium(&rows, BEARINGS, disk_axis_s, |_| Vector3::zeros());
    }
}

#[test]
fn a_disk_in_a_rolling_carrier_carries_the_spin_and_the_roll_acceleration() {
    let (roll, freq_hz) = (0.3, 0.25);
    let omega_f = std::f64::consts::TAU * freq_hz;
    let (c, a) = (0.5 * M * R * R, 0.25 * M * R * R);
    let carrier =
        format!(r#"{{ rate = [0.0, {roll}, 0.0], profile = "sine", freq_hz = {freq_hz} }}"#);
    let mut by_form = Vec::new();
    for form in Form::ALL {
        let rows = rows(&disk_in_carrier(&carrier, form));
        for s in &rows {
            let omega_c = Vector3::y() * (roll * (omega_f * s.t).sin());
            let omega_c_dot = Vector3::y() * (roll * omega_f * (omega_f * s.t).cos());
            let u = disk_axis_s(s);
            assert!(u.y.abs() <= 1e-12, "u stays normal to the roll axis");
            let scale = c * SPIN * roll;
            close(
                &s.support.unwrap().omega_c_s.unwrap(),
                &omega_c,
                roll,
                "Ω_c",
                s.t,
            );
            let expected = omega_c.cross(&u) * (c * SPIN) + omega_c_dot * a;
            close(&s.m_o_s, &expected, scale, "M_s", s.t);
            close(
                &s.h_o_s_integrated.unwrap(),
                &s.h_o_s,
                c * SPIN,
                "H_s_int",
                s.t,
            );
        }
        assert_equilibrium(&rows, BEARINGS, disk_axis_s, |_| Vector3::zeros());
        by_form.push(rows);
    }
    for (b, s) in by_form[0].iter().zip(&by_form[1]) {
        close(&b.m_o_s, &s.m_o_s, 1e-3, "body and space forms", b.t);
    }
}

/// A box (0.1 × 0.4 × 0.2 m, so that C = I_zz > B = I_yy) on a free hinge along body x = space x, in a carrier
/// turning at `yaw` about space z, released from rest at θ₀ = 30°; an event at each upward θ crossing.
fn box_on_hinge(yaw: f64, form: Form, method: &str) -> String {
    format!(
        r#"name = "box-on-hinge-in-carrier"
[body]
mass = 3.0
shape = {{ type = "box", size = [0.1, 0.4, 0.2] }}
[motion]
type = "hinge"
axis = [1.0, 0.0, 0.0]
angle_deg = 30.0
bearings = [-0.05, 0.05]
carrier = {{ rate = [0.0, 0.0, {yaw}] }}
[solver]
method = "{method}"
frame = "{}"
t_end = 20.0
rtol = 1e-12
atol = 1e-14
[output]
every = 0.05
[[event]]
name = "up"
when = "theta"
crosses = 0.0
direction = "up"
"#,
        form.name()
    )
}

#[test]
fn a_hinge_in_a_turning_carrier_swings_at_the_closed_form_period() {
    let yaw: f64 = 2.0;
    let m = 3.0;
    let (a, b, c) = (
        m * (0.16 + 0.04) / 12.0,
        m * (0.01 + 0.04) / 12.0,
        m * (0.01 + 0.16) / 12.0,
    );
    let omega0 = ((c - b) * yaw * yaw / a).sqrt();
    let theta0 = 30f64.to_radians();
    let k = theta0.sin();
    let period = 4.0 * JacobiElliptic::new(k * k).unwrap().quarter_period() / omega0;
    let jacobi = |theta: f64, theta_dot: f64| {
        0.5 * a * theta_dot * theta_dot
            - 0.5 * yaw * yaw * (b * theta.sin().powi(2) + c * theta.cos().powi(2))
    };
    let j0 = jacobi(theta0, 0.0);
    let mut theta_by_form = Vec::new();
    for form in Form::ALL {
        let scene = scene_from(&box_on_hinge(yaw, form, "dop853"), &Overrides::default());
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
        eprintln!(
            "{form:?}: {} crossings, period {period} s, worst spacing error {worst:e} s",
            events.len()
        );
        assert!(
            worst <= 1e-9 * period,
            "{form:?}: period off by {worst:e} s of {period} s"
        );
        for s in &rows {
            let support = s.support.unwrap();
            let j = jacobi(s.theta.unwrap(), support.theta_dot);
            assert!(
                (j - j0).abs() <= 1e-10 * j0.abs(),
                "t = {}: J {j} vs {j0}",
                s.t
            );
            // The drive supplies nothing about the axis: u·(dH/dt − M_eff) = 0.
            assert!(support.m_drive.abs() <= 1e-12 * (s.m_o_s.norm() + a * yaw * yaw));
        }
        assert_equilibrium(&rows, (-0.05, 0.05), box_axis_s, |_| Vector3::zeros());
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
fn bad_carriers_are_refused_naming_the_key() {
    let disk = |carrier: &str| disk_in_carrier(carrier, Form::Body);
    let free = r#"[body]
mass = 1.0
shape = { type = "sphere", radius = 0.1 }
[motion]
type = "free"
carrier = { rate = [0.0, 0.0, 1.0] }
[solver]
t_end = 1.0
[output]
every = 0.1
"#;
    let cases = [
        (
            "unknown profile",
            disk(r#"{ rate = [0.0, 0.0, 1.0], profile = "step" }"#),
            "profile",
        ),
        ("no rate", disk(r#"{ profile = "constant" }"#), "rate"),
        (
            "sine without freq_hz",
            disk(r#"{ rate = [0.0, 0.0, 1.0], profile = "sine" }"#),
            "freq_hz",
        ),
        (
            "freq_hz with a constant profile",
            disk(r#"{ rate = [0.0, 0.0, 1.0], freq_hz = 1.0 }"#),
            "freq_hz",
        ),
        (
            "negative freq_hz",
            disk(r#"{ rate = [0.0, 0.0, 1.0], profile = "sine", freq_hz = -1.0 }"#),
            "freq_hz",
        ),
        ("two components", disk(r#"{ rate = [0.0, 1.0] }"#), "rate"),
        (
            "unknown key",
            disk(r#"{ rate = [0.0, 0.0, 1.0], spin = 2.0 }"#),
            "spin",
        ),
        ("a carrier on free motion", free.to_string(), "carrier"),
    ];
    assert_refused_writing_nothing(&cases);
}

/// Runs scenarios/turbine_yawing_aircraft.toml into DIR/turbine.csv: that path and DIR/turbine.svg.
fn turbine_run(dir: &std::path::Path) -> (std::path::PathBuf, std::path::PathBuf) {
    let csv = dir.join("turbine.csv");
    let run = eulerdyn([
        "run",
        "scenarios/turbine_yawing_aircraft.toml",
        "-o",
        csv.to_str().unwrap(),
    ]);
    assert_eq!(run.code, Some(0), "{}", run.stderr);
    (csv, dir.join("turbine.svg"))
}

/// The sidecar's facts say the support moves (`moving_support`) and name the run's panels, and the plot, asked
/// for no panel, draws the bearings of such a run in space axes (in the spinning body's axes they would turn at the rotor's rate).
#[test]
fn a_carried_run_says_its_support_moves_and_plots_its_bearings_in_space_axes() {
    let dir = tempfile::tempdir().unwrap();
    let (csv, svg) = turbine_run(dir.path());
    let sidecar = std::fs::read_to_string(dir.path().join("turbine.csv.meta.json")).unwrap();
    let sidecar: serde_json::Value = serde_json::from_str(&sidecar).unwrap();
    assert_eq!(
        sidecar["facts"]["moving_support"],
        serde_json::Value::Bool(true)
    );
    // The facts name the run's panels: the six of every run, the axis's, its bearings in space axes.
    assert_eq!(
        sidecar["facts"]["panels"],
        serde_json::json!([
            "h_body",
            "h_space",
            "moment",
            "omega",
            "energy",
            "drift",
            "theta",
            "support",
            "bearings_space"
        ])
    );
    let out = eulerdyn(["plot", csv.to_str().unwrap(), "-o", svg.to_str().unwrap()]);
    assert_eq!(out.code, Some(0), "{}", out.stderr);
    let figure = std::fs::read_to_string(&svg).unwrap();
    assert!(figure.contains("Bearing forces on the body, space axes"));
}

#[test]
fn the_turbine_scenario_plots_its_bearing_loads_in_space_axes() {
    // scenarios/turbine_yawing_aircraft.toml: C = ½ m r² = 5.4 kg·m², 10 000 rpm, yaw 0.35 rad/s peak; the
    // gyroscopic couple's peak C ω Ω (Meriam & Kraige art. 7/10) over the bearing span 0.9 m plus half the weight
    // (588.6 N) bounds |R_A|.
    let dir = tempfile::tempdir().unwrap();
    let (csv, svg) = turbine_run(dir.path());
    let out = eulerdyn([
        "plot",
        csv.to_str().unwrap(),
        "-o",
        svg.to_str().unwrap(),
        "--panels",
        "omega,bearings_space",
    ]);
    assert_eq!(out.code, Some(0), "{}", out.stderr);
    let figure = std::fs::read_to_string(&svg).unwrap();
    assert!(figure.contains("Bearing forces on the body, space axes"));
    let path = std::path::Path::new("scenarios/turbine_yawing_aircraft.toml");
    let scene =
        eulerdyn::scene::load(path, &Overrides::default()).unwrap_or_else(|e| panic!("{e}"));
    let rows = simulate::samples(&scene).unwrap().0;
    let couple = 0.5 * 120.0 * 0.09 * (10_000.0 * std::f64::consts::TAU / 60.0) * 0.35;
    let peak = (rows.iter())
        .map(|s| s.support.unwrap().bearings.unwrap().r_a_s.z)
        .fold(f64::MIN, f64::max);
    // At the yaw's peak (t = 1 s, a row) Ω̇_c = 0 and M = C ω Ω (ẑ × u) ⊥ u, carried as vertical forces
    // ±M/(b − a) whatever u's heading, on top of half the weight.
    let bound = couple / 0.9 + 0.5 * 120.0 * 9.81;
    assert!(
        (peak - bound).abs() <= 1e-9 * bound,
        "peak R_A,z {peak} N vs {bound} N"
    );
}
