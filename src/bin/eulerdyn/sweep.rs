//! `eulerdyn sweep SWEEP.toml -o RESULTS.csv [--jobs N] [--shard K/N] [--series DIR]`: the runs of a sweep
//! ([`eulerdyn::analysis::sweep`]) in parallel, their results table written atomically, progress on stderr.

use std::io::{self, Write};
use std::path::{Path, PathBuf};
use std::time::Instant;

use clap::Args;

use crate::progress::{self, Progress};
use eulerdyn::analysis::sweep::{
    RunOutcome, SeriesSink, Shard, Status, Sweep, SweepError, TableWriter,
};
use eulerdyn::output::{AtomicFile, CsvWriter};
use eulerdyn::sample::{ColumnSet, Sample};
use eulerdyn::scene::{self, Overrides};

#[derive(Debug, Args)]
pub struct SweepArgs {
    /// Sweep file (TOML): the base scene, the keys varied (grids and random draws), the columns summarised.
    #[arg(value_name = "SWEEP.toml")]
    pub sweep: PathBuf,
    /// Results CSV, one row per run, sorted by run, written atomically; `-` or absent: stdout.
    #[arg(short = 'o', long = "output", value_name = "RESULTS.csv")]
    pub output: Option<PathBuf>,
    /// Threads (default: all cores).
    #[arg(long, value_name = "N")]
    pub jobs: Option<usize>,
    /// Run only the runs with run % N == K - 1 (1 <= K <= N), for N processes that split a sweep.
    #[arg(long, value_name = "K/N")]
    pub shard: Option<String>,
    /// Also write each run's time series, DIR/run_N.csv for run N (the directory is created).
    #[arg(long, value_name = "DIR")]
    pub series: Option<PathBuf>,
}

/// How a sweep command ended: bad input (exit 2), or the runs' counts (exit 1 unless all ok).
pub enum SweepFailure {
    Input(String),
    Run(String),
}

/// Runs the command; on success a one-line account for stderr and whether every run was ok.
pub fn sweep_command(args: &SweepArgs, quiet: bool) -> Result<(String, bool), SweepFailure> {
    let input = |m: String| SweepFailure::Input(m);
    let sweep = Sweep::load(&args.sweep).map_err(|e| input(e.to_string()))?;
    for warning in sweep.warnings() {
        eprintln!("{}: warning: {warning}", args.sweep.display());
    }
    // The base scene's own warnings (unit slips, the separatrix), once: every run is a variant of it.
    if let Ok(base) = scene::load(&sweep.scene_file, &Overrides::default()) {
        for warning in scene::advice::warnings(&base) {
            eprintln!("{}: warning: {warning}", sweep.scene_file.display());
        }
    }
    let shard = match &args.shard {
        Some(text) => Shard::parse(text).map_err(input)?,
        None => Shard::ALL,
    };
    if args.jobs == Some(0) {
        return Err(input("--jobs 0: give at least 1 thread".into()));
    }
    let output = args.output.as_deref().filter(|p| p.as_os_str() != "-");
    if let Some(out) = output {
        refuse_inputs(&sweep, out).map_err(input)?;
    }
    let series_dir = args.series.as_deref();
    if let Some(dir) = series_dir {
        std::fs::create_dir_all(dir).map_err(|e| {
            input(format!(
                "{}: cannot create the directory: {e}",
                dir.display()
            ))
        })?;
    }
    let mut file = output
        .map(|out| {
            AtomicFile::create(out)
                .map_err(|e| input(format!("{}: cannot create: {e}", out.display())))
        })
        .transpose()?;
    let planned = shard.runs(sweep.len()).count() as f64;
    let mut bar = Progress::bar("sweep", "done", planned, "runs", progress::wanted(quiet));
    let started = Instant::now();
    let to_dir = |run: u64, columns: ColumnSet, rows: &[Sample]| match series_dir {
        Some(dir) => write_series(dir, run, columns, rows),
        None => Ok(()),
    };
    let series: Option<&SeriesSink<'_>> = series_dir.map(|_| &to_dir as _);
    let mut counts = Counts::default();
    let jobs = args.jobs.unwrap_or(0);
    let where_to = output.map_or_else(|| "stdout".to_string(), |p| p.display().to_string());
    let result = match file.as_mut() {
        Some(f) => run_into(&sweep, jobs, shard, series, f.file(), &mut counts, &mut bar),
        None => run_into(
            &sweep,
            jobs,
            shard,
            series,
            io::stdout().lock(),
            &mut counts,
            &mut bar,
        ),
    };
    bar.finish();
    result.map_err(|e| SweepFailure::Run(format!("{where_to}: {e}")))?;
    if let Some(f) = file {
        f.commit()
            .map_err(|e| SweepFailure::Run(format!("{where_to}: cannot save: {e}")))?;
    }
    let account = format!(
        "{}: {} runs in {:.2} s: {} ok, {} failed, {} invalid{}",
        where_to,
        counts.total(),
        started.elapsed().as_secs_f64(),
        counts.ok,
        counts.failed,
        counts.invalid,
        if counts.all_ok() {
            ""
        } else {
            " (see the status and message columns)"
        }
    );
    Ok((account, counts.all_ok()))
}

/// The runs' statuses counted.
#[derive(Debug, Default)]
struct Counts {
    ok: u64,
    failed: u64,
    invalid: u64,
}

impl Counts {
    fn add(&mut self, o: &RunOutcome) {
        match o.status {
            Status::Ok => self.ok += 1,
            Status::Failed => self.failed += 1,
            Status::Invalid => self.invalid += 1,
        }
    }
    fn total(&self) -> u64 {
        self.ok + self.failed + self.invalid
    }
    fn all_ok(&self) -> bool {
        self.ok == self.total()
    }
}

/// Runs the sweep, writing its table into `out` and counting the statuses.
fn run_into(
    sweep: &Sweep,
    jobs: usize,
    shard: Shard,
    series: Option<&SeriesSink<'_>>,
    out: impl Write,
    counts: &mut Counts,
    bar: &mut Progress,
) -> Result<(), SweepError<io::Error>> {
    let mut table = TableWriter::new(out, sweep.layout().clone()).map_err(SweepError::Deliver)?;
    sweep.run_all(jobs, shard, series, |o| {
        counts.add(o);
        bar.set(counts.total() as f64);
        table.write(o)
    })?;
    table
        .finish()
        .map_err(SweepError::Deliver)?
        .flush()
        .map_err(SweepError::Deliver)
}

/// The results must not overwrite the sweep file or its base scene.
fn refuse_inputs(sweep: &Sweep, out: &Path) -> Result<(), String> {
    let same = |a: &Path| match (a.canonicalize(), out.canonicalize()) {
        (Ok(a), Ok(b)) => a == b,
        _ => false,
    };
    if same(&sweep.file) || same(&sweep.scene_file) {
        return Err(format!(
            "{}: the results would overwrite an input file; give another path",
            out.display()
        ));
    }
    Ok(())
}

/// Writes one run's rows as `DIR/run_<run>.csv`, atomically.
fn write_series(dir: &Path, run: u64, columns: ColumnSet, rows: &[Sample]) -> Result<(), String> {
    let path = dir.join(format!("run_{run:06}.csv"));
    let fail = |e: io::Error| format!("{}: {e}", path.display());
    let mut file = AtomicFile::create(&path).map_err(fail)?;
    let mut csv = CsvWriter::new(file.file(), columns).map_err(fail)?;
    for s in rows {
        csv.write(s).map_err(fail)?;
    }
    csv.finish().map_err(fail)?;
    file.commit().map_err(fail)
}
