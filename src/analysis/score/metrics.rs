//! The errors of their trajectory against the reference, row by row, and each metric's largest and final value
//! against its threshold.
//!
//! Their H and energy are computed from their attitude and ω with the scene's body, as eulerdyn computes its own
//! rows: H_b = I_O ω_b (I_O the inertia about the moment center), H_s = R H_b, T = ½ ω·H, plus V = −m g·r_C with
//! gravity (Rigid-body dynamics, lecture notes, eqs. 8.6, 8.9).

use nalgebra::Vector3;

use super::reader::TheirRow;
use super::reference::Reference;
use crate::analysis::compare::attitude_angle;
use crate::effects::{AppliedMoment, EffectMoments};
use crate::events::{Condition, Direction, Extremum};
use crate::frames::{BodyAxes, Vector};
use crate::motion::free::free_sample;
use crate::sample::Sample;
use crate::scene::Scene;

/// Attitude error (rad) allowed: 0.57°, what a viewer notices on a body across a screen.
pub const ATTITUDE_MAX: f64 = 1e-2;
/// ω error allowed, relative to the largest |ω| of the reference.
pub const OMEGA_MAX: f64 = 1e-2;
/// Energy drift allowed, relative to the reference's T + |V|.
pub const ENERGY_MAX: f64 = 1e-3;
/// |H| drift allowed, relative to the largest |H| of the reference.
pub const H_NORM_MAX: f64 = 1e-3;
/// Angle (rad) allowed between their H_s and the reference's: 0.06°; without the gyroscopic term ω × Iω a
/// torque-free body's H_s turns in space, which it never does.
pub const H_DIRECTION_MAX: f64 = 1e-3;
/// Error allowed in an event's time (s): one frame at 60 Hz.
pub const EVENT_TIME_MAX: f64 = 1.0 / 60.0;

/// One metric: its largest and final value against its threshold.
#[derive(Debug, Clone, PartialEq, serde::Serialize)]
pub struct Metric {
    /// A short key: attitude, omega, energy, h_norm, h_direction, event:NAME.
    pub key: String,
    /// The metric in words, with its unit.
    pub name: String,
    /// The largest value over their rows.
    pub largest: f64,
    /// The time of the largest value (s).
    pub at: f64,
    /// The value at their last row (the last occurrence for an event).
    pub last: f64,
    /// The stated threshold.
    pub threshold: f64,
    /// Whether the largest value is within the threshold.
    pub passes: bool,
    /// What else there is to know (an event missing or extra).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub note: Option<String>,
    /// An event's occurrences, each with its time error (events only).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub occurrences: Option<Vec<Occurrence>>,
}

/// One occurrence of an event on the reference and on their rows, matched in order; a side without it is `None`.
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
pub struct Occurrence {
    /// Its time on the reference (s).
    pub reference_t: Option<f64>,
    /// Its time on their rows (s).
    pub their_t: Option<f64>,
    /// |their_t − reference_t| (s), where both have it.
    pub error: Option<f64>,
}

/// A metric's values at their times, for the figure.
#[derive(Debug, Clone, PartialEq)]
pub struct Series {
    /// The metric's name.
    pub name: String,
    /// Their times (s).
    pub t: Vec<f64>,
    /// The metric at those times.
    pub values: Vec<f64>,
    /// The metric's stated threshold (drawn as a dashed line).
    pub threshold: f64,
}

impl Series {
    fn metric(&self, key: &str, threshold: f64) -> Metric {
        let (mut largest, mut at) = (0.0, 0.0);
        for (&t, &v) in self.t.iter().zip(&self.values) {
            if v > largest || v.is_nan() {
                (largest, at) = (v, t);
            }
        }
        Metric {
            key: key.into(),
            name: self.name.clone(),
            largest,
            at,
            last: self.values.last().copied().unwrap_or(0.0),
            threshold,
            passes: largest <= threshold,
            note: None,
            occurrences: None,
        }
    }
}

