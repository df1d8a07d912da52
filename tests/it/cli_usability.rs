//! The first hour of a new user: `--help` of every command with an example, `--version`, what `check` prints,
//! data on stdout and messages on stderr, `--quiet`, and no progress bar when stderr is not a terminal.

use std::path::Path;

use crate::common::{FREE_SCENE, bundled_scenarios, eulerdyn, repo_path, write_file};

fn scenario(name: &str) -> String {
    repo_path(&format!("scenarios/{name}.toml"))
        .to_string_lossy()
        .into_owned()
}

/// A path as command-line text (temporary paths are UTF-8).
fn text(path: &Path) -> &str {
    path.to_str().expect("a UTF-8 path")
}

#[test]
fn version_prints_the_crate_version() {
    let out = eulerdyn(["--version"]);
    out.expect_code(0);
    assert_eq!(
        out.stdout.trim(),
        format!("eulerdyn {}", env!("CARGO_PKG_VERSION"))
    );
}

#[test]
fn help_lists_every_command_with_examples() {
    let out = eulerdyn(["--help"]);
    out.expect_code(0);
    for command in ["run", "check", "compare", "plot", "accuracy"] {
        assert!(
            out.stdout.contains(&format!("  {command} ")),
            "no {command} in\n{}",
            out.stdout
        );
    }
    assert!(out.stdout.contains("Examples:"), "{}", out.stdout);
    assert!(out.stdout.contains("--quiet"), "{}", out.stdout);
    assert!(out.stdout.contains("--version"), "{}", out.stdout);
}

#[test]
fn help_of_every_command_shows_an_example_of_it() {
    for command in ["run", "check", "compare", "plot", "accuracy"] {
        for args in [vec![command, "--help"], vec!["help", command]] {
            let out = eulerdyn(&args);
            out.expect_code(0);
            assert!(
                out.stdout.contains("Example"),
                "{args:?}: no example in\n{}",
                out.stdout
            );
            assert!(
                out.stdout.contains(&format!("eulerdyn {command} ")),
                "{args:?}: the example does not use the command:\n{}",
                out.stdout
            );
        }
    }
    let plot = eulerdyn(["plot", "--help"]);
    assert!(plot.stdout.contains("--panels"), "{}", plot.stdout);
    assert!(plot.stdout.contains("h_body"), "{}", plot.stdout);
}

#[test]
fn check_describes_the_tilted_disk_at_a_glance() {
    let out = eulerdyn(["check", &scenario("tilted_disk")]);
    out.expect_code(0);
    let s = &out.stdout;
    for line in [
        "scene          tilted-disk",
        "body           mass 2 kg",
        "principal moment 3 = 9.000000e-2 kg*m^2 about body axis (0.000000, 0.000000, 1.000000)",
        "axis (0.000000, -0.500000, 0.866025) (body axes), 30.000 deg from principal axis 3",
        "rate 10 rad/s at t = 0, acceleration 0 rad/s^2: 1.592 turns by t_end",
        "moment center  C, the mass center, on the axis: H and M are about it",
        "M = (-1.948557, 0.000000, 0.000000) N*m (body axes), |M| = 1.948557e0",
        "kinetic energy 3.937500e0 J",
        "effects        none: the motion is prescribed",
        "method         dop853 (own backend), adaptive: rtol = 1e-10, atol = 1e-12",
        "output         t = 0 .. 1 s, a row every 0.01 s: 101 rows",
        "then theta, H_s_int_x, H_s_int_y, H_s_int_z",
        "estimate       about 100 steps",
    ] {
        assert!(s.contains(line), "no line {line:?} in\n{s}");
    }
    assert!(out.stderr.is_empty(), "{}", out.stderr);
}

