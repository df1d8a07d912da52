//! `eulerdyn balance`: the two correction masses of a fixed-axis or hinge scene, printed, and the balanced scene
//! written with `-o`.

use std::io::Write;
use std::path::{Path, PathBuf};

use clap::Args;

use eulerdyn::analysis::balance::{Balance, Planes, balance_scene};
use eulerdyn::output::AtomicFile;
use eulerdyn::scene;

#[derive(Debug, Args)]
pub struct BalanceArgs {
    /// Scene file (TOML) with a fixed_axis or hinge motion.
    pub scene: PathBuf,
    /// Axial positions A,B of the two correction planes (m, from `motion.point` along the axis).
    #[arg(long, value_name = "A,B", allow_hyphen_values = true)]
    pub planes: String,
    /// Distance of the correction masses from the axis (m).
    #[arg(long, value_name = "R", allow_negative_numbers = true)]
    pub radius: f64,
    /// Write the scene with both correction masses added (TOML, atomically).
    #[arg(short = 'o', long = "output", value_name = "BALANCED.toml")]
    pub output: Option<PathBuf>,
}

/// Runs the command; `Err` is bad input (exit 2) with its message.
pub fn balance_command(args: &BalanceArgs) -> Result<String, String> {
    let path = &args.scene;
    let text = scene::read(path).map_err(|e| e.to_string())?;
    let planes: Vec<Result<f64, _>> = args
        .planes
        .split(',')
        .map(|p| p.trim().parse::<f64>())
        .collect();
    let [Ok(a), Ok(b)] = planes[..] else {
        return Err(format!(
            "--planes {}: give two positions A,B in metres, e.g. --planes -0.1,0.1",
            args.planes
        ));
    };
    let planes = Planes {
        a,
        b,
        radius: args.radius,
    };
    let result = balance_scene(path, &text, &planes).map_err(|e| e.to_string())?;
    let mut report = result.report();
    if let Some(out) = &args.output {
        write_scene(out, &result).map_err(|e| format!("{}: {e}", out.display()))?;
        report += &format!("wrote the balanced scene to {}\n", out.display());
    }
    Ok(report)
}

/// The balanced scene as TOML, written atomically.
fn write_scene(out: &Path, result: &Balance) -> Result<(), String> {
    let text = result.balanced_toml()?;
    let mut file = AtomicFile::create(out).map_err(|e| format!("cannot create the file: {e}"))?;
    file.file()
        .write_all(text.as_bytes())
        .map_err(|e| format!("cannot write: {e}"))?;
    file.commit().map_err(|e| format!("cannot write: {e}"))
}
