//! The effects a scene may call for. Only the effects a scene lists are simulated; none means torque-free.

use std::sync::Arc;

use nalgebra::{Matrix3, Vector3};

mod columns;
mod compiled;
mod describe;
mod keys;
mod queries;
mod spec;
mod table;
mod user;
mod validate;

pub use columns::potential_columns;
pub use compiled::{AppliedMoment, EffectMoments, TorqueFree};
pub use queries::{TorqueGiven, gravity};
pub use spec::{EffectSpec, MagneticSpec, TorqueSpec, TorqueTableSpec};
pub use table::{Interpolation, TABLE_HEADER, TorqueTable};
pub use user::{MomentLaw, UserMoment};
pub(crate) use validate::validate_effects;

use crate::frames::Axes;
use crate::orbit::{CircularOrbit, DipoleField};
use crate::profile::Profile;
use crate::trig;

/// Gravity when a gravity effect leaves out `g`: (0, 0, −9.81) m/s², space axes (standard gravity along −z).
pub const DEFAULT_GRAVITY: [f64; 3] = [0.0, 0.0, -9.81];

/// One effect of the scene's `[[effect]]` list, validated.
#[derive(Debug, Clone, PartialEq)]
pub enum Effect {
    /// An applied torque (N·m), given in body or space axes, with a time profile.
    Torque {
        /// The axes `value` is given in.
        frame: Axes,
        /// The torque (N·m).
        value: Vector3<f64>,
        /// Its time profile.
        profile: Profile,
    },
    /// Uniform gravity g (space axes, m/s²) acting at C while the body turns about a fixed pivot
    /// (body axes, relative to C); the pivot becomes the moment center.
    Gravity {
        /// g (m/s², space axes).
        g_s: Vector3<f64>,
        /// The pivot from C (m, body axes).
        pivot_b: Vector3<f64>,
    },
    /// Viscous damping M = −c ω (N·m·s).
    Damping {
        /// c (N·m·s).
        c: f64,
    },
    /// A tabulated moment (N·m) in body or space axes, read from its file when the scene was validated.
    TorqueTable {
        /// The axes of the table's moments.
        frame: Axes,
        /// The table.
        table: Arc<TorqueTable>,
    },
    /// The gravity gradient of a circular orbit on a free body about C: M = 3n² n̂_b × (I n̂_b)
    /// ([`CircularOrbit::gravity_gradient_b`]).
    GravityGradient {
        /// The orbit.
        orbit: CircularOrbit,
        /// The body's inertia about C, body axes (kg·m²).
        inertia_c_b: Matrix3<f64>,
    },
    /// A residual dipole m (A·m², body axes) in the Earth's field along a circular orbit: M = m × B_b.
    Magnetic {
        /// The orbit.
        orbit: CircularOrbit,
        /// The Earth's field.
        field: DipoleField,
        /// m, body axes (A·m²).
        dipole_b: Vector3<f64>,
    },
    /// The user's own law ([`MomentLaw`]), named; added to a built scene by
    /// [`Scene::with_moment`](crate::scene::Scene::with_moment).
    User(UserMoment),
}

impl Effect {
    /// The name used in scene files.
    pub fn kind(&self) -> &'static str {
        match self {
            Effect::Torque { .. } => "torque",
            Effect::Gravity { .. } => "gravity",
            Effect::Damping { .. } => "damping",
            Effect::TorqueTable { .. } => "torque_table",
            Effect::GravityGradient { .. } => "gravity_gradient",
            Effect::Magnetic { .. } => "magnetic",
            Effect::User(_) => "user",
        }
    }

    /// What `check` and the run's sidecar call the effect: its [`kind`](Self::kind), and for the user's law
    /// `user:NAME`.
    pub fn label(&self) -> String {
        match self {
            Effect::User(user) => format!("user:{}", user.name),
            other => other.kind().to_string(),
        }
    }

    /// An upper bound of the moment's magnitude over all times and attitudes, on a body of mass `mass` (kg), N·m:
    /// |value| for a torque (every profile factor is at most 1 in magnitude), m |g| |pivot| for gravity (|ρ_C| =
    /// |pivot|), [`TorqueTable::largest_moment`] for a table, 3n²‖I‖ for a gravity gradient (|n̂ × I n̂| ≤ ‖I‖),
    /// |m| 2B₀(R/r)³ for a dipole in the Earth's field (its largest, over a pole);
    /// `None` for damping, whose moment −c ω depends on ω and
    /// whose power −c|ω|² is never positive, and for the user's law, which has no known bound.
    pub fn largest_moment(&self, mass: f64) -> Option<f64> {
        match self {
            Effect::Torque { value, .. } => Some(value.norm()),
            Effect::Gravity { g_s, pivot_b } => Some(mass * g_s.norm() * pivot_b.norm()),
            Effect::Damping { .. } => None,
            Effect::TorqueTable { table, .. } => Some(table.largest_moment()),
            Effect::GravityGradient { orbit, inertia_c_b } => {
                Some(3.0 * orbit.mean_motion().powi(2) * inertia_c_b.norm())
            }
            Effect::Magnetic {
                orbit,
                field,
                dipole_b,
            } => Some(dipole_b.norm() * field.largest_b(orbit.radius())),
            Effect::User(_) => None,
        }
    }
}

