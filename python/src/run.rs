//! `run`: a scene's rows as the command line's CSV columns, row-major float64 bytes; the GIL released meanwhile,
//! with Ctrl-C looked for a few times a second.

use std::ffi::CString;
use std::fmt;
use std::ops::ControlFlow;
use std::path::Path;
use std::sync::Arc;
use std::time::{Duration, Instant};

use eulerdyn::events::Occurrence;
use eulerdyn::frames::Axes;
use eulerdyn::named::Named;
use eulerdyn::sample::{ColumnSet, NonFinite};
use eulerdyn::scene::{Flags, Scene};
use eulerdyn::simulate::{self, RunError, RunFailed, RunReport};
use pyo3::exceptions::{PyTypeError, PyUserWarning, PyValueError};
use pyo3::prelude::*;
use pyo3::types::{PyBytes, PyDict};

use crate::errors::{no_panic, run_error};
use crate::input::SceneInput;
use crate::moment::{LawFailure, PyLaw, SharedLaw};
use crate::wheel_law::SharedWheelLaw;

/// How often a run looks for Ctrl-C (reacquiring the GIL to run Python's signal handlers).
const SIGNAL_INTERVAL: Duration = Duration::from_millis(50);

/// Why the Python sink stopped a run: a non-finite value (as the CSV writer refuses it), rows that do not fit in
/// memory, or a Python exception raised by a signal handler (KeyboardInterrupt).
#[derive(Debug)]
pub enum Stop {
    NonFinite(NonFinite),
    OutOfMemory { t: f64 },
    Python(PyErr),
}

impl Stop {
    /// The row time the run stopped at, when known.
    fn time(&self) -> Option<f64> {
        match self {
            Stop::NonFinite(e) => Some(e.t),
            Stop::OutOfMemory { t } => Some(*t),
            Stop::Python(_) => None,
        }
    }
}

impl fmt::Display for Stop {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Stop::NonFinite(e) => write!(f, "{e}"),
            Stop::OutOfMemory { t } => write!(
                f,
                "the rows up to t = {t} fill the memory: use a larger output.every (every=) or a shorter t_end, \
                 or the command line, which streams them to a file"
            ),
            Stop::Python(e) => write!(f, "{e}"),
        }
    }
}

impl std::error::Error for Stop {}

/// Calls `check` (with the GIL) at most every [`SIGNAL_INTERVAL`]: Python's signal handlers run there, and the
/// KeyboardInterrupt a Ctrl-C raises stops the run.
pub struct SignalCheck {
    last: Instant,
}

impl SignalCheck {
    pub fn new() -> Self {
        Self {
            last: Instant::now(),
        }
    }

    /// Runs Python's signal handlers if the interval has passed; their exception, if any.
    pub fn poll(&mut self) -> Result<(), PyErr> {
        if self.last.elapsed() < SIGNAL_INTERVAL {
            return Ok(());
        }
        self.last = Instant::now();
        Python::attach(|py| py.check_signals())
    }
}

/// A poll's answer for a library function that stops when it breaks: the exception (KeyboardInterrupt) is kept in
/// `interrupted`, to raise once the function has returned.
pub fn stop_on(polled: Result<(), PyErr>, interrupted: &mut Option<PyErr>) -> ControlFlow<()> {
    match polled {
        Ok(()) => ControlFlow::Continue(()),
        Err(e) => {
            *interrupted = Some(e);
            ControlFlow::Break(())
        }
    }
}

/// The run's report as a dict: rows, steps, rejected, evals, wall_seconds.
fn report_dict<'py>(py: Python<'py>, report: &RunReport) -> PyResult<Bound<'py, PyDict>> {
    let d = PyDict::new(py);
    d.set_item("rows", report.rows)?;
    d.set_item("steps", report.stats.steps)?;
    d.set_item("rejected", report.stats.rejected)?;
    d.set_item("evals", report.stats.evals)?;
    d.set_item("wall_seconds", report.wall_seconds)?;
    Ok(d)
}