/// Their rows as eulerdyn's rows (module docs); `None` without ω.
pub fn their_samples(scene: &Scene, rows: &[TheirRow]) -> Option<Vec<Sample>> {
    let (_, body) = scene.motion.rigid_free()?;
    let moments = EffectMoments::new(&scene.effects, scene.body.mass());
    rows.iter()
        .map(|r| {
            let omega_b = Vector::<BodyAxes>::new(r.omega_b?);
            let (h_b, _) = body.momentum_and_energy(&omega_b);
            let m_b = Vector::new(moments.moment_b(r.t, &r.q, &omega_b));
            let mut s = free_sample(r.t, r.q, omega_b, (h_b, h_b.in_space(&r.q)), m_b);
            s.potential = scene.gravity_potential(&r.q);
            Some(s)
        })
        .collect()
}

/// The largest of `f` over the reference rows (at least the smallest positive number).
fn scale(reference: &[Sample], f: impl Fn(&Sample) -> f64) -> f64 {
    reference.iter().map(f).fold(f64::MIN_POSITIVE, f64::max)
}

/// The metrics of `rows` (their `samples`, when they gave ω) against `reference`, and their series.
pub fn metrics(
    scene: &Scene,
    rows: &[TheirRow],
    samples: Option<&[Sample]>,
    reference: &Reference,
) -> (Vec<Metric>, Vec<Series>) {
    let refs = &reference.samples;
    let t: Vec<f64> = rows.iter().map(|r| r.t).collect();
    let series = |name: &str, values: Vec<f64>, threshold: f64| Series {
        name: name.into(),
        t: t.clone(),
        values,
        threshold,
    };
    let attitude = (rows.iter().zip(refs))
        .map(|(r, s)| attitude_angle(&r.q, &s.q))
        .collect();
    let mut all = vec![(
        series("attitude error angle (rad)", attitude, ATTITUDE_MAX),
        "attitude",
        ATTITUDE_MAX,
    )];
    if let Some(theirs) = samples {
        let omega_scale = scale(refs, |s| s.omega_b.norm());
        let energy = |s: &Sample| s.energy + s.potential.unwrap_or(0.0);
        let energy_scale = scale(refs, |s| s.energy + s.potential.unwrap_or(0.0).abs());
        let h_scale = scale(refs, |s| s.h_o_s.norm());
        let pairs = || theirs.iter().zip(refs);
        let omega = pairs().map(|(a, b)| (a.omega_b - b.omega_b).norm() / omega_scale);
        let energy = pairs().map(|(a, b)| (energy(a) - energy(b)).abs() / energy_scale);
        let h_norm = pairs().map(|(a, b)| (a.h_o_s.norm() - b.h_o_s.norm()).abs() / h_scale);
        let h_direction = pairs().map(|(a, b)| angle(&a.h_o_s, &b.h_o_s));
        all.push((
            series(
                "angular velocity error (relative)",
                omega.collect(),
                OMEGA_MAX,
            ),
            "omega",
            OMEGA_MAX,
        ));
        all.push((
            series("energy drift (relative)", energy.collect(), ENERGY_MAX),
            "energy",
            ENERGY_MAX,
        ));
        all.push((
            series("|H| drift (relative)", h_norm.collect(), H_NORM_MAX),
            "h_norm",
            H_NORM_MAX,
        ));
        all.push((
            series(
                "H direction drift in space (rad)",
                h_direction.collect(),
                H_DIRECTION_MAX,
            ),
            "h_direction",
            H_DIRECTION_MAX,
        ));
    }
    let mut metrics: Vec<Metric> = all
        .iter()
        .map(|(s, key, max)| s.metric(key, *max))
        .collect();
    if let Some(theirs) = samples {
        metrics.extend(event_metrics(scene, theirs, reference));
    }
    (metrics, all.into_iter().map(|(s, ..)| s).collect())
}

/// The angle between two vectors (rad), atan2(|a × b|, a·b): accurate for tiny angles.
fn angle(a: &Vector3<f64>, b: &Vector3<f64>) -> f64 {
    a.cross(b).norm().atan2(a.dot(b))
}

