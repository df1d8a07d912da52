//! `check`, `compare`, `accuracy` and `balance`: the commands of the same names, as dicts and CSV text.

use std::path::PathBuf;

use eulerdyn::analysis::balance::{
    Planes, Readings, Request, RequestError, TolerancePlanes, balance_report, table,
};
use eulerdyn::analysis::compare::{Comparison, compare_until};
use eulerdyn::analysis::describe::describe;
use eulerdyn::analysis::study::{self, StudyError, StudyOptions};
use eulerdyn::scene::{Flags, Overrides, SceneError};
use eulerdyn::simulate::RunFailed;
use pyo3::prelude::*;
use pyo3::types::{PyDict, PyList};

use crate::convert::{json_to_py, toml_to_py};
use crate::errors::{no_panic, run_error, run_error_message, scene_error};
use crate::input::SceneInput;
use crate::run::{SignalCheck, stop_on};

/// What `eulerdyn check` prints about a scene (a path or a dict), as a dict: `text` (the printout), `items` (each
/// label with its lines; a `warning` item for each warning), the settings as values: name, description, motion,
/// method, frame, backend, rtol, atol, dt, t_end, every, rows, columns; and `facts`, the scene's facts as the
/// sidecar writes them (invariants, closed_form, panels, check: the numbers at full precision). Raises
/// SceneError for bad input.
#[pyfunction]
pub fn check<'py>(py: Python<'py>, scene: &Bound<'py, PyAny>) -> PyResult<Bound<'py, PyDict>> {
    no_panic(|| {
        let input = SceneInput::from_py(scene)?;
        let s = input.scene(py, &Overrides::default())?;
        let warnings = eulerdyn::scene::advice::warnings(&s);
        let description = describe(&s, &warnings);
        let d = PyDict::new(py);
        d.set_item("text", description.text())?;
        let items = PyDict::new(py);
        for (label, lines) in description.items() {
            match items.get_item(label)? {
                Some(earlier) => {
                    let earlier = earlier.cast::<PyList>()?;
                    for line in lines {
                        earlier.append(line)?;
                    }
                }
                None => items.set_item(label, PyList::new(py, lines)?)?,
            }
        }
        d.set_item("items", items)?;
        d.set_item("name", &s.name)?;
        d.set_item("description", &s.description)?;
        let facts = serde_json::to_value(s.facts()).map_err(|e| {
            pyo3::exceptions::PyRuntimeError::new_err(format!("the scene's facts: {e}"))
        })?;
        d.set_item("motion", json_to_py(py, &facts["check"]["motion"])?)?;
        d.set_item("facts", json_to_py(py, &facts)?)?;
        let solver = &s.solver;
        d.set_item("method", solver.method.name())?;
        d.set_item("frame", solver.form.name())?;
        d.set_item("backend", solver.backend.name())?;
        d.set_item("rtol", solver.rtol)?;
        d.set_item("atol", solver.atol)?;
        d.set_item("dt", solver.dt)?;
        d.set_item("t_end", solver.t_end)?;
        d.set_item("every", s.schedule.every())?;
        d.set_item("rows", s.schedule.len())?;
        let columns: Vec<String> = (s.facts().columns().columns().into_iter())
            .map(|c| c.name.into_owned())
            .collect();
        d.set_item("columns", columns)?;
        Ok(d)
    })
}

/// The comparison as a dict: text (what `eulerdyn compare` prints), passes, tolerance, rows, closed_form (its name
/// or None), note, and table: (quantity, body_vs_space, body_vs_exact, space_vs_exact) per quantity.
fn comparison_dict<'py>(py: Python<'py>, c: &Comparison) -> PyResult<Bound<'py, PyDict>> {
    let d = PyDict::new(py);
    d.set_item("text", c.report())?;
    d.set_item("passes", c.passes())?;
    d.set_item("tolerance", c.tolerance)?;
    d.set_item("rows", c.rows)?;
    d.set_item("closed_form", c.exact.as_ref().map(|e| e.0))?;
    d.set_item("note", c.note.clone())?;
    let table: Vec<_> = c
        .table()
        .iter()
        .map(|r| {
            (
                r.quantity,
                r.body_vs_space,
                r.body_vs_exact,
                r.space_vs_exact,
            )
        })
        .collect();
    d.set_item("table", table)?;
    Ok(d)
}

/// Runs a scene (a path or a dict) in both forms of Euler's equation and against its closed form, as `eulerdyn
/// compare` (with its `--method`). Returns a dict (see `comparison_dict`); `passes` is False where the command
/// exits 1. Raises SceneError for bad input, RunError for a failed run.
#[pyfunction]
#[pyo3(signature = (scene, *, method=None))]
pub fn compare<'py>(
    py: Python<'py>,
    scene: &Bound<'py, PyAny>,
    method: Option<String>,
) -> PyResult<Bound<'py, PyDict>> {
    no_panic(|| {
        let input = SceneInput::from_py(scene)?;
        let flags = Flags {
            method: method.as_deref(),
            ..Flags::default()
        };
        let overrides = flags
            .overrides(&input.path)
            .map_err(|e| input.error(py, e))?;
        let s = input.scene(py, &overrides)?;
        let (result, interrupted) = py.detach(|| {
            let mut signals = SignalCheck::new();
            let mut interrupted = None;
            let result = compare_until(&s, || stop_on(signals.poll(), &mut interrupted));
            (result, interrupted)
        });
        if let Some(interrupt) = interrupted {
            return Err(interrupt);
        }
        let comparison = result.map_err(|e| run_error(py, &RunFailed::new(&input.path, &e)))?;
        comparison_dict(py, &comparison)
    })
}

