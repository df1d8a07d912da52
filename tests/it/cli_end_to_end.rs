//! The `eulerdyn` binary end to end, against the outside contract (the book's developers/contract.md): CSV layout and
//! row times, number round-trips, the `-o` file and its sidecar, command-line overrides, output safety, `check`.

use std::path::Path;

use crate::common::{
    FREE_SCENE, bundled_scenarios, column, dir_entries, eulerdyn, eulerdyn_to, expected_times,
    header, read_csv, repo_path, write_file,
};
use serde_json::{Value, json};

/// The columns every run writes, in the contract's order.
const CONTRACT_COLUMNS: [&str; 25] = [
    "t",
    "q_w",
    "q_x",
    "q_y",
    "q_z",
    "omega_b_x",
    "omega_b_y",
    "omega_b_z",
    "omega_s_x",
    "omega_s_y",
    "omega_s_z",
    "H_b_x",
    "H_b_y",
    "H_b_z",
    "H_s_x",
    "H_s_y",
    "H_s_z",
    "M_b_x",
    "M_b_y",
    "M_b_z",
    "M_s_x",
    "M_s_y",
    "M_s_z",
    "energy",
    "H_norm",
];

/// The tilted disk (prescribed motion, C on the axis) adds these after the contract's columns.
/// The prescribed motion's columns, then the support's (the contract's "Rotation about an invariant axis").
/// `M_sup_s_*` (third round) are appended after all of them.
const DISK_EXTRA_COLUMNS: [&str; 13] = [
    "theta",
    "H_s_int_x",
    "H_s_int_y",
    "H_s_int_z",
    "theta_dot",
    "theta_ddot",
    "F_sup_s_x",
    "F_sup_s_y",
    "F_sup_s_z",
    "M_drive",
    "M_sup_s_x",
    "M_sup_s_y",
    "M_sup_s_z",
];

fn tilted_disk() -> String {
    repo_path("scenarios/tilted_disk.toml")
        .to_string_lossy()
        .into_owned()
}

/// Runs the tilted disk to stdout with extra arguments; returns the CSV text.
fn disk_csv(extra: &[&str]) -> String {
    let mut args = vec!["run".to_string(), tilted_disk()];
    args.extend(extra.iter().map(|s| s.to_string()));
    let out = eulerdyn(&args);
    out.expect_code(0);
    out.stdout
}

/// The `t` column of a CSV text, exactly as parsed.
fn times(text: &str) -> Vec<f64> {
    let (head, records) = read_csv(text);
    column(&head, &records, "t")
}

/// A path as command-line text (temporary paths are UTF-8).
fn text(path: &Path) -> &str {
    path.to_str().expect("a UTF-8 path")
}

/// Reads a sidecar file as JSON.
fn sidecar(path: &Path) -> Value {
    let text = std::fs::read_to_string(path).expect("the sidecar exists");
    serde_json::from_str(&text).expect("the sidecar is JSON")
}

/// Temporary files a writer may have left next to `out.csv`.
fn temp_leftovers(dir: &Path) -> Vec<String> {
    dir_entries(dir)
        .into_iter()
        .filter(|n| n.ends_with(".tmp") || n.starts_with('.'))
        .collect()
}

#[test]
fn run_to_stdout_has_the_contract_header_and_rows_at_k_times_every() {
    let text = disk_csv(&[]);
    let expected: Vec<&str> = CONTRACT_COLUMNS
        .iter()
        .chain(DISK_EXTRA_COLUMNS.iter())
        .copied()
        .collect();
    assert_eq!(header(&text), expected, "header row");
    assert!(
        !text.lines().any(|l| l.starts_with('#')),
        "no comment lines"
    );

    let (head, records) = read_csv(&text);
    assert_eq!(head, expected);
    for r in &records {
        assert_eq!(r.len(), expected.len(), "every row has every column");
    }
    // The scene: t_end = 1, every = 0.01.
    let t = column(&head, &records, "t");
    let want = expected_times(0.01, 1.0);
    assert_eq!(t.len(), 101);
    for (k, (got, want)) in t.iter().zip(&want).enumerate() {
        assert!(got == want, "row {k}: t = {got:?}, want exactly {want:?}");
    }
    for (k, got) in t[..t.len() - 1].iter().enumerate() {
        assert!(
            *got == k as f64 * 0.01,
            "row {k}: t = {got:?} is not k*every"
        );
    }
    assert!(*t.last().unwrap() == 1.0, "the last row is at t_end");
}

