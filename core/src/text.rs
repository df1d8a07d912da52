//! Numbers and labelled lines for people: how `eulerdyn check`, the plots and the reports print a value, and the
//! [`Description`] that a capability adds its lines to.

use std::fmt::Write;

use nalgebra::Vector3;

/// Width of the label column.
pub const LABEL: usize = 15;

/// A component: six decimals, or scientific notation for very large or small magnitudes.
pub fn fixed(v: f64) -> String {
    if v == 0.0 || (1e-4..1e6).contains(&v.abs()) || !v.is_finite() {
        format!("{v:.6}")
    } else {
        format!("{v:.6e}")
    }
}

/// A number of turns: three decimals, scientific notation when huge.
pub fn turns(v: f64) -> String {
    if v.abs() < 1e6 || !v.is_finite() {
        format!("{v:.3}")
    } else {
        format!("{v:.3e}")
    }
}

/// A value as given: shortest form, scientific notation for very large or small magnitudes.
pub fn plain(v: f64) -> String {
    if v == 0.0 || (1e-4..1e15).contains(&v.abs()) || !v.is_finite() {
        format!("{v}")
    } else {
        format!("{v:e}")
    }
}

/// A value rounded for people: six significant digits, trailing zeros dropped, scientific notation below 1e-4
/// or from 1e6 (as C's `%g`): 1.9999999999999998e-5 → `2e-05`, 0.05 → `0.05`, 1234.5678 → `1234.57`.
pub fn for_people(v: f64) -> String {
    if v == 0.0 || !v.is_finite() {
        return format!("{v}");
    }
    let scientific = format!("{v:.5e}");
    let (mantissa, exponent) = scientific.split_once('e').unwrap_or((&scientific, "0"));
    let exponent: i32 = exponent.parse().unwrap_or(0);
    let trim = |text: &str| {
        if text.contains('.') {
            text.trim_end_matches('0').trim_end_matches('.').to_string()
        } else {
            text.to_string()
        }
    };
    if (-4..6).contains(&exponent) {
        let decimals = (5 - exponent) as usize;
        trim(&format!("{v:.decimals$}"))
    } else {
        let sign = if exponent < 0 { '-' } else { '+' };
        format!("{}e{sign}{:02}", trim(mantissa), exponent.abs())
    }
}

/// A vector as `(x, y, z)`, each component [`fixed`].
///
/// ```
/// use eulerdyn::text::vec3;
/// assert_eq!(vec3(&nalgebra::Vector3::new(1.0, 0.0, -2.5e-7)), "(1.000000, 0.000000, -2.500000e-7)");
/// ```
pub fn vec3(v: &Vector3<f64>) -> String {
    format!("({}, {}, {})", fixed(v[0]), fixed(v[1]), fixed(v[2]))
}

/// What a scene will simulate: labelled lines in the order `eulerdyn check` prints them.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct Description {
    /// (label, text) per line; a blank label continues the item above it (e.g. a tensor's rows).
    pub lines: Vec<(String, String)>,
}

impl Description {
    /// The items: each label with its lines (the continuation lines gathered under the label above them).
    pub fn items(&self) -> Vec<(&str, Vec<&str>)> {
        let mut items: Vec<(&str, Vec<&str>)> = Vec::new();
        for (label, text) in &self.lines {
            match items.last_mut() {
                Some((_, texts)) if label.is_empty() => texts.push(text),
                _ => items.push((label, vec![text])),
            }
        }
        items
    }

    /// The text `eulerdyn check` prints: the labels in a column, then the text.
    pub fn text(&self) -> String {
        let mut out = String::new();
        for (label, text) in &self.lines {
            let _ = writeln!(out, "{label:<LABEL$}{text}");
        }
        out
    }
}

/// Appends `text` under `label` (a blank label continues the previous item).
pub fn line(out: &mut Description, label: &str, text: &str) {
    out.lines.push((label.to_string(), text.to_string()));
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_items_gather_the_lines_under_their_labels() {
        let mut d = Description::default();
        line(&mut d, "body", "mass 1 kg");
        line(&mut d, "", "row 1");
        line(&mut d, "method", "rk4");
        assert_eq!(
            d.items(),
            vec![
                ("body", vec!["mass 1 kg", "row 1"]),
                ("method", vec!["rk4"])
            ]
        );
        assert_eq!(
            d.text(),
            format!(
                "{:<LABEL$}mass 1 kg\n{:<LABEL$}row 1\n{:<LABEL$}rk4\n",
                "body", "", "method"
            )
        );
    }

    #[test]
    fn numbers_for_people_have_six_significant_digits() {
        // 20 g*mm in kg*m as the scene's conversion computes it (20 × 1e-6 = 1.9999999999999998e-5).
        let twenty_gmm = 20.0 * 1e-6;
        assert_ne!(twenty_gmm, 2e-5);
        assert_eq!(for_people(twenty_gmm), "2e-05");
        assert_eq!(for_people(0.05), "0.05");
        assert_eq!(for_people(1234.5678), "1234.57");
        assert_eq!(for_people(-3.0), "-3");
        assert_eq!(for_people(2.5e7), "2.5e+07");
        assert_eq!(for_people(0.0), "0");
        assert_eq!(for_people(0.000123456789), "0.000123457");
    }
}
