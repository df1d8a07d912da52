//! The command line: `run`, `check`. Data goes to stdout, messages to stderr. Exit codes: 0 ok, 1 the run failed,
//! 2 bad input.

use std::fs::File;
use std::io::{self, Write};
use std::path::{Path, PathBuf};
use std::process::ExitCode;

use clap::{Args, Parser, Subcommand};

use crate::model::Scene;
use crate::output::{AtomicFile, ColumnSet, CsvWriter, meta};
use crate::report;
use crate::scene::{self, Overrides, SceneError};
use crate::simulate::{self, RunError, RunReport};

/// Euler's equation of rigid-body rotation, M = d/dt(I·ω), in body and space axes.
#[derive(Debug, Parser)]
#[command(name = "eulerdyn", version, about, long_about = None)]
pub struct Cli {
    #[command(subcommand)]
    pub command: Command,
}

#[derive(Debug, Subcommand)]
pub enum Command {
    /// Simulate a scene and write its CSV time series.
    #[command(
        after_help = "Example:\n  eulerdyn run scenarios/tilted_disk.toml -o disk.csv\n  eulerdyn run scenarios/tilted_disk.toml --t-end 1 --every 0.1"
    )]
    Run(RunArgs),
    /// Run a scene in both forms of Euler's equation and against its closed form; exit 1 if they differ by more
    /// than the scene's [compare] tolerance.
    #[command(after_help = "Example:\n  eulerdyn compare scenarios/asymmetric_free.toml")]
    Compare {
        /// Scene file (TOML).
        scene: PathBuf,
    },
    /// Validate a scene and print what it will simulate.
    #[command(after_help = "Example:\n  eulerdyn check scenarios/tilted_disk.toml")]
    Check {
        /// Scene file (TOML).
        scene: PathBuf,
    },
}

#[derive(Debug, Args)]
pub struct RunArgs {
    /// Scene file (TOML).
    pub scene: PathBuf,
    /// Output CSV file, written atomically with a FILE.meta.json sidecar; `-` or absent: stdout.
    #[arg(short = 'o', long = "output")]
    pub output: Option<PathBuf>,
    /// Integration method (rk4, dopri5, dop853).
    #[arg(long)]
    pub method: Option<String>,
    /// Form of Euler's equation: body or space.
    #[arg(long)]
    pub frame: Option<String>,
    /// Runge–Kutta implementation: own or ode_solvers.
    #[arg(long)]
    pub backend: Option<String>,
    /// Relative tolerance of adaptive methods.
    #[arg(long, allow_negative_numbers = true)]
    pub rtol: Option<f64>,
    /// Absolute tolerance of adaptive methods.
    #[arg(long, allow_negative_numbers = true)]
    pub atol: Option<f64>,
    /// Step of fixed-step methods (s).
    #[arg(long, allow_negative_numbers = true)]
    pub dt: Option<f64>,
    /// End time (s).
    #[arg(long = "t-end", allow_negative_numbers = true)]
    pub t_end: Option<f64>,
    /// Time between rows (s).
    #[arg(long, allow_negative_numbers = true)]
    pub every: Option<f64>,
}

/// A failure, with the exit code it maps to.
enum Failure {
    /// Bad input: exit 2.
    Input(String),
    /// The run failed: exit 1.
    Run(String),
}

impl From<SceneError> for Failure {
    fn from(e: SceneError) -> Self {
        Failure::Input(e.to_string())
    }
}

/// Parses the command line, runs the command, prints messages, and returns the exit code.
pub fn main() -> ExitCode {
    let cli = Cli::parse();
    if let Err(e) = crate::interrupt::install() {
        eprintln!(
            "warning: cannot handle interrupts ({e}); an interrupted run may leave a temporary file"
        );
    }
    let result = match cli.command {
        Command::Run(args) => run(&args),
        Command::Check { scene } => check(&scene),
        Command::Compare { scene } => compare(&scene),
    };
    match result {
        Ok(()) => ExitCode::SUCCESS,
        Err(Failure::Input(msg)) => {
            eprintln!("error: {msg}");
            ExitCode::from(2)
        }
        Err(Failure::Run(msg)) => {
            eprintln!("error: {msg}");
            ExitCode::from(1)
        }
    }
}

fn check(path: &Path) -> Result<(), Failure> {
    let scene = scene::load(path, &Overrides::default())?;
    print_stdout(&report::describe(&scene))
}

/// Writes `text` to stdout. A closed pipe (`| head`) is not an error; any other failure (a full disk) is a failed
/// run, reported as such instead of a panic.
fn print_stdout(text: &str) -> Result<(), Failure> {
    let mut out = io::stdout().lock();
    match out.write_all(text.as_bytes()).and_then(|()| out.flush()) {
        Ok(()) => Ok(()),
        Err(e) if e.kind() == io::ErrorKind::BrokenPipe => Ok(()),
        Err(e) => Err(Failure::Run(format!("stdout: cannot write: {e}"))),
    }
}

