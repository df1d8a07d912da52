//! A fit from start to report: the checks that need no run, the inertia's scale (held when no moment fixes it),
//! Levenberg–Marquardt, the weights from the residuals where no σ is given (then once more with them), a
//! parameter the data cannot determine, the estimates with their standard errors and 95 % intervals, and whether
//! the fitted inertia is a body.

use levenberg_marquardt::{LevenbergMarquardt, TerminationReason};
use nalgebra::{DMatrix, DVector, Matrix3};

use super::build::{Builder, scene_name};
use super::params::{Estimate, Parameters, reported_covariance};
use super::problem::{Data, Evaluation, Problem, Sigmas, evaluate};
use super::uncertainty::{Z95, conditioning, correlation, covariance, undetermined};
use super::{FitError, FitOptions};
use crate::body::RigidBody;
use crate::scene::{Scene, SceneSpec};

/// The scale's column (J along I → (1 + ε) I) counts as zero below this fraction of its parts' sizes: the
/// sensitivities' round-off is ~1e-10 of them, a known moment's share far above.
const SCALE_FREE: f64 = 1e-6;
/// The solver's tolerances on the relative change of the sum of squares and of x (MINPACK's ftol, xtol).
const TOLERANCE: f64 = 1e-10;
/// A window before the whole data is used only when its J (columns at their parameters' sizes) has σ_min/σ_max
/// above this.
const WINDOW_CONDITIONING: f64 = 1e-4;
/// The tolerances of a window before the whole data.
const WINDOW_TOLERANCE: f64 = 1e-4;
/// A window of the continuation has at least this many rows per parameter.
const WINDOW_ROWS: usize = 10;

/// One reported parameter.
#[derive(Debug, Clone, PartialEq, serde::Serialize)]
pub struct Parameter {
    /// The contract's name (`I_xx`, `I_1`, `omega0_x`, `q0_w`, `bias_x`…).
    pub name: String,
    /// The scene's value (0 for a bias).
    pub start: f64,
    /// The estimate.
    pub estimate: f64,
    /// Its standard error (0 for a value held).
    pub std_error: f64,
    /// The 95 % interval, estimate ∓ 1.96 standard errors.
    pub low: f64,
    /// Its upper end.
    pub high: f64,
}

/// The correlation matrix of the reported parameters.
#[derive(Debug, Clone, PartialEq, serde::Serialize)]
pub struct Correlation {
    /// The parameters, in the matrix's order.
    pub names: Vec<String>,
    /// Row by row.
    pub matrix: Vec<Vec<f64>>,
}

/// A value per channel: the gyro's (rad/s) and the attitude's (rad), where the data have it.
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
pub struct Channels {
    /// The gyro's.
    pub omega: Option<f64>,
    /// The attitude's.
    pub attitude: Option<f64>,
}

/// The residuals of one channel's component against time (the figure's curves).
#[derive(Debug, Clone, PartialEq)]
pub struct Residuals {
    /// `omega_x` … `attitude_z`.
    pub name: String,
    /// Times (s).
    pub t: Vec<f64>,
    /// Measured minus model… as the residual: model (+ bias) minus measured, rad/s or rad.
    pub values: Vec<f64>,
}

