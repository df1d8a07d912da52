//! `eulerdyn._eulerdyn`: the eulerdyn library for Python, one function per command of the command line (`run`,
//! `check`, `compare`, `accuracy`, `balance`, `score`, `fit`, `sweep`, `plot`, `view`). Each takes a scene file's path or a dict of the same keys, calls the
//! library (nothing is computed here), and returns plain Python data that `eulerdyn/__init__.py` turns into pandas
//! DataFrames.
//!
//! Bad input raises `eulerdyn.SceneError` (a `ValueError`) with the command line's message; a run that fails
//! raises `eulerdyn.RunError` with the time and the reason. Runs release the GIL and look for Ctrl-C
//! (KeyboardInterrupt) a few times a second. A panic in the library is caught and raised as `RunError`, never as
//! pyo3's `PanicException`.

mod commands;
mod convert;
mod errors;
mod figures;
mod fit;
mod input;
mod moment;
mod run;
mod score;
mod sweep;
mod wheel_law;

use pyo3::prelude::*;

/// The extension module: its functions, exceptions and `__version__` (the eulerdyn crate's).
#[pymodule]
fn _eulerdyn(m: &Bound<'_, PyModule>) -> PyResult<()> {
    let py = m.py();
    m.add("__version__", eulerdyn::VERSION)?;
    m.add("SceneError", py.get_type::<errors::SceneError>())?;
    m.add("RunError", py.get_type::<errors::RunError>())?;
    m.add_function(wrap_pyfunction!(run::run, m)?)?;
    m.add_function(wrap_pyfunction!(commands::check, m)?)?;
    m.add_function(wrap_pyfunction!(commands::compare, m)?)?;
    m.add_function(wrap_pyfunction!(commands::accuracy, m)?)?;
    m.add_function(wrap_pyfunction!(commands::balance, m)?)?;
    m.add_function(wrap_pyfunction!(score::score, m)?)?;
    m.add_function(wrap_pyfunction!(fit::fit, m)?)?;
    m.add_function(wrap_pyfunction!(sweep::sweep, m)?)?;
    m.add_function(wrap_pyfunction!(figures::plot, m)?)?;
    m.add_function(wrap_pyfunction!(figures::view, m)?)?;
    m.add_function(wrap_pyfunction!(figures::run_to_csv, m)?)?;
    Ok(())
}
