//! The `RUN.csv.meta.json` sidecar: what was simulated (the scene as run, defaults written in), by which version
//! and method, with what effort, and the unit of every column. One type, written by a run ([`Sidecar::of_run`])
//! and read back by `plot`, `view` and Python ([`Sidecar::read`]).

use std::path::{Path, PathBuf};

use serde::{Deserialize, Serialize};

use crate::effects::Effect;
use crate::events::Occurrence;
use crate::sample::Column;
use crate::scene::{Facts, MotionKind, Scene, SceneSpec};
use crate::simulate::{self, RunReport};

/// The sidecar of the run whose CSV is `csv`: `csv` with `.meta.json` appended.
///
/// ```
/// use std::path::Path;
/// assert_eq!(eulerdyn::output::sidecar::sidecar_path(Path::new("runs/disk.csv")), Path::new("runs/disk.csv.meta.json"));
/// ```
pub fn sidecar_path(csv: &Path) -> PathBuf {
    PathBuf::from(format!("{}.meta.json", csv.display()))
}

/// The whole document.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Sidecar {
    /// The version of eulerdyn that wrote the file (`Cargo.toml`), which says which contract it follows.
    pub eulerdyn_version: String,
    /// The scene as simulated.
    pub scene: SidecarScene,
    /// The method and its settings.
    pub solver: SidecarSolver,
    /// The run's effort and its energy drift.
    pub statistics: Statistics,
    /// What the run warned of (a coarse fixed step, a drifting energy), as printed on stderr.
    pub warnings: Vec<String>,
    /// Every CSV column, in order.
    pub columns: Vec<SidecarColumn>,
    /// The located `[[event]]`s, where the scene has any.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub events: Option<SidecarEvents>,
    /// What the scene conserves ([`Facts`]); absent in a sidecar written before 0.2.
    #[serde(default)]
    pub facts: Option<Facts>,
}

/// `events`: the events file beside the CSV and its occurrences.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct SidecarEvents {
    /// The events file's name (`RUN.csv.events.csv`, in the CSV's directory).
    pub file: String,
    /// Every occurrence, in time order.
    pub occurrences: Vec<SidecarEvent>,
}

/// One located event: the events file's row.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct SidecarEvent {
    /// The event's `name`.
    pub event: String,
    /// The time it occurred (s), located to 1e-13 s.
    pub t: f64,
    /// The quantity's value there (its column's unit).
    pub value: f64,
    /// `up`, `down`, `max` or `min`.
    pub direction: String,
}

/// `scene`: the scene as simulated, and the file it came from.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct SidecarScene {
    /// The scene file as given on the command line (`<dict>` from Python, absent for a scene built in code).
    pub path: Option<String>,
    /// The scene's `name`.
    pub name: String,
    /// The scene's `description`.
    pub description: String,
    /// `free`, `fixed_axis` or `hinge`.
    pub motion: MotionKind,
    /// The effects' types, in order (a user's law as `user:NAME`, [`Effect::label`]).
    pub effects: Vec<String>,
    /// The name of the wheel law that commanded the wheels (Rust's `Scene::with_wheel_law`, Python's
    /// `wheel_torque=`), absent when none did: the scene's text alone does not then reproduce the run.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub wheel_law: Option<String>,
    /// The scene file's text as written (absent for a scene built in code).
    pub text: Option<String>,
    /// The scene as simulated: overrides applied, defaults written in ([`Scene::spec`]).
    pub spec: SceneSpec,
}

/// `solver`: the method and its settings as run.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct SidecarSolver {
    /// The method (`rk4`, `dopri5`, `dop853`, `split2`, `split4`, `exact`).
    pub method: String,
    /// The Runge–Kutta implementation (`native` or `ode_solvers`).
    pub backend: String,
    /// The form of Euler's equation integrated (`body` or `space`).
    pub frame: String,
    /// Relative tolerance of the adaptive methods.
    pub rtol: f64,
    /// Absolute tolerance of the adaptive methods.
    pub atol: f64,
    /// The step asked for (s): the first step of an adaptive method, the step of a fixed-step one.
    pub dt: f64,
    /// Whether the method takes a fixed step.
    pub fixed_step: bool,
    /// The fixed step actually taken (s), for fixed-step methods.
    pub step_used: Option<f64>,
    /// The end time (s).
    pub t_end: f64,
    /// The time between rows (s).
    pub every: f64,
}

/// `statistics`: the run's effort.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Statistics {
    /// Steps taken (accepted).
    pub steps: u64,
    /// Steps rejected by an adaptive method's error control.
    pub rejected_steps: u64,
    /// Evaluations of the right-hand side (the equations of motion).
    pub rhs_evaluations: u64,
    /// Rows written to the CSV.
    pub rows: u64,
    /// Wall-clock time of the run (s).
    pub wall_seconds: f64,
    /// Relative drift of T + V where the scene conserves it.
    pub energy_drift: Option<f64>,
}

