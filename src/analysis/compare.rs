//! `eulerdyn compare`: the scene run in both forms of Euler's equation, side by side, and against the closed form
//! where one applies. The two runs stream in lockstep (the space form on a second thread), so memory does not grow
//! with the number of rows.

use std::ops::ControlFlow;
use std::sync::mpsc;
use std::thread;

use nalgebra::{Rotation3, UnitQuaternion, Vector3};

use crate::effects::Effect;
use crate::exact::{AxialTorqueSymmetric, DampedSpin, SymmetricTorqueFree, TorqueFreeBody};
use crate::frames::{Axes, Form};
use crate::integrate::IntegrateError;
use crate::method::Method;
use crate::motion::gyrostat::{Drive, Gyrostat};
use crate::profile::Profile;
use crate::sample::Sample;
use crate::scene::{Motion, Scene};
use crate::simulate::{self, RunError};
use crate::wheels::WheelControl;

/// A closed-form solution that applies to a scene.
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
        match self {
            Oracle::TorqueFree { .. } => {
                "torque-free body, Jacobi elliptic functions (Landau & Lifshitz §37)"
            }
            Oracle::AxialTorque(_) => "symmetric body under a constant axial torque (ω only)",
            Oracle::DampedSpin { .. } => "damped principal-axis spin, ω(0)·exp(−c t / I)",
            Oracle::FixedAxis => "prescribed fixed-axis motion, H_s = I_s(θ)·ω_s",
            Oracle::SymmetricGyrostat { .. } => {
                "torque-free symmetric gyrostat, transverse ω turning at ((C − A)ω₃ + h)/A (Hughes §3.5)"
            }
        }
    }

    /// The closed-form values at time t: ω_b, attitude (if known), H_s (if known), energy (if known).
    fn at(&self, t: f64) -> Exact {
        match self {
            Oracle::TorqueFree { exact, r_bp } => {
                let omega_b = r_bp * exact.omega_p(t);
                Exact {
                    omega_b: Some(omega_b),
                    q: Some(exact.attitude(t) * r_bp.inverse()),
                    h_s: Some(exact.h_s()),
                    energy: Some(exact.energy()),
                }
            }
            Oracle::AxialTorque(exact) => Exact {
                omega_b: Some(exact.omega_p(t)),
                q: None,
                h_s: None,
                energy: None,
            },
            Oracle::DampedSpin(spin) => {
                let s = spin.at(t);
                Exact {
                    omega_b: Some(s.omega_b),
                    q: Some(s.q),
                    h_s: Some(s.h_s),
                    energy: Some(s.energy),
                }
            }
            Oracle::FixedAxis => Exact::default(),
            Oracle::SymmetricGyrostat { exact, energy } => Exact {
                omega_b: Some(exact.omega_p(t)),
                q: Some(exact.attitude(t)),
                h_s: Some(exact.h_s()),
                energy: Some(*energy),
            },
        }
    }
}

