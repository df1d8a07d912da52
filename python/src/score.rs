//! `eulerdyn.score`: another program's trajectory against the referee, the dict `eulerdyn score THEIRS.csv --scene
//! SCENE --json` prints (with `--diagnose`, its `diagnosis`).

use std::path::PathBuf;

use pyo3::prelude::*;

use eulerdyn::analysis::score::{QuaternionOrder, ReadOptions, ScoreError, score_with};
use eulerdyn::frames::Axes;
use eulerdyn::scene::Overrides;

use crate::convert::json_to_py;
use crate::errors::{RunError, SceneError, no_panic};
use crate::input::SceneInput;

/// The score of the trajectory in the CSV `theirs` against the scene (a path or a dict), as the command's `--json`
/// gives it. `quaternion` ("wxyz" or "xyzw"), `omega` ("body" or "space") and `map` (pairs NAME, COLUMN) are the
/// command's `--quaternion`, `--omega` and `--map`. Raises SceneError for bad input (exit 2 of the command),
/// RunError when the referee's run fails.
#[pyfunction]
#[pyo3(signature = (theirs, scene, *, diagnose=false, quaternion="wxyz", omega="body", map=None))]
pub fn score<'py>(
    py: Python<'py>,
    theirs: PathBuf,
    scene: &Bound<'py, PyAny>,
    diagnose: bool,
    quaternion: &str,
    omega: &str,
    map: Option<Vec<(String, String)>>,
) -> PyResult<Bound<'py, PyAny>> {
    no_panic(|| {
        let options = read_options(quaternion, omega, map)?;
        let scene = SceneInput::from_py(scene)?.scene(py, &Overrides::default())?;
        let result = score_with(&theirs, &scene, &options, diagnose).map_err(|e| match e {
            ScoreError::Input(m) => SceneError::new_err(m),
            ScoreError::Run(m) => RunError::new_err(m),
        })?;
        let value = serde_json::to_value(&result)
            .map_err(|e| RunError::new_err(format!("the score as JSON: {e}")))?;
        json_to_py(py, &value)
    })
}

/// The reading options of the keywords `quaternion` ("wxyz" or "xyzw"), `omega` ("body" or "space") and `map`, as
/// the command's `--quaternion`, `--omega` and `--map`; another value raises SceneError.
pub fn read_options(
    quaternion: &str,
    omega: &str,
    map: Option<Vec<(String, String)>>,
) -> PyResult<ReadOptions> {
    let quaternion = match quaternion {
        "wxyz" => QuaternionOrder::Wxyz,
        "xyzw" => QuaternionOrder::Xyzw,
        other => {
            return Err(SceneError::new_err(format!(
                "quaternion={other:?}: give \"wxyz\" or \"xyzw\""
            )));
        }
    };
    let omega = match omega {
        "body" => Axes::Body,
        "space" => Axes::Space,
        other => {
            return Err(SceneError::new_err(format!(
                "omega={other:?}: give \"body\" or \"space\""
            )));
        }
    };
    Ok(ReadOptions {
        quaternion,
        omega: Some(omega),
        map: map.unwrap_or_default(),
    })
}
