//! `eulerdyn score`: another program's trajectory of a scene against eulerdyn's solution of it — the referee the
//! engine comparisons lacked (Erez, Tassa & Todorov, ICRA 2015, could only measure drift).
//!
//! [`reader`] reads their CSV, [`reference`](mod@reference) computes the referee at their times (the closed form where one
//! applies, else dop853 at rtol 1e-13 with its error estimated), [`metrics`] compares row by row — attitude
//! angle, ω, energy, |H|, H's direction in space, event times, a torque-free body's flips ([`flips`]) — [`hints`] names the likely export slip when their
//! first row is not the scene's initial state, [`diagnose`] names the engine model the trajectory is consistent with
//! (`--diagnose`), [`report`] prints, [`suite`] is the conformance
//! suite (`eulerdyn suite`, `eulerdyn score --suite`), `figure` (feature `plot`) draws the errors against time, `command` (feature `cli`) is
//! `eulerdyn score` and `eulerdyn suite`.

#[cfg(feature = "cli")]
pub mod command;
pub mod diagnose;
#[cfg(feature = "plot")]
pub mod figure;
pub mod flips;
pub mod hints;
pub mod metrics;
pub mod reader;
pub mod reference;
pub mod report;
pub mod suite;

use std::path::Path;

pub use metrics::{Metric, Series};
pub use reader::{QuaternionOrder, ReadOptions};
pub use reference::ErrorEstimate;

use crate::frames::Axes;
use crate::scene::Scene;

/// The referee must be at least this many times more accurate than the errors it reports.
pub const REFEREE_MARGIN: f64 = 100.0;

/// Why scoring stopped: bad input (exit 2) or a failed reference run (exit 1).
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum ScoreError {
    #[error("{0}")]
    /// Bad input (exit 2): the message names file, row and column.
    Input(String),
    #[error("{0}")]
    /// The reference run failed (exit 1).
    Run(String),
}

/// The score of one trajectory.
#[derive(Debug, Clone, serde::Serialize)]
pub struct Score {
    /// Their file.
    pub file: String,
    /// The scene's name.
    pub scene: String,
    /// Their rows scored.
    pub rows: usize,
    /// Their last time (s).
    pub t_last: f64,
    /// What the reference is.
    pub reference: String,
    /// The reference's own error where it is not the closed form's round-off.
    pub reference_error: Option<ErrorEstimate>,
    /// Whether the referee is at least [`REFEREE_MARGIN`] × more accurate than every error it reports.
    pub referee_adequate: bool,
    /// The metrics, each with its verdict.
    pub metrics: Vec<Metric>,
    /// Warnings from reading their file.
    pub warnings: Vec<String>,
    /// The likely export slip when their first row is not the scene's initial state ([`hints`]).
    pub hints: Vec<String>,
    /// What was not measured, and why.
    pub notes: Vec<String>,
    /// The engine model the trajectory is consistent with (`--diagnose`).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub diagnosis: Option<diagnose::Diagnosis>,
    /// The metrics' values against time (the figure's curves).
    #[serde(skip)]
    pub series: Vec<Series>,
    /// A suite's scene whose output the engine did not write: not scored, and not a pass.
    #[serde(skip_serializing_if = "std::ops::Not::not")]
    pub missing: bool,
    /// Their last time (s) when their rows end more than one row before the scene's `t_end` (an engine that
    /// stopped, or whose state stopped being finite): the rest is not scored, and the score is not a pass.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub ends_early: Option<f64>,
}

impl Score {
    /// Whether every metric is within its threshold over the whole scene (a missing output, or one that ends
    /// early, never passes).
    pub fn passes(&self) -> bool {
        !self.missing && self.ends_early.is_none() && self.metrics.iter().all(|m| m.passes)
    }

    /// The entry of a suite's scene `scene` whose output `file` is missing.
    pub fn missing(file: &Path, scene: &str) -> Self {
        Score {
            file: file.display().to_string(),
            scene: scene.to_string(),
            rows: 0,
            t_last: 0.0,
            reference: String::new(),
            reference_error: None,
            referee_adequate: true,
            metrics: Vec::new(),
            warnings: Vec::new(),
            hints: Vec::new(),
            notes: vec![format!(
                "{}: no such file: the engine's output for this scene (run its adapter first)",
                file.display()
            )],
            diagnosis: None,
            series: Vec::new(),
            missing: true,
            ends_early: None,
        }
    }

    /// The metric with this key.
    pub fn metric(&self, key: &str) -> Option<&Metric> {
        self.metrics.iter().find(|m| m.key == key)
    }
}

/// Scores the trajectory in `path` against `scene`.
pub fn score(path: &Path, scene: &Scene, options: &ReadOptions) -> Result<Score, ScoreError> {
    score_with(path, scene, options, false)
}

/// [`score`], with the diagnosis ([`diagnose`]) when `diagnose`.
pub fn score_with(
    path: &Path,
    scene: &Scene,
    options: &ReadOptions,
    diagnose: bool,
) -> Result<Score, ScoreError> {
    let t_end = scene.schedule.t_end();
    let trajectory = reader::read_trajectory(path, options, t_end)?;
    let rows = &trajectory.rows;
    let shown = path.display().to_string();
    let times: Vec<f64> = rows.iter().map(|r| r.t).collect();
    let reference = reference::reference(scene, &shown, &times)?;
    let diagnosis = match diagnose {
        true => Some(diagnose::diagnose(scene, rows, reference.every)?),
        false => None,
    };
    let samples = metrics::their_samples(scene, rows);
    let mut notes = Vec::new();
    let t_last = times[times.len() - 1];
    let ends_early =
        (t_last < t_end - reference.every * (1.0 + reference::GRID_SLACK)).then_some(t_last);
    if let Some(t) = ends_early {
        notes.push(format!(
            "their rows end at t = {t:.3} s, before the scene's t_end = {t_end} s: the rest is not scored, and the \
             score is not a pass"
        ));
    }
    if samples.is_none() {
        notes.push(if rows[0].omega_b.is_none() {
            "no omega columns: ω, energy, H and event times not measured".to_string()
        } else {
            "not a free rigid body: ω, energy, H and event times not measured".to_string()
        });
    }
    let (mut metrics, series) = metrics::metrics(scene, rows, samples.as_deref(), &reference);
    if let Some(theirs) = &samples {
        metrics.extend(flips::metric(scene, theirs, &reference));
    }
    let hints = hints::hints(
        &rows[0],
        &reference.samples[0],
        trajectory.columns,
        options.omega.unwrap_or(Axes::Body),
    );
    let referee_adequate = reference.estimate.is_none_or(|e| {
        let reported = |key: &str| metrics.iter().find(|m| m.key == key).map(|m| m.largest);
        let ok = |est: f64, key: &str| reported(key).is_none_or(|v| REFEREE_MARGIN * est <= v);
        ok(e.attitude, "attitude") && ok(e.omega, "omega")
    });
    Ok(Score {
        file: shown,
        scene: scene.name.clone(),
        rows: rows.len(),
        t_last,
        reference: reference.source,
        reference_error: reference.estimate,
        referee_adequate,
        metrics,
        warnings: trajectory.warnings,
        hints,
        notes,
        diagnosis,
        series,
        missing: false,
        ends_early,
    })
}
