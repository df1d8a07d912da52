//! Helpers shared by the tests: running the real `eulerdyn` binary, writing scenes into temporary directories,
//! checking what a run left on disk, and reading rows.

// Each test file uses its own subset of these helpers.
#![allow(dead_code)]

use std::ffi::OsStr;
use std::path::{Path, PathBuf};
use std::process::Command;

use eulerdyn::sample::Sample;
use eulerdyn::scene::{self, Overrides, Scene};

/// A free-motion scene: asymmetric body, torque-free, t_end = 1 s, a row every 0.1 s.
pub const FREE_SCENE: &str = r#"name = "free"

[body]
mass = 1.0
inertia = [1.0, 2.0, 3.0]

[initial]
omega = [0.3, 0.0, 2.0]

[solver]
t_end = 1.0

[output]
every = 0.1
"#;

/// What a run of the binary gave.
#[derive(Debug)]
pub struct Outcome {
    /// The exit code; `None` when a signal ended the process.
    pub code: Option<i32>,
    pub stdout: String,
    pub stderr: String,
}

impl Outcome {
    /// Panics with the whole outcome unless the exit code is `code`.
    pub fn expect_code(&self, code: i32) -> &Self {
        assert_eq!(
            self.code,
            Some(code),
            "expected exit code {code}\nstdout:\n{}\nstderr:\n{}",
            self.stdout,
            self.stderr
        );
        self
    }

    /// Whether the process panicked (exit 101 or a panic message).
    pub fn panicked(&self) -> bool {
        self.code == Some(101) || self.stderr.contains("panicked")
    }
}

/// Runs `eulerdyn` with `args` and collects its output.
pub fn eulerdyn<I, S>(args: I) -> Outcome
where
    I: IntoIterator<Item = S>,
    S: AsRef<OsStr>,
{
    let out = Command::new(env!("CARGO_BIN_EXE_eulerdyn"))
        .args(args)
        .output()
        .expect("the eulerdyn binary runs");
    Outcome {
        code: out.status.code(),
        stdout: String::from_utf8_lossy(&out.stdout).into_owned(),
        stderr: String::from_utf8_lossy(&out.stderr).into_owned(),
    }
}

/// Runs `eulerdyn` with `args` and its stdout sent to `stdout` (e.g. a file); collects stderr.
pub fn eulerdyn_to<I, S>(args: I, stdout: std::fs::File) -> Outcome
where
    I: IntoIterator<Item = S>,
    S: AsRef<OsStr>,
{
    let out = Command::new(env!("CARGO_BIN_EXE_eulerdyn"))
        .args(args)
        .stdout(stdout)
        .output()
        .expect("the eulerdyn binary runs");
    Outcome {
        code: out.status.code(),
        stdout: String::new(),
        stderr: String::from_utf8_lossy(&out.stderr).into_owned(),
    }
}

/// A file of the repository, e.g. `scenarios/tilted_disk.toml`.
pub fn repo_path(relative: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join(relative)
}

/// The bundled scenarios (`scenarios/*.toml`), in file-name order.
pub fn bundled_scenarios() -> Vec<PathBuf> {
    let mut scenes: Vec<PathBuf> = std::fs::read_dir(repo_path("scenarios"))
        .expect("the scenarios folder")
        .map(|e| e.expect("a directory entry").path())
        .filter(|p| p.extension().is_some_and(|x| x == "toml"))
        .collect();
    scenes.sort();
    scenes
}

/// Writes `text` to `dir/name` and returns the path.
pub fn write_file(dir: &Path, name: &str, text: impl AsRef<[u8]>) -> PathBuf {
    let path = dir.join(name);
    std::fs::write(&path, text).expect("the test can write its scene");
    path
}

/// The names of the entries of `dir`, sorted.
pub fn dir_entries(dir: &Path) -> Vec<String> {
    let mut names: Vec<String> = std::fs::read_dir(dir)
        .expect("the test directory is readable")
        .map(|e| {
            e.expect("a directory entry")
                .file_name()
                .to_string_lossy()
                .into_owned()
        })
        .collect();
    names.sort();
    names
}

/// The CSV header row of `text` (split on commas).
pub fn header(text: &str) -> Vec<String> {
    text.lines()
        .next()
        .unwrap_or("")
        .split(',')
        .map(str::to_string)
        .collect()
}

/// The header and the records of a CSV text, read with the `csv` crate.
pub fn read_csv(text: &str) -> (Vec<String>, Vec<csv::StringRecord>) {
    let mut reader = csv::Reader::from_reader(text.as_bytes());
    let head = reader
        .headers()
        .expect("a CSV header")
        .iter()
        .map(str::to_string)
        .collect();
    let records = reader
        .records()
        .collect::<Result<Vec<_>, _>>()
        .expect("well-formed CSV records");
    (head, records)
}

/// Runs `eulerdyn sweep SWEEP -o DIR/results.csv`, expecting exit 0, and reads the table.
pub fn sweep_table(sweep: &Path, dir: &Path) -> (Vec<String>, Vec<csv::StringRecord>) {
    let out = dir.join("results.csv");
    eulerdyn([
        "sweep",
        sweep.to_str().unwrap(),
        "-o",
        out.to_str().unwrap(),
    ])
    .expect_code(0);
    read_csv(&std::fs::read_to_string(&out).unwrap())
}

