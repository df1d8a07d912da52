//! `eulerdyn fit`: a body from its measured motion. The truth is a run of eulerdyn's own (dop853 at rtol 1e-13) or
//! a closed form: the torque-free symmetric top, ω₃ = n and ω₁ + iω₂ = a e^{iλt} with λ = (C − A) n / A (Landau &
//! Lifshitz, *Mechanics*, §33). The Jacobian is checked against central differences of the residuals; the
//! intervals' coverage over many noisy data sets (the 95 % intervals of a correctly specified least-squares
//! problem hold the truth 95 % of the time to first order: Seber & Wild, *Nonlinear Regression*, §5.2).

use eulerdyn::analysis::fit::build::Builder;
use eulerdyn::analysis::fit::params::Parameters;
use eulerdyn::analysis::fit::problem::{Sigmas, evaluate};
use eulerdyn::analysis::fit::solve::{Fit, fit};
use eulerdyn::analysis::fit::{Data, Estimate, FitError, FitOptions};
use eulerdyn::scene::{Overrides, Scene};
use eulerdyn::{Sample, simulate};
use nalgebra::{DVector, UnitQuaternion, Vector3};

use crate::common::{dir_entries, eulerdyn, scene_from, write_file};

/// A body with a full tensor (kg·m²), tumbling from ω₀ = (0.3, −0.2, 1.1) rad/s, with `effects` (scene lines).
fn truth_text(inertia: &str, effects: &str) -> String {
    format!(
        "[body]\nmass = 4.0\ninertia = {inertia}\n[initial]\nomega = [0.3, -0.2, 1.1]\n\
         attitude = [0.9, 0.1, -0.3, 0.2]\n{effects}\n[solver]\nrtol = 1e-13\natol = 1e-15\nt_end = 12.0\n\
         [output]\nevery = 0.01\n"
    )
}

const TENSOR: &str = "[[0.05, 0.002, -0.001], [0.002, 0.07, 0.003], [-0.001, 0.003, 0.09]]";
const KNOWN_TORQUE: &str =
    "[[effect]]\ntype = \"torque\"\nframe = \"body\"\nvalue = [0.004, -0.002, 0.003]\n";

/// The rows of `scene`'s run.
fn run(scene: &Scene) -> Vec<Sample> {
    simulate::samples(scene).unwrap().0
}

/// Uneven rows: of the run's rows, those whose index k has (7k² + 3k) mod 10 < 4 (gaps of 1 to 4 rows).
fn uneven(rows: &[Sample]) -> Vec<Sample> {
    (rows.iter().enumerate())
        .filter(|(k, _)| (7 * k * k + 3 * k) % 10 < 4)
        .map(|(_, s)| *s)
        .collect()
}

/// The data of `rows`: the gyro's ω + `bias` where `gyro`, the attitude where `attitude`.
fn data_of(rows: &[Sample], bias: Vector3<f64>, gyro: bool, attitude: bool) -> Data {
    Data {
        times: rows.iter().map(|s| s.t).collect(),
        omega_b: rows
            .iter()
            .map(|s| gyro.then(|| *s.omega_b + bias))
            .collect(),
        q: rows.iter().map(|s| attitude.then_some(s.q)).collect(),
    }
}

fn options(estimates: &[Estimate]) -> FitOptions {
    FitOptions {
        estimates: estimates.to_vec(),
        ..FitOptions::default()
    }
}

/// Asserts each (name, truth) estimate within 1e-7 of the truth.
fn assert_estimates(fitted: &Fit, truths: &[(&str, f64)]) {
    for (name, truth) in truths {
        let estimate = value(fitted, name);
        assert!((estimate - truth).abs() < 1e-7, "{name}: {estimate}");
    }
}

/// The estimate named `name`.
fn value(fit: &Fit, name: &str) -> f64 {
    (fit.parameters.iter())
        .find(|p| p.name == name)
        .unwrap_or_else(|| panic!("no parameter {name}"))
        .estimate
}

