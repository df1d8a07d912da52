//! The referee: eulerdyn's own solution of the scene at the other program's times — the closed form where one
//! applies ([`Oracle`]: the torque-free body by Jacobi elliptic functions, Landau & Lifshitz §37, run as the
//! method `exact`), else dop853 at rtol [`RTOL`] with its error estimated by a second run at rtol [`RTOL_CHECK`].
//!
//! Their times must lie on an equal grid t = k·Δt (the rows of a fixed-step engine, every one or every n-th
//! step), to within [`GRID_SLACK`]·Δt: the reference rows are computed exactly there, not interpolated.

use super::ScoreError;
use crate::analysis::compare::attitude_angle;
use crate::events::Occurrence;
use crate::method::Method;
use crate::sample::Sample;
use crate::scene::Oracle;
use crate::scene::{Overrides, Scene};
use crate::simulate::{self, RunError};

/// The referee's relative tolerance where no closed form applies.
pub const RTOL: f64 = 1e-13;
/// The tolerance of the second run whose difference from the first estimates the first one's error (an upper
/// bound: a run at rtol 1e-11 is less accurate than one at 1e-13).
pub const RTOL_CHECK: f64 = 1e-11;
/// Their times may differ from the grid k·Δt by this fraction of Δt (a spreadsheet's six decimals).
pub const GRID_SLACK: f64 = 1e-4;

/// How large the referee's own error is, where it is not the closed form's round-off.
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
pub struct ErrorEstimate {
    /// Attitude (rad): the largest angle between the runs at [`RTOL`] and [`RTOL_CHECK`], plus what their times'
    /// distance from the grid amounts to (|ω|max · the largest distance).
    pub attitude: f64,
    /// ω, relative to its largest magnitude.
    pub omega: f64,
}

/// The reference at their times.
#[derive(Debug, Clone)]
pub struct Reference {
    /// One row per row of theirs, in order.
    pub samples: Vec<Sample>,
    /// The scene's events on the reference, in time order.
    pub occurrences: Vec<Occurrence>,
    /// What the reference is, in words.
    pub source: String,
    /// `None` for the closed form (round-off only).
    pub estimate: Option<ErrorEstimate>,
    /// The grid Δt their times lie on (s), which the reference was computed on.
    pub every: f64,
}

/// The grid Δt their times lie on and the largest distance of a time from it (s).
pub(super) fn grid(path: &str, times: &[f64]) -> Result<(f64, f64), ScoreError> {
    let first_step = times[1] - times[0];
    let last = times[times.len() - 1];
    let every = last / (last / first_step).round().max(1.0);
    let mut slack: f64 = 0.0;
    for (i, &t) in times.iter().enumerate() {
        let k = (t / every).round();
        let off = (t - k * every).abs();
        if off > GRID_SLACK * every {
            return Err(ScoreError::Input(format!(
                "{path}: row {}, column `t`: time {} is not on the equal grid k·{every} s of the first rows; score \
                 needs the rows of a fixed-step run (every step or every n-th)",
                i + 1,
                t
            )));
        }
        slack = slack.max(off);
    }
    Ok((every, slack))
}

/// Runs `scene` with `overrides` on the grid and keeps, per grid index k, the row at k·Δt.
fn run_on_grid(
    scene: &Scene,
    overrides: &Overrides,
    every: f64,
) -> Result<(Vec<Option<Sample>>, Vec<Occurrence>), ScoreError> {
    let run_scene = scene
        .spec
        .build_with(overrides)
        .map_err(|e| ScoreError::Input(format!("the scene with the referee's settings: {e}")))?;
    let mut by_k: Vec<Option<Sample>> = Vec::new();
    let (_, occurrences) = simulate::run_with_events(&run_scene, |s: &Sample| {
        let k = (s.t / every).round() as usize;
        if by_k.len() <= k {
            by_k.resize(k + 1, None);
        }
        by_k[k] = Some(*s);
        Ok::<(), std::convert::Infallible>(())
    })
    .map_err(|e: RunError<_>| ScoreError::Run(format!("the reference run failed: {e}")))?;
    Ok((by_k, occurrences))
}

/// The rows of `by_k` at their times; a row the reference lacks (a `stop` event ended it) is refused.
fn pick(by_k: &[Option<Sample>], times: &[f64], every: f64) -> Result<Vec<Sample>, ScoreError> {
    times
        .iter()
        .map(|&t| {
            let k = (t / every).round() as usize;
            by_k.get(k).copied().flatten().ok_or_else(|| {
                ScoreError::Run(format!(
                    "the reference has no row at t = {t} (a `stop` event ended it)"
                ))
            })
        })
        .collect()
}

/// The reference for `scene` at `times` (at least two, increasing; read from `path`).
pub fn reference(scene: &Scene, path: &str, times: &[f64]) -> Result<Reference, ScoreError> {
    let (every, slack) = grid(path, times)?;
    let t_end = times[times.len() - 1];
    let base = Overrides {
        t_end: Some(t_end),
        every: Some(every),
        ..Overrides::default()
    };
    let closed = match scene.facts().oracle() {
        Some(o @ (Oracle::TorqueFree { .. } | Oracle::SymmetricGyrostat { .. })) => Some(o.name()),
        _ => None,
    };
    if let Some(name) = closed {
        let exact = Overrides {
            method: Some(Method::Exact),
            ..base
        };
        if scene.spec.build_with(&exact).is_ok() {
            let (by_k, occurrences) = run_on_grid(scene, &exact, every)?;
            return Ok(Reference {
                samples: pick(&by_k, times, every)?,
                occurrences,
                source: format!("closed form: {name}"),
                estimate: None,
                every,
            });
        }
    }
    let numerical = |rtol: f64| Overrides {
        method: Some(Method::Dop853),
        rtol: Some(rtol),
        atol: Some(rtol * 1e-2),
        ..base
    };
    let (by_k, occurrences) = run_on_grid(scene, &numerical(RTOL), every)?;
    let (check, _) = run_on_grid(scene, &numerical(RTOL_CHECK), every)?;
    let samples = pick(&by_k, times, every)?;
    let checks = pick(&check, times, every)?;
    let omega_max = samples.iter().map(|s| s.omega_b.norm()).fold(0.0, f64::max);
    let attitude = (samples.iter().zip(&checks))
        .map(|(a, b)| attitude_angle(&a.q, &b.q))
        .fold(0.0, f64::max);
    let omega = (samples.iter().zip(&checks))
        .map(|(a, b)| (a.omega_b - b.omega_b).norm())
        .fold(0.0, f64::max)
        / omega_max.max(f64::MIN_POSITIVE);
    Ok(Reference {
        samples,
        occurrences,
        source: format!("dop853 at rtol {RTOL:e} (no closed form applies to this scene)"),
        estimate: Some(ErrorEstimate {
            attitude: attitude + omega_max * slack,
            omega,
        }),
        every,
    })
}
