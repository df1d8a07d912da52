//! What a scene conserves, the closed form that applies and the panels its runs have, as one typed value
//! ([`Facts`]) computed from the validated scene: the run's energy watch, the sidecar's `facts`, `check` and the
//! plot (its drift panel, the panels it draws by default) all read it instead of deciding again.
//!
//! The invariants (Rigid-body dynamics, lecture notes, Thms 24–25; Landau & Lifshitz §§33–35):
//! - free motion with no effect: H_s (Ḣ_s = M_s = 0, whatever the rotors' motors do: their torques are internal),
//!   hence |H|; and T when no motor does work (no rotors, or every wheel spinning freely);
//! - free motion about a fixed pivot under gravity alone: T + V when no motor does work, and H_s,z when g is along
//!   space z (gravity's moment r × m g is horizontal);
//! - a hinge: T with no effect, T + V under gravity alone;
//! - a prescribed fixed axis turning steadily: T and |H| (H_s turns with the body; its magnitude does not);
//! - nothing with torques, damping or a user's law, an accelerating prescribed axis, a turning carrier (which
//!   does work on the body), or an imbalanced wheel (its turning moment changes H and T).

use nalgebra::Matrix3;
use serde::{Deserialize, Serialize};

use super::model::{Motion, Scene};
use super::oracle::{ClosedForm, Oracle};
use super::spec::MotionKind;
use crate::effects::Effect;
use crate::panel::Panel;
use crate::sample::ColumnSet;

/// One conserved quantity, named by its CSV column.
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord, Hash, Serialize, Deserialize)]
pub enum Invariant {
    /// The kinetic energy T (`energy`, J).
    #[serde(rename = "energy")]
    Energy,
    /// T + V (`energy_total`, J), under gravity.
    #[serde(rename = "energy_total")]
    EnergyTotal,
    /// |H| (`H_norm`, kg·m²/s).
    #[serde(rename = "H_norm")]
    HNorm,
    /// H_s,x (`H_s_x`, kg·m²/s, space axes).
    #[serde(rename = "H_s_x")]
    HSpaceX,
    /// H_s,y (`H_s_y`).
    #[serde(rename = "H_s_y")]
    HSpaceY,
    /// H_s,z (`H_s_z`).
    #[serde(rename = "H_s_z")]
    HSpaceZ,
}

impl Invariant {
    /// The CSV column that holds it.
    ///
    /// ```
    /// use eulerdyn::scene::Invariant;
    /// assert_eq!(Invariant::HSpaceZ.column(), "H_s_z");
    /// ```
    pub fn column(self) -> &'static str {
        match self {
            Invariant::Energy => "energy",
            Invariant::EnergyTotal => "energy_total",
            Invariant::HNorm => "H_norm",
            Invariant::HSpaceX => "H_s_x",
            Invariant::HSpaceY => "H_s_y",
            Invariant::HSpaceZ => "H_s_z",
        }
    }
}

/// What a scene conserves (the module's rules), in the order: energy, then momentum; the closed form that
/// applies, evaluated once; the columns and panels its runs have; the numbers `check` prints. Computed when the
/// scene is built ([`Scene::facts`]); the sidecar writes the serialisable part under `facts`.
#[derive(Debug, Clone, Default, PartialEq, Serialize, Deserialize)]
pub struct Facts {
    /// The conserved quantities, by their columns (`energy`, `H_s_x`…`H_s_z`, `H_norm` for a torque-free body;
    /// `energy_total` and `H_s_z` for a heavy top).
    pub invariants: Vec<Invariant>,
    /// The closed form that applies ([`Oracle::for_scene`]), if any: what `compare`, the accuracy study and
    /// `score` measure runs against.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub closed_form: Option<ClosedForm>,
    /// The axis's support moves in space ([`crate::motion::moving_support`]: a carrier): it does work on the body,
    /// and the bearing loads are read in space axes (written only when true).
    #[serde(default, skip_serializing_if = "std::ops::Not::not")]
    pub moving_support: bool,
    /// The panels `eulerdyn plot` draws of a run when none are asked for, in order (names as `--panels` takes
    /// them): the six every run has; θ and the support's force on an axis, with its bearings' forces (in space
    /// axes when the support moves); the wheels' spin and torque with rotors. Empty in a sidecar written before
    /// 0.4, whose plot reads them from the CSV's header.
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub panels: Vec<Panel>,
    /// The numbers `check` prints, at full precision (`check --json` writes them at its top level). `None` in a
    /// sidecar written before 0.5.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub check: Option<CheckNumbers>,
    /// The closed form itself ([`Facts::oracle`]); not written (the sidecar names it by `closed_form`).
    #[serde(skip)]
    oracle: Option<Oracle>,
    /// The optional columns a run writes ([`Facts::columns`]); not written here (the sidecar lists every column
    /// at its top level, `columns`).
    #[serde(skip)]
    columns: ColumnSet,
}