/// The symmetric gyrostat's closed form, where it applies: no effects, body axes principal with I₁ = I₂, and
/// every wheel balanced, on body ±z, at a constant relative spin (prescribed, or free: with ω₃ constant a free
/// wheel keeps its spin too).
fn symmetric_gyrostat(scene: &Scene, omega0_b: &Vector3<f64>, g: &Gyrostat) -> Option<Oracle> {
    let inertia = g.body().inertia_b();
    let diagonal = (0..3).all(|i| (0..3).all(|j| i == j || inertia[(i, j)] == 0.0));
    let steady = |r: &crate::motion::gyrostat::Rotor| {
        let on_z = r.axis_b.x == 0.0 && r.axis_b.y == 0.0;
        let constant = match &r.drive {
            Drive::Accel(alpha) => *alpha == 0.0,
            Drive::Torque(tau) => tau.is_zero(),
            Drive::Free => true,
            Drive::Table(_) | Drive::Law => false,
        };
        on_z && constant && r.imbalance.is_none() && r.control == WheelControl::default()
    };
    let applies = scene.effects.is_empty()
        && diagonal
        && inertia[(0, 0)] == inertia[(1, 1)]
        && g.rotors().iter().all(steady);
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

#[derive(Debug, Default)]
struct Exact {
    omega_b: Option<Vector3<f64>>,
    q: Option<UnitQuaternion<f64>>,
    h_s: Option<Vector3<f64>>,
    energy: Option<f64>,
}

/// The largest difference of one quantity over the rows: absolute, with the largest magnitude seen, so that the
/// relative difference is `abs / scale`.
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct Largest {
    /// The largest absolute difference (the quantity's unit).
    pub abs: f64,
    /// The largest magnitude of the quantity seen.
    pub scale: f64,
}

impl Largest {
    fn add(&mut self, diff: f64, magnitude: f64) {
        self.abs = self.abs.max(diff);
        self.scale = self.scale.max(magnitude);
    }

    /// The difference relative to the largest magnitude (absolute when the quantity is zero throughout).
    pub fn relative(&self) -> f64 {
        if self.scale > 0.0 {
            self.abs / self.scale
        } else {
            self.abs
        }
    }
}

/// Differences between two sources, per quantity.
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct Differences {
    /// |Δω_b| (rad/s).
    pub omega: Largest,
    /// |ΔH_s| (kg·m²/s).
    pub h_s: Largest,
    /// Angle of the rotation between the two attitudes (rad; absolute).
    pub attitude: Largest,
    /// |ΔT| (J).
    pub energy: Largest,
    /// Δ|H| (kg·m²/s).
    pub h_norm: Largest,
    /// |ΔM_s| (N·m).
    pub moment: Largest,
}

/// Angle of the rotation taking attitude a to b (rad): 2·atan2(|v|, |w|) of q = a⁻¹b, accurate for tiny angles
/// (unlike 2·acos w) and insensitive to the sign of q.
pub fn attitude_angle(a: &UnitQuaternion<f64>, b: &UnitQuaternion<f64>) -> f64 {
    let q = a.rotation_to(b);
    2.0 * q.imag().norm().atan2(q.scalar().abs())
}

impl Differences {
    fn add_samples(&mut self, a: &Sample, b: &Sample) {
        self.omega
            .add((a.omega_b - b.omega_b).norm(), a.omega_b.norm());
        self.h_s.add((a.h_s - b.h_s).norm(), a.h_s.norm());
        self.attitude.add(attitude_angle(&a.q, &b.q), 0.0);
        self.energy.add((a.energy - b.energy).abs(), a.energy.abs());
        self.h_norm
            .add((a.h_s.norm() - b.h_s.norm()).abs(), a.h_s.norm());
        self.moment.add((a.m_s - b.m_s).norm(), a.m_s.norm());
    }

    fn add_exact(&mut self, s: &Sample, e: &Exact) {
        if let Some(omega_b) = e.omega_b {
            self.omega.add((s.omega_b - omega_b).norm(), omega_b.norm());
        }
        if let Some(q) = e.q {
            self.attitude.add(attitude_angle(&s.q, &q), 0.0);
        }
        if let Some(h_s) = e.h_s {
            self.h_s.add((s.h_s - h_s).norm(), h_s.norm());
            self.h_norm
                .add((s.h_s.norm() - h_s.norm()).abs(), h_s.norm());
        }
        if let Some(energy) = e.energy {
            self.energy.add((s.energy - energy).abs(), energy.abs());
        }
        if let Some(h_int) = s.h_s_integrated {
            self.h_s.add((h_int - s.h_s).norm(), s.h_s.norm());
        }
    }

    /// The quantities that were compared, as (name, relative difference).
    pub fn rows(&self) -> Vec<(&'static str, f64)> {
        [
            ("omega", self.omega),
            ("H_s", self.h_s),
            ("attitude angle (rad)", self.attitude),
            ("energy", self.energy),
            ("|H|", self.h_norm),
            ("M", self.moment),
        ]
        .into_iter()
        .filter(|(_, d)| *d != Largest::default())
        .map(|(n, d)| (n, d.relative()))
        .collect()
    }

    /// The largest relative difference of any quantity.
    pub fn worst(&self) -> f64 {
        self.rows().iter().map(|r| r.1).fold(0.0, f64::max)
    }
}

/// One quantity of [`Comparison::table`]: relative differences (the attitude's absolute, in rad).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ComparisonRow {
    /// The quantity's name, e.g. `H_s` or `attitude angle (rad)`.
    pub quantity: &'static str,
    /// Body form against space form.
    pub body_vs_space: f64,
    /// Body form against the closed form, when it gives this quantity.
    pub body_vs_exact: Option<f64>,
    /// Space form against the closed form, when it gives this quantity.
    pub space_vs_exact: Option<f64>,
}

