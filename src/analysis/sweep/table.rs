//! The results table: a header row, then one row per run in run order. Numbers in the shortest form that reads
//! back to the same f64 (as in a run's CSV); an empty cell is no value (a failed or invalid run's summary, a drift
//! whose initial value is 0).

use std::io::{self, Write};

use super::outcome::{RunOutcome, RunSummary};
use crate::events::Extremum;

/// Which optional summary columns a sweep's table has.
#[derive(Debug, Clone, PartialEq)]
pub struct TableLayout {
    /// The varied keys, as written in the sweep file.
    pub keys: Vec<String>,
    /// `max_F_sup_norm`: the motion has a support (fixed axis, hinge).
    pub support: bool,
    /// `max_R_A_norm, max_R_B_norm`: the scene places bearings.
    pub bearings: bool,
    /// The `[summary]` columns.
    pub summary: Vec<String>,
    /// The base scene's `[[event]]`s: each name, and the kind of an extremum event.
    pub events: Vec<(String, Option<Extremum>)>,
}

impl TableLayout {
    /// The header: `run`, the keys, `status, message`, the summary columns, `steps, evals, wall_s`, then
    /// `min_X, max_X, final_X` for each `[summary]` column, then `<name>_count, <name>_first_t` (and
    /// `<name>_max` or `<name>_min` for an extremum) for each `[[event]]`.
    pub fn header(&self) -> Vec<String> {
        let mut h = vec!["run".to_string()];
        h.extend(self.keys.iter().cloned());
        h.extend(["status", "message", "max_M_norm"].map(String::from));
        if self.support {
            h.push("max_F_sup_norm".into());
        }
        if self.bearings {
            h.extend(["max_R_A_norm", "max_R_B_norm"].map(String::from));
        }
        h.extend(
            [
                "energy_drift",
                "H_drift",
                "final_omega_b_x",
                "final_omega_b_y",
                "final_omega_b_z",
                "steps",
                "evals",
                "wall_s",
            ]
            .map(String::from),
        );
        for name in &self.summary {
            h.extend(["min_", "max_", "final_"].map(|p| format!("{p}{name}")));
        }
        for (name, extremum) in &self.events {
            h.extend(["count", "first_t"].map(|s| format!("{name}_{s}")));
            match extremum {
                Some(Extremum::Max) => h.push(format!("{name}_max")),
                Some(Extremum::Min) => h.push(format!("{name}_min")),
                None => {}
            }
        }
        h
    }

    /// The cells of one run's row, in header order.
    pub fn row(&self, o: &RunOutcome) -> Vec<String> {
        let mut number = ryu::Buffer::new();
        let mut cell = |v: Option<f64>| match v {
            Some(x) if x.is_finite() => number.format_finite(x).to_string(),
            _ => String::new(),
        };
        let s: Option<&RunSummary> = o.summary.as_ref();
        let mut r = vec![o.run.to_string()];
        r.extend(o.values.iter().map(|v| cell(Some(*v))));
        r.push(o.status.name().to_string());
        r.push(o.message.clone());
        r.push(cell(s.map(|s| s.max_m_norm)));
        if self.support {
            r.push(cell(s.and_then(|s| s.max_f_sup_norm)));
        }
        if self.bearings {
            r.push(cell(s.and_then(|s| s.max_r_a_norm)));
            r.push(cell(s.and_then(|s| s.max_r_b_norm)));
        }
        r.push(cell(s.and_then(|s| s.energy_drift)));
        r.push(cell(s.and_then(|s| s.h_drift)));
        for k in 0..3 {
            r.push(cell(s.map(|s| s.final_omega_b[k])));
        }
        r.push(o.steps.to_string());
        r.push(o.evals.to_string());
        r.push(cell(Some(o.wall_s)));
        for k in 0..self.summary.len() {
            let column = s.and_then(|s| s.columns.get(k).copied().flatten());
            r.extend((0..3).map(|j| cell(column.map(|c| c[j]))));
        }
        for (k, (_, extremum)) in self.events.iter().enumerate() {
            let event = s.and_then(|s| s.events.get(k).copied());
            r.push(event.map_or(String::new(), |e| e.count.to_string()));
            r.push(cell(event.and_then(|e| e.first_t)));
            if extremum.is_some() {
                r.push(cell(event.and_then(|e| e.extreme)));
            }
        }
        r
    }
}

/// Writes the table row by row.
pub struct TableWriter<W: Write> {
    out: csv::Writer<W>,
    layout: TableLayout,
}

impl<W: Write> TableWriter<W> {
    /// Starts the table with its header.
    pub fn new(inner: W, layout: TableLayout) -> io::Result<Self> {
        let mut out = csv::Writer::from_writer(inner);
        out.write_record(layout.header())?;
        Ok(Self { out, layout })
    }

    /// Appends one run's row.
    pub fn write(&mut self, outcome: &RunOutcome) -> io::Result<()> {
        Ok(self.out.write_record(self.layout.row(outcome))?)
    }

    /// Flushes and returns the inner writer.
    pub fn finish(self) -> io::Result<W> {
        self.out.into_inner().map_err(|e| e.into_error())
    }
}