#[test]
fn a_t_end_that_is_not_a_multiple_of_every_ends_with_t_end_and_no_near_duplicate() {
    for (t_end, every, n) in [("0.995", 0.01, 101), ("0.3", 0.1, 4), ("0.25", 0.1, 4)] {
        let text = disk_csv(&["--t-end", t_end, "--every", &every.to_string()]);
        let t = times(&text);
        let t_end: f64 = t_end.parse().unwrap();
        assert_eq!(t.len(), n, "t_end {t_end}, every {every}: rows {t:?}");
        let want = expected_times(every, t_end);
        assert_eq!(t, want, "t_end {t_end}, every {every}");
        assert!(*t.last().unwrap() == t_end);
        let gap = t[t.len() - 1] - t[t.len() - 2];
        assert!(
            gap > 1e-9,
            "t_end {t_end}: near-duplicate last rows {:?}",
            &t[t.len() - 2..]
        );
        assert!(t.windows(2).all(|w| w[0] < w[1]), "strictly increasing");
    }
}

#[test]
fn t_end_zero_gives_one_row_at_zero() {
    let text = disk_csv(&["--t-end", "0"]);
    let (head, records) = read_csv(&text);
    assert_eq!(records.len(), 1, "{text}");
    assert!(column(&head, &records, "t")[0] == 0.0);
}

#[test]
fn every_value_round_trips_through_its_text() {
    let text = disk_csv(&["--t-end", "0.3", "--every", "0.01"]);
    let (_, records) = read_csv(&text);
    let mut buffer = ryu::Buffer::new();
    for (row, record) in records.iter().enumerate() {
        for field in record {
            let value: f64 = field
                .parse()
                .unwrap_or_else(|e| panic!("row {row}: {field:?} is not a number: {e}"));
            assert!(value.is_finite(), "row {row}: {field}");
            let ryu_text = buffer.format_finite(value);
            let debug_text = format!("{value:?}");
            assert!(
                ryu_text == field || debug_text == field,
                "row {row}: {field:?} is not the shortest round-trip text ({ryu_text:?})"
            );
        }
    }
    // k*every computed, never summed: 3 * 0.1 is 0.30000000000000004, and it is written so.
    let t = times(&disk_csv(&["--t-end", "0.5", "--every", "0.1"]));
    assert!(t[3] == 3.0 * 0.1);
    assert!(t[3] != 0.3);
}

#[test]
fn dash_output_means_stdout() {
    let out = eulerdyn(["run", &tilted_disk(), "-o", "-", "--t-end", "0.1"]);
    out.expect_code(0);
    assert_eq!(times(&out.stdout), expected_times(0.01, 0.1));
}