/// The outcome of `compare`.
pub struct Comparison {
    /// The body form against the space form, row by row.
    pub body_vs_space: Differences,
    /// Against the closed form, for the body and the space form, when one applies.
    pub exact: Option<(&'static str, Differences, Differences)>,
    /// The largest difference allowed (`compare_tolerance`).
    pub tolerance: f64,
    /// Rows compared.
    pub rows: u64,
    /// What the comparison means for the scene's method, when that needs saying (`exact`, split2/split4).
    pub note: Option<String>,
}

impl Comparison {
    /// Whether every difference is within the scene's tolerance.
    pub fn passes(&self) -> bool {
        let exact_worst = self
            .exact
            .as_ref()
            .map_or(0.0, |(_, b, s)| b.worst().max(s.worst()));
        self.body_vs_space.worst().max(exact_worst) <= self.tolerance
    }

    /// The relative differences per quantity (those compared between the forms), with the closed form's where it
    /// gives that quantity.
    pub fn table(&self) -> Vec<ComparisonRow> {
        let exact_rows = self.exact.as_ref().map(|(_, b, s)| (b.rows(), s.rows()));
        let lookup =
            |rows: &[(&str, f64)], name: &str| rows.iter().find(|r| r.0 == name).map(|r| r.1);
        self.body_vs_space
            .rows()
            .into_iter()
            .map(|(quantity, body_vs_space)| ComparisonRow {
                quantity,
                body_vs_space,
                body_vs_exact: exact_rows.as_ref().and_then(|(b, _)| lookup(b, quantity)),
                space_vs_exact: exact_rows.as_ref().and_then(|(_, s)| lookup(s, quantity)),
            })
            .collect()
    }

