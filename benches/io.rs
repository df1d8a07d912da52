//! What output and the process cost: CSV writing in rows per second, the peak resident memory of a run of 10^7
//! steps, and the whole `eulerdyn run` of the benchmark scene from process start to exit.
//!
//! Targets (issue 5): CSV ≥ 10^6 rows per second; 10^7 steps with a peak resident memory ≤ 16 MB; the whole
//! `eulerdyn run` of the benchmark scene ≤ 5 ms.
//!
//! - CSV: `CsvWriter` writing 10^6 rows (10^5 distinct rows of the benchmark body, ten times) into `io::sink()` and
//!   into a file (flushed, not synced); median of 5.
//! - Peak memory: VmHWM (the kernel's high-water mark of resident memory) of (a) this bench re-run as a child that
//!   integrates 10^7 RK4 steps through the library, streaming 10^4 rows as CSV into /dev/null, read from
//!   /proc/self/status at its end; (b) the release binary `eulerdyn run` on the same scene with the CSV to stdout,
//!   redirected to /dev/null (never `-o` at a system device), read from /proc/PID/status every 2 ms while it runs
//!   (the last reading before it exits).
//! - Process: the release binary spawned 50 times on scenarios/asymmetric_free.toml, median wall time from spawn to
//!   exit, with the CSV to stdout (redirected to /dev/null) and with `-o FILE` (atomic write: temporary file,
//!   fsync, rename, and the FILE.meta.json sidecar).
//!
//! Run: `cargo bench --bench io` (Linux: reads /proc).

use std::convert::Infallible;
use std::fs::File;
use std::hint::black_box;
use std::io;
use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};
use std::time::{Duration, Instant};

use eulerdyn::output::CsvWriter;
use eulerdyn::sample::{ColumnSet, Sample};
use eulerdyn::scene::{self, Overrides};
use eulerdyn::simulate;

/// The benchmark body, torque-free.
fn benchmark_scene(solver: &str, every: f64) -> String {
    format!(
        "name = \"benchmark\"\n[body]\nmass = 1.0\ninertia = [1.0, 2.0, 3.0]\n[initial]\nomega = [0.3, 0.0, 2.0]\n[solver]\n{solver}\n[output]\nevery = {every:e}\n"
    )
}

/// 10^7 RK4 steps (dt = 1e-5 s over 100 s), a row every 0.01 s.
fn ten_million_steps_scene() -> String {
    benchmark_scene("method = \"rk4\"\ndt = 1e-5\nt_end = 100.0", 0.01)
}

const ENV_CHILD: &str = "EULERDYN_BENCH_IO_CHILD";

fn median(mut v: Vec<f64>) -> f64 {
    v.sort_by(f64::total_cmp);
    v[v.len() / 2]
}

/// A line `key: value kB` of /proc/PID/status, in MB (10^6 bytes).
fn status_mb(status: &str, key: &str) -> Option<f64> {
    let line = status.lines().find(|l| l.starts_with(key))?;
    let kb: f64 = line.split_whitespace().nth(1)?.parse().ok()?;
    Some(kb * 1024.0 / 1e6)
}

/// The child mode: 10^7 steps through the library, rows streamed as CSV into /dev/null; prints VmHWM in MB.
fn child_peak_memory() {
    let text = ten_million_steps_scene();
    let scene = scene::parse(Path::new("ten_million.toml"), &text, &Overrides::default())
        .expect("the bench scene is valid");
    let sink = File::options()
        .write(true)
        .open("/dev/null")
        .expect("/dev/null opens");
    let mut writer = CsvWriter::new(sink, scene.facts().columns().clone()).expect("header written");
    let report = simulate::run(&scene, |s| writer.write(s)).expect("the run succeeds");
    writer.finish().expect("flushed");
    let status = std::fs::read_to_string("/proc/self/status").unwrap_or_default();
    println!(
        "{} {} {}",
        report.stats.steps,
        report.rows,
        status_mb(&status, "VmHWM:").unwrap_or(f64::NAN)
    );
}

