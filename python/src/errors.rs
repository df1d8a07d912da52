//! The module's exceptions, their attributes, and the catching of panics.

use std::panic::{AssertUnwindSafe, catch_unwind};

use eulerdyn::scene;
use eulerdyn::simulate::RunFailed;
use pyo3::create_exception;
use pyo3::exceptions::{PyRuntimeError, PyValueError};
use pyo3::prelude::*;

create_exception!(
    eulerdyn,
    SceneError,
    PyValueError,
    "A scene (or an argument) that is not valid. The message is the command line's: the file (or `<dict>`), the \
     key and what is wrong. Attributes: `file`, `key` (e.g. `body.mass`, or None), `line` and `column` (None for \
     a dict), `problem`."
);
create_exception!(
    eulerdyn,
    RunError,
    PyRuntimeError,
    "A run that failed (it diverged, its step size collapsed, a value became non-finite). The message is the \
     command line's. Attributes: `scene`, `t` (the time the run stopped at, s, or None), `reason`."
);

/// The `SceneError` exception for the library's error; `from_dict` drops the line and column (they would point
/// into TOML text the user never saw). A key set by a keyword argument is named by it, as Python calls it:
/// `solver.dt (from dt=)` where the command line says `solver.dt (from --dt)`.
pub fn scene_error(py: Python<'_>, mut e: scene::SceneError, from_dict: bool) -> PyErr {
    if from_dict {
        e.location = None;
    }
    e.key = e.key.map(|key| keyword_key(&key));
    let err = SceneError::new_err(e.to_string());
    let value = err.value(py);
    let set = value
        .setattr("file", e.file.display().to_string())
        .and_then(|()| value.setattr("key", e.key.clone()))
        .and_then(|()| value.setattr("line", e.location.map(|l| l.0)))
        .and_then(|()| value.setattr("column", e.location.map(|l| l.1)))
        .and_then(|()| value.setattr("problem", e.problem.clone()));
    match set {
        Ok(()) => err,
        Err(e) => e,
    }
}

/// A key as Python names it: `solver.t_end (from --t-end)` (the command line's flag) becomes
/// `solver.t_end (from t_end=)` (the keyword argument that set it); any other key is unchanged.
fn keyword_key(key: &str) -> String {
    match key
        .strip_suffix(')')
        .and_then(|rest| rest.rsplit_once(" (from --"))
    {
        Some((path, flag)) => format!("{path} (from {}=)", flag.replace('-', "_")),
        None => key.to_string(),
    }
}

/// The `RunError` exception for a failed run.
pub fn run_error(py: Python<'_>, failed: &RunFailed) -> PyErr {
    run_error_message(py, failed.to_string(), failed)
}

/// The `RunError` exception with the command line's `message` (when it is not [`RunFailed`]'s own).
pub fn run_error_message(py: Python<'_>, message: String, failed: &RunFailed) -> PyErr {
    let err = RunError::new_err(message);
    let value = err.value(py);
    let set = value
        .setattr("scene", failed.scene.display().to_string())
        .and_then(|()| value.setattr("t", failed.t))
        .and_then(|()| value.setattr("reason", failed.reason.clone()));
    match set {
        Ok(()) => err,
        Err(e) => e,
    }
}

/// Runs `work`, turning a panic into `RunError` ("internal error …") instead of pyo3's `PanicException`.
pub fn no_panic<T>(work: impl FnOnce() -> PyResult<T>) -> PyResult<T> {
    catch_unwind(AssertUnwindSafe(work)).unwrap_or_else(|payload| {
        let what = payload
            .downcast_ref::<&str>()
            .map(|s| s.to_string())
            .or_else(|| payload.downcast_ref::<String>().cloned())
            .unwrap_or_else(|| "a panic".into());
        Err(RunError::new_err(format!(
            "internal error in eulerdyn (please report it with the scene): {what}"
        )))
    })
}
