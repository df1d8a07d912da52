//! What one run of a sweep reports: its status and the summary of its rows, gathered row by row as the run
//! streams them (nothing of the time series is kept).

use crate::events::{Condition, Event, Extremum, Occurrence};
use crate::sample::{ColumnSet, Sample};

/// How a run ended.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Status {
    /// It ran to t_end.
    Ok,
    /// It stopped early (diverged, or the step size collapsed); the message says when and why.
    Failed,
    /// Its scene is not valid (the values make an invalid combination); the message names the key.
    Invalid,
}

impl Status {
    /// The word in the results table.
    pub fn name(self) -> &'static str {
        match self {
            Self::Ok => "ok",
            Self::Failed => "failed",
            Self::Invalid => "invalid",
        }
    }
}

/// One run of a sweep: its number, the values it was given, how it ended and what its rows showed.
#[derive(Debug, Clone, PartialEq)]
pub struct RunOutcome {
    /// The run's number, from 0.
    pub run: u64,
    /// The varied keys' values, in the sweep file's order.
    pub values: Vec<f64>,
    /// Whether the run was valid and finished.
    pub status: Status,
    /// Empty when ok.
    pub message: String,
    /// The summary of the rows; `None` for an invalid run.
    pub summary: Option<RunSummary>,
    /// Integrator steps and right-hand-side evaluations (0 unless ok).
    pub steps: u64,
    /// Right-hand-side evaluations.
    pub evals: u64,
    /// Wall time of the run: making its scene, running it, summarising it (s).
    pub wall_s: f64,
}

/// The largest and last values of a run's rows.
#[derive(Debug, Clone, PartialEq)]
pub struct RunSummary {
    /// Largest |M| (N·m).
    pub max_m_norm: f64,
    /// Largest |F_sup| (N), where the motion has a support.
    pub max_f_sup_norm: Option<f64>,
    /// Largest |R_A|, |R_B| (N), where the scene places bearings.
    pub max_r_a_norm: Option<f64>,
    /// Largest |R_B| (N).
    pub max_r_b_norm: Option<f64>,
    /// Largest |x(t) − x(0)| / |x(0)| of the energy and of |H|; `None` when x(0) = 0.
    pub energy_drift: Option<f64>,
    /// The same for |H|.
    pub h_drift: Option<f64>,
    /// ω in body axes at the last row (rad/s).
    pub final_omega_b: [f64; 3],
    /// For each `[summary]` column: min, max, final (`None` where the run has no such column).
    pub columns: Vec<Option<[f64; 3]>>,
    /// For each `[[event]]`, in order: what was located.
    pub events: Vec<EventSummary>,
}

/// One `[[event]]` of a run: `<name>_count`, `<name>_first_t` and, for extrema, `<name>_max` / `<name>_min`.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct EventSummary {
    /// Occurrences located.
    pub count: u64,
    /// The first one's time (s).
    pub first_t: Option<f64>,
    /// An extremum event's global extreme over the run: the largest located maximum, or the smallest minimum.
    pub extreme: Option<f64>,
}

/// Gathers a [`RunSummary`] from the rows of a run.
pub struct Summarizer {
    columns: ColumnSet,
    /// Where each `[summary]` column is in a row's values.
    wanted: Vec<Option<usize>>,
    row: Vec<f64>,
    first: Option<(f64, f64)>,
    summary: RunSummary,
}

/// The larger of an optional running maximum and `x`.
fn max_of(m: Option<f64>, x: f64) -> Option<f64> {
    Some(m.map_or(x, |m| m.max(x)))
}

/// |x − x0| / |x0|, `None` when x0 = 0.
fn relative(x: f64, x0: f64) -> Option<f64> {
    (x0 != 0.0).then(|| (x - x0).abs() / x0.abs())
}

impl Summarizer {
    /// A summarizer for a run with these columns, reporting the named `[summary]` columns.
    pub fn new(columns: &ColumnSet, summary_columns: &[String]) -> Self {
        let names = columns.columns();
        let wanted = summary_columns
            .iter()
            .map(|want| names.iter().position(|c| c.name == want.as_str()))
            .collect();
        Self {
            columns: columns.clone(),
            wanted,
            row: Vec::new(),
            first: None,
            summary: RunSummary {
                max_m_norm: 0.0,
                max_f_sup_norm: None,
                max_r_a_norm: None,
                max_r_b_norm: None,
                energy_drift: None,
                h_drift: None,
                final_omega_b: [f64::NAN; 3],
                columns: vec![None; summary_columns.len()],
                events: Vec::new(),
            },
        }
    }

    /// Takes one row.
    pub fn add(&mut self, s: &Sample) {
        let r = &mut self.summary;
        let h_norm = s.h_o_s.norm();
        let (energy0, h0) = *self.first.get_or_insert((s.energy, h_norm));
        r.max_m_norm = r.max_m_norm.max(s.m_o_s.norm());
        if let Some(support) = &s.support {
            r.max_f_sup_norm = max_of(r.max_f_sup_norm, support.f_sup_s.norm());
            if let Some(b) = &support.bearings {
                r.max_r_a_norm = max_of(r.max_r_a_norm, b.r_a_s.norm());
                r.max_r_b_norm = max_of(r.max_r_b_norm, b.r_b_s.norm());
            }
        }
        if let Some(d) = relative(s.energy, energy0) {
            r.energy_drift = max_of(r.energy_drift, d);
        }
        if let Some(d) = relative(h_norm, h0) {
            r.h_drift = max_of(r.h_drift, d);
        }
        r.final_omega_b = s.omega_b.into_inner().into();
        if self.wanted.iter().any(Option::is_some) {
            self.columns.values(s, &mut self.row);
            for (slot, at) in r.columns.iter_mut().zip(&self.wanted) {
                if let Some(&v) = at.and_then(|i| self.row.get(i)) {
                    *slot = Some(match *slot {
                        Some([lo, hi, _]) => [lo.min(v), hi.max(v), v],
                        None => [v, v, v],
                    });
                }
            }
        }
    }

    /// Takes the run's located events ([`crate::simulate::run_with_events`]) of the scene's `events`.
    pub fn add_events(&mut self, events: &[Event], occurrences: &[Occurrence]) {
        self.summary.events = (events.iter().enumerate())
            .map(|(i, event)| {
                let mine = || occurrences.iter().filter(move |o| o.event == i);
                let values = mine().map(|o| o.value);
                EventSummary {
                    count: mine().count() as u64,
                    first_t: mine().next().map(|o| o.t),
                    extreme: match event.condition {
                        Condition::Extremum(Extremum::Max) => values.reduce(f64::max),
                        Condition::Extremum(Extremum::Min) => values.reduce(f64::min),
                        Condition::Crossing { .. } => None,
                    },
                }
            })
            .collect();
    }

    /// The summary of the rows taken.
    pub fn finish(self) -> RunSummary {
        self.summary
    }
}