/// The numbers `check` prints about a scene, at full precision (SI units; body axes unless the name says
/// otherwise).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct CheckNumbers {
    /// kg.
    pub mass: f64,
    /// The mass center C from the reference origin (m).
    pub center_b: [f64; 3],
    /// The inertia tensor about C (kg·m²), rows; off-diagonal entries are −∫ x y dm.
    pub inertia_c_b: [[f64; 3]; 3],
    /// Principal moments about C (kg·m²), in [`crate::body::Principal`]'s order.
    pub principal_moments_c: [f64; 3],
    /// The principal axes (columns; rows written out), body axes.
    pub principal_axes_b: [[f64; 3]; 3],
    /// `free`, `fixed_axis` or `hinge`.
    pub motion: MotionKind,
    /// The moment center O (C, a gravity pivot, or the axis point) from C (m).
    pub moment_center_from_c_b: [f64; 3],
    /// The inertia tensor about O (kg·m²), rows.
    pub inertia_o_b: [[f64; 3]; 3],
    /// The fixed axis (unit, body axes), for a fixed axis or hinge.
    pub axis_b: Option<[f64; 3]>,
    /// The fixed step taken (s), for fixed-step methods ([`Scene::fixed_step`]).
    pub step_used: Option<f64>,
    /// Rows a run writes.
    pub rows: usize,
}

impl CheckNumbers {
    /// The numbers of `scene`.
    fn of(scene: &Scene) -> Self {
        let inertia_c = scene.body.inertia_c();
        let principal = scene.body.principal();
        let (rho_c_b, inertia_o_b) = scene.motion.about_moment_center();
        CheckNumbers {
            mass: scene.body.mass(),
            center_b: scene.center_b.into(),
            inertia_c_b: rows_of(inertia_c),
            principal_moments_c: principal.moments.into(),
            principal_axes_b: rows_of(principal.axes_b.matrix()),
            motion: scene.motion.kind(),
            moment_center_from_c_b: (-rho_c_b).into(),
            inertia_o_b: rows_of(&inertia_o_b),
            axis_b: scene.motion.axis().map(|a| a.axis_b().into_inner().into()),
            step_used: scene.fixed_step(),
            rows: scene.schedule.len(),
        }
    }
}

/// The rows of `m`.
fn rows_of(m: &Matrix3<f64>) -> [[f64; 3]; 3] {
    std::array::from_fn(|r| std::array::from_fn(|c| m[(r, c)]))
}

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
        Facts {
            invariants: invariants(scene, moving_support),
            closed_form: oracle.as_ref().map(Oracle::kind),
            moving_support,
            panels: panels(&scene.motion, moving_support),
            check: Some(CheckNumbers::of(scene)),
            oracle,
            columns: Scene::run_columns(&scene.motion, &scene.effects),
        }
    }

    /// Whether the scene conserves `invariant`.
    pub fn conserves(&self, invariant: Invariant) -> bool {
        self.invariants.contains(&invariant)
    }

    /// The conserved energy (T or T + V), if any: what the run's energy watch follows.
    pub fn conserved_energy(&self) -> Option<Invariant> {
        (self.invariants.iter())
            .copied()
            .find(|i| matches!(i, Invariant::Energy | Invariant::EnergyTotal))
    }

    /// The closed form that applies, as evaluated when the scene was built: what `compare`, the accuracy study
    /// and `score` measure runs against (`None` without one, and in facts read back from a sidecar).
    pub fn oracle(&self) -> Option<&Oracle> {
        self.oracle.as_ref()
    }

    /// The optional columns a run writes (θ, the support's, the potential's, the capabilities' groups); empty in
    /// facts read back from a sidecar, whose `columns` list them all.
    pub fn columns(&self) -> &ColumnSet {
        &self.columns
    }
}

