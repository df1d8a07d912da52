//! `eulerdyn accuracy`: the work-precision study of a scene — what each digit of accuracy costs in time.
//!
//! Every method of [`Method::ALL`] that the scene accepts is run over a sweep: adaptive methods over the
//! relative tolerances 1e-3 … 1e-13 (one per decade), fixed-step methods over step sizes halved from a coarse start.
//! Each run is compared, row by row while it streams, with a reference:
//!
//! - the closed form where one applies ([`Oracle::for_scene`]: torque-free body, damped principal-axis spin,
//!   constant axial torque on a symmetric body);
//! - for prescribed fixed-axis motion, the closed form H_s = I_s(θ)·ω_s against the numerically integrated
//!   Ḣ_s = M_s (ω and the attitude of such a run are the closed form itself, so their errors are 0);
//! - otherwise a reference run: DOP853 (own backend, body form) at rtol = 1e-14 (1e-13 if the scene refuses it),
//!   atol = 1e-15, whose own uncertainty is estimated by running the space form at the same tolerance.
//!
//! The reference rows are kept in memory (at most [`REFERENCE_MAX_ROWS`]); the rows of the runs are not.
//!
//! # Measures (one row of the table per run)
//!
//! - `err_omega`: largest |ω_b − ω_b,ref| over the rows (rad/s, absolute);
//! - `err_attitude`: largest angle of the rotation between the attitude and the reference's (rad; empty when the
//!   reference has no attitude);
//! - `energy_drift`, `H_drift`: largest |E − E_ref| and ||H| − |H|_ref| over the rows, relative to the largest
//!   |E_ref|, |H|_ref (torque-free: the drift from the conserved value);
//! - `wall_s`: the median wall time of several repeats of the integration alone (`simulate::run` with a sink that
//!   discards the rows; 5 repeats, 3 for runs over 0.2 s, 1 over 1 s); the first, untimed run computes the errors;
//! - `steps`, `rejected`, `evals`: the integrator's counters.
//!
//! Extra columns after the contract's: `err_H_s` (largest |H_s − H_s,ref|, kg·m²/s; for fixed-axis motion the
//! integrated H_s against the closed form), `atol`, `backend`, `repeats`, `status` (`ok`, or why the run failed:
//! e.g. a fixed step too large for the scene diverges; such rows have empty errors and are left out of the plot
//! and the summary).
//!
//! Tolerances: atol = rtol × (the scene's atol / rtol), so the scene's balance between absolute and relative error
//! is kept along the sweep. Fixed steps: dt₀ = every / 2^j, the largest such step with |ω|max·dt₀ ≤ 0.5, halved
//! [`StudyOptions::halvings`] times; the halving stops early once the error is at round-off (≤ 1e-13·|ω|max, or
//! no longer falling below 1e-8·|ω|max), when a run would take more than [`StudyOptions::max_fixed_steps`] steps,
//! or when the last run took over [`StudyOptions::slow_curve_seconds`].
//!
//! A method with neither a step nor a tolerance (`exact`) is run once. The ode_solvers backend is swept for the
//! Runge–Kutta methods only (labelled `rk4/ode_solvers`, …); the splitting methods and `exact` are the project's
//! own.

use std::convert::Infallible;
use std::fmt::{self, Write as _};
use std::hint::black_box;
use std::io::{self, Write};
use std::path::{Path, PathBuf};
use std::time::Instant;

use nalgebra::{UnitQuaternion, Vector3};

use crate::analysis::compare::{Oracle, attitude_angle};
use crate::frames::Form;
use crate::method::{Backend, Method};
use crate::output::AtomicFile;
use crate::sample::Sample;
use crate::scene::Scene;
use crate::scene::{self, Overrides, SceneError};
use crate::simulate;

/// The columns of the table, in order: the contract's twelve, then the extra ones.
pub const TABLE_COLUMNS: [&str; 17] = [
    "method",
    "frame",
    "rtol",
    "dt",
    "err_omega",
    "err_attitude",
    "energy_drift",
    "H_drift",
    "wall_s",
    "steps",
    "rejected",
    "evals",
    "err_H_s",
    "atol",
    "backend",
    "repeats",
    "status",
];

/// The error levels the summary names the cheapest method for.
pub const TARGETS: [f64; 3] = [1e-6, 1e-9, 1e-12];

/// Most rows of a reference kept in memory.
pub const REFERENCE_MAX_ROWS: usize = 1_000_000;

/// Relative tolerance of a reference run (and the fallback when the scene refuses it).
const REFERENCE_RTOL: [f64; 2] = [1e-14, 1e-13];
/// Absolute tolerance of a reference run.
const REFERENCE_ATOL: f64 = 1e-15;

/// How the study sweeps and times.
#[derive(Debug, Clone, PartialEq)]
pub struct StudyOptions {
    /// Relative tolerances of the adaptive methods, loosest first.
    pub rtols: Vec<f64>,
    /// Halvings of the fixed step after the first (10: 11 step sizes, the last 1/1024 of the first).
    pub halvings: u32,
    /// Timed repeats of a run (the median is reported); fewer for slow runs.
    pub repeats: usize,
    /// Backends swept; ode_solvers curves are labelled `method/ode_solvers`.
    pub backends: Vec<Backend>,
    /// Forms of Euler's equation swept.
    pub frames: Vec<Form>,
    /// Most steps of one fixed-step run.
    pub max_fixed_steps: f64,
    /// A curve stops refining once one of its runs took longer than this (s).
    pub slow_curve_seconds: f64,
}

