//! The wall time of a run: the median of timed repeats of the integration alone (`simulate::run` with a sink that
//! discards the rows), fewer repeats for slow runs.

use std::convert::Infallible;
use std::hint::black_box;
use std::time::Instant;

use crate::sample::Sample;
use crate::scene::Scene;
use crate::simulate::{self, RunError};

/// How many timed repeats a run gets after a first run of `first_seconds`: `repeats`, at most 3 over 0.2 s, 1 over
/// 1 s (and at least 1).
pub(super) fn repeats_after(first_seconds: f64, repeats: usize) -> usize {
    if first_seconds > 1.0 {
        1
    } else if first_seconds > 0.2 {
        3.min(repeats)
    } else {
        repeats
    }
    .max(1)
}

/// The median wall time (s) of `repeats` runs of `scene` whose rows are discarded.
pub(super) fn median_wall_time(scene: &Scene, repeats: usize) -> Result<f64, RunError<Infallible>> {
    let mut times = Vec::with_capacity(repeats);
    for _ in 0..repeats {
        let start = Instant::now();
        simulate::run(scene, |s: &Sample| {
            black_box(s);
            Ok::<(), Infallible>(())
        })?;
        times.push(start.elapsed().as_secs_f64());
    }
    Ok(median(&mut times))
}

/// The median (upper median for an even count); NaN for no values.
fn median(values: &mut [f64]) -> f64 {
    if values.is_empty() {
        return f64::NAN;
    }
    values.sort_by(f64::total_cmp);
    values[values.len() / 2]
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn median_and_repeats() {
        assert_eq!(median(&mut [3.0, 1.0, 2.0]), 2.0);
        assert!(median(&mut []).is_nan());
        assert_eq!(repeats_after(0.01, 5), 5);
        assert_eq!(repeats_after(0.5, 5), 3);
        assert_eq!(repeats_after(2.0, 5), 1);
        assert_eq!(repeats_after(0.01, 0), 1);
    }
}
