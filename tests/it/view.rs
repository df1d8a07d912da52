//! `eulerdyn view`: the page's data against the CSV, the decimation rule, and bad input (not a run, a missing or
//! broken sidecar, an output that cannot be written) — exit 2 with the file and the problem, no partial file. The
//! page in a real browser is tested by `tests/browser/test_view.py` (`.ci/browser-tests`).

use std::path::{Path, PathBuf};

use crate::common::{dir_entries, eulerdyn, repo_path, write_file};
use eulerdyn::output::view::{self, MAX_DRAWN_ROWS};

/// Runs `scenario` into `dir/name.csv` (with its sidecar) and returns the CSV's path.
fn run(dir: &Path, scenario: &str, name: &str) -> PathBuf {
    let csv = dir.join(format!("{name}.csv"));
    eulerdyn([
        "run".as_ref(),
        repo_path(scenario).as_os_str(),
        "-o".as_ref(),
        csv.as_os_str(),
    ])
    .expect_code(0);
    csv
}

/// `eulerdyn view CSV -o OUT`.
fn view_cmd(csv: &Path, out: &Path) -> crate::common::Outcome {
    eulerdyn([
        "view".as_ref(),
        csv.as_os_str(),
        "-o".as_ref(),
        out.as_os_str(),
    ])
}

