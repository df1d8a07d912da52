//! A built scene whose wheels are driven by the user's wheel law ([`WheelLaw`]), which a scene file cannot hold.

use super::model::Scene;
use super::source_map::KeyPath;
use super::validate::InvalidScene;
use crate::keys::invalid;
use crate::wheels::WheelLaw;

impl Scene {
    /// The scene with the wheel law `law` commanding the motor torque of every wheel (`[[body.rotor]]`), named
    /// `name`: τ_cmd = law(t, q, ω_b, spins), one torque per wheel in the scene's order, then each wheel's
    /// `max_torque`, `max_speed_rpm` and friction apply (`crate::wheels`). A wheel with its own driver
    /// (`torque`, `spin_accel`, `torque_table`, `mode = "free"`) is an error naming that wheel, and so is a law
    /// that gives another number of torques than there are wheels (it is called once at t = 0 to check).
    ///
    /// ```
    /// use eulerdyn::scene::{BodySpec, RotorSpec, SceneSpec};
    /// use nalgebra::{UnitQuaternion, Vector3};
    ///
    /// // One wheel about z driven by a PD law: (I − J) θ̈ = −τ with τ = −(k_p (θ_t − θ) − k_d ω_z).
    /// let body = BodySpec::principal(10.0, [1.0, 1.0, 1.0]).with_rotor(RotorSpec::new([0.0, 0.0, 1.0], 0.1, 0.0));
    /// let pd = |_t: f64, q: &UnitQuaternion<f64>, omega_b: &Vector3<f64>, _spins: &[f64]| {
    ///     let theta = q.scaled_axis().z;
    ///     vec![-(2.0 * (0.5 - theta) - 3.0 * omega_b.z)]
    /// };
    /// let scene = SceneSpec::new(body, 30.0, 1.0).build()?.with_wheel_law("pd", pd)?;
    /// let (samples, _) = eulerdyn::simulate::samples(&scene)?;
    /// assert!((samples.last().unwrap().q.scaled_axis().z - 0.5).abs() < 1e-3);
    /// # Ok::<(), Box<dyn std::error::Error>>(())
    /// ```
    pub fn with_wheel_law(
        mut self,
        name: &str,
        law: impl WheelLaw + 'static,
    ) -> Result<Scene, InvalidScene> {
        let Some((g, omega0_b)) = self.motion.gyrostat_mut() else {
            return invalid(
                KeyPath::root().key("body").key("rotor"),
                format!("the wheel law \"{name}\" needs a free body with wheels ([[body.rotor]])"),
            );
        };
        let start = (&self.attitude0, &**omega0_b);
        *g = g.take_law(&self.spec.body.rotor, name, law, start)?;
        Ok(self)
    }
}