/// The values of the column `name`, parsed as f64.
pub fn column(head: &[String], records: &[csv::StringRecord], name: &str) -> Vec<f64> {
    let i = head
        .iter()
        .position(|h| h == name)
        .unwrap_or_else(|| panic!("no column {name} in {head:?}"));
    records
        .iter()
        .map(|r| r[i].parse::<f64>().expect("a number"))
        .collect()
}

/// The row times the contract prescribes: k·every (computed, not summed) for k·every < t_end, then t_end.
pub fn expected_times(every: f64, t_end: f64) -> Vec<f64> {
    let mut times = Vec::new();
    let mut k = 0u64;
    while (k as f64) * every < t_end {
        times.push(k as f64 * every);
        k += 1;
    }
    times.push(t_end);
    times
}

/// Times where ω_b[axis] changes sign, by linear interpolation between rows.
pub fn sign_changes(rows: &[Sample], axis: usize) -> Vec<f64> {
    rows.windows(2)
        .filter(|w| w[0].omega_b[axis].signum() != w[1].omega_b[axis].signum())
        .map(|w| {
            let (a, b) = (w[0].omega_b[axis], w[1].omega_b[axis]);
            w[0].t + (w[1].t - w[0].t) * a / (a - b)
        })
        .collect()
}

/// The scene of `text` with `overrides`; panics with the scene error (a test's own scene text is valid).
pub fn scene_from(text: &str, overrides: &Overrides) -> Scene {
    scene::parse(Path::new("test.toml"), text, overrides).unwrap_or_else(|e| panic!("{e}\n{text}"))
}

/// A character device node `dir/name` made with `mknod` (major 1: minor 3 is the null device, 7 the full device),
/// so that no test writes to a system device through `-o`; `None` where that is not permitted (not root).
pub fn device_node(dir: &Path, name: &str, minor: &str) -> Option<PathBuf> {
    let path = dir.join(name);
    let made = Command::new("mknod")
        .arg(&path)
        .args(["c", "1", minor])
        .output()
        .is_ok_and(|o| o.status.success());
    made.then_some(path)
}

/// Runs each case's scene text with `run -o` in a fresh directory and asserts exit 2, a message naming the file
/// (`scene.toml`) and the key, and nothing written beside the scene. A case is (name, scene text, key).
pub fn assert_refused_writing_nothing(cases: &[(&str, String, &str)]) {
    for (name, text, key) in cases {
        let dir = tempfile::tempdir().unwrap();
        let scene = write_file(dir.path(), "scene.toml", text);
        let out_csv = dir.path().join("out.csv");
        let out = eulerdyn([
            "run",
            scene.to_str().unwrap(),
            "-o",
            out_csv.to_str().unwrap(),
        ]);
        assert_eq!(out.code, Some(2), "{name}: {}", out.stderr);
        assert!(
            out.stderr.contains("scene.toml") && out.stderr.contains(key),
            "{name}: the message names the file and `{key}`: {}",
            out.stderr
        );
        assert_eq!(
            dir_entries(dir.path()),
            ["scene.toml"],
            "{name}: nothing written"
        );
    }
}

/// The mass (kg), spin (rad/s) and bearing positions along the axis (m) of [`disk_on_bearings`].
pub const DISK_M: f64 = 2.0;
/// See [`DISK_M`].
pub const DISK_SPIN: f64 = 100.0;
/// See [`DISK_M`].
pub const DISK_BEARINGS: (f64, f64) = (-0.1, 0.15);

/// A thin disk (mass [`DISK_M`], radius `radius`, symmetry axis body z along space x at t = 0) spinning at
/// [`DISK_SPIN`] on bearings at [`DISK_BEARINGS`] along its axis, in the carrier `carrier` (a TOML inline table), solved by dop853
/// at rtol = atol = 1e-12 for 4 s in `form`; `motion` and `effects` are further lines of `[motion]` and after it.
pub fn disk_on_bearings(
    name: &str,
    radius: f64,
    carrier: &str,
    (motion, effects): (&str, &str),
    form: eulerdyn::Form,
) -> String {
    format!(
        r#"name = "{name}"
[body]
mass = {DISK_M}
shape = {{ type = "thin_disk", radius = {radius} }}
[motion]
type = "fixed_axis"
axis = [0.0, 0.0, 1.0]
axis_in_space = [1.0, 0.0, 0.0]
{motion}rate = {DISK_SPIN}
bearings = [{}, {}]
carrier = {carrier}
{effects}[solver]
method = "dop853"
frame = "{}"
t_end = 4.0
rtol = 1e-12
atol = 1e-12
[output]
every = 0.05
"#,
        DISK_BEARINGS.0,
        DISK_BEARINGS.1,
        form.name()
    )
}

/// The rows of the scene `text`, simulated in memory.
pub fn rows_of(text: &str) -> Vec<Sample> {
    let scene = scene_from(text, &Overrides::default());
    eulerdyn::simulate::samples(&scene)
        .unwrap_or_else(|e| panic!("{e}"))
        .0
}

/// |a − b| ≤ 1e-9 (|b| + `scale`): relative to b, plus 1e-9 · `scale` for components that pass through zero.
pub fn assert_close_1e9(
    a: &nalgebra::Vector3<f64>,
    b: &nalgebra::Vector3<f64>,
    scale: f64,
    what: &str,
    t: f64,
) {
    assert!(
        (a - b).norm() <= 1e-9 * (b.norm() + scale),
        "{what} at t = {t}: {a} vs {b}"
    );
}
