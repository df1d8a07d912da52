//! The output policy of every command with `-o` (README, "Errors and exit codes"; CONTRACT "Output paths"), through
//! the binary, for each kind of destination:
//! - a FIFO stays a FIFO and its reader gets the bytes the command writes to a regular file;
//! - a symlink stays a link and its target, in another directory, holds the output (the run's sidecar goes beside
//!   the path named, the link);
//! - a null device (made with `mknod` in a temporary directory) stays a device and the command exits 0;
//! - a full device stays a device and the command fails naming it;
//! - nothing is written beside a FIFO or a device (no sidecar, no temporary file).
//!
//! Device nodes need root; elsewhere the device cases are skipped, saying so on stderr, and the FIFO and symlink
//! cases still cover the policy. No test writes to a system device path: every node is made in a temporary
//! directory.

use std::io::Read;
use std::os::unix::fs::FileTypeExt;
use std::path::{Path, PathBuf};
use std::process::Command;

use crate::common::{
    FREE_SCENE, Outcome, device_node, dir_entries, eulerdyn, repo_path, write_file,
};

/// A path as command-line text (temporary paths are UTF-8).
fn text(path: &Path) -> &str {
    path.to_str().expect("a UTF-8 path")
}

/// A command with one output file: its arguments, with [`OUT`] where the output path goes.
struct Case {
    name: &'static str,
    args: Vec<String>,
    /// The output's extension, for the regular file and the symlink (`plot` chooses SVG or PNG by it).
    extension: &'static str,
    /// The command writes a sidecar `OUT.meta.json` beside a regular destination (`run`).
    sidecar: bool,
    /// The output holds wall times (a table's `wall_s`, a work-precision figure): compared by its shape only.
    timed: bool,
}

/// Stands for the output path in [`Case::args`].
const OUT: &str = "{OUT}";

impl Case {
    fn new(name: &'static str, args: &[&str], extension: &'static str) -> Self {
        Self {
            name,
            args: args.iter().map(|a| a.to_string()).collect(),
            extension,
            sidecar: false,
            timed: false,
        }
    }

    /// Runs the command writing to `out`.
    fn run(&self, out: &Path) -> Outcome {
        let args: Vec<&str> = self
            .args
            .iter()
            .map(|a| if a == OUT { text(out) } else { a.as_str() })
            .collect();
        let outcome = eulerdyn(&args);
        assert!(!outcome.panicked(), "{}: {}", self.name, outcome.stderr);
        outcome
    }

    /// The output's bytes in a form two runs agree on: for a timed CSV table, the columns `wall_s` and `repeats`
    /// blanked; for a timed figure, whether it is one complete SVG document.
    fn comparable(&self, bytes: &[u8]) -> String {
        let text = String::from_utf8_lossy(bytes).into_owned();
        if !self.timed {
            return text;
        }
        if text.starts_with("<svg") || text.starts_with("<?xml") {
            let complete = text.trim_end().ends_with("</svg>");
            return format!("an SVG document, complete: {complete}");
        }
        let mut lines = text.lines();
        let header: Vec<&str> = lines.next().unwrap_or("").split(',').collect();
        let timed: Vec<usize> = header
            .iter()
            .enumerate()
            .filter(|(_, h)| matches!(**h, "wall_s" | "repeats"))
            .map(|(i, _)| i)
            .collect();
        let mut out = header.join(",") + "\n";
        for line in lines {
            let cells: Vec<&str> = line
                .split(',')
                .enumerate()
                .map(|(i, c)| if timed.contains(&i) { "" } else { c })
                .collect();
            out += &(cells.join(",") + "\n");
        }
        out
    }
}

/// What the command writes to a new regular file `dir/out.EXT`, which is all it leaves there (and its sidecar).
fn regular_output(case: &Case, dir: &Path) -> Vec<u8> {
    let out = dir.join(format!("out.{}", case.extension));
    case.run(&out).expect_code(0);
    let mut expected = vec![format!("out.{}", case.extension)];
    if case.sidecar {
        expected.push(format!("out.{}.meta.json", case.extension));
    }
    assert_eq!(dir_entries(dir), expected, "{}", case.name);
    std::fs::read(&out).expect("the output exists")
}

/// A fresh directory `parent/name`.
fn subdir(parent: &Path, name: &str) -> PathBuf {
    let dir = parent.join(name);
    std::fs::create_dir(&dir).expect("a directory");
    dir
}

