//! The conformance suite: six scenes, each with its reference trajectory at 60 Hz (the closed form, or dop853 at
//! rtol 1e-13 where none applies), the setup an engine's adapter needs (JSON) and a note of what it tests
//! (the scene file's opening comment). `eulerdyn suite --out DIR` writes them; [`score_suite`] scores an engine's
//! outputs `DIR/ENGINE/<scene>.csv`.

use std::path::{Path, PathBuf};

use serde_json::json;

use super::{ReadOptions, Score, ScoreError, reference};
use crate::effects::TorqueGiven;
use crate::frames::Axes;
use crate::output::AtomicFile;
use crate::profile::Profile;
use crate::scene::{self, Overrides, Scene};

/// The rate of the reference rows and of the engines' runs (Hz).
pub const RATE_HZ: f64 = 60.0;

/// The suite's scenes: file stem and scene file.
pub const SCENES: [(&str, &str); 6] = [
    (
        "symmetric_precession",
        include_str!("scenes/symmetric_precession.toml"),
    ),
    ("tennis_racket", include_str!("scenes/tennis_racket.toml")),
    (
        "major_axis_spin",
        include_str!("scenes/major_axis_spin.toml"),
    ),
    ("fast_top", include_str!("scenes/fast_top.toml")),
    ("torque_pulse", include_str!("scenes/torque_pulse.toml")),
    ("full_tensor", include_str!("scenes/full_tensor.toml")),
];

/// The header of a suite trajectory (ω in body axes).
pub const HEADER: &str = "t,q_w,q_x,q_y,q_z,omega_x,omega_y,omega_z";

/// The scene `name` of the suite, parsed (its file named `DIR/<name>.toml` in messages).
fn parse(dir: &Path, name: &str, text: &str) -> Result<Scene, ScoreError> {
    scene::parse(
        &dir.join(format!("{name}.toml")),
        text,
        &Overrides::default(),
    )
    .map_err(|e| ScoreError::Input(e.to_string()))
}

/// The times k/[`RATE_HZ`] up to the scene's t_end.
pub fn times(scene: &Scene) -> Vec<f64> {
    let n = (scene.schedule.t_end() * RATE_HZ).round() as usize;
    (0..=n).map(|k| k as f64 / RATE_HZ).collect()
}

/// The reference trajectory of `scene` at 60 Hz, as CSV text ([`HEADER`]).
fn reference_csv(scene: &Scene, file: &str) -> Result<String, ScoreError> {
    let reference = reference::reference(scene, file, &times(scene))?;
    let mut out = format!("{HEADER}\n");
    for s in &reference.samples {
        let (q, w) = (s.q.quaternion(), s.omega_b);
        out.push_str(&format!(
            "{},{},{},{},{},{},{},{}\n",
            s.t, q.w, q.i, q.j, q.k, w.x, w.y, w.z
        ));
    }
    Ok(out)
}

/// What an engine's adapter needs to build the scene: mass, inertia about C (body axes), ω₀ (body axes), q₀
/// (w, x, y, z), gravity and the pivot from C (body axes), a torque pulse (space or body axes), t_end and rate.
pub fn setup(name: &str, scene: &Scene) -> serde_json::Value {
    let v = |x: &nalgebra::Vector3<f64>| [x.x, x.y, x.z];
    let inertia = scene.body.inertia_c();
    let omega0 = scene.motion.rigid_free().map(|(w, _)| v(w));
    let q = scene.attitude0.quaternion();
    let inertia_c_b = [0, 1, 2].map(|i| [0, 1, 2].map(|j| inertia[(i, j)]));
    let mut out = json!({
        "name": name,
        "t_end": scene.schedule.t_end(),
        "rate_hz": RATE_HZ,
        "mass": scene.body.mass(),
        "inertia_c_b": inertia_c_b,
        "omega0_b": omega0,
        "q0_wxyz": [q.w, q.i, q.j, q.k],
        "gravity_s": null,
        "pivot_from_c_b": null,
        "torque": null,
    });
    for effect in &scene.effects {
        if let Some((g_s, pivot_b)) = effect.gravity() {
            out["gravity_s"] = json!(v(&g_s));
            out["pivot_from_c_b"] = json!(v(&pivot_b));
        }
        if let Some(TorqueGiven {
            frame,
            value,
            profile,
        }) = effect.torque()
        {
            let (t_on, t_off) = match profile {
                Profile::Step { t_on, t_off } => (t_on, t_off),
                _ => (0.0, f64::INFINITY),
            };
            let frame = if frame == Axes::Space {
                "space"
            } else {
                "body"
            };
            out["torque"] =
                json!({"frame": frame, "value": v(&value), "t_on": t_on, "t_off": t_off});
        }
    }
    out
}