impl Default for StudyOptions {
    /// rtol 1e-3 … 1e-13, 10 halvings, 5 repeats, both backends, both frames, ≤ 2·10⁷ fixed steps, 1 s.
    fn default() -> Self {
        Self {
            rtols: (3..=13).map(|k| 10f64.powi(-k)).collect(),
            halvings: 10,
            repeats: 5,
            backends: vec![Backend::Own, Backend::OdeSolvers],
            frames: vec![Form::Body, Form::Space],
            max_fixed_steps: 2e7,
            slow_curve_seconds: 1.0,
        }
    }
}

impl StudyOptions {
    /// A quick study for tests and previews: 4 tolerances (1e-4, 1e-6, 1e-8, 1e-10), 4 step sizes, 1 repeat, own
    /// backend, body form.
    pub fn quick() -> Self {
        Self {
            rtols: vec![1e-4, 1e-6, 1e-8, 1e-10],
            halvings: 3,
            repeats: 1,
            backends: vec![Backend::Own],
            frames: vec![Form::Body],
            max_fixed_steps: 1e6,
            slow_curve_seconds: 0.5,
        }
    }
}

/// The quantity the summary and the plot rank runs by.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Measure {
    /// `err_omega` (free motion).
    Omega,
    /// `err_H_s`: H_s integrated from Ḣ_s = M_s against the closed form (prescribed fixed-axis motion, whose ω
    /// is the closed form itself).
    HSpace,
}

impl Measure {
    /// The table column.
    pub fn column(&self) -> &'static str {
        match self {
            Measure::Omega => "err_omega",
            Measure::HSpace => "err_H_s",
        }
    }

    /// What it is, for people.
    pub fn describe(&self) -> &'static str {
        match self {
            Measure::Omega => "largest |omega_b - omega_ref| over the rows (rad/s)",
            Measure::HSpace => {
                "largest |H_s integrated - I_s(theta) omega_s| over the rows (kg*m^2/s)"
            }
        }
    }
}

/// One run of the study: a method at one tolerance or step size, in one frame, on one backend.
#[derive(Debug, Clone, PartialEq)]
pub struct StudyRow {
    /// The curve's label: the method's name, with `/ode_solvers` for that backend.
    pub method: String,
    pub method_name: Method,
    pub backend: Backend,
    pub frame: Form,
    /// Relative tolerance (adaptive methods whose result depends on it).
    pub rtol: Option<f64>,
    /// Absolute tolerance used with `rtol`.
    pub atol: Option<f64>,
    /// Fixed step (fixed-step methods).
    pub dt: Option<f64>,
    /// Largest |ω_b − ω_b,ref| (rad/s); NaN for a failed run.
    pub err_omega: f64,
    /// Largest attitude angle to the reference (rad); `None` when the reference has no attitude.
    pub err_attitude: Option<f64>,
    /// Largest |E − E_ref| / max |E_ref|.
    pub energy_drift: f64,
    /// Largest ||H| − |H|_ref| / max |H|_ref.
    pub h_drift: f64,
    /// Largest |H_s − H_s,ref| (kg·m²/s); `None` when the reference has no H_s.
    pub err_h_s: Option<f64>,
    /// Median wall time of the integration (s).
    pub wall_s: f64,
    pub steps: u64,
    pub rejected: u64,
    pub evals: u64,
    /// Timed repeats behind `wall_s`.
    pub repeats: usize,
    /// `None` for a completed run, else why it failed.
    pub failure: Option<String>,
}

impl StudyRow {
    /// The error the study ranks by, if the run completed.
    pub fn error(&self, measure: Measure) -> Option<f64> {
        if self.failure.is_some() {
            return None;
        }
        match measure {
            Measure::Omega => Some(self.err_omega),
            Measure::HSpace => self.err_h_s,
        }
    }

    /// `rtol 1e-8` or `dt 0.0625` (or `closed form`), for people.
    pub fn setting(&self) -> String {
        match (self.rtol, self.dt) {
            (Some(r), _) => format!("rtol {}", short(r)),
            (None, Some(dt)) => format!("dt {} s", short(dt)),
            (None, None) => "no tolerance".into(),
        }
    }
}

/// The cheapest run reaching an error level.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Cheapest {
    /// The error level.
    pub target: f64,
    /// Index into [`Study::rows`] of the fastest run with error ≤ target, if any.
    pub row: Option<usize>,
    /// The same among the methods that integrate (fixed-step or adaptive: not `exact`, which evaluates the closed
    /// form at every row).
    pub integrator: Option<usize>,
}

/// A method (or backend) the study did not sweep, and why.
#[derive(Debug, Clone, PartialEq)]
pub struct Skipped {
    /// Method label (`exact`, `dop853/ode_solvers`, …).
    pub method: String,
    pub reason: String,
}

/// The outcome of [`accuracy`].
#[derive(Debug, Clone, PartialEq)]
pub struct Study {
    /// The scene file, as given.
    pub scene_path: PathBuf,
    /// The scene's name.
    pub scene_name: String,
    pub t_end: f64,
    /// Rows of every run.
    pub rows_per_run: usize,
    /// What the runs are compared with.
    pub reference: String,
    /// The same in a few words (for the figure).
    pub reference_short: String,
    /// The quantity runs are ranked by.
    pub measure: Measure,
    /// Every run, in the order run.
    pub rows: Vec<StudyRow>,
    /// The cheapest run for each of [`TARGETS`].
    pub cheapest: Vec<Cheapest>,
    /// What was not swept.
    pub skipped: Vec<Skipped>,
    /// Total wall time of the study (s).
    pub study_seconds: f64,
}

