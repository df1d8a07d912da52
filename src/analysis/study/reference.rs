//! What the study's runs are compared with: the closed form where one applies ([`Oracle::for_scene`]), the
//! closed form H_s = I_s(θ)·ω_s carried by the rows of prescribed fixed-axis motion, or else a reference run
//! (DOP853, own backend, body form, rtol 1e-14) whose uncertainty is the distance to the same run in the space form.

use std::convert::Infallible;
use std::path::Path;

use nalgebra::{UnitQuaternion, Vector3};

use crate::frames::Form;
use crate::method::{Backend, Method};
use crate::sample::Sample;
use crate::scene::{Oracle, Overrides, Scene, SceneSpec};
use crate::simulate;

use super::{Measure, StudyError};

/// Relative tolerance of a reference run (and the fallback when the scene refuses it).
const REFERENCE_RTOL: [f64; 2] = [1e-14, 1e-13];
/// Absolute tolerance of a reference run.
const REFERENCE_ATOL: f64 = 1e-15;

/// One row of a reference.
#[derive(Debug, Clone, Copy)]
pub(super) struct RefRow {
    pub t: f64,
    pub omega_b: Vector3<f64>,
    /// Attitude, body → space.
    pub q: Option<UnitQuaternion<f64>>,
    pub energy: f64,
    pub h_norm: f64,
    pub h_s: Option<Vector3<f64>>,
}

/// What runs are compared with.
pub(super) enum Reference {
    /// A value per row (closed form or reference run).
    Rows(Vec<RefRow>),
    /// Prescribed fixed-axis motion: the rows carry their own closed form.
    FixedAxis,
}

/// The reference of a study, what it is in words, and the quantity runs are ranked by.
pub(super) struct StudyReference {
    pub reference: Reference,
    /// For the summary.
    pub description: String,
    /// For the figure.
    pub short: String,
    pub measure: Measure,
}

impl StudyReference {
    /// The reference for the scene `base` (read from `path` as `spec`).
    pub fn for_scene(base: &Scene, path: &Path, spec: &SceneSpec) -> Result<Self, StudyError> {
        Ok(match base.facts().oracle() {
            Some(Oracle::FixedAxis) => Self {
                reference: Reference::FixedAxis,
                description: "closed form: prescribed fixed-axis motion, H_s = I_s(theta) omega_s against H_s integrated from dH_s/dt = M_s (omega and attitude are the closed form in every run)".to_string(),
                short: "closed form H_s = I_s(theta) omega_s".to_string(),
                measure: Measure::HSpace,
            },
            Some(o) => Self {
                reference: Reference::Rows(oracle_rows(base, o)),
                description: format!("closed form: {}", o.name()),
                short: "closed form".to_string(),
                measure: Measure::Omega,
            },
            None => Self::reference_runs(path, spec)?,
        })
    }

    /// No closed form: the reference run in the body form, its uncertainty from the same run in the space form.
    fn reference_runs(path: &Path, spec: &SceneSpec) -> Result<Self, StudyError> {
        let (rows, rtol, steps) = reference_run(path, spec, Form::Body)?;
        let (other, _, _) = reference_run(path, spec, Form::Space)?;
        let spread = rows
            .iter()
            .zip(&other)
            .map(|(a, b)| (a.omega_b - b.omega_b).norm())
            .fold(0.0, f64::max);
        Ok(Self {
            reference: Reference::Rows(rows),
            description: format!(
                "no closed form applies: reference run dop853 (own backend, body form) at rtol {rtol:e}, atol {REFERENCE_ATOL:e} ({steps} steps); its space form differs from it by {spread:.1e} rad/s in omega, so smaller errors are not resolved"
            ),
            short: format!("dop853 at rtol {rtol:e} (uncertainty {spread:.0e} rad/s)"),
            measure: Measure::Omega,
        })
    }

    /// The largest |ω| of a scene's motion: from the reference rows, or (fixed axis) from a run of the scene.
    pub fn omega_scale(&self, scene: &Scene) -> f64 {
        match &self.reference {
            Reference::Rows(rows) => rows.iter().map(|r| r.omega_b.norm()).fold(0.0, f64::max),
            Reference::FixedAxis => {
                let mut largest = 0.0f64;
                let _ = simulate::run(scene, |s: &Sample| {
                    largest = largest.max(s.omega_b.norm());
                    Ok::<(), Infallible>(())
                });
                largest
            }
        }
    }
}

/// The closed form at every row time ([`Oracle::at`]; T and |H| from ω where it gives only ω); empty for
/// fixed-axis motion, whose rows carry their own closed form.
fn oracle_rows(scene: &Scene, oracle: &Oracle) -> Vec<RefRow> {
    let inertia = *scene.body.inertia_c();
    let row = |t: f64| {
        let exact = oracle.at(t);
        let omega_b = exact.omega_b?;
        let h_b = inertia * omega_b;
        Some(RefRow {
            t,
            omega_b,
            q: exact.q,
            energy: exact.energy.unwrap_or_else(|| 0.5 * omega_b.dot(&h_b)),
            h_norm: exact.h_norm.unwrap_or_else(|| h_b.norm()),
            h_s: exact.h_s,
        })
    };
    scene.schedule.iter().map_while(row).collect()
}

/// The reference run: DOP853 on the own backend at the tightest tolerance the scene accepts, in `frame`; its rows,
/// its rtol and its steps.
fn reference_run(
    path: &Path,
    spec: &SceneSpec,
    form: Form,
) -> Result<(Vec<RefRow>, f64, u64), StudyError> {
    let mut last_refusal = None;
    for rtol in REFERENCE_RTOL {
        let overrides = Overrides {
            method: Some(Method::Dop853),
            form: Some(form),
            backend: Some(Backend::Own),
            rtol: Some(rtol),
            atol: Some(REFERENCE_ATOL),
            ..Overrides::default()
        };
        let scene = match spec.build_with(&overrides) {
            Ok(s) => s,
            Err(e) => {
                last_refusal = Some(e.to_string());
                continue;
            }
        };
        let mut rows = Vec::with_capacity(scene.schedule.len());
        let report = simulate::run(&scene, |s: &Sample| {
            rows.push(RefRow {
                t: s.t,
                omega_b: *s.omega_b,
                q: Some(s.q),
                energy: s.energy,
                h_norm: s.h_o_s.norm(),
                h_s: Some(*s.h_o_s),
            });
            Ok::<(), Infallible>(())
        })
        .map_err(|e| StudyError::Reference {
            file: path.to_path_buf(),
            problem: e.to_string(),
        })?;
        return Ok((rows, rtol, report.stats.steps));
    }
    Err(StudyError::Reference {
        file: path.to_path_buf(),
        problem: format!(
            "the scene refuses DOP853 at rtol 1e-14 and 1e-13: {}",
            last_refusal.unwrap_or_default()
        ),
    })
}