/// Asserts that the Jacobian of every parameter group at the start moved by `shifts` (index, amount) matches the
/// central differences of the residuals column by column.
fn assert_sensitivities_match(start: &Scene, data: &Data, shifts: &[(usize, f64)]) {
    let all = [
        Estimate::Inertia,
        Estimate::Omega0,
        Estimate::Attitude0,
        Estimate::GyroBias,
    ];
    let free = start.motion.free().unwrap();
    let params = Parameters::new(
        &all,
        *start.body.inertia_c(),
        **free.omega0_b,
        start.attitude0,
        false,
    );
    let builder = Builder::new(start).unwrap();
    let sigmas = Sigmas {
        omega: 1.0,
        attitude: 1.0,
    };
    let mut x = params.start();
    assert_eq!(x.len(), 15, "6 entries, ω₀, δ and the bias");
    for &(k, shift) in shifts {
        x[k] += shift;
    }
    let jacobian = evaluate(&builder, &params, data, sigmas, &x)
        .unwrap()
        .jacobian;
    for k in 0..x.len() {
        // h = 1e-5 of the coordinate's size: the differences' truncation error (h² f‴/6) is ~1e-10 of the
        // column, their noise (the residuals' integration error, ~1e-12, over h) ~1e-7 of it; a wheel model's own
        // differences add ~1e-10.
        let h = 1e-5 * x[k].abs().max(0.05);
        let at = |d: f64| {
            let mut y = x.clone();
            y[k] += d;
            evaluate(&builder, &params, data, sigmas, &y)
                .unwrap()
                .residuals
        };
        let difference: DVector<f64> = (at(h) - at(-h)) / (2.0 * h);
        let column = jacobian.column(k);
        let off = (difference - column).norm() / column.norm();
        assert!(
            off < 1e-5,
            "column {k} ({}): off by {off:e}",
            params.coordinate_names()[k]
        );
    }
}

#[test]
fn sensitivities_match_central_differences_of_the_residuals() {
    let effects = format!(
        "{KNOWN_TORQUE}[[effect]]\ntype = \"torque\"\nframe = \"space\"\nvalue = [0.001, 0.0, 0.002]\n\
         [[effect]]\ntype = \"damping\"\nc = 0.002\n"
    );
    let truth = scene_from(&truth_text(TENSOR, &effects), &Overrides::default());
    let rows: Vec<Sample> = run(&truth).into_iter().step_by(10).take(31).collect();
    let data = data_of(&rows, Vector3::new(0.01, 0.0, -0.02), true, true);
    let start_text = truth_text("[0.055, 0.066, 0.088]", &effects);
    let start = scene_from(&start_text, &Overrides::default());
    // Away from the start, so that q₀'s turn δ is not 0 and J_r(δ) ≠ 1.
    let shifts = [(3, 0.001), (6, 0.02), (9, 0.1), (10, -0.2), (11, 0.05)];
    assert_sensitivities_match(&start, &data, &shifts);
}

