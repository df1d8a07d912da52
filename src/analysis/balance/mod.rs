//! Balancing a rigid rotor in two planes (`eulerdyn balance`): from its known mass distribution ([`balance`],
//! the model), from measured 1× phasors by influence coefficients ([`influence`], `--measured`), or from one
//! measured run with the coefficients the model predicts (one-shot); and the balance grade the rotor meets before
//! and after, ISO 21940-11 ([`iso`]), judged at the service speed in the tolerance planes; [`slips`] warns of input
//! that would make that verdict wrong with confidence. [`balance_report`] does all of it; [`Report`] prints it as
//! text and JSON.

mod format;
pub mod influence;
pub mod iso;
mod model;
mod report;
pub mod slips;
pub mod table;

use std::path::{Path, PathBuf};

use nalgebra::{Complex, Matrix2, Vector2, Vector3};

pub use model::{Balance, BalanceError, Correction, Planes, balance};

use crate::scene::{Scene, SceneError, SceneSpec};
pub use format::wrap_deg;
pub use iso::TolerancePlanes;
pub use slips::Readings;

use influence::Phasor;
use iso::{Assessment, Judged};
use model::Rotor;

/// What `eulerdyn balance` is asked.
#[derive(Debug, Clone, PartialEq)]
pub struct Request {
    /// The correction planes and radius.
    /// The correction planes and radius.
    pub planes: Planes,
    /// `--grade G` (mm/s), > 0.
    pub grade: Option<f64>,
    /// `--rpm N`, > 0: the speed of the measured runs (the model's coefficients at it), instead of the scene's
    /// rate.
    pub rpm: Option<f64>,
    /// `--service-rpm N`, > 0: the maximum service speed the grade is judged at, instead of the scene's rate.
    pub service_rpm: Option<f64>,
    /// `--tolerance-planes`: where U_per is allotted (the bearing planes by default).
    pub tolerance_planes: TolerancePlanes,
    /// `--readings`: what the table's readings are (bearing forces in N by default).
    pub readings: Readings,
    /// `--measured PHASORS.csv`: the table's path (for messages) and its text.
    pub measured: Option<(PathBuf, String)>,
}

/// Why a request cannot be answered; every case is bad input (exit 2).
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum RequestError {
    /// An option's value: the message names the flag (`--grade 0: …`).
    #[error("{0}")]
    Option(String),
    /// The scene file, or a scene that cannot be balanced.
    #[error(transparent)]
    Scene(SceneError),
    /// The measured table, or a system it gives that cannot be solved.
    #[error(transparent)]
    Table(SceneError),
}

/// Where the influence coefficients came from.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Source {
    /// Fitted to the table's initial and trial runs.
    Measured,
    /// The scene's rigid-rotor model (one-shot: the table has only the initial run).
    Model,
}

/// Balancing by influence coefficients: what the table gave and what the corrections are.
#[derive(Debug, Clone, PartialEq)]
pub struct Influence {
    /// The table file.
    pub table: PathBuf,
    /// Where the coefficients came from (the measured table, or the model).
    pub source: Source,
    /// Rows of the table, and how many of them are trial runs.
    pub runs: usize,
    /// How many of them are trial runs.
    pub trial_runs: usize,
    /// α: reading per gram at the radius R; row = sensor (A, B), column = plane (A, B).
    pub alpha: Matrix2<Phasor>,
    /// cond₂(α).
    pub condition: f64,
    /// The initial readings as measured (the mean of the initial runs) and as the fit gives them.
    pub measured_initial: Vector2<Phasor>,
    /// The initial readings as the fit gives them.
    pub fitted_initial: Vector2<Phasor>,
    /// W = −α⁻¹ V⁰: the corrections, g at R, complex m·e^{iφ} (φ in the trial masses' convention).
    pub corrections_g: Vector2<Phasor>,
    /// The readings the initial run would give with the corrections added: V⁰_measured + α W.
    pub residual: Vector2<Phasor>,
}

