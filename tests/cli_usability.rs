//! The first hour of a new user: `--help` of every command with an example, `--version`, what `check` prints,
//! data on stdout and messages on stderr, `--quiet`, and no progress bar when stderr is not a terminal.

mod common;

use std::path::Path;

use common::{FREE_SCENE, eulerdyn, repo_path, write_file};

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
