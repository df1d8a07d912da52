//! A tabulated moment: the rows (t, M_x, M_y, M_z) of a CSV file, interpolated linearly or by a natural cubic
//! spline, zero outside the table's time range. Read once, when the scene is validated.

use std::path::{Path, PathBuf};

use nalgebra::Vector3;

use crate::named::{Named, serde_by_name};

/// How a table's moment is interpolated between its rows.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum Interpolation {
    /// The straight line between neighbouring rows.
    #[default]
    Linear,
    /// The natural cubic spline through the rows (second derivative zero at the first and last row).
    Cubic,
}

impl Interpolation {
    /// The name in scene files: `linear` or `cubic`.
    pub fn name(&self) -> &'static str {
        match self {
            Interpolation::Linear => "linear",
            Interpolation::Cubic => "cubic",
        }
    }
}

impl Named for Interpolation {
    const ALL: &'static [Self] = &[Interpolation::Linear, Interpolation::Cubic];

    fn name(&self) -> &'static str {
        Interpolation::name(self)
    }
}

serde_by_name!(Interpolation);

/// The header a torque table must have: t (s) and the moment's components (N·m).
pub const TABLE_HEADER: [&str; 4] = ["t", "M_x", "M_y", "M_z"];

/// max over A ∈ [0, 1] of |A³ − A| = 2/(3√3), at A = 1/√3: bounds the spline's curvature term.
const MAX_CUBIC_TERM: f64 = 0.384_900_179_459_750_5;

/// A moment tabulated at strictly increasing times t_0 < … < t_n (n ≥ 1), with its interpolation.
///
/// Linear: M(t) = A M_i + B M_{i+1} on [t_i, t_{i+1}], A = (t_{i+1} − t)/h_i, B = 1 − A, h_i = t_{i+1} − t_i.
/// Cubic (natural spline, Numerical Recipes 3rd ed. §3.3, eq. 3.3.3): the same plus
/// ((A³ − A) S_i + (B³ − B) S_{i+1}) h_i²/6, with the second derivatives S_i from the tridiagonal system
/// h_{i−1} S_{i−1} + 2 (h_{i−1} + h_i) S_i + h_i S_{i+1} = 6 (Δ_i − Δ_{i−1}), Δ_i = (M_{i+1} − M_i)/h_i, S_0 = S_n = 0.
/// A linear function has Δ_i constant, so S = 0 and both interpolations reproduce it.
#[derive(Debug, Clone, PartialEq)]
pub struct TorqueTable {
    path: PathBuf,
    interpolation: Interpolation,
    t: Vec<f64>,
    m: Vec<Vector3<f64>>,
    /// The spline's second derivatives S_i (empty for linear interpolation).
    s: Vec<Vector3<f64>>,
}

impl TorqueTable {
    /// Reads the table at `path`: header `t,M_x,M_y,M_z`, then one row per time. A bad header, a value that is
    /// not a finite number, t not strictly increasing or fewer than 2 rows is an error naming the file and row.
    pub fn read(path: &Path, interpolation: Interpolation) -> Result<Self, String> {
        Self::read_columns(path, interpolation, &TABLE_HEADER)
    }

    /// Reads a table whose header is `header` (`t` and one to three components, the missing ones zero), with
    /// [`TorqueTable::read`]'s checks; a UTF-8 byte-order mark and CRLF line ends are accepted.
    pub fn read_columns(
        path: &Path,
        interpolation: Interpolation,
        header: &[&str],
    ) -> Result<Self, String> {
        let text = std::fs::read_to_string(path)
            .map_err(|e| format!("{}: cannot read the table: {e}", path.display()))?;
        let text = text.strip_prefix('\u{feff}').unwrap_or(&text);
        let (t, m) = parse_rows(text, header).map_err(|e| format!("{}: {e}", path.display()))?;
        Ok(Self::new(path, interpolation, t, m))
    }

    /// The table of rows `(t, m)` (checked by the caller: strictly increasing, finite, at least 2).
    fn new(path: &Path, interpolation: Interpolation, t: Vec<f64>, m: Vec<Vector3<f64>>) -> Self {
        let s = match interpolation {
            Interpolation::Linear => Vec::new(),
            Interpolation::Cubic => natural_spline(&t, &m),
        };
        Self {
            path: path.to_path_buf(),
            interpolation,
            t,
            m,
            s,
        }
    }