/// Why the study could not be made.
#[derive(Debug, thiserror::Error)]
pub enum StudyError {
    /// The scene is not valid.
    #[error(transparent)]
    Scene(#[from] SceneError),
    /// The scene cannot be studied (too many rows, t_end = 0, no applicable method).
    #[error("{}: {problem}", file.display())]
    Unsuitable { file: PathBuf, problem: String },
    /// The reference run failed.
    #[error("{}: the reference run failed: {problem}", file.display())]
    Reference { file: PathBuf, problem: String },
    /// An output file cannot be created (bad path: exit 2) or written (exit 1).
    #[error("{}: {problem}", file.display())]
    Output {
        file: PathBuf,
        problem: String,
        /// Whether it is bad input (the path) rather than a failure to write.
        input: bool,
    },
}

impl StudyError {
    /// The exit code for the command line: 2 for bad input (the scene, a scene the study cannot use, an output
    /// path that cannot be created), 1 for a failure during the work (the reference run, writing a file).
    pub fn exit_code(&self) -> u8 {
        match self {
            StudyError::Scene(_) | StudyError::Unsuitable { .. } => 2,
            StudyError::Output { input: true, .. } => 2,
            StudyError::Reference { .. } | StudyError::Output { input: false, .. } => 1,
        }
    }
}

/// One row of a reference.
#[derive(Debug, Clone, Copy)]
struct RefRow {
    t: f64,
    omega_b: Vector3<f64>,
    q: Option<UnitQuaternion<f64>>,
    energy: f64,
    h_norm: f64,
    h_s: Option<Vector3<f64>>,
}

/// What runs are compared with.
enum Reference {
    /// A value per row (closed form or reference run).
    Rows(Vec<RefRow>),
    /// Prescribed fixed-axis motion: the rows carry their own closed form.
    FixedAxis,
}

/// The largest differences of one run, accumulated row by row.
#[derive(Debug, Clone, Copy, Default)]
struct Errors {
    omega: f64,
    attitude: Option<f64>,
    energy: f64,
    energy_scale: f64,
    h_norm: f64,
    h_scale: f64,
    h_s: Option<f64>,
}

impl Errors {
    fn max_into(slot: &mut Option<f64>, v: f64) {
        *slot = Some(slot.map_or(v, |old| old.max(v)));
    }

    fn add(&mut self, s: &Sample, r: &RefRow) {
        self.omega = self.omega.max((s.omega_b - r.omega_b).norm());
        if let Some(q) = &r.q {
            Self::max_into(&mut self.attitude, attitude_angle(&s.q, q));
        }
        self.energy = self.energy.max((s.energy - r.energy).abs());
        self.energy_scale = self.energy_scale.max(r.energy.abs());
        self.h_norm = self.h_norm.max((s.h_s.norm() - r.h_norm).abs());
        self.h_scale = self.h_scale.max(r.h_norm.abs());
        if let Some(h_s) = &r.h_s {
            Self::max_into(&mut self.h_s, (s.h_s - h_s).norm());
        }
    }

    fn add_fixed_axis(&mut self, s: &Sample) {
        self.attitude = Some(0.0);
        if let Some(h_int) = &s.h_s_integrated {
            Self::max_into(&mut self.h_s, (h_int - s.h_s).norm());
        }
        self.energy_scale = self.energy_scale.max(s.energy.abs());
        self.h_scale = self.h_scale.max(s.h_s.norm());
    }

    fn relative(abs: f64, scale: f64) -> f64 {
        if scale > 0.0 { abs / scale } else { abs }
    }
}

/// A run's row does not match the reference's (never expected: both follow the scene's schedule).
#[derive(Debug, thiserror::Error)]
#[error("row {row} at t = {t} has no reference row")]
struct RowMismatch {
    row: usize,
    t: f64,
}

/// The state of one sweep (curve) while it runs.
struct Sweep<'a> {
    path: &'a Path,
    text: &'a str,
    reference: &'a Reference,
    options: &'a StudyOptions,
}

/// What one planned run gives: a row, or `None` when the scene refuses the setting.
enum RunOutcome {
    Row(StudyRow),
    Refused(String),
}

