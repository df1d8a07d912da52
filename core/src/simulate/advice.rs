//! What a run should tell its user besides its rows: the step a fixed-step method really takes, a step too coarse
//! for the motion (before the run), and the drift of the energy where the scene conserves it (as the run goes).
//!
//! The thresholds are stated, not tuned to a scene: a fixed step should turn the body by at most
//! [`MAX_TURN_PER_STEP`] (ten steps per radian), and a conserved energy should stay within [`MAX_ENERGY_DRIFT`]
//! of its initial value; past either, the rows may be wrong while the run succeeds.

use std::fmt;

use crate::sample::Sample;
use crate::scene::Scene;

/// The most a fixed step should turn the body: |ω|·h ≤ 0.1 rad.
pub const MAX_TURN_PER_STEP: f64 = 0.1;

/// The largest relative drift |E(t) − E₀| / (T₀ + |V₀|) of a conserved energy E = T + V before a run is warned.
pub const MAX_ENERGY_DRIFT: f64 = 1e-3;

/// A fixed step that turns the body by more than [`MAX_TURN_PER_STEP`] at the largest rate the scene starts or
/// is driven with.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct CoarseStep {
    /// The step taken (s).
    pub step: f64,
    /// The rate (rad/s).
    pub omega: f64,
}

impl CoarseStep {
    /// The coarse step of `scene`, if its step is coarse: |ω|·h > [`MAX_TURN_PER_STEP`], with |ω| the initial
    /// rate of a free body or a hinge, and the largest rate of a prescribed motion over the run.
    pub fn of(scene: &Scene) -> Option<Self> {
        let step = scene.fixed_step()?;
        let omega = scene.motion.largest_rate(scene.solver.t_end);
        (omega * step > MAX_TURN_PER_STEP).then_some(Self { step, omega })
    }
}

impl fmt::Display for CoarseStep {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(
            f,
            "a fixed step of {} s turns the body by {} rad (|omega| = {} rad/s), more than the {} rad per step a \
             fixed-step method needs to be accurate: the rows may be wrong; use dt <= {} s or an adaptive method \
             (dopri5, dop853)",
            three_digits(self.step),
            three_digits(self.omega * self.step),
            three_digits(self.omega),
            MAX_TURN_PER_STEP,
            three_digits(MAX_TURN_PER_STEP / self.omega)
        )
    }
}

/// `x` rounded to three significant digits, for messages (0.000667, not 6.666666666666668e-4).
fn three_digits(x: f64) -> f64 {
    format!("{x:.2e}").parse().unwrap_or(x)
}

/// Follows E = T + V over the rows of a free body whose [`Facts`](crate::scene::Facts) say it conserves its energy
/// (T, or T + V under gravity alone) and keeps its largest relative drift |E(t) − E₀| / (T₀ + |V₀|).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct EnergyWatch {
    start: Option<(f64, f64)>,
    drift: f64,
}

impl EnergyWatch {
    /// The watch of a free body that conserves its energy (`scene.facts()`); `None` otherwise (torques, damping,
    /// a rotor's motor, friction or imbalance; a prescribed axis, whose energy is given, and a hinge are not watched).
    pub fn of(scene: &Scene) -> Option<Self> {
        let free = scene.motion.is_free();
        (free && scene.facts().conserved_energy().is_some()).then_some(Self {
            start: None,
            drift: 0.0,
        })
    }

    /// Takes one row (its `potential` filled in where the scene has gravity).
    pub fn add(&mut self, s: &Sample) {
        let v = s.potential.unwrap_or(0.0);
        let e = s.energy + v;
        match self.start {
            None => self.start = Some((e, (s.energy + v.abs()).max(f64::MIN_POSITIVE))),
            Some((e0, scale)) => self.drift = self.drift.max((e - e0).abs() / scale),
        }
    }

    /// The largest relative drift so far.
    pub fn drift(&self) -> f64 {
        self.drift
    }
}

/// The warning of a run whose conserved energy drifted past [`MAX_ENERGY_DRIFT`] (`energy_drift` as measured by
/// [`EnergyWatch`]).
pub fn drift_warning(energy_drift: Option<f64>) -> Option<String> {
    energy_drift.filter(|&d| d > MAX_ENERGY_DRIFT).map(|drift| {
        format!(
            "the energy T + V, which this scene conserves, drifted by {} of its initial value (more than {}): the \
             rows are not accurate; use a smaller dt or a tighter rtol",
            three_digits(drift),
            MAX_ENERGY_DRIFT
        )
    })
}

/// What a run is warned of before it starts: the scene's own warnings ([`crate::scene::advice::warnings`]: unit
/// slips, the separatrix) and a coarse fixed step ([`CoarseStep`]). The command line prints them on stderr, Python
/// issues them as `UserWarning`s.
pub fn warnings_before_run(scene: &Scene) -> Vec<String> {
    let coarse = CoarseStep::of(scene).map(|c| c.to_string());
    crate::scene::advice::warnings(scene)
        .into_iter()
        .chain(coarse)
        .collect()
}

/// Everything a finished run is warned about: [`warnings_before_run`] and a drifting energy ([`drift_warning`]).
pub fn warnings(scene: &Scene, energy_drift: Option<f64>) -> Vec<String> {
    warnings_before_run(scene)
        .into_iter()
        .chain(drift_warning(energy_drift))
        .collect()
}
