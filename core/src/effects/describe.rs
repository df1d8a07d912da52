//! An effect's line in `eulerdyn check`: what it is, its values and their axes.

use super::Effect;
use crate::profile::Profile;
use crate::text::{for_people, plain, vec3};

impl Effect {
    /// The effect in words: its kind, values, axes and time profile.
    ///
    /// ```
    /// use eulerdyn::effects::Effect;
    /// assert_eq!(Effect::Damping { c: 0.5 }.describe(), "viscous damping M = -0.5 N*m*s * omega");
    /// ```
    pub fn describe(&self) -> String {
        match self {
            Effect::Torque {
                frame,
                value,
                profile,
            } => {
                let profile = match profile {
                    Profile::Constant => "constant".to_string(),
                    Profile::Sine { freq_hz, phase_deg } => {
                        format!(
                            "sine at {} Hz, phase {} deg",
                            plain(*freq_hz),
                            plain(*phase_deg)
                        )
                    }
                    Profile::Step { t_on, t_off } => {
                        format!("step, on for {} <= t < {} s", plain(*t_on), plain(*t_off))
                    }
                };
                format!(
                    "torque {} N*m in {} axes, {profile}",
                    vec3(value),
                    frame.name()
                )
            }
            Effect::Gravity { g_s, pivot_b } => format!(
                "gravity g = {} m/s^2 (space axes) at C, pivot {} m from C (body axes)",
                vec3(g_s),
                vec3(pivot_b)
            ),
            Effect::Damping { c } => format!("viscous damping M = -{} N*m*s * omega", plain(*c)),
            Effect::TorqueTable { frame, table } => {
                let (t0, t1) = table.time_range();
                format!(
                    "torque table {} ({} rows, {} <= t <= {} s, {} interpolation, zero outside) in {} axes",
                    table.path().display(),
                    table.rows(),
                    plain(t0),
                    plain(t1),
                    table.interpolation().name(),
                    frame.name()
                )
            }
            Effect::GravityGradient { orbit, .. } => format!(
                "gravity gradient of the circular orbit r = {} km (n = {} rad/s): M = 3 n^2 nadir_b x (I nadir_b)",
                for_people(orbit.radius() / 1e3),
                for_people(orbit.mean_motion())
            ),
            Effect::Magnetic {
                field, dipole_b, ..
            } => format!(
                "magnetic: residual dipole {} A*m^2 (body axes) in a centred dipole field, B0 = {} T on the equator at \
                 the surface: M = m x B_b",
                vec3(dipole_b),
                for_people(field.b0())
            ),
            Effect::User(user) => format!(
                "user's moment law \"{}\" (a Rust or Python function of t, q, omega) in {} axes",
                user.name,
                user.frame.name()
            ),
        }
    }
}