/// The study's error as Python's: bad input (the command line's exit 2) as SceneError, a failed reference run as
/// RunError.
fn study_error(py: Python<'_>, input: &SceneInput, e: StudyError) -> PyErr {
    let message = e.to_string();
    match e {
        StudyError::Scene(e) => input.error(py, e),
        StudyError::Unsuitable { file, problem } => input.error(
            py,
            SceneError {
                file,
                key: None,
                location: None,
                problem,
            },
        ),
        StudyError::Reference { file, problem } | StudyError::Output { file, problem, .. } => {
            let failed = RunFailed {
                scene: file,
                t: None,
                reason: problem,
            };
            run_error_message(py, message, &failed)
        }
        StudyError::Interrupted { file } => {
            let failed = RunFailed {
                scene: file,
                t: None,
                reason: "interrupted".into(),
            };
            run_error_message(py, message, &failed)
        }
    }
}

/// The work-precision study of a scene (a path or a dict), as `eulerdyn accuracy`; `quick` runs the library's
/// quick study (4 tolerances, 4 step sizes, one repeat, own backend, body form) instead of the full one. Returns
/// the table as CSV text (the command's columns) and the summary the command prints. Raises SceneError for a scene
/// the study cannot use, RunError when the reference run fails, KeyboardInterrupt on Ctrl-C (between runs).
#[pyfunction]
#[pyo3(signature = (scene, *, quick=false))]
pub fn accuracy(
    py: Python<'_>,
    scene: &Bound<'_, PyAny>,
    quick: bool,
) -> PyResult<(String, String)> {
    no_panic(|| {
        let input = SceneInput::from_py(scene)?;
        let options = if quick {
            StudyOptions::quick()
        } else {
            StudyOptions::default()
        };
        let scene = input.scene(py, &Overrides::default())?;
        let result = py.detach(|| {
            let mut signals = SignalCheck::new();
            let mut interrupted = None;
            let study = study::accuracy_until(&scene, &options, |_, _, _| {
                stop_on(signals.poll(), &mut interrupted)
            });
            (study, interrupted)
        });
        match result {
            (_, Some(interrupt)) => Err(interrupt),
            (Ok(study), None) => Ok((study.table_csv(), study.summary())),
            (Err(e), None) => Err(study_error(py, &input, e)),
        }
    })
}

/// Two-plane balancing of a fixed-axis or hinge scene (a path or a dict), as `eulerdyn balance --planes A,B
/// --radius R [--grade G] [--service-rpm N] [--rpm N] [--tolerance-planes bearings|correction] [--measured
/// PHASORS.csv [--readings force|other]]`. Returns a dict: every key of `--json` (mode, planes, corrections (per
/// plane: plane, z, mass_g, angle_deg in [0, 360), at_b), unbalance_gmm, grade, influence, warnings, …), and text
/// (what the command prints), scene (the balanced scene as a dict) and toml (it as a scene file). Raises
/// SceneError for bad input or a scene that cannot be balanced.
#[pyfunction]
#[pyo3(signature = (scene, *, planes, radius, grade=None, rpm=None, measured=None, service_rpm=None,
                    tolerance_planes="bearings", readings="force"))]
#[allow(clippy::too_many_arguments)]
pub fn balance<'py>(
    py: Python<'py>,
    scene: &Bound<'py, PyAny>,
    planes: (f64, f64),
    radius: f64,
    grade: Option<f64>,
    rpm: Option<f64>,
    measured: Option<PathBuf>,
    service_rpm: Option<f64>,
    tolerance_planes: &str,
    readings: &str,
) -> PyResult<Bound<'py, PyDict>> {
    no_panic(|| {
        let tolerance_planes = match tolerance_planes {
            "bearings" => TolerancePlanes::Bearings,
            "correction" => TolerancePlanes::Correction,
            other => {
                return Err(crate::errors::SceneError::new_err(format!(
                    "tolerance_planes={other:?}: give \"bearings\" or \"correction\""
                )));
            }
        };
        let readings = match readings {
            "force" => Readings::Force,
            "other" => Readings::Other,
            other => {
                return Err(crate::errors::SceneError::new_err(format!(
                    "readings={other:?}: give \"force\" or \"other\""
                )));
            }
        };
        let input = SceneInput::from_py(scene)?;
        let measured = match measured {
            Some(path) => {
                let text = table::read(&path).map_err(|e| scene_error(py, e, false))?;
                Some((path, text))
            }
            None => None,
        };
        let request = Request {
            planes: Planes {
                a: planes.0,
                b: planes.1,
                radius,
            },
            grade,
            rpm,
            service_rpm,
            tolerance_planes,
            readings,
            measured,
        };
        let scene = input.scene(py, &Overrides::default())?;
        let report = balance_report(&scene, &request).map_err(|e| match e {
            RequestError::Option(message) => crate::errors::SceneError::new_err(message),
            RequestError::Scene(e) => input.error(py, e),
            RequestError::Table(e) => scene_error(py, e, false),
        })?;
        let d = json_to_py(py, &report.json())?.cast_into::<PyDict>()?;
        d.set_item("text", report.text())?;
        let result = &report.balance;
        let toml_text = result
            .balanced_toml()
            .map_err(crate::errors::RunError::new_err)?;
        let value = toml::Value::try_from(&result.balanced)
            .map_err(|e| crate::errors::RunError::new_err(e.to_string()))?;
        d.set_item("scene", toml_to_py(py, &value)?)?;
        d.set_item("toml", toml_text)?;
        Ok(d)
    })
}