impl Sweep<'_> {
    /// Runs one setting: errors on a first streaming run, then the timed repeats.
    fn run(
        &self,
        method: Method,
        backend: Backend,
        frame: Form,
        tolerances: Option<(f64, f64)>,
        dt: Option<f64>,
    ) -> RunOutcome {
        let overrides = Overrides {
            method: Some(method),
            frame: Some(frame),
            backend: Some(backend),
            rtol: tolerances.map(|t| t.0),
            atol: tolerances.map(|t| t.1),
            dt,
            ..Overrides::default()
        };
        let scene = match scene::parse(self.path, self.text, &overrides) {
            Ok(s) => s,
            Err(e) => return RunOutcome::Refused(e.problem),
        };
        let mut row = StudyRow {
            method: label(method, backend),
            method_name: method,
            backend,
            frame,
            rtol: tolerances.map(|t| t.0),
            atol: tolerances.map(|t| t.1),
            dt,
            err_omega: f64::NAN,
            err_attitude: None,
            energy_drift: f64::NAN,
            h_drift: f64::NAN,
            err_h_s: None,
            wall_s: f64::NAN,
            steps: 0,
            rejected: 0,
            evals: 0,
            repeats: 0,
            failure: None,
        };
        let mut errors = Errors::default();
        let mut k = 0usize;
        let first = simulate::run(&scene, |s: &Sample| {
            match self.reference {
                Reference::Rows(rows) => match rows.get(k) {
                    Some(r) if r.t == s.t => errors.add(s, r),
                    _ => return Err(RowMismatch { row: k, t: s.t }),
                },
                Reference::FixedAxis => errors.add_fixed_axis(s),
            }
            k += 1;
            Ok(())
        });
        let first = match first {
            Ok(report) => report,
            // Diverged, failed, or (never expected) a row without a reference row.
            Err(e) => {
                row.failure = Some(e.to_string());
                return RunOutcome::Row(row);
            }
        };
        row.err_omega = errors.omega;
        row.err_attitude = errors.attitude;
        row.energy_drift = Errors::relative(errors.energy, errors.energy_scale);
        row.h_drift = Errors::relative(errors.h_norm, errors.h_scale);
        row.err_h_s = errors.h_s;
        row.steps = first.stats.steps;
        row.rejected = first.stats.rejected;
        row.evals = first.stats.evals;
        let repeats = if first.wall_seconds > 1.0 {
            1
        } else if first.wall_seconds > 0.2 {
            3.min(self.options.repeats)
        } else {
            self.options.repeats
        }
        .max(1);
        let mut times = Vec::with_capacity(repeats);
        for _ in 0..repeats {
            let start = Instant::now();
            let timed = simulate::run(&scene, |s: &Sample| {
                black_box(s);
                Ok::<(), Infallible>(())
            });
            let elapsed = start.elapsed().as_secs_f64();
            if let Err(e) = timed {
                row.failure = Some(format!("a repeat failed where the first run did not: {e}"));
                return RunOutcome::Row(row);
            }
            times.push(elapsed);
        }
        row.wall_s = median(&mut times);
        row.repeats = repeats;
        RunOutcome::Row(row)
    }
}

/// The median (upper median for an even count); NaN for no values.
fn median(values: &mut [f64]) -> f64 {
    if values.is_empty() {
        return f64::NAN;
    }
    values.sort_by(f64::total_cmp);
    values[values.len() / 2]
}

/// `dop853` or `dop853/ode_solvers`.
fn label(method: Method, backend: Backend) -> String {
    match backend {
        Backend::Own => method.name().to_string(),
        other => format!("{}/{}", method.name(), other.name()),
    }
}

/// The closed form at every row time, from an oracle that gives ω (and perhaps the attitude and H_s).
fn oracle_rows(scene: &Scene, oracle: &Oracle) -> Option<Vec<RefRow>> {
    let inertia = *scene.body.inertia_c();
    let from_omega = |t: f64, omega_b: Vector3<f64>| {
        let h_b = inertia * omega_b;
        RefRow {
            t,
            omega_b,
            q: None,
            energy: 0.5 * omega_b.dot(&h_b),
            h_norm: h_b.norm(),
            h_s: None,
        }
    };
    let times = scene.schedule.iter();
    Some(match oracle {
        Oracle::TorqueFree { exact, principal_b } => times
            .map(|t| RefRow {
                t,
                omega_b: principal_b * exact.omega_p(t),
                q: Some(exact.attitude(t) * principal_b.inverse()),
                energy: exact.energy(),
                h_norm: exact.h_s().norm(),
                h_s: Some(exact.h_s()),
            })
            .collect(),
        Oracle::AxialTorque(exact) => times.map(|t| from_omega(t, exact.omega_p(t))).collect(),
        Oracle::DampedSpin {
            omega0_b,
            inertia,
            c,
            q0,
        } => {
            // As in `compare`: ω(t) = ω(0)·exp(−c t / I), turned angle ω(0)·I/c·(1 − exp(−c t / I)).
            let axis = nalgebra::Unit::new_normalize(*omega0_b);
            let w0 = omega0_b.norm();
            times
                .map(|t| {
                    let decay = (-c * t / inertia).exp();
                    let turned = w0 * inertia / c * (-(-c * t / inertia).exp_m1());
                    let q = q0 * UnitQuaternion::from_axis_angle(&axis, turned);
                    let omega_b = omega0_b * decay;
                    RefRow {
                        q: Some(q),
                        h_s: Some(q * (omega0_b * (inertia * decay))),
                        energy: 0.5 * inertia * w0 * w0 * decay * decay,
                        h_norm: inertia * w0 * decay,
                        ..from_omega(t, omega_b)
                    }
                })
                .collect()
        }
        Oracle::FixedAxis => return None,
    })
}

