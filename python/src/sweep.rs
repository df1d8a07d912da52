//! `sweep`: the runs of a sweep (a sweep file's path, or a dict of its keys), as `eulerdyn sweep SWEEP.toml
//! [--jobs N] [--shard K/N]`, their results table returned as CSV text.

use std::path::{Path, PathBuf};

use eulerdyn::analysis::sweep::{Shard, Sweep, SweepError, TableWriter};
use eulerdyn::scene;
use pyo3::exceptions::PyRuntimeError;
use pyo3::prelude::*;
use pyo3::types::PyDict;
use tempfile::TempDir;

use crate::errors::{SceneError, no_panic, scene_error};
use crate::input::{DICT_ORIGIN, dict_error, path_of, table_of, type_name};
use crate::moment::{PyLaw, SharedLaw};
use crate::run::{Laws, SignalCheck, law_error, law_name, moment_axes};
use crate::wheel_law::SharedWheelLaw;

/// A sweep given as a dict, written out as the files the library's [`Sweep::load`] reads: the sweep's keys as
/// `sweep.toml` and, when `scene` is a dict, the base scene as `scene.toml`, in a temporary directory that lives
/// as long as the sweep runs. Their messages name `<dict>` and the key within the dict (`vary[0].key`,
/// `scene.body.mass`), without a line and column.
struct StagedSweep {
    dir: TempDir,
    /// Whether the base scene was a dict (written as `scene.toml`) rather than a path.
    scene_from_dict: bool,
}

impl StagedSweep {
    /// Writes the dict's sweep (and its base scene, when a dict) as TOML files. The `scene` key is the base
    /// scene: a dict of a scene file's keys, or a path (str or os.PathLike, relative to the working directory).
    fn stage(dict: &Bound<'_, PyDict>) -> PyResult<Self> {
        let py = dict.py();
        let dir = tempfile::tempdir().map_err(|e| {
            PyRuntimeError::new_err(format!("a temporary directory for the sweep: {e}"))
        })?;
        let keys = dict.copy()?;
        let scene = dict.get_item("scene")?;
        if scene.is_some() {
            keys.del_item("scene")?;
        }
        let mut sweep = table_of(&keys, "")?;
        let scene_from_dict = scene.as_ref().is_some_and(|s| s.is_instance_of::<PyDict>());
        let scene_file = match scene {
            Some(s) if scene_from_dict => {
                let table = table_of(s.cast::<PyDict>()?, "scene")?;
                let path = dir.path().join("scene.toml");
                write_toml(py, &path, &table, "scene")?;
                Some(path)
            }
            Some(s) => Some(base_scene_path(&s)?),
            None => None,
        };
        if let Some(path) = scene_file {
            let text = path.to_string_lossy().into_owned();
            sweep.insert("scene".into(), toml::Value::String(text));
        }
        write_toml(py, &dir.path().join("sweep.toml"), &sweep, "")?;
        Ok(Self {
            dir,
            scene_from_dict,
        })
    }

    /// The sweep file written.
    fn sweep_file(&self) -> PathBuf {
        self.dir.path().join("sweep.toml")
    }

    /// The library's error about a written file as the dict's: `<dict>`, the key within the dict (the base
    /// scene's under `scene.`), no line and column. An error about a scene file the dict names is unchanged.
    fn error(&self, py: Python<'_>, mut e: scene::SceneError) -> PyErr {
        if e.file == self.sweep_file() {
            e.file = PathBuf::from(DICT_ORIGIN);
            return scene_error(py, e, true);
        }
        if self.scene_from_dict && e.file == self.dir.path().join("scene.toml") {
            e.file = PathBuf::from(DICT_ORIGIN);
            e.key = Some(
                e.key
                    .map_or_else(|| "scene".into(), |k| format!("scene.{k}")),
            );
            return scene_error(py, e, true);
        }
        scene_error(py, e, false)
    }
}

/// The base scene's path of a dict sweep's `scene`, made absolute (the sweep file that names it is elsewhere).
fn base_scene_path(scene: &Bound<'_, PyAny>) -> PyResult<PathBuf> {
    let path: PathBuf = scene.extract().map_err(|_| {
        let problem = format!(
            "expected the base scene: a scene file's path (str or os.PathLike) or a dict of its keys; got {}",
            type_name(scene)
        );
        dict_error(scene.py(), Some("scene"), problem)
    })?;
    std::path::absolute(&path).map_err(|e| {
        dict_error(
            scene.py(),
            Some("scene"),
            format!("{}: {e}", path.display()),
        )
    })
}

/// Writes a table as a TOML file; `key` names the dict it came from in the message.
fn write_toml(py: Python<'_>, path: &Path, table: &toml::Table, key: &str) -> PyResult<()> {
    let text = toml::to_string(table).map_err(|e| {
        let problem = format!("cannot be written as TOML: {e}");
        dict_error(py, (!key.is_empty()).then_some(key), problem)
    })?;
    std::fs::write(path, text)
        .map_err(|e| PyRuntimeError::new_err(format!("{}: {e}", path.display())))
}

