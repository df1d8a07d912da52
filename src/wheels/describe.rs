//! A wheel's line in `eulerdyn check`: its limits and friction, when it has any.

use super::{RPM, WheelControl};
use crate::text::{Description, line};

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