/// The reference run: DOP853 on the own backend at the tightest tolerance the scene accepts, in `frame`.
fn reference_run(
    path: &Path,
    text: &str,
    frame: Form,
) -> Result<(Vec<RefRow>, f64, u64), StudyError> {
    let mut last_refusal = None;
    for rtol in REFERENCE_RTOL {
        let overrides = Overrides {
            method: Some(Method::Dop853),
            frame: Some(frame),
            backend: Some(Backend::Own),
            rtol: Some(rtol),
            atol: Some(REFERENCE_ATOL),
            ..Overrides::default()
        };
        let scene = match scene::parse(path, text, &overrides) {
            Ok(s) => s,
            Err(e) => {
                last_refusal = Some(e.to_string());
                continue;
            }
        };
        let mut rows = Vec::with_capacity(scene.schedule.len());
        let report = simulate::run(&scene, |s: &Sample| {
            rows.push(RefRow {
                t: s.t,
                omega_b: s.omega_b,
                q: Some(s.q),
                energy: s.energy,
                h_norm: s.h_s.norm(),
                h_s: Some(s.h_s),
            });
            Ok::<(), Infallible>(())
        })
        .map_err(|e| StudyError::Reference {
            file: path.to_path_buf(),
            problem: e.to_string(),
        })?;
        return Ok((rows, rtol, report.stats.steps));
    }
    Err(StudyError::Reference {
        file: path.to_path_buf(),
        problem: format!(
            "the scene refuses DOP853 at rtol 1e-14 and 1e-13: {}",
            last_refusal.unwrap_or_default()
        ),
    })
}

/// The largest |ω| of a scene's motion: from the reference rows, or (fixed axis) from a run of the scene.
fn omega_scale(scene: &Scene, reference: &Reference) -> f64 {
    match reference {
        Reference::Rows(rows) => rows.iter().map(|r| r.omega_b.norm()).fold(0.0, f64::max),
        Reference::FixedAxis => {
            let mut largest = 0.0f64;
            let _ = simulate::run(scene, |s: &Sample| {
                largest = largest.max(s.omega_b.norm());
                Ok::<(), Infallible>(())
            });
            largest
        }
    }
}

/// The first fixed step: every / 2^j, the largest with |ω|max·dt ≤ 0.5 (at most 2^-40·every).
fn first_step(every: f64, omega_max: f64) -> f64 {
    let mut dt = every;
    let mut j = 0;
    while omega_max * dt > 0.5 && j < 40 {
        dt *= 0.5;
        j += 1;
    }
    dt
}

