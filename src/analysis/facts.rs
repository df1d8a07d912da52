//! What `check --json` prints: the numbers `check` shows rounded for reading (the mass center to 1 µm, moments to
//! 7 digits), here at full double precision, with the scene as simulated, for scripts and other tools.

use nalgebra::{Matrix3, Vector3};
use serde::Serialize;

use crate::body::Principal;
use crate::scene::{MotionKind, Scene, SceneSpec};
use crate::simulate;

/// A scene's facts at full precision (SI units; body axes unless the name says otherwise).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct SceneFacts {
    /// The scene's `name`.
    pub name: String,
    /// kg.
    pub mass: f64,
    /// The mass center C from the reference origin (m).
    pub center_b: [f64; 3],
    /// The inertia tensor about C (kg·m²), rows; off-diagonal entries are −∫ x y dm.
    pub inertia_c_b: [[f64; 3]; 3],
    /// Principal moments about C (kg·m²) and their axes as the columns of `principal_axes_b` (rows written out),
    /// in [`Principal`]'s order.
    pub principal_moments_c: [f64; 3],
    /// The principal axes (columns), body axes.
    pub principal_axes_b: [[f64; 3]; 3],
    /// `free`, `fixed_axis` or `hinge`.
    pub motion: MotionKind,
    /// The moment center O (C, a gravity pivot, or the axis point) from C (m), and the inertia about it.
    pub moment_center_from_c_b: [f64; 3],
    /// The inertia tensor about O (kg·m²), rows.
    pub inertia_o_b: [[f64; 3]; 3],
    /// The fixed axis (unit, body axes), for a fixed axis or hinge.
    pub axis_b: Option<[f64; 3]>,
    /// The fixed step taken (s), for fixed-step methods.
    pub step_used: Option<f64>,
    /// Rows a run writes.
    pub rows: usize,
    /// What `check` warns of.
    pub warnings: Vec<String>,
    /// The scene as simulated (defaults written in).
    pub spec: SceneSpec,
}

fn rows_of(m: &Matrix3<f64>) -> [[f64; 3]; 3] {
    std::array::from_fn(|r| std::array::from_fn(|c| m[(r, c)]))
}

fn array(v: &Vector3<f64>) -> [f64; 3] {
    [v.x, v.y, v.z]
}

/// The facts of `scene`, with the `warnings` `check` prints ([`crate::scene::advice::warnings`]).
pub fn facts(scene: &Scene, warnings: &[String]) -> SceneFacts {
    let inertia_c = scene.body.inertia_c();
    let principal = Principal::of(inertia_c);
    let (rho_c_b, inertia_o_b) = scene.motion.about_moment_center();
    let axis = scene.motion.axis();
    SceneFacts {
        name: scene.name.clone(),
        mass: scene.body.mass(),
        center_b: array(&scene.center_b),
        inertia_c_b: rows_of(inertia_c),
        principal_moments_c: array(&principal.moments),
        principal_axes_b: rows_of(principal.axes_b.matrix()),
        motion: scene.motion.kind(),
        moment_center_from_c_b: array(&-rho_c_b),
        inertia_o_b: rows_of(&inertia_o_b),
        axis_b: axis.map(|a| array(a.axis_b())),
        step_used: simulate::fixed_step(scene),
        rows: scene.schedule.len(),
        warnings: warnings.to_vec(),
        spec: scene.spec.clone(),
    }
}