/// One located event as the events file's row: (event, t, value, direction).
type EventRow = (String, f64, f64, &'static str);

/// The located events as rows of `FILE.events.csv` (`event,t,value,direction`), in time order.
fn event_rows(occurrences: &[Occurrence]) -> Vec<EventRow> {
    (occurrences.iter())
        .map(|o| (o.name.clone(), o.t, o.value, o.kind.name()))
        .collect()
}

/// Simulates a scene (a path or a dict) with the command line's `run` flags, and `moment` (a callable
/// f(t, q, omega_b) → 3 numbers, N·m in `moment_frame` axes) acting too. Returns the CSV's column names, the
/// rows as native-endian float64 bytes (row-major; empty with `rows=False`), the run's report (rows, steps,
/// rejected, evals, wall_seconds) and its located `[[event]]`s as (event, t, value, direction) tuples, the rows
/// of `FILE.events.csv`. Raises SceneError for bad input, RunError for a failed run (and for an exception in
/// `moment`, which is its cause), KeyboardInterrupt on Ctrl-C.
#[pyfunction]
#[pyo3(signature = (scene, *, method=None, frame=None, backend=None, rtol=None, atol=None, dt=None, t_end=None, every=None, moment=None, moment_frame=None, wheel_torque=None, rows=true))]
#[allow(clippy::too_many_arguments)]
#[allow(clippy::type_complexity)]
pub fn run<'py>(
    py: Python<'py>,
    scene: &Bound<'py, PyAny>,
    method: Option<String>,
    frame: Option<String>,
    backend: Option<String>,
    rtol: Option<f64>,
    atol: Option<f64>,
    dt: Option<f64>,
    t_end: Option<f64>,
    every: Option<f64>,
    moment: Option<Bound<'py, PyAny>>,
    moment_frame: Option<String>,
    wheel_torque: Option<Bound<'py, PyAny>>,
    rows: bool,
) -> PyResult<(
    Vec<String>,
    Bound<'py, PyBytes>,
    Bound<'py, PyDict>,
    Vec<EventRow>,
)> {
    let flags = Flags {
        method: method.as_deref(),
        frame: frame.as_deref(),
        backend: backend.as_deref(),
        rtol,
        atol,
        dt,
        t_end,
        every,
    };
    no_panic(|| {
        let input = SceneInput::from_py(scene)?;
        let overrides = flags
            .overrides(&input.path)
            .map_err(|e| input.error(py, e))?;
        let scene_model = input.scene(py, &overrides)?;
        let (scene_model, law) =
            with_laws(py, &input, scene_model, moment, moment_frame, wheel_torque)?;
        for warning in simulate::warnings_before_run(&scene_model) {
            warn(py, format!("{}: {warning}", input.path.display()))?;
        }
        let columns = scene_model.facts().columns();
        let names: Vec<String> = (columns.columns().into_iter())
            .map(|c| c.name.into_owned())
            .collect();
        let (result, bytes) = py.detach(|| simulate_rows(&scene_model, columns, rows));
        for (law, name, what) in &law {
            if let Some(failure) = law.failure() {
                let what = format!("the {what} function {name}()");
                return Err(law_error(py, &input.path, &what, failure));
            }
        }
        let (report, occurrences) = match result {
            Ok(done) => done,
            Err(RunError::Sink(Stop::Python(e))) => return Err(e),
            Err(RunError::Sink(stop)) => {
                let failed = RunFailed {
                    scene: input.path.clone(),
                    t: stop.time(),
                    reason: stop.to_string(),
                };
                return Err(run_error(py, &failed));
            }
            Err(e) => return Err(run_error(py, &RunFailed::new(&input.path, &e))),
        };
        if let Some(drift) = simulate::drift_warning(report.energy_drift) {
            warn(py, format!("{}: {drift}", input.path.display()))?;
        }
        Ok((
            names,
            PyBytes::new(py, &bytes),
            report_dict(py, &report)?,
            event_rows(&occurrences),
        ))
    })
}