/// The note of a scene: its file's opening comment, without the `#`.
fn note(text: &str) -> String {
    (text.lines())
        .take_while(|l| l.starts_with('#'))
        .map(|l| l.trim_start_matches('#').trim())
        .collect::<Vec<_>>()
        .join(" ")
}

/// Writes the suite into `dir` (created if needed): per scene `<name>.toml`, `<name>.csv` (the reference at 60 Hz)
/// and `<name>.json` (the adapters' setup), and `README.md` (the notes). Nothing is written unless every file
/// could be made. Returns the paths written.
pub fn write_suite(dir: &Path) -> Result<Vec<PathBuf>, ScoreError> {
    let output = |p: &Path, e: std::io::Error| {
        ScoreError::Run(format!("{}: cannot write: {e}", p.display()))
    };
    // A folder that cannot be made or a file that cannot be created is bad input (exit 2), as for every output.
    let refused = |p: &Path, e: std::io::Error| {
        ScoreError::Input(format!("{}: cannot create: {e}", p.display()))
    };
    if dir.exists() && !dir.is_dir() {
        return Err(ScoreError::Input(format!(
            "{}: --out names a file; give a folder (new or existing) for the suite",
            dir.display()
        )));
    }
    std::fs::create_dir_all(dir).map_err(|e| refused(dir, e))?;
    let mut contents: Vec<(PathBuf, String)> = Vec::new();
    let mut readme = String::from(
        "# eulerdyn conformance suite\n\nEach scene: `NAME.toml` (the scene), `NAME.csv` (eulerdyn's reference at \
         60 Hz: t, attitude q body → space, ω in body axes), `NAME.json` (what an engine's adapter needs). Score an \
         engine's outputs `ENGINE/NAME.csv` with `eulerdyn score --suite DIR --engine ENGINE`.\n\n",
    );
    for (name, text) in SCENES {
        let scene = parse(dir, name, text)?;
        let csv_path = dir.join(format!("{name}.csv"));
        let csv = reference_csv(&scene, &csv_path.display().to_string())?;
        let setup = serde_json::to_string_pretty(&setup(name, &scene)).unwrap_or_default();
        readme.push_str(&format!("## {name}\n\n{}\n\n", note(text)));
        contents.push((dir.join(format!("{name}.toml")), text.to_string()));
        contents.push((csv_path, csv));
        contents.push((dir.join(format!("{name}.json")), setup + "\n"));
    }
    contents.push((dir.join("README.md"), readme));
    let mut files = Vec::new();
    for (path, text) in &contents {
        let file = AtomicFile::create(path).map_err(|e| refused(path, e))?;
        files.push(file.write(text.as_bytes()).map_err(|e| output(path, e))?);
    }
    AtomicFile::commit_all(files).map_err(|(i, e)| output(&contents[i].0, e))?;
    Ok(contents.into_iter().map(|(p, _)| p).collect())
}

/// Scores the outputs of `engine` in `DIR/ENGINE/<scene>.csv` against the suite's scenes in `dir`; a scene whose
/// output is missing is marked ([`Score::missing`]) and the others scored, each diagnosed when `diagnose`. No
/// output at all is bad input.
pub fn score_suite(
    dir: &Path,
    engine: &str,
    options: &ReadOptions,
    diagnose: bool,
) -> Result<Vec<Score>, ScoreError> {
    let mut scores = Vec::new();
    for (name, _) in SCENES {
        let scene_path = dir.join(format!("{name}.toml"));
        let scene = scene::load(&scene_path, &Overrides::default())
            .map_err(|e| ScoreError::Input(e.to_string()))?;
        let theirs = dir.join(engine).join(format!("{name}.csv"));
        if theirs.is_file() {
            scores.push(super::score_with(&theirs, &scene, options, diagnose)?);
        } else {
            scores.push(Score::missing(&theirs, name));
        }
    }
    if scores.iter().all(|s| s.missing) {
        return Err(ScoreError::Input(format!(
            "{}: no output of the engine for any scene of the suite (run its adapter first)",
            dir.join(engine).display()
        )));
    }
    Ok(scores)
}