/// The page's embedded data document.
fn page_data(html: &str) -> serde_json::Value {
    let start = html
        .find(r#"id="eulerdyn-data">"#)
        .expect("the page embeds its data")
        + r#"id="eulerdyn-data">"#.len();
    let end = start + html[start..].find("</script>").expect("closed");
    serde_json::from_str(&html[start..end]).expect("the data is JSON")
}

/// The page's rows, each number parsed from its text by `str::parse` (correctly rounded, as the browser's
/// `JSON.parse`; serde_json's own float parsing may be one ulp off).
fn raw_rows(html: &str) -> Vec<Vec<f64>> {
    let start = html.find(r#""rows":[["#).expect("rows") + r#""rows":[["#.len();
    let end = start + html[start..].find("]]").expect("end of rows");
    html[start..end]
        .split("],[")
        .map(|row| {
            row.split(',')
                .map(|x| x.parse::<f64>().expect("a number"))
                .collect()
        })
        .collect()
}

#[test]
fn the_page_carries_every_row_of_the_tilted_disk_bit_for_bit_and_its_shape() {
    let dir = tempfile::tempdir().expect("a temporary directory");
    let csv = run(dir.path(), "scenarios/tilted_disk.toml", "disk");
    let out = dir.path().join("disk.html");
    let outcome = view_cmd(&csv, &out);
    outcome.expect_code(0);
    assert!(outcome.stderr.contains("wrote"), "{}", outcome.stderr);
    assert!(!outcome.stderr.contains("warning"), "{}", outcome.stderr);
    assert_eq!(
        dir_entries(dir.path()),
        ["disk.csv", "disk.csv.meta.json", "disk.html"]
    );
    let html = std::fs::read_to_string(&out).expect("the page");
    assert!(html.starts_with("<!DOCTYPE html>"));
    assert!(
        html.contains("default-src 'none'"),
        "the CSP forbids requests"
    );
    assert!(html.contains("three.js"), "three.js is embedded");
    let data = page_data(&html);
    let columns: Vec<&str> = data["columns"]
        .as_array()
        .expect("columns")
        .iter()
        .map(|c| c.as_str().expect("a name"))
        .collect();
    let (head, records) = crate::common::read_csv(&std::fs::read_to_string(&csv).expect("csv"));
    let rows = raw_rows(&html);
    assert_eq!(rows.len(), records.len());
    for (row, record) in rows.iter().zip(&records) {
        for (k, name) in columns.iter().enumerate() {
            let i = head.iter().position(|h| h == name).expect("a CSV column");
            let expected: f64 = record[i].parse().expect("a number");
            let got = row[k];
            assert_eq!(
                got.to_bits(),
                expected.to_bits(),
                "{name}: {got} vs {expected}"
            );
        }
    }
    let geometry = &data["geometry"];
    assert_eq!(geometry["body"]["kind"], "thin_disk");
    assert_eq!(geometry["body"]["radius"], 0.3);
    assert_eq!(geometry["motion"], "fixed_axis");
    let axis = geometry["axis_b"].as_array().expect("the fixed axis");
    assert!((axis[1].as_f64().expect("y") + 0.5).abs() < 1e-12);
    assert_eq!(data["stride"], 1);
    assert_eq!(data["rows_in_run"], 101);
}

#[test]
fn long_runs_keep_every_s_th_row_and_the_last() {
    let dir = tempfile::tempdir().expect("a temporary directory");
    let csv = run(dir.path(), "scenarios/tilted_disk.toml", "disk");
    // 101 rows, at most 10 kept: ceil(101 / 8) = 13 > 10 >= ceil(101 / 16) = 7, so rows 0, 16, …, 96 and 100.
    let run = view::read_view_run(&csv, 10).expect("read");
    assert_eq!(run.rows.stride, 16);
    assert_eq!(run.rows.rows_in_run, 101);
    let t: Vec<f64> = (0..run.rows.len()).map(|k| run.rows.row(k)[0]).collect();
    let expected: Vec<f64> = [0, 16, 32, 48, 64, 80, 96, 100]
        .iter()
        .map(|&k| k as f64 * 0.01)
        .collect();
    assert_eq!(t.len(), expected.len());
    for (a, b) in t.iter().zip(&expected) {
        assert!((a - b).abs() < 1e-12, "{t:?}");
    }
    assert!(run.rows_note().contains("every 16th row"));
    assert_eq!(MAX_DRAWN_ROWS, 10_000);
}

#[test]
fn a_csv_that_is_not_a_run_is_refused_naming_the_file_and_the_missing_columns() {
    let dir = tempfile::tempdir().expect("a temporary directory");
    let csv = write_file(dir.path(), "prices.csv", "date,price\n2024-01-01,3.5\n");
    let out = dir.path().join("prices.html");
    let outcome = view_cmd(&csv, &out);
    outcome.expect_code(2);
    assert!(outcome.stderr.contains("prices.csv"), "{}", outcome.stderr);
    assert!(
        outcome
            .stderr
            .contains("not a run written by `eulerdyn run`"),
        "{}",
        outcome.stderr
    );
    assert!(
        outcome.stderr.contains("`q_w`") && outcome.stderr.contains("date,price"),
        "{}",
        outcome.stderr
    );
    assert_eq!(dir_entries(dir.path()), ["prices.csv"]);
}

#[test]
fn empty_files_bad_cells_and_missing_files_are_refused_with_where_and_what() {
    let dir = tempfile::tempdir().expect("a temporary directory");
    let out = dir.path().join("out.html");
    let empty = write_file(dir.path(), "empty.csv", "");
    let e = view_cmd(&empty, &out);
    e.expect_code(2);
    assert!(
        e.stderr.contains("empty.csv: the file is empty"),
        "{}",
        e.stderr
    );

    let good = run(dir.path(), "scenarios/tilted_disk.toml", "disk");
    let text = std::fs::read_to_string(&good).expect("csv");
    let mut lines: Vec<String> = text.lines().map(str::to_string).collect();
    lines[3] = format!("x{}", lines[3]);
    let bad = write_file(dir.path(), "bad.csv", lines.join("\n") + "\n");
    let e = view_cmd(&bad, &out);
    e.expect_code(2);
    assert!(
        e.stderr.contains("bad.csv: row 3 (line 4), column `t`"),
        "{}",
        e.stderr
    );

    let missing = dir.path().join("nowhere.csv");
    let e = view_cmd(&missing, &out);
    e.expect_code(2);
    assert!(
        e.stderr.contains("nowhere.csv: cannot read the file"),
        "{}",
        e.stderr
    );
    assert!(!out.exists(), "no page for bad input");
}

#[test]
fn without_a_sidecar_the_page_draws_the_csv_and_says_so_on_stderr_and_in_the_page() {
    let dir = tempfile::tempdir().expect("a temporary directory");
    let csv = run(dir.path(), "scenarios/tilted_disk.toml", "disk");
    std::fs::remove_file(dir.path().join("disk.csv.meta.json")).expect("removed");
    let out = dir.path().join("disk.html");
    let outcome = view_cmd(&csv, &out);
    outcome.expect_code(0);
    assert!(
        outcome.stderr.contains("warning: there is no sidecar")
            && outcome.stderr.contains("disk.csv.meta.json"),
        "{}",
        outcome.stderr
    );
    let data = page_data(&std::fs::read_to_string(&out).expect("page"));
    assert_eq!(data["geometry"]["body"]["kind"], "unknown");
    let notes = data["notes"].to_string();
    assert!(
        notes.contains("no sidecar") && notes.contains("unit cube"),
        "{notes}"
    );
    assert_eq!(data["rows"].as_array().expect("rows").len(), 101);
}

#[test]
fn a_broken_sidecar_is_a_warning_not_a_failure() {
    let dir = tempfile::tempdir().expect("a temporary directory");
    let csv = run(dir.path(), "scenarios/tilted_disk.toml", "disk");
    write_file(dir.path(), "disk.csv.meta.json", "{ not json");
    let out = dir.path().join("disk.html");
    let outcome = view_cmd(&csv, &out);
    outcome.expect_code(0);
    assert!(
        outcome
            .stderr
            .contains("disk.csv.meta.json: the sidecar is not valid JSON"),
        "{}",
        outcome.stderr
    );
}

#[test]
fn an_output_that_cannot_be_written_is_bad_input_and_leaves_no_file() {
    let dir = tempfile::tempdir().expect("a temporary directory");
    let csv = run(dir.path(), "scenarios/tilted_disk.toml", "disk");
    let nowhere = dir.path().join("no_such_dir").join("disk.html");
    let e = view_cmd(&csv, &nowhere);
    e.expect_code(2);
    assert!(
        e.stderr
            .contains("no_such_dir/disk.html: cannot create the output file")
            && e.stderr.contains("does not exist"),
        "{}",
        e.stderr
    );
    // /sys refuses new files to every user, root included.
    let refused = Path::new("/sys/eulerdyn_view_test.html");
    let e = view_cmd(&csv, refused);
    e.expect_code(2);
    assert!(
        e.stderr
            .contains("/sys/eulerdyn_view_test.html: cannot create the output file"),
        "{}",
        e.stderr
    );
    let e = view_cmd(&csv, dir.path());
    e.expect_code(2);
    assert!(e.stderr.contains("is a directory"), "{}", e.stderr);
    assert_eq!(
        dir_entries(dir.path()),
        ["disk.csv", "disk.csv.meta.json"],
        "no temporary or partial file"
    );
}

#[test]
fn bad_input_leaves_an_existing_page_alone_and_the_csv_is_never_overwritten() {
    let dir = tempfile::tempdir().expect("a temporary directory");
    let out = write_file(dir.path(), "page.html", "old page");
    let csv = write_file(dir.path(), "x.csv", "t,a\n0,1\n");
    view_cmd(&csv, &out).expect_code(2);
    assert_eq!(std::fs::read_to_string(&out).expect("page"), "old page");
    let run_csv = run(dir.path(), "scenarios/tilted_disk.toml", "disk");
    let before = std::fs::read(&run_csv).expect("csv");
    let e = view_cmd(&run_csv, &run_csv);
    e.expect_code(2);
    assert!(e.stderr.contains("would overwrite the CSV"), "{}", e.stderr);
    assert_eq!(std::fs::read(&run_csv).expect("csv"), before);
}

#[test]
fn a_body_given_by_inertia_is_the_box_of_equal_moments_and_a_free_run_has_the_polhode_data() {
    let dir = tempfile::tempdir().expect("a temporary directory");
    let csv = run(dir.path(), "scenarios/tennis_racket.toml", "racket");
    let out = dir.path().join("racket.html");
    let outcome = view_cmd(&csv, &out);
    outcome.expect_code(0);
    assert!(
        outcome.stderr.contains("given by its inertia only"),
        "{}",
        outcome.stderr
    );
    let data = page_data(&std::fs::read_to_string(&out).expect("page"));
    let g = &data["geometry"];
    assert_eq!(g["motion"], "free");
    assert_eq!(g["body"]["kind"], "inertia_box");
    let size: Vec<f64> = g["body"]["size"]
        .as_array()
        .expect("size")
        .iter()
        .map(|v| v.as_f64().expect("a number"))
        .collect();
    // I = (1, 2, 3), m = 1: a² = 6(I2 + I3 − I1) = 24, b² = 12, c² = 0 (a lamina, drawn at 2 % of a).
    assert!((size[0] - 24f64.sqrt()).abs() < 1e-12, "{size:?}");
    assert!((size[1] - 12f64.sqrt()).abs() < 1e-12, "{size:?}");
    assert!((size[2] - 0.02 * 24f64.sqrt()).abs() < 1e-12, "{size:?}");
    assert_eq!(g["inertia_p"], serde_json::json!([1.0, 2.0, 3.0]));
}

#[test]
fn a_csv_on_stdin_is_shown_without_a_sidecar() {
    let dir = tempfile::tempdir().expect("a temporary directory");
    let csv = run(dir.path(), "scenarios/tilted_disk.toml", "disk");
    let out = dir.path().join("stdin.html");
    let output = std::process::Command::new(env!("CARGO_BIN_EXE_eulerdyn"))
        .args([
            "view".as_ref(),
            "-".as_ref(),
            "-o".as_ref(),
            out.as_os_str(),
        ])
        .stdin(std::fs::File::open(&csv).expect("the CSV"))
        .output()
        .expect("runs");
    let stderr = String::from_utf8_lossy(&output.stderr);
    assert_eq!(output.status.code(), Some(0), "{stderr}");
    assert!(stderr.contains("came from stdin"), "{stderr}");
    let data = page_data(&std::fs::read_to_string(&out).expect("page"));
    assert_eq!(data["rows_in_run"], 101);
    assert_eq!(data["geometry"]["body"]["kind"], "unknown");
}

#[test]
fn a_thin_rod_is_drawn_thick_enough_to_show_and_gravity_sets_the_first_view_s_up() {
    let dir = tempfile::tempdir().expect("a temporary directory");
    let csv = run(dir.path(), "scenarios/rod_pendulum.toml", "rod");
    let out = dir.path().join("rod.html");
    let outcome = view_cmd(&csv, &out);
    outcome.expect_code(0);
    // Drawing the rod thicker is said in the page's legend, not warned about.
    assert!(!outcome.stderr.contains("warning"), "{}", outcome.stderr);
    let data = page_data(&std::fs::read_to_string(&out).expect("page"));
    let body = &data["geometry"]["body"];
    assert_eq!(body["kind"], "thin_rod");
    // 5 % of the 1 m rod.
    assert_eq!(body["min_drawn_thickness"], 0.05);
    let said = body["drawn_thicker"].as_str().expect("the legend's words");
    assert!(said.contains("at least 0.050 m thick"), "{said}");
    // The scene's g = (0, -9.81, 0): the page puts +y up.
    assert_eq!(
        data["geometry"]["gravity_s"],
        serde_json::json!([0.0, -9.81, 0.0])
    );
}

#[test]
fn the_page_embeds_every_located_event_and_a_corrupt_events_file_is_refused() {
    let dir = tempfile::tempdir().unwrap();
    let events =
        "[[event]]\nname = \"down\"\nwhen = \"theta\"\ncrosses = 0.0\ndirection = \"down\"";
    let scene = write_file(
        dir.path(),
        "pend.toml",
        crate::events::pendulum(30.0, "dop853", 3.0, events),
    );
    let csv = dir.path().join("pend.csv");
    eulerdyn([
        "run".as_ref(),
        scene.as_os_str(),
        "-o".as_ref(),
        csv.as_os_str(),
    ])
    .expect_code(0);
    let out = dir.path().join("pend.html");
    view_cmd(&csv, &out).expect_code(0);
    let data = page_data(&std::fs::read_to_string(&out).unwrap());
    // The events file's rows, the same numbers, with the quantity from the sidecar's scene.
    let file = std::fs::read_to_string(dir.path().join("pend.csv.events.csv")).unwrap();
    let rows: Vec<Vec<&str>> = file
        .lines()
        .skip(1)
        .map(|l| l.split(',').collect())
        .collect();
    let embedded = data["events"].as_array().unwrap();
    assert_eq!(embedded.len(), rows.len());
    assert_eq!(rows.len(), 2, "{file}");
    for (e, row) in embedded.iter().zip(&rows) {
        assert_eq!(e["event"], "down");
        assert_eq!(e["when"], "theta");
        assert_eq!(e["direction"], "down");
        assert_eq!(e["t"].as_f64().unwrap(), row[1].parse::<f64>().unwrap());
        assert_eq!(e["value"].as_f64().unwrap(), row[2].parse::<f64>().unwrap());
    }
    // A run without events embeds none.
    let disk = run(dir.path(), "scenarios/tilted_disk.toml", "disk");
    view_cmd(&disk, &dir.path().join("disk.html")).expect_code(0);
    let disk_page = std::fs::read_to_string(dir.path().join("disk.html")).unwrap();
    assert_eq!(page_data(&disk_page)["events"], serde_json::json!([]));
    // A corrupt events file: bad input naming it and its line, the old page left alone.
    let events_file = dir.path().join("pend.csv.events.csv");
    std::fs::write(&events_file, file.replacen(",down\n", ",sideways\n", 1)).unwrap();
    let before = std::fs::read(&out).unwrap();
    let refused = view_cmd(&csv, &out);
    refused.expect_code(2);
    assert!(
        refused.stderr.contains(&format!(
            "{}: line 2: direction \"sideways\"",
            events_file.display()
        )),
        "{}",
        refused.stderr
    );
    assert_eq!(std::fs::read(&out).unwrap(), before);
}

#[test]
fn a_run_with_rotors_carries_each_wheel_s_axis_and_momentum_column() {
    let dir = tempfile::tempdir().unwrap();
    let csv = run(dir.path(), "scenarios/satellite_wheels.toml", "wheels");
    let out = dir.path().join("wheels.html");
    view_cmd(&csv, &out).expect_code(0);
    let data = page_data(&std::fs::read_to_string(&out).unwrap());
    let names = ["wheel_x", "wheel_y", "wheel_z"];
    let rotors = data["geometry"]["rotors"].as_array().unwrap();
    for (k, (rotor, name)) in rotors.iter().zip(names).enumerate() {
        assert_eq!(rotor["name"], name);
        let mut axis = [0.0; 3];
        axis[k] = 1.0;
        assert_eq!(rotor["axis_b"], serde_json::json!(axis));
    }
    // The rows carry each wheel's h, the CSV's values.
    let columns: Vec<&str> = (data["columns"].as_array().unwrap().iter())
        .map(|c| c.as_str().unwrap())
        .collect();
    let text = std::fs::read_to_string(&csv).unwrap();
    let header: Vec<&str> = text.lines().next().unwrap().split(',').collect();
    // Row 100, t = 10 s: half the motors' sine period, the wheels at their fastest (all 201 rows are kept).
    let middle: Vec<f64> = (text.lines().nth(101).unwrap().split(','))
        .map(|v| v.parse().unwrap())
        .collect();
    let page_middle = data["rows"][100].clone();
    for name in names {
        let h = format!("{name}_h");
        let in_page = columns.iter().position(|c| *c == h).expect("the column");
        let in_csv = header.iter().position(|c| *c == h).unwrap();
        assert!(middle[in_csv].abs() > 1e-3, "{h} = {}", middle[in_csv]);
        assert_eq!(page_middle[in_page].as_f64().unwrap(), middle[in_csv]);
    }
    // A run without rotors has neither.
    let disk = run(dir.path(), "scenarios/tilted_disk.toml", "disk");
    view_cmd(&disk, &dir.path().join("disk.html")).expect_code(0);
    let disk_data = page_data(&std::fs::read_to_string(dir.path().join("disk.html")).unwrap());
    assert_eq!(disk_data["geometry"]["rotors"], serde_json::json!([]));
    assert!(!disk_data["columns"].to_string().contains("_h\""));
}