#[test]
fn output_file_gets_csv_and_sidecar_and_nothing_else() {
    let dir = tempfile::tempdir().unwrap();
    let csv_path = dir.path().join("out.csv");
    let out = eulerdyn(["run", &tilted_disk(), "-o", text(&csv_path)]);
    out.expect_code(0);
    assert!(out.stdout.is_empty(), "stdout stays empty: {}", out.stdout);
    assert_eq!(dir_entries(dir.path()), ["out.csv", "out.csv.meta.json"]);

    let text = std::fs::read_to_string(&csv_path).unwrap();
    let (head, records) = read_csv(&text);
    assert_eq!(&head[..25], CONTRACT_COLUMNS);
    assert_eq!(records.len(), 101);

    let meta = sidecar(&dir.path().join("out.csv.meta.json"));
    assert_eq!(meta["eulerdyn_version"], env!("CARGO_PKG_VERSION"));
    let solver = &meta["solver"];
    assert_eq!(solver["method"], "dop853");
    assert_eq!(solver["rtol"].as_f64(), Some(1e-10));
    assert_eq!(solver["atol"].as_f64(), Some(1e-12));
    assert_eq!(solver["t_end"].as_f64(), Some(1.0));
    assert_eq!(solver["every"].as_f64(), Some(0.01));
    let stats = &meta["statistics"];
    let steps = stats["steps"].as_u64().expect("statistics.steps");
    let rejected = stats["rejected_steps"]
        .as_u64()
        .expect("statistics.rejected_steps");
    let evals = stats["rhs_evaluations"]
        .as_u64()
        .expect("statistics.rhs_evaluations");
    assert!(
        steps > 0 && evals >= steps,
        "steps {steps}, evaluations {evals}"
    );
    assert!(rejected <= steps);
    assert_eq!(stats["rows"].as_u64(), Some(records.len() as u64));
    assert!(
        meta["scene"]["text"]
            .as_str()
            .is_some_and(|s| s.contains("tilted-disk")),
        "the sidecar records the scene"
    );

    let columns = meta["columns"].as_array().expect("columns");
    let names: Vec<&str> = columns.iter().filter_map(|c| c["name"].as_str()).collect();
    assert_eq!(
        names, head,
        "a sidecar entry for every CSV column, in order"
    );
    for c in columns {
        let unit = c["unit"].as_str().unwrap_or("");
        assert!(!unit.is_empty(), "column {} has a unit", c["name"]);
    }
    let unit_of = |name: &str| {
        columns
            .iter()
            .find(|c| c["name"] == name)
            .and_then(|c| c["unit"].as_str())
            .unwrap_or("")
            .to_string()
    };
    assert_eq!(unit_of("t"), "s");
    assert_eq!(unit_of("omega_b_x"), "rad/s");
    assert_eq!(unit_of("M_s_z"), "N*m");
    assert_eq!(unit_of("energy"), "J");
    assert_eq!(unit_of("theta"), "rad");
}

#[test]
fn overrides_take_effect_and_are_recorded_in_the_sidecar() {
    let dir = tempfile::tempdir().unwrap();
    // Command-line flags, and the `solver` values the sidecar must then record.
    let cases: [(&[&str], Value); 4] = [
        (
            &["--method", "rk4", "--dt", "1e-3"],
            json!({"method": "rk4", "dt": 1e-3, "fixed_step": true}),
        ),
        (
            &["--frame", "body"],
            json!({"frame": "body", "method": "dop853"}),
        ),
        (
            &["--backend", "ode_solvers"],
            json!({"backend": "ode_solvers"}),
        ),
        (
            &[
                "--method", "dopri5", "--rtol", "1e-8", "--atol", "1e-10", "--t-end", "0.5",
                "--every", "0.05",
            ],
            json!({"method": "dopri5", "rtol": 1e-8, "atol": 1e-10, "t_end": 0.5, "every": 0.05}),
        ),
    ];
    for (i, (flags, recorded)) in cases.iter().enumerate() {
        let csv_path = dir.path().join(format!("out{i}.csv"));
        let mut args = vec![
            "run".to_string(),
            tilted_disk(),
            "-o".into(),
            csv_path.to_string_lossy().into_owned(),
        ];
        args.extend(flags.iter().map(|s| s.to_string()));
        let out = eulerdyn(&args);
        out.expect_code(0);
        let meta = sidecar(&dir.path().join(format!("out{i}.csv.meta.json")));
        for (key, want) in recorded.as_object().unwrap() {
            assert_eq!(&meta["solver"][key], want, "{flags:?}: solver.{key}");
        }
        let text = std::fs::read_to_string(&csv_path).unwrap();
        let (head, records) = read_csv(&text);
        assert_eq!(
            meta["statistics"]["rows"].as_u64(),
            Some(records.len() as u64)
        );
        // The disk's moment is steady: M_b_x = -1/4 m R^2 w^2 sin 30 cos 30 whatever the method and frame.
        let m_bx = column(&head, &records, "M_b_x");
        let want = -0.25 * 2.0 * 0.09 * 100.0 * 0.5 * 0.75f64.sqrt();
        assert!(
            m_bx.iter().all(|m| (m - want).abs() < 1e-6),
            "{flags:?}: M_b_x {:?} != {want}",
            &m_bx[..3]
        );
    }
    assert!(
        temp_leftovers(dir.path()).is_empty(),
        "{:?}",
        dir_entries(dir.path())
    );
}

