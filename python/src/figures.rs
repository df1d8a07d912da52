//! `plot` and `view`: eulerdyn's own figure (SVG text) and 3D page of a run's CSV, as `eulerdyn plot` and
//! `eulerdyn view` draw them, and `run_to_csv`, which writes a scene's run as `eulerdyn run -o` does (the CSV and
//! its sidecar), for the Python wrappers that take a scene or a DataFrame.

use std::path::PathBuf;

use eulerdyn::output::plot::{FigureOptions, FigureSize, Panel, PlotError, read_run, render_svg};
use eulerdyn::output::view::{ViewError, view_file};
use eulerdyn::output::{WriteRunError, write_run};
use eulerdyn::scene::{Overrides, SceneError};
use pyo3::prelude::*;
use pyo3::types::PyDict;

use crate::errors::{RunError, no_panic, scene_error};
use crate::input::SceneInput;

/// A `SceneError` naming `file` (bad input: the command line exits 2 on it).
fn input_error(py: Python<'_>, file: PathBuf, problem: String) -> PyErr {
    let e = SceneError {
        file,
        key: None,
        location: None,
        problem,
    };
    scene_error(py, e, false)
}

/// The figure of the run's CSV `csv` (its sidecar read when beside it), as `eulerdyn plot CSV -o FIG.svg [--panels
/// P] [--title T] [--size W,H]` draws it, as SVG text. `panels` is the command line's comma-separated list (None:
/// the panels the run has). Raises SceneError for an unusable CSV or option, RunError when it cannot be drawn.
#[pyfunction]
#[pyo3(signature = (csv, panels=None, title=None, size=None))]
pub fn plot(
    py: Python<'_>,
    csv: PathBuf,
    panels: Option<String>,
    title: Option<String>,
    size: Option<String>,
) -> PyResult<String> {
    no_panic(|| {
        let option = |problem: String| input_error(py, csv.clone(), problem);
        let panels = match &panels {
            Some(list) => Panel::parse_list(list).map_err(|p| option(format!("panels: {p}")))?,
            None => Vec::new(),
        };
        let size = match &size {
            Some(text) => Some(
                text.parse::<FigureSize>()
                    .map_err(|p| option(format!("size: {p}")))?,
            ),
            None => None,
        };
        let options = FigureOptions {
            size,
            title,
            dpi: None,
        };
        let drawn = py.detach(|| {
            let run = read_run(&csv, &panels)?;
            render_svg(&run, &panels, &options, &csv.with_extension("svg"))
        });
        drawn.map_err(|e| match e {
            PlotError::Input { file, problem } => input_error(py, file, problem),
            PlotError::Option(problem) => option(problem),
            PlotError::Output { .. } => RunError::new_err(e.to_string()),
        })
    })
}

/// Writes the 3D page of the run's CSV `csv` to `out`, as `eulerdyn view CSV -o OUT.html` does; what it drew as a
/// dict: rows_in_run, rows_drawn, stride, bytes, notes. Raises SceneError for an unusable CSV or output path,
/// RunError when the page cannot be written.
#[pyfunction]
pub fn view<'py>(py: Python<'py>, csv: PathBuf, out: PathBuf) -> PyResult<Bound<'py, PyDict>> {
    no_panic(|| {
        let summary = py.detach(|| view_file(&csv, &out)).map_err(|e| match e {
            ViewError::Input { file, problem } => input_error(py, file, problem),
            ViewError::Output { .. } => RunError::new_err(e.to_string()),
        })?;
        let d = PyDict::new(py);
        d.set_item("rows_in_run", summary.rows_in_run)?;
        d.set_item("rows_drawn", summary.rows_drawn)?;
        d.set_item("stride", summary.stride)?;
        d.set_item("bytes", summary.bytes)?;
        d.set_item("notes", summary.notes)?;
        Ok(d)
    })
}

/// Runs the scene (a path or a dict) and writes its CSV to `csv` with its sidecar beside it, as `eulerdyn run SCENE
/// -o CSV` does. Raises SceneError for bad input, RunError when the run fails.
#[pyfunction]
pub fn run_to_csv(py: Python<'_>, scene: &Bound<'_, PyAny>, csv: PathBuf) -> PyResult<()> {
    no_panic(|| {
        let input = SceneInput::from_py(scene)?;
        let scene = input.scene(py, &Overrides::default())?;
        py.detach(|| write_run(&scene, &csv))
            .map(|_| ())
            .map_err(|e| match e {
                WriteRunError::Output { file, problem } => input_error(py, file, problem),
                other => RunError::new_err(other.to_string()),
            })
    })
}
