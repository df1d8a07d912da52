//! What `check --json` prints: the numbers `check` shows rounded for reading (the mass center to 1 µm, moments to
//! 7 digits), here at full double precision ([`crate::scene::CheckNumbers`], from the scene's facts), with the
//! scene as simulated, for scripts and other tools.

use serde::Serialize;

use crate::scene::{CheckNumbers, Scene, SceneSpec};

/// A scene's facts at full precision (SI units; body axes unless the name says otherwise).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct SceneFacts {
    /// The scene's `name`.
    pub name: String,
    /// The numbers `check` prints: mass, mass center, inertia about C and about the moment center, principal
    /// moments and axes, motion, axis, step, rows (written at this level).
    #[serde(flatten)]
    pub numbers: Option<CheckNumbers>,
    /// What `check` warns of.
    pub warnings: Vec<String>,
    /// The scene as simulated (defaults written in).
    pub spec: SceneSpec,
}

/// The facts of `scene`, with the `warnings` `check` prints ([`crate::scene::advice::warnings`]).
pub fn facts(scene: &Scene, warnings: &[String]) -> SceneFacts {
    SceneFacts {
        name: scene.name.clone(),
        numbers: scene.facts().check.clone(),
        warnings: warnings.to_vec(),
        spec: scene.spec.clone(),
    }
}
