//! Output safety through the binary: an interrupted run, an unwritable directory and a diverging run leave no
//! partial output and an existing output untouched.

use std::path::Path;
use std::process::Command;
use std::time::{Duration, Instant};

const BIN: &str = env!("CARGO_BIN_EXE_eulerdyn");

/// A run of hours (1e10 RK4 steps of 1e-6 s up to t = 1e4 s): it is interrupted long before it ends.
const LONG_SCENE: &str = "[body]\nmass = 1.0\ninertia = [1.0, 2.0, 3.0]\n[initial]\nomega = [0.3, 0.0, 2.0]\n[solver]\nmethod = \"rk4\"\ndt = 1e-6\nt_end = 1e4\n[output]\nevery = 1.0\n";

fn leftovers(dir: &Path) -> Vec<String> {
    std::fs::read_dir(dir)
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .filter(|n| n.ends_with(".tmp"))
        .collect()
}

#[test]
fn sigint_leaves_no_partial_file_and_the_old_output_untouched() {
    let dir = tempfile::tempdir().unwrap();
    let scene = dir.path().join("long.toml");
    std::fs::write(&scene, LONG_SCENE).unwrap();
    let out = dir.path().join("out.csv");
    std::fs::write(&out, "previous contents\n").unwrap();
    let child = Command::new(BIN)
        .args(["run", scene.to_str().unwrap(), "-o", out.to_str().unwrap()])
        .stderr(std::process::Stdio::piped())
        .spawn()
        .unwrap();
    // Wait until the run is writing (its temporary file exists), then interrupt it.
    let start = Instant::now();
    while leftovers(dir.path()).is_empty() {
        assert!(
            start.elapsed() < Duration::from_secs(30),
            "the run never started writing"
        );
        std::thread::sleep(Duration::from_millis(20));
    }
    let status = Command::new("kill")
        .args(["-INT", &child.id().to_string()])
        .status()
        .unwrap();
    assert!(status.success());
    let output = child.wait_with_output().unwrap();
    assert_eq!(
        output.status.code(),
        Some(130),
        "exit code of an interrupted run"
    );
    let stderr = String::from_utf8_lossy(&output.stderr);
    assert!(stderr.contains("interrupted"), "{stderr}");
    assert_eq!(
        std::fs::read_to_string(&out).unwrap(),
        "previous contents\n"
    );
    assert!(
        leftovers(dir.path()).is_empty(),
        "{:?}",
        leftovers(dir.path())
    );
    assert!(!dir.path().join("out.csv.meta.json").exists());
}

#[test]
fn an_unwritable_directory_is_bad_input_and_creates_nothing() {
    // /sys refuses new files to every user, root included (unlike a chmod'ed directory).
    let output = Command::new(BIN)
        .args([
            "run",
            "scenarios/tilted_disk.toml",
            "-o",
            "/sys/eulerdyn-out.csv",
        ])
        .output()
        .unwrap();
    assert_eq!(output.status.code(), Some(2));
    let stderr = String::from_utf8_lossy(&output.stderr);
    assert!(
        stderr.contains("/sys/eulerdyn-out.csv") && stderr.contains("cannot create"),
        "{stderr}"
    );
    assert!(!Path::new("/sys/eulerdyn-out.csv").exists());
}

#[test]
fn a_diverging_run_stops_with_the_time_and_a_hint_and_writes_nothing() {
    // RK4 with dt = 0.5 s on a spin of 100 rad/s (|ω| dt = 50, far outside RK4's stability region ~2.8).
    let dir = tempfile::tempdir().unwrap();
    let scene = dir.path().join("fast.toml");
    std::fs::write(
        &scene,
        "[body]\nmass = 1.0\ninertia = [1.0, 2.0, 3.0]\n[initial]\nomega = [0.3, 100.0, 2.0]\n[solver]\nmethod = \"rk4\"\ndt = 0.5\nt_end = 1000.0\n[output]\nevery = 1.0\n",
    )
    .unwrap();
    let out = dir.path().join("out.csv");
    std::fs::write(&out, "previous contents\n").unwrap();
    let output = Command::new(BIN)
        .args(["run", scene.to_str().unwrap(), "-o", out.to_str().unwrap()])
        .output()
        .unwrap();
    assert_eq!(output.status.code(), Some(1));
    let stderr = String::from_utf8_lossy(&output.stderr);
    assert!(stderr.contains("t = "), "no time in: {stderr}");
    assert!(
        stderr.contains("dt") || stderr.contains("adaptive"),
        "no hint in: {stderr}"
    );
    assert_eq!(
        std::fs::read_to_string(&out).unwrap(),
        "previous contents\n"
    );
    assert!(leftovers(dir.path()).is_empty());
}