/// The torques of one frame summed, compiled once so that every evaluation does only the time-dependent
/// arithmetic: M(t) = Σ value_k · f_k(t) with the profiles of [`Profile`]. The constant torques are summed
/// into one vector, each sine keeps its angular frequency ω = 2π f (computed once, rounded as 2π·f·t would round
/// it), each step keeps its interval, each table is interpolated ([`TorqueTable::at`]).
#[derive(Debug, Clone, Default, PartialEq)]
pub struct TorqueSum {
    constant: Vector3<f64>,
    sines: Vec<SineTorque>,
    steps: Vec<StepTorque>,
    /// A boxed slice, two words: the scene's `Motion` holds a hinge's compiled effects and stays small.
    tables: Box<[Arc<TorqueTable>]>,
}

/// value · sin(ω t + φ).
#[derive(Debug, Clone, Copy, PartialEq)]
struct SineTorque {
    value: Vector3<f64>,
    omega_rad_s: f64,
    phase_rad: f64,
}

/// value for t_on ≤ t < t_off, else 0.
#[derive(Debug, Clone, Copy, PartialEq)]
struct StepTorque {
    value: Vector3<f64>,
    t_on: f64,
    t_off: f64,
}

impl TorqueSum {
    /// Adds the torque `value · f(t)`.
    pub fn add(&mut self, value: &Vector3<f64>, profile: &Profile) {
        match *profile {
            Profile::Constant => self.constant += value,
            Profile::Sine { freq_hz, phase_deg } => self.sines.push(SineTorque {
                value: *value,
                omega_rad_s: 2.0 * std::f64::consts::PI * freq_hz,
                phase_rad: phase_deg.to_radians(),
            }),
            Profile::Step { t_on, t_off } => self.steps.push(StepTorque {
                value: *value,
                t_on,
                t_off,
            }),
        }
    }

    /// Adds the tabulated torque `table`.
    pub fn add_table(&mut self, table: &Arc<TorqueTable>) {
        let mut tables = std::mem::take(&mut self.tables).into_vec();
        tables.push(Arc::clone(table));
        self.tables = tables.into_boxed_slice();
    }

    /// Whether the sum is zero at every time: no torque added, or only constant torques summing to zero.
    pub fn is_zero(&self) -> bool {
        self.constant == Vector3::zeros()
            && self.sines.is_empty()
            && self.steps.is_empty()
            && self.tables.is_empty()
    }

    /// The first corner of a table's moment later than `t` (s), where an adaptive method should end a step.
    pub fn corner_after(&self, t: f64) -> Option<f64> {
        (self.tables.iter())
            .filter_map(|table| table.corner_after(t))
            .min_by(f64::total_cmp)
    }

    /// M(t) = Σ value_k · f_k(t). Always inlined: a call at every Runge–Kutta stage would spill the state.
    #[inline(always)]
    pub fn at(&self, t: f64) -> Vector3<f64> {
        let mut m = self.constant;
        for sine in &self.sines {
            m += sine.value * trig::sin(sine.omega_rad_s * t + sine.phase_rad);
        }
        for step in &self.steps {
            if step.t_on <= t && t < step.t_off {
                m += step.value;
            }
        }
        for table in &self.tables {
            m += table.at(t);
        }
        m
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_torque_sum_is_the_sum_of_its_profiles() {
        let (a, b, c) = (
            Vector3::new(0.5, 0.0, -0.25),
            Vector3::new(0.0, 2.0, 1.0),
            Vector3::new(-1.0, 0.5, 0.0),
        );
        let mut sum = TorqueSum::default();
        assert!(sum.is_zero());
        sum.add(&a, &Profile::Constant);
        sum.add(&a, &Profile::Constant);
        sum.add(
            &b,
            &Profile::Sine {
                freq_hz: 0.5,
                phase_deg: 30.0,
            },
        );
        sum.add(
            &c,
            &Profile::Step {
                t_on: 1.0,
                t_off: 2.0,
            },
        );
        assert!(!sum.is_zero());
        for t in [0.0, 0.9, 1.0, 1.5, 2.0, 7.3] {
            // The sine as the profile defines it, by the crate's inline sine (tested against the library's in
            // `trig`).
            let sine = trig::sin(2.0 * std::f64::consts::PI * 0.5 * t + 30f64.to_radians());
            let step = if (1.0..2.0).contains(&t) { 1.0 } else { 0.0 };
            // Each term is computed as the profile defines it; only the order of the sum differs (exact here:
            // the constant part 2a is exact and the other terms are added one by one as before).
            assert_eq!(sum.at(t), a * 2.0 + b * sine + c * step, "t = {t}");
        }
    }

    #[test]
    fn constant_torques_that_cancel_sum_to_zero() {
        let mut sum = TorqueSum::default();
        let a = Vector3::new(0.5, -1.0, 2.0);
        sum.add(&a, &Profile::Constant);
        sum.add(&-a, &Profile::Constant);
        assert!(sum.is_zero());
        assert_eq!(sum.at(3.0), Vector3::zeros());
    }
}