/// The condition number above which the report warns that the planes' effects are nearly alike.
pub const CONDITION_WARNING: f64 = 100.0;

/// Everything `eulerdyn balance` prints.
#[derive(Debug, Clone, PartialEq)]
pub struct Report {
    /// The scene file.
    pub scene_file: PathBuf,
    /// The correction planes and radius.
    pub planes: Planes,
    /// The corrections applied (the model's, or the measured ones), the reference direction, the rotating
    /// reactions before and after, and the balanced scene.
    pub balance: Balance,
    /// Unbalance per plane, g·mm, complex U·e^{iφ} (φ the heavy spot's angle): `[before, after]`.
    pub unbalance: [[Phasor; 2]; 2],
    /// The grade met, when the service speed is known.
    pub grade: Option<Assessment>,
    /// Balancing by influence coefficients (`--measured`).
    pub influence: Option<Influence>,
    /// The speed of the measured runs (rad/s), when known, and whether it is `--rpm`'s.
    pub runs_speed: Option<(f64, bool)>,
    /// What the readings are.
    pub readings: Readings,
    /// Warnings about the input (a likely unit slip); with any, every verdict reads `unverified`.
    pub warnings: Vec<String>,
}

impl Influence {
    /// Whether cond₂(α) is above [`CONDITION_WARNING`].
    pub fn ill_conditioned(&self) -> bool {
        self.condition > CONDITION_WARNING
    }
}

/// `--grade`, `--rpm` and `--service-rpm` must be finite and > 0.
pub fn check_options(
    grade: Option<f64>,
    rpm: Option<f64>,
    service_rpm: Option<f64>,
) -> Result<(), RequestError> {
    if let Some(g) = grade.filter(|g| !(g.is_finite() && *g > 0.0)) {
        return Err(RequestError::Option(format!(
            "--grade {g}: the balance grade G must be a number > 0 (mm/s), e.g. --grade 6.3"
        )));
    }
    if let Some(n) = rpm.filter(|n| !(n.is_finite() && *n > 0.0)) {
        return Err(RequestError::Option(format!(
            "--rpm {n}: the speed must be a number > 0 (revolutions per minute)"
        )));
    }
    if let Some(n) = service_rpm.filter(|n| !(n.is_finite() && *n > 0.0)) {
        return Err(RequestError::Option(format!(
            "--service-rpm {n}: the maximum service speed must be a number > 0 (revolutions per minute)"
        )));
    }
    Ok(())
}