    /// A table for people: one line per quantity.
    pub fn report(&self) -> String {
        let mut out = String::new();
        out.push_str(&format!(
            "largest differences over {} rows (relative to the largest magnitude; attitude in rad)\n",
            self.rows
        ));
        match &self.exact {
            Some((name, _, _)) => out.push_str(&format!("closed form: {name}\n")),
            None => out.push_str("closed form: none applies to this scene\n"),
        }
        if let Some(note) = &self.note {
            out.push_str(note);
            out.push('\n');
        }
        out.push_str(&format!(
            "{:<22} {:>14} {:>14} {:>14}\n",
            "quantity", "body vs space", "body vs exact", "space vs exact"
        ));
        let cell = |v: Option<f64>| v.map_or("-".to_string(), |v| format!("{v:.3e}"));
        for row in self.table() {
            out.push_str(&format!(
                "{:<22} {:>14.3e} {:>14} {:>14}\n",
                row.quantity,
                row.body_vs_space,
                cell(row.body_vs_exact),
                cell(row.space_vs_exact)
            ));
        }
        out.push_str(&format!(
            "tolerance {:e}: {}\n",
            self.tolerance,
            if self.passes() { "within" } else { "EXCEEDED" }
        ));
        out
    }
}

/// What the comparison means for the scene's method, where it is not the obvious: for `exact` both forms are the
/// closed form, read two ways; for the splitting methods both forms are the same map.
fn method_note(scene: &Scene) -> Option<String> {
    match (scene.solver.method, &scene.motion) {
        (Method::Exact, Motion::Free { .. }) => Some(
            "method exact: both forms are the closed form — body: omega from the Jacobi functions; space: omega \
             from the closed-form attitude and the constant H_s — so \"body vs space\" checks the attitude \
             against omega, and \"vs exact\" the rows against the oracle"
                .into(),
        ),
        (Method::Split2 | Method::Split4, Motion::Free { .. }) => Some(format!(
            "method {}: the body form turns H_p, the space form keeps H_s; the two are the same map in exact \
             arithmetic, so \"body vs space\" is round-off (amplified where the motion is unstable, as near \
             the separatrix)",
            scene.solver.method.name()
        )),
        _ => None,
    }
}

/// The two runs of `compare` could not exchange a row: the other run stopped early (its own error says why).
#[derive(Debug, Clone, Copy, PartialEq, Eq, thiserror::Error)]
#[error("the other form's run stopped early")]
pub struct HandOver;

/// Runs the scene in both frames (in lockstep) and against its closed form.
pub fn compare(scene: &Scene) -> Result<Comparison, RunError<HandOver>> {
    compare_until(scene, || ControlFlow::Continue(()))
}

/// [`compare`], with `poll` called at every row of the body-form run: once it breaks, both runs stop and the
/// result is `Err(RunError::Sink(HandOver))` (the Python module's Ctrl-C).
pub fn compare_until(
    scene: &Scene,
    mut poll: impl FnMut() -> ControlFlow<()>,
) -> Result<Comparison, RunError<HandOver>> {
    let mut body_scene = scene.clone();
    body_scene.solver.form = Form::Body;
    let mut space_scene = scene.clone();
    space_scene.solver.form = Form::Space;
    let oracle = Oracle::for_scene(scene);
    let (sender, receiver) = mpsc::sync_channel::<Sample>(1024);
    let space_run = thread::spawn(move || {
        simulate::run(&space_scene, |s| sender.send(*s).map_err(|_| HandOver))
    });
    let mut body_vs_space = Differences::default();
    let mut body_vs_exact = Differences::default();
    let mut space_vs_exact = Differences::default();
    let mut rows = 0;
    let body_result = simulate::run(&body_scene, |b: &Sample| {
        if poll().is_break() {
            return Err(HandOver);
        }
        let Ok(s) = receiver.recv() else {
            // The space run stopped early; its own result says why.
            return Err(HandOver);
        };
        rows += 1;
        body_vs_space.add_samples(b, &s);
        if let Some(oracle) = &oracle {
            let exact = oracle.at(b.t);
            body_vs_exact.add_exact(b, &exact);
            space_vs_exact.add_exact(&s, &exact);
        }
        Ok(())
    });
    drop(receiver);
    let space_result = space_run.join().unwrap_or_else(|_| {
        Err(RunError::Integrate(IntegrateError::Backend {
            t: f64::NAN,
            message: "the space-form run panicked".into(),
        }))
    });
    // An integration failure (or divergence) in either run is the cause; a failed hand-over is only its
    // consequence.
    match (body_result, space_result) {
        (Ok(_), Ok(_)) => {}
        (Err(e @ (RunError::Integrate(_) | RunError::Diverged(_))), _)
        | (_, Err(e @ (RunError::Integrate(_) | RunError::Diverged(_)))) => return Err(e),
        (Err(e), _) | (_, Err(e)) => return Err(e),
    }
    Ok(Comparison {
        body_vs_space,
        exact: oracle.map(|o| (o.name(), body_vs_exact, space_vs_exact)),
        tolerance: scene.compare_tolerance,
        rows,
        note: method_note(scene),
    })
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

    fn free_scene() -> Scene {
        crate::scene::SceneSpec::new(
            crate::scene::BodySpec::principal(1.0, [1.0, 2.0, 3.0]),
            2.0,
            0.5,
        )
        .with_omega([0.3, 0.0, 2.0])
        .build()
        .unwrap()
    }

    #[test]
    fn the_table_is_the_report_s_rows() {
        let c = compare(&free_scene()).unwrap();
        let table = c.table();
        assert_eq!(table.len(), c.body_vs_space.rows().len());
        // The torque-free body has a closed form for every quantity compared.
        assert!(
            table
                .iter()
                .all(|r| r.body_vs_exact.is_some() && r.space_vs_exact.is_some())
        );
        for r in &table {
            let line = c
                .report()
                .lines()
                .find(|l| l.starts_with(r.quantity))
                .map(str::to_string);
            assert!(line.is_some_and(|l| l.contains(&format!("{:.3e}", r.body_vs_space))));
        }
    }

    #[test]
    fn a_poll_that_breaks_stops_both_runs() {
        let mut polls = 0;
        let result = compare_until(&free_scene(), || {
            polls += 1;
            if polls > 2 {
                ControlFlow::Break(())
            } else {
                ControlFlow::Continue(())
            }
        });
        assert!(matches!(result, Err(RunError::Sink(HandOver))));
        assert_eq!(polls, 3);
    }
}
