//! The work-precision study behind `eulerdyn accuracy`: what each digit of accuracy costs in time.
//!
//! Every method of [`Method::ALL`] that the scene accepts is run over a sweep (adaptive methods over relative
//! tolerances, fixed-step methods over halved step sizes), each run's error measured against a reference (a closed
//! form, or a tight DOP853 run), and its integration timed. The outcome is a [`Study`]: a table (one row per run,
//! [`TABLE_COLUMNS`]), and a summary naming the cheapest method for each of [`TARGETS`] — among the runs whose
//! curve converges there ([`convergence`]), so that a run reaching a target by chance is not named. How the sweep
//! is chosen, what each measure means and how the time is taken: `docs/book/src/explanation/accuracy-study.md`.
//!
//! - this module: the options, the plan of runs, and [`accuracy`], which runs it;
//! - `convergence`: whether a run counts for a target (its curve's error falls with the setting there);
//! - `reference`: the closed form or reference run the errors are taken against;
//! - `sweep`: one curve of runs, and one run: its scene, its errors, its timing;
//! - `measure`: the errors of one run against the reference, row by row;
//! - `timing`: the timed repeats of a run;
//! - `table`, `summary`: the study as CSV and in words;
//! - `figure` (feature `plot`): the work-precision figure; `files`: `run_accuracy_command`, the study of a scene
//!   file with its table and figure written atomically (`eulerdyn accuracy`).

pub mod convergence;
#[cfg(feature = "plot")]
pub mod figure;
#[cfg(feature = "plot")]
mod files;
mod measure;
mod reference;
mod summary;
mod sweep;
mod table;
mod timing;

use std::ops::ControlFlow;
use std::path::{Path, PathBuf};
use std::time::Instant;

use crate::frames::Form;
use crate::method::{Backend, Method};
use crate::scene::{Scene, SceneError};

#[cfg(feature = "plot")]
pub use files::run_accuracy_command;
pub use measure::Measure;
pub use summary::{CurveCost, format_seconds};
pub use table::TABLE_COLUMNS;

/// The error levels the summary names the cheapest method for.
pub const TARGETS: [f64; 3] = [1e-6, 1e-9, 1e-12];

/// Most rows of a reference kept in memory.
pub const REFERENCE_MAX_ROWS: usize = 1_000_000;

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

/// One run of the study: a method at one tolerance or step size, in one frame, on one backend.
#[derive(Debug, Clone, PartialEq)]
pub struct StudyRow {
    /// The curve's label: the method's name, with `/ode_solvers` for that backend.
    pub method: String,
    /// The method.
    pub method_name: Method,
    /// Its implementation.
    pub backend: Backend,
    /// The form of Euler's equation integrated.
    pub form: Form,
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
    /// Steps taken.
    pub steps: u64,
    /// Steps rejected.
    pub rejected: u64,
    /// Right-hand-side evaluations.
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
            (Some(r), _) => format!("rtol {}", summary::short(r)),
            (None, Some(dt)) => format!("dt {} s", summary::short(dt)),
            (None, None) => "no tolerance".into(),
        }
    }
}

/// The cheapest run reaching an error level.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Cheapest {
    /// The error level.
    pub target: f64,
    /// Index into [`Study::rows`] of the fastest run with error ≤ target that counts for it (its curve converges
    /// there: [`convergence`]), if any.
    pub row: Option<usize>,
    /// The same among the methods that integrate (fixed-step or adaptive: not `exact`, which evaluates the closed
    /// form at every row).
    pub integrator: Option<usize>,
    /// The fastest run with error ≤ target that does not count for it (its curve does not converge there), when
    /// it is faster than [`Cheapest::integrator`] or there is none: reported, never named the cheapest.
    pub unconverged: Option<usize>,
}

/// A method (or backend) the study did not sweep, and why.
#[derive(Debug, Clone, PartialEq)]
pub struct Skipped {
    /// Method label (`exact`, `dop853/ode_solvers`, …).
    pub method: String,
    /// Why it was not run.
    pub reason: String,
}

