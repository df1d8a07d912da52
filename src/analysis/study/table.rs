//! The study as a CSV table: a header row ([`TABLE_COLUMNS`]), then a row per run. Numbers in the shortest form
//! that reads back to the same f64; an empty cell is no value (rtol of a fixed-step run, errors of a failed run).

use std::io::{self, Write};

use super::Study;

/// The columns of the table, in order: the contract's twelve, then the extra ones.
pub const TABLE_COLUMNS: [&str; 17] = [
    "method",
    "frame",
    "rtol",
    "dt",
    "err_omega",
    "err_attitude",
    "energy_drift",
    "H_drift",
    "wall_s",
    "steps",
    "rejected",
    "evals",
    "err_H_s",
    "atol",
    "backend",
    "repeats",
    "status",
];

/// A number for the table: shortest form that reads back to the same f64; empty for none or NaN.
fn cell(v: Option<f64>) -> String {
    match v {
        Some(x) if !x.is_nan() => format!("{x:e}"),
        _ => String::new(),
    }
}

impl Study {
    /// Writes the table as CSV: a header row ([`TABLE_COLUMNS`]), then a row per run. Empty cells: no value
    /// (rtol of a fixed-step run, errors of a failed run).
    pub fn write_table(&self, out: impl Write) -> io::Result<()> {
        let mut w = csv::Writer::from_writer(out);
        w.write_record(TABLE_COLUMNS)?;
        for r in &self.rows {
            let ok = r.failure.is_none();
            let when_ok = |v: f64| cell(ok.then_some(v));
            w.write_record([
                r.method.clone(),
                r.form.name().to_string(),
                cell(r.rtol),
                cell(r.dt),
                when_ok(r.err_omega),
                cell(r.err_attitude.filter(|_| ok)),
                when_ok(r.energy_drift),
                when_ok(r.h_drift),
                when_ok(r.wall_s),
                r.steps.to_string(),
                r.rejected.to_string(),
                r.evals.to_string(),
                cell(r.err_h_s.filter(|_| ok)),
                cell(r.atol),
                r.backend.name().to_string(),
                r.repeats.to_string(),
                r.failure
                    .as_ref()
                    .map_or_else(|| "ok".to_string(), |f| format!("failed: {f}")),
            ])?;
        }
        w.flush()
    }

    /// The table as CSV text.
    pub fn table_csv(&self) -> String {
        let mut bytes = Vec::new();
        // Writing into a Vec cannot fail.
        let _ = self.write_table(&mut bytes);
        String::from_utf8_lossy(&bytes).into_owned()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn cells() {
        assert_eq!(cell(Some(1e-10)), "1e-10");
        assert_eq!(cell(Some(0.125)), "1.25e-1");
        assert_eq!(cell(None), "");
        assert_eq!(cell(Some(f64::NAN)), "");
    }
}
