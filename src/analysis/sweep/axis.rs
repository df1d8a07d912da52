//! How one key varies: a grid of values, or a distribution drawn from once per run.
//!
//! Run i's draws come from a generator seeded by (seed, i) alone — xoshiro256++ (Blackman & Vigna, "Scrambled
//! linear pseudorandom number generators", ACM TOMS 47, 2021), whose output rand documents as reproducible — so a
//! draw never depends on which thread, process or shard runs it.

use rand::SeedableRng;
use rand::rngs::Xoshiro256PlusPlus;
use rand_distr::{Distribution, Normal, Uniform};

/// One varied key's values.
#[derive(Debug, Clone, PartialEq)]
pub enum Axis {
    /// A grid axis: these values, in order.
    Grid(Vec<f64>),
    /// One draw per run from N(mean, sd²).
    Normal(Normal<f64>),
    /// One draw per run, uniform on [low, high).
    Uniform(Uniform<f64>),
}

/// The most values one grid axis may have.
pub const MAX_GRID: f64 = 1e8;

fn finite(name: &str, v: f64) -> Result<f64, String> {
    if v.is_finite() {
        Ok(v)
    } else {
        Err(format!("{name} must be a finite number, got {v}"))
    }
}

/// The number of values `n` of linspace or logspace: a whole number ≥ 1.
fn count(n: f64) -> Result<usize, String> {
    if n.fract() == 0.0 && (1.0..=MAX_GRID).contains(&n) {
        Ok(n as usize)
    } else {
        Err(format!(
            "[from, to, n]: n must be a whole number from 1 to {MAX_GRID:e}, got {n}"
        ))
    }
}

impl Axis {
    /// `values = [..]`: at least one, all finite.
    pub fn values(values: Vec<f64>) -> Result<Self, String> {
        if values.is_empty() {
            return Err("the grid is empty: give at least one value".into());
        }
        for v in &values {
            finite("every value", *v)?;
        }
        Ok(Self::Grid(values))
    }

    /// `linspace = [from, to, n]`: n values evenly spaced from `from` to `to`, both included (n = 1: `from`).
    ///
    /// ```
    /// use eulerdyn::analysis::sweep::Axis;
    /// assert_eq!(Axis::linspace(0.0, 45.0, 4.0), Ok(Axis::Grid(vec![0.0, 15.0, 30.0, 45.0])));
    /// assert!(Axis::linspace(0.0, 1.0, 0.0).is_err());
    /// ```
    pub fn linspace(from: f64, to: f64, n: f64) -> Result<Self, String> {
        let (from, to, n) = (finite("from", from)?, finite("to", to)?, count(n)?);
        let step = if n > 1 {
            (to - from) / (n - 1) as f64
        } else {
            0.0
        };
        let mut values: Vec<f64> = (0..n).map(|k| from + step * k as f64).collect();
        values[n - 1] = if n > 1 { to } else { from };
        Ok(Self::Grid(values))
    }

    /// `geomspace = [from, to, n]` (as numpy's `geomspace`; `logspace` is the same): n values spaced
    /// geometrically from `from` to `to`, both included, x_k = from·(to/from)^(k/(n−1)); `from` and `to` are the
    /// values themselves (not powers of ten, unlike numpy's `logspace`), non-zero and of one sign.
    ///
    /// ```
    /// use eulerdyn::analysis::sweep::Axis;
    /// let Axis::Grid(v) = Axis::logspace(1.0, 100.0, 3.0).unwrap() else { panic!() };
    /// assert_eq!(v[0], 1.0);
    /// assert!((v[1] - 10.0).abs() < 1e-14);
    /// assert_eq!(v[2], 100.0);
    /// ```
    pub fn logspace(from: f64, to: f64, n: f64) -> Result<Self, String> {
        let (from, to, n) = (finite("from", from)?, finite("to", to)?, count(n)?);
        if from == 0.0 || to == 0.0 || from.signum() != to.signum() {
            return Err(format!(
                "[from, to, n]: from and to must be non-zero and of the same sign for geometric spacing, got {from} and {to}"
            ));
        }
        let ratio = if n > 1 {
            (to / from).powf(1.0 / (n - 1) as f64)
        } else {
            1.0
        };
        let mut values: Vec<f64> = (0..n).map(|k| from * ratio.powi(k as i32)).collect();
        values[n - 1] = if n > 1 { to } else { from };
        Ok(Self::Grid(values))
    }

