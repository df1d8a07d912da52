//! `type = "gravity_gradient"`: the gravity gradient of the scene's circular orbit on a free body about C,
//! M = 3n² n̂_b × (I n̂_b) ([`CircularOrbit::gravity_gradient_b`]).

use nalgebra::{Matrix3, Vector3};

use super::compiling::{AttitudeLaw, Compiling};
use super::kind::{EffectKind, KindSpec, NoKeys, Placement, SharedKeys};
use crate::keys::{Checked, KeyPath};
use crate::orbit::CircularOrbit;
use crate::text::for_people;

/// `type = "gravity_gradient"`: no keys; the orbit is the scene's and the inertia the body's.
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct GravityGradientSpec;

impl KindSpec for GravityGradientSpec {
    type Keys = NoKeys;
    type Effect = GravityGradient;

    /// The gradient: no keys.
    fn read(_: &NoKeys, _: &SharedKeys, _: &KeyPath, _: &str) -> Checked<Self> {
        Ok(GravityGradientSpec)
    }

    /// No keys.
    fn write(&self, _: &mut SharedKeys) -> NoKeys {
        NoKeys {}
    }

    /// The gradient validated: an orbit and a free body, whose inertia about C it takes.
    fn validate(&self, at: &KeyPath, on: &Placement) -> Checked<GravityGradient> {
        Ok(GravityGradient {
            orbit: on.in_orbit(at, "gravity_gradient")?,
            inertia_c_b: *on.inertia_c_b,
        })
    }
}

/// The gravity gradient of a circular orbit on a free body of inertia I about C (body axes, kg·m²).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct GravityGradient {
    /// The orbit.
    pub orbit: CircularOrbit,
    /// The body's inertia about C, body axes (kg·m²).
    pub inertia_c_b: Matrix3<f64>,
}

impl EffectKind for GravityGradient {
    fn kind(&self) -> &'static str {
        "gravity_gradient"
    }

    fn is_orbit_gravity(&self) -> bool {
        true
    }

    fn uses_mass_distribution(&self) -> bool {
        true
    }

    fn describe(&self) -> String {
        format!(
            "gravity gradient of the circular orbit r = {} km (n = {} rad/s): M = 3 n^2 nadir_b x (I nadir_b)",
            for_people(self.orbit.radius() / 1e3),
            for_people(self.orbit.mean_motion())
        )
    }

    /// 3n²‖I‖, since |n̂ × I n̂| ≤ ‖I‖.
    fn largest_moment(&self, _mass: f64) -> Option<f64> {
        Some(3.0 * self.orbit.mean_motion().powi(2) * self.inertia_c_b.norm())
    }

    fn size_key(&self) -> &'static str {
        "type"
    }

    fn compile(&self, into: &mut Compiling) {
        into.attitude_law(std::sync::Arc::new(*self));
    }
}

impl AttitudeLaw for GravityGradient {
    /// n̂_s(t), nadir.
    fn vector_s(&self, t: f64) -> Vector3<f64> {
        self.orbit.nadir_s(t)
    }

    /// 3n² n̂_b × (I n̂_b).
    fn moment_b(&self, nadir_b: &Vector3<f64>) -> Vector3<f64> {
        (self.orbit).gravity_gradient_b(nadir_b, &self.inertia_c_b)
    }
}