#[test]
fn check_names_the_pivot_as_moment_center_of_the_heavy_top() {
    let out = eulerdyn(["check", &scenario("heavy_top")]);
    out.expect_code(0);
    let s = &out.stdout;
    for line in [
        "moment center  the fixed pivot, (0.000000, 0.000000, -0.050000) m from C (body axes)",
        "principal moments about the pivot: 1.466667e-3, 1.466667e-3, 4.000000e-4 kg*m^2",
        "effects        gravity g = (0.000000, 0.000000, -9.810000) m/s^2",
        "attitude: body axes turned 20.000 deg about (1.000000, 0.000000, 0.000000)",
        "rtol = 1e-11",
        "501 rows",
    ] {
        assert!(s.contains(line), "no line {line:?} in\n{s}");
    }
    // The adaptive estimate: more steps than rows (the top spins at 150 rad/s), a number that is printed.
    let estimate = s
        .lines()
        .find(|l| l.starts_with("estimate"))
        .expect("an estimate line");
    let steps: f64 = estimate
        .split_whitespace()
        .nth(2)
        .and_then(|n| n.parse().ok())
        .unwrap_or_else(|| panic!("{estimate}"));
    assert!((1000.0..10000.0).contains(&steps), "{estimate}");
}

#[test]
fn check_counts_the_fixed_steps_and_the_offset_bearing_force() {
    let dir = tempfile::tempdir().unwrap();
    let scene = write_file(
        dir.path(),
        "rk4.toml",
        FREE_SCENE.replace("[solver]\n", "[solver]\nmethod = \"rk4\"\ndt = 0.001\n"),
    );
    let out = eulerdyn(["check", text(&scene)]);
    out.expect_code(0);
    assert!(
        out.stdout
            .contains("rk4 (own backend), fixed step dt = 0.001 s"),
        "{}",
        out.stdout
    );
    assert!(
        out.stdout.contains("estimate       1000 steps of dt"),
        "{}",
        out.stdout
    );
    assert!(
        out.stdout.contains("moment center  C, the mass center"),
        "{}",
        out.stdout
    );
    let out = eulerdyn(["check", &scenario("offset_disk")]);
    out.expect_code(0);
    for line in [
        "the axis point (0.020000, 0.000000, 0.000000) m from C (body axes)",
        "bearing force F = m a_C",
        "then theta, F_s_x, F_s_y, F_s_z",
    ] {
        assert!(out.stdout.contains(line), "no {line:?} in\n{}", out.stdout);
    }
}

#[test]
fn run_to_stdout_writes_only_data_there_and_no_progress_when_stderr_is_not_a_terminal() {
    let out = eulerdyn(["run", &scenario("tilted_disk")]);
    out.expect_code(0);
    assert!(out.stdout.starts_with("t,q_w,"), "{}", &out.stdout[..80]);
    assert_eq!(out.stdout.lines().count(), 102);
    // stderr is a pipe here: no bar, no carriage returns, no escape sequences.
    assert!(!out.stderr.contains('\r'), "{:?}", out.stderr);
    assert!(!out.stderr.contains('\u{1b}'), "{:?}", out.stderr);
    assert!(!out.stderr.contains("[="), "{:?}", out.stderr);
}

#[test]
fn run_to_a_file_reports_on_stderr_unless_quiet() {
    let dir = tempfile::tempdir().unwrap();
    let csv = dir.path().join("disk.csv");
    let out = eulerdyn(["run", &scenario("tilted_disk"), "-o", text(&csv)]);
    out.expect_code(0);
    assert!(out.stdout.is_empty(), "{}", out.stdout);
    assert!(
        out.stderr.starts_with("wrote 101 rows to "),
        "{}",
        out.stderr
    );
    for args in [
        vec!["run", "-q", &scenario("tilted_disk"), "-o", text(&csv)],
        vec!["--quiet", "run", &scenario("tilted_disk"), "-o", text(&csv)],
    ] {
        let out = eulerdyn(&args);
        out.expect_code(0);
        assert!(out.stdout.is_empty(), "{args:?}: {}", out.stdout);
        assert!(out.stderr.is_empty(), "{args:?}: {}", out.stderr);
    }
}

