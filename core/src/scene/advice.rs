//! Warnings about a valid scene: values that look like a unit slip, and a free body started near the separatrix,
//! where a tiny change of ω₀ or of the inertia decides the motion. `check`, `run`, `sweep` (for its base scene)
//! and Python print them, and a run's sidecar lists them; nothing is refused.

use crate::scene::{AxisDirection, MotionSpec, Scene, SceneSpec, ShapeSpec};

/// A body dimension above this looks like millimetres written as metres (m).
pub const LARGEST_PLAUSIBLE_SIZE: f64 = 100.0;

/// A tilt in degrees looks like radians written as degrees when, read as radians, it is within this of a whole
/// number of degrees (0.5236 → 30.0001°) — and is not itself a round number of degrees (see [`looks_like_radians`]).
pub const RADIANS_TO_WHOLE_DEGREES: f64 = 0.01;

/// A free asymmetric body is near the separatrix when |δ| < this, δ = (H² − 2E·I₂) / (2E·(I₃ − I₁)).
pub const SEPARATRIX_DISTANCE: f64 = 1e-3;

/// A wheel's static imbalance (g·mm) below this looks like kg·m written as g·mm (10⁶ × too small): ISO 21940-11's
/// finest grade, G 0.4 (e·Ω = 0.4 mm/s), allows U = m_w·(0.4 mm/s)/Ω, which for a wheel of 20 g at 60 000 rpm
/// (Ω = 6283 rad/s) is 1.3e-3 g·mm; a wheel ten times finer than that is not made.
pub const SMALLEST_PLAUSIBLE_IMBALANCE_GMM: f64 = 1e-4;

/// Whether an angle written in degrees, `deg`, looks like radians: 0 < |deg| < 2π, its value read as radians is
/// within [`RADIANS_TO_WHOLE_DEGREES`] of a whole number of degrees, and it has more than one decimal (a skew of
/// 0.5°, 1° or 1.5° is a real rotor's, not a slip; 0.5236 or 0.0349 is 30° or 2° in radians).
pub fn looks_like_radians(deg: f64) -> bool {
    let as_degrees = deg.to_degrees();
    let round_itself = ((deg * 10.0).round() - deg * 10.0).abs() < 1e-9;
    deg != 0.0
        && deg.abs() < std::f64::consts::TAU
        && (as_degrees - as_degrees.round()).abs() < RADIANS_TO_WHOLE_DEGREES
        && !round_itself
}

/// Values of `spec` that look like a unit slip: a body dimension over [`LARGEST_PLAUSIBLE_SIZE`], an angle in
/// degrees that [`looks_like_radians`].
pub fn unit_slips(spec: &SceneSpec) -> Vec<String> {
    let mut out = Vec::new();
    if let Some(shape) = spec.body.shape_spec() {
        let sizes: Vec<(&str, f64)> = match *shape {
            ShapeSpec::ThinDisk { radius } | ShapeSpec::Sphere { radius } => {
                vec![("radius", radius)]
            }
            ShapeSpec::Disk { radius, thickness } => {
                vec![("radius", radius), ("thickness", thickness)]
            }
            ShapeSpec::ThinRod { length } => vec![("length", length)],
            ShapeSpec::Box { size } => size.iter().map(|&s| ("size", s)).collect(),
            ShapeSpec::Cylinder { radius, height } => vec![("radius", radius), ("height", height)],
        };
        for (key, v) in sizes
            .into_iter()
            .filter(|(_, v)| *v > LARGEST_PLAUSIBLE_SIZE)
        {
            out.push(format!(
                "body.shape.{key} = {v} m: a body over {LARGEST_PLAUSIBLE_SIZE} m across; if millimetres were \
                 meant, write {} m",
                v / 1000.0
            ));
        }
    }
    let tilt = spec
        .motion
        .as_ref()
        .and_then(MotionSpec::axis)
        .and_then(|a| match a.direction {
            AxisDirection::TiltDeg(v) => Some(v),
            AxisDirection::Body(_) => None,
        });
    if let Some(v) = tilt.filter(|v| looks_like_radians(*v)) {
        out.push(format!(
            "motion.tilt_deg = {v} is {v} degrees; if radians were meant, that is {:.1} degrees",
            v.to_degrees()
        ));
    }
    out.extend(imbalance_slips(spec));
    out
}

