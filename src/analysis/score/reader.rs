//! Reading another program's trajectory: time, attitude (a quaternion in either order, or a rotation matrix) and
//! optionally ω (body or space axes), by header names through the shared run reader ([`RunCsvReader`]), so a
//! spreadsheet's CSV (byte-order mark, CRLF line ends) reads as well.
//!
//! Every refusal names the file, the row and the column: a missing time or attitude column, time not increasing,
//! a quaternion whose norm is off 1 by more than [`NORM_REFUSED`] (one off by more than [`NORM_WARNED`] is
//! normalised with a warning), a matrix that is not a rotation to the same bounds, an unknown `--map` target.

use std::path::Path;

use nalgebra::{Matrix3, Rotation3, UnitQuaternion, Vector3};

use super::ScoreError;
use crate::frames::Axes;
use crate::output::run_csv::RunCsvReader;

/// A quaternion (or a matrix's RᵀR − I) off unit norm by more than this is refused.
pub const NORM_REFUSED: f64 = 1e-6;
/// Off by more than this (and at most [`NORM_REFUSED`]) it is normalised with a warning.
pub const NORM_WARNED: f64 = 1e-12;

/// The order of a quaternion given as the generic columns `q_0..q_3`: scalar first (`wxyz`, MuJoCo's) or last
/// (`xyzw`, Rapier's, Bullet's, Unity's). Columns named `q_w..q_z` say their order themselves.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum QuaternionOrder {
    #[default]
    /// Scalar first: (w, x, y, z).
    Wxyz,
    /// Scalar last: (x, y, z, w).
    Xyzw,
}

/// How to read the file: the quaternion order, ω's axes, and `--map NAME=COLUMN` renames.
#[derive(Debug, Clone, Default)]
pub struct ReadOptions {
    /// The order of the columns `q_0..q_3`.
    pub quaternion: QuaternionOrder,
    /// The axes of the `omega_x..z` columns (default body).
    pub omega: Option<Axes>,
    /// (eulerdyn's name, the file's column).
    pub map: Vec<(String, String)>,
}

/// eulerdyn's names for the columns it reads: the targets `--map` accepts.
pub const NAMES: [&str; 21] = [
    "t", "q_w", "q_x", "q_y", "q_z", "q_0", "q_1", "q_2", "q_3", "R_11", "R_12", "R_13", "R_21",
    "R_22", "R_23", "R_31", "R_32", "R_33", "omega_x", "omega_y", "omega_z",
];
/// The angular velocity's columns.
const OMEGA: [&str; 3] = ["omega_x", "omega_y", "omega_z"];

/// One row of their trajectory: time, attitude (body → space) and ω in body axes when given.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct TheirRow {
    /// Time (s).
    pub t: f64,
    /// Attitude, body → space.
    pub q: UnitQuaternion<f64>,
    /// ω in body axes (rad/s), when their file gives ω.
    pub omega_b: Option<Vector3<f64>>,
}

/// Their whole trajectory, with the warnings reading it gave.
#[derive(Debug, Clone)]
pub struct Trajectory {
    /// Their rows, in time order.
    pub rows: Vec<TheirRow>,
    /// What reading it warned of (e.g. quaternions normalised).
    pub warnings: Vec<String>,
    /// The columns the attitude was read from.
    pub columns: AttitudeColumns,
}

/// Which columns gave the attitude.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum AttitudeColumns {
    /// `q_w..q_z`, named for their components.
    Named,
    /// `q_0..q_3`, in this order (`--quaternion`).
    Generic(QuaternionOrder),
    /// `R_11..R_33`.
    Matrix,
}

