//! Committed figures do not go stale and runs are bit-reproducible: docs/make_gallery.sh, run with this build's
//! binary into a temporary directory, remakes every committed figure of the README's gallery byte for byte (the
//! timed work-precision figure aside), and the same binary and input give the same bytes twice.

use std::process::Command;

use crate::common::{eulerdyn, repo_path};

#[test]
fn the_gallery_script_remakes_the_committed_figures_byte_for_byte() {
    let dir = tempfile::tempdir().unwrap();
    let status = Command::new("sh")
        .arg(repo_path("docs/make_gallery.sh"))
        .current_dir(repo_path(""))
        .env("EULERDYN", env!("CARGO_BIN_EXE_eulerdyn"))
        .env("GALLERY_DIR", dir.path())
        .env("GALLERY_FIGURES_ONLY", "1")
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
            "heavy_top.svg",
            "motor_runup_bearings.svg",
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
