//! `eulerdyn score` (another program's trajectory against the referee) and `eulerdyn suite` (the conformance
//! suite): their arguments and printing, registered in the binary's `capabilities!` list.

use std::path::{Path, PathBuf};

use clap::{Args, Subcommand, ValueEnum};

use super::{QuaternionOrder, ReadOptions, Score, ScoreError, Series, figure, report, suite};
use crate::command::{Command, CommandError};
use crate::frames::Axes;
use crate::output::{AtomicFile, plot};
use crate::scene::{self, Overrides};

/// The commands of scoring.
#[derive(Debug, Subcommand)]
pub enum Commands {
    /// Score another program's trajectory of a scene against eulerdyn's exact solution (or dop853 at rtol 1e-13):
    /// attitude, omega, energy, |H|, H's direction and event times, each against a stated threshold; exit 1 when
    /// one fails. With --suite DIR --engine NAME: an engine's report card on the conformance suite.
    #[command(
        after_help = "Examples:\n  eulerdyn score theirs.csv --scene scenarios/tennis_racket.toml\n  eulerdyn score rapier.csv --scene s.toml --quaternion xyzw --omega space --map q_0=qx --map q_1=qy --map q_2=qz --map q_3=qw\n  eulerdyn suite --out suite && eulerdyn score --suite suite --engine mujoco_rk4\n  eulerdyn score theirs.csv --scene scenarios/tennis_racket.toml --diagnose"
    )]
    Score(ScoreArgs),
    /// Write the conformance suite: six scenes, each with its reference trajectory at 60 Hz, its adapter setup
    /// (JSON) and a note of what it tests.
    #[command(after_help = "Example:\n  eulerdyn suite --out suite")]
    Suite(SuiteArgs),
}

impl Command for Commands {
    fn run(&self, quiet: bool) -> Result<(), CommandError> {
        match self {
            Commands::Score(args) => score_command(args, quiet),
            Commands::Suite(args) => suite_command(args, quiet),
        }
        .map_err(|e| match e {
            ScoreError::Input(m) => CommandError::Input(m),
            ScoreError::Run(m) => CommandError::Run(m),
        })
    }
}

// The variants' names say what they are; doc comments on them would turn clap's one-line list of possible values
// into a paragraph per value.
/// The order of the generic quaternion columns q_0..q_3: scalar first (`wxyz`) or last (`xyzw`).
#[derive(Debug, Clone, Copy, ValueEnum)]
#[allow(missing_docs)]
pub enum OrderArg {
    Wxyz,
    Xyzw,
}

/// The axes of their ω columns.
#[derive(Debug, Clone, Copy, ValueEnum)]
#[allow(missing_docs)]
pub enum OmegaArg {
    Body,
    Space,
}

/// `eulerdyn score`'s arguments.
#[derive(Debug, Args)]
pub struct ScoreArgs {
    /// Their trajectory: a CSV with t, the attitude (q_w..q_z, q_0..q_3 or R_11..R_33) and optionally omega_x..z.
    #[arg(value_name = "THEIRS.csv", required_unless_present = "suite")]
    pub theirs: Option<PathBuf>,
    /// The scene their trajectory simulates (TOML).
    #[arg(long, value_name = "SCENE", conflicts_with = "suite")]
    #[arg(required_unless_present = "suite")]
    pub scene: Option<PathBuf>,
    /// Score an engine's outputs DIR/ENGINE/SCENE.csv against the suite written by `eulerdyn suite --out DIR`.
    #[arg(long, value_name = "DIR", requires = "engine")]
    #[arg(conflicts_with = "theirs")]
    pub suite: Option<PathBuf>,
    /// The engine's folder in the suite (with --suite).
    #[arg(long, value_name = "NAME")]
    pub engine: Option<String>,
    /// The order of the generic quaternion columns q_0..q_3: scalar first or last.
    #[arg(long, value_enum, default_value = "wxyz")]
    pub quaternion: OrderArg,
    /// The axes of omega_x..z.
    #[arg(long, value_enum, default_value = "body")]
    pub omega: OmegaArg,
    /// NAME=COLUMN: read eulerdyn's column NAME (t, q_w…, R_11…, omega_x…) from their column COLUMN; repeatable.
    #[arg(long = "map", value_name = "NAME=COLUMN")]
    pub map: Vec<String>,
    /// Print the score as JSON instead of the table.
    #[arg(long)]
    pub json: bool,
    /// Name the engine model the trajectory is consistent with: explicit or semi-implicit Euler or RK4, ω held in
    /// world or body axes, the gyroscopic term full, left out or flipped, 1, 2, 4 or 8 substeps a row.
    #[arg(long)]
    pub diagnose: bool,
    /// Draw the errors against time (log scale) into this SVG file.
    #[arg(long, value_name = "FIG.svg")]
    pub plot: Option<PathBuf>,
}

