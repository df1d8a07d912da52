//! A moving mass's path in body axes: r(t), ṙ(t), r̈(t) from `from` to `to` over [start, start + duration] with a
//! `linear` or `smooth` profile, or from a table of positions (linear between rows, held outside).

use nalgebra::Vector3;

use crate::named::{Named, serde_by_name};

/// How a mass moves from `from` to `to`: the fraction s(τ) of the way at τ = (t − start)/duration ∈ [0, 1].
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum Profile {
    /// s = τ: constant relative speed, which starts and stops at once (an impulsive internal drive: ω jumps).
    Linear,
    /// s = 3τ² − 2τ³ (the cubic smoothstep): zero relative speed at both ends.
    #[default]
    Smooth,
}

impl Named for Profile {
    const ALL: &'static [Self] = &[Profile::Linear, Profile::Smooth];

    fn name(&self) -> &'static str {
        match self {
            Profile::Linear => "linear",
            Profile::Smooth => "smooth",
        }
    }
}

serde_by_name!(Profile);

/// Which one-sided value a path gives at a corner (a time where its velocity or acceleration jumps).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Side {
    /// The limit from before: a step that ends at the corner.
    Before,
    /// The limit from after: a row, and a step that starts at the corner.
    After,
}

/// Position (m), velocity (m/s) and acceleration (m/s²) of a mass relative to the body, body axes.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Kinematics {
    /// r.
    pub r: Vector3<f64>,
    /// ṙ.
    pub v: Vector3<f64>,
    /// r̈ (its finite part: a `linear` start or a table row is a jump of ṙ, not an acceleration).
    pub a: Vector3<f64>,
}

/// A validated path.
#[derive(Debug, Clone, PartialEq)]
pub enum MassPath {
    /// From `from` to `to` over [start, start + duration].
    Move {
        /// Position before `start` (m).
        from: Vector3<f64>,
        /// Position from `start + duration` on (m).
        to: Vector3<f64>,
        /// s.
        start: f64,
        /// s, > 0.
        duration: f64,
        /// s(τ).
        profile: Profile,
    },
    /// Positions at strictly increasing times (at least two rows): linear between rows, the first and last held.
    Table {
        /// Row times (s).
        t: Vec<f64>,
        /// Positions (m).
        r: Vec<Vector3<f64>>,
    },
}

impl MassPath {
    /// r, ṙ, r̈ at t, one-sided at a corner.
    ///
    /// ```
    /// use eulerdyn::shape_change::{MassPath, Profile, Side};
    /// use nalgebra::Vector3;
    /// let path = MassPath::Move {
    ///     from: Vector3::zeros(), to: Vector3::new(1.0, 0.0, 0.0), start: 0.0, duration: 2.0,
    ///     profile: Profile::Smooth,
    /// };
    /// let mid = path.at(1.0, Side::After);
    /// assert_eq!((mid.r.x, mid.v.x, mid.a.x), (0.5, 0.75, 0.0));
    /// ```
    pub fn at(&self, t: f64, side: Side) -> Kinematics {
        match self {
            MassPath::Move {
                from,
                to,
                start,
                duration,
                profile,
            } => {
                let (s, ds, dds) = profile_at(*profile, (t - start) / duration, side);
                let span = to - from;
                Kinematics {
                    r: from + span * s,
                    v: span * (ds / duration),
                    a: span * (dds / (duration * duration)),
                }
            }
            MassPath::Table { t: times, r } => table_at(times, r, t, side),
        }
    }

    /// The corners of the path (where ṙ or r̈ jumps), in increasing order.
    pub fn corners(&self) -> Vec<f64> {
        match self {
            MassPath::Move {
                start, duration, ..
            } => vec![*start, start + duration],
            MassPath::Table { t, .. } => t.clone(),
        }
    }

    /// The time from which the mass no longer moves (s).
    pub fn end(&self) -> f64 {
        self.corners().last().copied().unwrap_or(0.0)
    }
}

/// s(τ), ds/dτ and d²s/dτ² of `profile`; 0 before τ = 0 and 1 after τ = 1 with zero rates; at τ = 0 and τ = 1 the
/// side's limit.
fn profile_at(profile: Profile, tau: f64, side: Side) -> (f64, f64, f64) {
    let inside = match side {
        Side::After => (0.0..1.0).contains(&tau),
        Side::Before => tau > 0.0 && tau <= 1.0,
    };
    if !inside {
        return (if tau <= 0.0 { 0.0 } else { 1.0 }, 0.0, 0.0);
    }
    match profile {
        Profile::Linear => (tau, 1.0, 0.0),
        Profile::Smooth => (
            tau * tau * (3.0 - 2.0 * tau),
            6.0 * tau * (1.0 - tau),
            6.0 - 12.0 * tau,
        ),
    }
}