    /// The file the table was read from.
    pub fn path(&self) -> &Path {
        &self.path
    }

    /// The interpolation between rows.
    pub fn interpolation(&self) -> Interpolation {
        self.interpolation
    }

    /// The table's first and last time (s).
    pub fn time_range(&self) -> (f64, f64) {
        (self.t[0], self.t[self.t.len() - 1])
    }

    /// The number of rows.
    pub fn rows(&self) -> usize {
        self.t.len()
    }

    /// M(t), N·m: interpolated within [t_0, t_n], zero outside.
    pub fn at(&self, t: f64) -> Vector3<f64> {
        let n = self.t.len() - 1;
        if !(self.t[0] <= t && t <= self.t[n]) {
            return Vector3::zeros();
        }
        // The interval [t_i, t_{i+1}] that holds t (the last one for t = t_n).
        let i = (self.t.partition_point(|ti| *ti <= t) - 1).min(n - 1);
        let h = self.t[i + 1] - self.t[i];
        let a = (self.t[i + 1] - t) / h;
        let b = 1.0 - a;
        let linear = self.m[i] * a + self.m[i + 1] * b;
        if self.s.is_empty() {
            return linear;
        }
        linear + (self.s[i] * (a * a * a - a) + self.s[i + 1] * (b * b * b - b)) * (h * h / 6.0)
    }

    /// The first row time later than `t`: where the moment has a corner (its slope, or for the spline its third
    /// derivative, changes; at t_0 and t_n it may jump).
    pub fn corner_after(&self, t: f64) -> Option<f64> {
        self.t.get(self.t.partition_point(|ti| *ti <= t)).copied()
    }

    /// An upper bound of |M(t)| over all t (N·m): the largest row for linear interpolation; for the spline, each
    /// interval's max(|M_i|, |M_{i+1}|) + max|A³ − A| (|S_i| + |S_{i+1}|) h_i²/6.
    pub fn largest_moment(&self) -> f64 {
        (0..self.t.len() - 1)
            .map(|i| {
                let ends = self.m[i].norm().max(self.m[i + 1].norm());
                let curvature = match self.s.is_empty() {
                    true => 0.0,
                    false => {
                        let h = self.t[i + 1] - self.t[i];
                        MAX_CUBIC_TERM * (self.s[i].norm() + self.s[i + 1].norm()) * h * h / 6.0
                    }
                };
                ends + curvature
            })
            .fold(0.0, f64::max)
    }
}

/// The rows of a table's text: the times and moments, or what is wrong and in which row.
fn parse_rows(text: &str, header_names: &[&str]) -> Result<(Vec<f64>, Vec<Vector3<f64>>), String> {
    let what = if header_names.len() == 4 {
        "t in s, the moment in N*m"
    } else {
        "t in s, the torque in N*m"
    };
    let (t, rows) = parse_table(text, header_names, what)?;
    let m = (rows.iter())
        .map(|values| Vector3::from_fn(|i, _| values.get(i).copied().unwrap_or(0.0)))
        .collect();
    Ok((t, m))
}

/// Reads the table at `path` ([`parse_table`]); its errors name the file.
pub(crate) fn read_rows(
    path: &Path,
    header: &[&str],
    units: &str,
) -> Result<(Vec<f64>, Vec<Vec<f64>>), String> {
    let text = std::fs::read_to_string(path)
        .map_err(|e| format!("{}: cannot read the table: {e}", path.display()))?;
    parse_table(&text, header, units).map_err(|e| format!("{}: {e}", path.display()))
}

