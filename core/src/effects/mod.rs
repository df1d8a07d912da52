//! The effects a scene may call for. Only the effects a scene lists are simulated; none means torque-free.
//!
//! Each kind lives in its own folder (its keys, its spec as a scene gives it, its validated form and what it
//! answers through the door of `kind.rs`); `kinds.rs` registers them. Below the kinds: the door, what they compile
//! into (`compiling.rs`, with the shared `torque_sum.rs`, `table.rs` and `law.rs`); above them: the registry, the
//! compiled sum (`compiled.rs`), the list's validation and these queries, through which the rest of the library
//! asks an effect, so that no file outside this folder names a kind.

mod b_dot;
mod compiled;
mod compiling;
mod damping;
mod gravity;
mod gravity_gradient;
mod kind;
mod kinds;
mod law;
mod magnetic;
mod spec_builders;
mod table;
mod torque;
mod torque_sum;
mod torque_table;
mod user;
mod validate;

use nalgebra::{UnitQuaternion, Vector3};

pub use b_dot::{BDot, BDotSpec};
pub use compiled::{AppliedMoment, EffectMoments, TorqueFree};
pub use compiling::{AttitudeLaw, Compiling};
pub use damping::{Damping, DampingSpec};
pub use gravity::{DEFAULT_GRAVITY, Gravity, GravitySpec, potential_columns};
pub use gravity_gradient::{GravityGradient, GravityGradientSpec};
pub use kind::EffectKind;
pub use kinds::{Effect, EffectSpec};
pub use law::{MomentLaw, UserMoment};
pub use magnetic::{MagneticDipole, MagneticSpec};
pub(crate) use table::read_rows;
pub use table::{Interpolation, TABLE_HEADER, TorqueTable};
pub use torque::{TorqueGiven, TorqueSpec};
pub use torque_sum::TorqueSum;
pub use torque_table::{TabulatedTorque, TorqueTableSpec};
pub(crate) use validate::validate_effects;

use crate::orbit::{CircularOrbit, DipoleField};
use crate::sample::ColumnGroup;

/// What the rest of the library asks of an effect, each through its kind ([`Effect::door`]).
impl Effect {
    /// The name used in scene files.
    pub fn kind(&self) -> &'static str {
        self.door().kind()
    }

    /// What `check` and the run's sidecar call the effect: its [`kind`](Self::kind), and for the user's law
    /// `user:NAME`.
    pub fn label(&self) -> String {
        self.door().label()
    }

    /// The effect in words: its kind, values, axes and time profile.
    ///
    /// ```
    /// use eulerdyn::effects::{Damping, Effect};
    /// assert_eq!(Effect::Damping(Damping { c: 0.5 }).describe(), "viscous damping M = -0.5 N*m*s * omega");
    /// ```
    pub fn describe(&self) -> String {
        self.door().describe()
    }

    /// An upper bound of the moment's magnitude over all times, attitudes and rates on a body of mass `mass`
    /// (kg), N·m ([`EffectKind::largest_moment`]).
    pub fn largest_moment(&self, mass: f64) -> Option<f64> {
        self.door().largest_moment(mass)
    }

    /// Whether the moment depends on the body's mass distribution ([`EffectKind::uses_mass_distribution`]).
    pub fn uses_mass_distribution(&self) -> bool {
        self.door().uses_mass_distribution()
    }

    /// Gravity's g (space axes, m/s²) and the pivot from C (body axes, m), when this effect is gravity.
    pub fn gravity(&self) -> Option<(Vector3<f64>, Vector3<f64>)> {
        self.door().gravity()
    }

    /// c (N·m·s), when this effect is viscous damping M = −c ω.
    pub fn damping(&self) -> Option<f64> {
        self.door().damping()
    }

    /// Whether the moment's work has no known bound (the user's own law, [`MomentLaw`]).
    pub fn is_user(&self) -> bool {
        self.door().unbounded_work()
    }

    /// Whether the moment depends on ω other than as viscous damping (B-dot, the user's law): the splitting methods
    /// cannot apply it.
    pub fn depends_on_rate(&self) -> bool {
        self.door().depends_on_rate()
    }

    /// Gravity's potential on a body of mass `mass` at the attitude `q`: V = −m g·r_C, with r_C = q ρ_C the mass
    /// center from the pivot in space axes (ρ_C = −pivot); `None` for every other effect.
    pub fn potential(&self, mass: f64, q: &UnitQuaternion<f64>) -> Option<f64> {
        self.door().potential(mass, q)
    }

    /// The orbit and the Earth's field, when this effect acts in the field (`magnetic`, `b_dot`).
    pub fn field(&self) -> Option<(CircularOrbit, DipoleField)> {
        self.door().field()
    }

    /// The effect's own columns (B-dot's dipole), written after the orbit's and the field's.
    pub fn columns(&self) -> Option<ColumnGroup> {
        self.door().columns()
    }
}

/// The scene's gravity: g (space axes) and the pivot from C (body axes) of its gravity effect, if it has one.
pub fn gravity(effects: &[Effect]) -> Option<(Vector3<f64>, Vector3<f64>)> {
    effects.iter().find_map(Effect::gravity)
}
