//! The panels of a run's figure (`eulerdyn plot`): their names, the columns each draws and which runs have them.
//! Vocabulary, so that a scene's [`crate::scene::Facts`] can say which panels its runs have; the plot
//! (`output::plot`, feature `plot`) draws them.

use std::fmt;
use std::str::FromStr;

/// One panel of the figure.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Panel {
    /// H in body axes (and |H|).
    HBody,
    /// H in space axes (and |H|).
    HSpace,
    /// The moment M about the moment center, body axes (solid) and space axes (dashed).
    Moment,
    /// The angular velocity ω, body axes (solid) and space axes (dashed).
    Omega,
    /// The kinetic energy.
    Energy,
    /// |x(t) − x(0)| / |x(0)| of |H| and of the energy, on a log scale.
    Drift,
    /// The bearings' forces on the body: |R_A|, |R_B| and their components in body axes (A solid, B dashed).
    /// Only runs with bearings have its columns.
    Bearings,
    /// The same in space axes (`bearings_space`): for a rotor spinning fast, or in a turning carrier, whose loads
    /// are steadier in space than in the spinning body. Drawn only when asked for.
    BearingsSpace,
    /// The force the support applies to the body, F_sup, in space axes, and |F_sup| (fixed_axis and hinge runs).
    Support,
    /// The angle θ turned about the fixed axis (fixed_axis and hinge runs).
    Theta,
    /// Each wheel's spin relative to the body (runs with `[[body.rotor]]`; its columns are the run's).
    WheelSpin,
    /// Each wheel's axial moment of momentum J (a·ω + Ω) (runs with `[[body.rotor]]`).
    WheelMomentum,
    /// Each wheel's motor torque applied (solid), commanded and its friction torque (dashed, wheels under control).
    WheelTorque,
    /// Each wheel's friction torque (runs whose wheels are under control: a law, a table, a limit or friction).
    WheelFriction,
    /// The attitude from the LVLH frame of the scene's orbit: roll, pitch and yaw (rad).
    Lvlh,
    /// The Earth's field in body axes, B_b (T): runs with an effect that acts in it (`magnetic`, `b_dot`).
    Field,
    /// The magnetorquers' dipole in body axes, m_b (A·m²): runs with `b_dot`.
    Dipole,
    /// The inertia about the system's centre of mass, body axes (kg·m²): runs of a body that changes shape.
    Inertia,
    /// The power the internal drives put into the motion, P_internal (W): runs of a body that changes shape.
    InternalPower,
}

impl Panel {
    /// The panels every run has, in the order they are drawn by default.
    pub const ALL: [Panel; 6] = [
        Panel::HBody,
        Panel::HSpace,
        Panel::Moment,
        Panel::Omega,
        Panel::Energy,
        Panel::Drift,
    ];

    /// The panels of fixed-axis and hinge runs (bearings: with bearings only), drawn after [`Panel::ALL`] by
    /// default when the run has their columns.
    pub const AXIS_ONLY: [Panel; 3] = [Panel::Theta, Panel::Support, Panel::Bearings];

    /// The panels a run has, read from its header (`has`) where no sidecar says them
    /// ([`crate::scene::Facts::panels`]): every panel of [`Panel::ALL`], then those of [`Panel::AXIS_ONLY`] whose
    /// columns the header has (the bearings in space axes when the support moves, `moving_support`), then
    /// [`Panel::WHEELS`] when the run has `wheels` (their names), with [`Panel::WheelFriction`] when each has its
    /// `<name>_friction` column (wheels under control), then those of [`Panel::ORBIT`] whose columns it has.
    ///
    /// ```
    /// use eulerdyn::panel::Panel;
    /// let free_columns = |c: &str| Panel::ALL.iter().any(|p| p.columns().contains(&c));
    /// assert_eq!(Panel::of_run(free_columns, false, &[]), Panel::ALL);
    /// let wheel = Panel::of_run(|c| free_columns(c) || c.starts_with("rw_"), false, &["rw".to_string()]);
    /// assert_eq!(wheel.last(), Some(&Panel::WheelFriction));
    /// let in_orbit = Panel::of_run(|c| free_columns(c) || c.ends_with("_lvlh"), false, &[]);
    /// assert_eq!(in_orbit.last(), Some(&Panel::Lvlh));
    /// let with_b_dot = Panel::of_run(|c| free_columns(c) || c.starts_with("B_b") || c.starts_with("m_b"), false, &[]);
    /// assert_eq!(with_b_dot[with_b_dot.len() - 2..], [Panel::Field, Panel::Dipole]);
    /// ```
    pub fn of_run(
        has: impl Fn(&str) -> bool,
        moving_support: bool,
        wheels: &[String],
    ) -> Vec<Panel> {
        let axis = (Panel::AXIS_ONLY.into_iter())
            .filter(|p| p.columns().iter().all(|c| has(c)))
            .map(|p| match p {
                Panel::Bearings if moving_support => Panel::BearingsSpace,
                p => p,
            });
        let friction = wheels.iter().all(|n| has(&format!("{n}_friction")));
        let wheel_panels = Panel::wheel_panels(!wheels.is_empty(), friction);
        let lvlh = (Panel::ORBIT.into_iter().chain(Panel::SHAPE))
            .filter(|p| p.columns().iter().all(|c| has(c)));
        Panel::ALL
            .into_iter()
            .chain(axis)
            .chain(wheel_panels)
            .chain(lvlh)
            .collect()
    }