/// How the attitude is given.
enum Attitude {
    /// Indices of w, x, y, z.
    Quaternion([usize; 4], [&'static str; 4]),
    /// Indices of R_11..R_33, row by row.
    Matrix([usize; 9]),
}

/// Reads `path` (ending no later than `t_end`).
pub fn read_trajectory(
    path: &Path,
    options: &ReadOptions,
    t_end: f64,
) -> Result<Trajectory, ScoreError> {
    let measured = read_measured(path, options, t_end, true)?;
    let rows = (measured.rows.iter())
        .map(|r| TheirRow {
            t: r.t,
            q: r.q.expect("the attitude is required"),
            omega_b: r.omega_b,
        })
        .collect();
    Ok(Trajectory {
        rows,
        warnings: measured.warnings,
        columns: measured.columns.expect("the attitude is required"),
    })
}

/// One row of a measured motion: time, and the attitude and the body-axis ω where the file gives them.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct MeasuredRow {
    /// Time (s).
    pub t: f64,
    /// Attitude, body → space, when the file gives it.
    pub q: Option<UnitQuaternion<f64>>,
    /// ω in body axes (rad/s), when the file gives it.
    pub omega_b: Option<Vector3<f64>>,
}

/// A measured motion: a gyro's ω and/or the attitude against time.
#[derive(Debug, Clone)]
pub struct Measured {
    /// The rows, in time order.
    pub rows: Vec<MeasuredRow>,
    /// What reading it warned of (e.g. quaternions normalised).
    pub warnings: Vec<String>,
    /// The columns the attitude was read from, when it was.
    pub columns: Option<AttitudeColumns>,
}

/// Reads `path` (ending no later than `t_end`): the attitude is refused missing when `need_attitude`, else either
/// the attitude or ω (or both) must be there. ω in space axes needs the attitude to be turned into the body.
pub fn read_measured(
    path: &Path,
    options: &ReadOptions,
    t_end: f64,
    need_attitude: bool,
) -> Result<Measured, ScoreError> {
    let input = |problem: String| ScoreError::Input(format!("{}: {problem}", path.display()));
    let mut csv = open_mapped(path, options)?;
    let (map, omega_axes) = with_own_omega(&csv, options);
    let column = |name: &str| -> String {
        (map.iter().rev())
            .find(|(n, _)| n == name)
            .map_or(name.to_string(), |(_, c)| c.clone())
    };
    let find = |csv: &RunCsvReader<_>, name: &str| csv.index_of(&column(name));
    let t_index = find(&csv, "t").ok_or_else(|| {
        input(format!(
            "no time column `{}` (map one with --map t=COLUMN); its columns are {}",
            column("t"),
            csv.header_shown()
        ))
    })?;
    let attitude = attitude_columns(&csv, &column, options.quaternion);
    let omega: Vec<Option<usize>> = OMEGA.iter().map(|n| find(&csv, n)).collect();
    let omega = match omega.as_slice() {
        [Some(x), Some(y), Some(z)] => Some([*x, *y, *z]),
        [None, None, None] => None,
        _ => {
            return Err(input(format!(
                "only some of the columns {} are present: give all three or none",
                OMEGA.map(&column).join(", ")
            )));
        }
    };
    let attitude_wanted =
        "q_w,q_x,q_y,q_z, q_0..q_3 (with --quaternion) or R_11..R_33 (or map them with --map)";
    match (&attitude, omega) {
        (None, _) if need_attitude => {
            return Err(input(format!(
                "no attitude columns: give {attitude_wanted}; its columns are {}",
                csv.header_shown()
            )));
        }
        (None, None) => {
            return Err(input(format!(
                "neither a gyro's omega_x,omega_y,omega_z nor the attitude ({attitude_wanted}); its columns are {}",
                csv.header_shown()
            )));
        }
        (None, Some(_)) if omega_axes == Axes::Space => {
            return Err(input(
                "omega in space axes (--omega space) needs the attitude to turn it into the body, and the file has \
                 no attitude columns"
                    .into(),
            ));
        }
        _ => {}
    }
    let mut reading = Reading::new(path, t_end, omega_axes);
    let (index, names) = reading.columns(t_index, attitude.as_ref(), omega, &column);
    let names: Vec<&str> = names.iter().map(String::as_str).collect();
    let mut values = vec![0.0; index.len()];
    while csv
        .next_row(&index, &names, &mut values)
        .map_err(|e| ScoreError::Input(e.to_string()))?
    {
        reading.add(csv.rows(), &values, attitude.as_ref(), omega.is_some())?;
    }
    let columns = attitude.as_ref().map(|a| match a {
        Attitude::Quaternion(_, names) if names[0] == "q_w" => AttitudeColumns::Named,
        Attitude::Quaternion(..) => AttitudeColumns::Generic(options.quaternion),
        Attitude::Matrix(_) => AttitudeColumns::Matrix,
    });
    reading.finish(columns)
}

/// The file opened, every `--map NAME=COLUMN` checked: NAME one of [`NAMES`], COLUMN one of the file's.
fn open_mapped(
    path: &Path,
    options: &ReadOptions,
) -> Result<RunCsvReader<std::fs::File>, ScoreError> {
    for (name, _) in &options.map {
        if !NAMES.contains(&name.as_str()) {
            return Err(ScoreError::Input(format!(
                "--map {name}=…: `{name}` is not one of eulerdyn's column names ({})",
                NAMES.join(", ")
            )));
        }
    }
    let csv = RunCsvReader::open(path).map_err(|e| ScoreError::Input(e.to_string()))?;
    for (name, their) in &options.map {
        if csv.index_of(their).is_none() {
            return Err(ScoreError::Input(format!(
                "{}: --map {name}={their}: the file has no column `{their}`; its columns are {}",
                path.display(),
                csv.header_shown()
            )));
        }
    }
    Ok(csv)
}

/// The column map and ω's axes: the options', except that a file of eulerdyn's own (`omega_b_x..z`, no
/// `omega_x..z`, none mapped) has its body-axis ω read from `omega_b_x..z`.
fn with_own_omega<R: std::io::Read>(
    csv: &RunCsvReader<R>,
    options: &ReadOptions,
) -> (Vec<(String, String)>, Axes) {
    const OWN: [&str; 3] = ["omega_b_x", "omega_b_y", "omega_b_z"];
    let mut map = options.map.clone();
    let has = |c: &str| csv.index_of(c).is_some();
    let mapped = map.iter().any(|(n, _)| OMEGA.contains(&n.as_str()));
    if !mapped && !OMEGA.iter().any(|n| has(n)) && OWN.iter().all(|c| has(c)) {
        map.extend((OMEGA.iter().zip(OWN)).map(|(n, c)| (n.to_string(), c.to_string())));
        return (map, Axes::Body);
    }
    (map, options.omega.unwrap_or(Axes::Body))
}

/// The attitude's columns: q_w..q_z, else q_0..q_3 in `order`, else R_11..R_33.
fn attitude_columns<R: std::io::Read>(
    csv: &RunCsvReader<R>,
    column: &dyn Fn(&str) -> String,
    order: QuaternionOrder,
) -> Option<Attitude> {
    let all = |names: &[&str]| -> Option<Vec<usize>> {
        names.iter().map(|n| csv.index_of(&column(n))).collect()
    };
    if let Some(i) = all(&["q_w", "q_x", "q_y", "q_z"]) {
        return Some(Attitude::Quaternion(
            [i[0], i[1], i[2], i[3]],
            ["q_w", "q_x", "q_y", "q_z"],
        ));
    }
    if let Some(i) = all(&["q_0", "q_1", "q_2", "q_3"]) {
        return Some(match order {
            QuaternionOrder::Wxyz => {
                Attitude::Quaternion([i[0], i[1], i[2], i[3]], ["q_0", "q_1", "q_2", "q_3"])
            }
            QuaternionOrder::Xyzw => {
                Attitude::Quaternion([i[3], i[0], i[1], i[2]], ["q_3", "q_0", "q_1", "q_2"])
            }
        });
    }
    let names = [
        "R_11", "R_12", "R_13", "R_21", "R_22", "R_23", "R_31", "R_32", "R_33",
    ];
    all(&names).map(|i| Attitude::Matrix(std::array::from_fn(|k| i[k])))
}

/// The rows read so far and what they gave.
struct Reading<'p> {
    path: &'p Path,
    t_end: f64,
    omega_axes: Axes,
    rows: Vec<MeasuredRow>,
    /// Rows normalised, and the first.
    normalised: (u64, u64),
    attitude_names: String,
}

