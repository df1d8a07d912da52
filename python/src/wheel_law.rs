//! `run(scene, wheel_torque=f)`: a Python callable as the wheel law. f(t, q, omega_b, spins) with q = (w, x, y, z),
//! omega_b = (x, y, z) and spins (one per wheel, rad/s) as tuples of floats returns one commanded motor torque per
//! wheel (N·m), in the scene's order. What f raises, a result that is not one finite number per wheel, or a
//! KeyboardInterrupt is kept by the [`PyLaw`], the law then gives NaN torques, which stop the run, and the run's
//! caller raises it.

use std::sync::Arc;

use eulerdyn::wheels::{WheelInputs, WheelLaw};
use pyo3::exceptions::{PyTypeError, PyValueError};
use pyo3::prelude::*;

use crate::moment::{PyLaw, describe};

/// The law as the scene holds it, shared with the caller that reads its failure.
pub struct SharedWheelLaw(pub Arc<PyLaw>);

impl WheelLaw for SharedWheelLaw {
    fn torques(&self, now: &WheelInputs<'_>) -> Vec<f64> {
        let WheelInputs {
            t,
            q,
            omega_b,
            spins,
        } = *now;
        let n = spins.len();
        self.0.guarded(t, vec![f64::NAN; n], || {
            Python::attach(|py| {
                py.check_signals()?;
                let q = (q.w, q.i, q.j, q.k);
                let omega = (omega_b.x, omega_b.y, omega_b.z);
                let spins = pyo3::types::PyTuple::new(py, spins)?;
                let result = self.0.function().call1(py, (t, q, omega, spins))?;
                torques_of(result.bind(py), n)
            })
        })
    }
}

/// One finite number per wheel, or a TypeError/ValueError that says what f returned instead.
fn torques_of(result: &Bound<'_, PyAny>, n: usize) -> PyResult<Vec<f64>> {
    let what = format!(
        "the wheel_torque function must return {n} numbers (one motor torque per wheel, in N*m)"
    );
    let values: Vec<f64> = result
        .extract()
        .map_err(|_| PyTypeError::new_err(format!("{what}, got {}", describe(result))))?;
    if values.len() != n {
        return Err(PyValueError::new_err(format!(
            "{what}, got {} numbers",
            values.len()
        )));
    }
    if !values.iter().all(|v| v.is_finite()) {
        return Err(PyValueError::new_err(format!(
            "the wheel_torque function returned a non-finite torque {values:?}"
        )));
    }
    Ok(values)
}