/// Runs the work-precision study of the scene file `scene_path` whose text is `text`. `progress(done, total,
/// what)` is called before every run (and once at the end with done = total); `total` is the planned number of
/// runs, some of which a curve may skip (the count then jumps).
pub fn accuracy(
    scene_path: &Path,
    text: &str,
    options: &StudyOptions,
    mut progress: impl FnMut(usize, usize, &str),
) -> Result<Study, StudyError> {
    let started = Instant::now();
    let base = scene::parse(scene_path, text, &Overrides::default())?;
    let unsuitable = |problem: String| StudyError::Unsuitable {
        file: scene_path.to_path_buf(),
        problem,
    };
    let n_rows = base.schedule.len();
    if base.solver.t_end <= 0.0 {
        return Err(unsuitable(
            "solver.t_end = 0: there is nothing to integrate; give t_end > 0".into(),
        ));
    }
    if n_rows > REFERENCE_MAX_ROWS {
        return Err(unsuitable(format!(
            "the scene writes {n_rows} rows; the accuracy study keeps the reference at every row in memory and takes at most {REFERENCE_MAX_ROWS}: use a larger output.every (or --every)"
        )));
    }
    progress(0, 1, "reference");
    let oracle = Oracle::for_scene(&base);
    let (reference, reference_text, reference_short, measure) = match &oracle {
        Some(Oracle::FixedAxis) => (
            Reference::FixedAxis,
            "closed form: prescribed fixed-axis motion, H_s = I_s(theta) omega_s against H_s integrated from dH_s/dt = M_s (omega and attitude are the closed form in every run)".to_string(),
            "closed form H_s = I_s(theta) omega_s".to_string(),
            Measure::HSpace,
        ),
        Some(o) => {
            let rows = oracle_rows(&base, o).unwrap_or_default();
            (
                Reference::Rows(rows),
                format!("closed form: {}", o.name()),
                "closed form".to_string(),
                Measure::Omega,
            )
        }
        None => {
            let (rows, rtol, steps) = reference_run(scene_path, text, Form::Body)?;
            let (other, _, _) = reference_run(scene_path, text, Form::Space)?;
            let spread = rows
                .iter()
                .zip(&other)
                .map(|(a, b)| (a.omega_b - b.omega_b).norm())
                .fold(0.0, f64::max);
            (
                Reference::Rows(rows),
                format!(
                    "no closed form applies: reference run dop853 (own backend, body form) at rtol {rtol:e}, atol {REFERENCE_ATOL:e} ({steps} steps); its space form differs from it by {spread:.1e} rad/s in omega, so smaller errors are not resolved"
                ),
                format!("dop853 at rtol {rtol:e} (uncertainty {spread:.0e} rad/s)"),
                Measure::Omega,
            )
        }
    };
    let omega_max = omega_scale(&base, &reference);
    let dt0 = first_step(base.schedule.every(), omega_max);
    let atol_ratio = base.solver.atol / base.solver.rtol;
    let sweep = Sweep {
        path: scene_path,
        text,
        reference: &reference,
        options,
    };

    // Every (backend, method, frame) curve and its planned number of runs. Other backends than the own one run
    // the Runge–Kutta methods only.
    let mut curves = Vec::new();
    for &backend in &options.backends {
        for method in Method::ALL {
            if backend != Backend::Own && !method.is_runge_kutta() {
                continue;
            }
            for &frame in &options.frames {
                let planned = if method.is_fixed_step() {
                    options.halvings as usize + 1
                } else if method.is_adaptive() {
                    options.rtols.len()
                } else {
                    1
                };
                curves.push((backend, method, frame, planned));
            }
        }
    }
    let total: usize = curves.iter().map(|c| c.3).sum();
    let mut done = 0usize;
    let mut rows: Vec<StudyRow> = Vec::new();
    let mut skipped: Vec<Skipped> = Vec::new();
    let mut skip = |method: String, reason: String| {
        if !skipped.iter().any(|s| s.method == method) {
            skipped.push(Skipped { method, reason });
        }
    };
    for (backend, method, frame, planned) in curves {
        let name = label(method, backend);
        let curve_start = rows.len();
        let mut ran = 0usize;
        let what = |setting: &str| format!("{name} ({} form) {setting}", frame.name());
        if method.is_fixed_step() {
            let mut previous: Option<f64> = None;
            for k in 0..=options.halvings {
                let dt = dt0 / 2f64.powi(k as i32);
                if base.solver.t_end / dt > options.max_fixed_steps {
                    break;
                }
                progress(done + ran, total, &what(&format!("dt {dt:e} s")));
                ran += 1;
                let row = match sweep.run(method, backend, frame, None, Some(dt)) {
                    RunOutcome::Row(row) => row,
                    RunOutcome::Refused(reason) => {
                        // A method the scene refuses is skipped; a step it refuses (too many steps) ends the curve.
                        if k == 0 {
                            skip(name.clone(), reason);
                        }
                        break;
                    }
                };
                let err = row.error(measure);
                let slow = row.wall_s > options.slow_curve_seconds;
                rows.push(row);
                if let Some(err) = err {
                    let scale = omega_max.max(1.0);
                    let at_round_off = err <= 1e-13 * scale
                        || previous.is_some_and(|p| err < 1e-8 * scale && err > 0.7 * p);
                    if at_round_off {
                        break;
                    }
                    previous = Some(err);
                }
                if slow {
                    break;
                }
            }
        } else if method.is_adaptive() {
            for &rtol in &options.rtols {
                progress(done + ran, total, &what(&format!("rtol {rtol:e}")));
                ran += 1;
                // Rounded to 12 digits, so that 1e-6 × 1e-2 is written 1e-8, not 1.0000000000000001e-8.
                let atol = format!("{:.11e}", rtol * atol_ratio)
                    .parse()
                    .unwrap_or(rtol * atol_ratio);
                let tolerances = Some((rtol, atol));
                match sweep.run(method, backend, frame, tolerances, None) {
                    RunOutcome::Row(row) => {
                        let slow = row.wall_s > options.slow_curve_seconds;
                        rows.push(row);
                        if slow {
                            break;
                        }
                    }
                    RunOutcome::Refused(reason) => {
                        if rows.len() == curve_start {
                            skip(name.clone(), reason);
                            break;
                        }
                    }
                }
            }
        } else {
            // No step and no tolerance (`exact`): one run.
            progress(done, total, &what("(no tolerance)"));
            match sweep.run(method, backend, frame, None, None) {
                RunOutcome::Row(row) => rows.push(row),
                RunOutcome::Refused(reason) => skip(name.clone(), reason),
            }
        }
        done += planned;
    }
    progress(total, total, "done");
    if rows.is_empty() {
        return Err(unsuitable(format!(
            "no method applies to this scene ({})",
            skipped
                .iter()
                .map(|s| format!("{}: {}", s.method, s.reason))
                .collect::<Vec<_>>()
                .join("; ")
        )));
    }
    let fastest = |target: f64, integrators_only: bool| {
        rows.iter()
            .enumerate()
            .filter(|(_, r)| r.error(measure).is_some_and(|e| e <= target))
            .filter(|(_, r)| {
                !integrators_only || r.method_name.is_fixed_step() || r.method_name.is_adaptive()
            })
            .min_by(|a, b| a.1.wall_s.total_cmp(&b.1.wall_s))
            .map(|(i, _)| i)
    };
    let cheapest = TARGETS
        .iter()
        .map(|&target| Cheapest {
            target,
            row: fastest(target, false),
            integrator: fastest(target, true),
        })
        .collect();
    Ok(Study {
        scene_path: scene_path.to_path_buf(),
        scene_name: base.name.clone(),
        t_end: base.solver.t_end,
        rows_per_run: n_rows,
        reference: reference_text,
        reference_short,
        measure,
        rows,
        cheapest,
        skipped,
        study_seconds: started.elapsed().as_secs_f64(),
    })
}

/// A number for the table: shortest form that reads back to the same f64; empty for none or NaN.
fn cell(v: Option<f64>) -> String {
    match v {
        Some(x) if !x.is_nan() => format!("{x:e}"),
        _ => String::new(),
    }
}

/// A number for people: its shortest form when that is short (`1e-10`, `6.25e-2`), else 4 digits (`5.623e-11`).
fn short(x: f64) -> String {
    let exact = format!("{x:e}");
    if exact.len() <= 8 {
        exact
    } else {
        format!("{x:.3e}")
    }
}

/// A duration for people: `41.2 µs`, `3.10 ms`, `1.25 s`.
pub fn format_seconds(s: f64) -> String {
    if s < 1e-3 {
        format!("{:.1} µs", s * 1e6)
    } else if s < 1.0 {
        format!("{:.2} ms", s * 1e3)
    } else {
        format!("{s:.2} s")
    }
}