    /// The wheel panels a run has: none without `wheels`, else [`Panel::WHEELS`], then [`Panel::WheelFriction`]
    /// with the wheels' `friction` columns.
    pub fn wheel_panels(wheels: bool, friction: bool) -> Vec<Panel> {
        let friction = [Panel::WheelFriction].into_iter().filter(|_| friction);
        (Panel::WHEELS.into_iter().chain(friction))
            .filter(|_| wheels)
            .collect()
    }

    /// Whether the panel draws the wheels' columns (named by the wheels).
    pub fn is_wheel(self) -> bool {
        matches!(
            self,
            Panel::WheelSpin | Panel::WheelMomentum | Panel::WheelTorque | Panel::WheelFriction
        )
    }

    /// The name used with `--panels`.
    pub fn name(self) -> &'static str {
        match self {
            Panel::HBody => "h_body",
            Panel::HSpace => "h_space",
            Panel::Moment => "moment",
            Panel::Omega => "omega",
            Panel::Energy => "energy",
            Panel::Drift => "drift",
            Panel::Bearings => "bearings",
            Panel::BearingsSpace => "bearings_space",
            Panel::Support => "support",
            Panel::Theta => "theta",
            Panel::WheelSpin => "wheel_spin",
            Panel::WheelMomentum => "wheel_h",
            Panel::WheelTorque => "wheel_torque",
            Panel::WheelFriction => "wheel_friction",
            Panel::Lvlh => "lvlh",
            Panel::Field => "field",
            Panel::Dipole => "dipole",
            Panel::Inertia => "inertia",
            Panel::InternalPower => "internal_power",
        }
    }

    /// The panels of rotor runs, drawn after the others by default when the run has wheel columns; their columns
    /// are named by the wheels (`<name>_spin`, `<name>_h`, `<name>_torque`, `<name>_torque_cmd`,
    /// `<name>_friction`). [`Panel::WheelFriction`] follows them when the wheels are under control.
    pub const WHEELS: [Panel; 3] = [Panel::WheelSpin, Panel::WheelMomentum, Panel::WheelTorque];

    /// The panels of runs in orbit, drawn last by default when the run has their columns: the attitude from LVLH,
    /// the field, the magnetorquers' dipole.
    pub const ORBIT: [Panel; 3] = [Panel::Lvlh, Panel::Field, Panel::Dipole];

    /// The panels of a body that changes shape, drawn after the orbit's by default when the run has their columns.
    pub const SHAPE: [Panel; 2] = [Panel::Inertia, Panel::InternalPower];

    /// The CSV columns the panel needs (besides `t`).
    pub fn columns(self) -> &'static [&'static str] {
        match self {
            Panel::HBody => &["H_b_x", "H_b_y", "H_b_z", "H_norm"],
            Panel::HSpace => &["H_s_x", "H_s_y", "H_s_z", "H_norm"],
            Panel::Moment => &["M_b_x", "M_b_y", "M_b_z", "M_s_x", "M_s_y", "M_s_z"],
            Panel::Omega => &[
                "omega_b_x",
                "omega_b_y",
                "omega_b_z",
                "omega_s_x",
                "omega_s_y",
                "omega_s_z",
            ],
            Panel::Energy => &["energy"],
            Panel::Drift => &["H_norm", "energy"],
            Panel::Bearings => &[
                "R_A_b_x", "R_A_b_y", "R_A_b_z", "R_B_b_x", "R_B_b_y", "R_B_b_z",
            ],
            Panel::BearingsSpace => &[
                "R_A_s_x", "R_A_s_y", "R_A_s_z", "R_B_s_x", "R_B_s_y", "R_B_s_z",
            ],
            Panel::Support => &["F_sup_s_x", "F_sup_s_y", "F_sup_s_z"],
            Panel::Theta => &["theta"],
            Panel::Lvlh => &["roll_lvlh", "pitch_lvlh", "yaw_lvlh"],
            Panel::Field => &["B_b_x", "B_b_y", "B_b_z"],
            Panel::Dipole => &["m_b_x", "m_b_y", "m_b_z"],
            Panel::Inertia => &["I_b_xx", "I_b_yy", "I_b_zz", "I_b_xy", "I_b_xz", "I_b_yz"],
            Panel::InternalPower => &["P_internal"],
            Panel::WheelSpin | Panel::WheelMomentum | Panel::WheelTorque | Panel::WheelFriction => {
                &[]
            }
        }
    }

    /// A panel that draws its [`columns`](Self::columns) as they are, one curve each: its title, its axis label and
    /// each curve's label, in the order of the columns; `None` for the panels drawn their own way.
    ///
    /// ```
    /// use eulerdyn::panel::Panel;
    /// let (_, axis, labels) = Panel::Field.plain_curves().unwrap();
    /// assert_eq!((axis, labels.len()), ("B (T)", Panel::Field.columns().len()));
    /// assert!(Panel::Drift.plain_curves().is_none());
    /// ```
    pub fn plain_curves(self) -> Option<(&'static str, &'static str, &'static [&'static str])> {
        match self {
            Panel::Theta => Some(("Angle θ turned about the fixed axis", "θ (rad)", &["θ"])),
            Panel::Lvlh => Some((
                "Attitude from LVLH (3-2-1: yaw, pitch, roll)",
                "angle (rad)",
                &["roll", "pitch", "yaw"],
            )),
            Panel::Field => Some((
                "The Earth's field B in body axes",
                "B (T)",
                &["B_b,x", "B_b,y", "B_b,z"],
            )),
            Panel::Dipole => Some((
                "The magnetorquers' dipole m in body axes (B-dot)",
                "m (A·m²)",
                &["m_b,x", "m_b,y", "m_b,z"],
            )),
            Panel::Inertia => Some((
                "Inertia about C(t), body axes",
                "I (kg·m²)",
                &["I_xx", "I_yy", "I_zz", "I_xy", "I_xz", "I_yz"],
            )),
            Panel::InternalPower => Some((
                "Power of the internal drives, dT/dt − M·ω",
                "P_internal (W)",
                &["P_internal"],
            )),
            _ => None,
        }
    }

    /// The CSV columns the panel draws when the file has them: V and T + V (gravity scenes) for the energy panel,
    /// T + V and H_s,z (an invariant under vertical gravity) for the drift panel; the H panels read T and ω_b for
    /// the run's momentum scale, below which a change of H is drawn flat.
    pub fn optional_columns(self) -> &'static [&'static str] {
        match self {
            Panel::HBody | Panel::HSpace => &["energy", "omega_b_x", "omega_b_y", "omega_b_z"],
            Panel::Energy => &["potential", "energy_total"],
            Panel::Drift => &["energy_total", "H_s_z"],
            _ => &[],
        }
    }

    /// Which runs have the panel's columns, for panels that not every run can draw.
    pub fn which_runs(self) -> Option<&'static str> {
        match self {
            Panel::Bearings | Panel::BearingsSpace => {
                Some("only runs of scenes with `bearings` have the bearing forces")
            }
            Panel::Support | Panel::Theta => Some("only fixed_axis and hinge runs have them"),
            Panel::Lvlh => Some("only runs of scenes with an [orbit] have the LVLH angles"),
            Panel::Field => Some(
                "only runs of scenes with an effect in the Earth's field (magnetic, b_dot) have the field B_b",
            ),
            Panel::Dipole => {
                Some("only runs of scenes with b_dot have the magnetorquers' dipole m_b")
            }
            Panel::Inertia | Panel::InternalPower => Some(
                "only runs of a body that changes shape ([[body.moving_mass]], inertia_table) have them",
            ),
            Panel::WheelSpin | Panel::WheelMomentum | Panel::WheelTorque => {
                Some("only runs of scenes with [[body.rotor]] have the wheels' columns")
            }
            Panel::WheelFriction => Some(
                "only runs whose wheels are under control (a law, a table, mode = \"free\", a limit or friction) \
                 have the wheels' friction columns",
            ),
            _ => None,
        }
    }

    /// What a run of `eulerdyn run` lacks when it has not the panel's columns, in words ("this run has …"), for
    /// panels that not every run can draw.
    pub fn absence(self) -> Option<&'static str> {
        match self {
            Panel::Bearings => Some(
                "no bearings (only runs of scenes with `bearings` have the bearing forces, columns R_A_b_x … \
                 R_B_b_z, that the bearings panel draws)",
            ),
            Panel::BearingsSpace => Some(
                "no bearings (only runs of scenes with `bearings` have the bearing forces, columns R_A_s_x … \
                 R_B_s_z, that the bearings_space panel draws)",
            ),
            Panel::Theta => Some(
                "no fixed axis, so no angle `theta` (needed by theta; only fixed_axis and hinge runs have them)",
            ),
            Panel::Support => Some(
                "no support force `F_sup_s_*` (needed by support; only fixed_axis and hinge runs have them)",
            ),
            _ => None,
        }
    }

    /// A comma-separated list of panel names (`h_body,h_space`), in the order given; a name given twice is drawn
    /// once. `all` alone stands for every panel the run has (an empty list, as when none is given: the run's
    /// wheel and axis panels too).
    ///
    /// ```
    /// use eulerdyn::panel::Panel;
    /// assert_eq!(Panel::parse_list("omega, wheel_h").unwrap(), [Panel::Omega, Panel::WheelMomentum]);
    /// assert!(Panel::parse_list("all").unwrap().is_empty());
    /// assert!(Panel::parse_list("all,theta").is_err());
    /// ```
    pub fn parse_list(text: &str) -> Result<Vec<Panel>, String> {
        if text.split(',').any(|name| name.trim() == "all") {
            return match text.trim() {
                "all" => Ok(Vec::new()),
                _ => Err(format!(
                    "\"all\" stands alone (every panel the run has) in \"{text}\"; to choose, name the panels \
                     (panels: {})",
                    Self::names()
                )),
            };
        }
        let mut panels = Vec::new();
        for name in text.split(',').map(str::trim) {
            if name.is_empty() {
                return Err(format!(
                    "empty panel name in \"{text}\"; give names separated by commas, e.g. h_body,h_space (panels: {})",
                    Self::names()
                ));
            }
            let panel = name.parse::<Panel>()?;
            if !panels.contains(&panel) {
                panels.push(panel);
            }
        }
        Ok(panels)
    }

    /// Every panel name, comma-separated.
    pub fn names() -> String {
        Panel::ALL.map(Panel::name).join(", ")
            + ", and for fixed_axis and hinge runs: theta, support, bearings (with bearings only), bearings_space \
               (the same in space axes, drawn only when asked for), and for rotor runs: wheel_spin, wheel_h, \
               wheel_torque, wheel_friction (wheels under control), and for runs in orbit: lvlh, field (magnetic, b_dot), \
               dipole (b_dot), and for a body that changes shape: inertia, internal_power"
    }
}

impl fmt::Display for Panel {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

impl FromStr for Panel {
    type Err = String;

    fn from_str(s: &str) -> Result<Self, Self::Err> {
        Panel::ALL
            .into_iter()
            .chain(Panel::AXIS_ONLY)
            .chain([Panel::BearingsSpace])
            .chain(Panel::WHEELS)
            .chain([Panel::WheelFriction])
            .chain(Panel::ORBIT)
            .chain(Panel::SHAPE)
            .find(|p| p.name() == s)
            .ok_or_else(|| format!("unknown panel \"{s}\"; panels: {}, or all", Panel::names()))
    }
}

impl serde::Serialize for Panel {
    fn serialize<S: serde::Serializer>(&self, serializer: S) -> Result<S::Ok, S::Error> {
        serializer.serialize_str(self.name())
    }
}

impl<'de> serde::Deserialize<'de> for Panel {
    fn deserialize<D: serde::Deserializer<'de>>(deserializer: D) -> Result<Self, D::Error> {
        String::deserialize(deserializer)?
            .parse()
            .map_err(serde::de::Error::custom)
    }
}
