//! The closed forms that apply to a scene ([`Oracle::for_scene`], named by [`ClosedForm`] in the scene's
//! [`Facts`](super::Facts)) and their value at a time ([`Oracle::at`]): `compare`, the accuracy study and `score`
//! all evaluate them here.

use nalgebra::{Rotation3, UnitQuaternion, Vector3};

use crate::effects::Effect;
use crate::exact::{AxialTorqueSymmetric, DampedSpin, SymmetricTorqueFree, TorqueFreeBody};
use crate::frames::Axes;
use crate::profile::Profile;
use crate::wheels::gyrostat::Gyrostat;
use serde::{Deserialize, Serialize};

use super::model::{Motion, Scene};

/// Which closed form applies to a scene, by the name the sidecar's `facts` gives it.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum ClosedForm {
    /// [`Oracle::TorqueFree`].
    TorqueFree,
    /// [`Oracle::AxialTorque`].
    AxialTorque,
    /// [`Oracle::DampedSpin`].
    DampedSpin,
    /// [`Oracle::FixedAxis`].
    FixedAxis,
    /// [`Oracle::SymmetricGyrostat`].
    SymmetricGyrostat,
}

impl ClosedForm {
    /// What reports call it.
    ///
    /// ```
    /// use eulerdyn::scene::ClosedForm;
    /// assert!(ClosedForm::TorqueFree.name().contains("Landau & Lifshitz §37"));
    /// ```
    pub fn name(self) -> &'static str {
        match self {
            ClosedForm::TorqueFree => {
                "torque-free body, Jacobi elliptic functions (Landau & Lifshitz §37)"
            }
            ClosedForm::AxialTorque => "symmetric body under a constant axial torque (ω only)",
            ClosedForm::DampedSpin => "damped principal-axis spin, ω(0)·exp(−c t / I)",
            ClosedForm::FixedAxis => "prescribed fixed-axis motion, H_s = I_s(θ)·ω_s",
            ClosedForm::SymmetricGyrostat => {
                "torque-free symmetric gyrostat, transverse ω turning at ((C − A)ω₃ + h)/A (Hughes §3.5)"
            }
        }
    }
}

/// A closed-form solution that applies to a scene.
#[derive(Debug, Clone, PartialEq)]
pub enum Oracle {
    /// Torque-free body: ω and attitude (Landau & Lifshitz §37).
    TorqueFree {
        /// The closed form in principal axes.
        exact: Box<TorqueFreeBody>,
        /// Principal → body: `v_b = r_bp * v_p`; its columns are the principal axes in body axes.
        r_bp: UnitQuaternion<f64>,
    },
    /// Symmetric body (I1 = I2, body axes principal) under a constant torque along its symmetry axis: ω only.
    AxialTorque(AxialTorqueSymmetric),
    /// Spin about a principal axis under viscous damping M = −cω (see [`DampedSpin`]).
    DampedSpin(DampedSpin),
    /// Prescribed fixed-axis motion: the closed-form H_s = I_s(θ)·ω_s against Ḣ_s = M_s integrated.
    FixedAxis,
    /// Torque-free symmetric gyrostat (I₁ = I₂, body axes principal, balanced wheels on the symmetry axis at a
    /// constant relative spin): ω, attitude and H_s (Hughes §3.5; [`SymmetricTorqueFree::gyrostat`]).
    SymmetricGyrostat {
        /// The closed form (the symmetric top with the wheels' h added).
        exact: Box<SymmetricTorqueFree>,
        /// T = ½ ωᵀIω + Σ (J_k Ω_k (a_k·ω) + ½ J_k Ω_k²), constant.
        energy: f64,
    },
}