/// The outcome of [`accuracy`].
#[derive(Debug, Clone, PartialEq)]
pub struct Study {
    /// The scene file, as given.
    pub scene_path: PathBuf,
    /// The scene's name.
    pub scene_name: String,
    /// The end time of every run (s).
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
    Unsuitable {
        /// The scene file.
        file: PathBuf,
        /// Why.
        problem: String,
    },
    /// The reference run failed.
    #[error("{}: the reference run failed: {problem}", file.display())]
    Reference {
        /// The scene file.
        file: PathBuf,
        /// Why it failed.
        problem: String,
    },
    /// The study was stopped before it finished ([`accuracy_until`]).
    #[error("{}: the study was interrupted", file.display())]
    Interrupted {
        /// The scene file.
        file: PathBuf,
    },
    /// An output file cannot be created (bad path: exit 2) or written (exit 1).
    #[error("{}: {problem}", file.display())]
    Output {
        /// The output path.
        file: PathBuf,
        /// What is wrong.
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
            StudyError::Reference { .. }
            | StudyError::Interrupted { .. }
            | StudyError::Output { input: false, .. } => 1,
        }
    }
}

/// One planned curve: a method in one form on one backend, and how many runs it may take.
#[derive(Debug, Clone, Copy)]
struct Curve {
    backend: Backend,
    method: Method,
    form: Form,
    planned: usize,
}

/// Every (backend, method, frame) curve and its planned number of runs. Other backends than the own one run the
/// Runge–Kutta methods only.
fn plan(options: &StudyOptions) -> Vec<Curve> {
    let mut curves = Vec::new();
    for &backend in &options.backends {
        for method in Method::ALL {
            if backend != Backend::Own && !method.is_runge_kutta() {
                continue;
            }
            for &form in &options.frames {
                let planned = if method.is_fixed_step() {
                    options.halvings as usize + 1
                } else if method.is_adaptive() {
                    options.rtols.len()
                } else {
                    1
                };
                curves.push(Curve {
                    backend,
                    method,
                    form,
                    planned,
                });
            }
        }
    }
    curves
}

/// The runs made so far, and the methods left out.
#[derive(Debug, Default)]
struct Runs {
    rows: Vec<StudyRow>,
    skipped: Vec<Skipped>,
}

impl Runs {
    /// Records that `method` was not swept (once per method: its first reason).
    fn skip(&mut self, method: String, reason: String) {
        if !self.skipped.iter().any(|s| s.method == method) {
            self.skipped.push(Skipped { method, reason });
        }
    }
}

/// The scene's file (or `<scene>` for one built in code), for messages and the summary.
fn scene_file(scene: &Scene) -> PathBuf {
    scene
        .source
        .as_ref()
        .map_or_else(|| PathBuf::from("<scene>"), |s| s.path.clone())
}

/// Refuses a scene the study cannot use (t_end = 0, too many rows for the reference).
fn check_studied(scene: &Scene, scene_path: &Path) -> Result<(), StudyError> {
    let unsuitable = |problem: String| StudyError::Unsuitable {
        file: scene_path.to_path_buf(),
        problem,
    };
    let n_rows = scene.schedule.len();
    if scene.solver.t_end <= 0.0 {
        return Err(unsuitable(
            "solver.t_end = 0: there is nothing to integrate; give t_end > 0".into(),
        ));
    }
    if n_rows > REFERENCE_MAX_ROWS {
        return Err(unsuitable(format!(
            "the scene writes {n_rows} rows; the accuracy study keeps the reference at every row in memory and takes at most {REFERENCE_MAX_ROWS}: use a larger output.every (or --every)"
        )));
    }
    Ok(())
}

