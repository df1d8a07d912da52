//! The scene as simulated: its spec with the command line's overrides applied and every default written in, so
//! that a scene that leaves a key at its default and one that writes the default out are the same value (the run's
//! sidecar records it; the analyses that vary a scene start from it).

use super::super::model::SolverConfig;
use super::super::spec::{
    CompareSpec, InitialSpec, MotionSpec, OutputSpec, RateSpec, SceneSpec, SolverSpec,
};

impl SceneSpec {
    /// This spec, validated into `solver`, `every` and `compare_tolerance`, with the defaults written in: the
    /// solver's and output's values as run; an axis motion's `rate_rpm` as `rate` (rad/s); a free motion as no
    /// `[motion]` table with `initial.omega`; `name`, `description` and `compare.tolerance`. (The typed spec
    /// already holds the other defaults: a torque's frame and profile, gravity's `g`, an axis's point.)
    /// Alternatives (`axis` or `tilt_deg`, `attitude` or `attitude_euler_deg`) stay as given.
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
            form: Some(solver.form),
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
        match spec.motion.as_mut() {
            Some(MotionSpec::FixedAxis(m)) => m.axis.rate = resolved_rate(m.axis.rate),
            Some(MotionSpec::Hinge(m)) => m.axis.rate = resolved_rate(m.axis.rate),
            Some(MotionSpec::Free) | None => {
                spec.motion = None;
                let initial = spec.initial.get_or_insert_with(InitialSpec::default);
                initial.omega.get_or_insert([0.0; 3]);
            }
        }
        spec
    }
}

/// `rate_rpm` becomes `rate` (rad/s), the one the run used.
fn resolved_rate(rate: RateSpec) -> RateSpec {
    RateSpec::RadPerSecond(rate.rad_per_second())
}