/// A fit's result: what `--json` prints.
#[derive(Debug, Clone, serde::Serialize)]
pub struct Fit {
    /// The measured file.
    pub file: String,
    /// The scene.
    pub scene: String,
    /// Rows read; with a gyro reading; with an attitude.
    pub rows: usize,
    /// Rows with a gyro reading.
    pub gyro_rows: usize,
    /// Rows with an attitude.
    pub attitude_rows: usize,
    /// The groups estimated.
    pub estimate: Vec<String>,
    /// The estimates.
    pub parameters: Vec<Parameter>,
    /// Their correlations.
    pub correlation: Correlation,
    /// The residuals' RMS per channel (rad/s, rad).
    pub rms: Channels,
    /// The σ the residuals were weighed with (given, or from the residuals).
    pub sigma: Channels,
    /// The channels whose σ came from the residuals.
    pub sigma_from_residuals: Vec<String>,
    /// χ² per degree of freedom (1 by construction for a σ from the residuals).
    pub chi2_dof: f64,
    /// Degrees of freedom: residuals minus parameters.
    pub dof: usize,
    /// Whether the solver converged.
    pub converged: bool,
    /// Why it stopped.
    pub termination: String,
    /// Its iterations (Jacobians computed).
    pub iterations: usize,
    /// Whether the inertia's scale was held.
    pub scale_held: bool,
    /// What the reader should know (the scale held, the weights).
    pub notes: Vec<String>,
    /// Why the fitted inertia is not a body, when it is not.
    pub unphysical: Option<String>,
    /// Warnings from reading the file.
    pub warnings: Vec<String>,
    /// The residuals against time.
    #[serde(skip)]
    pub residuals: Vec<Residuals>,
    /// The scene with the estimates in.
    #[serde(skip)]
    pub fitted: SceneSpec,
}

impl Fit {
    /// Whether the fit converged to a body (exit 0).
    pub fn succeeded(&self) -> bool {
        self.converged && self.unphysical.is_none()
    }
}

/// The checks that need no run: the data a parameter needs, σ given positive, point masses with the inertia.
fn check(data: &Data, scene: &Scene, options: &FitOptions) -> Result<(), FitError> {
    let (gyro, attitude) = data.counts();
    let has = |e: Estimate| options.estimates.contains(&e);
    if has(Estimate::Attitude0) && attitude == 0 {
        return Err(FitError::Input(
            "--estimate attitude0: the data cannot determine it: the measured file has no attitude columns".into(),
        ));
    }
    if has(Estimate::GyroBias) && gyro == 0 {
        return Err(FitError::Input(
            "--estimate gyro_bias: the data cannot determine it: the measured file has no gyro columns (omega_x..z)".into(),
        ));
    }
    for (name, sigma) in [
        ("--sigma-omega", options.sigma_omega),
        ("--sigma-attitude", options.sigma_attitude),
    ] {
        if let Some(s) = sigma
            && !(s.is_finite() && s > 0.0)
        {
            return Err(FitError::Input(format!(
                "{name} {s}: must be a finite number > 0"
            )));
        }
    }
    if (has(Estimate::Inertia) || has(Estimate::Principal))
        && !scene.spec.body.point_mass.is_empty()
    {
        return Err(FitError::Input(format!(
            "{}: body.point_mass: fit estimates the whole body's inertia about C; give it as [body] inertia \
             (the point masses' share included) instead of point masses",
            scene_name(scene)
        )));
    }
    Ok(())
}

/// Fits `scene` to `data` (see the module's doc).
pub fn fit(data: &Data, scene: &Scene, options: &FitOptions) -> Result<Fit, FitError> {
    check(data, scene, options)?;
    let builder = Builder::new(scene)?;
    let free = scene.motion.free().expect("the builder checked");
    let mut params = Parameters::new(
        &options.estimates,
        *scene.body.inertia_c(),
        **free.omega0_b,
        scene.attitude0,
        false,
    );
    let mut sigmas = Sigmas {
        omega: options.sigma_omega.unwrap_or(1.0),
        attitude: options.sigma_attitude.unwrap_or(1.0),
    };
    let at_start = |params: &Parameters, sigmas: Sigmas| {
        evaluate(&builder, params, data, sigmas, &params.start())
            .map_err(|e| FitError::Run(format!("the model at the scene's start: {e}")))
    };
    let mut start = at_start(&params, sigmas)?;
    if scale_free(&params, &params.start(), &start.jacobian) {
        params = params.with_scale_held(true);
        start = at_start(&params, sigmas)?;
    }
    let mut outcome = continued(&builder, &params, data, sigmas, start)?;
    let estimated = estimated_sigmas(data, options);
    if !estimated.is_empty() {
        let from = sigmas;
        sigmas = residual_sigmas(data, &outcome.evaluation, sigmas, params.len());
        let reweighted = outcome.evaluation.reweighted(data, from, sigmas);
        let (gyro, attitude) = data.counts();
        outcome = if gyro > 0 && attitude > 0 {
            let x = outcome.x.clone();
            let again = minimize(&builder, &params, data, sigmas, x, &reweighted, TOLERANCE)?;
            Outcome {
                iterations: outcome.iterations + again.iterations,
                ..again
            }
        } else {
            Outcome {
                evaluation: reweighted,
                ..outcome
            }
        };
    }
    let last = &outcome.evaluation;
    if let Some(k) = undetermined(&last.jacobian, &params.scales()) {
        let name = &params.coordinate_names()[k];
        return Err(FitError::Input(format!(
            "--estimate: the data cannot determine {name}: the residuals do not move with it, or move with it only \
             as with a combination of the other parameters; estimate fewer parameters or measure a motion that moves it"
        )));
    }
    Ok(report(
        &builder,
        &params,
        data,
        scene,
        (sigmas, estimated),
        &outcome,
        last,
    ))
}

