//! `eulerdyn sweep`: run numbering and grid order, determinism across threads and shards, invalid and failed runs as
//! rows, the bearing-load map against its closed form, time series on request, and bad sweep files.

use std::path::{Path, PathBuf};

use crate::common::{column, dir_entries, eulerdyn, read_csv, repo_path, write_file};
use eulerdyn::analysis::sweep::{RunOutcome, Shard, Status, Sweep};

/// A sweep file in `dir` over the free scene `base.toml` written next to it.
fn free_sweep(dir: &Path, body: &str) -> PathBuf {
    write_file(dir, "base.toml", crate::common::FREE_SCENE);
    write_file(dir, "sweep.toml", format!("scene = \"base.toml\"\n{body}"))
}

fn outcomes(sweep: &Sweep, jobs: usize, shard: Shard) -> Vec<RunOutcome> {
    let mut all = Vec::new();
    sweep
        .run_all(jobs, shard, None, |o| {
            all.push(o.clone());
            Ok::<(), std::io::Error>(())
        })
        .unwrap();
    all
}

/// Every field but the wall time.
fn without_wall(mut o: Vec<RunOutcome>) -> Vec<RunOutcome> {
    o.iter_mut().for_each(|o| o.wall_s = 0.0);
    o
}

#[test]
fn runs_are_the_grid_product_last_axis_fastest_with_repeats_consecutive() {
    let dir = tempfile::tempdir().unwrap();
    let path = free_sweep(
        dir.path(),
        "runs = 2\n[[vary]]\nkey = \"body.mass\"\nvalues = [1.0, 2.0]\n[[vary]]\nkey = \"initial.omega.2\"\nlinspace = [1.0, 3.0, 3]\n[[vary]]\nkey = \"solver.rtol\"\nlogspace = [1e-4, 1e-8, 3]\n",
    );
    let sweep = Sweep::load(&path).unwrap();
    assert_eq!(sweep.len(), 2 * 2 * 3 * 3);
    let v = |run| sweep.values(run);
    // Run i is grid point i / runs; the last axis (rtol) varies fastest.
    assert_eq!(v(0), vec![1.0, 1.0, 1e-4]);
    assert_eq!(v(1), v(0));
    assert_eq!(v(2)[..2], [1.0, 1.0]);
    assert!((v(2)[2] - 1e-6).abs() < 1e-20);
    assert_eq!(v(4), vec![1.0, 1.0, 1e-8]);
    assert_eq!(v(6), vec![1.0, 2.0, 1e-4]);
    assert_eq!(v(18), vec![2.0, 1.0, 1e-4]);
    assert_eq!(v(35), vec![2.0, 3.0, 1e-8]);
}

#[test]
fn draws_depend_on_seed_and_run_not_on_threads_or_shards() {
    let dir = tempfile::tempdir().unwrap();
    let path = free_sweep(
        dir.path(),
        "seed = 7\nruns = 5\n[[vary]]\nkey = \"initial.omega.0\"\nvalues = [0.1, 0.3]\n[[vary]]\nkey = \"body.inertia.1\"\nuniform = { low = 2.0, high = 2.1 }\n[[vary]]\nkey = \"initial.omega.2\"\nnormal = { mean = 2.0, sd = 0.1 }\n",
    );
    let sweep = Sweep::load(&path).unwrap();
    let one = without_wall(outcomes(&sweep, 1, Shard::ALL));
    assert_eq!(one.len(), 10);
    assert!(one.iter().all(|o| o.status == Status::Ok), "{one:?}");
    assert_eq!(without_wall(outcomes(&sweep, 2, Shard::ALL)), one);
    let mut merged: Vec<RunOutcome> = (1..=3)
        .flat_map(|k| outcomes(&sweep, 2, Shard { index: k, count: 3 }))
        .collect();
    merged.sort_by_key(|o| o.run);
    assert_eq!(without_wall(merged), one);
    // Distinct draws per run, and the same draws from a second load.
    assert_ne!(one[0].values[1], one[1].values[1]);
    assert_eq!(Sweep::load(&path).unwrap().values(3), sweep.values(3));
}

#[test]
fn the_bearing_load_map_matches_the_closed_form_in_every_run() {
    // The notes' disk (m = 2 kg, R = 0.3 m) on a fixed axis tilted θ from its symmetry axis at rate ω: the
    // bearings supply M = ω × H of magnitude ¼ m R² ω² sin θ cos θ (Meghdari, Rigid Body Dynamics, the tilted-disk
    // example), as two equal and opposite forces M/(b − a) with b − a = 0.2 m; C is on the axis, so F_sup = 0.
    let sweep = Sweep::load(&repo_path("scenarios/sweeps/disk_bearing_map.toml")).unwrap();
    let all = outcomes(&sweep, 2, Shard::ALL);
    assert_eq!(all.len(), 19 * 11);
    for o in &all {
        let (tilt, rate) = (o.values[0].to_radians(), o.values[1]);
        let moment = 0.25 * 2.0 * 0.09 * rate * rate * tilt.sin() * tilt.cos();
        let s = o.summary.as_ref().unwrap();
        let scale = 0.25 * 2.0 * 0.09 * rate * rate;
        assert!((s.max_m_norm - moment.abs()).abs() <= 1e-9 * scale, "{o:?}");
        let bearing = moment.abs() / 0.2;
        for r in [s.max_r_a_norm.unwrap(), s.max_r_b_norm.unwrap()] {
            assert!((r - bearing).abs() <= 1e-9 * scale / 0.2, "{o:?}");
        }
        assert!(s.max_f_sup_norm.unwrap() <= 1e-9 * scale, "{o:?}");
    }
}

