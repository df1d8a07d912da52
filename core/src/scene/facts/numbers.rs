//! The numbers `check` prints ([`CheckNumbers::of`]), computed once with the scene's facts: the body about C and
//! about the moment center O, the axis (its tilt from the nearest principal axis, bearings, imbalance) and the
//! state at t = 0 (H_O = I_O ω + Σ J_k Ω_k a_k, T = ½ ω·H_O + the wheels' share; a prescribed axis's row at t = 0).

use nalgebra::{Matrix3, Vector3};

use super::{AxisNumbers, BearingNumbers, CheckNumbers, MomentCenter, MotionNumbers, StartNumbers};
use crate::body::Principal;
use crate::effects;
use crate::frames::{BodyAxes, Vector};
use crate::motion::attribute::StartRow;
use crate::motion::fixed_axis::FixedAxis;
use crate::motion::free::FreeBody;
use crate::scene::model::Scene;

impl CheckNumbers {
    /// The numbers of `scene`.
    pub(super) fn of(scene: &Scene) -> Self {
        let inertia_c = scene.body.inertia_c();
        let principal = scene.body.principal();
        let (rho_c_b, inertia_o_b) = scene.motion.about_moment_center();
        CheckNumbers {
            mass: scene.body.mass(),
            center_b: scene.center_b.into(),
            inertia_c_b: rows_of(inertia_c),
            principal_moments_c: principal.moments.into(),
            principal_axes_b: rows_of(principal.axes_b.matrix()),
            motion: scene.motion.kind(),
            moment_center_from_c_b: (-rho_c_b).into(),
            inertia_o_b: rows_of(&inertia_o_b),
            axis_b: scene.motion.axis().map(|a| a.axis_b().into_inner().into()),
            step_used: scene.fixed_step(),
            rows: scene.schedule.len(),
            motion_numbers: Some(MotionNumbers::of(scene, &inertia_o_b)),
        }
    }
}

impl MotionNumbers {
    /// The moment center, axis and initial state of `scene`, whose inertia about O is `inertia_o_b`.
    fn of(scene: &Scene, inertia_o_b: &Matrix3<f64>) -> Self {
        let pivot = effects::gravity(&scene.effects).is_some();
        let axis = scene.motion.axis();
        let moment_center = match axis {
            None if pivot => MomentCenter::Pivot,
            Some(a) if *a.point_b() != Vector3::zeros() => MomentCenter::AxisPoint,
            _ => MomentCenter::MassCenter,
        };
        // A hinge's state at the start is its θ₀ and θ̇₀, in its axis numbers.
        let at_start = match (scene.motion.free(), scene.motion.prescribed()) {
            (Some(free), _) => Some(match free.attribute {
                Some(a) => StartNumbers::of_row(a.door().start(free.omega0_b, &scene.attitude0)),
                None => StartNumbers::free(scene, free.omega0_b, free.body),
            }),
            (None, Some(axis)) => Some(StartNumbers::fixed_axis(scene, axis)),
            (None, None) => None,
        };
        MotionNumbers {
            moment_center,
            principal_moments_o: Principal::of(inertia_o_b).moments.into(),
            axis: axis.map(|a| AxisNumbers::of(scene, a)),
            at_start,
        }
    }
}

impl AxisNumbers {
    /// The axis `axis` of `scene`: tilt, rates, I_uu, bearings, imbalance (static s = m ρ_C⊥, e = |s|/m; dynamic
    /// d = I_O u − (u·I_O u) u, [`FixedAxis::imbalance`]).
    fn of(scene: &Scene, axis: &FixedAxis) -> Self {
        let u_b = axis.axis_b().into_inner();
        let (tilt_deg, nearest_principal) = scene.body.principal().tilt_of(&u_b);
        let hinge = scene.motion.hinge();
        let at = |z: f64| (*axis.point_b() + scene.center_b + u_b * z).into();
        let (static_imbalance, dynamic_imbalance) = axis.imbalance();
        let e = static_imbalance.norm() / axis.mass();
        AxisNumbers {
            tilt_deg,
            nearest_principal,
            rate: axis.rate(),
            accel: axis.accel(),
            i_uu: hinge.map_or_else(|| axis.i_uu(), |h| h.i_uu()),
            theta0: hinge.map(|h| h.theta0()),
            bearings: axis.bearings().map(|b| BearingNumbers {
                a: b.a,
                b: b.b,
                a_b: at(b.a),
                b_b: at(b.b),
            }),
            imbalance_static_kgm: axis.mass() * e,
            imbalance_offset_m: e,
            imbalance_dynamic_kgm2: dynamic_imbalance.norm(),
        }
    }
}

impl StartNumbers {
    /// A free rigid body: H_O = I_O ω, H_O,s = R₀ H_O, T = ½ ω·H_O.
    fn free(scene: &Scene, omega0_b: &Vector<BodyAxes>, free: &FreeBody) -> Self {
        let h_b = free.inertia_b() * **omega0_b;
        Self::of_row(StartRow {
            omega_b: **omega0_b,
            h_o_b: h_b,
            h_o_s: scene.attitude0 * h_b,
            energy: 0.5 * omega0_b.dot(&h_b),
        })
    }

    /// A free body's state at t = 0 (a body attribute's, [`BodyAttribute::start`]).
    fn of_row(row: StartRow) -> Self {
        StartNumbers {
            omega_b: row.omega_b.into(),
            h_o_b: row.h_o_b.into(),
            h_o_s: row.h_o_s.into(),
            m_o_b: None,
            f_s: None,
            energy: row.energy,
        }
    }

    /// A prescribed axis: its row at t = 0 in the scene's form.
    fn fixed_axis(scene: &Scene, axis: &FixedAxis) -> Self {
        let s = axis.sample(0.0, scene.solver.form);
        StartNumbers {
            omega_b: (*s.omega_b).into(),
            h_o_b: (*s.h_o_b).into(),
            h_o_s: (*s.h_o_s).into(),
            m_o_b: Some((*s.m_o_b).into()),
            f_s: s.f_s.map(|f| (*f).into()),
            energy: s.energy,
        }
    }
}

/// The rows of `m`.
fn rows_of(m: &Matrix3<f64>) -> [[f64; 3]; 3] {
    std::array::from_fn(|r| std::array::from_fn(|c| m[(r, c)]))
}
