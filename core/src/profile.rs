//! A time profile p(t) that multiplies a value: an applied torque's, a rotor motor's, a carrier's rate and its
//! vehicle's acceleration. One type from the scene file to the equations: read from its keys (`profile`,
//! `freq_hz`, `phase_deg`, `t_on`, `t_off`), checked, evaluated and written back.
//!
//! ```text
//!   constant   p(t) = 1
//!   sine       p(t) = sin(2π f t + φ)
//!   step       p(t) = 1 for t_on ≤ t < t_off, else 0
//! ```

use serde::{Deserialize, Serialize};

use crate::keys::{Checked, KeyPath, Keys, finite, invalid};
use crate::text::plain;

/// A time profile p(t) ([module doc](self)).
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Profile {
    /// `profile = "constant"`: p = 1.
    Constant,
    /// `profile = "sine"`: p = sin(2π f t + φ).
    Sine {
        /// `freq_hz`: f, Hz, ≥ 0.
        freq_hz: f64,
        /// `phase_deg`: φ in degrees (absent: 0).
        phase_deg: f64,
    },
    /// `profile = "step"`: p = 1 for t_on ≤ t < t_off, zero otherwise.
    Step {
        /// `t_on`: s (absent: 0).
        t_on: f64,
        /// `t_off`: s, later than t_on (absent: never, +∞).
        t_off: f64,
    },
}

/// The `profile` key's values, as the reference lists them.
pub(crate) const PROFILES: &str = "\"constant\" | \"sine\" | \"step\"";

/// The `profile` key: which profile the other keys describe.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub(crate) enum ProfileKind {
    Constant,
    Sine,
    Step,
}

/// A profile's keys as a table gives them (each absent as `None`), spliced into a table that has them
/// (`#[key(flatten)]`: a torque effect, a wheel's motor).
#[derive(Debug, Clone, Copy, Default, PartialEq, Keys)]
pub(crate) struct ProfileKeys {
    /// the moment's time profile p(t): 1, sin(2π freq_hz t + phase_deg), or 1 for t_on ≤ t < t_off (else 0)
    #[key(kind = PROFILES, shown = "\"constant\"")]
    pub(crate) profile: Option<ProfileKind>,
    /// ≥ 0
    #[key(unit = "Hz", shown = "required for `sine`")]
    pub(crate) freq_hz: Option<f64>,
    /// `sine` only
    #[key(unit = "deg", shown = "0")]
    pub(crate) phase_deg: Option<f64>,
    /// `step` only
    #[key(unit = "s", shown = "0")]
    pub(crate) t_on: Option<f64>,
    /// `step` only; > t_on
    #[key(unit = "s", shown = "never")]
    pub(crate) t_off: Option<f64>,
}

/// The profile in words, as `eulerdyn check` prints it after the value it multiplies.
///
/// ```
/// use eulerdyn::profile::Profile;
/// let sine = Profile::Sine { freq_hz: 0.5, phase_deg: 90.0 };
/// assert_eq!(sine.to_string(), "times sin(2 pi 0.5 Hz t + 90 deg)");
/// assert_eq!(Profile::Constant.to_string(), "constant");
/// ```
impl std::fmt::Display for Profile {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match *self {
            Profile::Constant => write!(f, "constant"),
            Profile::Sine { freq_hz, phase_deg } => write!(
                f,
                "times sin(2 pi {} Hz t + {} deg)",
                plain(freq_hz),
                plain(phase_deg)
            ),
            Profile::Step { t_on, t_off } => {
                write!(f, "times 1 for {} <= t < {} s", plain(t_on), plain(t_off))
            }
        }
    }
}

impl Profile {
    /// p(t), with the standard library's sine.
    ///
    /// ```
    /// use eulerdyn::profile::Profile;
    /// let step = Profile::Step { t_on: 1.0, t_off: 2.0 };
    /// assert_eq!((step.at(0.5), step.at(1.0), step.at(2.0)), (0.0, 1.0, 0.0));
    /// let sine = Profile::Sine { freq_hz: 0.25, phase_deg: 0.0 };
    /// assert!((sine.at(1.0) - 1.0).abs() < 1e-15);
    /// ```
    pub fn at(&self, t: f64) -> f64 {
        match *self {
            Profile::Constant => 1.0,
            Profile::Sine { .. } => {
                let (omega, phase) = self.sine_rad().unwrap_or_default();
                (omega * t + phase).sin()
            }
            Profile::Step { t_on, t_off } => f64::from(u8::from(t_on <= t && t < t_off)),
        }
    }

