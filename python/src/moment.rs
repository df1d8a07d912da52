//! `run(scene, moment=f, moment_frame=…)`: a Python callable as the user's moment law. The run releases the GIL;
//! the law takes it back for every call, runs Python's signal handlers first (Ctrl-C), and calls
//! f(t, q, omega_b) with q = (w, x, y, z) and omega_b = (x, y, z) as tuples of floats. What f raises, a result that
//! is not 3 finite numbers, or a KeyboardInterrupt is kept: the law then gives a non-finite moment, which stops the
//! run, and the run's caller raises it ([`PyLaw::failure`]).

use std::sync::{Arc, Mutex};

use eulerdyn::effects::MomentLaw;
use nalgebra::{UnitQuaternion, Vector3};
use pyo3::exceptions::{PyKeyboardInterrupt, PyTypeError, PyValueError};
use pyo3::prelude::*;

/// Why the law stopped the run: the exception (f's own, its result's, or a signal handler's) and the time of the
/// call.
pub struct LawFailure {
    pub error: PyErr,
    pub t: f64,
}

/// A Python callable f(t, q, omega_b) → 3 numbers (N·m) and the first failure of its calls.
pub struct PyLaw {
    function: Py<PyAny>,
    failure: Mutex<Option<LawFailure>>,
}

impl PyLaw {
    /// The law of `function`, shared with the scene that calls it.
    pub fn new(function: Py<PyAny>) -> Arc<Self> {
        Arc::new(Self {
            function,
            failure: Mutex::new(None),
        })
    }

    /// The first failure of the law's calls, if any (taken out).
    pub fn failure(&self) -> Option<LawFailure> {
        self.failure.lock().ok()?.take()
    }

    /// Whether the failure is Ctrl-C's KeyboardInterrupt (raised as it is, not as a RunError).
    pub fn is_interrupt(py: Python<'_>, failure: &LawFailure) -> bool {
        failure.error.is_instance_of::<PyKeyboardInterrupt>(py)
    }

    /// One call of f with the GIL: signals first, then f(t, q, omega_b), its result checked.
    fn call(
        &self,
        t: f64,
        q: &UnitQuaternion<f64>,
        omega_b: &Vector3<f64>,
    ) -> PyResult<Vector3<f64>> {
        Python::attach(|py| {
            py.check_signals()?;
            let q = (q.w, q.i, q.j, q.k);
            let omega = (omega_b.x, omega_b.y, omega_b.z);
            let result = self.function.call1(py, (t, q, omega))?;
            moment_of(result.bind(py))
        })
    }
}

/// The 3 finite numbers f returned, or a TypeError/ValueError that says what it returned instead.
fn moment_of(result: &Bound<'_, PyAny>) -> PyResult<Vector3<f64>> {
    let values: Vec<f64> = result.extract().map_err(|_| {
        PyTypeError::new_err(format!(
            "the moment function must return 3 numbers (M_x, M_y, M_z in N*m), got {}",
            describe(result)
        ))
    })?;
    let [x, y, z] = <[f64; 3]>::try_from(values.as_slice()).map_err(|_| {
        PyValueError::new_err(format!(
            "the moment function must return 3 numbers (M_x, M_y, M_z in N*m), got {} numbers",
            values.len()
        ))
    })?;
    if ![x, y, z].iter().all(|v| v.is_finite()) {
        return Err(PyValueError::new_err(format!(
            "the moment function returned a non-finite moment ({x}, {y}, {z})"
        )));
    }
    Ok(Vector3::new(x, y, z))
}

/// A value's repr and type, for a message.
pub fn describe(value: &Bound<'_, PyAny>) -> String {
    let repr = value.repr().map(|r| r.to_string()).unwrap_or_default();
    let kind = value
        .get_type()
        .name()
        .map(|n| n.to_string())
        .unwrap_or_default();
    format!("{repr} (a {kind})")
}

impl PyLaw {
    /// The result of `call` at time `t`; after a failure (kept for the caller) `nan`, which stops the run.
    pub fn guarded<T>(&self, t: f64, nan: T, call: impl FnOnce() -> PyResult<T>) -> T {
        let Ok(mut failure) = self.failure.lock() else {
            return nan;
        };
        if failure.is_some() {
            return nan;
        }
        // The lock is held during the call: the law is called from one thread at a time anyway.
        match call() {
            Ok(m) => m,
            Err(error) => {
                *failure = Some(LawFailure { error, t });
                nan
            }
        }
    }

    /// The Python callable.
    pub fn function(&self) -> &Py<PyAny> {
        &self.function
    }
}

impl MomentLaw for PyLaw {
    /// f's moment; after a failure (kept for the caller) NaN, which stops the run.
    fn moment(&self, t: f64, q: &UnitQuaternion<f64>, omega_b: &Vector3<f64>) -> Vector3<f64> {
        self.guarded(t, Vector3::repeat(f64::NAN), || self.call(t, q, omega_b))
    }
}

/// The law as the scene holds it: `Arc<PyLaw>` shared between the scene and the caller that reads its failure.
pub struct SharedLaw(pub Arc<PyLaw>);

impl MomentLaw for SharedLaw {
    fn moment(&self, t: f64, q: &UnitQuaternion<f64>, omega_b: &Vector3<f64>) -> Vector3<f64> {
        self.0.moment(t, q, omega_b)
    }
}