/// 10^5 rows of the benchmark body (a row every 1 ms over 100 s).
fn sample_rows() -> (Vec<Sample>, ColumnSet) {
    let text = benchmark_scene("method = \"dop853\"\nrtol = 1e-10\nt_end = 100.0", 1e-3);
    let scene = scene::parse(Path::new("rows.toml"), &text, &Overrides::default())
        .expect("the bench scene is valid");
    let mut rows = Vec::with_capacity(scene.schedule.len());
    simulate::run(&scene, |s| {
        rows.push(*s);
        Ok::<(), Infallible>(())
    })
    .expect("the run succeeds");
    (rows, scene.facts().columns().clone())
}

/// Rows per second writing `passes` times every row of `rows` into `out`, flushed.
fn csv_rate<W: io::Write>(rows: &[Sample], columns: ColumnSet, passes: usize, out: W) -> f64 {
    let start = Instant::now();
    let mut writer = CsvWriter::new(out, columns).expect("header written");
    for _ in 0..passes {
        for s in rows {
            writer.write(s).expect("row written");
        }
    }
    black_box(writer.finish().expect("flushed"));
    (rows.len() * passes) as f64 / start.elapsed().as_secs_f64()
}

fn csv_writing(tmp: &Path) {
    let (rows, columns) = sample_rows();
    let passes = 10;
    let n = rows.len() * passes;
    let mut to_sink = Vec::new();
    let mut to_file = Vec::new();
    let path = tmp.join("io_bench_rows.csv");
    for _ in 0..5 {
        to_sink.push(csv_rate(&rows, columns.clone(), passes, io::sink()));
        let file = File::create(&path).expect("the bench file is created");
        to_file.push(csv_rate(&rows, columns.clone(), passes, file));
    }
    let bytes = std::fs::metadata(&path).map(|m| m.len()).unwrap_or(0);
    let _ = std::fs::remove_file(&path);
    let (sink, file) = (median(to_sink), median(to_file));
    println!(
        "CSV writing, {n} rows of {} columns ({:.0} bytes per row), median of 5:",
        columns.columns().len(),
        bytes as f64 / n as f64
    );
    let verdict = |r: f64| if r >= 1e6 { "ok" } else { "MISSED" };
    println!(
        "  into io::sink()   {:6.2} million rows/s   (target >= 1: {})",
        sink / 1e6,
        verdict(sink)
    );
    println!(
        "  into a file       {:6.2} million rows/s   (target >= 1: {})   [{}]",
        file / 1e6,
        verdict(file),
        tmp.display()
    );
}

/// Runs `eulerdyn run SCENE > /dev/null` and polls its VmHWM; returns (last reading in MB, wall time).
fn polled_peak(bin: &Path, scene: &Path) -> Option<(f64, f64)> {
    let start = Instant::now();
    let mut child = Command::new(bin)
        .args(["run"])
        .arg(scene)
        .stdout(Stdio::null())
        .stderr(Stdio::null())
        .spawn()
        .ok()?;
    let status_path = format!("/proc/{}/status", child.id());
    let mut peak = f64::NAN;
    loop {
        if let Ok(status) = std::fs::read_to_string(&status_path)
            && let Some(mb) = status_mb(&status, "VmHWM:")
        {
            peak = mb;
        }
        match child.try_wait() {
            Ok(Some(_)) => break,
            Ok(None) => std::thread::sleep(Duration::from_millis(2)),
            Err(_) => return None,
        }
    }
    Some((peak, start.elapsed().as_secs_f64()))
}

