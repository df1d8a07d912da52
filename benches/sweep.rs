//! What a run costs inside a sweep: a 10^4-run Monte Carlo of the benchmark body (I = (1, 2, 3) kg·m²,
//! ω0 = (0.3, 0, 2) rad/s, torque-free, DOP853 body form at rtol 1e-12 for 100 s, a row every 0.5 s; ω0_x drawn
//! from N(0.3, 0.01)), per run, against
//!
//! * the integration alone: `simulate::run` of the same 10^4 scenes, built beforehand, rows handed to a sink that
//!   drops them (what any sweep must pay);
//! * one process per scene: the release binary `eulerdyn run SCENE` (CSV to /dev/null) spawned once per scene, one
//!   after the other, for the first 200 of the scenes, each written to its own file beforehand;
//! * the sweep itself (`Sweep::run_all`, the results table written to memory) on 1 and on 2 threads.
//!
//! Targets (issue 15): sweep on 1 thread ≤ 1.3 × the integration alone per run; ≥ 6 × faster than a process per
//! scene; 2 threads ≥ 1.7 × faster than 1. Each in-process figure is the median of 3 passes, interleaved so that a
//! slow spell of the machine hits all alike.
//!
//! Run: `cargo bench --bench sweep`. `EULERDYN_BENCH_QUICK=1` runs 10^3 runs instead of 10^4.

use std::convert::Infallible;
use std::hint::black_box;
use std::path::Path;
use std::process::{Command, Stdio};
use std::time::Instant;

use eulerdyn::analysis::sweep::{Shard, Sweep, TableWriter};
use eulerdyn::scene::Scene;
use eulerdyn::simulate;

/// The benchmark scene, as `scenarios/asymmetric_free.toml` runs it.
const BASE_SCENE: &str = "name = \"benchmark\"\n[body]\nmass = 1.0\ninertia = [1.0, 2.0, 3.0]\n[initial]\nomega = [0.3, 0.0, 2.0]\n[solver]\nmethod = \"dop853\"\nframe = \"body\"\nrtol = 1e-12\natol = 1e-14\nt_end = 100.0\n[output]\nevery = 0.5\n";

/// Scenes spawned as processes (each costs a process start, so fewer than the sweep's runs).
const PROCESS_RUNS: u64 = 200;
const PASSES: usize = 3;

fn median(mut v: Vec<f64>) -> f64 {
    v.sort_by(f64::total_cmp);
    v[v.len() / 2]
}

/// Seconds per run of the whole sweep on `jobs` threads, the table written to memory.
fn sweep_per_run(sweep: &Sweep, jobs: usize) -> f64 {
    let start = Instant::now();
    let mut table = TableWriter::new(Vec::new(), sweep.layout().clone()).expect("header");
    sweep
        .run_all(jobs, Shard::ALL, None, |o| table.write(o))
        .expect("the sweep runs");
    let bytes = table.finish().expect("flushed");
    black_box(bytes.len());
    start.elapsed().as_secs_f64() / sweep.len() as f64
}

/// Seconds per run of the integrations alone.
fn integration_per_run(scenes: &[Scene]) -> f64 {
    let start = Instant::now();
    for scene in scenes {
        let report = simulate::run(scene, |s| {
            black_box(s);
            Ok::<(), Infallible>(())
        })
        .expect("the run succeeds");
        black_box(report.rows);
    }
    start.elapsed().as_secs_f64() / scenes.len() as f64
}

/// Seconds per run of `eulerdyn run SCENE` as a process, one after the other.
fn process_per_run(binary: &str, dir: &Path, sweep: &Sweep) -> f64 {
    let files: Vec<_> = (0..PROCESS_RUNS)
        .map(|run| {
            let omega_x = sweep.values(run)[0];
            let text = BASE_SCENE.replace("omega = [0.3,", &format!("omega = [{omega_x:?},"));
            let path = dir.join(format!("scene_{run}.toml"));
            std::fs::write(&path, text).expect("scene written");
            path
        })
        .collect();
    let start = Instant::now();
    for path in &files {
        let status = Command::new(binary)
            .arg("run")
            .arg(path)
            .stdout(Stdio::null())
            .stderr(Stdio::null())
            .status()
            .expect("eulerdyn starts");
        assert!(status.success(), "eulerdyn run {} failed", path.display());
    }
    start.elapsed().as_secs_f64() / files.len() as f64
}

fn main() {
    let runs = if std::env::var_os("EULERDYN_BENCH_QUICK").is_some() {
        1_000
    } else {
        10_000
    };
    let dir = tempfile::tempdir().expect("temporary directory");
    std::fs::write(dir.path().join("base.toml"), BASE_SCENE).expect("scene written");
    let sweep_file = dir.path().join("sweep.toml");
    let text = format!(
        "scene = \"base.toml\"\nseed = 1\nruns = {runs}\n[[vary]]\nkey = \"initial.omega.0\"\nnormal = {{ mean = 0.3, sd = 0.01 }}\n"
    );
    std::fs::write(&sweep_file, text).expect("sweep written");
    let sweep = Sweep::load(&sweep_file).expect("the bench sweep is valid");
    let scenes: Vec<Scene> = (0..sweep.len())
        .map(|run| {
            sweep
                .scene(&sweep.values(run))
                .expect("every draw is valid")
        })
        .collect();

    let (mut alone, mut one, mut two) = (Vec::new(), Vec::new(), Vec::new());
    for _ in 0..PASSES {
        alone.push(integration_per_run(&scenes));
        one.push(sweep_per_run(&sweep, 1));
        two.push(sweep_per_run(&sweep, 2));
    }
    let process = process_per_run(env!("CARGO_BIN_EXE_eulerdyn"), dir.path(), &sweep);
    let (alone, one, two) = (median(alone), median(one), median(two));
    let ms = |s: f64| s * 1e3;
    println!("sweep of {runs} runs of the benchmark body (median of {PASSES} passes), per run:");
    println!("  integration alone             {:8.4} ms", ms(alone));
    println!(
        "  sweep, 1 thread               {:8.4} ms   {:.3} x the integration alone (target <= 1.3)",
        ms(one),
        one / alone
    );
    println!(
        "  sweep, 2 threads              {:8.4} ms   {:.2} x faster than 1 thread (target >= 1.7)",
        ms(two),
        one / two
    );
    println!(
        "  one process per scene ({PROCESS_RUNS})   {:8.4} ms   the sweep on 1 thread is {:.1} x faster (target >= 6)",
        ms(process),
        process / one
    );
}
