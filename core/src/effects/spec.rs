//! One `[[effect]]` as Rust code gives it: an applied torque with its time profile, uniform gravity, viscous
//! damping, a tabulated torque (read from and written to its file form in `keys.rs`, validated in `validate.rs`).

use std::path::{Path, PathBuf};

use super::{DEFAULT_GRAVITY, Interpolation};
use crate::frames::Axes;
use crate::profile::Profile;

/// One `[[effect]]`, by its `type`.
#[derive(Debug, Clone, PartialEq)]
pub enum EffectSpec {
    /// `type = "torque"`.
    Torque(TorqueSpec),
    /// `type = "gravity"`: uniform gravity acting at C.
    Gravity {
        /// `g`: m/s², space axes (absent: [`DEFAULT_GRAVITY`]).
        g: [f64; 3],
        /// `pivot`: the fixed point of a free body, body axes, from the reference origin (m); absent on a fixed
        /// axis or hinge, whose axis point is the moment center.
        pivot: Option<[f64; 3]>,
    },
    /// `type = "damping"`: M = −c ω.
    Damping {
        /// `c`: N·m·s, ≥ 0.
        c: f64,
    },
    /// `type = "torque_table"`: a moment tabulated in a CSV file.
    TorqueTable(TorqueTableSpec),
    /// `type = "gravity_gradient"`: the gravity gradient of the scene's `[orbit]` on a free body.
    GravityGradient,
    /// `type = "magnetic"`: the moment m × B of the body's residual dipole in the Earth's field along the orbit.
    Magnetic(MagneticSpec),
}

/// `type = "magnetic"`: a residual dipole in a centred-dipole Earth field ([`crate::orbit::DipoleField`]).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct MagneticSpec {
    /// `dipole`: the body's residual dipole, body axes (A·m²; absent: zero).
    pub dipole: [f64; 3],
    /// `field_tilt_deg`: the field dipole's tilt from the Earth's axis (deg; absent: 0).
    pub field_tilt_deg: f64,
    /// `field_lon_deg`: the longitude a tilted dipole leans toward at t = 0 (deg; absent: 0).
    pub field_lon_deg: f64,
    /// `field_b0`: the field on the equator at the surface (T; absent: [`crate::orbit::DEFAULT_B0`]).
    pub field_b0: f64,
}

impl MagneticSpec {
    /// A residual dipole `dipole` (A·m², body axes) in the default field, aligned with the Earth's axis.
    ///
    /// ```
    /// use eulerdyn::scene::{EffectSpec, MagneticSpec};
    /// let spec = EffectSpec::from(MagneticSpec::new([0.0, 0.0, 0.05]));
    /// assert_eq!(spec.kind(), "magnetic");
    /// ```
    pub fn new(dipole: [f64; 3]) -> Self {
        MagneticSpec {
            dipole,
            field_tilt_deg: 0.0,
            field_lon_deg: 0.0,
            field_b0: crate::orbit::DEFAULT_B0,
        }
    }
}

impl From<MagneticSpec> for EffectSpec {
    fn from(magnetic: MagneticSpec) -> Self {
        EffectSpec::Magnetic(magnetic)
    }
}

/// `type = "torque_table"`: the rows (t, M_x, M_y, M_z) of `file`, interpolated, zero outside the table's range.
#[derive(Debug, Clone, PartialEq)]
pub struct TorqueTableSpec {
    /// `file`: the CSV (header `t,M_x,M_y,M_z`). A scene file's reader joins a relative path to the scene file's
    /// directory; a scene built in code reads it relative to the current directory.
    pub file: PathBuf,
    /// `frame`: the axes of the moment (absent: body).
    pub frame: Axes,
    /// `interpolation` (absent: linear).
    pub interpolation: Interpolation,
}

