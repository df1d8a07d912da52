//! `eulerdyn balance`: the two correction masses of a fixed-axis or hinge scene, printed, and the balanced scene
//! written with `-o`.

use std::io::Write;
use std::path::{Path, PathBuf};

use clap::Args;

use crate::analysis::balance::{Balance, Planes, balance};
use crate::output::AtomicFile;
use crate::scene::{self, Overrides};

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
    let in_file = |problem: String| format!("{}: {problem}", path.display());
    // Validate first, for messages with line and column; then balance the typed scene.
    scene::load(path, &Overrides::default()).map_err(|e| e.to_string())?;
    let spec = scene::load_spec(path).map_err(|e| e.to_string())?;
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
    let result = balance(
        &spec,
        &Planes {
            a,
            b,
            radius: args.radius,
        },
    )
    .map_err(|e| in_file(format!("cannot balance: {e}")))?;
    if let Some(out) = &args.output {
        write_scene(out, &result).map_err(|e| format!("{}: {e}", out.display()))?;
    }
    Ok(report(&result, args.output.as_deref()))
}

/// The balanced scene as TOML, written atomically.
fn write_scene(out: &Path, result: &Balance) -> Result<(), String> {
    let text =
        toml::to_string(&result.balanced).map_err(|e| format!("cannot write the scene: {e}"))?;
    let mut file = AtomicFile::create(out).map_err(|e| format!("cannot create the file: {e}"))?;
    let header = "# Written by `eulerdyn balance`: the scene with its two correction masses ([[body.point_mass]]).\n";
    file.file()
        .write_all(header.as_bytes())
        .and_then(|()| file.file().write_all(text.as_bytes()))
        .map_err(|e| format!("cannot write: {e}"))?;
    file.commit().map_err(|e| format!("cannot write: {e}"))
}

/// What `balance` prints.
fn report(result: &Balance, out: Option<&Path>) -> String {
    let mut text = String::new();
    let r = &result.reference_b;
    text += &format!(
        "angles about the axis from {} across it: ({:.6}, {:.6}, {:.6}) in body axes\n",
        result.reference_name, r.x, r.y, r.z
    );
    for (name, c) in ["A", "B"].iter().zip(&result.corrections) {
        if c.mass == 0.0 {
            text += &format!("plane {name} at {} m: mass 0 kg (none needed)\n", c.z);
        } else {
            text += &format!(
                "plane {name} at {} m: mass {:.9e} kg at {:.6} deg, at = [{:e}, {:e}, {:e}] m (body axes, from the reference origin)\n",
                c.z, c.mass, c.angle_deg, c.at_b.x, c.at_b.y, c.at_b.z
            );
        }
    }
    text += &format!(
        "largest rotating bearing reaction at {} rad/s without effects: {:.6e} N before, {:.6e} N after\n",
        result.rate, result.largest_reaction[0], result.largest_reaction[1]
    );
    if let Some(out) = out {
        text += &format!("wrote the balanced scene to {}\n", out.display());
    }
    text
}
