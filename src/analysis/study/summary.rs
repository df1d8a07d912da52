//! The study in words: the reference, the cheapest method for each of [`TARGETS`], the wall time each curve takes
//! to reach them, and what was not swept.

use std::fmt::{self, Write as _};

use crate::frames::Form;

use super::convergence::{self, NotCounted};
use super::{Cheapest, Study, StudyRow, TARGETS};

/// A number for people: its shortest form when that is short (`1e-10`, `6.25e-2`), else 4 digits (`5.623e-11`).
pub(super) fn short(x: f64) -> String {
    let exact = format!("{x:e}");
    if exact.len() <= 8 {
        exact
    } else {
        format!("{x:.3e}")
    }
}

/// A duration for people: `41.2 µs`, `3.10 ms`, `1.25 s`.
pub fn format_seconds(s: f64) -> String {
    if s < 1e-3 {
        format!("{:.1} µs", s * 1e6)
    } else if s < 1.0 {
        format!("{:.2} ms", s * 1e3)
    } else {
        format!("{s:.2} s")
    }
}

/// One curve's cheapest run for each of [`TARGETS`].
#[derive(Debug, Clone, PartialEq)]
pub struct CurveCost {
    /// The curve's label (`dop853`, `dop853/ode_solvers`).
    pub method: String,
    /// The form integrated.
    pub form: Form,
    /// Index into [`Study::rows`] of the fastest run of the curve reaching each target and counting for it (the
    /// curve converges there: [`convergence`]).
    pub rows: [Option<usize>; 3],
    /// For each target: a run of the curve reaches it, but none counts for it (shown `n.c.`).
    pub unconverged: [bool; 3],
}

impl Study {
    /// What the study found, for people: the reference, the cheapest method for each of [`TARGETS`], the fastest
    /// run of each method, and what was not swept.
    pub fn summary(&self) -> String {
        let mut out = String::new();
        self.write_header(&mut out);
        for c in &self.cheapest {
            self.write_cheapest(&mut out, c);
        }
        self.write_costs(&mut out);
        for s in &self.skipped {
            let _ = writeln!(out, "not swept: {}: {}", s.method, s.reason);
        }
        out
    }

    /// The scene, the number of runs, the reference and the measure.
    fn write_header(&self, out: &mut String) {
        let failed = self.rows.iter().filter(|r| r.failure.is_some()).count();
        let name = if self.scene_name.is_empty() {
            String::new()
        } else {
            format!(" ({})", self.scene_name)
        };
        let _ = writeln!(
            out,
            "accuracy of {}{name}: {} runs ({failed} failed), t_end = {} s, {} rows per run, study took {}",
            self.scene_path.display(),
            self.rows.len(),
            self.t_end,
            self.rows_per_run,
            format_seconds(self.study_seconds)
        );
        let _ = writeln!(out, "reference: {}", self.reference);
        let _ = writeln!(
            out,
            "error: {} = {}; time: median wall time of the integration alone",
            self.measure.column(),
            self.measure.describe()
        );
    }

    /// A run with its error and cost: `dop853 (body form, rtol 1e-8): 1.23e-9 in 3.10 ms (…)`.
    fn describe_run(&self, r: &StudyRow) -> String {
        format!(
            "{} ({} form, {}): {:.2e} in {} ({} steps, {} rejected, {} evaluations)",
            r.method,
            r.form.name(),
            r.setting(),
            r.error(self.measure).unwrap_or(f64::NAN),
            format_seconds(r.wall_s),
            r.steps,
            r.rejected,
            r.evals
        )
    }

    /// The cheapest run for one error level (or the closest any run came), the cheapest that integrates when that
    /// is another run, and a faster run that reached the level without converging to it ([`convergence`]).
    fn write_cheapest(&self, out: &mut String, c: &Cheapest) {
        let column = self.measure.column();
        let head = format!("cheapest for {column} <= {:e}:", c.target);
        let _ = match (c.row.map(|i| &self.rows[i]), c.unconverged) {
            (Some(r), _) => writeln!(out, "{head} {}", self.describe_run(r)),
            (None, Some(u)) => writeln!(
                out,
                "{head} no run converges to it: {}",
                self.not_counted(u, c.target)
            ),
            (None, None) => match self.closest() {
                Some((e, r)) => writeln!(
                    out,
                    "{head} no run reaches it (smallest: {e:.2e}, {} {} form {})",
                    r.method,
                    r.form.name(),
                    r.setting()
                ),
                None => writeln!(out, "{head} no run completed"),
            },
        };
        if c.integrator != c.row
            && let Some(r) = c.integrator.map(|i| &self.rows[i])
        {
            let _ = writeln!(
                out,
                "    cheapest that integrates: {}",
                self.describe_run(r)
            );
        }
        if let (Some(u), Some(_)) = (c.unconverged, c.row) {
            let lead = if c.integrator.is_some() {
                "faster, not counted"
            } else {
                "no run that integrates converges to it"
            };
            let _ = writeln!(out, "    {lead}: {}", self.not_counted(u, c.target));
        }
    }