fn peak_memory(bin: &Path, tmp: &Path) {
    println!(
        "peak resident memory (VmHWM) of a run of 10^7 RK4 steps (benchmark body, dt = 1e-5 s, t_end = 100 s, 10^4 rows):"
    );
    let exe = std::env::current_exe().expect("the bench knows its path");
    match Command::new(exe).env(ENV_CHILD, "peak").output() {
        Ok(out) if out.status.success() => {
            let text = String::from_utf8_lossy(&out.stdout);
            let parts: Vec<&str> = text.split_whitespace().collect();
            if let [steps, rows, mb] = parts.as_slice() {
                let mb: f64 = mb.parse().unwrap_or(f64::NAN);
                println!(
                    "  library (simulate::run + CsvWriter into /dev/null): {steps} steps, {rows} rows, {mb:.2} MB   (target <= 16: {})",
                    if mb <= 16.0 { "ok" } else { "MISSED" }
                );
            } else {
                println!("  library: unexpected child output {text:?}");
            }
        }
        Ok(out) => println!(
            "  library: the child failed: {}",
            String::from_utf8_lossy(&out.stderr)
        ),
        Err(e) => println!("  library: cannot start the child: {e}"),
    }
    let scene = tmp.join("io_bench_ten_million.toml");
    if std::fs::write(&scene, ten_million_steps_scene()).is_err() {
        println!("  binary: cannot write {}", scene.display());
        return;
    }
    match polled_peak(bin, &scene) {
        Some((mb, wall)) => println!(
            "  binary (eulerdyn run SCENE > /dev/null): {mb:.2} MB (last reading before exit), {wall:.2} s   (target <= 16: {})",
            if mb <= 16.0 { "ok" } else { "MISSED" }
        ),
        None => println!("  binary: cannot run {}", bin.display()),
    }
    let _ = std::fs::remove_file(&scene);
}

/// Median wall time (s) of `runs` spawns of `bin args`, stdout and stderr to /dev/null; `None` if one failed.
fn spawn_median(bin: &Path, args: &[&std::ffi::OsStr], runs: usize) -> Option<f64> {
    let mut times = Vec::with_capacity(runs);
    for _ in 0..runs {
        let start = Instant::now();
        let status = Command::new(bin)
            .args(args)
            .stdout(Stdio::null())
            .stderr(Stdio::null())
            .status()
            .ok()?;
        times.push(start.elapsed().as_secs_f64());
        if !status.success() {
            return None;
        }
    }
    Some(median(times))
}

fn whole_run(bin: &Path, tmp: &Path) {
    let scene = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("scenarios/asymmetric_free.toml");
    let out = tmp.join("io_bench_run.csv");
    let runs = 50;
    println!(
        "the whole `eulerdyn run scenarios/asymmetric_free.toml` (dop853, rtol 1e-12, 201 rows), spawn to exit, median of {runs}:"
    );
    let show = |what: &str, t: Option<f64>| match t {
        Some(t) => println!(
            "  {what:<44} {:6.2} ms   (target <= 5: {})",
            t * 1e3,
            if t <= 5e-3 { "ok" } else { "MISSED" }
        ),
        None => println!("  {what:<44} failed"),
    };
    // Warm the page cache first.
    let _ = spawn_median(bin, &["run".as_ref(), scene.as_os_str()], 3);
    show(
        "CSV to stdout (redirected to /dev/null)",
        spawn_median(bin, &["run".as_ref(), scene.as_os_str()], runs),
    );
    show(
        "-o FILE (atomic: temp file, fsync, rename; sidecar)",
        spawn_median(
            bin,
            &[
                "run".as_ref(),
                scene.as_os_str(),
                "-o".as_ref(),
                out.as_os_str(),
            ],
            runs,
        ),
    );
    show(
        "eulerdyn --version (process start and exit only)",
        spawn_median(bin, &["--version".as_ref()], runs),
    );
    let _ = std::fs::remove_file(&out);
    let _ = std::fs::remove_file(tmp.join("io_bench_run.csv.meta.json"));
}

fn main() {
    if std::env::var(ENV_CHILD).as_deref() == Ok("peak") {
        child_peak_memory();
        return;
    }
    let bin = PathBuf::from(env!("CARGO_BIN_EXE_eulerdyn"));
    let tmp = PathBuf::from(env!("CARGO_TARGET_TMPDIR"));
    csv_writing(&tmp);
    println!();
    peak_memory(&bin, &tmp);
    println!();
    whole_run(&bin, &tmp);
}