/// The loaded sweep of a path or a dict, and the staged files of a dict (kept while the sweep runs).
fn load(py: Python<'_>, sweep: &Bound<'_, PyAny>) -> PyResult<(Sweep, Option<StagedSweep>)> {
    if let Ok(dict) = sweep.cast::<PyDict>() {
        let staged = StagedSweep::stage(dict)?;
        let plan = Sweep::load(&staged.sweep_file()).map_err(|e| staged.error(py, e))?;
        return Ok((plan, Some(staged)));
    }
    let path = path_of(sweep, "sweep")?;
    let plan = Sweep::load(&path).map_err(|e| scene_error(py, e, false))?;
    Ok((plan, None))
}

/// Runs the sweep `sweep` (a sweep file's path, its base scene relative to it; or a dict of its keys, its
/// `scene` a path or a dict) on `jobs` threads (None: all cores), only the runs of `shard` ("K/N") if given.
/// Returns the results table as CSV text (the command's columns, one row per run, sorted by run; a failed or
/// invalid run is a row with its status and message). Raises SceneError for a bad sweep, a bad shard or
/// jobs = 0, KeyboardInterrupt on Ctrl-C (between runs).
///
/// `moment` (f(t, q, omega_b) → 3 numbers, in `moment_frame` axes) acts in every run and `wheel_torque`
/// (f(t, q, omega_b, spins) → one torque per wheel) commands every run's wheels, as in `run`; an exception in either
/// stops the sweep's runs and is raised as RunError naming the function.
#[pyfunction]
#[pyo3(signature = (sweep, *, jobs=None, shard=None, moment=None, moment_frame=None, wheel_torque=None))]
#[allow(clippy::too_many_arguments)]
pub fn sweep(
    py: Python<'_>,
    sweep: &Bound<'_, PyAny>,
    jobs: Option<usize>,
    shard: Option<String>,
    moment: Option<Bound<'_, PyAny>>,
    moment_frame: Option<String>,
    wheel_torque: Option<Bound<'_, PyAny>>,
) -> PyResult<String> {
    no_panic(|| {
        let (plan, _staged) = load(py, sweep)?;
        for warning in plan.warnings() {
            crate::run::warn(py, format!("{}: {warning}", plan.file.display()))?;
        }
        let (plan, laws) = with_laws(plan, moment, moment_frame, wheel_torque)?;
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
        for (law, name, what) in &laws {
            if let Some(failure) = law.failure() {
                let what = format!("the {what} function {name}()");
                return Err(law_error(py, &plan.scene_file, &what, failure));
            }
        }
        match result {
            Ok(bytes) => {
                String::from_utf8(bytes).map_err(|e| PyRuntimeError::new_err(e.to_string()))
            }
            Err(SweepError::Deliver(e)) => Err(e),
            Err(SweepError::Threads(message)) => Err(PyRuntimeError::new_err(message)),
        }
    })
}

/// The sweep with `moment` and `wheel_torque` applied to each run's scene, and the laws (to read their failures).
fn with_laws(
    plan: Sweep,
    moment: Option<Bound<'_, PyAny>>,
    moment_frame: Option<String>,
    wheel_torque: Option<Bound<'_, PyAny>>,
) -> PyResult<(Sweep, Laws)> {
    let mut laws = Laws::new();
    let mut moment_law = None;
    if let Some(f) = moment {
        let law = PyLaw::new(f.clone().unbind());
        let name = law_name(&f, "moment", "f(t, q, omega_b) -> 3 numbers")?;
        let axes = moment_axes(moment_frame.as_deref())?;
        moment_law = Some((law.clone(), name.clone(), axes));
        laws.push((law, name, "moment"));
    }
    let mut wheel_law = None;
    if let Some(f) = wheel_torque {
        let law = PyLaw::new(f.clone().unbind());
        let name = law_name(
            &f,
            "wheel_torque",
            "f(t, q, omega_b, spins) -> one torque per wheel",
        )?;
        wheel_law = Some((law.clone(), name.clone()));
        laws.push((law, name, "wheel_torque"));
    }
    if laws.is_empty() {
        return Ok((plan, laws));
    }
    let plan = plan.with_prepare(move |mut scene| {
        if let Some((law, name, axes)) = &moment_law {
            scene = (scene.with_moment(name, *axes, SharedLaw(law.clone())))
                .map_err(|e| e.to_string())?;
        }
        if let Some((law, name)) = &wheel_law {
            scene = (scene.with_wheel_law(name, SharedWheelLaw(law.clone())))
                .map_err(|e| e.to_string())?;
        }
        Ok(scene)
    });
    Ok((plan, laws))
}
