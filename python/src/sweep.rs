//! `sweep`: the runs of a sweep file, as `eulerdyn sweep SWEEP.toml [--jobs N] [--shard K/N]`, their results table
//! returned as CSV text.

use std::path::PathBuf;

use eulerdyn::analysis::sweep::{Shard, Sweep, SweepError, TableWriter};
use pyo3::exceptions::PyRuntimeError;
use pyo3::prelude::*;

use crate::errors::{SceneError, no_panic, scene_error};
use crate::run::SignalCheck;

/// Runs the sweep file at `sweep` (its base scene relative to it) on `jobs` threads (None: all cores), only the
/// runs of `shard` ("K/N") if given. Returns the results table as CSV text (the command's columns, one row per run,
/// sorted by run; a failed or invalid run is a row with its status and message). Raises SceneError for a bad
/// sweep file, a bad shard or jobs = 0, KeyboardInterrupt on Ctrl-C (between runs).
#[pyfunction]
#[pyo3(signature = (sweep, *, jobs=None, shard=None))]
pub fn sweep(
    py: Python<'_>,
    sweep: PathBuf,
    jobs: Option<usize>,
    shard: Option<String>,
) -> PyResult<String> {
    no_panic(|| {
        let plan = Sweep::load(&sweep).map_err(|e| scene_error(py, e, false))?;
        let shard = match shard {
            Some(text) => Shard::parse(&text).map_err(SceneError::new_err)?,
            None => Shard::ALL,
        };
        if jobs == Some(0) {
            return Err(SceneError::new_err("jobs = 0: give at least 1 thread"));
        }
        let result = py.detach(|| {
            let mut signals = SignalCheck::new();
            let mut table = TableWriter::new(Vec::new(), plan.layout().clone())
                .map_err(|e| SweepError::Deliver(PyRuntimeError::new_err(e.to_string())))?;
            plan.run_all(jobs.unwrap_or(0), shard, None, |outcome| {
                table
                    .write(outcome)
                    .map_err(|e| PyRuntimeError::new_err(e.to_string()))?;
                signals.poll()
            })?;
            table
                .finish()
                .map_err(|e| SweepError::Deliver(PyRuntimeError::new_err(e.to_string())))
        });
        match result {
            Ok(bytes) => {
                String::from_utf8(bytes).map_err(|e| PyRuntimeError::new_err(e.to_string()))
            }
            Err(SweepError::Deliver(e)) => Err(e),
            Err(SweepError::Threads(message)) => Err(PyRuntimeError::new_err(message)),
        }
    })
}
