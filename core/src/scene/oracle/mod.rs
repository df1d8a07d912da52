//! The closed forms that apply to a scene ([`Oracle::for_scene`], named by [`ClosedForm`] in the scene's
//! [`Facts`](super::Facts)) and their value at a time ([`Oracle::at`]): `compare`, the accuracy study and `score`
//! all evaluate them here.

mod applies;

use nalgebra::{UnitQuaternion, Vector3};
use serde::{Deserialize, Serialize};

use crate::exact::{AxialTorqueSymmetric, DampedSpin, SymmetricTorqueFree, TorqueFreeBody};

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