#[test]
fn noise_free_data_on_uneven_rows_recover_the_truth() {
    let truth = scene_from(&truth_text(TENSOR, KNOWN_TORQUE), &Overrides::default());
    let bias = Vector3::new(0.01, -0.02, 0.005);
    let rows = uneven(&run(&truth));
    let data = data_of(&rows, bias, true, true);
    // 5–10 % off in the inertia and ω₀, 3° off in q₀.
    let mut start_text = truth_text("[0.052, 0.066, 0.095]", KNOWN_TORQUE);
    start_text = start_text.replace("[0.3, -0.2, 1.1]", "[0.28, -0.21, 1.05]");
    start_text = start_text.replace("[0.9, 0.1, -0.3, 0.2]", "[0.9, 0.12, -0.32, 0.19]");
    let start = scene_from(&start_text, &Overrides::default());
    let all = [
        Estimate::Inertia,
        Estimate::Omega0,
        Estimate::Attitude0,
        Estimate::GyroBias,
    ];
    let fitted = fit(&data, &start, &options(&all)).unwrap();
    assert!(fitted.converged, "{}", fitted.termination);
    assert!(!fitted.scale_held, "a known torque fixes the scale");
    let inertia = truth.body.inertia_c();
    let names = ["I_xx", "I_yy", "I_zz", "I_xy", "I_xz", "I_yz"];
    let entries = [(0, 0), (1, 1), (2, 2), (0, 1), (0, 2), (1, 2)];
    for (name, entry) in names.iter().zip(entries) {
        let off = (value(&fitted, name) - inertia[entry]).abs() / inertia.trace();
        assert!(off < 1e-7, "{name}: off by {off:e} of the trace");
    }
    for (k, axis) in ["x", "y", "z"].iter().enumerate() {
        let omega0 = [0.3, -0.2, 1.1][k];
        let off = (value(&fitted, &format!("omega0_{axis}")) - omega0).abs() / 1.1;
        assert!(off < 1e-7, "omega0_{axis}: off by {off:e}");
        let off = (value(&fitted, &format!("bias_{axis}")) - bias[k]).abs() / 1.1;
        assert!(off < 1e-7, "bias_{axis}: off by {off:e}");
    }
    let q = UnitQuaternion::new_normalize(nalgebra::Quaternion::new(
        value(&fitted, "q0_w"),
        value(&fitted, "q0_x"),
        value(&fitted, "q0_y"),
        value(&fitted, "q0_z"),
    ));
    assert!(
        q.angle_to(&truth.attitude0) < 1e-7,
        "q0 off by {:e} rad",
        q.angle_to(&truth.attitude0)
    );
}

/// The torque-free top of `moments` (A, A, C) from ω₀ = (a, 0, n): ω at `times` (Landau & Lifshitz §33).
fn symmetric_top(moments: [f64; 3], a: f64, n: f64, times: &[f64]) -> Vec<Vector3<f64>> {
    let lambda = (moments[2] - moments[0]) * n / moments[0];
    (times.iter())
        .map(|&t| Vector3::new(a * (lambda * t).cos(), a * (lambda * t).sin(), n))
        .collect()
}

/// A torque-free top's scene (principal moments `moments`), from ω₀ = (0.2, 0, 2) rad/s.
fn top_text(moments: &str, omega: &str) -> String {
    format!(
        "[body]\nmass = 1.0\ninertia = {moments}\n[initial]\nomega = {omega}\n[solver]\nt_end = 20.0\n\
         [output]\nevery = 0.1\n"
    )
}

#[test]
fn without_a_known_moment_the_scale_is_held_and_the_ratios_recovered() {
    let times: Vec<f64> = (0..=200).map(|k| k as f64 * 0.1).collect();
    let omega = symmetric_top([1.0, 1.0, 1.6], 0.2, 2.0, &times);
    let data = Data {
        times,
        omega_b: omega.into_iter().map(Some).collect(),
        q: vec![None; 201],
    };
    let start = scene_from(
        &top_text("[1.1, 0.95, 1.6]", "[0.19, 0.01, 2.05]"),
        &Overrides::default(),
    );
    let fitted = fit(
        &data,
        &start,
        &options(&[Estimate::Principal, Estimate::Omega0]),
    )
    .unwrap();
    assert!(fitted.converged && fitted.scale_held);
    assert!(
        fitted.notes[0].contains("scale is held"),
        "{:?}",
        fitted.notes
    );
    assert_estimates(
        &fitted,
        &[
            ("I_1", 1.0),
            ("I_2", 1.0),
            ("I_3", 1.6),
            ("omega0_x", 0.2),
            ("omega0_y", 0.0),
        ],
    );
    let held = fitted.parameters.iter().find(|p| p.name == "I_3").unwrap();
    assert_eq!(held.std_error, 0.0, "the held moment has no error");
}