#[test]
fn quiet_keeps_errors_and_their_exit_codes() {
    let dir = tempfile::tempdir().unwrap();
    let scene = write_file(
        dir.path(),
        "bad.toml",
        FREE_SCENE.replace("mass = 1.0", "mass = -1.0"),
    );
    let out = eulerdyn(["run", "-q", text(&scene)]);
    out.expect_code(2);
    assert!(out.stderr.contains("body.mass"), "{}", out.stderr);
    let svg = dir.path().join("x.svg");
    let out = eulerdyn([
        "plot",
        "-q",
        text(&dir.path().join("none.csv")),
        "-o",
        text(&svg),
    ]);
    out.expect_code(2);
    assert!(out.stderr.contains("none.csv"), "{}", out.stderr);
}

#[test]
fn plot_and_compare_are_quiet_with_quiet() {
    let dir = tempfile::tempdir().unwrap();
    let csv = dir.path().join("free.csv");
    let scene = write_file(dir.path(), "free.toml", FREE_SCENE);
    eulerdyn(["run", "-q", text(&scene), "-o", text(&csv)]).expect_code(0);
    let svg = dir.path().join("free.svg");
    let out = eulerdyn(["plot", "-q", text(&csv), "-o", text(&svg)]);
    out.expect_code(0);
    assert!(out.stderr.is_empty() && out.stdout.is_empty(), "{out:?}");
    assert!(svg.exists());
    let out = eulerdyn(["compare", "-q", text(&scene)]);
    out.expect_code(0);
    assert!(out.stderr.is_empty(), "{}", out.stderr);
    assert!(
        out.stdout.contains("omega"),
        "the comparison is data: {}",
        out.stdout
    );
}

/// Asserts that `text` contains every one of `parts`.
fn contains_all(text: &str, parts: &[&str]) {
    for part in parts {
        assert!(text.contains(part), "no {part:?} in\n{text}");
    }
}

/// The sidecar of a run written to `csv`.
fn sidecar_of(csv: &Path) -> serde_json::Value {
    let text =
        std::fs::read_to_string(format!("{}.meta.json", csv.display())).expect("the sidecar");
    serde_json::from_str(&text).expect("the sidecar is JSON")
}

#[test]
fn a_fixed_step_too_coarse_for_the_motion_is_reported_and_warned() {
    // The heavy top spins at 150 rad/s; `--dt 0.05` is capped at the row spacing (every = 0.01 s), so each RK4
    // step turns the body by 1.5 rad, and T + V, conserved by a top on a fixed pivot, drifts by about 8 %.
    let dir = tempfile::tempdir().unwrap();
    let top_with_rk4 = |dt: &str, csv: &Path| {
        let top = scenario("heavy_top");
        let out = eulerdyn(["run", &top, "--method", "rk4", "--dt", dt, "-o", text(csv)]);
        out.expect_code(0);
        out
    };
    let coarse = dir.path().join("coarse.csv");
    let out = top_with_rk4("0.05", &coarse);
    contains_all(
        &out.stderr,
        &[
            "warning: a fixed step of 0.01 s turns the body by 1.5 rad",
            "warning: the energy T + V",
            "500 steps of 0.01 s",
        ],
    );
    let meta = sidecar_of(&coarse);
    assert_eq!(meta["solver"]["dt"], 0.05);
    assert_eq!(meta["solver"]["step_used"], 0.01);
    assert_eq!(meta["warnings"].as_array().map(Vec::len), Some(2), "{meta}");
    let drift = meta["statistics"]["energy_drift"].as_f64().unwrap();
    assert!(drift > 0.01, "energy drift {drift}");

    // A step of 0.5 ms turns it by 0.075 rad: no warning, and the energy holds.
    let fine = dir.path().join("fine.csv");
    let out = top_with_rk4("0.0005", &fine);
    assert!(!out.stderr.contains("warning"), "{}", out.stderr);
    let meta = sidecar_of(&fine);
    assert_eq!(meta["warnings"].as_array().map(Vec::len), Some(0));
    assert!(meta["statistics"]["energy_drift"].as_f64().unwrap() < 1e-3);

    // `check` reports the step taken and warns before the run.
    let scene = std::fs::read_to_string(scenario("heavy_top"))
        .unwrap()
        .replace("method = \"dop853\"", "method = \"rk4\"\ndt = 0.05");
    let path = write_file(dir.path(), "rk4_top.toml", scene);
    let out = eulerdyn(["check", text(&path)]);
    out.expect_code(0);
    contains_all(
        &out.stdout,
        &[
            "fixed step dt = 0.05 s",
            "steps of 0.01 s are taken",
            "500 steps of 0.01 s",
            "warning",
        ],
    );
}