/// A FIFO with a reader thread: the command's output reaches the reader, byte for byte as in a regular file, the
/// FIFO stays a FIFO and nothing is written beside it.
fn check_fifo(case: &Case, work: &Path, reference: &[u8]) {
    let dir = subdir(work, "fifo");
    let fifo = dir.join("out");
    let made = Command::new("mkfifo")
        .arg(&fifo)
        .status()
        .expect("mkfifo runs");
    assert!(made.success(), "mkfifo {}", fifo.display());
    // The test holds the FIFO open for writing too (on Linux, opening a FIFO for reading and writing does not
    // wait), and opens the reader's end before the command starts (which then does not wait either), so that
    // the reader never waits forever, whatever the command does: it reads to the end once both the command and
    // the test have closed their ends.
    let keeper = std::fs::File::options()
        .read(true)
        .write(true)
        .open(&fifo)
        .expect("the FIFO opens");
    let mut reading = std::fs::File::open(&fifo).expect("the reader's end opens");
    let reader = std::thread::spawn(move || {
        let mut bytes = Vec::new();
        reading
            .read_to_end(&mut bytes)
            .expect("the reader reads to the end");
        bytes
    });
    let outcome = case.run(&fifo);
    drop(keeper);
    let received = reader.join().expect("the reader thread");
    outcome.expect_code(0);
    assert_eq!(
        case.comparable(&received),
        case.comparable(reference),
        "{}: the reader gets what a regular file gets",
        case.name
    );
    let kind = std::fs::symlink_metadata(&fifo).expect("there").file_type();
    assert!(kind.is_fifo(), "{}: still a FIFO", case.name);
    assert_eq!(dir_entries(&dir), ["out"], "{}", case.name);
}

/// A symlink to a file in another directory: the link is kept, its target holds the output, nothing else is
/// written beside the target, and a sidecar goes beside the link (the path named).
fn check_symlink(case: &Case, work: &Path, reference: &[u8]) {
    let (links, data) = (subdir(work, "links"), subdir(work, "data"));
    let target_name = format!("target.{}", case.extension);
    write_file(&data, &target_name, "old contents\n");
    let link_name = format!("out.{}", case.extension);
    let link = links.join(&link_name);
    let pointing = format!("../data/{target_name}");
    std::os::unix::fs::symlink(&pointing, &link).expect("a link");
    case.run(&link).expect_code(0);
    assert!(link.is_symlink(), "{}: still a link", case.name);
    assert_eq!(
        std::fs::read_link(&link).expect("a link"),
        Path::new(&pointing)
    );
    let written = std::fs::read(data.join(&target_name)).expect("the target");
    assert_eq!(
        case.comparable(&written),
        case.comparable(reference),
        "{}: the target holds the output",
        case.name
    );
    assert_eq!(dir_entries(&data), [target_name], "{}", case.name);
    let mut beside_link = vec![link_name.clone()];
    if case.sidecar {
        let sidecar = links.join(format!("{link_name}.meta.json"));
        assert!(sidecar.is_file() && !sidecar.is_symlink(), "{}", case.name);
        beside_link.push(format!("{link_name}.meta.json"));
    }
    assert_eq!(dir_entries(&links), beside_link, "{}", case.name);
}

fn is_char_device(path: &Path) -> bool {
    std::fs::symlink_metadata(path).is_ok_and(|m| m.file_type().is_char_device())
}

/// A null device: exit 0, still a device, nothing beside it. A full device: the command fails naming it, the
/// device stays, nothing beside it. Skipped (said on stderr) where device nodes cannot be made.
fn check_devices(case: &Case, work: &Path) {
    let (null_dir, full_dir) = (subdir(work, "null"), subdir(work, "full"));
    let (Some(null), Some(full)) = (
        device_node(&null_dir, "null", "3"),
        device_node(&full_dir, "full", "7"),
    ) else {
        eprintln!(
            "{}: skipped the null- and full-device cases: mknod is not permitted here (not root); the FIFO and \
             symlink cases ran",
            case.name
        );
        return;
    };
    case.run(&null).expect_code(0);
    assert!(is_char_device(&null), "{}: still a device", case.name);
    assert_eq!(dir_entries(&null_dir), ["null"], "{}", case.name);

    let outcome = case.run(&full);
    assert!(
        matches!(outcome.code, Some(c) if c != 0),
        "{}: {outcome:?}",
        case.name
    );
    assert!(outcome.stderr.starts_with("error: "), "{}", outcome.stderr);
    assert!(
        outcome.stderr.contains(text(&full)) && outcome.stderr.contains("No space left"),
        "{}: names the device and the problem: {}",
        case.name,
        outcome.stderr
    );
    assert!(is_char_device(&full), "{}: still a device", case.name);
    assert_eq!(dir_entries(&full_dir), ["full"], "{}", case.name);
}