/// The interval [t_i, t_{i+1}] of the rows `times` that holds t — the later one at a row for `After`, the earlier
/// for `Before` — or, outside the rows, `Err` with the row held there (the first or the last).
pub(crate) fn interval(times: &[f64], t: f64, side: Side) -> Result<usize, usize> {
    let n = times.len() - 1;
    let outside = match side {
        Side::After => t < times[0] || t >= times[n],
        Side::Before => t <= times[0] || t > times[n],
    };
    match (outside, side) {
        (true, _) => Err(if t <= times[0] { 0 } else { n }),
        (false, Side::After) => Ok(times.partition_point(|ti| *ti <= t) - 1),
        (false, Side::Before) => Ok(times.partition_point(|ti| *ti < t) - 1),
    }
}

/// The table's position at t (linear between rows, held outside) and its slope on the side's interval.
fn table_at(times: &[f64], r: &[Vector3<f64>], t: f64, side: Side) -> Kinematics {
    match interval(times, t, side) {
        Err(held) => Kinematics {
            r: r[held],
            v: Vector3::zeros(),
            a: Vector3::zeros(),
        },
        Ok(i) => {
            let v = (r[i + 1] - r[i]) / (times[i + 1] - times[i]);
            Kinematics {
                r: r[i] + v * (t - times[i]),
                v,
                a: Vector3::zeros(),
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn x(v: f64) -> Vector3<f64> {
        Vector3::new(v, 0.0, 0.0)
    }

    #[test]
    fn a_linear_move_starts_and_stops_at_once_and_its_sides_say_so() {
        let path = MassPath::Move {
            from: x(1.0),
            to: x(3.0),
            start: 1.0,
            duration: 4.0,
            profile: Profile::Linear,
        };
        assert_eq!(path.at(1.0, Side::Before).v, x(0.0));
        assert_eq!(path.at(1.0, Side::After).v, x(0.5));
        assert_eq!(path.at(5.0, Side::Before).v, x(0.5));
        assert_eq!(path.at(5.0, Side::After).v, x(0.0));
        assert_eq!(path.at(5.0, Side::After).r, x(3.0));
        assert_eq!(path.at(3.0, Side::After).r, x(2.0));
        assert_eq!(path.at(0.0, Side::After).r, x(1.0));
    }

    #[test]
    fn the_smooth_profile_is_the_derivative_of_its_position() {
        let path = MassPath::Move {
            from: x(0.0),
            to: x(2.0),
            start: 0.5,
            duration: 3.0,
            profile: Profile::Smooth,
        };
        // Central differences of r and ṙ: error h²/6 |r'''| ≤ 1e-8 · 12·2/27, far below the 1e-7 allowed.
        let h = 1e-4;
        for t in [0.7, 1.3, 2.0, 3.1] {
            let (a, b) = (path.at(t - h, Side::After), path.at(t + h, Side::After));
            let k = path.at(t, Side::After);
            assert!(((b.r - a.r) / (2.0 * h) - k.v).norm() < 1e-7);
            assert!(((b.v - a.v) / (2.0 * h) - k.a).norm() < 1e-7);
        }
        // Zero relative speed at both ends (the smoothstep's s'(0) = s'(1) = 0).
        assert_eq!(path.at(0.5, Side::After).v, x(0.0));
        assert_eq!(path.at(3.5, Side::Before).v, x(0.0));
    }

    #[test]
    fn a_table_is_linear_between_rows_and_held_outside() {
        let path = MassPath::Table {
            t: vec![1.0, 2.0, 4.0],
            r: vec![x(0.0), x(1.0), x(2.0)],
        };
        assert_eq!(path.at(0.0, Side::After).r, x(0.0));
        assert_eq!(path.at(1.5, Side::After).r, x(0.5));
        assert_eq!(path.at(2.0, Side::Before).v, x(1.0));
        assert_eq!(path.at(2.0, Side::After).v, x(0.5));
        assert_eq!(path.at(4.0, Side::After).v, x(0.0));
        assert_eq!(path.at(9.0, Side::After).r, x(2.0));
        assert_eq!(path.corners(), vec![1.0, 2.0, 4.0]);
    }
}