/// `eulerdyn suite`'s arguments.
#[derive(Debug, Args)]
pub struct SuiteArgs {
    /// The folder to write the suite into (created if needed).
    #[arg(long, value_name = "DIR")]
    pub out: PathBuf,
}

/// The reading options of `args`.
fn options(args: &ScoreArgs) -> Result<ReadOptions, ScoreError> {
    read_options(args.quaternion, args.omega, &args.map).map_err(ScoreError::Input)
}

/// The reading options of `--quaternion`, `--omega` and `--map` (shared with `fit`); a `--map` without `=` is
/// refused.
pub fn read_options(
    quaternion: OrderArg,
    omega: OmegaArg,
    map: &[String],
) -> Result<ReadOptions, String> {
    let map = (map.iter())
        .map(|m| {
            m.split_once('=')
                .map(|(n, c)| (n.trim().to_string(), c.trim().to_string()))
                .ok_or_else(|| format!("--map {m}: expected NAME=COLUMN"))
        })
        .collect::<Result<_, _>>()?;
    Ok(ReadOptions {
        quaternion: match quaternion {
            OrderArg::Wxyz => QuaternionOrder::Wxyz,
            OrderArg::Xyzw => QuaternionOrder::Xyzw,
        },
        omega: Some(match omega {
            OmegaArg::Body => Axes::Body,
            OmegaArg::Space => Axes::Space,
        }),
        map,
    })
}

/// Writes the figure of `series` to `path`: PNG when its name ends in `.png`, else SVG. A path that cannot be
/// created (a missing folder) is bad input (exit 2), as for every other output; a failed write is exit 1.
fn write_plot(path: &Path, title: &str, series: &[Series]) -> Result<(), ScoreError> {
    let svg = figure::render_svg(title, series).map_err(ScoreError::Run)?;
    let fail = |e: String| format!("{}: cannot write the figure: {e}", path.display());
    let bytes =
        plot::figure_bytes(svg, figure::PIXELS, path).map_err(|e| ScoreError::Run(fail(e)))?;
    let file = AtomicFile::create(path).map_err(|e| {
        ScoreError::Input(format!(
            "{}: cannot create the output file: {e}",
            path.display()
        ))
    })?;
    file.write_and_commit(&bytes)
        .map_err(|e| ScoreError::Run(fail(e.to_string())))
}

/// `eulerdyn score`: prints the score (or the suite's report card); `Err(Run)` when a verdict fails (exit 1).
fn score_command(args: &ScoreArgs, quiet: bool) -> Result<(), ScoreError> {
    let options = options(args)?;
    let (text, json, passes, figure) = match (&args.suite, &args.theirs, &args.scene) {
        (Some(dir), _, _) => {
            let engine = args.engine.as_deref().unwrap_or_default();
            let scores = suite::score_suite(dir, engine, &options, args.diagnose)?;
            let series: Vec<Series> = (scores.iter().filter(|s| !s.missing))
                .map(|s| Series {
                    name: s.scene.clone(),
                    ..s.series[0].clone()
                })
                .collect();
            let title = format!("{engine}: attitude error against the referee (rad)");
            (
                report::card(engine, &scores),
                serde_json::to_string_pretty(&scores),
                scores.iter().all(Score::passes),
                (title, series),
            )
        }
        (None, Some(theirs), Some(scene_path)) => {
            let scene = scene::load(scene_path, &Overrides::default())
                .map_err(|e| ScoreError::Input(e.to_string()))?;
            let s = super::score_with(theirs, &scene, &options, args.diagnose)?;
            let title = format!("{}: errors against the referee", theirs.display());
            (
                report::text(&s),
                serde_json::to_string_pretty(&s),
                s.passes(),
                (title, s.series.clone()),
            )
        }
        _ => {
            return Err(ScoreError::Input(
                "give THEIRS.csv --scene SCENE, or --suite DIR --engine NAME".into(),
            ));
        }
    };
    if let Some(path) = &args.plot {
        write_plot(path, &figure.0, &figure.1)?;
    }
    if args.json {
        println!("{}", json.map_err(|e| ScoreError::Run(e.to_string()))?);
    } else {
        print!("{text}");
    }
    if !quiet && let Some(path) = &args.plot {
        eprintln!("wrote {}", path.display());
    }
    if passes {
        Ok(())
    } else {
        Err(ScoreError::Run(
            "not every metric passes the referee's threshold".into(),
        ))
    }
}

/// `eulerdyn suite`: writes the suite, says what on stderr.
fn suite_command(args: &SuiteArgs, quiet: bool) -> Result<(), ScoreError> {
    let written = suite::write_suite(&args.out)?;
    if !quiet {
        eprintln!("wrote {} files into {}", written.len(), args.out.display());
    }
    Ok(())
}