/// The rows of a CSV table with the header `header` (`t` first; `units` says what its columns hold): the times,
/// strictly increasing, and each row's other values, all finite; at least 2 rows. A UTF-8 byte-order mark and CRLF
/// line ends (as spreadsheets save CSV) are accepted.
pub(crate) fn parse_table(
    text: &str,
    header_names: &[&str],
    units: &str,
) -> Result<(Vec<f64>, Vec<Vec<f64>>), String> {
    let text = text.strip_prefix('\u{feff}').unwrap_or(text);
    let mut lines = text
        .lines()
        .enumerate()
        .filter(|(_, l)| !l.trim().is_empty());
    let expected = header_names.join(",");
    let Some((_, header)) = lines.next() else {
        return Err(format!(
            "the table is empty; it needs the header `{expected}` and at least 2 rows"
        ));
    };
    let names: Vec<&str> = header.split(',').map(str::trim).collect();
    if names != header_names {
        return Err(format!(
            "row 0 (the header): expected `{expected}` ({units}), got `{}`",
            header.trim()
        ));
    }
    let (mut t, mut rows) = (Vec::new(), Vec::new());
    for (row, (index, line)) in lines.enumerate() {
        let at = format!("row {} (line {})", row + 1, index + 1);
        let values =
            row_values(line, header_names).map_err(|problem| format!("{at}: {problem}"))?;
        match t.last() {
            Some(last) if values[0] <= *last => {
                return Err(format!(
                    "{at}: t = {} is not later than the previous row's t = {last}; t must be strictly increasing",
                    values[0]
                ));
            }
            _ => {}
        }
        t.push(values[0]);
        rows.push(values[1..].to_vec());
    }
    if t.len() < 2 {
        return Err(format!(
            "the table has {} row(s) after its header; it needs at least 2 to interpolate",
            t.len()
        ));
    }
    Ok((t, rows))
}

/// The finite numbers of one row, one per column of `header`.
fn row_values(line: &str, header: &[&str]) -> Result<Vec<f64>, String> {
    let fields: Vec<&str> = line.split(',').map(str::trim).collect();
    if fields.len() != header.len() {
        return Err(format!(
            "expected {} values ({}), got {}: `{}`",
            header.len(),
            header.join(","),
            fields.len(),
            line.trim()
        ));
    }
    let mut values = vec![0.0; header.len()];
    for ((value, field), name) in values.iter_mut().zip(&fields).zip(header) {
        *value = match field.parse::<f64>() {
            Ok(v) if v.is_finite() => v,
            _ => return Err(format!("{name} must be a finite number, got `{field}`")),
        };
    }
    Ok(values)
}

/// The natural spline's second derivatives S_0..S_n (S_0 = S_n = 0) by the Thomas algorithm on the tridiagonal
/// system of [`TorqueTable`] (diagonally dominant, so no pivoting is needed).
fn natural_spline(t: &[f64], m: &[Vector3<f64>]) -> Vec<Vector3<f64>> {
    let n = t.len() - 1;
    let mut s = vec![Vector3::zeros(); n + 1];
    if n < 2 {
        return s;
    }
    let h: Vec<f64> = t.windows(2).map(|w| w[1] - w[0]).collect();
    let slope = |i: usize| (m[i + 1] - m[i]) / h[i];
    // Forward elimination over the interior unknowns S_1..S_{n−1}.
    let mut diag = vec![0.0; n];
    let mut rhs = vec![Vector3::zeros(); n];
    for i in 1..n {
        let d = 2.0 * (h[i - 1] + h[i]);
        let r = (slope(i) - slope(i - 1)) * 6.0;
        if i == 1 {
            (diag[i], rhs[i]) = (d, r);
        } else {
            let w = h[i - 1] / diag[i - 1];
            diag[i] = d - w * h[i - 1];
            rhs[i] = r - rhs[i - 1] * w;
        }
    }
    for i in (1..n).rev() {
        s[i] = (rhs[i] - s[i + 1] * h[i]) / diag[i];
    }
    s
}

#[cfg(test)]
mod tests {
    use super::*;

    fn table(interpolation: Interpolation, rows: &[[f64; 4]]) -> TorqueTable {
        let t = rows.iter().map(|r| r[0]).collect();
        let m = rows
            .iter()
            .map(|r| Vector3::new(r[1], r[2], r[3]))
            .collect();
        TorqueTable::new(Path::new("x.csv"), interpolation, t, m)
    }

