//! The keys of a body that changes shape, declared once: `[[body.moving_mass]]` ([`MovingMassSpec`], its file form
//! `MovingMassFile`) with its path as a group ([`PathSpec`]), and `[body]`'s `inertia_table`; `[body]` registers
//! both with one field, `shape_change: ShapeChangeSpec` (the group [`ShapeChangeKeys`]).

use std::path::{Path, PathBuf};

use super::path::Profile;
use crate::keys::{Checked, Group, KeyPath, Keys, Part, Table, invalid};

/// One `[[body.moving_mass]]`: a point mass moved inside the body along a path in body axes.
#[derive(Debug, Clone, PartialEq, Table)]
#[table(
    file = MovingMassFile,
    header = "[[body.moving_mass]]",
    about = "a point mass moved inside a freely turning body (`[body]` is the rest of the body)",
    what = "a moving mass"
)]
pub struct MovingMassSpec {
    /// the prefix of its position columns `<name>_x`, `<name>_y`, `<name>_z`: letters, digits, `_`; unique
    #[key(shown = "mass0, mass1, …")]
    pub name: Option<String>,
    /// > 0
    #[key(unit = "kg")]
    pub mass: f64,
    /// `from`, `to`, `start`, `duration` and `profile`, or `table`.
    #[key(flatten = PathKeys)]
    pub path: PathSpec,
}

/// A moving mass's path as the scene gives it.
#[derive(Debug, Clone, PartialEq)]
pub enum PathSpec {
    /// From `from` to `to` over [start, start + duration] (m, s, body axes from the reference origin).
    Move {
        /// Position before `start`.
        from: [f64; 3],
        /// Position from `start + duration` on.
        to: [f64; 3],
        /// s.
        start: f64,
        /// s.
        duration: f64,
        /// How it moves.
        profile: Profile,
    },
    /// Positions in time from a table (header `t,x,y,z`), relative to the scene file.
    Table(PathBuf),
}

/// A moving mass's path keys, read as its [`PathSpec`].
#[derive(Debug, Clone, Default, PartialEq, Keys)]
pub(crate) struct PathKeys {
    /// position before `start`, body axes from the reference origin
    #[key(position, shown = "required without `table`")]
    from: Option<[f64; 3]>,
    /// position from `start + duration` on
    #[key(position, shown = "required without `table`")]
    to: Option<[f64; 3]>,
    /// when the move starts
    #[key(unit = "s", shown = "0")]
    start: Option<f64>,
    /// > 0: how long the move takes
    #[key(unit = "s", shown = "required without `table`")]
    duration: Option<f64>,
    /// `"linear"` (constant speed, started and stopped at once) or `"smooth"` (s = 3τ² − 2τ³: no speed at either end)
    #[key(kind = "\"linear\" or \"smooth\"", shown = "\"smooth\"")]
    profile: Option<Profile>,
    /// instead of `from` … `profile`: positions in time, header `t,x,y,z` (s; m, body axes), linear between rows and held outside; relative to the scene file
    table: Option<PathBuf>,
}

/// Either `table`, or `from`, `to` and `duration` (with `start` and `profile`).
impl Group<PathKeys> for PathSpec {
    fn read(doc: &PathKeys, at: &KeyPath) -> Checked<Self> {
        if let Some(table) = &doc.table {
            if let Some(other) = doc.given().into_iter().find(|k| *k != "table") {
                return invalid(
                    at.clone().key(other),
                    format!("`table` gives the path: remove `{other}` (or the table)"),
                );
            }
            return Ok(PathSpec::Table(table.clone()));
        }
        let need = |value: Option<[f64; 3]>, name: &str| {
            value.ok_or_else(|| crate::keys::Invalid {
                key: at.clone().key(name),
                problem: format!(
                    "missing: a moving mass needs `{name}` (or its positions in a `table`)"
                ),
            })
        };
        let (from, to) = (need(doc.from, "from")?, need(doc.to, "to")?);
        let Some(duration) = doc.duration else {
            return invalid(
                at.clone().key("duration"),
                "missing: a moving mass needs `duration` (or its positions in a `table`)",
            );
        };
        Ok(PathSpec::Move {
            from,
            to,
            start: doc.start.unwrap_or(0.0),
            duration,
            profile: doc.profile.unwrap_or_default(),
        })
    }

    fn write(&self, file: &mut PathKeys) {
        match self {
            PathSpec::Table(path) => file.table = Some(path.clone()),
            PathSpec::Move {
                from,
                to,
                start,
                duration,
                profile,
            } => {
                (file.from, file.to) = (Some(*from), Some(*to));
                (file.start, file.duration) = (Some(*start), Some(*duration));
                file.profile = Some(*profile);
            }
        }
    }

    fn take_files_in(&mut self, dir: &Path) {
        if let PathSpec::Table(file) = self {
            *file = dir.join(&*file);
        }
    }
}

/// What changes the body's shape, as `[body]` gives it: moving masses or an inertia history (validation refuses
/// both at once).
#[derive(Debug, Clone, Default, PartialEq)]
pub struct ShapeChangeSpec {
    /// `[[body.moving_mass]]`.
    pub moving_mass: Vec<MovingMassSpec>,
    /// `inertia_table`, relative to the scene file.
    pub inertia_table: Option<PathBuf>,
}

/// `[body]`'s keys of a body that changes shape.
#[derive(Debug, Clone, Default, PartialEq, Keys)]
pub(crate) struct ShapeChangeKeys {
    /// point masses moved inside the body: `[[body.moving_mass]]`
    #[key(table, kind = "array of tables")]
    moving_mass: Vec<MovingMassFile>,
    /// instead of moving masses: the whole body's inertia about C in time, header `t,I_xx,I_yy,I_zz,I_xy,I_xz,I_yz` (s; kg·m², body axes, tensor entries), linear between rows and held outside, relative to the scene file; the internal motion is taken to carry no moment of momentum relative to the body
    inertia_table: Option<PathBuf>,
}

impl Group<ShapeChangeKeys> for ShapeChangeSpec {
    fn read(doc: &ShapeChangeKeys, at: &KeyPath) -> Checked<Self> {
        let moving_mass = (doc.moving_mass.iter().enumerate())
            .map(|(i, f)| MovingMassSpec::read(f, &at.clone().key("moving_mass").index(i)))
            .collect::<Checked<_>>()?;
        Ok(Self {
            moving_mass,
            inertia_table: doc.inertia_table.clone(),
        })
    }

    fn write(&self, file: &mut ShapeChangeKeys) {
        file.moving_mass = self.moving_mass.iter().map(Part::write).collect();
        file.inertia_table = self.inertia_table.clone();
    }

    fn take_files_in(&mut self, dir: &Path) {
        for mass in &mut self.moving_mass {
            mass.take_files_in(dir);
        }
        if let Some(file) = &mut self.inertia_table {
            *file = dir.join(&*file);
        }
    }
}

impl ShapeChangeSpec {
    /// Whether the body changes shape (moving masses or an inertia table given).
    pub fn is_some(&self) -> bool {
        !self.moving_mass.is_empty() || self.inertia_table.is_some()
    }
}
