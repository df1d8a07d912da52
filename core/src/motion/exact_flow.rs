//! The method `exact`: the torque-free flow in closed form, no stepping of an integrator. The rows of the schedule's
//! equal grid t_k = k·every come from [`TorqueFreeBody::equal_grid`] (each row advanced from the previous one by the
//! addition theorems of sn, cn, dn and of the third-kind integral, restarted from a direct evaluation every
//! [`crate::exact::ANCHOR_ROWS`] rows, so round-off stays within 1e-13 of the direct evaluation); the last row t_end
//! is evaluated directly. Nothing accumulates beyond one re-anchoring interval: the error at t = 10⁶ s is that of
//! evaluating the closed form once.
//!
//! ω_p(t) by Jacobi elliptic functions and the attitude by the elliptic integral of the third kind (Landau &
//! Lifshitz, *Mechanics*, §37; Celledoni, Fassò, Säfström & Zanna 2008), both from [`TorqueFreeBody`], in the
//! principal axes of the body about its moment center, mapped to body axes by P ([`FreeBody::principal_axes_b`]).
//!
//! The two forms give two independent readings of the same closed form, so that `eulerdyn compare` checks one
//! against the other:
//!
//! * body form: ω_b = P ω_p(t) from sn, cn, dn; H_b = P diag(I) ω_p; H_s = q_b(t) H_b;
//! * space form: H_s = q_b(0) H_b(0), the constant; H_b = q_b(t)⁻¹ H_s; ω_b = I⁻¹ H_b — ω from the attitude.
//!
//! Work counters: [`Stats::steps`] = row intervals (each crossed in one closed-form evaluation),
//! [`Stats::evals`] = rows evaluated.

use nalgebra::{UnitQuaternion, Vector3};

use crate::exact::{ExactError, TorqueFreeBody};
use crate::frames::{Form, Vector};
use crate::integrate::{IntegrateError, Schedule, Stats};
use crate::motion::free::FreeBody;
use crate::sample::Sample;

/// The closed-form torque-free motion of a [`FreeBody`] from ω_b(0) and q_b(0).
#[derive(Debug, Clone)]
pub struct ExactFlow {
    exact: TorqueFreeBody,
    body: FreeBody,
    /// P as a quaternion: principal → body.
    axes_q: UnitQuaternion<f64>,
}

impl ExactFlow {
    /// The motion of `body` from the angular velocity `omega0_b` (body axes) and attitude `q0_b` (body → space).
    /// Errors where [`TorqueFreeBody::new`] does (non-finite input, moments violating the triangle inequality).
    pub fn new(
        body: &FreeBody,
        omega0_b: &Vector3<f64>,
        q0_b: &UnitQuaternion<f64>,
    ) -> Result<Self, ExactError> {
        let axes_q = UnitQuaternion::from_rotation_matrix(body.principal_axes_b());
        let omega0_p = axes_q.inverse_transform_vector(omega0_b);
        let exact = TorqueFreeBody::new(*body.principal_moments(), omega0_p, q0_b * axes_q)?;
        Ok(Self {
            exact,
            body: *body,
            axes_q,
        })
    }

    /// The closed form in principal axes.
    pub fn closed_form(&self) -> &TorqueFreeBody {
        &self.exact
    }

    /// The row at time t in the form `frame` (module docs), evaluated directly. M = 0: the flow is torque-free.
    pub fn sample(&self, t: f64, form: Form) -> Sample {
        let q = self.exact.attitude(t) * self.axes_q.inverse();
        let omega_h_b = || {
            let omega_p = self.exact.omega_p(t);
            let h_p = omega_p.component_mul(self.body.principal_moments());
            (self.axes_q * omega_p, self.axes_q * h_p)
        };
        self.row(t, q, omega_h_b, form)
    }

    /// The row at t from the attitude q (body → space) and (ω_b, H_b) (asked for in the body form only).
    fn row(
        &self,
        t: f64,
        q: UnitQuaternion<f64>,
        omega_h_b: impl FnOnce() -> (Vector3<f64>, Vector3<f64>),
        form: Form,
    ) -> Sample {
        let (omega_b, h_b, h_s) = match form {
            Form::Body => {
                let (omega_b, h_b) = omega_h_b();
                (omega_b, h_b, q * h_b)
            }
            Form::Space => {
                let h_s = self.exact.h_s();
                let h_b = q.inverse_transform_vector(&h_s);
                (self.body.inertia_inv_b() * h_b, h_b, h_s)
            }
        };
        let zero = (Vector::zeros(), Vector::zeros());
        let h = (Vector::new(h_b), Vector::new(h_s));
        Sample::rigid(t, q, Vector::new(omega_b), h, zero)
    }

    /// Streams the row of every schedule time to `on_row`. A non-finite row (which the closed form does not
    /// produce for valid input) stops the run with `NonFinite` instead of being reported.
    pub fn run<E>(
        &self,
        schedule: &Schedule,
        form: Form,
        mut on_row: impl FnMut(&Sample) -> Result<(), E>,
    ) -> Result<Stats, IntegrateError<E>> {
        let mut stats = Stats::default();
        let mut grid = self
            .exact
            .equal_grid(schedule.every())
            .in_axes(&self.axes_q);
        let last = schedule.len() - 1;
        for k in 0..schedule.len() {
            let t = schedule.time(k);
            let sample = match grid.next() {
                // Rows before the last are on the grid: t = k·every, as the walk forms it.
                Some((t_grid, omega_b, q)) if k < last => {
                    debug_assert_eq!(t_grid, t);
                    self.row(t, q, || (omega_b, self.body.inertia_b() * omega_b), form)
                }
                _ => self.sample(t, form),
            };
            stats.evals += 1;
            if t > 0.0 {
                stats.steps += 1;
            }
            if !sample_is_finite(&sample) {
                return Err(IntegrateError::NonFinite { t });
            }
            on_row(&sample).map_err(|cause| IntegrateError::Stopped { t, cause })?;
        }
        Ok(stats)
    }
}

/// Whether every value of a free-motion row is finite.
pub fn sample_is_finite(s: &Sample) -> bool {
    s.q.coords
        .iter()
        .chain(s.omega_b.iter())
        .chain(s.h_o_b.iter())
        .chain(s.h_o_s.iter())
        .chain(s.m_o_b.iter())
        .all(|v| v.is_finite())
        && s.energy.is_finite()
}