impl<'p> Reading<'p> {
    fn new(path: &'p Path, t_end: f64, omega_axes: Axes) -> Self {
        Self {
            path,
            t_end,
            omega_axes,
            rows: Vec::new(),
            normalised: (0, 0),
            attitude_names: String::new(),
        }
    }

    /// The indices read per row (t, the attitude's, ω's) and the names shown in messages.
    fn columns(
        &mut self,
        t: usize,
        attitude: Option<&Attitude>,
        omega: Option<[usize; 3]>,
        column: &dyn Fn(&str) -> String,
    ) -> (Vec<usize>, Vec<String>) {
        let mut index = vec![t];
        let mut names = vec![column("t")];
        match attitude {
            None => {}
            Some(Attitude::Quaternion(i, n)) => {
                index.extend(i);
                names.extend(n.iter().map(|n| column(n)));
            }
            Some(Attitude::Matrix(i)) => {
                index.extend(i);
                names.extend(
                    (1..=3)
                        .flat_map(|r| (1..=3).map(move |c| format!("R_{r}{c}")))
                        .map(|n| column(&n)),
                );
            }
        }
        self.attitude_names = names[1..].join(",");
        if let Some(i) = omega {
            index.extend(i);
            names.extend(OMEGA.map(column));
        }
        (index, names)
    }

