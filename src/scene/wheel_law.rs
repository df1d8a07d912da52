//! A built scene whose wheels are driven by the user's wheel law ([`WheelLaw`]), which a scene file cannot hold.

use super::model::{Motion, Scene};
use super::source_map::KeyPath;
use super::spec::RotorDrive;
use super::validate::InvalidScene;
use crate::keys::{Checked, invalid};
use crate::wheels::{WheelInputs, WheelLaw, WheelTorqueLaw};

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
        let rotors = || KeyPath::root().key("body").key("rotor");
        self.wheels_take_a_law(name)?;
        let Motion::Free {
            gyrostat: Some(g),
            omega0_b,
            ..
        } = &mut self.motion
        else {
            return invalid(
                rotors(),
                format!("the wheel law \"{name}\" needs a free body with wheels ([[body.rotor]])"),
            );
        };
        let spins0: Vec<f64> = g.rotors().iter().map(|r| r.spin0).collect();
        let now = WheelInputs {
            t: 0.0,
            q: &self.attitude0,
            omega_b: omega0_b,
            spins: &spins0,
        };
        let given = law.torques(&now).len();
        if given != spins0.len() {
            return invalid(
                rotors(),
                format!(
                    "the wheel law \"{name}\" gives {given} torque(s), the body has {} wheel(s): one torque per \
                     wheel, in the scene's order",
                    spins0.len()
                ),
            );
        }
        let law = WheelTorqueLaw::new(name, law);
        **g = (**g).clone().with_law(law).map_err(|e| InvalidScene {
            key: rotors(),
            problem: e.to_string(),
        })?;
        Ok(self)
    }

    /// Whether every wheel can take the law `name`: none has its own driver.
    fn wheels_take_a_law(&self, name: &str) -> Checked<()> {
        for (k, rotor) in self.spec.body.rotor.iter().enumerate() {
            let driver = match rotor.drive {
                RotorDrive::ConstantSpin => continue,
                RotorDrive::SpinAccel(_) => "spin_accel",
                RotorDrive::Torque { .. } => "torque",
                RotorDrive::Table(_) => "torque_table",
                RotorDrive::Free => "mode",
            };
            let wheel = rotor.name.clone().unwrap_or_else(|| format!("rotor{k}"));
            return invalid(
                KeyPath::root()
                    .key("body")
                    .key("rotor")
                    .index(k)
                    .key(driver),
                format!(
                    "the wheel `{wheel}` has its own driver (`{driver}`), so the wheel law \"{name}\" cannot drive \
                     it: remove `{driver}` or give the law only a body whose wheels have no driver"
                ),
            );
        }
        if name.trim().is_empty() {
            return invalid(
                KeyPath::root().key("body").key("rotor"),
                "a wheel law needs a name (what check and the sidecar call it)",
            );
        }
        Ok(())
    }
}