/// For each of [`TARGETS`], the fastest run reaching it that counts for it ([`convergence`]), the same among the
/// methods that integrate, and the fastest run reaching it by chance when that one is faster.
fn cheapest(rows: &[StudyRow], measure: Measure) -> Vec<Cheapest> {
    let fastest = |target: f64, integrators_only: bool, counted: bool| {
        rows.iter()
            .enumerate()
            .filter(|(_, r)| r.error(measure).is_some_and(|e| e <= target))
            .filter(|(_, r)| {
                !integrators_only || r.method_name.is_fixed_step() || r.method_name.is_adaptive()
            })
            .filter(|(i, _)| convergence::counts(rows, measure, *i, target) == counted)
            .min_by(|a, b| a.1.wall_s.total_cmp(&b.1.wall_s))
            .map(|(i, _)| i)
    };
    TARGETS
        .iter()
        .map(|&target| {
            let integrator = fastest(target, true, true);
            let unconverged = fastest(target, true, false)
                .filter(|&u| integrator.is_none_or(|i| rows[u].wall_s < rows[i].wall_s));
            Cheapest {
                target,
                row: fastest(target, false, true),
                integrator,
                unconverged,
            }
        })
        .collect()
}

/// Runs the work-precision study of `scene` (every run a variant of its [`Scene::spec`], the scene as simulated).
/// `progress(done, total, what)` is called before every run (and once at the end with done = total); `total` is the planned number of
/// runs, some of which a curve may skip (the count then jumps).
pub fn accuracy(
    scene: &Scene,
    options: &StudyOptions,
    mut progress: impl FnMut(usize, usize, &str),
) -> Result<Study, StudyError> {
    accuracy_until(scene, options, |done, total, what| {
        progress(done, total, what);
        ControlFlow::Continue(())
    })
}

/// [`accuracy`], stopped before the next run with [`StudyError::Interrupted`] once `progress` breaks (the Python
/// module's Ctrl-C).
pub fn accuracy_until(
    base: &Scene,
    options: &StudyOptions,
    mut progress: impl FnMut(usize, usize, &str) -> ControlFlow<()>,
) -> Result<Study, StudyError> {
    let started = Instant::now();
    let path = scene_file(base);
    let scene_path = path.as_path();
    check_studied(base, scene_path)?;
    // Every run changes the typed scene as simulated (never the text).
    let spec = &base.spec;
    let interrupted = || StudyError::Interrupted {
        file: scene_path.to_path_buf(),
    };
    if progress(0, 1, "reference").is_break() {
        return Err(interrupted());
    }
    let reference = reference::StudyReference::for_scene(base, scene_path, spec)?;
    let sweep = sweep::Sweep::new(spec, base, &reference, options);
    let curves = plan(options);
    let total: usize = curves.iter().map(|c| c.planned).sum();
    let mut done = 0usize;
    let mut runs = Runs::default();
    let mut stopped = false;
    for curve in curves {
        sweep.curve(&curve, &mut runs, |ran, what| {
            let flow = progress(done + ran, total, what);
            stopped |= flow.is_break();
            flow
        });
        if stopped {
            return Err(interrupted());
        }
        done += curve.planned;
    }
    // The end is reported; the study is complete whatever the answer.
    let _ = progress(total, total, "done");
    if runs.rows.is_empty() {
        return Err(StudyError::Unsuitable {
            file: scene_path.to_path_buf(),
            problem: format!(
                "no method applies to this scene ({})",
                runs.skipped
                    .iter()
                    .map(|s| format!("{}: {}", s.method, s.reason))
                    .collect::<Vec<_>>()
                    .join("; ")
            ),
        });
    }
    Ok(Study {
        scene_path: scene_path.to_path_buf(),
        scene_name: base.name.clone(),
        t_end: base.solver.t_end,
        rows_per_run: base.schedule.len(),
        cheapest: cheapest(&runs.rows, reference.measure),
        reference: reference.description,
        reference_short: reference.short,
        measure: reference.measure,
        rows: runs.rows,
        skipped: runs.skipped,
        study_seconds: started.elapsed().as_secs_f64(),
    })
}
