//! `type = "torque"`: an applied torque `value · p(t)` (N·m) in body or space axes, with a time profile p
//! ([`Profile`]).

use nalgebra::Vector3;

use super::compiling::Compiling;
use super::kind::{EffectKind, KindSpec, Placement, SharedKeys};
use crate::frames::Axes;
use crate::keys::{Checked, KeyPath, Keys, required, vector};
use crate::profile::{Profile, ProfileKeys};
use crate::text::vec3;

/// A torque's keys (with `frame`, which a torque table shares, in the registry's table).
#[derive(Debug, Clone, Copy, Default, PartialEq, Keys)]
pub(crate) struct TorqueKeys {
    /// the torque (amplitude for `sine`)
    #[key(unit = "N·m", shown = "required for `torque`")]
    pub(crate) value: Option<[f64; 3]>,
    /// torque: value·p(t)
    #[key(flatten)]
    pub(crate) profile: ProfileKeys,
}

/// `type = "torque"`: `value` in `frame` axes times its time profile.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct TorqueSpec {
    /// `frame`: the axes the value is given in (absent: body).
    pub frame: Axes,
    /// `value`: N·m.
    pub value: [f64; 3],
    /// `profile` and its keys (absent: constant).
    pub profile: Profile,
}

impl TorqueSpec {
    /// A constant torque `value` (N·m) in `axes`.
    ///
    /// ```
    /// use eulerdyn::frames::Axes;
    /// use eulerdyn::{profile::Profile, scene::TorqueSpec};
    /// let t = TorqueSpec::new(Axes::Space, [0.0, 0.0, 0.2]);
    /// assert_eq!(t.profile, Profile::Constant);
    /// ```
    pub fn new(axes: Axes, value: [f64; 3]) -> Self {
        Self {
            frame: axes,
            value,
            profile: Profile::Constant,
        }
    }

    /// This torque times sin(2π f t + φ), f = `freq_hz`, φ = `phase_deg`.
    ///
    /// ```
    /// use eulerdyn::frames::Axes;
    /// use eulerdyn::{profile::Profile, scene::TorqueSpec};
    /// let t = TorqueSpec::new(Axes::Body, [0.0, 0.0, 1.0]).sine(2.0, 90.0);
    /// assert_eq!(t.profile, Profile::Sine { freq_hz: 2.0, phase_deg: 90.0 });
    /// ```
    pub fn sine(mut self, freq_hz: f64, phase_deg: f64) -> Self {
        self.profile = Profile::Sine { freq_hz, phase_deg };
        self
    }

    /// This torque for t_on ≤ t < t_off only.
    ///
    /// ```
    /// use eulerdyn::frames::Axes;
    /// use eulerdyn::{profile::Profile, scene::TorqueSpec};
    /// let t = TorqueSpec::new(Axes::Body, [0.0, 0.0, 1.0]).step(0.5, 1.5);
    /// assert_eq!(t.profile, Profile::Step { t_on: 0.5, t_off: 1.5 });
    /// ```
    pub fn step(mut self, t_on: f64, t_off: f64) -> Self {
        self.profile = Profile::Step { t_on, t_off };
        self
    }
}

impl KindSpec for TorqueSpec {
    type Keys = TorqueKeys;
    type Effect = TorqueGiven;

    /// The torque as its keys give it, in the table's `frame` (body axes unless given).
    fn read(
        keys: &TorqueKeys,
        shared: &SharedKeys,
        at: &KeyPath,
        kind_text: &str,
    ) -> Checked<Self> {
        Ok(TorqueSpec {
            frame: shared.frame.unwrap_or(Axes::Body),
            value: required(at.clone().key("value"), keys.value, kind_text)?,
            profile: Profile::read(at, &keys.profile, "a sine torque")?,
        })
    }

    /// Its keys and the table's `frame`.
    fn write(&self, shared: &mut SharedKeys) -> TorqueKeys {
        shared.frame = Some(self.frame);
        TorqueKeys {
            value: Some(self.value),
            profile: self.profile.keys(),
        }
    }

    /// The torque validated, its table at `at`: a finite value and a valid profile.
    fn validate(&self, at: &KeyPath, _on: &Placement) -> Checked<TorqueGiven> {
        let profile = self.profile.checked(at)?;
        Ok(TorqueGiven {
            frame: self.frame,
            value: vector(at.clone().key("value"), self.value, "N*m")?,
            profile,
        })
    }
}

/// An applied torque, validated: its axes, value (N·m) and time profile.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct TorqueGiven {
    /// The axes `value` is given in.
    pub frame: Axes,
    /// The torque (N·m).
    pub value: Vector3<f64>,
    /// Its time profile.
    pub profile: Profile,
}

impl EffectKind for TorqueGiven {
    fn kind(&self) -> &'static str {
        "torque"
    }

    fn describe(&self) -> String {
        let profile = match self.profile {
            Profile::Constant => "constant".to_string(),
            Profile::Sine { freq_hz, phase_deg } => {
                format!(
                    "sine at {} Hz, phase {} deg",
                    crate::text::plain(freq_hz),
                    crate::text::plain(phase_deg)
                )
            }
            Profile::Step { t_on, t_off } => format!(
                "step, on for {} <= t < {} s",
                crate::text::plain(t_on),
                crate::text::plain(t_off)
            ),
        };
        format!(
            "torque {} N*m in {} axes, {profile}",
            vec3(&self.value),
            self.frame.name()
        )
    }

    /// |value|: every profile factor is at most 1 in magnitude.
    fn largest_moment(&self, _mass: f64) -> Option<f64> {
        Some(self.value.norm())
    }

    fn compile(&self, into: &mut Compiling) {
        into.torques(self.frame).add(&self.value, &self.profile);
    }
}
