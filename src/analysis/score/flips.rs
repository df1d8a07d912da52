//! A torque-free body's flips, scored without an `[[event]]`: the times at which ω's component along the
//! intermediate principal axis changes sign — the Dzhanibekov flip of a tennis racket, whose timing an engine
//! without ω × Iω, or with its sign wrong, gets wrong first.
//!
//! Every torque-free motion with three distinct moments I₁ < I₂ < I₃ has ω₂ ∝ sn τ (Landau & Lifshitz §37), so ω₂
//! changes sign every 2K/λ; it is a flip — the intermediate axis turning over against H — when the polhode passes
//! near that axis. With H and T conserved the largest |H₂| has a closed form (h₁ = 0 or h₃ = 0 in the two
//! conservation laws Σhᵢ² = H², Σhᵢ²/Iᵢ = 2T):
//!
//! ```text
//!   2T ≤ H²/I₂ (ω circulates about the major axis):  H₂,max² = (2T − H²/I₃)/(1/I₂ − 1/I₃)
//!   2T > H²/I₂ (about the minor axis):                H₂,max² = (H²/I₁ − 2T)/(1/I₁ − 1/I₂)
//! ```
//!
//! The body flips when H₂,max ≥ |H|·cos 45° ([`APPROACH`]): the intermediate axis swings through more than 90°. The
//! reference's flip times are the roots of the closed form's ω₂(t), found by Brent's method to
//! [`crate::events::T_TOL`]; theirs are the sign changes of their ω_b along the same axis, interpolated linearly
//! between rows as an `[[event]]`'s are.

use nalgebra::Vector3;

use super::metrics::{self, Metric};
use super::reference::Reference;
use crate::events::{Condition, Direction, T_TOL, brent};
use crate::exact::TorqueFreeBody;
use crate::sample::Sample;
use crate::scene::{Oracle, Scene};

/// The body flips when the intermediate axis comes within this cosine of H (45°).
pub const APPROACH: f64 = std::f64::consts::FRAC_1_SQRT_2;

/// The metric's key is `event:flip`; an `[[event]]` of the scene by this name is scored instead.
pub const NAME: &str = "flip";

/// The metric in words (the guide says how the flips are found).
pub const LABEL: &str = "automatic flip time error (s)";

/// The intermediate principal axis of a flipping torque-free body.
struct Flipping<'a> {
    exact: &'a TorqueFreeBody,
    /// Its index among the principal moments (user order).
    index: usize,
    /// The axis in body axes.
    axis_b: Vector3<f64>,
}

/// The intermediate axis of `scene`'s body when it is torque-free with three distinct moments and flips.
fn flipping(scene: &Scene) -> Option<Flipping<'_>> {
    let Some(Oracle::TorqueFree { exact, r_bp }) = scene.facts().oracle() else {
        return None;
    };
    let moments = exact.moments_p();
    let mut order = [0, 1, 2];
    order.sort_by(|&a, &b| moments[a].total_cmp(&moments[b]));
    let [minor, mid, major] = order.map(|k| moments[k]);
    if mid - minor <= 1e-12 * major || major - mid <= 1e-12 * major {
        return None;
    }
    let (h_p, energy2) = (exact.h_p(0.0), 2.0 * exact.energy());
    let h2 = h_p.norm_squared();
    let h_mid2 = if energy2 <= h2 / mid {
        (energy2 - h2 / major) / (1.0 / mid - 1.0 / major)
    } else {
        (h2 / minor - energy2) / (1.0 / minor - 1.0 / mid)
    };
    (h_mid2 >= APPROACH * APPROACH * h2).then(|| Flipping {
        exact,
        index: order[1],
        axis_b: r_bp * Vector3::ith(order[1], 1.0),
    })
}

/// The flip metric of their samples, when the scene's body flips and none of its `[[event]]`s is named
/// [`NAME`] (the scene's own event is scored instead).
pub fn metric(scene: &Scene, theirs: &[Sample], reference: &Reference) -> Option<Metric> {
    if scene.events.iter().any(|e| e.name == NAME) {
        return None;
    }
    let flipping = flipping(scene)?;
    let t: Vec<f64> = theirs.iter().map(|s| s.t).collect();
    let along = |samples: &[Sample]| -> Vec<f64> {
        samples
            .iter()
            .map(|s| s.omega_b.dot(&flipping.axis_b))
            .collect()
    };
    let crossing = Condition::Crossing {
        value: 0.0,
        direction: Direction::Both,
    };
    let found = metrics::locate(&crossing, &t, &along(theirs));
    let expected: Vec<f64> = metrics::locate(&crossing, &t, &along(&reference.samples))
        .iter()
        .map(|&guess| refine(&flipping, &t, guess))
        .collect();
    Some(metrics::event_metric(NAME, LABEL, &found, &expected))
}

/// The root of the closed form's ω along the intermediate axis in the row interval around `guess`.
fn refine(flipping: &Flipping, t: &[f64], guess: f64) -> f64 {
    let k = t.partition_point(|&tk| tk < guess).clamp(1, t.len() - 1);
    let g = |time: f64| flipping.exact.omega_p(time)[flipping.index];
    let (a, b) = (t[k - 1], t[k]);
    let (ga, gb) = (g(a), g(b));
    if ga == 0.0 || gb == 0.0 {
        return if ga == 0.0 { a } else { b };
    }
    if ga.signum() == gb.signum() {
        return guess;
    }
    brent(g, a, b, T_TOL)
}