#[test]
fn attitude_data_alone_give_the_start_and_a_bias_is_refused() {
    let truth = scene_from(&truth_text(TENSOR, ""), &Overrides::default());
    let rows: Vec<Sample> = run(&truth).into_iter().step_by(5).collect();
    let data = data_of(&rows, Vector3::zeros(), false, true);
    let mut start_text = truth_text(TENSOR, "");
    start_text = start_text.replace("[0.3, -0.2, 1.1]", "[0.31, -0.18, 1.12]");
    start_text = start_text.replace("[0.9, 0.1, -0.3, 0.2]", "[0.88, 0.12, -0.3, 0.21]");
    let start = scene_from(&start_text, &Overrides::default());
    let fitted = fit(
        &data,
        &start,
        &options(&[Estimate::Omega0, Estimate::Attitude0]),
    )
    .unwrap();
    assert!(fitted.converged);
    assert!((value(&fitted, "omega0_z") - 1.1).abs() < 1e-8);
    assert!((value(&fitted, "q0_w") - truth.attitude0.w).abs() < 1e-8);
    let refused = fit(&data, &start, &options(&[Estimate::GyroBias])).unwrap_err();
    assert!(
        matches!(&refused, FitError::Input(m) if m.contains("gyro_bias")),
        "{refused}"
    );
}

/// A standard normal deviate from a 64-bit state (splitmix64, then Box–Muller).
fn normal(state: &mut u64) -> f64 {
    let mut uniform = || {
        *state = state.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = *state;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        ((z ^ (z >> 31)) >> 11) as f64 / (1u64 << 53) as f64
    };
    let (u, v) = (uniform().max(1e-300), uniform());
    (-2.0 * u.ln()).sqrt() * (std::f64::consts::TAU * v).cos()
}

#[test]
fn the_95_percent_intervals_hold_the_truth_95_percent_of_the_time() {
    // A triaxial tumble, gyro only, σ = 2e-3 rad/s given; 300 data sets. The count of intervals holding the
    // truth is binomial (300, 0.95): its standard deviation is 3.8 (1.26 %), so [0.91, 0.99] is ±3.2 of them.
    let truth = scene_from(
        &top_text("[1.0, 1.3, 1.6]", "[0.4, 0.1, 1.5]"),
        &Overrides::default(),
    );
    let rows: Vec<Sample> = run(&truth).into_iter().step_by(2).collect();
    let start = scene_from(
        &top_text("[1.02, 1.28, 1.6]", "[0.41, 0.09, 1.49]"),
        &Overrides::default(),
    );
    let truths = [
        ("I_1", 1.0),
        ("I_2", 1.3),
        ("omega0_x", 0.4),
        ("omega0_y", 0.1),
        ("omega0_z", 1.5),
    ];
    let sigma = 2e-3;
    let mut held = [0usize; 5];
    let mut chi2 = 0.0;
    let seeds = 300;
    for seed in 0..seeds {
        let mut state = 0x5EED_0000 + seed as u64;
        let mut data = data_of(&rows, Vector3::zeros(), true, false);
        for w in data.omega_b.iter_mut().flatten() {
            *w += Vector3::new(normal(&mut state), normal(&mut state), normal(&mut state)) * sigma;
        }
        let mut opts = options(&[Estimate::Principal, Estimate::Omega0]);
        opts.sigma_omega = Some(sigma);
        let fitted = fit(&data, &start, &opts).unwrap();
        assert!(fitted.converged && fitted.scale_held);
        chi2 += fitted.chi2_dof;
        for (k, (name, truth)) in truths.iter().enumerate() {
            let p = fitted.parameters.iter().find(|p| p.name == *name).unwrap();
            held[k] += usize::from(p.low <= *truth && *truth <= p.high);
        }
    }
    for (k, (name, _)) in truths.iter().enumerate() {
        let coverage = held[k] as f64 / seeds as f64;
        assert!(
            (0.91..=0.99).contains(&coverage),
            "{name}: coverage {coverage}"
        );
    }
    // χ²/dof of 303 residuals less 4 parameters averages 1 with a standard deviation of √(2/299)/√300 ≈ 0.005.
    let mean = chi2 / seeds as f64;
    assert!((mean - 1.0).abs() < 0.02, "mean chi2/dof {mean}");
}

