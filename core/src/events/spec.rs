//! One `[[event]]` as Rust code gives it: a moment between the rows to locate — a quantity crossing a value, or
//! its local extrema — built by [`EventSpec`]'s constructors (the spec is declared with its table in `keys.rs`,
//! validated in `validate.rs`).

use super::{Direction, EventSpec, Extremum};

/// What an `[[event]]` looks for: exactly one of `crosses` and `extremum`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum ConditionSpec {
    /// `crosses = value`, `direction` (absent: both).
    Crosses {
        /// The value crossed.
        value: f64,
        /// Which crossings count.
        direction: Direction,
    },
    /// `extremum = "max" | "min"`.
    Extremum(Extremum),
}

impl EventSpec {
    /// The event `name`: `when` crossing `value` in `direction`.
    ///
    /// ```
    /// use eulerdyn::scene::{Direction, EventSpec};
    /// let flip = EventSpec::crossing("flip", "omega_b_y", 0.0, Direction::Down);
    /// assert!(!flip.stop);
    /// ```
    pub fn crossing(name: &str, when: &str, value: f64, direction: Direction) -> Self {
        Self::of(
            name.into(),
            when.into(),
            ConditionSpec::Crosses { value, direction },
        )
    }

    /// The event `name`: every local extremum of `when` of the kind `extremum`.
    ///
    /// ```
    /// use eulerdyn::scene::{ConditionSpec, EventSpec, Extremum};
    /// let peak = EventSpec::extremum("peak_load", "|R_A|", Extremum::Max);
    /// assert_eq!(peak.condition, ConditionSpec::Extremum(Extremum::Max));
    /// ```
    pub fn extremum(name: &str, when: &str, extremum: Extremum) -> Self {
        Self::of(name.into(), when.into(), ConditionSpec::Extremum(extremum))
    }

    /// The same event, ending the run at its first occurrence.
    pub fn stopping(mut self) -> Self {
        self.stop = true;
        self
    }
}
