//! Whether a run's error reached a target because its curve converges there, or by chance: the study names a run
//! the cheapest to an error level only in the first case (`docs/book/src/explanation/accuracy-study.md`, "Convergence").
//!
//! A curve is one method in one form on one backend; its completed runs are ordered from the loosest setting (the
//! largest rtol or dt) to the tightest. A run of a curve with error ≤ ε **counts** for the target ε when
//! 1. every tighter run of the curve reaches ε too, and
//! 2. the curve converges there: its tightest run's error is at least [`MARGIN`] times below ε, or its error still
//!    falls at the tight end — over its last three runs, at every step, and from the first of them to the
//!    tightest by at least the square root of the ratio of their settings (10× over two decades of rtol, 2× over
//!    two halvings of dt; an error ∝ setting^p with p ≥ [`MIN_ORDER`]).
//!
//! Near a separatrix, for instance, the error of every method levels off at the problem's own sensitivity; a run
//! that lands below the target there (the next tighter one does not) is luck, and is reported as such. A method
//! with neither a step nor a tolerance (`exact`) has nothing to converge in: its run counts when it reaches ε.

use super::{Measure, StudyRow};

/// How far below the target the tightest run of a curve must be for the curve to count as converged there,
/// whatever its slope (it went well past the target).
pub const MARGIN: f64 = 10.0;

/// The least log–log slope of error against setting at the tight end of a converging curve.
pub const MIN_ORDER: f64 = 0.5;

/// Why a run that reaches a target does not count for it.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum NotCounted {
    /// A tighter run of the same curve (index into the study's rows) misses the target.
    TighterMisses(usize),
    /// The error does not fall with the setting at the tight end: the first and the last of the curve's last three
    /// runs (indices into the study's rows, looser first); and the tightest is within [`MARGIN`] of the target.
    NoFall(usize, usize),
}

/// The completed runs of `row`'s curve as (setting, error, row index), loosest first.
fn curve_of(rows: &[StudyRow], measure: Measure, row: &StudyRow) -> Vec<(f64, f64, usize)> {
    let mut points: Vec<(f64, f64, usize)> = rows
        .iter()
        .enumerate()
        .filter(|(_, r)| r.method == row.method && r.form == row.form)
        .filter_map(|(i, r)| Some((r.rtol.or(r.dt)?, r.error(measure)?, i)))
        .collect();
    points.sort_by(|a, b| b.0.total_cmp(&a.0));
    points
}

/// Whether run `i`, which reaches `target`, counts for it (`Ok`), or why not (see the module documentation).
pub fn verdict(
    rows: &[StudyRow],
    measure: Measure,
    i: usize,
    target: f64,
) -> Result<(), NotCounted> {
    let row = &rows[i];
    let Some(setting) = row.rtol.or(row.dt) else {
        return Ok(());
    };
    let curve = curve_of(rows, measure, row);
    if let Some(&(_, _, miss)) = curve
        .iter()
        .find(|&&(s, e, _)| s < setting && (e > target || e.is_nan()))
    {
        return Err(NotCounted::TighterMisses(miss));
    }
    let Some(&(s_tight, e_tight, tightest)) = curve.last() else {
        return Ok(());
    };
    if e_tight * MARGIN <= target {
        return Ok(());
    }
    let end = &curve[curve.len().saturating_sub(3)..];
    let (s_loose, e_loose, looser) = end[0];
    let falls = s_loose > s_tight
        && end.windows(2).all(|w| w[1].1 < w[0].1)
        && e_loose >= e_tight * (s_loose / s_tight).powf(MIN_ORDER);
    if falls {
        Ok(())
    } else {
        Err(NotCounted::NoFall(looser, tightest))
    }
}

/// Whether run `i` reaches `target` and counts for it.
pub fn counts(rows: &[StudyRow], measure: Measure, i: usize, target: f64) -> bool {
    rows[i].error(measure).is_some_and(|e| e <= target) && verdict(rows, measure, i, target).is_ok()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::frames::Form;
    use crate::method::{Backend, Method};

    /// A dop853 curve with these (rtol, err_omega) runs.
    fn curve(runs: &[(f64, f64)]) -> Vec<StudyRow> {
        runs.iter()
            .map(|&(rtol, err)| StudyRow {
                method: "dop853".into(),
                method_name: Method::Dop853,
                backend: Backend::Own,
                form: Form::Body,
                rtol: Some(rtol),
                atol: Some(rtol * 1e-2),
                dt: None,
                err_omega: err,
                err_attitude: None,
                energy_drift: 0.0,
                h_drift: 0.0,
                err_h_s: None,
                wall_s: 1e-3,
                steps: 1,
                rejected: 0,
                evals: 1,
                repeats: 1,
                failure: None,
            })
            .collect()
    }

    #[test]
    fn a_curve_still_falling_at_its_tight_end_counts_and_a_flat_or_erratic_one_does_not() {
        // Falling 10x per decade: every run reaching 1e-9 counts.
        let rows = curve(&[(1e-9, 1e-8), (1e-10, 1e-9), (1e-11, 1e-10)]);
        assert_eq!(verdict(&rows, Measure::Omega, 1, 1e-9), Ok(()));
        // The separatrix's runs of the same method: 1.6e-9, 7.8e-10, 5.7e-10 fall, but 2.8x over two decades.
        let rows = curve(&[(1e-11, 1.6e-9), (1e-12, 7.8e-10), (1e-13, 5.7e-10)]);
        assert_eq!(
            verdict(&rows, Measure::Omega, 1, 1e-9),
            Err(NotCounted::NoFall(0, 2))
        );
        // Falling 14x over two decades, but up and down on the way (ode_solvers' dopri5 near the separatrix).
        let rows = curve(&[(1e-11, 3.1e-9), (1e-12, 9.1e-9), (1e-13, 2.2e-10)]);
        assert_eq!(
            verdict(&rows, Measure::Omega, 2, 1e-9),
            Err(NotCounted::NoFall(0, 2))
        );
        // Flat, but 10x below the target at its tightest: the target lies well inside what the curve resolves.
        let rows = curve(&[(1e-11, 1e-13), (1e-12, 1e-13), (1e-13, 1e-13)]);
        assert_eq!(verdict(&rows, Measure::Omega, 0, 1e-12), Ok(()));
        // Reached at 1e-10 and missed again at 1e-11.
        let rows = curve(&[(1e-10, 3.5e-10), (1e-11, 1.9e-9), (1e-12, 1e-11)]);
        assert_eq!(
            verdict(&rows, Measure::Omega, 0, 1e-9),
            Err(NotCounted::TighterMisses(1))
        );
        assert!(!counts(&rows, Measure::Omega, 0, 1e-9) && counts(&rows, Measure::Omega, 2, 1e-9));
    }
}
