//! The command line: `run`, `check`, `compare`, `plot`, `view`, …. Data goes to stdout, messages (and the progress bar) to
//! stderr. Exit codes: 0 ok, 1 the run failed, 2 bad input.

use std::io::{self, IsTerminal, Write};
use std::path::{Path, PathBuf};
use std::process::ExitCode;

use clap::{Args, Parser, Subcommand};

use crate::balance::{BalanceArgs, balance_command};
use crate::capabilities::Capabilities;
use crate::progress::{self, Progress};
use crate::sweep::{SweepArgs, SweepFailure, sweep_command};
use crate::view::{ViewArgs, view_command};
use eulerdyn::analysis::describe;
use eulerdyn::command::{Command as _, CommandError};
use eulerdyn::events::Occurrence;
use eulerdyn::output::events_file::{events_path, events_table};
use eulerdyn::output::plot::{self, Panel, PlotError};
use eulerdyn::output::view::ViewError;
use eulerdyn::output::{CsvWriter, WriteRunError, same_file, write_run_with_events};
use eulerdyn::sample::ColumnSet;
use eulerdyn::scene::Scene;
use eulerdyn::scene::{self, Flags, Overrides, SceneError};
use eulerdyn::simulate::{self, RunError, RunFailed, RunReport};

/// Euler's equation of rigid-body rotation, M = d/dt(I·ω), in body and space axes.
#[derive(Debug, Parser)]
#[command(
    name = "eulerdyn",
    version,
    about,
    long_about = None,
    after_help = "Examples:\n  eulerdyn check scenarios/tilted_disk.toml              what will be simulated\n  eulerdyn run scenarios/tilted_disk.toml -o disk.csv    the CSV time series (and disk.csv.meta.json)\n  eulerdyn plot disk.csv -o disk.svg                     H in body and space axes, M, omega, energy, drift\n  eulerdyn compare scenarios/asymmetric_free.toml        both forms against the closed form\n  eulerdyn accuracy scenarios/asymmetric_free.toml -o t.csv --plot t.svg   what each digit of accuracy costs\n  eulerdyn sweep scenarios/sweeps/disk_bearing_map.toml -o map.csv   many runs, one row each\n\nData goes to stdout, messages to stderr. Exit codes: 0 ok, 1 the run failed, 2 bad input, 130 interrupted."
)]
pub struct Cli {
    /// No progress bar and no messages on stderr except errors.
    #[arg(short, long, global = true)]
    pub quiet: bool,
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
    /// than the scene's `[compare]` tolerance.
    #[command(after_help = "Example:\n  eulerdyn compare scenarios/asymmetric_free.toml")]
    Compare {
        /// Scene file (TOML).
        scene: PathBuf,
        /// Integration method instead of the scene's (rk4, dopri5, dop853, split2, split4, exact).
        #[arg(long)]
        method: Option<String>,
    },
    /// Validate a scene and print what it will simulate.
    #[command(after_help = "Example:\n  eulerdyn check scenarios/tilted_disk.toml")]
    Check {
        /// Scene file (TOML).
        scene: PathBuf,
        /// Print the numbers at full precision as JSON (mass, C, inertia, principal axes, moment center, the
        /// scene as simulated) instead of the text.
        #[arg(long)]
        json: bool,
    },
    /// Plot a run's CSV as a figure (SVG, or PNG when the output ends in .png).
    ///
    /// One panel per quantity, in a grid: H in body and in space axes, the moment M, omega, the energy, and the
    /// drift of the scene's invariants on a log scale.
    Plot(PlotArgs),
    /// Work-precision study: every applicable method over a sweep of tolerances or step sizes, its error against
    /// the closed form (or a reference run) and its cost in wall time, steps and evaluations.
    Accuracy(AccuracyArgs),
    /// Two-plane balancing of a fixed-axis or hinge scene: the correction masses that remove the static and the
    /// dynamic imbalance, so that the rotating bearing reactions vanish at every rate; from the scene's mass
    /// distribution or from measured 1x phasors, with the ISO 21940-11 balance grade before and after.
    Balance(BalanceArgs),
    /// Sweeps and Monte Carlo: many runs of a base scene with numeric keys set from grids or random draws, run in
    /// parallel, one results row per run (largest loads, drifts, final omega, cost).
    #[command(
        after_help = "Examples:\n  eulerdyn sweep scenarios/sweeps/disk_bearing_map.toml -o map.csv\n  eulerdyn sweep scenarios/sweeps/tumble_monte_carlo.toml -o mc.csv --jobs 2\n  eulerdyn sweep SWEEP.toml -o part_3.csv --shard 3/8       one of 8 independent processes\n\nExit codes: 0 all runs ok, 1 some runs failed or were invalid (the table is complete), 2 a bad sweep file."
    )]
    Sweep(SweepArgs),
    /// Show a run in 3D: one self-contained HTML page (no network request) with the body, its axes, ω, H and M,
    /// the trail of H, play/pause, a time slider and speed control.
    #[command(
        after_help = "Example:\n  eulerdyn run scenarios/tilted_disk.toml -o disk.csv\n  eulerdyn view disk.csv -o disk.html     then open disk.html in a browser\n\nThe body's shape comes from the sidecar disk.csv.meta.json; without it the body is drawn as a cube.\nRuns of more than 10000 rows are decimated for the page (the page and the README say which rows are kept)."
    )]
    View(ViewArgs),
    /// The commands that live in a capability's folder ([`Capabilities`]).
    #[command(flatten)]
    Capability(Capabilities),
}