/// Whether the inertia's scale is free of the data: J along I → (1 + ε) I, Σ_k x_k J_k over the inertia's
/// coordinates, is zero to round-off (every moment in the scene scales with I, or there is none).
fn scale_free(params: &Parameters, x: &DVector<f64>, jacobian: &DMatrix<f64>) -> bool {
    let names = params.coordinate_names();
    let inertia: Vec<usize> = (0..params.len())
        .filter(|&k| names[k].starts_with("I_"))
        .collect();
    if inertia.is_empty() {
        return false;
    }
    let along = inertia
        .iter()
        .fold(DVector::zeros(jacobian.nrows()), |s, &k| {
            s + jacobian.column(k) * x[k]
        });
    let size: f64 = (inertia.iter())
        .map(|&k| jacobian.column(k).norm() * x[k].abs())
        .sum();
    along.norm() <= SCALE_FREE * size
}

/// The windows of a continuation over the data: the rows up to t_last/2^k for k = 6 … 0, each with at least
/// [`WINDOW_ROWS`] per parameter and more rows than the one before.
fn windows(data: &Data, parameters: usize) -> Vec<usize> {
    let t_last = *data.times.last().expect("at least two rows");
    let least = WINDOW_ROWS * parameters.max(1);
    let mut out: Vec<usize> = Vec::new();
    for k in (1..=6).rev() {
        let t = t_last / f64::from(1u32 << k);
        let rows = data.times.partition_point(|&s| s <= t);
        if rows >= least && out.last().is_none_or(|&r| rows > r) {
            out.push(rows);
        }
    }
    out.push(data.times.len());
    out
}

/// Levenberg–Marquardt continued over growing windows of the data ([`windows`]), each from the last one's
/// estimate: a long record of a tumble has a sum of squares with many valleys (a start a little off turns the
/// model's phase by radians by the end), a short one has one, and each doubling keeps the estimate in its valley.
fn continued(
    builder: &Builder,
    params: &Parameters,
    data: &Data,
    sigmas: Sigmas,
    start: Evaluation,
) -> Result<Outcome, FitError> {
    let windows = windows(data, params.len());
    let mut x = params.start();
    let mut iterations = 0;
    let mut last = None;
    for (k, &rows) in windows.iter().enumerate() {
        let part = data.prefix(rows);
        let whole = k + 1 == windows.len();
        let at = match whole && k == 0 {
            true => start.clone(),
            false => evaluate(builder, params, &part, sigmas, &x)
                .map_err(|e| FitError::Run(format!("the model on the first {rows} rows: {e}")))?,
        };
        // A window whose rows do not determine every parameter (no pulse yet, a rate still too slow to show
        // the inertia) would let the undetermined ones wander: it is passed over.
        if !whole && conditioning(&at.jacobian, &params.scales()) < WINDOW_CONDITIONING {
            continue;
        }
        // A window before the whole data only has to bring x into the valley: loose tolerances there.
        let tolerance = if whole { TOLERANCE } else { WINDOW_TOLERANCE };
        let outcome = minimize(builder, params, &part, sigmas, x, &at, tolerance)?;
        iterations += outcome.iterations;
        x = outcome.x.clone();
        last = Some(outcome);
    }
    let last = last.expect("at least the whole data");
    Ok(Outcome { iterations, ..last })
}

