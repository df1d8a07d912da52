//! What a scene conserves, the closed form that applies and the panels its runs have, as one typed value
//! ([`Facts`]) computed from the validated scene: the run's energy watch, the sidecar's `facts`, `check` and the
//! plot (its drift panel, the panels it draws by default) all read it instead of deciding again. This module
//! holds the value; [`Facts::of`] (`of.rs`) computes it from a scene.

mod numbers;
mod of;

use serde::{Deserialize, Serialize};

use super::oracle::{ClosedForm, Oracle};
use super::spec::MotionKind;
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
/// scene is built ([`crate::scene::Scene::facts`]); the sidecar writes the serialisable part under `facts`.
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
    /// The fixed step taken (s), for fixed-step methods ([`crate::scene::Scene::fixed_step`]).
    pub step_used: Option<f64>,
    /// Rows a run writes.
    pub rows: usize,
    /// The moment center, the axis and the state at t = 0 (written from 0.6.0).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub motion_numbers: Option<MotionNumbers>,
}

/// What `check` prints of the motion, at full precision.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct MotionNumbers {
    /// Which point the moment center O is.
    pub moment_center: MomentCenter,
    /// The principal moments about O (kg·m²), in [`crate::body::Principal`]'s order.
    pub principal_moments_o: [f64; 3],
    /// The fixed axis or hinge.
    pub axis: Option<AxisNumbers>,
    /// The state at t = 0 (free motion and a prescribed axis; a hinge's follows from its angle and rate).
    pub at_start: Option<StartNumbers>,
}

/// The point the moments of a scene are taken about.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum MomentCenter {
    /// The mass center C (free motion, or C on the fixed axis).
    MassCenter,
    /// The fixed pivot of a gravity effect.
    Pivot,
    /// The fixed axis's point, off C.
    AxisPoint,
}

/// A fixed axis or hinge: its tilt, rates, bearings and imbalance.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct AxisNumbers {
    /// The angle between the axis and the nearest principal direction about C (degrees).
    pub tilt_deg: f64,
    /// That principal axis (1-based), [`crate::body::Principal::tilt_of`].
    pub nearest_principal: usize,
    /// θ̇ at t = 0 (rad/s).
    pub rate: f64,
    /// θ̈ (rad/s²).
    pub accel: f64,
    /// I_uu = u·I_O u, the moment of inertia about the axis (kg·m²).
    pub i_uu: f64,
    /// A hinge's θ at t = 0 (rad).
    pub theta0: Option<f64>,
    /// The bearings, where the scene places them.
    pub bearings: Option<BearingNumbers>,
    /// The static imbalance m·e (kg·m).
    pub imbalance_static_kgm: f64,
    /// e, C's distance from the axis (m).
    pub imbalance_offset_m: f64,
    /// The dynamic imbalance |I_O u − (u·I_O u) u| (kg·m²).
    pub imbalance_dynamic_kgm2: f64,
}

/// Where bearings A and B sit: along the axis from its point (m), and from the reference origin (m, body axes).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct BearingNumbers {
    /// A's position along the axis.
    pub a: f64,
    /// B's position along the axis.
    pub b: f64,
    /// A from the reference origin.
    pub a_b: [f64; 3],
    /// B from the reference origin.
    pub b_b: [f64; 3],
}

/// The state at t = 0, about the moment center O.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct StartNumbers {
    /// ω (rad/s, body axes).
    pub omega_b: [f64; 3],
    /// H_O, the wheels' included (kg·m²/s, body axes).
    pub h_o_b: [f64; 3],
    /// H_O in space axes.
    pub h_o_s: [f64; 3],
    /// A prescribed axis: the moment M_O its support supplies (N·m, body axes).
    pub m_o_b: Option<[f64; 3]>,
    /// A prescribed axis with C off it: the force F = m a_C (N, space axes).
    pub f_s: Option<[f64; 3]>,
    /// The kinetic energy T, the wheels' included (J).
    pub energy: f64,
}