/// Per event of the scene, the error of each occurrence's time on their rows against the reference's, matched
/// in order.
fn event_metrics(scene: &Scene, theirs: &[Sample], reference: &Reference) -> Vec<Metric> {
    let columns = scene.facts().columns();
    let mut row = Vec::new();
    let values: Vec<Vec<f64>> = (scene.events.iter())
        .map(|e| {
            (theirs.iter())
                .map(|s| {
                    columns.values(s, &mut row);
                    e.quantity.of(&row)
                })
                .collect()
        })
        .collect();
    let t: Vec<f64> = theirs.iter().map(|s| s.t).collect();
    (scene.events.iter().enumerate())
        .map(|(i, e)| {
            let found = locate(&e.condition, &t, &values[i]);
            let expected: Vec<f64> = (reference.occurrences.iter())
                .filter(|o| o.event == i)
                .map(|o| o.t)
                .collect();
            let label = format!("event `{}` time error (s)", e.name);
            event_metric(&e.name, &label, &found, &expected)
        })
        .collect()
}

/// The metric `event:NAME` of one event, described by `label`, from its times on their rows and on the reference.
pub(super) fn event_metric(name: &str, label: &str, found: &[f64], expected: &[f64]) -> Metric {
    let errors: Vec<(f64, f64)> = (found.iter().zip(expected))
        .map(|(a, b)| ((a - b).abs(), *b))
        .collect();
    let (largest, at) = errors.iter().fold(
        (0.0, 0.0),
        |acc, &(v, t)| if v > acc.0 { (v, t) } else { acc },
    );
    let note = (found.len() != expected.len()).then(|| {
        format!(
            "{} occurrences on their rows, {} on the reference",
            found.len(),
            expected.len()
        )
    });
    let occurrences = (0..found.len().max(expected.len()))
        .map(|k| {
            let (their_t, reference_t) = (found.get(k).copied(), expected.get(k).copied());
            Occurrence {
                reference_t,
                their_t,
                error: their_t.zip(reference_t).map(|(a, b)| (a - b).abs()),
            }
        })
        .collect();
    Metric {
        key: format!("event:{name}"),
        name: label.to_string(),
        largest,
        at,
        last: errors.last().map_or(0.0, |e| e.0),
        threshold: EVENT_TIME_MAX,
        passes: largest <= EVENT_TIME_MAX && note.is_none(),
        note,
        occurrences: Some(occurrences),
    }
}

/// The times at which quantity `q` on rows at times `t` meets `condition`: a crossing linearly interpolated
/// between the two rows around it, an extremum at the vertex of the parabola through three rows.
pub fn locate(condition: &Condition, t: &[f64], q: &[f64]) -> Vec<f64> {
    let mut found = Vec::new();
    match *condition {
        Condition::Crossing { value, direction } => {
            for k in 1..t.len() {
                let (a, b) = (q[k - 1] - value, q[k] - value);
                let up = a < 0.0 && b >= 0.0;
                let down = a > 0.0 && b <= 0.0;
                let wanted = match direction {
                    Direction::Up => up,
                    Direction::Down => down,
                    Direction::Both => up || down,
                };
                if wanted {
                    found.push(t[k - 1] + (t[k] - t[k - 1]) * a / (a - b));
                }
            }
        }
        Condition::Extremum(kind) => {
            for k in 1..t.len().saturating_sub(1) {
                let (d0, d1) = (q[k] - q[k - 1], q[k + 1] - q[k]);
                let turn = match kind {
                    Extremum::Max => d0 > 0.0 && d1 <= 0.0,
                    Extremum::Min => d0 < 0.0 && d1 >= 0.0,
                };
                if turn {
                    found.push(vertex(
                        [t[k - 1], t[k], t[k + 1]],
                        [q[k - 1], q[k], q[k + 1]],
                    ));
                }
            }
        }
    }
    found
}

/// The abscissa of the vertex of the parabola through three points (the middle one where they are collinear).
fn vertex(t: [f64; 3], q: [f64; 3]) -> f64 {
    let (d0, d1) = ((q[1] - q[0]) / (t[1] - t[0]), (q[2] - q[1]) / (t[2] - t[1]));
    let curvature = (d1 - d0) / (t[2] - t[0]);
    if curvature == 0.0 {
        return t[1];
    }
    // q'(τ) = d0 + 2·curvature·(τ − (t0 + t1)/2) = 0.
    0.5 * (t[0] + t[1]) - d0 / (2.0 * curvature)
}