/// The invariants of `scene` (the module's rules).
fn invariants(scene: &Scene, moving_support: bool) -> Vec<Invariant> {
    let gravity_only = scene
        .effects
        .iter()
        .all(|e| matches!(e, Effect::Gravity { .. }));
    let vertical_gravity = scene.effects.iter().all(|e| match e {
        Effect::Gravity { g_s, .. } => g_s.x == 0.0 && g_s.y == 0.0,
        _ => true,
    });
    let torque_free = scene.effects.is_empty();
    use Invariant::*;
    match &scene.motion {
        Motion::Free { gyrostat, .. } => {
            if gyrostat.as_ref().is_some_and(|g| g.imbalanced()) {
                vec![]
            } else {
                let no_motor_work = gyrostat.as_ref().is_none_or(|g| g.wheels_spin_freely());
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
        }
        Motion::Hinge(_) if moving_support => vec![],
        Motion::Hinge(_) if torque_free => vec![Energy, HNorm],
        Motion::Hinge(_) if gravity_only => vec![EnergyTotal],
        Motion::Hinge(_) => vec![],
        Motion::FixedAxis(axis) if moving_support || axis.accel() != 0.0 => vec![],
        Motion::FixedAxis(_) => vec![Energy, HNorm],
    }
}

/// The panels of a run of `motion` ([`Facts::panels`]).
fn panels(motion: &Motion, moving_support: bool) -> Vec<Panel> {
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
    if let Motion::Free {
        gyrostat: Some(_), ..
    } = motion
    {
        panels.extend(Panel::WHEELS);
    }
    panels
}

#[cfg(test)]
mod tests {
    use super::Invariant::*;
    use super::*;
    use crate::scene::{Overrides, parse};

    /// The facts of the bundled scenario `name` (scenarios/NAME.toml).
    fn facts_of(name: &str) -> Facts {
        let path = std::path::PathBuf::from(format!("scenarios/{name}.toml"));
        let text = std::fs::read_to_string(&path).expect("a bundled scenario");
        let scene = parse(&path, &text, &Overrides::default()).expect("a valid scene");
        scene.facts().clone()
    }

    /// The invariants of the bundled scenario `name`.
    fn of_scenario(name: &str) -> Vec<Invariant> {
        facts_of(name).invariants
    }

    #[test]
    fn each_motion_conserves_what_its_equations_say() {
        // Torque-free: T and H_s (Landau & Lifshitz §§33–35), so |H| too.
        let torque_free = vec![Energy, HSpaceX, HSpaceY, HSpaceZ, HNorm];
        assert_eq!(of_scenario("tennis_racket"), torque_free);
        // A heavy top about its pivot: T + V and H_s,z (gravity's moment is horizontal).
        assert_eq!(of_scenario("heavy_top"), vec![EnergyTotal, HSpaceZ]);
        // A hinge under gravity alone: T + V.
        assert_eq!(of_scenario("rod_pendulum"), vec![EnergyTotal]);
        // A steady prescribed axis: T and |H|; accelerating, or in a turning carrier: nothing.
        assert_eq!(of_scenario("tilted_disk"), vec![Energy, HNorm]);
        assert_eq!(of_scenario("disk_spin_up"), vec![]);
        assert_eq!(of_scenario("turbine_yawing_aircraft"), vec![]);
        // A sine torque or damping: nothing.
        assert_eq!(of_scenario("sine_torque"), vec![]);
        assert_eq!(of_scenario("damped_spin"), vec![]);
        // A gyrostat whose wheels hold their relative spin (a motor at work): H_s, not T.
        assert_eq!(
            of_scenario("kelvin_gyrostat"),
            vec![HSpaceX, HSpaceY, HSpaceZ, HNorm]
        );
    }

    /// The closed form each bundled scenario is measured against (`Oracle::for_scene`'s conditions): a torque-free
    /// body (Landau & Lifshitz §37), a prescribed axis (H_s = I_s(θ) ω_s, eq. 8.10), a damped principal spin; none
    /// for a heavy top or a hinge.
    #[test]
    fn the_facts_name_the_closed_form_that_applies() {
        let closed_form = |name: &str| facts_of(name).closed_form;
        assert_eq!(closed_form("tennis_racket"), Some(ClosedForm::TorqueFree));
        assert_eq!(closed_form("tilted_disk"), Some(ClosedForm::FixedAxis));
        assert_eq!(closed_form("damped_spin"), Some(ClosedForm::DampedSpin));
        assert_eq!(closed_form("heavy_top"), None);
        assert_eq!(closed_form("rod_pendulum"), None);
    }

    /// The closed form is evaluated once, with the scene: the facts hold it and name it by its kind; the columns
    /// are those a run writes (a heavy top's potential, a disk's θ and support).
    #[test]
    fn the_facts_hold_the_closed_form_and_the_columns_they_name() {
        for name in ["tennis_racket", "tilted_disk", "damped_spin", "heavy_top"] {
            let facts = facts_of(name);
            assert_eq!(
                facts.oracle().map(Oracle::kind),
                facts.closed_form,
                "{name}"
            );
        }
        assert!(facts_of("heavy_top").columns().potential);
        let disk = facts_of("tilted_disk");
        assert!(disk.columns().theta && disk.columns().support && !disk.columns().potential);
    }

    /// A user's moment added to a built scene changes what it conserves: the facts are computed again (a
    /// torque-free body keeps neither T nor H_s under a moment, and no closed form applies).
    #[test]
    fn a_users_moment_recomputes_the_facts() {
        use crate::frames::Axes;
        use nalgebra::{UnitQuaternion, Vector3};
        let path = std::path::PathBuf::from("scenarios/tennis_racket.toml");
        let text = std::fs::read_to_string(&path).expect("a bundled scenario");
        let scene = parse(&path, &text, &Overrides::default()).expect("a valid scene");
        assert!(scene.facts().oracle().is_some());
        let push =
            |_t: f64, _q: &UnitQuaternion<f64>, _w: &Vector3<f64>| Vector3::new(0.0, 0.0, 0.1);
        let pushed = scene.with_moment("push", Axes::Body, push).expect("a law");
        assert_eq!(pushed.facts().invariants, vec![]);
        assert_eq!(pushed.facts().closed_form, None);
        assert!(pushed.facts().oracle().is_none());
    }

    /// A carrier moves the axis's support (`MovingSupport`); a prescribed axis fixed in space and a free body have
    /// none.
    #[test]
    fn the_facts_say_when_the_support_moves() {
        assert!(facts_of("turbine_yawing_aircraft").moving_support);
        assert!(!facts_of("tilted_disk").moving_support);
        assert!(!facts_of("tennis_racket").moving_support);
    }

    #[test]
    fn the_conserved_energy_is_t_or_t_plus_v() {
        let facts = |invariants| Facts {
            invariants,
            ..Facts::default()
        };
        assert_eq!(facts(vec![Energy, HNorm]).conserved_energy(), Some(Energy));
        assert_eq!(
            facts(vec![EnergyTotal, HSpaceZ]).conserved_energy(),
            Some(EnergyTotal)
        );
        assert_eq!(facts(vec![HSpaceZ]).conserved_energy(), None);
    }

    #[test]
    fn the_sidecar_names_the_invariants_by_their_columns() {
        let json = serde_json::to_string(&Facts {
            invariants: vec![EnergyTotal, HSpaceZ],
            ..Facts::default()
        })
        .unwrap();
        assert_eq!(json, r#"{"invariants":["energy_total","H_s_z"]}"#);
    }
}
