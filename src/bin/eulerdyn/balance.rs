//! `eulerdyn balance`: the two correction masses of a fixed-axis or hinge scene (from the model, or from a measured
//! table), the unbalance per plane and the balance grade, printed (or as JSON), and the balanced scene written
//! with `-o`.

use std::io::Write;
use std::path::{Path, PathBuf};

use clap::Args;
use clap::builder::{PossibleValuesParser, TypedValueParser};

use eulerdyn::analysis::balance::{
    Planes, Readings, Report, Request, TolerancePlanes, balance_report, check_options, table,
};
use eulerdyn::named::Named;
use eulerdyn::output::{AtomicFile, same_file};
use eulerdyn::scene::{self, Overrides};

/// The values of a `Named` enum as clap's choices: listed by name in the help and in clap's message for another
/// word, parsed into the value.
fn named<T: Named + Send + Sync>() -> impl TypedValueParser<Value = T> {
    PossibleValuesParser::new(T::ALL.iter().map(Named::name))
        .map(|name| T::parse(&name).expect("clap accepts only the names"))
}

#[derive(Debug, Args)]
#[command(
    after_help = "Examples:\n  eulerdyn balance scenarios/rotor_bearings.toml --planes -0.1,0.1 --radius 0.2 -o balanced.toml\n  eulerdyn balance scenarios/fan_rotor_g63.toml --planes -0.1,0.08 --radius 0.25 --grade 6.3 \\\n      --service-rpm 2950 --measured scenarios/fan_rotor_measured.csv      from measured phasors, to G 6.3\n\nThe grade is judged at the service speed (--service-rpm, default the scene's rate) in the bearing planes;\nwith --measured and without --service-rpm the verdict reads `unverified`. --rpm is the speed of the measured runs. A likely unit slip is warned of and the verdict reads `unverified`.\n\nPhasors: amp*cos(theta + phase), theta turned since the reference mark passed the sensor; trial angles\nfrom the mark in the direction of rotation (or both the other way: the corrections follow the trials' convention)."
)]
pub struct BalanceArgs {
    /// Scene file (TOML) with a fixed_axis or hinge motion.
    pub scene: PathBuf,
    /// Axial positions A,B of the two correction planes (m, from `motion.point` along the axis).
    #[arg(long, value_name = "A,B", allow_hyphen_values = true)]
    pub planes: String,
    /// Distance of the correction masses from the axis (m).
    #[arg(long, value_name = "R", allow_negative_numbers = true)]
    pub radius: f64,
    /// Balance grade G (mm/s, ISO 21940-11, e.g. 6.3 for a fan): U_per, its shares, pass/fail.
    #[arg(long, value_name = "G", allow_negative_numbers = true)]
    pub grade: Option<f64>,
    /// The speed of the measured runs (revolutions per minute), for the model's coefficients, instead of the
    /// scene's rate.
    #[arg(long, value_name = "N", allow_negative_numbers = true)]
    pub rpm: Option<f64>,
    /// The rotor's maximum service speed (revolutions per minute), the one the grade is judged at (ISO 21940-11),
    /// instead of the scene's rate.
    #[arg(long, value_name = "N", allow_negative_numbers = true)]
    pub service_rpm: Option<f64>,
    /// Where U_per is allotted: the bearing planes (ISO 21940-11; the correction planes when the scene has no
    /// bearings) or the correction planes.
    #[arg(long, value_name = "PLANES", default_value = "bearings", value_parser = named::<TolerancePlanes>())]
    pub tolerance_planes: TolerancePlanes,
    /// What the table's readings are: bearing forces in N (compared with the rigid-rotor model), or vibration in
    /// any unit.
    #[arg(long, value_name = "KIND", default_value = "force", value_parser = named::<Readings>())]
    pub readings: Readings,
    /// Balance from measured 1× phasors (CSV: run,trial_plane,trial_mass_g,trial_angle_deg,A_amp,A_phase_deg,
    /// B_amp,B_phase_deg) by influence coefficients; only an initial row: one-shot, with the model's coefficients.
    #[arg(long, value_name = "PHASORS.csv")]
    pub measured: Option<PathBuf>,
    /// Print the report as JSON (every figure of the text).
    #[arg(long)]
    pub json: bool,
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
    check_options(args.grade, args.rpm, args.service_rpm).map_err(|e| e.to_string())?;
    if let Some(out) = args.output.as_ref().filter(|out| same_file(path, out)) {
        return Err(format!(
            "{}: the output would overwrite the scene file; give another path",
            out.display()
        ));
    }
    let measured = match &args.measured {
        Some(table) => Some((
            table.clone(),
            table::read(table).map_err(|e| e.to_string())?,
        )),
        None => None,
    };
    let request = Request {
        planes: Planes {
            a,
            b,
            radius: args.radius,
        },
        grade: args.grade,
        rpm: args.rpm,
        service_rpm: args.service_rpm,
        tolerance_planes: args.tolerance_planes,
        readings: args.readings,
        measured,
    };
    let scene = scene::parse(path, &text, &Overrides::default()).map_err(|e| e.to_string())?;
    let result = balance_report(&scene, &request).map_err(|e| e.to_string())?;
    let mut wrote = None;
    if let Some(out) = &args.output {
        write_scene(out, &result).map_err(|e| format!("{}: {e}", out.display()))?;
        wrote = Some(out.display().to_string());
    }
    if args.json {
        let mut json = result.json();
        json["wrote"] = wrote.into();
        return Ok(format!("{json:#}\n"));
    }
    let mut report = result.text();
    if let Some(out) = wrote {
        report += &format!("wrote the balanced scene to {out}\n");
    }
    Ok(report)
}

/// The balanced scene as TOML, written atomically.
fn write_scene(out: &Path, result: &Report) -> Result<(), String> {
    let text = result.balance.balanced_toml()?;
    let mut file = AtomicFile::create(out).map_err(|e| format!("cannot create the file: {e}"))?;
    file.file()
        .write_all(text.as_bytes())
        .map_err(|e| format!("cannot write: {e}"))?;
    file.commit().map_err(|e| format!("cannot write: {e}"))
}