#[derive(Debug, Args)]
#[command(
    after_help = "Example:\n  eulerdyn accuracy scenarios/asymmetric_free.toml -o table.csv --plot work_precision.svg\n\nWithout -o the table goes to stdout and the summary to stderr; with -o the summary goes to stdout."
)]
pub struct AccuracyArgs {
    /// Scene file (TOML).
    pub scene: PathBuf,
    /// Table CSV, a row per run, columns:
    /// method,frame,rtol,dt,err_omega,err_attitude,energy_drift,H_drift,wall_s,steps,rejected,evals,err_H_s,atol,backend,repeats,status
    ///
    /// `-` or absent: stdout.
    #[arg(short = 'o', long = "output", value_name = "TABLE.csv")]
    pub output: Option<PathBuf>,
    /// Log-log SVG figure: error against wall time, a curve per method.
    #[arg(long, value_name = "FIG.svg")]
    pub plot: Option<PathBuf>,
}

#[derive(Debug, Args)]
#[command(
    after_help = "Examples:\n  eulerdyn run scenarios/tilted_disk.toml -o disk.csv\n  eulerdyn plot disk.csv -o disk.svg\n  eulerdyn plot disk.csv -o disk_h.svg --panels h_body,h_space\n  eulerdyn plot disk.csv -o disk.png --panels h_body,h_space --size 16,10 --title \"Tilted disk\"   PNG, 300 dpi\n  eulerdyn run scenarios/motor_runup.toml -o m.csv && eulerdyn plot m.csv -o m.svg --panels omega,theta,support,bearings\n  eulerdyn run scenarios/tennis_racket.toml | eulerdyn plot - -o racket.svg --panels omega,drift\n\nPanels: h_body, h_space, moment, omega, energy, drift (every run has these six); for fixed_axis\nand hinge runs also theta, support and bearings (with bearings; bearings_space draws them in space axes); for runs\nwith wheels wheel_spin, wheel_h, wheel_torque and, under control, wheel_friction. Default and `all`: the panels the run has. The energy panel adds V and T + V when the run has them (gravity).\nPanels are laid out in a grid (two columns from three panels on), 16 cm wide by default; sizes are in\ncentimetres at 96 pixels per inch, and every text is at least 9 pt (12 px) at that size.\nThe output's extension chooses the format: FIG.png is PNG (text in the embedded DejaVu Sans), else SVG."
)]
pub struct PlotArgs {
    /// CSV written by `eulerdyn run` (columns are found by their header names); `-`: stdin.
    #[arg(value_name = "RUN.csv")]
    pub csv: PathBuf,
    /// Output file, written atomically (a device or FIFO is written through): SVG, or PNG when its name ends in
    /// .png; `-`: SVG to stdout.
    #[arg(short = 'o', long = "output", value_name = "FIG.svg")]
    pub output: Option<PathBuf>,
    /// Panels to draw, comma-separated, in the order given: h_body, h_space, moment, omega, energy, drift (every
    /// run has these six); theta, support, bearings (and bearings_space, the same in space axes) for fixed_axis
    /// and hinge runs; wheel_spin, wheel_h, wheel_torque (with the friction dashed) for runs with wheels
    /// ([[body.rotor]]) and wheel_friction for wheels under control; lvlh (roll, pitch, yaw from the LVLH frame)
    /// for runs in orbit, field (B in body axes) with magnetic or b_dot, dipole (the magnetorquers') with b_dot. `all`, alone: every panel the run has.
    ///
    /// Default: the panels the run has (and `all`): the six, then theta and support for a fixed_axis or hinge
    /// run, bearings when it has bearings, wheel_spin, wheel_h and wheel_torque when it has wheels, with
    /// wheel_friction when they are under control, and lvlh, field and dipole in orbit when the run has them.
    #[arg(long, value_name = "LIST")]
    pub panels: Option<String>,
    /// Figure width and height in centimetres (at 96 pixels per inch), e.g. 16,12. Default: 16 cm wide, as
    /// tall as the panels' rows need (6 cm a row in one column, 7 cm in two, plus 0.9 cm for the title).
    #[arg(long, value_name = "W,H")]
    pub size: Option<String>,
    /// The figure's title, instead of the scene, method and rows; `--title ""`: no title.
    #[arg(long, value_name = "TEXT")]
    pub title: Option<String>,
    /// Pixels per inch of a PNG (default 300): a 16 cm figure is then 1890 px wide. PNG output only.
    #[arg(long, value_name = "N")]
    pub dpi: Option<String>,
}