/// A Python law, its name and its keyword (`moment`, `wheel_torque`).
pub type Laws = Vec<(Arc<PyLaw>, String, &'static str)>;

/// The scene with `moment` (a callable f(t, q, omega_b), its result in `moment_frame` axes) acting and
/// `wheel_torque` (a callable f(t, q, omega_b, spins)) commanding its wheels, and those laws.
pub fn with_laws(
    py: Python<'_>,
    input: &SceneInput,
    mut scene: Scene,
    moment: Option<Bound<'_, PyAny>>,
    moment_frame: Option<String>,
    wheel_torque: Option<Bound<'_, PyAny>>,
) -> PyResult<(Scene, Laws)> {
    let mut laws = Laws::new();
    if let Some(f) = moment {
        let law = PyLaw::new(f.clone().unbind());
        let name = law_name(&f, "moment", "f(t, q, omega_b) -> 3 numbers")?;
        let axes = moment_axes(moment_frame.as_deref())?;
        scene = (scene.with_moment(&name, axes, SharedLaw(law.clone())))
            .map_err(|inv| input.invalid(py, inv))?;
        laws.push((law, name, "moment"));
    }
    if let Some(f) = wheel_torque {
        let law = PyLaw::new(f.clone().unbind());
        let name = law_name(
            &f,
            "wheel_torque",
            "f(t, q, omega_b, spins) -> one torque per wheel",
        )?;
        scene = (scene.with_wheel_law(&name, SharedWheelLaw(law.clone())))
            .map_err(|inv| input.invalid(py, inv))?;
        laws.push((law, name, "wheel_torque"));
    }
    Ok((scene, laws))
}

/// The run's outcome (report and located events, or why it stopped).
type Outcome = Result<(RunReport, Vec<Occurrence>), RunError<Stop>>;

/// Runs the scene through [`simulate::run_with_events`] (the command line's `run`), its rows as native-endian
/// float64 bytes (row-major) when `rows`, only checked for finite values and Ctrl-C otherwise.
fn simulate_rows(scene: &Scene, columns: &ColumnSet, rows: bool) -> (Outcome, Vec<u8>) {
    let row_bytes = columns.columns().len() * size_of::<f64>();
    let mut bytes: Vec<u8> = Vec::new();
    // At most a million rows up front; more as they come, refused (not aborted) when memory runs out.
    if rows {
        let _ = bytes.try_reserve(scene.schedule.len().min(1 << 20) * row_bytes);
    }
    let mut values = Vec::new();
    let mut signals = SignalCheck::new();
    let result = simulate::run_with_events(scene, |s| {
        columns
            .finite_values(s, &mut values)
            .map_err(Stop::NonFinite)?;
        if rows {
            bytes
                .try_reserve(row_bytes)
                .map_err(|_| Stop::OutOfMemory { t: s.t })?;
            bytes.extend(values.iter().flat_map(|v| v.to_ne_bytes()));
        }
        signals.poll().map_err(Stop::Python)
    });
    (result, bytes)
}

/// What `check` and the sidecar call the callable given as `keyword` (`signature` what it should be): its
/// `__name__` (`python` without one).
pub fn law_name(f: &Bound<'_, PyAny>, keyword: &str, signature: &str) -> PyResult<String> {
    if !f.is_callable() {
        return Err(PyTypeError::new_err(format!(
            "{keyword}: expected a callable {signature}, got {}",
            f.get_type().name()?
        )));
    }
    Ok(f.getattr("__name__")
        .and_then(|n| n.extract::<String>())
        .unwrap_or_else(|_| "python".to_string()))
}

/// The axes of the callable's moment: `moment_frame`, `body` (default) or `space`.
pub fn moment_axes(frame: Option<&str>) -> PyResult<Axes> {
    Axes::parse(frame.unwrap_or("body"))
        .map_err(|e| PyValueError::new_err(format!("moment_frame: {e}")))
}

/// The error of a run stopped by its law (`what`: "the moment function f()"): Ctrl-C's KeyboardInterrupt as it
/// is; anything else as `RunError` naming the function, with its exception as the cause.
pub fn law_error(py: Python<'_>, scene: &Path, what: &str, failure: LawFailure) -> PyErr {
    if PyLaw::is_interrupt(py, &failure) {
        return failure.error;
    }
    let failed = RunFailed {
        scene: scene.to_path_buf(),
        t: Some(failure.t),
        reason: format!("{what} at t = {}: {}", failure.t, failure.error),
    };
    let err = run_error(py, &failed);
    err.set_cause(py, Some(failure.error));
    err
}

/// Issues a Python `UserWarning` (the command line prints the same text on stderr as `warning: …`).
pub fn warn(py: Python<'_>, message: String) -> PyResult<()> {
    let text = CString::new(message.replace('\0', " ")).unwrap_or_default();
    PyErr::warn(py, &py.get_type::<PyUserWarning>(), &text, 2)
}
