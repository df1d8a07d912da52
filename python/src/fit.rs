//! `eulerdyn.fit`: a body from its measured motion, the dict `eulerdyn fit MEASURED.csv --scene SCENE --estimate
//! LIST --json` prints.

use std::path::PathBuf;

use pyo3::prelude::*;

use eulerdyn::analysis::fit::{FitError, FitOptions, fit_file, parse_estimates};
use eulerdyn::scene::Overrides;

use crate::convert::json_to_py;
use crate::errors::{RunError, SceneError, no_panic};
use crate::input::SceneInput;
use crate::run::{law_error, with_laws};
use crate::score::read_options;

/// The fit of the scene (a path or a dict) to the measured motion in the CSV `measured`, as the command's `--json`
/// gives it. `estimate` lists the parameter groups; `sigma_omega`, `sigma_attitude`, `quaternion` ("wxyz" or
/// "xyzw"), `omega` ("body" or "space") and `map` (pairs NAME, COLUMN) are the command's options. Raises SceneError
/// for bad input (exit 2 of the command), RunError when the model cannot be run at the scene's start; a fit that
/// does not converge or whose inertia is not a body is returned with `converged` false or `unphysical` set.
/// `moment`, `moment_frame` and `wheel_torque` are `run`'s: the laws act in the fit's model as in the run.
#[pyfunction]
#[pyo3(signature = (measured, scene, *, estimate, sigma_omega=None, sigma_attitude=None, quaternion="wxyz", omega="body", map=None, moment=None, moment_frame=None, wheel_torque=None))]
#[allow(clippy::too_many_arguments)]
pub fn fit<'py>(
    py: Python<'py>,
    measured: PathBuf,
    scene: &Bound<'py, PyAny>,
    estimate: Vec<String>,
    sigma_omega: Option<f64>,
    sigma_attitude: Option<f64>,
    quaternion: &str,
    omega: &str,
    map: Option<Vec<(String, String)>>,
    moment: Option<Bound<'py, PyAny>>,
    moment_frame: Option<String>,
    wheel_torque: Option<Bound<'py, PyAny>>,
) -> PyResult<Bound<'py, PyAny>> {
    no_panic(|| {
        let fail = |e: FitError| match e {
            FitError::Input(m) => SceneError::new_err(m),
            FitError::Run(m) => RunError::new_err(m),
        };
        let options = FitOptions {
            estimates: parse_estimates(&estimate.join(",")).map_err(fail)?,
            sigma_omega,
            sigma_attitude,
            read: read_options(quaternion, omega, map)?,
        };
        let input = SceneInput::from_py(scene)?;
        let scene = input.scene(py, &Overrides::default())?;
        let (scene, laws) = with_laws(py, &input, scene, moment, moment_frame, wheel_torque)?;
        let result = py.detach(|| fit_file(&measured, &scene, &options));
        for (law, name, what) in &laws {
            if let Some(failure) = law.failure() {
                let what = format!("the {what} function {name}()");
                return Err(law_error(py, &input.path, &what, failure));
            }
        }
        let result = result.map_err(fail)?;
        let value = serde_json::to_value(&result)
            .map_err(|e| RunError::new_err(format!("the fit as JSON: {e}")))?;
        json_to_py(py, &value)
    })
}