#[test]
fn a_bad_scene_leaves_an_existing_output_untouched() {
    let dir = tempfile::tempdir().unwrap();
    let csv_path = write_file(dir.path(), "out.csv", b"precious,data\n1,2\n");
    let meta_path = write_file(dir.path(), "out.csv.meta.json", b"{\"old\": true}\n");
    let scene = write_file(
        dir.path(),
        "bad.toml",
        FREE_SCENE.replace("mass = 1.0", "mass = -1.0"),
    );
    let out = eulerdyn(["run", text(&scene), "-o", text(&csv_path)]);
    out.expect_code(2);
    assert!(out.stderr.contains("body.mass"), "{}", out.stderr);
    assert_eq!(std::fs::read(&csv_path).unwrap(), b"precious,data\n1,2\n");
    assert_eq!(std::fs::read(&meta_path).unwrap(), b"{\"old\": true}\n");
    assert_eq!(
        dir_entries(dir.path()),
        ["bad.toml", "out.csv", "out.csv.meta.json"]
    );
}

#[test]
fn a_missing_output_directory_is_bad_input_named_in_the_message() {
    let dir = tempfile::tempdir().unwrap();
    let csv_path = write_file(dir.path(), "out.csv", b"precious\n");
    let missing = dir.path().join("no_such_dir").join("out.csv");
    let out = eulerdyn(["run", &tilted_disk(), "-o", text(&missing)]);
    out.expect_code(2);
    assert!(
        out.stderr
            .contains(&*dir.path().join("no_such_dir").to_string_lossy()),
        "the message names the path: {}",
        out.stderr
    );
    assert!(out.stdout.is_empty());
    assert_eq!(std::fs::read(&csv_path).unwrap(), b"precious\n");
    assert_eq!(dir_entries(dir.path()), ["out.csv"]);
}

#[test]
fn an_output_path_that_is_a_directory_is_refused() {
    let dir = tempfile::tempdir().unwrap();
    let out = eulerdyn(["run", &tilted_disk(), "-o", text(dir.path())]);
    assert!(!out.panicked(), "{}", out.stderr);
    out.expect_code(2);
    assert!(
        out.stderr.contains(&*dir.path().to_string_lossy()),
        "{}",
        out.stderr
    );
    assert!(
        dir_entries(dir.path()).is_empty(),
        "{:?}",
        dir_entries(dir.path())
    );
}

#[test]
fn a_full_device_is_a_failed_run_not_a_panic() {
    // A full device made in a temporary directory (never the system's /dev/full through -o); needs root.
    let dir = tempfile::tempdir().unwrap();
    let Some(full) = crate::common::device_node(dir.path(), "full", "7") else {
        eprintln!("skipped: mknod is not permitted here (not root)");
        return;
    };
    let out = eulerdyn(["run", &tilted_disk(), "-o", text(&full)]);
    assert!(!out.panicked(), "{}", out.stderr);
    out.expect_code(1);
    assert!(out.stderr.contains(text(&full)), "{}", out.stderr);
    assert!(out.stderr.starts_with("error: "), "{}", out.stderr);
}

#[test]
fn a_full_stdout_is_a_failure_not_a_panic() {
    let Ok(full) = std::fs::File::options().write(true).open("/dev/full") else {
        return;
    };
    for args in [vec!["check", &tilted_disk()], vec!["run", &tilted_disk()]] {
        let out = eulerdyn_to(&args, full.try_clone().unwrap());
        assert!(!out.panicked(), "{args:?}: {}", out.stderr);
        assert_eq!(out.code, Some(1), "{args:?}: {}", out.stderr);
        assert!(out.stderr.contains("stdout"), "{}", out.stderr);
    }
}