#[derive(Debug, Args)]
pub struct RunArgs {
    /// Scene file (TOML).
    pub scene: PathBuf,
    /// Output CSV file, written atomically with a FILE.meta.json sidecar; `-` or absent: stdout.
    #[arg(short = 'o', long = "output")]
    pub output: Option<PathBuf>,
    /// Integration method: rk4, dopri5, dop853, split2, split4 or exact (torque-free only).
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

impl From<CommandError> for Failure {
    fn from(e: CommandError) -> Self {
        match e {
            CommandError::Input(m) => Failure::Input(m),
            CommandError::Run(m) => Failure::Run(m),
        }
    }
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
    let quiet = cli.quiet;
    let result = match cli.command {
        Command::Run(args) => run(&args, quiet),
        Command::Check { scene, json } => check(&scene, json),
        Command::Compare { scene, method } => compare(&scene, method, quiet),
        Command::Plot(args) => plot_command(&args, quiet),
        Command::Accuracy(args) => accuracy_command(&args, quiet),
        Command::Balance(args) => balance_command(&args)
            .map_err(Failure::Input)
            .and_then(|text| print_stdout(&text)),
        Command::Sweep(args) => sweep(&args, quiet),
        Command::View(args) => view(&args, quiet),
        Command::Capability(c) => c.run(quiet).map_err(Failure::from),
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

/// `eulerdyn view`: writes the page; warnings and what was written on stderr unless `quiet`.
fn view(args: &ViewArgs, quiet: bool) -> Result<(), Failure> {
    let lines = view_command(args).map_err(|e| match e {
        ViewError::Input { .. } => Failure::Input(e.to_string()),
        ViewError::Output { .. } => Failure::Run(e.to_string()),
    })?;
    if !quiet {
        for line in lines {
            eprintln!("{line}");
        }
    }
    Ok(())
}

fn sweep(args: &SweepArgs, quiet: bool) -> Result<(), Failure> {
    match sweep_command(args, quiet) {
        Ok((account, true)) => {
            if !quiet {
                eprintln!("wrote {account}");
            }
            Ok(())
        }
        Ok((account, false)) => Err(Failure::Run(format!("not every run was ok: {account}"))),
        Err(SweepFailure::Input(m)) => Err(Failure::Input(m)),
        Err(SweepFailure::Run(m)) => Err(Failure::Run(m)),
    }
}

fn check(path: &Path, json: bool) -> Result<(), Failure> {
    let scene = scene::load(path, &Overrides::default())?;
    let warnings = scene::advice::warnings(&scene);
    if json {
        let facts = eulerdyn::analysis::facts::facts(&scene, &warnings);
        let text = serde_json::to_string_pretty(&facts).map_err(|e| Failure::Run(e.to_string()))?;
        return print_stdout(&format!("{text}\n"));
    }
    print_stdout(&describe::describe(&scene, &warnings).text())
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

fn compare(path: &Path, method: Option<String>, quiet: bool) -> Result<(), Failure> {
    let overrides = Flags {
        method: method.as_deref(),
        ..Flags::default()
    }
    .overrides(path)?;
    let scene = scene::load(path, &overrides)?;
    let spinner = Progress::spinner(
        "compare",
        "running both forms and the closed form",
        progress::wanted(quiet),
    );
    let comparison = eulerdyn::analysis::compare::compare(&scene);
    spinner.finish();
    let comparison = comparison.map_err(|e| Failure::Run(RunFailed::new(path, &e).to_string()))?;
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

fn run(args: &RunArgs, quiet: bool) -> Result<(), Failure> {
    let overrides = Flags {
        method: args.method.as_deref(),
        frame: args.frame.as_deref(),
        backend: args.backend.as_deref(),
        rtol: args.rtol,
        atol: args.atol,
        dt: args.dt,
        t_end: args.t_end,
        every: args.every,
    }
    .overrides(&args.scene)?;
    let scene_model = scene::load(&args.scene, &overrides)?;
    for warning in simulate::warnings_before_run(&scene_model) {
        eprintln!("{}: warning: {warning}", args.scene.display());
    }
    let columns = scene_model.facts().columns().clone();
    let mut progress = Progress::bar(
        "run",
        "t",
        scene_model.solver.t_end,
        "s",
        progress::wanted(quiet),
    );
    let output = args.output.as_deref().filter(|p| p.as_os_str() != "-");
    let Some(out_path) = output else {
        let written = write_csv(
            &args.scene,
            &scene_model,
            columns,
            io::stdout().lock(),
            &mut progress,
        );
        progress.finish();
        return match written {
            Ok((_, _, events)) => {
                if !scene_model.events.is_empty() {
                    eprint!("{}", events_table(&events));
                }
                Ok(())
            }
            Err(RunError::Sink(e)) if e.kind() == io::ErrorKind::BrokenPipe => Ok(()),
            Err(e) => Err(run_failure(&args.scene, Path::new("stdout"), e)),
        };
    };
    run_to_file(args, &scene_model, out_path, progress, quiet)
}

/// `run -o FILE`: the CSV and its sidecar written by the library ([`eulerdyn::output::write_run`]: atomically,
/// or the CSV alone written through to a device or FIFO), then the "wrote …" line.
fn run_to_file(
    args: &RunArgs,
    scene_model: &Scene,
    out_path: &Path,
    mut progress: Progress,
    quiet: bool,
) -> Result<(), Failure> {
    let (report, events) = write_run_with_events(scene_model, out_path, |t| progress.set(t))
        .map_err(|e| match e {
            WriteRunError::Output { .. } => Failure::Input(e.to_string()),
            WriteRunError::Run(e) => run_failure(&args.scene, out_path, e),
            WriteRunError::Save { .. } => Failure::Run(e.to_string()),
        })?;
    progress.finish();
    if let Some(drift) = simulate::drift_warning(report.energy_drift) {
        eprintln!("{}: warning: {drift}", args.scene.display());
    }
    if quiet {
        return Ok(());
    }
    let step = scene_model
        .fixed_step()
        .map_or(String::new(), |h| format!(" of {h} s"));
    eprintln!(
        "wrote {} rows to {} ({} steps{step}, {} rejected, {} right-hand-side evaluations, {:.3} s)",
        report.rows,
        out_path.display(),
        report.stats.steps,
        report.stats.rejected,
        report.stats.evals,
        report.wall_seconds
    );
    if !scene_model.events.is_empty() {
        eprintln!(
            "wrote {} events to {}",
            events.len(),
            events_path(out_path).display()
        );
    }
    Ok(())
}

/// Runs the scene, streaming its rows as CSV into `out` and its time into `progress`; returns the report, the
/// flushed writer and the located events.
fn write_csv<W: Write>(
    scene_path: &Path,
    scene: &Scene,
    columns: ColumnSet,
    out: W,
    progress: &mut Progress,
) -> Result<(RunReport, W, Vec<Occurrence>), RunError<io::Error>> {
    let mut writer = CsvWriter::new(out, columns).map_err(RunError::Sink)?;
    let (report, events) = simulate::run_with_events(scene, |s| {
        progress.set(s.t);
        writer.write(s)
    })?;
    let out = writer.finish().map_err(RunError::Sink)?;

    if let Some(drift) = simulate::drift_warning(report.energy_drift) {
        eprintln!("{}: warning: {drift}", scene_path.display());
    }
    Ok((report, out, events))
}

fn run_failure(scene: &Path, out: &Path, e: RunError<io::Error>) -> Failure {
    match e {
        e @ (RunError::Integrate(_) | RunError::Diverged(_)) => {
            Failure::Run(RunFailed::new(scene, &e).to_string())
        }
        RunError::Sink(e) => Failure::Run(format!("{}: cannot write: {e}", out.display())),
    }
}

/// `eulerdyn accuracy`: the work-precision study, its table to `-o FILE` (or stdout) and its figure to `--plot`.
fn accuracy_command(args: &AccuracyArgs, quiet: bool) -> Result<(), Failure> {
    let table = args.output.as_deref().filter(|p| p.as_os_str() != "-");
    let mut progress = None;
    let result = eulerdyn::analysis::study::run_accuracy_command(
        &args.scene,
        table,
        args.plot.as_deref(),
        &eulerdyn::analysis::study::StudyOptions::default(),
        |done, total, _label| {
            progress
                .get_or_insert_with(|| {
                    Progress::bar(
                        "accuracy",
                        "run",
                        total as f64,
                        "runs",
                        progress::wanted(quiet),
                    )
                })
                .update(done as f64, total as f64);
        },
    );
    if let Some(p) = progress {
        p.finish();
    }
    let study = result.map_err(|e| match e.exit_code() {
        2 => Failure::Input(e.to_string()),
        _ => Failure::Run(e.to_string()),
    })?;
    match table {
        Some(_) => print_stdout(&study.summary()),
        None => {
            print_stdout(&study.table_csv())?;
            eprint!("{}", study.summary());
            Ok(())
        }
    }
}

/// The figure options of `plot`'s arguments; a bad value is bad input naming its flag.
fn figure_options(args: &PlotArgs) -> Result<plot::FigureOptions, Failure> {
    let size = args
        .size
        .as_deref()
        .map(str::parse::<plot::FigureSize>)
        .transpose()
        .map_err(|e| Failure::Input(format!("--size: {e}")))?;
    let dpi = args
        .dpi
        .as_deref()
        .map(plot::parse_dpi)
        .transpose()
        .map_err(|e| Failure::Input(format!("--dpi: {e}")))?;
    Ok(plot::FigureOptions {
        size,
        title: args.title.clone(),
        dpi,
    })
}

/// `eulerdyn plot`: reads a run's CSV and writes the SVG figure to `-o FILE` (atomically) or to stdout.
fn plot_command(args: &PlotArgs, quiet: bool) -> Result<(), Failure> {
    // None: the panels the run has, chosen once its header is read.
    let panels = match args.panels.as_deref() {
        Some(list) => {
            Panel::parse_list(list).map_err(|e| Failure::Input(format!("--panels: {e}")))?
        }
        None => Vec::new(),
    };
    let options = figure_options(args)?;
    let to_stdout = match args.output.as_deref() {
        Some(p) => p.as_os_str() == "-",
        None if io::stdout().is_terminal() => {
            return Err(Failure::Input(
                "give the SVG file to write with -o FIG.svg (or -o - to write the SVG to stdout)"
                    .into(),
            ));
        }
        None => true,
    };
    let plot_failure = |e: PlotError| match e {
        PlotError::Input { .. } | PlotError::Option(_) => Failure::Input(e.to_string()),
        PlotError::Output { .. } => Failure::Run(e.to_string()),
    };
    match args.output.as_deref().filter(|_| !to_stdout) {
        Some(out) => {
            if same_file(&args.csv, out) {
                return Err(Failure::Input(format!(
                    "{}: the figure would overwrite the CSV it plots; give another -o path",
                    out.display()
                )));
            }
            let summary =
                plot::plot_file(&args.csv, out, &panels, &options).map_err(plot_failure)?;
            if !quiet {
                let names: Vec<&str> = summary.panels.iter().map(|p| p.name()).collect();
                eprintln!(
                    "wrote {} ({} rows; panels {}; {} x {} px)",
                    out.display(),
                    summary.rows,
                    names.join(", "),
                    summary.pixels.0,
                    summary.pixels.1
                );
            }
            Ok(())
        }
        None => {
            if options.dpi.is_some() {
                return Err(Failure::Input(
                    "--dpi: only a PNG has a resolution, and stdout gets SVG; give -o FIG.png"
                        .into(),
                ));
            }
            let run = plot::read_run(&args.csv, &panels).map_err(plot_failure)?;
            let svg = plot::render_svg(&run, &panels, &options, Path::new("stdout"))
                .map_err(plot_failure)?;
            print_stdout(&svg)
        }
    }
}
