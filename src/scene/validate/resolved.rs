//! The scene as simulated: its spec with the command line's overrides applied and every default written in, so
//! that a scene that leaves a key at its default and one that writes the default out are the same value (the run's
//! sidecar records it; the analyses that vary a scene start from it).

use super::super::model::SolverConfig;
use super::super::spec::{
    CompareSpec, EffectKind, EffectSpec, InitialSpec, MotionKind, OutputSpec, ProfileKind,
    SceneSpec, SolverSpec,
};
use crate::effects::DEFAULT_GRAVITY;
use crate::frames::Axes;

impl SceneSpec {
    /// This spec, validated into `solver`, `every` and `compare_tolerance`, with the defaults written in: the
    /// solver's and output's values as run; each torque's `frame` and `profile` (with a sine's `phase_deg` and a
    /// step's `t_on`); gravity's `g`; an axis motion's `rate`, `accel` (fixed axis), `angle_deg` (hinge) and
    /// `point`; a free motion as no `[motion]` table with `initial.omega`; `name`, `description` and
    /// `compare.tolerance`. Alternatives (`axis` or `tilt_deg`, `attitude` or `attitude_euler_deg`) stay as given.
    pub(in crate::scene) fn resolved(
        &self,
        solver: &SolverConfig,
        every: f64,
        compare_tolerance: f64,
    ) -> SceneSpec {
        let mut spec = self.clone();
        spec.name.get_or_insert_with(String::new);
        spec.description.get_or_insert_with(String::new);
        spec.solver = SolverSpec {
            method: Some(solver.method),
            frame: Some(solver.form),
            backend: Some(solver.backend),
            rtol: Some(solver.rtol),
            atol: Some(solver.atol),
            dt: Some(solver.dt),
            t_end: solver.t_end,
        };
        spec.output = OutputSpec { every };
        spec.compare = Some(CompareSpec {
            tolerance: compare_tolerance,
        });
        spec.effect.iter_mut().for_each(resolve_effect);
        match spec.motion.as_mut() {
            Some(m) if m.kind != Some(MotionKind::Free) => {
                // `rate_rpm` becomes `rate` (rad/s), the one the run used.
                if let Some(rpm) = m.rate_rpm.take() {
                    m.rate = Some(rpm * std::f64::consts::TAU / 60.0);
                }
                m.rate.get_or_insert(0.0);
                m.point.get_or_insert([0.0; 3]);
                match m.kind {
                    Some(MotionKind::Hinge) => m.angle_deg.get_or_insert(0.0),
                    _ => m.accel.get_or_insert(0.0),
                };
            }
            _ => {
                spec.motion = None;
                let initial = spec.initial.get_or_insert_with(InitialSpec::default);
                initial.omega.get_or_insert([0.0; 3]);
            }
        }
        spec
    }
}

/// One effect's defaults written in.
fn resolve_effect(effect: &mut EffectSpec) {
    match effect.kind {
        Some(EffectKind::Torque) => {
            effect.frame.get_or_insert(Axes::Body);
            match *effect.profile.get_or_insert(ProfileKind::Constant) {
                ProfileKind::Sine => _ = effect.phase_deg.get_or_insert(0.0),
                ProfileKind::Step => _ = effect.t_on.get_or_insert(0.0),
                ProfileKind::Constant => {}
            }
        }
        Some(EffectKind::Gravity) => _ = effect.g.get_or_insert(DEFAULT_GRAVITY),
        Some(EffectKind::Damping) | None => {}
    }
}