    /// The completed run with the smallest error, and that error.
    fn closest(&self) -> Option<(f64, &StudyRow)> {
        self.rows
            .iter()
            .filter_map(|r| r.error(self.measure).map(|e| (e, r)))
            .min_by(|a, b| a.0.total_cmp(&b.0))
    }

    /// Run `i`, which reaches `target` without counting for it, and why it does not count.
    fn not_counted(&self, i: usize, target: f64) -> String {
        let r = &self.rows[i];
        let error = |k: usize| self.rows[k].error(self.measure).unwrap_or(f64::NAN);
        let at = |k: usize| format!("{:.2e} at {}", error(k), self.rows[k].setting());
        let (knob, tightens) = if r.rtol.is_some() {
            ("tolerance", "tightens")
        } else {
            ("step", "shrinks")
        };
        let why = match convergence::verdict(&self.rows, self.measure, i, target) {
            Ok(()) => "it counts".to_string(),
            Err(NotCounted::TighterMisses(k)) => format!(
                "its error does not stay below the target as the {knob} {tightens} ({})",
                at(k)
            ),
            Err(NotCounted::NoFall(a, b)) if a == b => {
                format!("its curve has one run ({}): no convergence to see", at(b))
            }
            Err(NotCounted::NoFall(a, b)) => format!(
                "its error does not fall with the {knob} in the measured range ({}, {})",
                at(a),
                at(b)
            ),
        };
        format!(
            "{} reaches {:.2e} in {}, but {why}: reached by chance, not named",
            self.describe_setting(r),
            error(i),
            format_seconds(r.wall_s)
        )
    }

    /// `dop853 (body form, rtol 1e-8)`.
    fn describe_setting(&self, r: &StudyRow) -> String {
        format!("{} ({} form, {})", r.method, r.form.name(), r.setting())
    }

    /// The table of the wall time each curve takes to reach each of [`TARGETS`].
    fn write_costs(&self, out: &mut String) {
        let curves = self.costs();
        if curves.is_empty() {
            return;
        }
        let column = self.measure.column();
        let _ = writeln!(
            out,
            "\nwall time to reach {column} <= {} (the cheapest run of each method and form; - : not reached; \
             n.c.: reached, but the method does not converge there):",
            TARGETS.map(|t| format!("{t:e}")).join(" / ")
        );
        let _ = write!(out, "{:<20} {:<6}", "method", "form");
        for t in TARGETS {
            let _ = write!(out, " {:>10}", format!("{t:e}"));
        }
        let _ = writeln!(out);
        for c in &curves {
            let _ = write!(out, "{:<20} {:<6}", c.method, c.form.name());
            for (i, unconverged) in c.rows.into_iter().zip(c.unconverged) {
                let cell = match i {
                    Some(i) => format_seconds(self.rows[i].wall_s),
                    None if unconverged => "n.c.".to_string(),
                    None => "-".to_string(),
                };
                let _ = write!(out, " {cell:>10}");
            }
            let _ = writeln!(out);
        }
    }

    /// For every curve (method label and form, in the order run), the fastest run reaching each of [`TARGETS`]
    /// that counts for it, and whether a run reached it without counting.
    pub fn costs(&self) -> Vec<CurveCost> {
        let mut curves: Vec<CurveCost> = Vec::new();
        for (i, r) in self.rows.iter().enumerate() {
            let k = match curves
                .iter()
                .position(|c| c.method == r.method && c.form == r.form)
            {
                Some(k) => k,
                None => {
                    curves.push(CurveCost {
                        method: r.method.clone(),
                        form: r.form,
                        rows: [None; 3],
                        unconverged: [false; 3],
                    });
                    curves.len() - 1
                }
            };
            let Some(err) = r.error(self.measure) else {
                continue;
            };
            let curve = &mut curves[k];
            for (j, target) in TARGETS.into_iter().enumerate() {
                if err > target {
                    continue;
                }
                if !convergence::counts(&self.rows, self.measure, i, target) {
                    curve.unconverged[j] = true;
                } else if curve.rows[j].is_none_or(|o| r.wall_s < self.rows[o].wall_s) {
                    curve.rows[j] = Some(i);
                }
            }
        }
        for curve in &mut curves {
            for j in 0..TARGETS.len() {
                curve.unconverged[j] &= curve.rows[j].is_none();
            }
        }
        curves
    }
}

impl fmt::Display for Study {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.summary())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn numbers_for_people() {
        assert_eq!(format_seconds(4.12e-5), "41.2 µs");
        assert_eq!(format_seconds(0.0031), "3.10 ms");
        assert_eq!(short(1e-10), "1e-10");
        assert_eq!(short(9.765625e-4), "9.766e-4");
    }
}