    /// A sine's ω = 2π f (rad/s) and φ (rad); `None` for the others.
    pub fn sine_rad(&self) -> Option<(f64, f64)> {
        match *self {
            Profile::Sine { freq_hz, phase_deg } => {
                Some((std::f64::consts::TAU * freq_hz, phase_deg.to_radians()))
            }
            _ => None,
        }
    }

    /// The profile the keys under `table` give, for `what` (a sine torque, a carrier): each kind's keys only
    /// with it, a sine's `freq_hz` required.
    pub(crate) fn read(table: &KeyPath, keys: &ProfileKeys, what: &str) -> Checked<Profile> {
        let key = |name: &str| table.clone().key(name);
        let misplaced = |name: &str, present: bool, kind: &str| -> Checked<()> {
            if present {
                invalid(
                    key(name),
                    format!("`{name}` applies to profile = \"{kind}\" only"),
                )
            } else {
                Ok(())
            }
        };
        let sine_keys = |kind| {
            misplaced("freq_hz", keys.freq_hz.is_some(), kind)?;
            misplaced("phase_deg", keys.phase_deg.is_some(), kind)
        };
        let step_keys = |kind| {
            misplaced("t_on", keys.t_on.is_some(), kind)?;
            misplaced("t_off", keys.t_off.is_some(), kind)
        };
        Ok(match keys.profile.unwrap_or(ProfileKind::Constant) {
            ProfileKind::Constant => {
                sine_keys("sine")?;
                step_keys("step")?;
                Profile::Constant
            }
            ProfileKind::Sine => {
                step_keys("step")?;
                let Some(freq_hz) = keys.freq_hz else {
                    return invalid(
                        key("freq_hz"),
                        format!("{what} needs `freq_hz` (Hz, finite, >= 0)"),
                    );
                };
                Profile::Sine {
                    freq_hz,
                    phase_deg: keys.phase_deg.unwrap_or(0.0),
                }
            }
            ProfileKind::Step => {
                sine_keys("sine")?;
                Profile::Step {
                    t_on: keys.t_on.unwrap_or(0.0),
                    t_off: keys.t_off.unwrap_or(f64::INFINITY),
                }
            }
        })
    }

    /// The keys that give this profile back (an absent `t_off`, +∞, left out).
    pub(crate) fn keys(&self) -> ProfileKeys {
        match *self {
            Profile::Constant => ProfileKeys {
                profile: Some(ProfileKind::Constant),
                ..ProfileKeys::default()
            },
            Profile::Sine { freq_hz, phase_deg } => ProfileKeys {
                profile: Some(ProfileKind::Sine),
                freq_hz: Some(freq_hz),
                phase_deg: Some(phase_deg),
                ..ProfileKeys::default()
            },
            Profile::Step { t_on, t_off } => ProfileKeys {
                profile: Some(ProfileKind::Step),
                t_on: Some(t_on),
                t_off: Some(t_off).filter(|t| *t != f64::INFINITY),
                ..ProfileKeys::default()
            },
        }
    }

    /// The profile's values checked (its keys under `table`): a sine's frequency finite and ≥ 0 and its phase
    /// finite, a step's `t_on` finite and `t_off` later.
    pub(crate) fn checked(self, table: &KeyPath) -> Checked<Profile> {
        let key = |name: &str| table.clone().key(name);
        match self {
            Profile::Constant => {}
            Profile::Sine { freq_hz, phase_deg } => {
                let f = finite(key("freq_hz"), freq_hz, "Hz")?;
                if f < 0.0 {
                    return invalid(key("freq_hz"), format!("must be >= 0 (Hz), got {f:?}"));
                }
                finite(key("phase_deg"), phase_deg, "degrees")?;
            }
            Profile::Step { t_on, t_off } => {
                let t_on = finite(key("t_on"), t_on, "s")?;
                if t_off.is_nan() || t_off <= t_on {
                    return invalid(
                        key("t_off"),
                        format!("must be later than t_on = {t_on:?} s, got {t_off:?}"),
                    );
                }
            }
        }
        Ok(self)
    }
}
