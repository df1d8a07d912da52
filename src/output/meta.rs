//! The `FILE.meta.json` sidecar: what was simulated, by which version and method, with what effort, and the unit
//! of every column.

use serde_json::{Value, json};

use crate::scene::{Motion, Scene};
use crate::simulate::{self, RunReport};

use crate::sample::Column;

/// The sidecar document for a run of `scene` (read from `scene_path`, whose text is `scene_text`).
pub fn sidecar(
    scene_path: &str,
    scene_text: &str,
    scene: &Scene,
    report: &RunReport,
    columns: &[Column],
) -> Value {
    let s = &scene.solver;
    let motion = match scene.motion {
        Motion::Free { .. } => "free",
        Motion::FixedAxis { .. } => "fixed_axis",
        Motion::Hinge { .. } => "hinge",
    };
    json!({
        "eulerdyn_version": env!("CARGO_PKG_VERSION"),
        "scene": {
            "path": scene_path,
            "name": scene.name,
            "description": scene.description,
            "motion": motion,
            "effects": scene.effects.iter().map(|e| e.kind()).collect::<Vec<_>>(),
            "text": scene_text,
        },
        "solver": {
            "method": s.method.name(),
            "backend": s.backend.name(),
            "frame": s.frame.name(),
            "rtol": s.rtol,
            "atol": s.atol,
            "dt": s.dt,
            "fixed_step": s.method.is_fixed_step(),
            "step_used": simulate::fixed_step(scene),
            "t_end": s.t_end,
            "every": scene.schedule.every(),
        },
        "statistics": {
            "steps": report.stats.steps,
            "rejected_steps": report.stats.rejected,
            "rhs_evaluations": report.stats.evals,
            "rows": report.rows,
            "wall_seconds": report.wall_seconds,
            "energy_drift": report.energy_drift,
        },
        "warnings": simulate::warnings(scene, report.energy_drift),
        "columns": columns.iter().map(|c| json!({"name": c.name, "unit": c.unit, "meaning": c.meaning})).collect::<Vec<_>>(),
    })
}