#[test]
fn the_output_may_not_overwrite_the_scene() {
    let dir = tempfile::tempdir().unwrap();
    let scene = write_file(dir.path(), "scene.toml", FREE_SCENE);
    let same = dir.path().join(".").join("scene.toml");
    let out = eulerdyn(["run", text(&scene), "-o", text(&same)]);
    out.expect_code(2);
    assert!(out.stderr.contains("overwrite"), "{}", out.stderr);
    assert_eq!(std::fs::read_to_string(&scene).unwrap(), FREE_SCENE);
    assert_eq!(dir_entries(dir.path()), ["scene.toml"]);
}

#[test]
fn a_failed_run_leaves_an_existing_output_untouched() {
    // A fixed step far too large for a fast spin: either refused up front (2) or a failed run (1).
    let dir = tempfile::tempdir().unwrap();
    let csv_path = write_file(dir.path(), "out.csv", b"precious\n");
    let scene = write_file(
        dir.path(),
        "fast.toml",
        FREE_SCENE
            .replace("omega = [0.3, 0.0, 2.0]", "omega = [300.0, 1.0, 2000.0]")
            .replace("t_end = 1.0", "t_end = 10.0\nmethod = \"rk4\"\ndt = 0.5")
            .replace("every = 0.1", "every = 0.5"),
    );
    let out = eulerdyn(["run", text(&scene), "-o", text(&csv_path)]);
    assert!(!out.panicked(), "{}", out.stderr);
    assert!(
        matches!(out.code, Some(1 | 2)),
        "exit {:?}: {}",
        out.code,
        out.stderr
    );
    assert!(out.stderr.contains("error: "), "{}", out.stderr);
    assert_eq!(std::fs::read(&csv_path).unwrap(), b"precious\n");
    assert_eq!(dir_entries(dir.path()), ["fast.toml", "out.csv"]);
}

#[test]
fn check_accepts_every_shipped_scenario_and_describes_it() {
    let scenes = bundled_scenarios();
    for path in &scenes {
        let out = eulerdyn(["check", text(path)]);
        assert_eq!(out.code, Some(0), "{}: {}", path.display(), out.stderr);
        let text = out.stdout.to_lowercase();
        for what in ["principal moment", "center", "method"] {
            assert!(
                text.contains(what),
                "{}: no {what} in\n{}",
                path.display(),
                out.stdout
            );
        }
    }
    assert!(!scenes.is_empty(), "no bundled scenarios");
}

#[test]
fn check_prints_the_method_and_moment_center_of_the_disk() {
    let out = eulerdyn(["check", &tilted_disk()]);
    out.expect_code(0);
    assert!(out.stdout.contains("dop853"), "{}", out.stdout);
    assert!(
        out.stdout.contains("9.000000e-2"),
        "I3 = mR^2/2: {}",
        out.stdout
    );
}

#[test]
fn free_motion_conserves_energy() {
    let dir = tempfile::tempdir().unwrap();
    let scene = write_file(
        dir.path(),
        "free.toml",
        FREE_SCENE.replace("t_end = 1.0", "t_end = 10.0"),
    );
    let out = eulerdyn(["run", text(&scene)]);
    out.expect_code(0);
    let (head, records) = read_csv(&out.stdout);
    assert_eq!(&head[..], CONTRACT_COLUMNS, "free motion adds no columns");
    let t = column(&head, &records, "t");
    assert_eq!(t, expected_times(0.1, 10.0));
    let energy = column(&head, &records, "energy");
    let e0 = energy[0];
    // T = 1/2 (1 * 0.3^2 + 3 * 2^2)
    assert!((e0 - 0.5 * (0.09 + 12.0)).abs() < 1e-12, "energy(0) = {e0}");
    for (k, e) in energy.iter().enumerate() {
        assert!(
            ((e - e0) / e0).abs() < 1e-9,
            "t = {}: energy {e} drifted from {e0}",
            t[k]
        );
    }
    // Torque-free: M is zero, |H| constant.
    for name in ["M_b_x", "M_b_y", "M_b_z", "M_s_x", "M_s_y", "M_s_z"] {
        assert!(
            column(&head, &records, name).iter().all(|m| *m == 0.0),
            "{name}"
        );
    }
    let h = column(&head, &records, "H_norm");
    assert!(h.iter().all(|x| ((x - h[0]) / h[0]).abs() < 1e-9));
}