#[test]
fn the_command_writes_the_contract_table_and_exits_0() {
    let dir = tempfile::tempdir().unwrap();
    let path = free_sweep(
        dir.path(),
        "[[vary]]\nkey = \"initial.omega.2\"\nvalues = [1.0, 2.0]\n[summary]\ncolumns = [\"omega_b_x\", \"H_s_z\"]\n",
    );
    let out = dir.path().join("results.csv");
    eulerdyn(["sweep", path.to_str().unwrap(), "-o", out.to_str().unwrap()]).expect_code(0);
    let (head, rows) = read_csv(&std::fs::read_to_string(&out).unwrap());
    let expected = "run,initial.omega.2,status,message,max_M_norm,energy_drift,H_drift,final_omega_b_x,final_omega_b_y,final_omega_b_z,steps,evals,wall_s,min_omega_b_x,max_omega_b_x,final_omega_b_x,min_H_s_z,max_H_s_z,final_H_s_z";
    assert_eq!(head.join(","), expected);
    assert_eq!(rows.len(), 2);
    assert_eq!(column(&head, &rows, "run"), vec![0.0, 1.0]);
    // Torque-free: H_s is constant, so min = max = final = I3 ω_z(0) = 3 ω_z(0) (kg·m²/s; H_s_z because the
    // attitude starts at identity).
    for (row, omega_z) in [(0, 1.0), (1, 2.0)] {
        for name in ["min_H_s_z", "max_H_s_z", "final_H_s_z"] {
            let v = column(&head, &rows, name)[row];
            assert!((v - 3.0 * omega_z).abs() < 1e-9, "{name} = {v}");
        }
    }
    assert!(column(&head, &rows, "H_drift").iter().all(|d| *d < 1e-9));
}

#[test]
fn invalid_and_failed_runs_are_rows_and_the_sweep_goes_on_with_exit_1() {
    let dir = tempfile::tempdir().unwrap();
    // Mass −1 is invalid; dt = 0.5 s with RK4 at |ω| = 100 rad/s diverges (|ω| dt = 50, far outside RK4's
    // stability region); dt = 1e-3 s runs.
    write_file(
        dir.path(),
        "base.toml",
        "[body]\nmass = 1.0\ninertia = [1.0, 2.0, 3.0]\n[initial]\nomega = [0.3, 100.0, 2.0]\n[solver]\nmethod = \"rk4\"\ndt = 0.001\nt_end = 2.0\n[output]\nevery = 0.5\n",
    );
    let path = write_file(
        dir.path(),
        "sweep.toml",
        "scene = \"base.toml\"\n[[vary]]\nkey = \"body.mass\"\nvalues = [-1.0, 1.0]\n[[vary]]\nkey = \"solver.dt\"\nvalues = [0.001, 0.5]\n",
    );
    let out = dir.path().join("results.csv");
    let outcome = eulerdyn(["sweep", path.to_str().unwrap(), "-o", out.to_str().unwrap()]);
    outcome.expect_code(1);
    assert!(
        outcome.stderr.contains("2 ok") || outcome.stderr.contains("1 ok"),
        "{}",
        outcome.stderr
    );
    let (head, rows) = read_csv(&std::fs::read_to_string(&out).unwrap());
    let status: Vec<&str> = rows
        .iter()
        .map(|r| &r[head.iter().position(|h| h == "status").unwrap()])
        .collect();
    assert_eq!(status, ["invalid", "invalid", "ok", "failed"]);
    let message = |i: usize| rows[i][head.iter().position(|h| h == "message").unwrap()].to_string();
    assert!(message(0).contains("body.mass"), "{}", message(0));
    assert!(message(3).contains("t = "), "{}", message(3));
    assert_eq!(message(2), "");
}

#[test]
fn series_are_written_on_request_and_equal_a_run_of_the_same_scene() {
    let dir = tempfile::tempdir().unwrap();
    let path = free_sweep(
        dir.path(),
        "[[vary]]\nkey = \"initial.omega.0\"\nvalues = [0.1, 0.2]\n",
    );
    let series = dir.path().join("series");
    let out = dir.path().join("results.csv");
    eulerdyn([
        "sweep",
        path.to_str().unwrap(),
        "-o",
        out.to_str().unwrap(),
        "--series",
        series.to_str().unwrap(),
    ])
    .expect_code(0);
    assert_eq!(dir_entries(&series), ["run_000000.csv", "run_000001.csv"]);
    let scene = write_file(
        dir.path(),
        "run1.toml",
        crate::common::FREE_SCENE.replace("omega = [0.3, 0.0, 2.0]", "omega = [0.2, 0.0, 2.0]"),
    );
    let single = eulerdyn(["run", scene.to_str().unwrap()]);
    assert_eq!(
        std::fs::read_to_string(series.join("run_000001.csv")).unwrap(),
        single.stdout
    );
}

