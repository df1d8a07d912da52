//! One `[[body.rotor]]` as Rust code gives it: the builders of a wheel's typed spec ([`RotorSpec`], declared with
//! its table in [`keys`](super::keys), validated in [`validate`](super::validate)) and its drive.

use crate::profile::Profile;
use crate::wheels::{RotorSpec, WheelKeys};

/// What drives a rotor's relative spin.
#[derive(Debug, Clone, PartialEq)]
pub enum RotorDrive {
    /// Neither `spin_accel` nor `torque`: the relative spin stays constant (the motor supplies what that takes).
    ConstantSpin,
    /// `spin_accel`: Ω(t) = spin + spin_accel·t (rad/s²); the motor torque is an output.
    SpinAccel(f64),
    /// `torque` (N·m) with a torque effect's `profile`: the motor torque on the wheel about its axis; the body
    /// feels its opposite.
    Torque {
        /// τ (N·m).
        value: f64,
        /// Its time profile.
        profile: Profile,
    },
    /// `torque_table`: the motor torque commanded by a table (header `t,torque`), relative to the scene file.
    Table(std::path::PathBuf),
    /// `mode = "free"`: no motor, the wheel spins freely (friction only).
    Free,
}

impl RotorDrive {
    /// The key that gives this drive in `[[body.rotor]]` (`None`: no key, a constant relative spin).
    ///
    /// ```
    /// use eulerdyn::scene::RotorDrive;
    /// assert_eq!((RotorDrive::Free.key(), RotorDrive::ConstantSpin.key()), (Some("mode"), None));
    /// ```
    pub fn key(&self) -> Option<&'static str> {
        match self {
            RotorDrive::ConstantSpin => None,
            RotorDrive::SpinAccel(_) => Some("spin_accel"),
            RotorDrive::Torque { .. } => Some("torque"),
            RotorDrive::Table(_) => Some("torque_table"),
            RotorDrive::Free => Some("mode"),
        }
    }
}

impl RotorSpec {
    /// A wheel of moment of inertia `inertia` (kg·m²) about `axis_b` (body axes) at the reference origin, spinning
    /// at `spin` (rad/s) relative to the body, kept constant.
    ///
    /// ```
    /// use eulerdyn::scene::{RotorDrive, RotorSpec};
    /// let wheel = RotorSpec::new([1.0, 0.0, 0.0], 0.01, 0.0).with_drive(RotorDrive::SpinAccel(2.0));
    /// assert_eq!(wheel.drive, RotorDrive::SpinAccel(2.0));
    /// ```
    pub fn new(axis_b: [f64; 3], inertia: f64, spin: f64) -> Self {
        Self {
            spin,
            ..Self::of(
                axis_b,
                inertia,
                RotorDrive::ConstantSpin,
                WheelKeys::default(),
            )
        }
    }

    /// With the static imbalance `static_gmm` (g·mm) and the dynamic imbalance `dynamic_gmm2` (g·mm²) of a wheel
    /// centred at `at` (m, body axes, from the reference origin).
    ///
    /// ```
    /// use eulerdyn::scene::RotorSpec;
    /// let wheel = RotorSpec::new([0.0, 0.0, 1.0], 0.01, 600.0).with_imbalance([0.1, 0.0, 0.0], 2.0, 50.0);
    /// assert_eq!((wheel.imbalance_static_gmm, wheel.imbalance_dynamic_gmm2), (2.0, 50.0));
    /// ```
    pub fn with_imbalance(mut self, at: [f64; 3], static_gmm: f64, dynamic_gmm2: f64) -> Self {
        self.at = at;
        self.imbalance_static_gmm = static_gmm;
        self.imbalance_dynamic_gmm2 = dynamic_gmm2;
        self
    }

    /// With `drive`.
    ///
    /// ```
    /// use eulerdyn::scene::{RotorDrive, RotorSpec};
    /// let wheel = RotorSpec::new([0.0, 0.0, 1.0], 0.01, 0.0).with_drive(RotorDrive::SpinAccel(2.0));
    /// assert_eq!(wheel.drive, RotorDrive::SpinAccel(2.0));
    /// ```
    pub fn with_drive(mut self, drive: RotorDrive) -> Self {
        self.drive = drive;
        self
    }

    /// With the limits and friction `wheel`.
    ///
    /// ```
    /// use eulerdyn::scene::RotorSpec;
    /// use eulerdyn::wheels::WheelKeys;
    /// let limits = WheelKeys { max_torque: Some(0.05), ..WheelKeys::default() };
    /// let wheel = RotorSpec::new([0.0, 0.0, 1.0], 0.01, 0.0).with_wheel(limits.clone());
    /// assert_eq!(wheel.wheel, limits);
    /// ```
    pub fn with_wheel(mut self, wheel: WheelKeys) -> Self {
        self.wheel = wheel;
        self
    }

    /// With `name`.
    ///
    /// ```
    /// use eulerdyn::scene::RotorSpec;
    /// let wheel = RotorSpec::new([0.0, 0.0, 1.0], 0.01, 0.0).with_name("wheel_z");
    /// assert_eq!(wheel.name.as_deref(), Some("wheel_z"));
    /// ```
    pub fn with_name(mut self, name: &str) -> Self {
        self.name = Some(name.to_string());
        self
    }
}