impl Study {
    /// Writes the table as CSV: a header row ([`TABLE_COLUMNS`]), then a row per run. Empty cells: no value
    /// (rtol of a fixed-step run, errors of a failed run).
    pub fn write_table(&self, out: impl Write) -> io::Result<()> {
        let mut w = csv::Writer::from_writer(out);
        w.write_record(TABLE_COLUMNS)?;
        for r in &self.rows {
            let ok = r.failure.is_none();
            let when_ok = |v: f64| cell(ok.then_some(v));
            w.write_record([
                r.method.clone(),
                r.frame.name().to_string(),
                cell(r.rtol),
                cell(r.dt),
                when_ok(r.err_omega),
                cell(r.err_attitude.filter(|_| ok)),
                when_ok(r.energy_drift),
                when_ok(r.h_drift),
                when_ok(r.wall_s),
                r.steps.to_string(),
                r.rejected.to_string(),
                r.evals.to_string(),
                cell(r.err_h_s.filter(|_| ok)),
                cell(r.atol),
                r.backend.name().to_string(),
                r.repeats.to_string(),
                r.failure
                    .as_ref()
                    .map_or_else(|| "ok".to_string(), |f| format!("failed: {f}")),
            ])?;
        }
        w.flush()
    }

    /// The table as CSV text.
    pub fn table_csv(&self) -> String {
        let mut bytes = Vec::new();
        // Writing into a Vec cannot fail.
        let _ = self.write_table(&mut bytes);
        String::from_utf8_lossy(&bytes).into_owned()
    }

    /// What the study found, for people: the reference, the cheapest method for each of [`TARGETS`], the fastest
    /// run of each method, and what was not swept.
    pub fn summary(&self) -> String {
        let mut out = String::new();
        let failed = self.rows.iter().filter(|r| r.failure.is_some()).count();
        let name = if self.scene_name.is_empty() {
            String::new()
        } else {
            format!(" ({})", self.scene_name)
        };
        let _ = writeln!(
            out,
            "accuracy of {}{name}: {} runs ({failed} failed), t_end = {} s, {} rows per run, study took {}",
            self.scene_path.display(),
            self.rows.len(),
            self.t_end,
            self.rows_per_run,
            format_seconds(self.study_seconds)
        );
        let _ = writeln!(out, "reference: {}", self.reference);
        let _ = writeln!(
            out,
            "error: {} = {}; time: median wall time of the integration alone",
            self.measure.column(),
            self.measure.describe()
        );
        let column = self.measure.column();
        let describe = |r: &StudyRow| {
            format!(
                "{} ({} form, {}): {:.2e} in {} ({} steps, {} rejected, {} evaluations)",
                r.method,
                r.frame.name(),
                r.setting(),
                r.error(self.measure).unwrap_or(f64::NAN),
                format_seconds(r.wall_s),
                r.steps,
                r.rejected,
                r.evals
            )
        };
        for c in &self.cheapest {
            let _ = match c.row.map(|i| &self.rows[i]) {
                Some(r) => writeln!(
                    out,
                    "cheapest for {column} <= {:e}: {}",
                    c.target,
                    describe(r)
                ),
                None => {
                    let best = self
                        .rows
                        .iter()
                        .filter_map(|r| r.error(self.measure).map(|e| (e, r)))
                        .min_by(|a, b| a.0.total_cmp(&b.0));
                    match best {
                        Some((e, r)) => writeln!(
                            out,
                            "cheapest for {column} <= {:e}: no run reaches it (smallest: {e:.2e}, {} {} form {})",
                            c.target,
                            r.method,
                            r.frame.name(),
                            r.setting()
                        ),
                        None => writeln!(
                            out,
                            "cheapest for {column} <= {:e}: no run completed",
                            c.target
                        ),
                    }
                }
            };
            if c.integrator != c.row
                && let Some(r) = c.integrator.map(|i| &self.rows[i])
            {
                let _ = writeln!(out, "    cheapest that integrates: {}", describe(r));
            }
        }
        let curves = self.costs();
        if !curves.is_empty() {
            let _ = writeln!(
                out,
                "\nwall time to reach {column} <= {} (the cheapest run of each method and form; - : not reached):",
                TARGETS.map(|t| format!("{t:e}")).join(" / ")
            );
            let _ = write!(out, "{:<20} {:<6}", "method", "form");
            for t in TARGETS {
                let _ = write!(out, " {:>10}", format!("{t:e}"));
            }
            let _ = writeln!(out);
            for c in &curves {
                let _ = write!(out, "{:<20} {:<6}", c.method, c.frame.name());
                for i in c.rows {
                    let cell =
                        i.map_or_else(|| "-".to_string(), |i| format_seconds(self.rows[i].wall_s));
                    let _ = write!(out, " {cell:>10}");
                }
                let _ = writeln!(out);
            }
        }
        for s in &self.skipped {
            let _ = writeln!(out, "not swept: {}: {}", s.method, s.reason);
        }
        out
    }
}

/// One curve's cheapest run for each of [`TARGETS`].
#[derive(Debug, Clone, PartialEq)]
pub struct CurveCost {
    /// The curve's label (`dop853`, `dop853/ode_solvers`).
    pub method: String,
    pub frame: Form,
    /// Index into [`Study::rows`] of the fastest run of the curve reaching each target.
    pub rows: [Option<usize>; 3],
}