impl Facts {
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

#[cfg(test)]
mod tests {
    use super::Invariant::*;
    use super::*;
    use crate::scene::{Overrides, parse};

    /// The repository's bundled scenarios (this crate is core/ in the workspace).
    const SCENARIOS: &str = concat!(env!("CARGO_MANIFEST_DIR"), "/../scenarios");

    /// The facts of the bundled scenario `name` (scenarios/NAME.toml).
    fn facts_of(name: &str) -> Facts {
        let path = std::path::Path::new(SCENARIOS).join(format!("{name}.toml"));
        let text = std::fs::read_to_string(&path).expect("a bundled scenario");
        let scene = parse(&path, &text, &Overrides::default()).expect("a valid scene");
        scene.facts().clone()
    }

    /// The invariants of the bundled scenario `name`.
    fn of_scenario(name: &str) -> Vec<Invariant> {
        facts_of(name).invariants
    }

    /// The tilted disk (m = 2 kg, R = 0.3 m, ω = 10 rad/s, axis 30° from the symmetry axis): I₁ = ¼ m R² = 0.045,
    /// I₃ = ½ m R² = 0.09 kg·m²; about the axis I_uu = I₁ sin²θ + I₃ cos²θ = 0.07875 kg·m²; the product of inertia
    /// (dynamic imbalance) |d| = (I₃ − I₁) sin θ cos θ, and the bearings' moment |M| = |d| ω² = 1.9486 N·m (Rigid-body
    /// dynamics, lecture notes: the tilted disk, M = ω × H with H = I ω).
    #[test]
    fn check_numbers_give_the_axis_and_the_state_at_the_start() {
        let check = facts_of("tilted_disk").check.expect("numbers");
        let motion = check.motion_numbers.expect("motion numbers");
        let axis = motion.axis.expect("an axis");
        let (i1, i3, theta, omega) = (0.045, 0.09, 30f64.to_radians(), 10.0);
        let d = (i3 - i1) * theta.sin() * theta.cos();
        assert_eq!(motion.moment_center, MomentCenter::MassCenter);
        assert!((axis.tilt_deg - 30.0).abs() < 1e-9 && axis.nearest_principal == 3);
        assert!((axis.i_uu - (i1 * theta.sin().powi(2) + i3 * theta.cos().powi(2))).abs() < 1e-15);
        assert!((axis.imbalance_dynamic_kgm2 - d).abs() < 1e-15);
        assert_eq!((axis.imbalance_static_kgm, axis.theta0), (0.0, None));
        let start = motion.at_start.expect("a state at t = 0");
        let m = start.m_o_b.expect("the bearings' moment");
        let m_norm = (m[0] * m[0] + m[1] * m[1] + m[2] * m[2]).sqrt();
        assert!((m_norm - d * omega * omega).abs() < 1e-13, "{m_norm}");
        // The heavy top's moment center is its pivot, 5 cm below C.
        let top = facts_of("heavy_top").check.expect("numbers");
        let top_motion = top.motion_numbers.expect("motion numbers");
        assert_eq!(top_motion.moment_center, MomentCenter::Pivot);
        assert_eq!(top.moment_center_from_c_b, [0.0, 0.0, -0.05]);
        assert!(
            top_motion.axis.is_none() && top_motion.at_start.is_some_and(|s| s.m_o_b.is_none())
        );
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
        let groups = |name: &str| -> Vec<&'static str> {
            let facts = facts_of(name);
            facts.columns().groups.iter().map(|g| g.name).collect()
        };
        assert_eq!(groups("heavy_top"), ["potential"]);
        assert_eq!(
            groups("tilted_disk"),
            ["theta", "h_s_integrated", "support", "support"]
        );
    }

    /// A user's moment added to a built scene changes what it conserves: the facts are computed again (a
    /// torque-free body keeps neither T nor H_s under a moment, and no closed form applies).
    #[test]
    fn a_users_moment_recomputes_the_facts() {
        use crate::frames::Axes;
        use nalgebra::{UnitQuaternion, Vector3};
        let path = std::path::Path::new(SCENARIOS).join("tennis_racket.toml");
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
