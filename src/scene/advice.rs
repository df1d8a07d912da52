//! Warnings about a valid scene: values that look like a unit slip, and a free body started near the separatrix,
//! where a tiny change of ω₀ or of the inertia decides the motion. `check` prints them; nothing is refused.

use crate::scene::{Motion, Scene, SceneSpec};

/// A body dimension above this looks like millimetres written as metres (m).
pub const LARGEST_PLAUSIBLE_SIZE: f64 = 100.0;

/// A tilt in degrees of magnitude below this (and not 0) looks like radians written as degrees.
pub const SMALLEST_PLAUSIBLE_DEGREES: f64 = 2.0;

/// A free asymmetric body is near the separatrix when |δ| < this, δ = (H² − 2E·I₂) / (2E·(I₃ − I₁)).
pub const SEPARATRIX_DISTANCE: f64 = 1e-3;

/// Values of `spec` that look like a unit slip: a body dimension over [`LARGEST_PLAUSIBLE_SIZE`], an angle in
/// degrees under [`SMALLEST_PLAUSIBLE_DEGREES`] that would be a plausible angle in radians.
pub fn unit_slips(spec: &SceneSpec) -> Vec<String> {
    let mut out = Vec::new();
    if let Some(shape) = &spec.body.shape {
        let sizes = [
            ("radius", shape.radius),
            ("thickness", shape.thickness),
            ("length", shape.length),
            ("height", shape.height),
        ];
        let boxed = shape.size.iter().flatten().map(|&s| ("size", Some(s)));
        for (key, value) in sizes.into_iter().chain(boxed) {
            if let Some(v) = value.filter(|v| *v > LARGEST_PLAUSIBLE_SIZE) {
                out.push(format!(
                    "body.shape.{key} = {v} m: a body over {LARGEST_PLAUSIBLE_SIZE} m across; if millimetres were \
                     meant, write {} m",
                    v / 1000.0
                ));
            }
        }
    }
    if let Some(motion) = &spec.motion {
        if let Some(v) = motion
            .tilt_deg
            .filter(|v| *v != 0.0 && v.abs() < SMALLEST_PLAUSIBLE_DEGREES)
        {
            out.push(format!(
                "motion.tilt_deg = {v} is {v} degrees; if radians were meant, that is {:.1} degrees",
                v.to_degrees()
            ));
        }
    }
    out
}

/// The relative distance of a free asymmetric body's initial ω from the separatrix, with principal moments
/// I₁ < I₂ < I₃ about its moment center:
///
/// ```text
///   δ = (H² − 2E·I₂) / (2E·(I₃ − I₁)),   H² = Σ (I_k ω_k)²,   2E = Σ I_k ω_k²
/// ```
///
/// δ = 0 on the separatrix, δ > 0 for rotation about the major axis, δ < 0 about the minor one (Landau & Lifshitz
/// §37: the polhodes through the intermediate axis). `None` for prescribed motion, a body at rest, or one with two
/// equal principal moments (to 1e-9).
pub fn separatrix_distance(scene: &Scene) -> Option<f64> {
    let Motion::Free { omega0_b, body } = &scene.motion else {
        return None;
    };
    let omega_p = body.principal_axes_b().transpose() * omega0_b;
    let mut pairs: Vec<(f64, f64)> = (0..3)
        .map(|k| (body.principal_moments()[k], omega_p[k]))
        .collect();
    pairs.sort_by(|a, b| a.0.total_cmp(&b.0));
    let (i1, i2, i3) = (pairs[0].0, pairs[1].0, pairs[2].0);
    if (i2 - i1) <= 1e-9 * i3 || (i3 - i2) <= 1e-9 * i3 {
        return None;
    }
    let h2: f64 = pairs.iter().map(|(i, w)| (i * w).powi(2)).sum();
    let two_e: f64 = pairs.iter().map(|(i, w)| i * w * w).sum();
    (two_e > 0.0).then(|| (h2 - two_e * i2) / (two_e * (i3 - i1)))
}

/// Everything `check` warns about in a valid scene (its spec and the scene built from it).
pub fn warnings(spec: &SceneSpec, scene: &Scene) -> Vec<String> {
    let mut out = unit_slips(spec);
    if let Some(delta) = separatrix_distance(scene).filter(|d| d.abs() < SEPARATRIX_DISTANCE) {
        out.push(format!(
            "the initial omega lies near the separatrix of this asymmetric body (delta = (H^2 - 2E*I2) / \
             (2E*(I3 - I1)) = {delta:.2e}, within {SEPARATRIX_DISTANCE:e}): tiny changes of omega0 or the inertia \
             change when, and whether, the body flips"
        ));
    }
    out
}