#[test]
fn no_bundled_scenario_is_warned_of_but_the_tennis_racket() {
    for path in bundled_scenarios() {
        let out = eulerdyn(["check", text(&path)]);
        out.expect_code(0);
        // Only the tennis racket is warned of, by design: it starts near the separatrix.
        let warnings: Vec<&str> = out
            .stdout
            .lines()
            .filter(|l| l.starts_with("warning"))
            .collect();
        let expected = usize::from(path.ends_with("tennis_racket.toml"));
        assert_eq!(
            warnings.len(),
            expected,
            "{}:\n{}",
            path.display(),
            out.stdout
        );
    }
}

#[test]
fn check_warns_of_values_that_look_like_unit_slips() {
    let dir = tempfile::tempdir().unwrap();
    let disk = std::fs::read_to_string(scenario("tilted_disk")).unwrap();
    let cases = [
        (
            disk.replace("radius = 0.3 }", "radius = 300.0 }"),
            "body.shape.radius = 300 m: a body over 100 m across; if millimetres were meant, write 0.3 m",
        ),
        (
            disk.replace("tilt_deg = 30 ", "tilt_deg = 0.5236 "),
            "motion.tilt_deg = 0.5236 is 0.5236 degrees; if radians were meant, that is 30.0 degrees",
        ),
    ];
    for (k, (scene_text, warning)) in cases.iter().enumerate() {
        assert_ne!(scene_text, &disk, "case {k}: the scene was not changed");
        let path = write_file(dir.path(), &format!("slip{k}.toml"), scene_text);
        let out = eulerdyn(["check", path.to_str().unwrap()]);
        out.expect_code(0);
        assert!(out.stdout.contains(warning), "{}", out.stdout);
    }
    // The notes' disk as written: no warning.
    let out = eulerdyn(["check", &scenario("tilted_disk")]);
    assert!(!out.stdout.contains("warning"), "{}", out.stdout);
}

#[test]
fn check_warns_of_an_initial_omega_near_the_separatrix() {
    // The tennis racket: I = (1, 2, 3), ω0 = (0.001, 2, 0.001): H² − 2E·I₂ = 2e-6, 2E·(I₃ − I₁) = 16.000008, so
    // δ = 1.25e-7 (Landau & Lifshitz §37: the separatrix is H² = 2E·I₂).
    let out = eulerdyn(["check", &scenario("tennis_racket")]);
    out.expect_code(0);
    contains_all(&out.stdout, &["near the separatrix", "= 1.25e-7"]);
    // The benchmark body, ω0 = (0.3, 0, 2): δ = (36.09 − 24.18)/(12.09·2) = 0.49, far from it.
    let out = eulerdyn(["check", &scenario("asymmetric_free")]);
    assert!(!out.stdout.contains("separatrix"), "{}", out.stdout);
}

