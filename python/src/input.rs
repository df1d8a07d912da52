//! A scene as Python gives it: a path (`str` or `os.PathLike`) of a scene file, or a dict of the same keys. A dict
//! becomes TOML text, so that the library parses and validates both the same way, with the same messages: they
//! name `<dict>` for the file and the key at fault, without a line and column.

use std::path::PathBuf;

use eulerdyn::scene::{self, Overrides, Scene};
use pyo3::exceptions::PyTypeError;
use pyo3::prelude::*;
use pyo3::types::{PyBool, PyDict, PyFloat, PyInt, PyList, PyString, PyTuple};

use crate::errors::scene_error;

/// What a dict scene is called in messages, in place of a file name.
pub const DICT_ORIGIN: &str = "<dict>";

/// A scene's origin (its file, or `<dict>`) and its TOML text.
pub struct SceneInput {
    /// The scene file, or [`DICT_ORIGIN`]: messages name it.
    pub path: PathBuf,
    /// The scene as TOML text.
    pub text: String,
    /// Whether the scene was a dict (its messages have no line and column).
    pub from_dict: bool,
}

impl SceneInput {
    /// Reads a path's scene file, or turns a dict into TOML text.
    pub fn from_py(scene: &Bound<'_, PyAny>) -> PyResult<Self> {
        let py = scene.py();
        if let Ok(dict) = scene.cast::<PyDict>() {
            let table = table_of(dict, "")?;
            let text = toml::to_string(&table).map_err(|e| {
                let problem = format!("cannot be written as a scene: {e}");
                dict_error(py, None, problem)
            })?;
            return Ok(Self {
                path: PathBuf::from(DICT_ORIGIN),
                text,
                from_dict: true,
            });
        }
        let path = path_of(scene, "scene")?;
        let text = scene::read(&path).map_err(|e| scene_error(py, e, false))?;
        Ok(Self {
            path,
            text,
            from_dict: false,
        })
    }

    /// The library's error as `SceneError`.
    pub fn error(&self, py: Python<'_>, e: scene::SceneError) -> PyErr {
        scene_error(py, e, self.from_dict)
    }

    /// A built scene's refusal (e.g. of a user's moment) as `SceneError` naming this scene and the key.
    pub fn invalid(&self, py: Python<'_>, inv: scene::InvalidScene) -> PyErr {
        let e = scene::SceneError {
            file: self.path.clone(),
            key: Some(inv.key.to_string()),
            location: None,
            problem: inv.problem,
        };
        self.error(py, e)
    }

    /// The validated scene with `overrides` (as the command line's flags).
    pub fn scene(&self, py: Python<'_>, overrides: &Overrides) -> PyResult<Scene> {
        scene::parse(&self.path, &self.text, overrides).map_err(|e| self.error(py, e))
    }
}

/// A `SceneError` about a dict's key.
pub fn dict_error(py: Python<'_>, key: Option<&str>, problem: String) -> PyErr {
    let e = scene::SceneError {
        file: PathBuf::from(DICT_ORIGIN),
        key: key.map(str::to_string),
        location: None,
        problem,
    };
    scene_error(py, e, true)
}

/// The path a `what` argument (`scene`, `sweep`) gives when it is not a dict: a str or an os.PathLike, else a
/// TypeError that says what it may be.
pub fn path_of(value: &Bound<'_, PyAny>, what: &str) -> PyResult<PathBuf> {
    value.extract().map_err(|_| {
        PyTypeError::new_err(format!(
            "{what}: expected a {what} file's path (str or os.PathLike) or a dict of its keys, got {}",
            type_name(value)
        ))
    })
}

/// The Python type's name of `value`, for messages.
pub fn type_name(value: &Bound<'_, PyAny>) -> String {
    value
        .get_type()
        .name()
        .map_or_else(|_| "?".into(), |n| n.to_string())
}

/// A dict as a TOML table; `key` is its key path (empty for the scene itself).
pub fn table_of(dict: &Bound<'_, PyDict>, key: &str) -> PyResult<toml::Table> {
    let mut table = toml::Table::new();
    for (k, v) in dict.iter() {
        let Ok(name) = k.cast::<PyString>() else {
            let problem = format!(
                "keys are strings; got the key {} ({})",
                k.repr().map_or_else(|_| "?".into(), |r| r.to_string()),
                type_name(&k)
            );
            return Err(dict_error(
                dict.py(),
                (!key.is_empty()).then_some(key),
                problem,
            ));
        };
        let name: String = name.extract()?;
        let path = if key.is_empty() {
            name.clone()
        } else {
            format!("{key}.{name}")
        };
        table.insert(name, value_of(&v, &path)?);
    }
    Ok(table)
}

/// A Python value as a TOML value: bool, int, float, str, dict, list or tuple (and NumPy arrays and scalars,
/// through their `tolist()`).
fn value_of(value: &Bound<'_, PyAny>, key: &str) -> PyResult<toml::Value> {
    let py = value.py();
    if value.is_instance_of::<PyBool>() {
        return Ok(toml::Value::Boolean(value.extract()?));
    }
    if value.is_instance_of::<PyInt>() {
        return value
            .extract::<i64>()
            .map(toml::Value::Integer)
            .map_err(|_| {
                dict_error(
                    py,
                    Some(key),
                    "the integer is too large for a scene file".into(),
                )
            });
    }
    if value.is_instance_of::<PyFloat>() {
        return Ok(toml::Value::Float(value.extract()?));
    }
    if let Ok(s) = value.cast::<PyString>() {
        return Ok(toml::Value::String(s.extract()?));
    }
    if let Ok(dict) = value.cast::<PyDict>() {
        return table_of(dict, key).map(toml::Value::Table);
    }
    if value.is_instance_of::<PyList>() || value.is_instance_of::<PyTuple>() {
        let items = value
            .try_iter()?
            .enumerate()
            .map(|(k, item)| value_of(&item?, &format!("{key}[{k}]")))
            .collect::<PyResult<Vec<_>>>()?;
        return Ok(toml::Value::Array(items));
    }
    if value.hasattr("tolist")? {
        return value_of(&value.call_method0("tolist")?, key);
    }
    let problem = if value.is_none() {
        "None has no value in a scene file: leave the key out".to_string()
    } else {
        format!(
            "expected a number, string, bool, list or dict; got {}",
            type_name(value)
        )
    };
    Err(dict_error(py, Some(key), problem))
}
