//! Output ("row") times of a run.

use thiserror::Error;

/// Largest row count whose times k·every are all exactly representable grid indices (2^53).
const MAX_ROWS: u64 = 1 << 53;

/// Relative margin that keeps a grid row from landing (almost) on t_end: a grid time k·every
/// is kept only if k·every < t_end − 1e-12·t_end, so no near-duplicate last row appears.
const END_MARGIN: f64 = 1e-12;

/// Output times of a run: t_k = k·every for every k ≥ 0 with k·every < t_end − 1e-12·t_end,
/// followed by t_end itself. t_end = 0 gives the single row t = 0.
///
/// Each grid time is computed as the product `k as f64 * every` (one rounding), never as a
/// running sum, so times do not drift over long runs.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Schedule {
    every: f64,
    t_end: f64,
    /// Number of grid rows k·every (excluding the final t_end row).
    grid: u64,
}

/// Invalid [`Schedule`] parameters.
#[derive(Debug, Clone, Copy, PartialEq, Error)]
pub enum ScheduleError {
    /// `every` must be positive and finite.
    #[error("output interval every = {every} must be positive and finite")]
    InvalidEvery {
        /// The rejected value.
        every: f64,
    },
    /// `t_end` must be ≥ 0 and finite.
    #[error("end time t_end = {t_end} must be non-negative and finite")]
    InvalidEnd {
        /// The rejected value.
        t_end: f64,
    },
    /// More than 2^53 rows (or more than `usize::MAX`) would be produced.
    #[error("every = {every} and t_end = {t_end} give too many output rows — increase every")]
    TooManyRows {
        /// Output interval.
        every: f64,
        /// End time.
        t_end: f64,
    },
}

impl Schedule {
    /// Creates the schedule t_k = k·every (k·every < t_end·(1 − 1e-12)), then t_end.
    pub fn new(every: f64, t_end: f64) -> Result<Self, ScheduleError> {
        if !(every.is_finite() && every > 0.0) {
            return Err(ScheduleError::InvalidEvery { every });
        }
        if !(t_end.is_finite() && t_end >= 0.0) {
            return Err(ScheduleError::InvalidEnd { t_end });
        }
        let limit = t_end - END_MARGIN * t_end;
        // Count k ≥ 0 with k·every < limit: start from ⌈limit/every⌉, then fix rounding with the
        // products actually used by `time`.
        let estimate = (limit / every).ceil();
        if estimate.is_nan() || estimate >= MAX_ROWS as f64 {
            return Err(ScheduleError::TooManyRows { every, t_end });
        }
        let mut grid = estimate.max(0.0) as u64;
        while grid > 0 && (grid - 1) as f64 * every >= limit {
            grid -= 1;
        }
        while (grid as f64) * every < limit {
            grid += 1;
        }
        if grid >= MAX_ROWS || usize::try_from(grid + 1).is_err() {
            return Err(ScheduleError::TooManyRows { every, t_end });
        }
        Ok(Self { every, t_end, grid })
    }

    /// Output interval.
    pub fn every(&self) -> f64 {
        self.every
    }

    /// Final time (the last row).
    pub fn t_end(&self) -> f64 {
        self.t_end
    }

    /// Number of rows (≥ 1): the grid rows plus the final t_end row.
    pub fn len(&self) -> usize {
        // Checked in `new`.
        (self.grid + 1) as usize
    }

    /// Always false: a schedule has at least the row t_end (t = 0 when t_end = 0).
    pub fn is_empty(&self) -> bool {
        false
    }

    /// Time of row `k`: k·every for k < len − 1, t_end for k = len − 1.
    ///
    /// # Panics
    /// If `k >= self.len()`.
    pub fn time(&self, k: usize) -> f64 {
        let k64 = k as u64;
        if k64 < self.grid {
            k64 as f64 * self.every
        } else if k64 == self.grid {
            self.t_end
        } else {
            panic!("row {k} out of range: the schedule has {} rows", self.len())
        }
    }

    /// The largest step a fixed-step driver takes when asked for steps of `dt`: each row interval Δ is cut into
    /// n = ⌈Δ/dt⌉ equal steps Δ/n (see [`super::run_fixed_step`]), so the step is at most min(dt, every).
    ///
    /// ```
    /// use eulerdyn::integrate::Schedule;
    /// let schedule = Schedule::new(0.01, 5.0).unwrap();
    /// assert_eq!(schedule.largest_fixed_step(0.05), 0.01); // capped at the row spacing
    /// assert_eq!(schedule.largest_fixed_step(0.004), 0.01 / 3.0);
    /// ```
    pub fn largest_fixed_step(&self, dt: f64) -> f64 {
        let step = |delta: f64| delta / super::rk4_substeps(delta, dt) as f64;
        let rows = self.len();
        if rows < 2 {
            return 0.0;
        }
        let last = self.t_end - self.time(rows - 2);
        if rows > 2 {
            step(self.every).max(step(last))
        } else {
            step(last)
        }
    }