/// Balances `scene` as `request` asks (`eulerdyn balance`): the model's corrections, or with a measured table
/// those of its influence coefficients (one-shot: the model's at the runs' speed, `--rpm` or the scene's rate);
/// the unbalance per plane before and after; the balance grade at the maximum service speed (`--service-rpm` or
/// the scene's rate) in the tolerance planes, when that speed is known; and the warnings of [`slips`]. The
/// balanced scene is the scene as simulated ([`Scene::spec`], defaults written in) with the two correction masses
/// added.
pub fn balance_report(scene: &Scene, request: &Request) -> Result<Report, RequestError> {
    check_options(request.grade, request.rpm, request.service_rpm)?;
    let path_buf = scene
        .source
        .as_ref()
        .map_or_else(|| PathBuf::from("<scene>"), |s| s.path.clone());
    let path = path_buf.as_path();
    let spec = scene.spec.clone();
    let refuse = |problem: String| SceneError {
        file: path.to_path_buf(),
        key: None,
        location: None,
        problem,
    };
    let cannot = |e: BalanceError| RequestError::Scene(refuse(format!("cannot balance: {e}")));
    let rotor = Rotor::new(&spec, &request.planes).map_err(cannot)?;
    let scene_rate = Some(rotor.axis.rate().abs()).filter(|w| *w > 0.0);
    let runs_speed = speed(request.rpm, scene_rate);
    let service_speed = speed(request.service_rpm, scene_rate);
    if request.grade.is_some() && service_speed.is_none() {
        return Err(RequestError::Scene(refuse(
            "--grade needs the maximum service speed: the scene's motion.rate is 0; give --service-rpm".into(),
        )));
    }
    let runs_omega = runs_speed.map(|(w, _)| w);
    let (corrections, influence) = match &request.measured {
        None => {
            let [v_a, v_b] = rotor.plane_vectors();
            let planes = &request.planes;
            let model = [
                rotor.correction(planes.a, v_a),
                rotor.correction(planes.b, v_b),
            ];
            (model, None)
        }
        Some((table, table_text)) => {
            let found = measured(&rotor, table, table_text, runs_omega)?;
            (measured_corrections(&rotor, &found), Some(found))
        }
    };
    let balance = rotor.apply(&spec, corrections).map_err(cannot)?;
    let unbalance = match &influence {
        None => model_unbalance(&rotor, &balance.balanced).map_err(cannot)?,
        Some(found) => measured_unbalance(found, request.planes.radius),
    };
    let mut grade = service_speed.map(|speed| judge(&rotor, request, &unbalance, speed));
    let warnings = slips::warnings(
        &rotor,
        request,
        influence.as_ref(),
        runs_omega,
        grade.as_ref(),
    );
    if !warnings.is_empty() {
        grade.iter_mut().for_each(Assessment::unverify);
    }
    Ok(Report {
        scene_file: path.to_path_buf(),
        planes: request.planes,
        balance,
        unbalance,
        grade,
        influence,
        runs_speed,
        readings: request.readings,
        warnings,
    })
}

/// A speed (rad/s) and whether its flag gave it: the flag's `rpm`, else the scene's rate `scene_rate`.
fn speed(rpm: Option<f64>, scene_rate: Option<f64>) -> Option<(f64, bool)> {
    rpm.map(|n| (iso::rpm_to_rad_s(n), true))
        .or(scene_rate.map(|w| (w, false)))
}

/// The grade of the correction planes' `unbalance` (g·mm, `[before, after]`) at the service `speed`: in the
/// bearing planes (converted with the same resultant and moment, ISO 21940-11, 4.4) when the scene has bearings
/// and `--tolerance-planes` is `bearings`, else in the correction planes.
fn judge(
    rotor: &Rotor,
    request: &Request,
    unbalance: &[[Phasor; 2]; 2],
    speed: (f64, bool),
) -> Assessment {
    let correction_z = [request.planes.a, request.planes.b];
    let (planes, z) = match (request.tolerance_planes, rotor.axis.bearings()) {
        (TolerancePlanes::Bearings, Some(b)) => (TolerancePlanes::Bearings, [b.a, b.b]),
        _ => (TolerancePlanes::Correction, correction_z),
    };
    let in_planes = unbalance.map(|u| iso::to_planes(u, correction_z, z).map(|v| v.norm()));
    let judged = Judged {
        mass: rotor.axis.mass(),
        z_c: rotor.axis.rho_c_b().dot(&rotor.u_b),
        planes,
        z,
    };
    iso::assess(in_planes, judged, speed, request.grade)
}

/// The model's unbalance per plane (g·mm, at the heavy spot's angle): before, the opposite of the corrections
/// m r; after, that of the balanced scene `balanced` (round-off).
fn model_unbalance(rotor: &Rotor, balanced: &SceneSpec) -> Result<[[Phasor; 2]; 2], BalanceError> {
    let after = Rotor::new(balanced, &rotor.planes)?;
    let heavy_spots = |r: &Rotor| {
        r.plane_vectors().map(|v: Vector3<f64>| {
            let v = -v * 1e6;
            if v.norm() == 0.0 {
                Complex::new(0.0, 0.0)
            } else {
                Complex::from_polar(v.norm(), rotor.angle_of(&v))
            }
        })
    };
    Ok([heavy_spots(rotor), heavy_spots(&after)])
}