#[test]
fn a_parameter_the_data_cannot_determine_is_named() {
    // A top spinning about its symmetry axis: ω stays (0, 0, n), and nothing in it moves with I_1 or I_2.
    let times: Vec<f64> = (0..=50).map(|k| k as f64 * 0.1).collect();
    let data = Data {
        omega_b: times
            .iter()
            .map(|_| Some(Vector3::new(0.0, 0.0, 2.0)))
            .collect(),
        q: vec![None; times.len()],
        times,
    };
    let start = scene_from(
        &top_text("[1.0, 1.0, 1.6]", "[0.0, 0.0, 2.0]"),
        &Overrides::default(),
    );
    let refused = fit(&data, &start, &options(&[Estimate::Principal])).unwrap_err();
    assert!(
        matches!(&refused, FitError::Input(m) if m.contains("cannot determine I_")),
        "{refused}"
    );
}

/// Writes the gyro data of `omega` at `times` as a CSV (t, omega_x..z).
fn gyro_csv(times: &[f64], omega: &[Vector3<f64>]) -> String {
    let mut text = String::from("t,omega_x,omega_y,omega_z\n");
    for (t, w) in times.iter().zip(omega) {
        text.push_str(&format!("{t},{},{},{}\n", w.x, w.y, w.z));
    }
    text
}

#[test]
fn the_command_prints_writes_a_scene_that_runs_and_a_figure() {
    let dir = tempfile::tempdir().unwrap();
    let times: Vec<f64> = (0..=200).map(|k| k as f64 * 0.1).collect();
    let omega = symmetric_top([1.0, 1.0, 1.6], 0.2, 2.0, &times);
    let csv = write_file(dir.path(), "gyro.csv", gyro_csv(&times, &omega));
    let scene = write_file(
        dir.path(),
        "top.toml",
        top_text("[1.1, 0.95, 1.6]", "[0.19, 0.01, 2.05]"),
    );
    let fitted = dir.path().join("fitted.toml");
    let figure = dir.path().join("residuals.svg");
    let args = |extra: &[&str]| {
        let mut a = vec![
            "fit",
            csv.to_str().unwrap(),
            "--scene",
            scene.to_str().unwrap(),
        ];
        a.extend_from_slice(&["--estimate", "principal,omega0"]);
        a.extend_from_slice(extra);
        a.iter().map(|s| s.to_string()).collect::<Vec<_>>()
    };
    let out = eulerdyn(args(&[
        "--json",
        "-o",
        fitted.to_str().unwrap(),
        "--plot",
        figure.to_str().unwrap(),
    ]));
    out.expect_code(0);
    let json: serde_json::Value = serde_json::from_str(&out.stdout).unwrap();
    for field in [
        "parameters",
        "correlation",
        "rms",
        "chi2_dof",
        "converged",
        "scale_held",
    ] {
        assert!(json.get(field).is_some(), "--json has `{field}`");
    }
    assert_eq!(json["parameters"][0]["name"], "I_1");
    assert!((json["parameters"][0]["estimate"].as_f64().unwrap() - 1.0).abs() < 1e-7);
    assert!(
        std::fs::read_to_string(&figure)
            .unwrap()
            .starts_with("<svg")
    );
    let run = eulerdyn(["run", fitted.to_str().unwrap(), "-o", "-"]);
    run.expect_code(0);
    let text = eulerdyn(args(&[]));
    text.expect_code(0);
    assert!(
        text.stdout.contains("95 % interval") && text.stdout.contains("chi2/dof"),
        "{}",
        text.stdout
    );
}

