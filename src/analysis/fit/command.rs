//! `eulerdyn fit`: its arguments and printing, registered in the binary's `capabilities!` list.

use std::path::{Path, PathBuf};

use clap::{Args, Subcommand};

use super::solve::Fit;
use super::{FitError, FitOptions, figure, fit_file, parse_estimates, report};
use crate::analysis::score::command::{OmegaArg, OrderArg, read_options};
use crate::command::{Command, CommandError};
use crate::output::{AtomicFile, plot};
use crate::scene::{self, Overrides};

/// The commands of fitting.
#[derive(Debug, Subcommand)]
pub enum Commands {
    /// Estimate a body from its measured motion: the inertia, omega0, the initial attitude and a gyro's bias that
    /// make the scene's model match a gyro's omega and/or the attitude (least squares, Jacobians from the
    /// variational equations), with standard errors, 95 % intervals and correlations; exit 1 when the fit does not
    /// converge or its inertia is not a body.
    #[command(
        after_help = "Examples:\n  eulerdyn fit gyro.csv --scene scenarios/cubesat_tumble.toml --estimate principal,omega0,gyro_bias\n  eulerdyn fit log.csv --scene s.toml --estimate inertia,omega0 --sigma-omega 1e-3 --json -o fitted.toml --plot residuals.svg"
    )]
    Fit(FitArgs),
}

impl Command for Commands {
    fn run(&self, quiet: bool) -> Result<(), CommandError> {
        match self {
            Commands::Fit(args) => fit_command(args, quiet),
        }
    }
}

/// `eulerdyn fit`'s arguments.
#[derive(Debug, Args)]
pub struct FitArgs {
    /// The measured motion: a CSV with t and a gyro's omega_x..z and/or the attitude (q_w..q_z, q_0..q_3 or
    /// R_11..R_33); rows need not be evenly spaced.
    #[arg(value_name = "MEASURED.csv")]
    pub measured: PathBuf,
    /// The scene: the model (its effects act as in `run`) and the start of the estimates.
    #[arg(long, value_name = "SCENE")]
    pub scene: PathBuf,
    /// A comma list of: inertia, principal, omega0, attitude0, gyro_bias.
    #[arg(long, value_name = "LIST")]
    pub estimate: String,
    /// The gyro's noise (rad/s, one sigma per axis); default: from the residuals.
    #[arg(long, value_name = "S")]
    pub sigma_omega: Option<f64>,
    /// The attitude's noise (rad, one sigma per axis); default: from the residuals.
    #[arg(long, value_name = "S")]
    pub sigma_attitude: Option<f64>,
    /// The order of the generic quaternion columns q_0..q_3: scalar first or last.
    #[arg(long, value_enum, default_value = "wxyz")]
    pub quaternion: OrderArg,
    /// The axes of omega_x..z.
    #[arg(long, value_enum, default_value = "body")]
    pub omega: OmegaArg,
    /// NAME=COLUMN: read eulerdyn's column NAME (t, q_w…, R_11…, omega_x…) from the file's COLUMN; repeatable.
    #[arg(long = "map", value_name = "NAME=COLUMN")]
    pub map: Vec<String>,
    /// Print the fit as JSON instead of the table.
    #[arg(long)]
    pub json: bool,
    /// Draw the residuals against time into this SVG (or .png) file.
    #[arg(long, value_name = "FIG.svg")]
    pub plot: Option<PathBuf>,
    /// Write the scene with the estimates in (a scene that runs).
    #[arg(short = 'o', long = "output", value_name = "FITTED.toml")]
    pub output: Option<PathBuf>,
}

/// The options of `args`.
fn options(args: &FitArgs) -> Result<FitOptions, FitError> {
    Ok(FitOptions {
        estimates: parse_estimates(&args.estimate)?,
        sigma_omega: args.sigma_omega,
        sigma_attitude: args.sigma_attitude,
        read: read_options(args.quaternion, args.omega, &args.map).map_err(FitError::Input)?,
    })
}

/// An output file opened (a path that cannot be created is bad input, exit 2) and its bytes written (a failed
/// write is exit 1).
fn write(path: &Path, bytes: &[u8]) -> Result<(), CommandError> {
    let file = AtomicFile::create(path).map_err(|e| {
        CommandError::Input(format!(
            "{}: cannot create the output file: {e}",
            path.display()
        ))
    })?;
    file.write_and_commit(bytes)
        .map_err(|e| CommandError::Run(format!("{}: cannot write: {e}", path.display())))
}

/// The figure's bytes: PNG when the name ends in `.png`, else SVG.
fn figure_bytes(path: &Path, fit: &Fit) -> Result<Vec<u8>, CommandError> {
    let title = format!("{}: residuals of the fit", fit.file);
    let svg = figure::render_svg(&title, &fit.residuals).map_err(CommandError::Run)?;
    plot::figure_bytes(svg, figure::PIXELS, path)
        .map_err(|e| CommandError::Run(format!("{}: cannot write the figure: {e}", path.display())))
}

/// `eulerdyn fit`: prints the fit; writes `-o` and `--plot` only when it succeeded.
fn fit_command(args: &FitArgs, quiet: bool) -> Result<(), CommandError> {
    let input = |e: FitError| match e {
        FitError::Input(m) => CommandError::Input(m),
        FitError::Run(m) => CommandError::Run(m),
    };
    let options = options(args).map_err(input)?;
    let scene = scene::load(&args.scene, &Overrides::default())
        .map_err(|e| CommandError::Input(e.to_string()))?;
    let fit = fit_file(&args.measured, &scene, &options).map_err(input)?;
    if args.json {
        let json =
            serde_json::to_string_pretty(&fit).map_err(|e| CommandError::Run(e.to_string()))?;
        println!("{json}");
    } else {
        print!("{}", report::text(&fit));
    }
    if !fit.succeeded() {
        return Err(CommandError::Run(match &fit.unphysical {
            Some(why) => format!("{why}; nothing written"),
            None => format!(
                "the fit did not converge ({}); nothing written",
                fit.termination
            ),
        }));
    }
    if let Some(path) = &args.plot {
        write(path, &figure_bytes(path, &fit)?)?;
    }
    if let Some(path) = &args.output {
        let text = toml::to_string(&fit.fitted)
            .map_err(|e| CommandError::Run(format!("cannot write the scene: {e}")))?;
        write(path, text.as_bytes())?;
    }
    if !quiet {
        for path in args.plot.iter().chain(&args.output) {
            eprintln!("wrote {}", path.display());
        }
    }
    Ok(())
}