/// The unbalance per plane (g·mm) that explains the readings: before, −W·R; after, α⁻¹ (V⁰ + α W)·R, that of the
/// predicted residual readings (zero when the system is square and its readings fit exactly).
fn measured_unbalance(found: &Influence, radius: f64) -> [[Phasor; 2]; 2] {
    let radius_mm = Complex::new(radius * 1e3, 0.0);
    let before = -found.corrections_g * radius_mm;
    let after = found
        .alpha
        .try_inverse()
        .map_or(Vector2::zeros(), |inv| inv * found.residual * radius_mm);
    [[before[0], before[1]], [after[0], after[1]]]
}

/// The measured corrections as point masses of the rotor: |W_j| g at the angle arg W_j, at the radius R.
fn measured_corrections(rotor: &Rotor, found: &Influence) -> [Correction; 2] {
    let planes = [rotor.planes.a, rotor.planes.b];
    [0, 1].map(|j| {
        let w = found.corrections_g[j];
        rotor.correction_at(planes[j], w.norm() * 1e-3, w.arg())
    })
}

/// Reads the table and solves for the corrections: fitted coefficients when it has trial runs, the rigid-rotor
/// model's at the speed `omega` when it has only initial runs.
fn measured(
    rotor: &Rotor,
    table_path: &Path,
    table_text: &str,
    omega: Option<f64>,
) -> Result<Influence, RequestError> {
    let refuse = |problem: String| {
        RequestError::Table(SceneError {
            file: table_path.to_path_buf(),
            key: None,
            location: None,
            problem,
        })
    };
    let table = table::parse(table_path, table_text).map_err(RequestError::Table)?;
    let runs = table.runs();
    let measured_initial =
        influence::initial_readings(&runs).ok_or_else(|| refuse("no initial run".into()))?;
    let (source, alpha, fitted_initial) = if table.has_trials() {
        let fit = influence::fit(&runs).ok_or_else(|| {
            refuse("the runs do not determine the influence coefficients (rank below 3)".into())
        })?;
        (Source::Measured, fit.alpha, fit.initial)
    } else {
        (
            Source::Model,
            one_shot_coefficients(rotor, omega).map_err(refuse)?,
            measured_initial,
        )
    };
    let condition = influence::condition_number(&alpha);
    let corrections_g = influence::corrections(&alpha, &fitted_initial).ok_or_else(|| {
        refuse(format!(
            "the system is singular (condition number {condition:.3e}): the trial runs in plane A ({}) and \
             plane B ({}) change the readings in the same proportion; place the planes farther apart",
            table.trial_lines(0),
            table.trial_lines(1)
        ))
    })?;
    Ok(Influence {
        table: table_path.to_path_buf(),
        source,
        runs: runs.len(),
        trial_runs: runs.iter().filter(|r| r.trial.is_some()).count(),
        residual: measured_initial + alpha * corrections_g,
        alpha,
        condition,
        measured_initial,
        fitted_initial,
        corrections_g,
    })
}

/// The rigid-rotor model's coefficients for the scene's bearings and planes at `omega` (one-shot balancing).
fn one_shot_coefficients(rotor: &Rotor, omega: Option<f64>) -> Result<Matrix2<Phasor>, String> {
    let Some(bearings) = rotor.axis.bearings() else {
        return Err(
            "only an initial run: one-shot balancing takes the influence coefficients from the \
                    scene's model, which needs the bearings where the forces were measured \
                    (motion.bearings); or add trial runs"
                .into(),
        );
    };
    let Some(omega) = omega else {
        return Err(
            "only an initial run: one-shot balancing needs the speed of the run; the scene's \
                    motion.rate is 0, give --rpm"
                .into(),
        );
    };
    let planes = [rotor.planes.a, rotor.planes.b];
    Ok(influence::rigid_rotor_coefficients(
        [bearings.a, bearings.b],
        planes,
        rotor.planes.radius,
        omega,
    ))
}