/// Wheel imbalances no wheel could have. A wheel of mass m_w and axial moment J = m_w k² (k its radius of
/// gyration) has at most U_s = m_w·k (its whole mass at k from the axis) = √(J·m_w) ≤ √(J·m), m the body's mass,
/// which includes the wheel's: a larger U_s is a unit slip (kg·m or g·m written as g·mm, or kg·m² as g·mm²). A U_s
/// below [`SMALLEST_PLAUSIBLE_IMBALANCE_GMM`] is finer than any balancing grade: kg·m written as g·mm.
fn imbalance_slips(spec: &SceneSpec) -> Vec<String> {
    let mut out = Vec::new();
    for (k, rotor) in spec.body.rotor.iter().enumerate() {
        let key = format!("body.rotor.{k}.imbalance_static_gmm");
        let u_gmm = rotor.imbalance_static_gmm;
        // √(J m) in kg·m, then in g·mm (1 kg·m = 10⁶ g·mm).
        let most_gmm = (rotor.inertia * spec.body.mass).sqrt() * 1e6;
        if u_gmm > most_gmm {
            out.push(format!(
                "{key} = {u_gmm} g*mm is more than a wheel of J = {} kg*m^2 in a body of {} kg can have (its whole \
                 mass at its radius of gyration: sqrt(J*m) = {most_gmm:.3e} g*mm); is it in g*mm?",
                rotor.inertia, spec.body.mass
            ));
        } else if u_gmm > 0.0 && u_gmm < SMALLEST_PLAUSIBLE_IMBALANCE_GMM {
            // The value read as kg·m, in g·mm, to 7 significant digits (2e-5 kg·m: 20 g·mm, not 20.000000000000004).
            let as_kgm: f64 = format!("{:.6e}", u_gmm * 1e6)
                .parse()
                .unwrap_or(u_gmm * 1e6);
            out.push(format!(
                "{key} = {u_gmm} g*mm is finer than any balancing grade (G 0.4 allows 1.3e-3 g*mm on a 20 g \
                 wheel at 60000 rpm); if kg*m were meant, that is {as_kgm} g*mm"
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
    let (omega0_b, body) = scene.motion.rigid_free()?;
    let omega_p = body.principal_axes_b().transpose() * **omega0_b;
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

/// Everything `check` warns about in a valid scene (unit slips in its spec, a torque-free body's separatrix).
pub fn warnings(scene: &Scene) -> Vec<String> {
    let mut out = unit_slips(&scene.spec);
    let torque_free = scene.effects.is_empty();
    let near = separatrix_distance(scene).filter(|d| torque_free && d.abs() < SEPARATRIX_DISTANCE);
    if let Some(delta) = near {
        out.push(format!(
            "the initial omega lies near the separatrix of this asymmetric body (delta = (H^2 - 2E*I2) / \
             (2E*(I3 - I1)) = {delta:.2e}, within {SEPARATRIX_DISTANCE:e}): tiny changes of omega0 or the inertia \
             change when, and whether, the body flips"
        ));
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn radians_written_as_degrees_are_told_from_real_skews() {
        // 30°, 2°, 90° and 45° in radians, as a user types them (4 decimals): slips.
        #[allow(clippy::approx_constant)]
        let slips = [0.5236, 0.0349, 1.5708, 0.7854];
        for slip in slips {
            assert!(looks_like_radians(slip), "{slip}");
        }
        // A rotor's skew of 0.5–2°, round tilts, and 0: as meant.
        for skew in [0.5, 1.0, 1.5, 2.0, 0.25, 30.0, 0.0, 7.5] {
            assert!(!looks_like_radians(skew), "{skew}");
        }
    }
}