/// Where the solver stopped, and the evaluation there.
struct Outcome {
    x: DVector<f64>,
    evaluation: Evaluation,
    converged: bool,
    termination: String,
    iterations: usize,
}

/// Levenberg–Marquardt from x0.
fn minimize(
    builder: &Builder,
    params: &Parameters,
    data: &Data,
    sigmas: Sigmas,
    x0: DVector<f64>,
    start: &Evaluation,
    tolerance: f64,
) -> Result<Outcome, FitError> {
    let problem = Problem::new(builder, params, data, sigmas, x0, start);
    let solver = LevenbergMarquardt::new()
        .with_ftol(tolerance)
        .with_xtol(tolerance)
        .with_gtol(tolerance);
    let (problem, report) = solver.minimize(problem);
    let evaluation = (problem.evaluation())
        .map_err(|e| FitError::Run(format!("the model at the solver's last point: {e}")))?;
    Ok(Outcome {
        evaluation,
        x: problem.x().clone(),
        // MINPACK's "no further improvement possible" (info 6–8) is the optimum to round-off: converged too.
        converged: report.termination.was_successful()
            || matches!(
                report.termination,
                TerminationReason::NoImprovementPossible(_)
            ),
        termination: format!("{:?}", report.termination),
        iterations: problem.jacobians(),
    })
}

/// The channels whose σ comes from the residuals.
fn estimated_sigmas(data: &Data, options: &FitOptions) -> Vec<String> {
    let (gyro, attitude) = data.counts();
    let mut out = Vec::new();
    if gyro > 0 && options.sigma_omega.is_none() {
        out.push("omega".to_string());
    }
    if attitude > 0 && options.sigma_attitude.is_none() {
        out.push("attitude".to_string());
    }
    out
}

/// The residuals' sums of squares per channel (unweighted), with the number of residuals of each.
fn channel_sums(data: &Data, e: &Evaluation, sigmas: Sigmas) -> [(f64, usize); 2] {
    let mut sums = [(0.0, 0), (0.0, 0)];
    for (_, c, at) in data.blocks() {
        sums[c].0 += (e.residuals.fixed_rows::<3>(at) * sigmas.of(c)).norm_squared();
        sums[c].1 += 3;
    }
    sums
}

/// σ per channel from the residuals, σ_c² = RSS_c / (n_c (1 − p/n)) (the degrees of freedom shared in proportion),
/// for the channels not given; at least 1e-300 so that a noise-free fit still divides.
fn residual_sigmas(data: &Data, e: &Evaluation, sigmas: Sigmas, p: usize) -> Sigmas {
    let sums = channel_sums(data, e, sigmas);
    let n: usize = sums.iter().map(|s| s.1).sum();
    let of = |(rss, count): (f64, usize)| {
        let dof = count as f64 * (1.0 - p as f64 / n as f64);
        (rss / dof.max(1.0)).sqrt().max(1e-300)
    };
    let (gyro, attitude) = data.counts();
    Sigmas {
        omega: if gyro > 0 { of(sums[0]) } else { sigmas.omega },
        attitude: if attitude > 0 {
            of(sums[1])
        } else {
            sigmas.attitude
        },
    }
}

