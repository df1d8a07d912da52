//! Committed figures do not go stale and runs are bit-reproducible: docs/make_gallery.sh, run with this build's
//! binary into a temporary directory, remakes every committed figure of the README's gallery byte for byte (the
//! timed work-precision figure aside), and the same binary and input give the same bytes twice.

use std::path::Path;
use std::process::Command;

use eulerdyn::scene::{Overrides, load};
use eulerdyn::wheels::AttitudePd;
use nalgebra::{UnitQuaternion, Vector3};

use crate::common::{eulerdyn, repo_path};

/// The run of examples/wheel_slew.rs (the same scene and law, made here with this build's library rather than by
/// the example's own binary, which `cargo test --test it` does not rebuild) written to `out`.
fn write_slew(out: &Path) {
    let target = UnitQuaternion::from_euler_angles(0.6, -0.4, 0.9);
    let pd = AttitudePd::new(
        target,
        0.6,
        3.0,
        vec![Vector3::x(), Vector3::y(), Vector3::z()],
    );
    let scene = load(
        &repo_path("scenarios/slew_three_wheels.toml"),
        &Overrides::default(),
    )
    .unwrap()
    .with_wheel_law("pd_slew", pd)
    .unwrap();
    eulerdyn::output::write_run(&scene, out).unwrap();
}

#[test]
fn the_gallery_script_remakes_the_committed_figures_byte_for_byte() {
    let dir = tempfile::tempdir().unwrap();
    let slew = tempfile::tempdir().unwrap();
    let slew_csv = slew.path().join("slew.csv");
    write_slew(&slew_csv);
    let status = Command::new("sh")
        .arg(repo_path("docs/make_gallery.sh"))
        .current_dir(repo_path(""))
        .env("EULERDYN", env!("CARGO_BIN_EXE_eulerdyn"))
        .env("GALLERY_DIR", dir.path())
        .env("GALLERY_FIGURES_ONLY", "1")
        .env("SLEW_CSV", &slew_csv)
        .status()
        .expect("sh runs");
    assert!(status.success(), "docs/make_gallery.sh failed");
    let mut made: Vec<_> = std::fs::read_dir(dir.path())
        .unwrap()
        .map(|e| e.unwrap().file_name().into_string().unwrap())
        .collect();
    made.sort();
    assert_eq!(
        made,
        [
            "cubesat_b_dot.svg",
            "explorer1.svg",
            "gravity_gradient_boom.svg",
            "heavy_top.svg",
            "motor_runup_bearings.svg",
            "slew_wheels.svg",
            "tennis_racket.svg",
            "tilted_disk_h.svg",
            "turbine_bearings.svg",
            "turbine_turn_bearings.svg"
        ]
    );
    for name in made {
        let fresh = std::fs::read(dir.path().join(&name)).unwrap();
        let committed = std::fs::read(repo_path(&format!("docs/{name}"))).unwrap();
        assert!(
            fresh == committed,
            "docs/{name} is stale: `sh docs/make_gallery.sh` remakes it differently"
        );
    }
}

#[test]
fn the_same_binary_and_input_give_the_same_bytes() {
    let dir = tempfile::tempdir().unwrap();
    for scene in ["tilted_disk", "tennis_racket", "heavy_top", "motor_runup"] {
        let scene_path = repo_path(&format!("scenarios/{scene}.toml"));
        let runs: Vec<Vec<u8>> = (0..2)
            .map(|k| {
                let out = dir.path().join(format!("{scene}_{k}.csv"));
                let (scene_text, out_text) = (scene_path.to_str().unwrap(), out.to_str().unwrap());
                eulerdyn(["run", scene_text, "-o", out_text]).expect_code(0);
                std::fs::read(out).unwrap()
            })
            .collect();
        assert!(
            runs[0] == runs[1],
            "{scene}: two runs wrote different bytes"
        );
    }
}