fn compare(path: &Path) -> Result<(), Failure> {
    let scene = scene::load(path, &Overrides::default())?;
    let comparison = crate::compare::compare(&scene)
        .map_err(|e| Failure::Run(format!("{}: the run failed: {e}", path.display())))?;
    print_stdout(&comparison.report())?;
    if comparison.passes() {
        Ok(())
    } else {
        Err(Failure::Run(format!(
            "{}: the differences exceed the tolerance {:e}",
            path.display(),
            comparison.tolerance
        )))
    }
}

fn run(args: &RunArgs) -> Result<(), Failure> {
    let overrides = Overrides {
        method: args.method.clone(),
        frame: args.frame.clone(),
        backend: args.backend.clone(),
        rtol: args.rtol,
        atol: args.atol,
        dt: args.dt,
        t_end: args.t_end,
        every: args.every,
    };
    let scene_model = scene::load(&args.scene, &overrides)?;
    let columns = simulate::columns(&scene_model);
    let output = args.output.as_deref().filter(|p| p.as_os_str() != "-");
    let Some(out_path) = output else {
        return match write_csv(&scene_model, columns, io::stdout().lock()) {
            Ok(_) => Ok(()),
            Err(RunError::Sink(e)) if e.kind() == io::ErrorKind::BrokenPipe => Ok(()),
            Err(e) => Err(run_failure(&args.scene, Path::new("stdout"), e)),
        };
    };
    let file_error = |what: &str, e: io::Error| format!("{}: {what}: {e}", out_path.display());
    if same_file(&args.scene, out_path) {
        return Err(Failure::Input(format!(
            "{}: the output would overwrite the scene file; give another -o path",
            out_path.display()
        )));
    }
    // A destination that exists and is not a regular file (/dev/null, a pipe) is written directly.
    if out_path.exists() && !out_path.is_file() && !out_path.is_dir() {
        let file = File::options()
            .write(true)
            .open(out_path)
            .map_err(|e| Failure::Input(file_error("cannot open", e)))?;
        write_csv(&scene_model, columns, file)
            .map_err(|e| run_failure(&args.scene, out_path, e))?;
        return Ok(());
    }
    let mut csv_file = AtomicFile::create(out_path)
        .map_err(|e| Failure::Input(file_error("cannot create the output file", e)))?;
    let (report, _) = write_csv(&scene_model, columns, csv_file.file())
        .map_err(|e| run_failure(&args.scene, out_path, e))?;
    let scene_text = std::fs::read_to_string(&args.scene).unwrap_or_default();
    let sidecar = meta::sidecar(
        &args.scene.display().to_string(),
        &scene_text,
        &scene_model,
        &report,
        &columns.columns(),
    );
    let meta_path = PathBuf::from(format!("{}.meta.json", out_path.display()));
    let meta_error = |what: &str, e: io::Error| format!("{}: {what}: {e}", meta_path.display());
    let mut meta_file =
        AtomicFile::create(&meta_path).map_err(|e| Failure::Run(meta_error("cannot create", e)))?;
    serde_json::to_writer_pretty(meta_file.file(), &sidecar)
        .map_err(io::Error::from)
        .and_then(|()| meta_file.file().write_all(b"\n"))
        .map_err(|e| Failure::Run(meta_error("cannot write", e)))?;
    csv_file
        .commit()
        .map_err(|e| Failure::Run(file_error("cannot save", e)))?;
    meta_file
        .commit()
        .map_err(|e| Failure::Run(meta_error("cannot save", e)))?;
    eprintln!(
        "wrote {} rows to {} ({} steps, {} rejected, {} right-hand-side evaluations, {:.3} s)",
        report.rows,
        out_path.display(),
        report.stats.steps,
        report.stats.rejected,
        report.stats.evals,
        report.wall_seconds
    );
    Ok(())
}

/// Runs the scene, streaming its rows as CSV into `out`; returns the report and the flushed writer.
fn write_csv<W: Write>(
    scene: &Scene,
    columns: ColumnSet,
    out: W,
) -> Result<(RunReport, W), RunError<io::Error>> {
    let mut writer = CsvWriter::new(out, columns).map_err(RunError::Sink)?;
    let report = simulate::run(scene, |s| writer.write(s))?;
    let out = writer.finish().map_err(RunError::Sink)?;
    Ok((report, out))
}

/// Whether two paths name the same existing file.
fn same_file(a: &Path, b: &Path) -> bool {
    match (a.canonicalize(), b.canonicalize()) {
        (Ok(a), Ok(b)) => a == b,
        _ => false,
    }
}

fn run_failure(scene: &Path, out: &Path, e: RunError<io::Error>) -> Failure {
    match e {
        RunError::Integrate(e) => Failure::Run(format!("{}: the run failed: {e}", scene.display())),
        RunError::Sink(e) => Failure::Run(format!("{}: cannot write: {e}", out.display())),
    }
}
