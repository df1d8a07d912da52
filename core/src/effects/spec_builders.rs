//! Shorthands for the common effects as a scene gives them: gravity about a pivot or on an axis, viscous damping.

use super::damping::DampingSpec;
use super::gravity::{DEFAULT_GRAVITY, GravitySpec};
use super::kinds::EffectSpec;

impl EffectSpec {
    /// Uniform gravity `g_s` (m/s², space axes) acting at C, the free body turning about `pivot_b` (body axes,
    /// from the reference origin, m).
    ///
    /// ```
    /// use eulerdyn::scene::EffectSpec;
    /// let top = EffectSpec::gravity([0.0, 0.0, -9.81], [0.0, 0.0, -0.05]);
    /// assert_eq!(top.kind(), "gravity");
    /// ```
    pub fn gravity(g_s: [f64; 3], pivot_b: [f64; 3]) -> Self {
        EffectSpec::Gravity(GravitySpec {
            g: g_s,
            pivot: Some(pivot_b),
        })
    }

    /// Uniform gravity `g_s` (m/s², space axes) acting at C of a body on a fixed axis or hinge, whose axis point
    /// is the moment center (no pivot).
    ///
    /// ```
    /// use eulerdyn::effects::{EffectSpec, GravitySpec};
    /// let weight = EffectSpec::weight([0.0, -9.81, 0.0]);
    /// assert_eq!(weight, EffectSpec::Gravity(GravitySpec { g: [0.0, -9.81, 0.0], pivot: None }));
    /// ```
    pub fn weight(g_s: [f64; 3]) -> Self {
        EffectSpec::Gravity(GravitySpec {
            g: g_s,
            pivot: None,
        })
    }

    /// Standard gravity [`DEFAULT_GRAVITY`] on a body on a fixed axis or hinge (what `type = "gravity"` without `g`
    /// means).
    ///
    /// ```
    /// use eulerdyn::scene::EffectSpec;
    /// assert_eq!(EffectSpec::standard_weight(), EffectSpec::weight([0.0, 0.0, -9.81]));
    /// ```
    pub fn standard_weight() -> Self {
        Self::weight(DEFAULT_GRAVITY)
    }

    /// Viscous damping M = −c ω, `c` in N·m·s.
    ///
    /// ```
    /// use eulerdyn::effects::{DampingSpec, EffectSpec};
    /// assert_eq!(EffectSpec::damping(0.1), EffectSpec::Damping(DampingSpec { c: 0.1 }));
    /// ```
    pub fn damping(c: f64) -> Self {
        EffectSpec::Damping(DampingSpec { c })
    }
}