/// Runs a bad sweep: exit 2, the message contains every one of `expected`, and no output file appears.
fn refused(sweep_body: &str, args: &[&str], expected: &[&str]) {
    let dir = tempfile::tempdir().unwrap();
    let path = free_sweep(dir.path(), sweep_body);
    let out = dir.path().join("results.csv");
    let mut all = vec!["sweep", path.to_str().unwrap(), "-o", out.to_str().unwrap()];
    all.extend_from_slice(args);
    let outcome = eulerdyn(all);
    outcome.expect_code(2);
    for e in expected {
        assert!(
            outcome.stderr.contains(e),
            "missing {e:?} in: {}",
            outcome.stderr
        );
    }
    assert!(!outcome.panicked());
    assert!(!out.exists());
    assert_eq!(dir_entries(dir.path()), ["base.toml", "sweep.toml"]);
}

#[test]
fn bad_sweep_files_exit_2_naming_file_key_and_line_and_write_nothing() {
    let vary = |key: &str, way: &str| format!("[[vary]]\nkey = \"{key}\"\n{way}\n");
    // An unknown key, with the sweep file's line of `key`.
    refused(
        &vary("motion.tilt_degs", "values = [1.0]"),
        &[],
        &[
            "sweep.toml:3:1",
            "vary[0].key",
            "not a key of the scene format",
        ],
    );
    refused(
        &vary("body.masss", "values = [1.0]"),
        &[],
        &["not a key of the scene format"],
    );
    // A key whose value is not a number.
    refused(
        &vary("solver.method", "values = [1.0]"),
        &[],
        &["sweep.toml:3", "not a numeric key"],
    );
    // An empty grid, and a grid of no values.
    refused(
        &vary("body.mass", "values = []"),
        &[],
        &["vary[0].values", "empty"],
    );
    refused(
        &vary("body.mass", "linspace = [1.0, 2.0, 0]"),
        &[],
        &["vary[0].linspace", "n must be"],
    );
    refused(&vary("body.mass", ""), &[], &["give exactly one of"]);
    // An unknown summary column.
    refused(
        &(vary("body.mass", "values = [1.0]") + "[summary]\ncolumns = [\"R_A_s_x\"]\n"),
        &[],
        &["summary.columns", "R_A_s_x"],
    );
    // Shards outside 1 <= K <= N.
    for shard in ["0/3", "4/3", "x", "1/0"] {
        refused(
            &vary("body.mass", "values = [1.0]"),
            &["--shard", shard],
            &["--shard", "1 <= K <= N"],
        );
    }
}

#[test]
fn a_missing_base_scene_exits_2() {
    let dir = tempfile::tempdir().unwrap();
    let path = write_file(
        dir.path(),
        "sweep.toml",
        "scene = \"nowhere.toml\"\n[[vary]]\nkey = \"body.mass\"\nvalues = [1.0]\n",
    );
    let out = dir.path().join("results.csv");
    let outcome = eulerdyn(["sweep", path.to_str().unwrap(), "-o", out.to_str().unwrap()]);
    outcome.expect_code(2);
    assert!(
        outcome.stderr.contains("sweep.toml:1:1") && outcome.stderr.contains("nowhere.toml"),
        "{}",
        outcome.stderr
    );
    assert!(!out.exists());
}

#[test]
fn outcomes_arrive_in_run_order_across_batches_and_a_delivery_error_stops_the_sweep() {
    // 300 runs go in several batches (2·threads, doubling), the next batch running while the last is delivered:
    // every run once, in order. A failing delivery ends the sweep with that error, at that outcome.
    let dir = tempfile::tempdir().unwrap();
    let path = free_sweep(
        dir.path(),
        "runs = 300\n[[vary]]\nkey = \"initial.omega.0\"\nnormal = { mean = 0.3, sd = 0.01 }\n",
    );
    let sweep = Sweep::load(&path).unwrap();
    for jobs in [1, 2] {
        let runs: Vec<u64> = outcomes(&sweep, jobs, Shard::ALL)
            .iter()
            .map(|o| o.run)
            .collect();
        assert_eq!(runs, (0..300).collect::<Vec<u64>>(), "jobs {jobs}");
        let mut delivered = 0;
        let result = sweep.run_all(jobs, Shard::ALL, None, |o| {
            delivered += 1;
            if o.run == 40 {
                Err(std::io::Error::other("disk full"))
            } else {
                Ok(())
            }
        });
        let message = result.err().map(|e| e.to_string());
        assert_eq!(message.as_deref(), Some("disk full"), "jobs {jobs}");
        assert_eq!(delivered, 41, "jobs {jobs}");
    }
}