#[test]
fn bad_input_is_refused_and_an_inertia_that_is_no_body_is_reported_writing_nothing() {
    let times: Vec<f64> = (0..=100).map(|k| k as f64 * 0.05).collect();
    // The top of (1.2, 1.2, 2.5): C > A + B, no mass distribution has it; the start (1.25, 1.25, 2.5) is a body.
    let omega = symmetric_top([1.2, 1.2, 2.5], 0.2, 2.0, &times);
    let gyro = gyro_csv(&times, &omega);
    let start = top_text("[1.25, 1.25, 2.5]", "[0.2, 0.0, 2.0]");
    let axis = "[body]\nmass = 1.0\ninertia = [1.25, 1.25, 2.5]\n[motion]\ntype = \"fixed_axis\"\n\
                axis = [0.0, 0.0, 1.0]\nrate = 2.0\n[solver]\nt_end = 20.0\n[output]\nevery = 0.1\n"
        .to_string();
    let cases: [(&str, &str, String, &str, i32, &str); 8] = [
        (
            "unknown parameter",
            "mass",
            gyro.clone(),
            &start,
            2,
            "--estimate mass",
        ),
        (
            "attitude0 without attitude",
            "attitude0",
            gyro.clone(),
            &start,
            2,
            "attitude0",
        ),
        (
            "bias without gyro",
            "gyro_bias",
            "t,q_w,q_x,q_y,q_z\n0,1,0,0,0\n1,1,0,0,0\n".into(),
            &start,
            2,
            "gyro_bias",
        ),
        (
            "no data columns",
            "omega0",
            "t,a\n0,1\n1,2\n".into(),
            &start,
            2,
            "data.csv",
        ),
        (
            "time not increasing",
            "omega0",
            "t,omega_x,omega_y,omega_z\n0,0,0,2\n0,0,0,2\n".into(),
            &start,
            2,
            "row 2",
        ),
        (
            "an axis motion",
            "omega0",
            gyro.clone(),
            &axis,
            2,
            "free body",
        ),
        (
            "both inertia forms",
            "inertia,principal",
            gyro.clone(),
            &start,
            2,
            "not both",
        ),
        (
            "not a body",
            "principal,omega0",
            gyro.clone(),
            &start,
            1,
            "triangle",
        ),
    ];
    for (name, estimate, data, scene, code, says) in cases {
        let dir = tempfile::tempdir().unwrap();
        let csv = write_file(dir.path(), "data.csv", data);
        let scene = write_file(dir.path(), "scene.toml", scene);
        let out = eulerdyn([
            "fit",
            csv.to_str().unwrap(),
            "--scene",
            scene.to_str().unwrap(),
            "--estimate",
            estimate,
            "-o",
            dir.path().join("fitted.toml").to_str().unwrap(),
            "--plot",
            dir.path().join("fig.svg").to_str().unwrap(),
        ]);
        assert_eq!(out.code, Some(code), "{name}: {}", out.stderr);
        assert!(
            out.stderr.contains(says) || out.stdout.contains(says),
            "{name}: says `{says}`: {}",
            out.stderr
        );
        assert_eq!(
            dir_entries(dir.path()),
            ["data.csv", "scene.toml"],
            "{name}: nothing written"
        );
    }
}

#[test]
fn a_users_law_acts_in_the_model_as_in_the_run() {
    // A PD-like law M = −k (ω − ω_ref) in body axes, added to the built scene (no scene file holds it): it is known,
    // so it fixes the scale, and the fit must carry it into every scene it builds.
    let law = |_t: f64, _q: &UnitQuaternion<f64>, w: &Vector3<f64>| {
        (Vector3::new(0.0, 0.0, 1.0) - w) * 0.02
    };
    let with_law = |text: &str| {
        scene_from(text, &Overrides::default())
            .with_moment("pd", eulerdyn::Axes::Body, law)
            .unwrap()
    };
    let truth = with_law(&truth_text(TENSOR, ""));
    let rows: Vec<Sample> = run(&truth).into_iter().step_by(5).collect();
    let data = data_of(&rows, Vector3::zeros(), true, false);
    let start = with_law(&truth_text("[0.052, 0.068, 0.092]", ""));
    let fitted = fit(
        &data,
        &start,
        &options(&[Estimate::Inertia, Estimate::Omega0]),
    )
    .unwrap();
    assert!(
        fitted.converged && !fitted.scale_held,
        "{}",
        fitted.termination
    );
    let inertia = truth.body.inertia_c();
    for (name, entry) in [("I_xx", (0, 0)), ("I_zz", (2, 2)), ("I_yz", (1, 2))] {
        let off = (value(&fitted, name) - inertia[entry]).abs() / inertia.trace();
        assert!(off < 1e-7, "{name}: off by {off:e} of the trace");
    }
}

