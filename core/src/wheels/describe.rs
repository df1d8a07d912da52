//! The wheels' lines in `eulerdyn check`: each rotor (axis, J, spin, drive), its limits and friction, its
//! imbalance.

use super::gyrostat::{Drive, Gyrostat};
use super::{RPM, WheelControl};
use crate::text::{Description, for_people, line, vec3};

impl Gyrostat {
    /// Appends the rotors' lines to `w`: each wheel's axis, J, initial relative spin and drive, its limits and
    /// friction, its imbalance; the body's inertia is with them locked.
    pub fn describe(&self, w: &mut Description) {
        line(
            w,
            "rotors",
            &format!(
                "{} wheel(s) inside the body; the inertia above is the body with them locked, H = I omega + sum J Omega a",
                self.rotors().len()
            ),
        );
        for r in self.rotors() {
            let drive = match &r.drive {
                Drive::Accel(alpha) if *alpha == 0.0 => "constant relative spin".to_string(),
                Drive::Accel(alpha) => format!("spin prescribed, d(Omega)/dt = {alpha} rad/s^2"),
                Drive::Torque(_) => {
                    "driven by its motor torque (the body feels the opposite)".to_string()
                }
                Drive::Table(table) => format!(
                    "motor torque commanded by the table {}",
                    table.path().display()
                ),
                Drive::Law => format!(
                    "motor torque commanded by the wheel law \"{}\"",
                    self.law().map_or("", |law| law.name.as_str())
                ),
                Drive::Free => "free: no motor (friction only)".to_string(),
            };
            line(
                w,
                "",
                &format!(
                    "{}: axis {} (body axes), J = {} kg*m^2, Omega(0) = {} rad/s relative, {drive}",
                    r.name,
                    vec3(&r.axis_b.into_inner()),
                    for_people(r.inertia),
                    for_people(r.spin0)
                ),
            );
            r.control.describe(w);
            if let Some(u) = &r.imbalance {
                line(
                    w,
                    "",
                    &format!(
                        "  imbalance: static {} kg*m (a force U_s Omega^2), dynamic {} kg*m^2 (a couple U_d Omega^2), \
                         turning with the wheel from body direction {} at t = 0; wheel centre {} m from the moment center",
                        for_people(u.static_kgm),
                        for_people(u.dynamic_kgm2),
                        vec3(&u.w2_b),
                        vec3(&u.r_b)
                    ),
                );
            }
        }
    }

    /// Each wheel's imbalance as an effect on the body (a line of `check`'s effects): a force and a couple
    /// turning with the wheel.
    pub fn imbalance_effects(&self) -> Vec<String> {
        (self.rotors().iter())
            .filter_map(|r| {
                let u = r.imbalance.as_ref()?;
                Some(format!(
                    "imbalance of rotor {}: static {} kg*m, dynamic {} kg*m^2 (a force and a couple turning with the \
                     wheel, growing as its spin squared)",
                    r.name,
                    for_people(u.static_kgm),
                    for_people(u.dynamic_kgm2)
                ))
            })
            .collect()
    }
}

impl WheelControl {
    /// Appends the wheel's limits and friction to `w` (a continuation line), or nothing without any.
    ///
    /// ```
    /// use eulerdyn::text::Description;
    /// use eulerdyn::wheels::WheelControl;
    /// let mut w = Description::default();
    /// WheelControl::default().describe(&mut w);
    /// assert!(w.lines.is_empty());
    /// WheelControl { max_torque: 0.2, ..WheelControl::default() }.describe(&mut w);
    /// assert_eq!(w.lines[0].1, "motor torque within +-0.2 N*m");
    /// ```
    pub fn describe(&self, w: &mut Description) {
        let mut parts = Vec::new();
        if self.max_torque.is_finite() {
            parts.push(format!("motor torque within +-{} N*m", self.max_torque));
        }
        if self.max_speed.is_finite() {
            let rpm = self.max_speed / RPM;
            parts.push(format!("relative speed within +-{rpm} rpm"));
        }
        let f = &self.friction;
        if f.is_some() {
            parts.push(format!(
                "friction: Coulomb {} N*m, viscous {} N*m*s, Stribeck {} N*m over {} rad/s (dissipates energy, keeps H)",
                f.coulomb, f.viscous, f.stribeck_torque, f.stribeck_speed
            ));
        }
        if !parts.is_empty() {
            line(w, "", &parts.join("; "));
        }
    }
}
