//! Events: the moments between the rows — a quantity crossing a value, or reaching a local extremum, located on the
//! run's continuous solution (a method's dense output, or the closed form) rather than read off the rows.
//!
//! An event's quantity is a CSV column of the run, or the norm |X| of a vector column group X_s_x..z, computed from
//! a [`Sample`] by the same code that writes a row ([`ColumnSet::values`]), so every column can be watched.
//!
//! [`Locator::span`] takes the solution over one interval [t₀, t₁] (an integrator step, or the interval between
//! two rows of a closed form) as a function t ↦ sample. It evaluates the quantity at [`PROBES`] + 1 equally spaced
//! points and, where g changes sign between two of them, finds the root with Brent's method ([`brent`]) to
//! [`T_TOL`]:
//! - a crossing of c: g(t) = q(t) − c; `up` is g going from < 0 to > 0, `down` the reverse;
//! - an extremum: g(t) = q'(t), by the central difference (q(t + δ) − q(t − δ))/(2δ) on the continuous solution
//!   with δ = [`DIFF_STEP`]·(t₁ − t₀); a maximum is q' going from > 0 to < 0. Values of q' within the difference's
//!   rounding noise count as zero, so a quantity that starts at rest (q'(0) = 0) has no extremum at t = 0.
//!
//! A sign is remembered across intervals, so a root on an interval's end is found once.

use crate::sample::{Column, ColumnSet, Sample};

mod brent;
mod keys;
mod spec;
mod validate;

pub use brent::brent;
pub use keys::EventSpec;
pub use spec::ConditionSpec;
pub(crate) use validate::validate_events;

/// Subintervals of each interval at which the quantity is sampled for sign changes: two roots closer than
/// (t₁ − t₀)/`PROBES` may be missed (a crossing and its return).
pub const PROBES: usize = 4;

/// Absolute tolerance of the located times (s), on top of 4ε·|t| ([`brent`]).
pub const T_TOL: f64 = 1e-13;

/// δ of the central difference of an extremum, relative to the interval's length.
pub const DIFF_STEP: f64 = 1e-4;

/// What an event watches: a column's value, or the norm of a vector's three columns.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Quantity {
    /// The value of the column at this index of a row.
    Column(usize),
    /// √(x² + y² + z²) of the columns at these indices.
    Norm([usize; 3]),
}

impl Quantity {
    /// The quantity named `when` among a run's `columns`: a column's name, or `|X|` where X_s_x, X_s_y, X_s_z are
    /// columns (`|R_A|`, `|H|`, `|omega|` …). The error says what the name could be.
    pub fn parse(when: &str, columns: &[Column]) -> Result<Self, String> {
        let index = |name: &str| columns.iter().position(|c| c.name == name);
        if let Some(inner) = when.strip_prefix('|').and_then(|w| w.strip_suffix('|')) {
            let found = ["x", "y", "z"].map(|axis| index(&format!("{inner}_s_{axis}")));
            return match found {
                [Some(x), Some(y), Some(z)] => Ok(Quantity::Norm([x, y, z])),
                _ => Err(format!(
                    "\"{when}\": the run has no columns {inner}_s_x, {inner}_s_y, {inner}_s_z; vectors: {}",
                    vector_names(columns).join(", ")
                )),
            };
        }
        index(when).map(Quantity::Column).ok_or_else(|| {
            let names: Vec<&str> = columns.iter().map(|c| c.name.as_ref()).collect();
            format!(
                "\"{when}\" is not a column of this run; its columns are {}, and the norms {}",
                names.join(", "),
                vector_names(columns).join(", ")
            )
        })
    }

    /// The quantity's value in a row's values.
    pub fn of(&self, row: &[f64]) -> f64 {
        match *self {
            Quantity::Column(i) => row[i],
            Quantity::Norm([x, y, z]) => {
                (row[x] * row[x] + row[y] * row[y] + row[z] * row[z]).sqrt()
            }
        }
    }
}