impl TorqueTableSpec {
    /// The table `file`, body axes, interpolated linearly.
    ///
    /// ```
    /// use eulerdyn::effects::Interpolation;
    /// use eulerdyn::frames::Axes;
    /// use eulerdyn::scene::TorqueTableSpec;
    /// let table = TorqueTableSpec::new("thruster.csv").in_axes(Axes::Space).cubic();
    /// assert_eq!((table.frame, table.interpolation), (Axes::Space, Interpolation::Cubic));
    /// ```
    pub fn new(file: impl AsRef<Path>) -> Self {
        Self {
            file: file.as_ref().to_path_buf(),
            frame: Axes::Body,
            interpolation: Interpolation::Linear,
        }
    }

    /// This table's moment given in `axes`.
    pub fn in_axes(mut self, axes: Axes) -> Self {
        self.frame = axes;
        self
    }

    /// This table interpolated by the natural cubic spline.
    pub fn cubic(mut self) -> Self {
        self.interpolation = Interpolation::Cubic;
        self
    }
}

impl From<TorqueTableSpec> for EffectSpec {
    fn from(table: TorqueTableSpec) -> Self {
        EffectSpec::TorqueTable(table)
    }
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

impl EffectSpec {
    /// Uniform gravity `g_s` (m/s², space axes) acting at C, the free body turning about `pivot_b` (body axes,
    /// from the reference origin, m).
    ///
    /// ```
    /// use eulerdyn::scene::EffectSpec;
    /// let top = EffectSpec::gravity([0.0, 0.0, -9.81], [0.0, 0.0, -0.05]);
    /// assert!(matches!(top, EffectSpec::Gravity { pivot: Some(_), .. }));
    /// ```
    pub fn gravity(g_s: [f64; 3], pivot_b: [f64; 3]) -> Self {
        EffectSpec::Gravity {
            g: g_s,
            pivot: Some(pivot_b),
        }
    }

    /// Uniform gravity `g_s` (m/s², space axes) acting at C of a body on a fixed axis or hinge, whose axis point
    /// is the moment center (no pivot).
    ///
    /// ```
    /// use eulerdyn::scene::EffectSpec;
    /// assert_eq!(EffectSpec::weight([0.0, -9.81, 0.0]), EffectSpec::Gravity { g: [0.0, -9.81, 0.0], pivot: None });
    /// ```
    pub fn weight(g_s: [f64; 3]) -> Self {
        EffectSpec::Gravity {
            g: g_s,
            pivot: None,
        }
    }

    /// Standard gravity [`DEFAULT_GRAVITY`] on a body on a fixed axis or hinge (what `type = "gravity"` without `g`
    /// means).
    ///
    /// ```
    /// use eulerdyn::scene::EffectSpec;
    /// assert_eq!(EffectSpec::standard_weight(), EffectSpec::weight([0.0, 0.0, -9.81]));
    /// ```
    pub fn standard_weight() -> Self {
        Self::weight(DEFAULT_GRAVITY)
    }

    /// Viscous damping M = −c ω, `c` in N·m·s.
    ///
    /// ```
    /// use eulerdyn::scene::EffectSpec;
    /// assert_eq!(EffectSpec::damping(0.1), EffectSpec::Damping { c: 0.1 });
    /// ```
    pub fn damping(c: f64) -> Self {
        EffectSpec::Damping { c }
    }

    /// The effect's `type` in a scene file: `torque`, `gravity`, `damping`, `torque_table`, `gravity_gradient` or
    /// `magnetic`.
    pub fn kind(&self) -> &'static str {
        match self {
            EffectSpec::Torque(_) => "torque",
            EffectSpec::Gravity { .. } => "gravity",
            EffectSpec::Damping { .. } => "damping",
            EffectSpec::TorqueTable(_) => "torque_table",
            EffectSpec::GravityGradient => "gravity_gradient",
            EffectSpec::Magnetic(_) => "magnetic",
        }
    }
}

impl From<TorqueSpec> for EffectSpec {
    fn from(torque: TorqueSpec) -> Self {
        EffectSpec::Torque(torque)
    }
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
