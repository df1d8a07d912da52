//! A curve's points reduced to bounded memory (at most about [`MAX_POINTS`](super::MAX_POINTS) per curve), keeping
//! for each run of consecutive rows its smallest and its largest value, in time order, so that peaks, flips and
//! spikes stay visible.

use super::MAX_POINTS;

/// A curve's points reduced to bounded memory: consecutive rows are grouped in buckets, and each bucket keeps its
/// smallest and largest value. Buckets start at one row each; when there are too many, neighbours merge.
#[derive(Debug, Clone, Default)]
pub(super) struct Decimator {
    /// (lowest point, highest point) of each bucket.
    buckets: Vec<((f64, f64), (f64, f64))>,
    /// Rows per full bucket.
    per_bucket: usize,
    /// Rows in the last bucket.
    in_last: usize,
}

impl Decimator {
    pub(super) fn new() -> Self {
        Self {
            buckets: Vec::new(),
            per_bucket: 1,
            in_last: 0,
        }
    }

    pub(super) fn push(&mut self, t: f64, y: f64) {
        let point = (t, y);
        if let Some(last) = self.buckets.last_mut()
            && self.in_last < self.per_bucket
        {
            if y < last.0.1 {
                last.0 = point;
            }
            if y > last.1.1 {
                last.1 = point;
            }
            self.in_last += 1;
            return;
        }
        if self.buckets.len() >= MAX_POINTS / 2 {
            // Every bucket is full: merge neighbours, halving their number.
            self.buckets = self
                .buckets
                .chunks(2)
                .map(|pair| {
                    let lo = pair
                        .iter()
                        .map(|b| b.0)
                        .fold(pair[0].0, |a, b| if b.1 < a.1 { b } else { a });
                    let hi = pair
                        .iter()
                        .map(|b| b.1)
                        .fold(pair[0].1, |a, b| if b.1 > a.1 { b } else { a });
                    (lo, hi)
                })
                .collect();
            self.per_bucket *= 2;
        }
        self.buckets.push((point, point));
        self.in_last = 1;
    }

    /// The kept points, in time order.
    pub(super) fn points(&self) -> Vec<(f64, f64)> {
        let mut out = Vec::with_capacity(2 * self.buckets.len());
        for &(lo, hi) in &self.buckets {
            if lo == hi {
                out.push(lo);
            } else if lo.0 <= hi.0 {
                out.extend([lo, hi]);
            } else {
                out.extend([hi, lo]);
            }
        }
        out
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_decimator_keeps_every_point_of_a_short_curve() {
        let mut d = Decimator::new();
        for k in 0..100 {
            d.push(f64::from(k), f64::from(k * k));
        }
        let points = d.points();
        assert_eq!(points.len(), 100);
        assert_eq!(points[99], (99.0, 9801.0));
    }

    #[test]
    fn the_decimator_bounds_memory_and_keeps_the_extremes_in_time_order() {
        let mut d = Decimator::new();
        let n = 1_000_003;
        for k in 0..n {
            let t = f64::from(k);
            // A single spike that must survive.
            let y = if k == 777_777 { 50.0 } else { (t * 1e-3).sin() };
            d.push(t, y);
        }
        let points = d.points();
        assert!(points.len() <= MAX_POINTS + 2, "{}", points.len());
        assert!(points.contains(&(777_777.0, 50.0)));
        assert!(points.windows(2).all(|w| w[0].0 < w[1].0));
        let lowest = points.iter().map(|p| p.1).fold(f64::INFINITY, f64::min);
        assert!(lowest < -0.999_999);
        assert_eq!(points.last().map(|p| p.0), Some(f64::from(n - 1)));
    }
}