    fn refuse(&self, row: u64, column: &str, problem: String) -> ScoreError {
        ScoreError::Input(format!(
            "{}: row {row}, column `{column}`: {problem}",
            self.path.display()
        ))
    }

    /// Adds data row `row` (1-based).
    fn add(
        &mut self,
        row: u64,
        v: &[f64],
        attitude: Option<&Attitude>,
        with_omega: bool,
    ) -> Result<(), ScoreError> {
        let t = v[0];
        if let Some(last) = self.rows.last()
            && t <= last.t
        {
            return Err(self.refuse(
                row,
                "t",
                format!("time {t} does not increase (the row before has {})", last.t),
            ));
        }
        if t < 0.0 {
            return Err(self.refuse(
                row,
                "t",
                format!("time {t} is negative: the scene starts at t = 0"),
            ));
        }
        if t > self.t_end * (1.0 + 1e-12) + 1e-12 {
            return Err(self.refuse(
                row,
                "t",
                format!(
                    "time {t} is past the scene's t_end = {}{}",
                    self.t_end,
                    if t / 1000.0 <= self.t_end {
                        " (if the times are in milliseconds, give them in seconds)"
                    } else {
                        ""
                    }
                ),
            ));
        }
        let q = match attitude {
            Some(attitude) => Some(self.attitude(row, v, attitude)?),
            None => None,
        };
        let n = match attitude {
            None => 1,
            Some(Attitude::Quaternion(..)) => 5,
            Some(Attitude::Matrix(_)) => 10,
        };
        let omega_b = with_omega.then(|| {
            let w = Vector3::new(v[n], v[n + 1], v[n + 2]);
            match (self.omega_axes, q) {
                (Axes::Space, Some(q)) => q.inverse_transform_vector(&w),
                _ => w,
            }
        });
        self.rows.push(MeasuredRow { t, q, omega_b });
        Ok(())
    }

    /// The attitude of data row `row`, refused off a unit quaternion (or a rotation) by more than
    /// [`NORM_REFUSED`], normalised (and counted) off by more than [`NORM_WARNED`].
    fn attitude(
        &mut self,
        row: u64,
        v: &[f64],
        attitude: &Attitude,
    ) -> Result<UnitQuaternion<f64>, ScoreError> {
        let (q, off) = match attitude {
            Attitude::Quaternion(..) => {
                let q = nalgebra::Quaternion::new(v[1], v[2], v[3], v[4]);
                (UnitQuaternion::new_normalize(q), (q.norm() - 1.0).abs())
            }
            Attitude::Matrix(_) => {
                let r = Matrix3::new(v[1], v[2], v[3], v[4], v[5], v[6], v[7], v[8], v[9]);
                let off = (r.transpose() * r - Matrix3::identity()).abs().max();
                let off = if r.determinant() < 0.0 {
                    f64::INFINITY
                } else {
                    off
                };
                let rotation = Rotation3::from_matrix_eps(&r, 1e-15, 100, Rotation3::identity());
                (UnitQuaternion::from_rotation_matrix(&rotation), off)
            }
        };
        if off > NORM_REFUSED {
            let names = self.attitude_names.clone();
            return Err(self.refuse(
                row,
                &names,
                format!("the attitude is off a unit quaternion (or a rotation) by {off:.3e}, more than {NORM_REFUSED:e}"),
            ));
        }
        if off > NORM_WARNED {
            self.normalised.0 += 1;
            if self.normalised.1 == 0 {
                self.normalised.1 = row;
            }
        }
        Ok(q)
    }

    fn finish(self, columns: Option<AttitudeColumns>) -> Result<Measured, ScoreError> {
        if self.rows.len() < 2 {
            return Err(ScoreError::Input(format!(
                "{}: {} data rows; a trajectory needs at least 2",
                self.path.display(),
                self.rows.len()
            )));
        }
        let mut warnings = Vec::new();
        if self.normalised.0 > 0 {
            warnings.push(format!(
                "{}: {} rows (the first row {}) had an attitude off unit norm by more than {NORM_WARNED:e}: normalised",
                self.path.display(),
                self.normalised.0,
                self.normalised.1
            ));
        }
        Ok(Measured {
            rows: self.rows,
            warnings,
            columns,
        })
    }
}
