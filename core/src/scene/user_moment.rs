//! A built scene with one more effect: the user's own moment law ([`MomentLaw`]), which a scene file cannot hold.

use super::facts::Facts;
use super::model::Scene;
use super::source_map::KeyPath;
use super::validate::InvalidScene;
use crate::effects::{Effect, MomentLaw, UserMoment};
use crate::frames::Axes;
use crate::keys::{Checked, invalid};

impl Scene {
    /// The scene with the user's law `law` acting too: its moment M(t, q, ω_b) (N·m) given in `axes`, named
    /// `name` in `check` and in the run's sidecar (as `user:NAME`). The run calls it at every right-hand-side
    /// evaluation through the same compiled effects as the scene's own.
    ///
    /// Only a free body with a Runge–Kutta method (rk4, dopri5, dop853) takes one: a prescribed axis computes its
    /// moment, a hinge's moments are compiled at validation, split2/split4 apply only moments that do not depend
    /// on ω, and `exact` is torque-free. The divergence guard, which bounds the effects' work by their largest
    /// moment, is off for such a run (a law has no known bound).
    ///
    /// ```
    /// use eulerdyn::frames::Axes;
    /// use eulerdyn::scene::{BodySpec, SceneSpec};
    /// use nalgebra::{UnitQuaternion, Vector3};
    ///
    /// // A PD attitude controller, M = −k_p θ_err·axis − k_d ω, turning a body about z to θ = 0.5 rad.
    /// let (k_p, k_d) = (4.0, 4.0);
    /// let target = UnitQuaternion::from_axis_angle(&Vector3::z_axis(), 0.5);
    /// let pd = move |_t: f64, q: &UnitQuaternion<f64>, omega_b: &Vector3<f64>| {
    ///     let error = q.rotation_to(&target); // the turn that remains, space axes
    ///     let error_b = q.inverse_transform_vector(&error.scaled_axis());
    ///     error_b * k_p - omega_b * k_d
    /// };
    /// let scene = SceneSpec::new(BodySpec::principal(1.0, [1.0, 1.0, 1.0]), 10.0, 0.5)
    ///     .build()?
    ///     .with_moment("pd", Axes::Body, pd)?;
    /// let (samples, _) = eulerdyn::simulate::samples(&scene)?;
    /// let q_end = samples.last().unwrap().q;
    /// assert!(q_end.angle_to(&target) < 1e-3);
    /// # Ok::<(), Box<dyn std::error::Error>>(())
    /// ```
    pub fn with_moment(
        mut self,
        name: &str,
        axes: Axes,
        law: impl MomentLaw + 'static,
    ) -> Result<Scene, InvalidScene> {
        self.takes_a_law(name)?;
        let user = UserMoment::new(name, axes, law);
        self.effects.push(Effect::from(user));
        self.facts = Facts::of(&self);
        Ok(self)
    }

    /// Whether this scene's motion and method can run a user's law called `name`.
    fn takes_a_law(&self, name: &str) -> Checked<()> {
        let key = KeyPath::root().key("effect").index(self.effects.len());
        if name.trim().is_empty() {
            return invalid(
                key,
                "a user's moment needs a name (what check and the sidecar call it)",
            );
        }
        if !self.motion.is_free() {
            return invalid(
                KeyPath::root().key("motion").key("type"),
                format!(
                    "the user's moment \"{name}\" needs a free body: a fixed axis computes its moment from the \
                     motion, and a hinge's moments are fixed when its scene is built"
                ),
            );
        }
        if !self.solver.method.is_runge_kutta() {
            return invalid(
                KeyPath::root().key("solver").key("method"),
                format!(
                    "method \"{}\" cannot apply the user's moment \"{name}\" (split2/split4 apply only moments that \
                     do not depend on omega; exact is torque-free): use rk4, dopri5 or dop853",
                    self.solver.method.name()
                ),
            );
        }
        Ok(())
    }
}