impl Oracle {
    /// The closed form that applies to the scene, if any.
    pub fn for_scene(scene: &Scene) -> Option<Oracle> {
        let omega0_b = match &scene.motion {
            Motion::FixedAxis(_) => return Some(Oracle::FixedAxis),
            Motion::Hinge(_) => return None,
            Motion::Free {
                omega0_b,
                gyrostat: Some(g),
                ..
            } => return symmetric_gyrostat(scene, omega0_b, g),
            Motion::Free { omega0_b, .. } => *omega0_b,
        };
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
            [
                Effect::Torque {
                    frame: Axes::Body,
                    value,
                    profile: Profile::Constant,
                },
            ] => {
                let m = principal.moments;
                let axial = value[0] == 0.0 && value[1] == 0.0;
                let body_axes_principal = r_bp == UnitQuaternion::identity();
                (axial && body_axes_principal && m[0] == m[1])
                    .then(|| AxialTorqueSymmetric::new(m[0], m[2], value[2], omega0_b).ok())
                    .flatten()
                    .map(Oracle::AxialTorque)
            }
            [Effect::Damping { c }] => {
                // ω(0) along a principal axis: I·ω = I_k·ω, with no transverse part (to round-off).
                let h0_b = scene.body.inertia_c() * omega0_b;
                let inertia = h0_b.dot(&omega0_b) / omega0_b.norm_squared();
                let along = (h0_b - omega0_b * inertia).norm() <= 1e-14 * h0_b.norm();
                along
                    .then(|| DampedSpin::new(omega0_b, inertia, *c, scene.attitude0).ok())
                    .flatten()
                    .map(Oracle::DampedSpin)
            }
            _ => None,
        }
    }

    /// A short name for reports.
    pub fn name(&self) -> &'static str {
        self.kind().name()
    }

    /// Which closed form it is.
    pub fn kind(&self) -> ClosedForm {
        match self {
            Oracle::TorqueFree { .. } => ClosedForm::TorqueFree,
            Oracle::AxialTorque(_) => ClosedForm::AxialTorque,
            Oracle::DampedSpin(_) => ClosedForm::DampedSpin,
            Oracle::FixedAxis => ClosedForm::FixedAxis,
            Oracle::SymmetricGyrostat { .. } => ClosedForm::SymmetricGyrostat,
        }
    }

    /// The closed form at time t ([`Exact`]): what `compare`, the study and `score` measure a run against.
    pub fn at(&self, t: f64) -> Exact {
        match self {
            Oracle::TorqueFree { exact, r_bp } => {
                let h_s = exact.h_s();
                Exact {
                    omega_b: Some(r_bp * exact.omega_p(t)),
                    q: Some(exact.attitude(t) * r_bp.inverse()),
                    h_s: Some(h_s),
                    h_norm: Some(h_s.norm()),
                    energy: Some(exact.energy()),
                }
            }
            Oracle::AxialTorque(exact) => Exact {
                omega_b: Some(exact.omega_p(t)),
                ..Exact::default()
            },
            Oracle::DampedSpin(spin) => {
                let s = spin.at(t);
                Exact {
                    omega_b: Some(s.omega_b),
                    q: Some(s.q),
                    h_s: Some(s.h_s),
                    h_norm: Some(s.h_norm),
                    energy: Some(s.energy),
                }
            }
            Oracle::FixedAxis => Exact::default(),
            Oracle::SymmetricGyrostat { exact, energy } => {
                let h_s = exact.h_s();
                Exact {
                    omega_b: Some(exact.omega_p(t)),
                    q: Some(exact.attitude(t)),
                    h_s: Some(h_s),
                    h_norm: Some(h_s.norm()),
                    energy: Some(*energy),
                }
            }
        }
    }
}

/// The symmetric gyrostat's closed form, where it applies: no effects, body axes principal with I₁ = I₂, and
/// every wheel balanced, on body ±z, at a constant relative spin (prescribed, or free: with ω₃ constant a free
/// wheel keeps its spin too).
fn symmetric_gyrostat(scene: &Scene, omega0_b: &Vector3<f64>, g: &Gyrostat) -> Option<Oracle> {
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
        *omega0_b,
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

/// The closed form at one time; `None` where it says nothing (the axial torque's attitude, H_s and T).
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct Exact {
    /// ω (rad/s, body axes).
    pub omega_b: Option<Vector3<f64>>,
    /// The attitude, body → space.
    pub q: Option<UnitQuaternion<f64>>,
    /// H_s about the moment center (kg·m²/s, space axes).
    pub h_s: Option<Vector3<f64>>,
    /// |H| (kg·m²/s).
    pub h_norm: Option<f64>,
    /// The kinetic energy T (J).
    pub energy: Option<f64>,
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::body::Principal;
    use nalgebra::Matrix3;

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