impl Study {
    /// For every curve (method label and form, in the order run), the fastest run reaching each of [`TARGETS`].
    pub fn costs(&self) -> Vec<CurveCost> {
        let mut curves: Vec<CurveCost> = Vec::new();
        for (i, r) in self.rows.iter().enumerate() {
            let k = match curves
                .iter()
                .position(|c| c.method == r.method && c.frame == r.frame)
            {
                Some(k) => k,
                None => {
                    curves.push(CurveCost {
                        method: r.method.clone(),
                        frame: r.frame,
                        rows: [None; 3],
                    });
                    curves.len() - 1
                }
            };
            let Some(err) = r.error(self.measure) else {
                continue;
            };
            for (slot, target) in curves[k].rows.iter_mut().zip(TARGETS) {
                let faster = slot.is_none_or(|j| r.wall_s < self.rows[j].wall_s);
                if err <= target && faster {
                    *slot = Some(i);
                }
            }
        }
        curves
    }
}

impl fmt::Display for Study {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.summary())
    }
}

/// Whether two paths name the same existing file.
fn same_file(a: &Path, b: &Path) -> bool {
    match (a.canonicalize(), b.canonicalize()) {
        (Ok(a), Ok(b)) => a == b,
        _ => false,
    }
}

/// Opens an output file atomically, refusing the scene file itself.
fn create_output(scene: &Path, out: &Path) -> Result<AtomicFile, StudyError> {
    let refuse = |problem: String| StudyError::Output {
        file: out.to_path_buf(),
        problem,
        input: true,
    };
    if same_file(scene, out) {
        return Err(refuse(
            "the output would overwrite the scene file; give another path".into(),
        ));
    }
    AtomicFile::create(out).map_err(|e| refuse(format!("cannot create the output file: {e}")))
}

/// Writes `bytes` into an open output file and renames it over its destination.
fn finish_output(mut file: AtomicFile, bytes: &[u8]) -> Result<(), StudyError> {
    let path = file.path().to_path_buf();
    let fail = |what: &str, e: io::Error| StudyError::Output {
        file: path.clone(),
        problem: format!("{what}: {e}"),
        input: false,
    };
    file.file()
        .write_all(bytes)
        .map_err(|e| fail("cannot write", e))?;
    file.commit().map_err(|e| fail("cannot save", e))
}

/// `eulerdyn accuracy SCENE [-o TABLE.csv] [--plot FIG.svg]`: reads and validates the scene, creates the output
/// files (before the study, so that a bad path fails at once), runs the study with `progress` (see [`accuracy`]),
/// then writes the table and the figure atomically: on any failure no partial file is left and existing files are
/// untouched. Returns the study; print [`Study::summary`], and [`Study::table_csv`] when no table file is given.
pub fn run_accuracy_command(
    scene_path: &Path,
    table: Option<&Path>,
    plot: Option<&Path>,
    options: &StudyOptions,
    progress: impl FnMut(usize, usize, &str),
) -> Result<Study, StudyError> {
    // `load` gives the messages for a missing, unreadable or non-UTF-8 file and validates the scene.
    scene::load(scene_path, &Overrides::default())?;
    let text = std::fs::read_to_string(scene_path).map_err(|e| {
        StudyError::Scene(SceneError {
            file: scene_path.to_path_buf(),
            key: None,
            location: None,
            problem: format!("cannot read the file: {e}"),
        })
    })?;
    if let (Some(t), Some(p)) = (table, plot)
        && t == p
    {
        return Err(StudyError::Output {
            file: p.to_path_buf(),
            problem: "the table and the figure would be the same file".into(),
            input: true,
        });
    }
    let table_file = table.map(|p| create_output(scene_path, p)).transpose()?;
    let plot_file = plot.map(|p| create_output(scene_path, p)).transpose()?;
    let study = accuracy(scene_path, &text, options, progress)?;
    let svg =
        match &plot_file {
            Some(f) => Some(crate::output::work_precision::render_svg(&study).map_err(
                |problem| StudyError::Output {
                    file: f.path().to_path_buf(),
                    problem,
                    input: false,
                },
            )?),
            None => None,
        };
    if let Some(f) = table_file {
        finish_output(f, study.table_csv().as_bytes())?;
    }
    if let (Some(f), Some(svg)) = (plot_file, svg) {
        finish_output(f, svg.as_bytes())?;
    }
    Ok(study)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn first_step_is_a_power_of_two_fraction_of_every() {
        assert_eq!(first_step(0.5, 2.02), 0.125);
        assert_eq!(first_step(0.5, 0.0), 0.5);
        assert_eq!(first_step(0.01, 10.0), 0.01);
        assert!(first_step(1.0, f64::MAX) > 0.0);
    }

    #[test]
    fn median_and_cells() {
        assert_eq!(median(&mut [3.0, 1.0, 2.0]), 2.0);
        assert!(median(&mut []).is_nan());
        assert_eq!(cell(Some(1e-10)), "1e-10");
        assert_eq!(cell(Some(0.125)), "1.25e-1");
        assert_eq!(cell(None), "");
        assert_eq!(cell(Some(f64::NAN)), "");
        assert_eq!(format_seconds(4.12e-5), "41.2 µs");
        assert_eq!(format_seconds(0.0031), "3.10 ms");
        assert_eq!(short(1e-10), "1e-10");
        assert_eq!(short(9.765625e-4), "9.766e-4");
    }
}