/// One CSV column: its name, SI unit and meaning.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct SidecarColumn {
    /// The column's header.
    pub name: String,
    /// Its SI unit (`1` for a number without unit).
    pub unit: String,
    /// What it is, with its frame and the point a moment is about.
    pub meaning: String,
}

impl Sidecar {
    /// The sidecar of a run of `scene` that wrote `columns` and ended with `report`.
    pub fn of_run(scene: &Scene, report: &RunReport, columns: &[Column]) -> Self {
        let s = &scene.solver;
        let source = scene.source.as_ref();
        Self {
            eulerdyn_version: env!("CARGO_PKG_VERSION").to_string(),
            scene: SidecarScene {
                path: source.map(|s| s.path.display().to_string()),
                name: scene.name.clone(),
                description: scene.description.clone(),
                motion: scene.motion.kind(),
                effects: scene.effects.iter().map(Effect::label).collect(),
                wheel_law: scene.motion.wheel_law().map(str::to_string),
                text: source.map(|s| s.text.clone()),
                spec: scene.spec.clone(),
            },
            solver: SidecarSolver {
                method: s.method.name().to_string(),
                backend: s.backend.name().to_string(),
                frame: s.form.name().to_string(),
                rtol: s.rtol,
                atol: s.atol,
                dt: s.dt,
                fixed_step: s.method.is_fixed_step(),
                step_used: scene.fixed_step(),
                t_end: s.t_end,
                every: scene.schedule.every(),
            },
            statistics: Statistics {
                steps: report.stats.steps,
                rejected_steps: report.stats.rejected,
                rhs_evaluations: report.stats.evals,
                rows: report.rows,
                wall_seconds: report.wall_seconds,
                energy_drift: report.energy_drift,
            },
            warnings: simulate::warnings(scene, report.energy_drift),
            columns: columns
                .iter()
                .map(|c| SidecarColumn {
                    name: c.name.to_string(),
                    unit: c.unit.into(),
                    meaning: c.meaning.into(),
                })
                .collect(),
            events: None,
            facts: Some(scene.facts().clone()),
        }
    }

    /// The sidecar listing the events file `file` (absent: a scene without events) and its `occurrences`.
    ///
    /// ```
    /// use std::path::Path;
    /// use eulerdyn::events::{Kind, Occurrence};
    /// use eulerdyn::output::Sidecar;
    /// use eulerdyn::scene::{BodySpec, SceneSpec};
    /// use eulerdyn::simulate::RunReport;
    /// let scene = SceneSpec::new(BodySpec::principal(1.0, [1.0, 2.0, 3.0]), 1.0, 0.5).build()?;
    /// let top = Occurrence { event: 0, name: "top".into(), t: 0.25, value: 1.5, kind: Kind::Max };
    /// let sidecar = Sidecar::of_run(&scene, &RunReport::default(), &[])
    ///     .with_events(Some(Path::new("runs/disk.csv.events.csv")), &[top]);
    /// let events = sidecar.events.unwrap();
    /// assert_eq!(events.file, "disk.csv.events.csv");
    /// assert_eq!((events.occurrences[0].t, events.occurrences[0].direction.as_str()), (0.25, "max"));
    /// // No events file: no `events`.
    /// assert!(Sidecar::of_run(&scene, &RunReport::default(), &[]).with_events(None, &[]).events.is_none());
    /// # Ok::<(), Box<dyn std::error::Error>>(())
    /// ```
    pub fn with_events(mut self, file: Option<&Path>, occurrences: &[Occurrence]) -> Self {
        self.events = file.map(|file| SidecarEvents {
            file: (file.file_name()).map_or_else(String::new, |n| n.to_string_lossy().into_owned()),
            occurrences: (occurrences.iter())
                .map(|o| SidecarEvent {
                    event: o.name.clone(),
                    t: o.t,
                    value: o.value,
                    direction: o.kind.name().into(),
                })
                .collect(),
        });
        self
    }

    /// The document as pretty JSON with a final newline.
    pub fn to_json(&self) -> String {
        let mut text = serde_json::to_string_pretty(self).unwrap_or_default();
        text.push('\n');
        text
    }

    /// Reads the sidecar of the run whose CSV is `csv` ([`sidecar_path`]); the error says, in a few words, why
    /// there is none to use (missing, unreadable, not JSON, not an eulerdyn sidecar).
    pub fn read(csv: &Path) -> Result<Sidecar, String> {
        let text = match std::fs::read_to_string(sidecar_path(csv)) {
            Ok(text) => text,
            Err(e) if e.kind() == std::io::ErrorKind::NotFound => {
                return Err("there is no sidecar".into());
            }
            Err(e) => return Err(format!("the sidecar cannot be read ({e})")),
        };
        Self::from_json(&text)
    }

    /// Parses a sidecar document.
    pub fn from_json(text: &str) -> Result<Sidecar, String> {
        serde_json::from_str(text).map_err(|e| match e.classify() {
            serde_json::error::Category::Data => {
                format!(
                    "the sidecar is not one that this eulerdyn writes ({e}); run the scene again"
                )
            }
            _ => format!("the sidecar is not valid JSON ({e})"),
        })
    }
}