    /// Iterator over the row times, in increasing order.
    pub fn iter(&self) -> ScheduleIter {
        ScheduleIter {
            schedule: *self,
            next: 0,
        }
    }
}

impl IntoIterator for &Schedule {
    type Item = f64;
    type IntoIter = ScheduleIter;
    fn into_iter(self) -> ScheduleIter {
        self.iter()
    }
}

/// Iterator over the row times of a [`Schedule`] (see [`Schedule::iter`]).
#[derive(Debug, Clone)]
pub struct ScheduleIter {
    schedule: Schedule,
    next: usize,
}

impl Iterator for ScheduleIter {
    type Item = f64;

    fn next(&mut self) -> Option<f64> {
        if self.next < self.schedule.len() {
            let t = self.schedule.time(self.next);
            self.next += 1;
            Some(t)
        } else {
            None
        }
    }

    fn size_hint(&self) -> (usize, Option<usize>) {
        let n = self.schedule.len() - self.next;
        (n, Some(n))
    }
}

impl ExactSizeIterator for ScheduleIter {}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn multiple_of_every_has_no_duplicate_end() {
        let s = Schedule::new(0.1, 1.0).unwrap();
        let t: Vec<f64> = s.iter().collect();
        assert_eq!(t.len(), 11);
        assert_eq!(s.len(), 11);
        for (k, &tk) in t.iter().enumerate().take(10) {
            assert_eq!(tk, k as f64 * 0.1);
        }
        assert_eq!(t[10], 1.0);
    }

    #[test]
    fn non_multiple_end_is_appended() {
        let s = Schedule::new(0.3, 1.0).unwrap();
        let t: Vec<f64> = s.iter().collect();
        assert_eq!(t, vec![0.0, 0.3, 0.6, 3.0 * 0.3, 1.0]);
    }

    #[test]
    fn zero_end_is_single_row() {
        let s = Schedule::new(0.5, 0.0).unwrap();
        assert_eq!(s.len(), 1);
        assert_eq!(s.iter().collect::<Vec<_>>(), vec![0.0]);
    }

    #[test]
    fn end_shorter_than_every() {
        let s = Schedule::new(2.0, 0.5).unwrap();
        assert_eq!(s.iter().collect::<Vec<_>>(), vec![0.0, 0.5]);
    }

    #[test]
    fn near_duplicate_last_row_is_dropped() {
        // 3·every = 1 − 1e-13 lies within 1e-12·t_end below t_end = 1: that grid row is dropped,
        // so the run does not end with two rows 1e-13 apart.
        let every = (1.0 - 1e-13) / 3.0;
        let s = Schedule::new(every, 1.0).unwrap();
        let t: Vec<f64> = s.iter().collect();
        assert_eq!(t, vec![0.0, every, 2.0 * every, 1.0]);
        // Just outside the margin the grid row is kept.
        let every = (1.0 - 1e-11) / 3.0;
        assert_eq!(Schedule::new(every, 1.0).unwrap().len(), 5);
    }

    #[test]
    fn times_are_products_and_strictly_increasing() {
        let s = Schedule::new(0.01, 1000.0).unwrap();
        assert_eq!(s.len(), 100_001);
        let mut prev = -1.0;
        for (k, t) in s.iter().enumerate() {
            assert!(t > prev);
            if k + 1 < s.len() {
                assert_eq!(t, k as f64 * 0.01);
            }
            prev = t;
        }
        assert_eq!(prev, 1000.0);
    }

    #[test]
    fn invalid_parameters() {
        assert!(matches!(
            Schedule::new(0.0, 1.0),
            Err(ScheduleError::InvalidEvery { .. })
        ));
        assert!(matches!(
            Schedule::new(f64::NAN, 1.0),
            Err(ScheduleError::InvalidEvery { .. })
        ));
        assert!(matches!(
            Schedule::new(0.1, -1.0),
            Err(ScheduleError::InvalidEnd { .. })
        ));
        assert!(matches!(
            Schedule::new(0.1, f64::INFINITY),
            Err(ScheduleError::InvalidEnd { .. })
        ));
        assert!(matches!(
            Schedule::new(1e-300, 1e10),
            Err(ScheduleError::TooManyRows { .. })
        ));
    }

    #[test]
    #[should_panic(expected = "out of range")]
    fn time_out_of_range_panics() {
        Schedule::new(0.5, 1.0).unwrap().time(3);
    }
}
