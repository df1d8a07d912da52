//! What the rest of the library asks of an effect, answered here: facts, closed forms, validation, the suite and
//! the 3D page read an effect through these, so that the variants of [`Effect`] are matched in this folder only.

use nalgebra::{UnitQuaternion, Vector3};

use super::Effect;
use crate::frames::Axes;
use crate::orbit::{CircularOrbit, DipoleField};
use crate::profile::Profile;

/// An applied torque as given: its axes, value (N·m) and time profile.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct TorqueGiven {
    /// The axes `value` is given in.
    pub frame: Axes,
    /// The torque (N·m).
    pub value: Vector3<f64>,
    /// Its time profile.
    pub profile: Profile,
}

impl Effect {
    /// Gravity's g (space axes, m/s²) and the pivot from C (body axes, m), when this effect is gravity.
    pub fn gravity(&self) -> Option<(Vector3<f64>, Vector3<f64>)> {
        match self {
            Effect::Gravity { g_s, pivot_b } => Some((*g_s, *pivot_b)),
            _ => None,
        }
    }

    /// The torque as given, when this effect is an applied torque (not a table).
    pub fn torque(&self) -> Option<TorqueGiven> {
        match *self {
            Effect::Torque {
                frame,
                value,
                profile,
            } => Some(TorqueGiven {
                frame,
                value,
                profile,
            }),
            _ => None,
        }
    }

    /// c (N·m·s), when this effect is viscous damping M = −c ω.
    pub fn damping(&self) -> Option<f64> {
        match self {
            Effect::Damping { c } => Some(*c),
            _ => None,
        }
    }

    /// Whether this is the user's own law ([`super::MomentLaw`]), whose work has no known bound.
    pub fn is_user(&self) -> bool {
        matches!(self, Effect::User(_))
    }

    /// Gravity's potential on a body of mass `mass` at the attitude `q`: V = −m g·r_C, with r_C = q ρ_C the mass
    /// center from the pivot in space axes (ρ_C = −pivot); `None` for every other effect.
    pub fn potential(&self, mass: f64, q: &UnitQuaternion<f64>) -> Option<f64> {
        self.gravity()
            .map(|(g_s, pivot_b)| -mass * g_s.dot(&(q * -pivot_b)))
    }
}

impl From<TorqueGiven> for Effect {
    /// The applied torque `value · f(t)` in `frame`, as a scene's `[[effect]] type = "torque"` gives it.
    ///
    /// ```
    /// use eulerdyn::effects::{Effect, TorqueGiven};
    /// use eulerdyn::frames::Axes;
    /// use eulerdyn::profile::Profile;
    /// use nalgebra::Vector3;
    ///
    /// let given = TorqueGiven { frame: Axes::Space, value: Vector3::new(0.0, 0.0, 0.1), profile: Profile::Constant };
    /// assert_eq!(Effect::from(given).torque(), Some(given));
    /// ```
    fn from(given: TorqueGiven) -> Self {
        Effect::Torque {
            frame: given.frame,
            value: given.value,
            profile: given.profile,
        }
    }
}

impl From<super::UserMoment> for Effect {
    /// The user's own law as an effect ([`crate::scene::Scene::with_moment`] adds it).
    fn from(user: super::UserMoment) -> Self {
        Effect::User(user)
    }
}

impl Effect {
    /// The orbit and the Earth's field, when this effect is a dipole in the field.
    pub fn field(&self) -> Option<(CircularOrbit, DipoleField)> {
        match self {
            Effect::Magnetic { orbit, field, .. } => Some((*orbit, *field)),
            _ => None,
        }
    }
}

/// The scene's gravity: g (space axes) and the pivot from C (body axes) of its gravity effect, if it has one.
pub fn gravity(effects: &[Effect]) -> Option<(Vector3<f64>, Vector3<f64>)> {
    effects.iter().find_map(Effect::gravity)
}