/// The `|X|` names of a run's vector column groups (X_s_x present).
fn vector_names(columns: &[Column]) -> Vec<String> {
    (columns.iter())
        .filter_map(|c| c.name.strip_suffix("_s_x"))
        .map(|x| format!("|{x}|"))
        .collect()
}

/// Which crossings of a value count (`direction` in a scene).
#[derive(Debug, Clone, Copy, PartialEq, Eq, serde::Serialize, serde::Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Direction {
    /// Crossings upward (the value rising through it).
    Up,
    /// Crossings downward.
    Down,
    /// Both.
    Both,
}

/// Which extrema count (`extremum` in a scene).
#[derive(Debug, Clone, Copy, PartialEq, Eq, serde::Serialize, serde::Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Extremum {
    /// Local maxima.
    Max,
    /// Local minima.
    Min,
}

/// What makes an occurrence.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Condition {
    /// The quantity crossing `value` in `direction`.
    Crossing {
        /// The value crossed (the quantity's unit).
        value: f64,
        /// Which crossings count.
        direction: Direction,
    },
    /// Every local extremum of this kind.
    Extremum(Extremum),
}

/// One validated `[[event]]`.
#[derive(Debug, Clone, PartialEq)]
pub struct Event {
    /// `name`.
    pub name: String,
    /// `when` as written.
    pub when: String,
    /// The quantity watched (`when`'s column).
    pub quantity: Quantity,
    /// What makes an occurrence.
    pub condition: Condition,
    /// `stop`: the run ends at the first occurrence.
    pub stop: bool,
}

/// The kind of an occurrence: the `direction` column of the events file.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Kind {
    /// An upward crossing.
    Up,
    /// A downward crossing.
    Down,
    /// A local maximum.
    Max,
    /// A local minimum.
    Min,
}

impl Kind {
    /// `up`, `down`, `max`, `min`.
    pub fn name(self) -> &'static str {
        match self {
            Kind::Up => "up",
            Kind::Down => "down",
            Kind::Max => "max",
            Kind::Min => "min",
        }
    }
}

/// One located event.
#[derive(Debug, Clone, PartialEq)]
pub struct Occurrence {
    /// The event's index in the scene's events.
    pub event: usize,
    /// Its name.
    pub name: String,
    /// The time (s).
    pub t: f64,
    /// The quantity's value there.
    pub value: f64,
    /// Its kind: the events file's `direction`.
    pub kind: Kind,
}

/// Finds the events of a run interval by interval (module docs).
pub struct Locator<'e> {
    events: &'e [Event],
    columns: ColumnSet,
    /// Scratch for one row's values.
    row: Vec<f64>,
    /// Per event, the last nonzero sign of g seen (0: none yet).
    last_sign: Vec<f64>,
    found: Vec<Occurrence>,
    stopped: bool,
}

/// The values of g for every event at one probe point.
type Probe = Vec<f64>;

impl<'e> Locator<'e> {
    /// A locator for `events` on a run with `columns`.
    pub fn new(events: &'e [Event], columns: ColumnSet) -> Self {
        Self {
            events,
            columns,
            row: Vec::new(),
            last_sign: vec![0.0; events.len()],
            found: Vec::new(),
            stopped: false,
        }
    }

    /// The occurrences found so far, in time order.
    pub fn occurrences(&self) -> &[Occurrence] {
        &self.found
    }

    /// The occurrences, in time order.
    pub fn finish(self) -> Vec<Occurrence> {
        self.found
    }

    /// The quantity of event `e` at t.
    fn quantity(&mut self, e: usize, at: &mut impl FnMut(f64) -> Sample, t: f64) -> f64 {
        self.columns.values(&at(t), &mut self.row);
        self.events[e].quantity.of(&self.row)
    }

