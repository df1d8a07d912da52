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
//! Then (issue 26) the same for every method — the benchmark body, 201 rows, the fixed-step methods at dt = 0.01 s —
//! with the per-run overhead of the sweep in µs (making the run's scene from the template and checking it, the
//! summary, the table row: the sweep on 1 thread minus the integration alone), and the 10^6-run Monte Carlo of the
//! dop853 case extrapolated from the 2-thread figure (target ≤ 120 s). The load average is printed beside: on a
//! shared machine the 2-thread figures need both cores free.
//!
//! Run: `cargo bench --bench sweep`. `EULERDYN_BENCH_QUICK=1` runs 10^3 runs instead of 10^4 (and a tenth of the
//! runs per method).

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

/// A sweep of `runs` draws of ω0_x ~ N(0.3, 0.01) around `base` (a scene's text), written to `dir` under `name`,
/// and its scenes, built beforehand.
fn benchmark_sweep(dir: &Path, name: &str, base: &str, runs: u64) -> (Sweep, Vec<Scene>) {
    std::fs::write(dir.join(format!("{name}.toml")), base).expect("scene written");
    let sweep_file = dir.join(format!("{name}_sweep.toml"));
    let text = format!(
        "scene = \"{name}.toml\"\nseed = 1\nruns = {runs}\n[[vary]]\nkey = \"initial.omega.0\"\nnormal = {{ mean = 0.3, sd = 0.01 }}\n"
    );
    std::fs::write(&sweep_file, text).expect("sweep written");
    let sweep = Sweep::load(&sweep_file).expect("the bench sweep is valid");
    let scenes = (0..sweep.len())
        .map(|run| {
            sweep
                .scene(&sweep.values(run))
                .expect("every draw is valid")
        })
        .collect();
    (sweep, scenes)
}

/// The one-minute load average (/proc/loadavg), for the conditions of a measurement.
fn load_average() -> String {
    std::fs::read_to_string("/proc/loadavg")
        .ok()
        .and_then(|s| s.split_whitespace().next().map(str::to_string))
        .unwrap_or_else(|| "?".into())
}

/// CPU seconds this process has used (user + system; /proc/self/stat, in ticks of 1/100 s).
fn process_cpu_seconds() -> f64 {
    let stat = std::fs::read_to_string("/proc/self/stat").unwrap_or_default();
    let fields: Vec<f64> = stat
        .rsplit_once(')')
        .map(|(_, rest)| {
            rest.split_whitespace()
                .filter_map(|f| f.parse().ok())
                .collect()
        })
        .unwrap_or_default();
    // After the command name: state (not a number, skipped), then ppid … cmajflt (10 fields), utime, stime.
    fields
        .get(10)
        .zip(fields.get(11))
        .map_or(f64::NAN, |(u, s)| (u + s) / 100.0)
}

/// `f`'s result and the CPU seconds the process used meanwhile, added to `cpu`.
fn with_cpu<T>(cpu: &mut f64, f: impl FnOnce() -> T) -> T {
    let before = process_cpu_seconds();
    let out = f();
    *cpu += process_cpu_seconds() - before;
    out
}

/// Every method in a sweep: per run alone, on 1 and 2 threads, the overhead and the scaling; beside the wall-clock
/// scaling (which needs both cores free), the CPU time per run on 2 threads over that on 1 (1.00: the threads
/// add no work, whatever else runs on the machine).
fn every_method(dir: &Path, quick: bool) {
    // Runs per method: about 0.3 s a pass on 1 thread.
    let cases: [(&str, u64); 6] = [
        ("rk4", 600),
        ("dopri5", 200),
        ("dop853", 1_500),
        ("split2", 800),
        ("split4", 250),
        ("exact", 12_000),
    ];
    println!(
        "every method, the benchmark body over 100 s with 201 rows (rtol 1e-12, atol 1e-14; dt = 0.01 s), median of \
         {PASSES} passes, per run (load average {} before):",
        load_average()
    );
    println!(
        "  {:<8} {:>6} {:>12} {:>12} {:>12} {:>12} {:>18} {:>8}",
        "method",
        "runs",
        "alone",
        "1 thread",
        "overhead",
        "2 threads",
        "2 vs 1 (>= 1.7)",
        "CPU 2/1"
    );
    let mut dop853_two = f64::NAN;
    for (method, runs) in cases {
        let runs = if quick { runs / 10 } else { runs };
        let mut base = BASE_SCENE.replace("method = \"dop853\"", &format!("method = \"{method}\""));
        if matches!(method, "rk4" | "split2" | "split4") {
            base = base.replace("t_end = 100.0\n", "t_end = 100.0\ndt = 0.01\n");
        }
        let (sweep, scenes) = benchmark_sweep(dir, method, &base, runs);
        let (mut alone, mut one, mut two) = (Vec::new(), Vec::new(), Vec::new());
        let (mut cpu_one, mut cpu_two) = (0.0, 0.0);
        for _ in 0..PASSES {
            alone.push(integration_per_run(&scenes));
            one.push(with_cpu(&mut cpu_one, || sweep_per_run(&sweep, 1)));
            two.push(with_cpu(&mut cpu_two, || sweep_per_run(&sweep, 2)));
        }
        let (alone, one, two) = (median(alone), median(one), median(two));
        if method == "dop853" {
            dop853_two = two;
        }
        let us = |s: f64| format!("{:.1} us", s * 1e6);
        let scaling = one / two;
        println!(
            "  {method:<8} {runs:>6} {:>12} {:>12} {:>12} {:>12} {:>9.2} x {:<6} {:>8.2}",
            us(alone),
            us(one),
            us(one - alone),
            us(two),
            scaling,
            if scaling >= 1.7 { "ok" } else { "MISSED" },
            cpu_two / cpu_one
        );
    }
    println!(
        "  10^6-run Monte Carlo of the benchmark body (dop853, rtol 1e-12, 201 rows) on 2 threads, extrapolated: \
         {:.0} s (target <= 120 s; load average {} after)",
        dop853_two * 1e6,
        load_average()
    );
}

fn main() {
    let quick = std::env::var_os("EULERDYN_BENCH_QUICK").is_some();
    let runs = if quick { 1_000 } else { 10_000 };
    let dir = tempfile::tempdir().expect("temporary directory");
    let (sweep, scenes) = benchmark_sweep(dir.path(), "base", BASE_SCENE, runs);
    let (mut alone, mut one, mut two) = (Vec::new(), Vec::new(), Vec::new());
    for _ in 0..PASSES {
        alone.push(integration_per_run(&scenes));
        one.push(sweep_per_run(&sweep, 1));
        two.push(sweep_per_run(&sweep, 2));
    }
    let process = process_per_run(env!("CARGO_BIN_EXE_eulerdyn"), dir.path(), &sweep);
    let (alone, one, two) = (median(alone), median(one), median(two));
    let ms = |s: f64| s * 1e3;
    println!(
        "sweep of {runs} runs of the benchmark body (median of {PASSES} passes; load average {}), per run:",
        load_average()
    );
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
    println!();
    every_method(dir.path(), quick);
}