    /// `normal = { mean, sd }`: sd ≥ 0.
    pub fn normal(mean: f64, sd: f64) -> Result<Self, String> {
        let (mean, sd) = (finite("mean", mean)?, finite("sd", sd)?);
        if sd < 0.0 {
            return Err(format!("sd must be ≥ 0, got {sd}"));
        }
        Normal::new(mean, sd)
            .map(Self::Normal)
            .map_err(|_| format!("sd must be ≥ 0, got {sd}"))
    }

    /// `uniform = { low, high }`: low < high.
    pub fn uniform(low: f64, high: f64) -> Result<Self, String> {
        let (low, high) = (finite("low", low)?, finite("high", high)?);
        if low >= high {
            return Err(format!("low must be less than high, got {low} and {high}"));
        }
        Uniform::new(low, high)
            .map(Self::Uniform)
            .map_err(|e| format!("{e}"))
    }

    /// The number of grid values; `None` for a distribution.
    pub fn grid_len(&self) -> Option<usize> {
        match self {
            Self::Grid(values) => Some(values.len()),
            _ => None,
        }
    }

    /// A value the key can take, to check the key before any run: the first grid value, the mean, or `low`.
    pub fn probe(&self) -> f64 {
        match self {
            Self::Grid(values) => values[0],
            Self::Normal(d) => d.mean(),
            Self::Uniform(d) => {
                let mut rng = Xoshiro256PlusPlus::seed_from_u64(0);
                d.sample(&mut rng)
            }
        }
    }

    /// The value of a grid axis at `index`, or a draw from `rng`.
    pub fn value(&self, index: usize, rng: &mut Xoshiro256PlusPlus) -> f64 {
        match self {
            Self::Grid(values) => values[index],
            Self::Normal(d) => d.sample(rng),
            Self::Uniform(d) => d.sample(rng),
        }
    }
}

/// The generator of run `run`'s draws: seeded by (seed, run) through two rounds of SplitMix64 (Steele, Lea &
/// Flood, "Fast splittable pseudorandom number generators", OOPSLA 2014), so that neighbouring runs and seeds
/// give unrelated streams.
pub fn run_rng(seed: u64, run: u64) -> Xoshiro256PlusPlus {
    Xoshiro256PlusPlus::seed_from_u64(splitmix64(splitmix64(seed) ^ run))
}

fn splitmix64(x: u64) -> u64 {
    let mut z = x.wrapping_add(0x9e37_79b9_7f4a_7c15);
    z = (z ^ (z >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
    z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
    z ^ (z >> 31)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn draws_depend_on_seed_and_run_only() {
        let axis = Axis::normal(2.0, 0.01).unwrap();
        let draw = |seed, run| axis.value(0, &mut run_rng(seed, run));
        assert_eq!(draw(1, 7), draw(1, 7));
        assert_ne!(draw(1, 7), draw(1, 8));
        assert_ne!(draw(1, 7), draw(2, 7));
    }

    #[test]
    fn normal_draws_have_the_stated_mean_and_sd() {
        // 10^4 draws: the sample mean is within 4 standard errors (sd/100) of the mean.
        let axis = Axis::normal(2.0, 0.5).unwrap();
        let draws: Vec<f64> = (0..10_000)
            .map(|i| axis.value(0, &mut run_rng(3, i)))
            .collect();
        let mean = draws.iter().sum::<f64>() / 1e4;
        let sd = (draws.iter().map(|x| (x - mean).powi(2)).sum::<f64>() / (1e4 - 1.0)).sqrt();
        assert!((mean - 2.0).abs() < 4.0 * 0.5 / 100.0, "mean {mean}");
        assert!((sd - 0.5).abs() < 0.02, "sd {sd}");
    }

    #[test]
    fn refuses_empty_and_degenerate_axes() {
        assert!(Axis::values(vec![]).unwrap_err().contains("empty"));
        assert!(Axis::linspace(0.0, 1.0, 2.5).is_err());
        assert!(Axis::logspace(-1.0, 1.0, 3.0).is_err());
        assert!(Axis::normal(0.0, -1.0).is_err());
        assert!(Axis::uniform(1.0, 1.0).is_err());
    }
}
