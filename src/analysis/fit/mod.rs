//! `eulerdyn fit`: a body from its measured motion — the inertia (six entries, or the principal moments on the
//! scene's axes), ω₀, q₀ and a gyro's bias that make the scene's model best match a gyro's ω and/or the attitude,
//! by least squares (Levenberg–Marquardt) with the Jacobian from the forward sensitivities ([`model`]), and what
//! the data say about each estimate ([`uncertainty`]).
//!
//! [`params`] lays out what is estimated, [`build`] makes the scene's model at a parameter point ([`wheels`]: a
//! body's wheels), [`problem`]
//! gives the solver residuals and Jacobian, [`solve`] runs it (weights, the inertia's scale, the checks),
//! [`report`] prints; `figure` (feature `plot`) draws the residuals, `command` (feature `cli`) is `eulerdyn fit`.

pub mod build;
#[cfg(feature = "cli")]
pub mod command;
#[cfg(feature = "plot")]
pub mod figure;
pub mod model;
pub mod params;
pub mod problem;
pub mod report;
pub mod solve;
pub mod uncertainty;
pub mod wheels;

use std::path::Path;

pub use params::Estimate;
pub use problem::Data;

use crate::analysis::score::ReadOptions;
use crate::analysis::score::reader::read_measured;
use crate::scene::Scene;

/// Why a fit stopped before its report: bad input (exit 2) or a failed run (exit 1).
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum FitError {
    #[error("{0}")]
    /// Bad input (exit 2): the message names the file, row, column or parameter.
    Input(String),
    #[error("{0}")]
    /// The model could not be run at the start (exit 1).
    Run(String),
}

/// What to estimate and how to weigh the data.
#[derive(Debug, Clone, Default)]
pub struct FitOptions {
    /// The parameter groups, in `--estimate`'s order.
    pub estimates: Vec<Estimate>,
    /// The gyro's σ (rad/s); `None`: from the residuals.
    pub sigma_omega: Option<f64>,
    /// The attitude's σ (rad); `None`: from the residuals.
    pub sigma_attitude: Option<f64>,
    /// How to read the measured file.
    pub read: ReadOptions,
}

/// `--estimate`'s comma list, each name once.
pub fn parse_estimates(list: &str) -> Result<Vec<Estimate>, FitError> {
    let mut out = Vec::new();
    for name in list.split(',').map(str::trim).filter(|n| !n.is_empty()) {
        let estimate = Estimate::named(name).ok_or_else(|| {
            FitError::Input(format!(
                "--estimate {name}: not a parameter; give a comma list of {}",
                Estimate::NAMES.join(", ")
            ))
        })?;
        if out.contains(&estimate) {
            return Err(FitError::Input(format!("--estimate {name}: named twice")));
        }
        out.push(estimate);
    }
    if out.contains(&Estimate::Inertia) && out.contains(&Estimate::Principal) {
        return Err(FitError::Input(
            "--estimate: give `inertia` (six entries) or `principal` (three moments), not both"
                .into(),
        ));
    }
    if out.is_empty() {
        return Err(FitError::Input(format!(
            "--estimate: empty; give a comma list of {}",
            Estimate::NAMES.join(", ")
        )));
    }
    Ok(out)
}

/// Reads the measured motion in `path` (a gyro's ω and/or the attitude, rows at any times up to the scene's
/// t_end), with the reading's warnings.
pub fn read_data(
    path: &Path,
    scene: &Scene,
    read: &ReadOptions,
) -> Result<(Data, Vec<String>), FitError> {
    let measured = read_measured(path, read, scene.solver.t_end, false).map_err(|e| match e {
        crate::analysis::score::ScoreError::Input(m)
        | crate::analysis::score::ScoreError::Run(m) => FitError::Input(m),
    })?;
    let data = Data {
        times: measured.rows.iter().map(|r| r.t).collect(),
        omega_b: measured.rows.iter().map(|r| r.omega_b).collect(),
        q: measured.rows.iter().map(|r| r.q).collect(),
    };
    Ok((data, measured.warnings))
}

/// Fits `scene` to the measured motion in `path` (see [`solve::fit`]).
pub fn fit_file(path: &Path, scene: &Scene, options: &FitOptions) -> Result<solve::Fit, FitError> {
    let (data, warnings) = read_data(path, scene, &options.read)?;
    let mut fit = solve::fit(&data, scene, options)?;
    fit.file = path.display().to_string();
    fit.warnings.splice(0..0, warnings);
    Ok(fit)
}
