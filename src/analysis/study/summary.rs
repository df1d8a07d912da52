//! The study in words: the reference, the cheapest method for each of [`TARGETS`], the wall time each curve takes
//! to reach them, and what was not swept.

use std::fmt::{self, Write as _};

use crate::frames::Form;

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
    pub frame: Form,
    /// Index into [`Study::rows`] of the fastest run of the curve reaching each target.
    pub rows: [Option<usize>; 3],
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
            r.frame.name(),
            r.setting(),
            r.error(self.measure).unwrap_or(f64::NAN),
            format_seconds(r.wall_s),
            r.steps,
            r.rejected,
            r.evals
        )
    }

    /// The cheapest run for one error level (or the closest any run came), and the cheapest that integrates when
    /// that is another run.
    fn write_cheapest(&self, out: &mut String, c: &Cheapest) {
        let column = self.measure.column();
        let _ = match c.row.map(|i| &self.rows[i]) {
            Some(r) => writeln!(
                out,
                "cheapest for {column} <= {:e}: {}",
                c.target,
                self.describe_run(r)
            ),
            None => {
                let best = self
                    .rows
                    .iter()
                    .filter_map(|r| r.error(self.measure).map(|e| (e, r)))
                    .min_by(|a, b| a.0.total_cmp(&b.0));
                match best {
                    Some((e, r)) => writeln!(
                        out,
                        "cheapest for {column} <= {:e}: no run reaches it (smallest: {e:.2e}, {} {} form {})",
                        c.target,
                        r.method,
                        r.frame.name(),
                        r.setting()
                    ),
                    None => writeln!(
                        out,
                        "cheapest for {column} <= {:e}: no run completed",
                        c.target
                    ),
                }
            }
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
            "\nwall time to reach {column} <= {} (the cheapest run of each method and form; - : not reached):",
            TARGETS.map(|t| format!("{t:e}")).join(" / ")
        );
        let _ = write!(out, "{:<20} {:<6}", "method", "form");
        for t in TARGETS {
            let _ = write!(out, " {:>10}", format!("{t:e}"));
        }
        let _ = writeln!(out);
        for c in &curves {
            let _ = write!(out, "{:<20} {:<6}", c.method, c.frame.name());
            for i in c.rows {
                let cell =
                    i.map_or_else(|| "-".to_string(), |i| format_seconds(self.rows[i].wall_s));
                let _ = write!(out, " {cell:>10}");
            }
            let _ = writeln!(out);
        }
    }

    /// For every curve (method label and form, in the order run), the fastest run reaching each of [`TARGETS`].
    pub fn costs(&self) -> Vec<CurveCost> {
        let mut curves: Vec<CurveCost> = Vec::new();
        for (i, r) in self.rows.iter().enumerate() {
            let k = match curves
                .iter()
                .position(|c| c.method == r.method && c.frame == r.frame)
            {
                Some(k) => k,
                None => {
                    curves.push(CurveCost {
                        method: r.method.clone(),
                        frame: r.frame,
                        rows: [None; 3],
                    });
                    curves.len() - 1
                }
            };
            let Some(err) = r.error(self.measure) else {
                continue;
            };
            for (slot, target) in curves[k].rows.iter_mut().zip(TARGETS) {
                let faster = slot.is_none_or(|j| r.wall_s < self.rows[j].wall_s);
                if err <= target && faster {
                    *slot = Some(i);
                }
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
