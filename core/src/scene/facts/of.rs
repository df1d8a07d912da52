//! The facts of a validated scene ([`Facts::of`]), computed once when it is built.
//!
//! The invariants (Rigid-body dynamics, lecture notes, Thms 24–25; Landau & Lifshitz §§33–35):
//! - free motion with no effect: H_s (Ḣ_s = M_s = 0, whatever the rotors' motors do: their torques are internal),
//!   hence |H|; and T when no motor does work (no rotors, or every wheel spinning freely);
//! - free motion about a fixed pivot under gravity alone: T + V when no motor does work, and H_s,z when g is along
//!   space z (gravity's moment r × m g is horizontal);
//! - a hinge: T with no effect, T + V under gravity alone;
//! - a prescribed fixed axis turning steadily: T and |H| (H_s turns with the body; its magnitude does not);
//! - a body that changes shape (M = d/dt(I·ω)), torque-free: H_s and |H|, not T (its drives do work, P_internal);
//! - nothing with torques, damping or a user's law, an accelerating prescribed axis, a turning carrier (which
//!   does work on the body), or an imbalanced wheel (its turning moment changes H and T).

use super::{CheckNumbers, Facts, Invariant};
use crate::effects::Effect;
use crate::panel::Panel;
use crate::sample::ColumnSet;
use crate::scene::model::Scene;
use crate::scene::motion::Motion;
use crate::scene::oracle::Oracle;
use crate::scene::spec::MotionKind;

impl Facts {
    /// The facts of `scene`.
    ///
    /// ```
    /// use eulerdyn::scene::{BodySpec, Invariant, SceneSpec, ShapeSpec};
    /// let scene = SceneSpec::new(BodySpec::shape(1.0, ShapeSpec::sphere(0.1)), 1.0, 0.01)
    ///     .with_omega([0.0, 0.0, 3.0])
    ///     .build()?;
    /// let facts = scene.facts();
    /// assert!(facts.conserves(Invariant::Energy) && facts.conserves(Invariant::HSpaceX));
    /// # Ok::<(), Box<dyn std::error::Error>>(())
    /// ```
    pub fn of(scene: &Scene) -> Self {
        let moving_support = (scene.motion.axis()).is_some_and(|a| a.moving_support().is_some());
        let oracle = Oracle::for_scene(scene);
        let columns = Scene::run_columns(&scene.motion, &scene.effects, scene.orbit.as_ref());
        Facts {
            invariants: invariants(scene, moving_support),
            closed_form: oracle.as_ref().map(Oracle::kind),
            moving_support,
            panels: panels(&scene.motion, moving_support, &columns),
            check: Some(CheckNumbers::of(scene)),
            oracle,
            columns,
        }
    }
}

/// The invariants of `scene` (the module's rules).
fn invariants(scene: &Scene, moving_support: bool) -> Vec<Invariant> {
    let gravity_only = scene.effects.iter().all(|e| e.gravity().is_some());
    let vertical_gravity = (scene.effects.iter())
        .filter_map(Effect::gravity)
        .all(|(g_s, _)| g_s.x == 0.0 && g_s.y == 0.0);
    let torque_free = scene.effects.is_empty();
    use Invariant::*;
    let motion = &scene.motion;
    match motion.kind() {
        MotionKind::Free => {
            let attribute = motion.attribute().map(|a| a.door());
            if attribute.is_some_and(|a| a.turns_momentum()) {
                return vec![];
            }
            // Internal drives (motors, a changing shape's, P_internal) change T, not H.
            let no_motor_work = attribute.is_none_or(|a| !a.does_work());
            let energy = if torque_free { Energy } else { EnergyTotal };
            let mut kept = Vec::new();
            if no_motor_work && gravity_only {
                kept.push(energy);
            }
            if torque_free {
                kept.extend([HSpaceX, HSpaceY, HSpaceZ, HNorm]);
            } else if gravity_only && vertical_gravity {
                kept.push(HSpaceZ);
            }
            kept
        }
        MotionKind::Hinge if moving_support => vec![],
        MotionKind::Hinge if torque_free => vec![Energy, HNorm],
        MotionKind::Hinge if gravity_only => vec![EnergyTotal],
        MotionKind::Hinge => vec![],
        MotionKind::FixedAxis
            if moving_support || motion.axis().is_some_and(|a| a.accel() != 0.0) =>
        {
            vec![]
        }
        MotionKind::FixedAxis => vec![Energy, HNorm],
    }
}

/// The panels of a run of `motion` writing `columns` ([`Facts::panels`]): the orbit's when it has their columns.
fn panels(motion: &Motion, moving_support: bool, columns: &ColumnSet) -> Vec<Panel> {
    let mut panels = Panel::ALL.to_vec();
    if let Some(axis) = motion.axis() {
        panels.extend([Panel::Theta, Panel::Support]);
        if axis.bearings().is_some() {
            panels.push(match moving_support {
                true => Panel::BearingsSpace,
                false => Panel::Bearings,
            });
        }
    }
    if let Some(attribute) = motion.attribute() {
        panels.extend(attribute.door().panels());
    }
    let names: Vec<String> = columns
        .columns()
        .iter()
        .map(|c| c.name.to_string())
        .collect();
    let has_all = |p: &Panel| p.columns().iter().all(|c| names.iter().any(|n| n == c));
    panels.extend(Panel::ORBIT.into_iter().chain(Panel::SHAPE).filter(has_all));
    panels
}