#[test]
fn run_and_sweep_warn_of_unit_slips_where_the_run_is_and_the_sidecar_lists_them() {
    let dir = tempfile::tempdir().unwrap();
    let disk = std::fs::read_to_string(scenario("tilted_disk")).unwrap();
    let slip = disk.replace("tilt_deg = 30 ", "tilt_deg = 0.5236 ");
    assert_ne!(slip, disk, "the scenario sets tilt_deg = 30");
    let scene = write_file(dir.path(), "slip.toml", &slip);
    let csv = dir.path().join("slip.csv");
    let out = eulerdyn(["run", text(&scene), "-o", text(&csv)]);
    out.expect_code(0);
    let warning =
        "motion.tilt_deg = 0.5236 is 0.5236 degrees; if radians were meant, that is 30.0 degrees";
    assert!(
        out.stderr
            .contains(&format!("slip.toml: warning: {warning}")),
        "{}",
        out.stderr
    );
    let sidecar = eulerdyn::output::Sidecar::read(&csv).unwrap();
    assert!(
        sidecar.warnings.iter().any(|w| w == warning),
        "{:?}",
        sidecar.warnings
    );
    // To stdout too: the warning is on stderr, the CSV clean.
    let out = eulerdyn(["run", text(&scene)]);
    out.expect_code(0);
    assert!(out.stderr.contains(warning) && !out.stdout.contains("warning"));
    // A sweep of it says so once, for its base scene.
    let sweep = write_file(
        dir.path(),
        "sweep.toml",
        "scene = \"slip.toml\"\n[[vary]]\nkey = \"motion.rate\"\nvalues = [5.0, 10.0, 20.0]\n",
    );
    let out = eulerdyn(["sweep", text(&sweep), "-o", text(&dir.path().join("s.csv"))]);
    out.expect_code(0);
    assert_eq!(out.stderr.matches(warning).count(), 1, "{}", out.stderr);
    // A real rotor's skew of 1° is not a slip.
    let skew = write_file(
        dir.path(),
        "skew.toml",
        disk.replace("tilt_deg = 30 ", "tilt_deg = 1.0 "),
    );
    let out = eulerdyn(["run", text(&skew)]);
    out.expect_code(0);
    assert!(!out.stderr.contains("radians"), "{}", out.stderr);
    let out = eulerdyn(["check", text(&skew)]);
    assert!(!out.stdout.contains("warning"), "{}", out.stdout);
}

#[test]
fn rate_rpm_is_the_rate_in_revolutions_per_minute_and_both_is_an_error() {
    let dir = tempfile::tempdir().unwrap();
    let disk = std::fs::read_to_string(scenario("tilted_disk")).unwrap();
    assert!(
        disk.contains("rate = 10.0"),
        "the scenario spins at 10 rad/s"
    );
    // 3000 rpm = 3000 · 2π/60 rad/s = 100π rad/s.
    let rad_s = 3000.0 * std::f64::consts::TAU / 60.0;
    let by_rad_s = write_file(
        dir.path(),
        "rad_s.toml",
        disk.replace("rate = 10.0", &format!("rate = {rad_s:?}")),
    );
    let by_rpm = write_file(
        dir.path(),
        "rpm.toml",
        disk.replace("rate = 10.0", "rate_rpm = 3000.0"),
    );
    let a = eulerdyn(["run", text(&by_rad_s)]);
    let b = eulerdyn(["run", text(&by_rpm)]);
    a.expect_code(0);
    b.expect_code(0);
    assert_eq!(a.stdout, b.stdout, "the same CSV");
    let both = write_file(
        dir.path(),
        "both.toml",
        disk.replace("rate = 10.0", "rate = 10.0\nrate_rpm = 3000.0"),
    );
    let out = eulerdyn(["check", text(&both)]);
    out.expect_code(2);
    assert!(
        out.stderr.contains("key `motion.rate_rpm`") && out.stderr.contains("not both"),
        "{}",
        out.stderr
    );
}