    /// g of event `e` at t (module docs) and the size below which it counts as zero.
    fn g(
        &mut self,
        e: usize,
        at: &mut impl FnMut(f64) -> Sample,
        t: f64,
        delta: f64,
    ) -> (f64, f64) {
        match self.events[e].condition {
            Condition::Crossing { value, .. } => (self.quantity(e, at, t) - value, 0.0),
            Condition::Extremum(_) => {
                let (hi, lo) = (
                    self.quantity(e, at, t + delta),
                    self.quantity(e, at, t - delta),
                );
                let noise = 64.0 * f64::EPSILON * hi.abs().max(lo.abs()) / delta;
                ((hi - lo) / (2.0 * delta), noise)
            }
        }
    }

    /// Looks at the solution over [t0, t1], `at(t)` its row at t (t0 ≤ t ≤ t1, a little beyond for the central
    /// difference). Records the occurrences in (t0, t1] and returns the time of the first occurrence of an event
    /// with `stop` (the occurrences after it are dropped), `None` otherwise. After a stop it finds nothing more.
    pub fn span(&mut self, t0: f64, t1: f64, mut at: impl FnMut(f64) -> Sample) -> Option<f64> {
        if self.stopped || t1 <= t0 || self.events.is_empty() {
            return None;
        }
        let delta = DIFF_STEP * (t1 - t0);
        let times: Vec<f64> = (0..=PROBES)
            .map(|i| {
                if i == PROBES {
                    t1
                } else {
                    t0 + (t1 - t0) * i as f64 / PROBES as f64
                }
            })
            .collect();
        let probes: Vec<Probe> = (times.iter())
            .map(|&t| {
                (0..self.events.len())
                    .map(|e| {
                        let (g, noise) = self.g(e, &mut at, t, delta);
                        if g.abs() <= noise { 0.0 } else { g }
                    })
                    .collect()
            })
            .collect();
        let first_new = self.found.len();
        for e in 0..self.events.len() {
            for (i, probe) in probes.iter().enumerate() {
                let g = probe[e];
                let last = self.last_sign[e];
                if g == 0.0 || (g > 0.0) == (last > 0.0) {
                    if g != 0.0 {
                        self.last_sign[e] = g.signum();
                    }
                    continue;
                }
                self.last_sign[e] = g.signum();
                if last == 0.0 || i == 0 {
                    continue;
                }
                self.record(e, (times[i - 1], times[i]), last, &mut at, delta);
            }
        }
        self.found[first_new..].sort_by(|a, b| a.t.total_cmp(&b.t));
        let stop =
            (first_new..self.found.len()).find(|&i| self.events[self.found[i].event].stop)?;
        self.found.truncate(stop + 1);
        self.stopped = true;
        Some(self.found[stop].t)
    }

    /// Locates the root of g of event `e` in [a, b] (g went from the sign `before` to the other) and records it if
    /// the event counts it.
    fn record(
        &mut self,
        e: usize,
        (a, b): (f64, f64),
        before: f64,
        at: &mut impl FnMut(f64) -> Sample,
        delta: f64,
    ) {
        let rising = before < 0.0;
        let kind = match self.events[e].condition {
            Condition::Crossing { direction, .. } => match (direction, rising) {
                (Direction::Up | Direction::Both, true) => Kind::Up,
                (Direction::Down | Direction::Both, false) => Kind::Down,
                _ => return,
            },
            Condition::Extremum(Extremum::Max) if !rising => Kind::Max,
            Condition::Extremum(Extremum::Min) if rising => Kind::Min,
            Condition::Extremum(_) => return,
        };
        let t = brent(|t| self.g(e, at, t, delta).0, a, b, T_TOL);
        if t <= 0.0 {
            // The run's start is no moment between rows (a quantity at rest at t = 0 is not an extremum there).
            return;
        }
        let value = self.quantity(e, at, t);
        self.found.push(Occurrence {
            event: e,
            name: self.events[e].name.clone(),
            t,
            value,
            kind,
        });
    }
}