    #[test]
    fn both_interpolations_pass_through_the_rows_and_are_zero_outside() {
        let rows = [
            [0.0, 1.0, 0.0, 2.0],
            [0.5, -1.0, 3.0, 0.0],
            [1.5, 2.0, 1.0, -1.0],
            [2.0, 0.0, 0.0, 0.5],
        ];
        for interpolation in Interpolation::ALL {
            let tab = table(*interpolation, &rows);
            for r in &rows {
                let expected = Vector3::new(r[1], r[2], r[3]);
                assert!(
                    (tab.at(r[0]) - expected).norm() < 1e-15,
                    "{interpolation:?}"
                );
            }
            assert_eq!(tab.at(-1e-9), Vector3::zeros());
            assert_eq!(tab.at(2.0 + 1e-9), Vector3::zeros());
            assert_eq!(tab.corner_after(0.0), Some(0.5));
            assert_eq!(tab.corner_after(-3.0), Some(0.0));
            assert_eq!(tab.corner_after(2.0), None);
        }
    }

    /// The natural spline's conditions (NR §3.3): S″ continuous at the interior rows (the S_i solve the system),
    /// S′ continuous there, S″ = 0 at both ends. Checked by finite differences of `at`.
    #[test]
    fn the_cubic_is_a_natural_spline() {
        let rows = [
            [0.0, 0.0, 1.0, 0.0],
            [1.0, 2.0, -1.0, 0.0],
            [1.5, 1.0, 0.0, 1.0],
            [3.0, -2.0, 0.5, 0.0],
        ];
        let tab = table(Interpolation::Cubic, &rows);
        let d = 1e-5;
        let slope = |t: f64| (tab.at(t + d) - tab.at(t - d)) / (2.0 * d);
        for knot in [1.0, 1.5] {
            let left = (tab.at(knot) - tab.at(knot - d)) / d;
            let right = (tab.at(knot + d) - tab.at(knot)) / d;
            assert!((left - right).norm() < 1e-3, "slope jumps at {knot}");
        }
        let curvature = |t: f64| (slope(t + d) - slope(t - d)) / (2.0 * d);
        assert!(curvature(4.0 * d).norm() < 1e-3);
        assert!(curvature(3.0 - 4.0 * d).norm() < 1e-3);
        assert!(curvature(1.2).norm() > 0.1, "the spline bends");
    }

    #[test]
    fn the_bound_holds_on_a_fine_grid() {
        let rows = [
            [0.0, 0.0, 0.0, 0.0],
            [0.1, 5.0, -5.0, 1.0],
            [0.2, 0.0, 0.0, 0.0],
            [1.0, 0.0, 4.0, 0.0],
        ];
        for interpolation in Interpolation::ALL {
            let tab = table(*interpolation, &rows);
            let bound = tab.largest_moment();
            let largest = (0..=10_000)
                .map(|k| tab.at(k as f64 * 1e-4).norm())
                .fold(0.0, f64::max);
            assert!(largest <= bound, "{interpolation:?}: {largest} > {bound}");
        }
    }

    #[test]
    fn bad_tables_name_the_row() {
        let cases = [
            ("", "the table is empty"),
            (
                "t,M_x,M_y\n0,1,2\n",
                "row 0 (the header): expected `t,M_x,M_y,M_z`",
            ),
            ("t,M_x,M_y,M_z\n0,0,0,0\n", "has 1 row(s)"),
            (
                "t,M_x,M_y,M_z\n0,0,0,0\n1,0,nan,0\n",
                "row 2 (line 3): M_y must be a finite",
            ),
            (
                "t,M_x,M_y,M_z\n0,0,0,0\n1,0,x,0\n",
                "row 2 (line 3): M_y must be a finite",
            ),
            (
                "t,M_x,M_y,M_z\n0,0,0,0\n0,0,0,0\n",
                "row 2 (line 3): t = 0 is not later",
            ),
            (
                "t,M_x,M_y,M_z\n0,0,0\n",
                "row 1 (line 2): expected 4 values",
            ),
        ];
        for (text, expected) in cases {
            let e = parse_rows(text, &TABLE_HEADER).unwrap_err();
            assert!(e.contains(expected), "{text:?}: {e}");
        }
    }

    #[test]
    fn a_spreadsheet_s_bom_and_crlf_are_accepted() {
        let plain = parse_rows("t,M_x,M_y,M_z\n0,1,2,3\n1,4,5,6\n", &TABLE_HEADER).unwrap();
        let saved = parse_rows(
            "\u{feff}t,M_x,M_y,M_z\r\n0,1,2,3\r\n1,4,5,6\r\n",
            &TABLE_HEADER,
        )
        .unwrap();
        assert_eq!(saved, plain);
    }
}
