//! A user's wheel law given to a built gyrostat (`Scene::with_wheel_law`): every wheel must be free of a driver of
//! its own, and the law must give one torque per wheel (it is called once, at t = 0, to check).

use nalgebra::{UnitQuaternion, Vector3};

use super::RotorSpec;
use super::gyrostat::Gyrostat;
use super::{WheelInputs, WheelLaw, WheelTorqueLaw};
use crate::keys::{Checked, Invalid, KeyPath, invalid};

impl Gyrostat {
    /// The gyrostat with the law `law`, named `name`, commanding every wheel; `specs` are its wheels as the scene
    /// gives them (`[[body.rotor]]`, for the key a refusal names), `q0` and `omega0_b` the state at t = 0.
    pub(crate) fn take_law(
        &self,
        specs: &[RotorSpec],
        name: &str,
        law: impl WheelLaw + 'static,
        (q0, omega0_b): (&UnitQuaternion<f64>, &Vector3<f64>),
    ) -> Checked<Gyrostat> {
        let rotors = || KeyPath::root().key("body").key("rotor");
        no_wheel_has_a_driver(specs, name)?;
        if name.trim().is_empty() {
            return invalid(
                rotors(),
                "a wheel law needs a name (what check and the sidecar call it)",
            );
        }
        let spins0: Vec<f64> = self.rotors().iter().map(|r| r.spin0).collect();
        let now = WheelInputs {
            t: 0.0,
            q: q0,
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
        (self.clone())
            .with_law(WheelTorqueLaw::new(name, law))
            .map_err(|e| Invalid {
                key: rotors(),
                problem: e.to_string(),
            })
    }
}

/// Refuses the law `name` when a wheel of `specs` has its own driver, naming that driver's key.
fn no_wheel_has_a_driver(specs: &[RotorSpec], name: &str) -> Checked<()> {
    for (k, rotor) in specs.iter().enumerate() {
        let Some(driver) = rotor.drive.key() else {
            continue;
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
    Ok(())
}
