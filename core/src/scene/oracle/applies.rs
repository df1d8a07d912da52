//! Which closed form applies to a scene ([`Oracle::for_scene`]): the conditions under which the exact solutions of
//! [`crate::exact`] hold for it, and their setting from the scene (principal axes, initial state, the wheels' h).

use nalgebra::{Rotation3, UnitQuaternion};

use super::Oracle;
use crate::effects::TorqueGiven;
use crate::exact::{AxialTorqueSymmetric, DampedSpin, SymmetricTorqueFree, TorqueFreeBody};
use crate::frames::{Axes, BodyAxes, Vector};
use crate::profile::Profile;
use crate::scene::model::Scene;
use crate::scene::spec::MotionKind;
use crate::wheels::gyrostat::Gyrostat;

impl Oracle {
    /// The closed form that applies to the scene, if any.
    pub fn for_scene(scene: &Scene) -> Option<Oracle> {
        let motion = &scene.motion;
        let free = match motion.kind() {
            MotionKind::FixedAxis => return Some(Oracle::FixedAxis),
            MotionKind::Hinge => return None,
            MotionKind::Free => motion.free()?,
        };
        if free.attribute.is_some() {
            // The closed forms are of rigid bodies and of the symmetric gyrostat; I(t) has none.
            return (free.gyrostat).and_then(|g| symmetric_gyrostat(scene, free.omega0_b, g));
        }
        let omega0_b = free.omega0_b.into_inner();
        let principal = scene.body.principal();
        let r_bp = principal_to_body(&principal.axes_b);
        match scene.effects.as_slice() {
            [] => {
                let omega0_p = r_bp.inverse_transform_vector(&omega0_b);
                TorqueFreeBody::new(principal.moments, omega0_p, scene.attitude0 * r_bp)
                    .ok()
                    .map(|exact| Oracle::TorqueFree {
                        exact: Box::new(exact),
                        r_bp,
                    })
            }
            [effect] => match (effect.torque(), effect.damping()) {
                (
                    Some(TorqueGiven {
                        frame: Axes::Body,
                        value,
                        profile: Profile::Constant,
                    }),
                    _,
                ) => {
                    let m = principal.moments;
                    let axial = value[0] == 0.0 && value[1] == 0.0;
                    let body_axes_principal = r_bp == UnitQuaternion::identity();
                    (axial && body_axes_principal && m[0] == m[1])
                        .then(|| AxialTorqueSymmetric::new(m[0], m[2], value[2], omega0_b).ok())
                        .flatten()
                        .map(Oracle::AxialTorque)
                }
                (_, Some(c)) => {
                    // ω(0) along a principal axis: I·ω = I_k·ω, with no transverse part (to round-off).
                    let h0_b = scene.body.inertia_c() * omega0_b;
                    let inertia = h0_b.dot(&omega0_b) / omega0_b.norm_squared();
                    let along = (h0_b - omega0_b * inertia).norm() <= 1e-14 * h0_b.norm();
                    along
                        .then(|| DampedSpin::new(omega0_b, inertia, c, scene.attitude0).ok())
                        .flatten()
                        .map(Oracle::DampedSpin)
                }
                _ => None,
            },
            _ => None,
        }
    }
}

/// The symmetric gyrostat's closed form, where it applies: no effects, body axes principal with I₁ = I₂, and
/// every wheel balanced, on body ±z, at a constant relative spin (prescribed, or free: with ω₃ constant a free
/// wheel keeps its spin too).
fn symmetric_gyrostat(scene: &Scene, omega0_b: &Vector<BodyAxes>, g: &Gyrostat) -> Option<Oracle> {
    let inertia = g.body().inertia_b();
    let diagonal = (0..3).all(|i| (0..3).all(|j| i == j || inertia[(i, j)] == 0.0));
    let applies = scene.effects.is_empty()
        && diagonal
        && inertia[(0, 0)] == inertia[(1, 1)]
        && (g.rotors().iter())
            .all(|r| r.axis_b.x == 0.0 && r.axis_b.y == 0.0 && r.spins_steadily());
    if !applies {
        return None;
    }
    let h_rotor = (g.rotors().iter())
        .map(|r| r.inertia * r.spin0 * r.axis_b.z)
        .sum();
    let spins: Vec<f64> = g.rotors().iter().map(|r| r.spin0).collect();
    let energy = g.kinetic_energy(omega0_b, &spins);
    SymmetricTorqueFree::gyrostat(
        inertia[(0, 0)],
        inertia[(2, 2)],
        h_rotor,
        omega0_b.into_inner(),
        scene.attitude0,
    )
    .ok()
    .map(|exact| Oracle::SymmetricGyrostat {
        exact: Box::new(exact),
        energy,
    })
}

/// The rotation principal → body (`v_b = r_bp * v_p`) whose matrix has the principal axes, in body axes, as its
/// columns (as [`crate::body::Principal::axes_b`] holds them).
fn principal_to_body(axes_b: &Rotation3<f64>) -> UnitQuaternion<f64> {
    UnitQuaternion::from_rotation_matrix(axes_b)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::body::Principal;
    use nalgebra::{Matrix3, Vector3};

    #[test]
    fn r_bp_maps_principal_to_body_axes() {
        // A tensor whose principal axes are not the body axes.
        let turn = Rotation3::from_euler_angles(0.3, -0.7, 1.1);
        let inertia_b = turn.matrix()
            * Matrix3::from_diagonal(&Vector3::new(1.0, 2.0, 3.0))
            * turn.matrix().transpose();
        let principal = Principal::of(&inertia_b);
        let r_bp = principal_to_body(&principal.axes_b);
        for k in 0..3 {
            // Principal axis k, expressed in body axes, is r_bp · e_k, an eigenvector of the body tensor.
            let axis_b = r_bp * Vector3::ith(k, 1.0);
            let moment = principal.moments[k];
            assert!(
                (inertia_b * axis_b - axis_b * moment).norm() < 1e-12,
                "axis {k}"
            );
            // The eigenvector the tensor was built with (moments ascending: same order, up to sign).
            assert!(
                (axis_b.dot(&turn.matrix().column(k)).abs() - 1.0).abs() < 1e-12,
                "axis {k}"
            );
            // And the body's eigenvector, expressed in principal axes, is e_k.
            let e_k = r_bp.inverse_transform_vector(&axis_b);
            assert!((e_k - Vector3::ith(k, 1.0)).norm() < 1e-12, "axis {k}");
        }
    }
}
