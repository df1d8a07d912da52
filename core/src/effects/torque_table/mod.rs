//! `type = "torque_table"`: a moment tabulated in a CSV file (rows t, M_x, M_y, M_z), interpolated linearly or by
//! a natural cubic spline ([`TorqueTable`]), zero outside the table's rows, in body or space axes.

use std::path::{Path, PathBuf};
use std::sync::Arc;

use super::compiling::Compiling;
use super::kind::{EffectKind, KindSpec, Placement, SharedKeys};
use super::table::{Interpolation, TorqueTable};
use crate::frames::Axes;
use crate::keys::{Checked, KeyPath, Keys, invalid, required};
use crate::text::plain;

/// A torque table's keys (with `frame`, which a torque shares, in the registry's table).
#[derive(Debug, Clone, Default, PartialEq, Keys)]
pub(crate) struct TorqueTableKeys {
    /// CSV with header t,M_x,M_y,M_z (s, N·m), relative to the scene file; zero outside its rows
    #[key(shown = "required for `torque_table`")]
    pub(crate) file: Option<PathBuf>,
    /// torque_table: between rows (cubic: the natural spline)
    #[key(kind = "\"linear\" | \"cubic\"", shown = "\"linear\"")]
    pub(crate) interpolation: Option<Interpolation>,
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

impl KindSpec for TorqueTableSpec {
    type Keys = TorqueTableKeys;
    type Effect = TabulatedTorque;

    /// The table as its keys give it, in the table's `frame` (body axes unless given).
    fn read(
        keys: &TorqueTableKeys,
        shared: &SharedKeys,
        at: &KeyPath,
        kind_text: &str,
    ) -> Checked<Self> {
        Ok(TorqueTableSpec {
            file: required(at.clone().key("file"), keys.file.clone(), kind_text)?,
            frame: shared.frame.unwrap_or(Axes::Body),
            interpolation: keys.interpolation.unwrap_or_default(),
        })
    }

    /// Its keys and the table's `frame`.
    fn write(&self, shared: &mut SharedKeys) -> TorqueTableKeys {
        shared.frame = Some(self.frame);
        TorqueTableKeys {
            file: Some(self.file.clone()),
            interpolation: Some(self.interpolation),
        }
    }

    /// The table validated: read here, once, so that its errors name the file and the row.
    fn validate(&self, at: &KeyPath, _on: &Placement) -> Checked<TabulatedTorque> {
        let table = TorqueTable::read(&self.file, self.interpolation)
            .or_else(|problem| invalid(at.clone().key("file"), problem))?;
        Ok(TabulatedTorque {
            frame: self.frame,
            table: Arc::new(table),
        })
    }

    /// Its file taken relative to `dir`.
    fn take_files_in(&mut self, dir: &Path) {
        self.file = dir.join(&self.file);
    }
}

/// A tabulated moment (N·m) in body or space axes, read from its file when the scene was validated.
#[derive(Debug, Clone, PartialEq)]
pub struct TabulatedTorque {
    /// The axes of the table's moments.
    pub frame: Axes,
    /// The table.
    pub table: Arc<TorqueTable>,
}

impl EffectKind for TabulatedTorque {
    fn kind(&self) -> &'static str {
        "torque_table"
    }

    fn describe(&self) -> String {
        let (t0, t1) = self.table.time_range();
        format!(
            "torque table {} ({} rows, {} <= t <= {} s, {} interpolation, zero outside) in {} axes",
            self.table.path().display(),
            self.table.rows(),
            plain(t0),
            plain(t1),
            self.table.interpolation().name(),
            self.frame.name()
        )
    }

    /// [`TorqueTable::largest_moment`].
    fn largest_moment(&self, _mass: f64) -> Option<f64> {
        Some(self.table.largest_moment())
    }

    fn size_key(&self) -> &'static str {
        "file"
    }

    fn compile(&self, into: &mut Compiling) {
        into.torques(self.frame).add_table(&self.table);
    }
}
