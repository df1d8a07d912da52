//! The run's sidecar (`RUN.csv.meta.json`) has one schema, written and read through `eulerdyn::output::Sidecar`,
//! and records the scene as simulated: a scene that leaves a key at its default and one that writes the default
//! out give the same CSV, the same sidecar scene and the same plots.

use std::path::Path;

use crate::common::{eulerdyn, write_file};
use eulerdyn::output::Sidecar;
use eulerdyn::scene::EffectSpec;

/// The bundled heavy top with `g` left at its default, and the same scene with every default the sidecar fills
/// in written out (gravity's g, the solver's form and backend, and `dt`, which an adaptive method does not use).
fn heavy_top_pair() -> (String, String) {
    let top = std::fs::read_to_string("scenarios/heavy_top.toml").expect("the bundled heavy top");
    let g = "g = [0.0, 0.0, -9.81]      # m/s^2, space axes\n";
    assert!(top.contains(g), "the scenario writes g out");
    let left_out = top.replace(g, "");
    let written_out = top.replace(
        "method = \"dop853\"\n",
        "method = \"dop853\"\nframe = \"body\"\nbackend = \"own\"\ndt = 0.001\n",
    );
    (left_out, written_out)
}

/// Runs `scene_text` from `dir/NAME.toml` to `dir/NAME.csv` and plots its drift panel and its default panels.
fn run_and_plot(dir: &Path, name: &str, scene_text: &str) -> (String, Sidecar, String, String) {
    let scene = write_file(dir, &format!("{name}.toml"), scene_text);
    let csv = dir.join(format!("{name}.csv"));
    let csv_arg = csv.to_str().expect("a UTF-8 path");
    eulerdyn(["run", scene.to_str().expect("a UTF-8 path"), "-o", csv_arg]).expect_code(0);
    let plot = |panels: &str, out: &str| {
        let out = dir.join(out);
        eulerdyn([
            "plot",
            csv_arg,
            "--panels",
            panels,
            "-o",
            out.to_str().expect("a UTF-8 path"),
        ])
        .expect_code(0);
        std::fs::read_to_string(out).expect("the figure")
    };
    let drift = plot("drift", &format!("{name}_drift.svg"));
    let h = plot("h_body,h_space,energy", &format!("{name}_h.svg"));
    let sidecar = Sidecar::read(&csv).expect("the sidecar reads back as its type");
    (
        std::fs::read_to_string(&csv).expect("the CSV"),
        sidecar,
        drift,
        h,
    )
}

#[test]
fn a_default_left_out_and_written_out_give_the_same_csv_sidecar_scene_and_plots() {
    let dir = tempfile::tempdir().expect("a temporary directory");
    let (left_out, written_out) = heavy_top_pair();
    let (csv_a, sidecar_a, drift_a, h_a) = run_and_plot(dir.path(), "a", &left_out);
    let (csv_b, sidecar_b, drift_b, h_b) = run_and_plot(dir.path(), "b", &written_out);
    assert_eq!(csv_a, csv_b, "the same CSV bytes");
    assert_eq!(
        sidecar_a.scene.spec, sidecar_b.scene.spec,
        "the same scene as simulated"
    );
    let g = match sidecar_a.scene.spec.effect[0] {
        EffectSpec::Gravity(gravity) => Some(gravity.g),
        _ => None,
    };
    assert_eq!(g, Some([0.0, 0.0, -9.81]), "the default g is written in");
    // The regression: with g left out the drift panel had dropped H_s,z, the heavy top's second invariant.
    assert!(
        drift_a.contains("H_s,z: relative"),
        "H_s,z on the drift panel"
    );
    assert_eq!(drift_a, drift_b, "the same drift panel");
    assert_eq!(h_a, h_b, "the same H and energy panels");
}

#[test]
fn the_sidecar_round_trips_through_its_type() {
    let dir = tempfile::tempdir().expect("a temporary directory");
    let (scene_text, _) = heavy_top_pair();
    let (_, sidecar, _, _) = run_and_plot(dir.path(), "top", &scene_text);
    let again = Sidecar::from_json(&sidecar.to_json()).expect("reads back");
    assert_eq!(again, sidecar);
    assert_eq!(sidecar.scene.motion, eulerdyn::scene::MotionKind::Free);
    assert_eq!(sidecar.scene.effects, ["gravity"]);
    assert_eq!(sidecar.solver.method, "dop853");
    // The scene as simulated builds the same scene as the file.
    let rebuilt = sidecar.scene.spec.build().expect("a valid scene");
    assert_eq!(rebuilt.spec, sidecar.scene.spec, "resolving is idempotent");
}