/// The report at the optimum.
fn report(
    builder: &Builder,
    params: &Parameters,
    data: &Data,
    scene: &Scene,
    (sigmas, estimated): (Sigmas, Vec<String>),
    outcome: &Outcome,
    last: &Evaluation,
) -> Fit {
    let x = &outcome.x;
    let cov = covariance(&last.jacobian);
    let reported = params.reported(x);
    let cov_reported = reported_covariance(&reported, &cov);
    let parameters: Vec<Parameter> = (reported.iter().enumerate())
        .map(|(k, r)| {
            let se = cov_reported[(k, k)].max(0.0).sqrt();
            Parameter {
                name: r.name.clone(),
                start: r.start,
                estimate: r.estimate,
                std_error: se,
                low: r.estimate - Z95 * se,
                high: r.estimate + Z95 * se,
            }
        })
        .collect();
    let corr = correlation(&cov_reported);
    let (gyro, attitude) = data.counts();
    let sums = channel_sums(data, last, sigmas);
    let rms = |(rss, n): (f64, usize)| (n > 0).then(|| (rss / n as f64).sqrt());
    let m = last.residuals.len();
    let dof = m.saturating_sub(params.len());
    let inertia = params.inertia(x);
    Fit {
        file: String::new(),
        scene: scene_name(scene),
        rows: data.times.len(),
        gyro_rows: gyro,
        attitude_rows: attitude,
        estimate: params
            .estimates
            .iter()
            .map(|e| e.name().to_string())
            .collect(),
        correlation: Correlation {
            names: parameters.iter().map(|p| p.name.clone()).collect(),
            matrix: corr
                .row_iter()
                .map(|r| r.iter().copied().collect())
                .collect(),
        },
        parameters,
        rms: Channels {
            omega: rms(sums[0]),
            attitude: rms(sums[1]),
        },
        sigma: Channels {
            omega: (gyro > 0).then_some(sigmas.omega),
            attitude: (attitude > 0).then_some(sigmas.attitude),
        },
        notes: notes(params, &estimated),
        sigma_from_residuals: estimated,
        chi2_dof: last.residuals.norm_squared() / dof.max(1) as f64,
        dof,
        converged: outcome.converged,
        termination: outcome.termination.clone(),
        iterations: outcome.iterations,
        scale_held: params.scale_held,
        unphysical: unphysical(params, scene, &inertia),
        warnings: Vec::new(),
        residuals: residual_series(data, last, sigmas),
        fitted: builder.spec_at(&inertia, &params.omega0(x), &params.q0(x)),
    }
}

/// What the reader should know about the scale and the weights.
fn notes(params: &Parameters, estimated: &[String]) -> Vec<String> {
    let mut notes = Vec::new();
    if params.scale_held {
        notes.push(if params.has(Estimate::Inertia) {
            format!(
                "the inertia's scale is held at the scene's trace {:.6e} kg*m^2: no moment in the scene is known, so \
                 the motion fixes the inertia only up to a common factor",
                params.inertia0.trace()
            )
        } else {
            "the inertia's scale is held at the scene's largest principal moment: no moment in the scene is known, \
             so the motion fixes the inertia only up to a common factor"
                .to_string()
        });
    }
    for channel in estimated {
        notes.push(format!(
            "the {channel} residuals' sigma was estimated from the residuals (give --sigma-{channel} to fix it)"
        ));
    }
    notes
}

/// Why the fitted inertia is not a body (not positive definite, or breaking the triangle inequality).
fn unphysical(params: &Parameters, scene: &Scene, inertia: &Matrix3<f64>) -> Option<String> {
    if !(params.has(Estimate::Inertia) || params.has(Estimate::Principal)) {
        return None;
    }
    RigidBody::new(scene.body.mass(), *inertia)
        .err()
        .map(|e| format!("the fitted inertia is not a body: {e}"))
}

/// Each channel's component residuals (model + bias − measured) against time, unweighted.
fn residual_series(data: &Data, e: &Evaluation, sigmas: Sigmas) -> Vec<Residuals> {
    let names = [
        "omega_x",
        "omega_y",
        "omega_z",
        "attitude_x",
        "attitude_y",
        "attitude_z",
    ];
    let mut series: Vec<Residuals> = (names.iter())
        .map(|n| Residuals {
            name: n.to_string(),
            t: Vec::new(),
            values: Vec::new(),
        })
        .collect();
    for (i, c, at) in data.blocks() {
        for k in 0..3 {
            series[3 * c + k].t.push(data.times[i]);
            series[3 * c + k]
                .values
                .push(e.residuals[at + k] * sigmas.of(c));
        }
    }
    series.retain(|s| !s.t.is_empty());
    series
}