/// Every kind of destination for `case`.
fn check_policy(case: &Case) {
    let work = tempfile::tempdir().expect("a temporary directory");
    let reference = regular_output(case, &subdir(work.path(), "regular"));
    check_fifo(case, work.path(), &reference);
    check_symlink(case, work.path(), &reference);
    check_devices(case, work.path());
}

/// The free scene of the tests, in `dir`.
fn free_scene(dir: &Path) -> PathBuf {
    write_file(dir, "free.toml", FREE_SCENE)
}

/// A run's CSV and its sidecar in `dir`, for `plot` and `view`.
fn run_csv(dir: &Path) -> PathBuf {
    let csv = dir.join("run.csv");
    eulerdyn(["run", text(&free_scene(dir)), "-o", text(&csv), "-q"]).expect_code(0);
    csv
}

#[test]
fn run_follows_the_output_policy() {
    let inputs = tempfile::tempdir().expect("a temporary directory");
    let scene = free_scene(inputs.path());
    check_policy(&Case {
        sidecar: true,
        ..Case::new("run", &["run", text(&scene), "-q", "-o", OUT], "csv")
    });
}

#[test]
fn sweep_follows_the_output_policy() {
    let inputs = tempfile::tempdir().expect("a temporary directory");
    free_scene(inputs.path());
    let sweep = write_file(
        inputs.path(),
        "sweep.toml",
        "scene = \"free.toml\"\n[[vary]]\nkey = \"initial.omega.0\"\nvalues = [0.1, 0.2, 0.3]\n",
    );
    check_policy(&Case {
        timed: true,
        ..Case::new(
            "sweep",
            &["sweep", text(&sweep), "-q", "--jobs", "1", "-o", OUT],
            "csv",
        )
    });
}

/// A short study: the benchmark body, torque-free, 1 s.
fn study_scene(dir: &Path) -> PathBuf {
    write_file(
        dir,
        "study.toml",
        "[body]\nmass = 1.0\ninertia = [1.0, 2.0, 3.0]\n[initial]\nomega = [0.3, 0.0, 2.0]\n[solver]\nt_end = 1.0\n[output]\nevery = 0.5\n",
    )
}

#[test]
fn accuracy_table_follows_the_output_policy() {
    let inputs = tempfile::tempdir().expect("a temporary directory");
    let scene = study_scene(inputs.path());
    check_policy(&Case {
        timed: true,
        ..Case::new("accuracy -o", &["accuracy", text(&scene), "-o", OUT], "csv")
    });
}

#[test]
fn accuracy_figure_follows_the_output_policy() {
    let inputs = tempfile::tempdir().expect("a temporary directory");
    let scene = study_scene(inputs.path());
    check_policy(&Case {
        timed: true,
        ..Case::new(
            "accuracy --plot",
            &["accuracy", text(&scene), "--plot", OUT],
            "svg",
        )
    });
}

#[test]
fn plot_follows_the_output_policy() {
    let inputs = tempfile::tempdir().expect("a temporary directory");
    let csv = run_csv(inputs.path());
    check_policy(&Case::new(
        "plot",
        &["plot", text(&csv), "-q", "-o", OUT],
        "svg",
    ));
}

#[test]
fn view_follows_the_output_policy() {
    let inputs = tempfile::tempdir().expect("a temporary directory");
    let csv = run_csv(inputs.path());
    check_policy(&Case::new(
        "view",
        &["view", text(&csv), "-q", "-o", OUT],
        "html",
    ));
}

#[test]
fn balance_follows_the_output_policy() {
    let scene = repo_path("scenarios/rotor_bearings.toml");
    check_policy(&Case::new(
        "balance",
        &[
            "balance",
            text(&scene),
            "--planes",
            "-0.1,0.1",
            "--radius",
            "0.2",
            "-o",
            OUT,
        ],
        "toml",
    ));
}

#[test]
fn a_socket_is_refused_naming_it_and_stays_a_socket() {
    let dir = tempfile::tempdir().expect("a temporary directory");
    let scene = free_scene(dir.path());
    let socket = dir.path().join("out.sock");
    let _listener = std::os::unix::net::UnixListener::bind(&socket).expect("a socket");
    let outcome = eulerdyn(["run", text(&scene), "-o", text(&socket)]);
    outcome.expect_code(2);
    assert!(outcome.stderr.contains(text(&socket)), "{}", outcome.stderr);
    let kind = std::fs::symlink_metadata(&socket)
        .expect("there")
        .file_type();
    assert!(kind.is_socket());
    assert_eq!(dir_entries(dir.path()), ["free.toml", "out.sock"]);
}