/// One wheel spinning at a constant 40 rad/s about body x, and one driven by a sine torque about z (scene lines;
/// smooth in t: across a step's jump two adaptive runs' differences are noise of the tolerance over h).
const WHEELS: &str = "[[body.rotor]]\naxis = [1.0, 0.0, 0.0]\ninertia = 0.002\nspin = 40.0\n\
                      [[body.rotor]]\naxis = [0.0, 0.0, 1.0]\ninertia = 0.001\nspin = 0.0\n\
                      torque = 0.0005\nprofile = \"sine\"\nfreq_hz = 0.2\n";

#[test]
fn wheels_act_in_the_model_their_sensitivities_match_differences_and_the_truth_is_recovered() {
    // The wheels' momentum is known, so it fixes the inertia's scale (no scale is held).
    let truth = scene_from(&truth_text(TENSOR, WHEELS), &Overrides::default());
    let rows: Vec<Sample> = run(&truth).into_iter().step_by(4).collect();
    let data = data_of(&rows, Vector3::new(0.002, 0.0, -0.001), true, true);
    let start = scene_from(
        &truth_text("[0.052, 0.068, 0.092]", WHEELS),
        &Overrides::default(),
    );
    assert_sensitivities_match(&start, &data, &[(9, 0.05)]);
    let all = [
        Estimate::Inertia,
        Estimate::Omega0,
        Estimate::Attitude0,
        Estimate::GyroBias,
    ];
    let fitted = fit(&data, &start, &options(&all)).unwrap();
    assert!(
        fitted.converged && !fitted.scale_held,
        "{}",
        fitted.termination
    );
    let inertia = truth.body.inertia_c();
    for (name, entry) in [
        ("I_xx", (0, 0)),
        ("I_yy", (1, 1)),
        ("I_zz", (2, 2)),
        ("I_xy", (0, 1)),
    ] {
        let off = (value(&fitted, name) - inertia[entry]).abs() / inertia.trace();
        assert!(off < 1e-7, "{name}: off by {off:e} of the trace");
    }
    assert!((value(&fitted, "bias_x") - 0.002).abs() < 1e-8);
}

#[test]
fn a_planar_body_with_a_wheel_is_recovered_on_the_triangles_edge() {
    // Kelvin's gyrostat (I = 1, 2, 3: I_1 + I_2 = I_3, a planar body) holding its intermediate axis with a wheel:
    // the fit's steps straddle the edge of the bodies, where the wheels' model must still be built.
    let text = std::fs::read_to_string(crate::common::repo_path("scenarios/kelvin_gyrostat.toml"))
        .unwrap();
    let truth = scene_from(&text, &Overrides::default());
    let rows: Vec<Sample> = run(&truth).into_iter().step_by(2).collect();
    let data = data_of(&rows, Vector3::zeros(), true, true);
    let start_text = (text.replace("inertia = [1.0, 2.0, 3.0]", "inertia = [1.05, 1.95, 2.95]"))
        .replace("omega = [0.1, 1.0, 0.0]", "omega = [0.09, 1.02, 0.01]");
    assert_ne!(start_text, text);
    let start = scene_from(&start_text, &Overrides::default());
    let estimates = [Estimate::Principal, Estimate::Omega0, Estimate::Attitude0];
    let fitted = fit(&data, &start, &options(&estimates)).unwrap();
    assert!(
        fitted.converged && !fitted.scale_held,
        "{}",
        fitted.termination
    );
    assert_estimates(
        &fitted,
        &[
            ("I_1", 1.0),
            ("I_2", 2.0),
            ("I_3", 3.0),
            ("omega0_x", 0.1),
            ("omega0_y", 1.0),
        ],
    );
}
