//! `type = "gravity"`: uniform gravity g acting at C while the body turns about a fixed point, the moment center:
//! M = ρ_C × m Rᵀg, ρ_C = −pivot the mass center from the pivot (body axes); its potential V = −m g·r_C and the
//! columns that write it.

mod columns;

use nalgebra::{UnitQuaternion, Vector3};

pub use columns::potential_columns;

use super::compiling::Compiling;
use super::kind::{EffectKind, KindSpec, Placement, SharedKeys};
use crate::keys::{Checked, KeyPath, Keys, invalid, vector};
use crate::text::vec3;

/// Gravity when a gravity effect leaves out `g`: (0, 0, −9.81) m/s², space axes (standard gravity along −z).
pub const DEFAULT_GRAVITY: [f64; 3] = [0.0, 0.0, -9.81];

/// Gravity's keys.
#[derive(Debug, Clone, Copy, Default, PartialEq, Keys)]
pub(crate) struct GravityKeys {
    /// gravity: uniform, space axes, acting at C
    #[key(unit = "m/s²", shown = "[0, 0, -9.81]")]
    pub(crate) g: Option<[f64; 3]>,
    /// gravity: the fixed point, which becomes the moment center (an error with a fixed axis or hinge)
    #[key(position, shown = "required for free motion")]
    pub(crate) pivot: Option<[f64; 3]>,
}

/// `type = "gravity"`: uniform gravity acting at C.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct GravitySpec {
    /// `g`: m/s², space axes (absent: [`DEFAULT_GRAVITY`]).
    pub g: [f64; 3],
    /// `pivot`: the fixed point of a free body, body axes, from the reference origin (m); absent on a fixed axis
    /// or hinge, whose axis point is the moment center.
    pub pivot: Option<[f64; 3]>,
}

impl KindSpec for GravitySpec {
    type Keys = GravityKeys;
    type Effect = Gravity;

    /// Gravity as its keys give it.
    fn read(keys: &GravityKeys, _: &SharedKeys, _: &KeyPath, _: &str) -> Checked<Self> {
        Ok(GravitySpec {
            g: keys.g.unwrap_or(DEFAULT_GRAVITY),
            pivot: keys.pivot,
        })
    }

    /// Its keys.
    fn write(&self, _: &mut SharedKeys) -> GravityKeys {
        GravityKeys {
            g: Some(self.g),
            pivot: self.pivot,
        }
    }

    /// Gravity validated, its table at `at`, placed `on` the body: its moment center the pivot of a free body or
    /// the axis point of a fixed axis or hinge.
    fn validate(&self, at: &KeyPath, on: &Placement) -> Checked<Gravity> {
        let key = |name: &str| at.clone().key(name);
        Ok(Gravity {
            g_s: vector(key("g"), self.g, "m/s^2")?,
            pivot_b: match (on.axis_point_b, self.pivot) {
                (Some(_), Some(_)) => {
                    return invalid(
                        key("pivot"),
                        "with a fixed axis or a hinge the moment center is the axis point (`motion.point`): remove `pivot`",
                    );
                }
                (Some(point_b), None) => *point_b,
                (None, Some(pivot)) => vector(key("pivot"), pivot, "m")? - on.center_b,
                (None, None) => {
                    return invalid(
                        key("pivot"),
                        "missing: effect type = \"gravity\" needs `pivot`",
                    );
                }
            },
        })
    }
}

/// Uniform gravity g (space axes, m/s²) acting at C while the body turns about a fixed pivot (body axes, relative
/// to C); the pivot becomes the moment center.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Gravity {
    /// g (m/s², space axes).
    pub g_s: Vector3<f64>,
    /// The pivot from C (m, body axes).
    pub pivot_b: Vector3<f64>,
}

impl EffectKind for Gravity {
    fn kind(&self) -> &'static str {
        "gravity"
    }

    fn uses_mass_distribution(&self) -> bool {
        true
    }

    fn describe(&self) -> String {
        format!(
            "gravity g = {} m/s^2 (space axes) at C, pivot {} m from C (body axes)",
            vec3(&self.g_s),
            vec3(&self.pivot_b)
        )
    }

    /// m |g| |pivot|, since |ρ_C| = |pivot|.
    fn largest_moment(&self, mass: f64) -> Option<f64> {
        Some(mass * self.g_s.norm() * self.pivot_b.norm())
    }

    fn size_key(&self) -> &'static str {
        "g"
    }

    fn compile(&self, into: &mut Compiling) {
        into.uniform_gravity(self.g_s, -self.pivot_b);
    }

    fn gravity(&self) -> Option<(Vector3<f64>, Vector3<f64>)> {
        Some((self.g_s, self.pivot_b))
    }

    /// V = −m g·r_C, with r_C = q ρ_C the mass center from the pivot in space axes (ρ_C = −pivot).
    fn potential(&self, mass: f64, q: &UnitQuaternion<f64>) -> Option<f64> {
        Some(-mass * self.g_s.dot(&(q * -self.pivot_b)))
    }
}
