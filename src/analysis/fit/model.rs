//! The model a fit integrates: Euler's equation of the free body in body axes with its attitude, and beside it the
//! variational equations of both in each parameter (forward sensitivities, Hairer, Nørsett & Wanner I §I.14).
//!
//! With I ω̇ = M(t, q, ω) − ω × I ω and q̇ = ½ q ⊗ (0, ω), a parameter p moving I by E = ∂I/∂p moves
//! s_ω = ∂ω/∂p and s_q = ∂q/∂p as
//!
//! ```text
//! I ṡ_ω = ∂M/∂(q, ω)·(s_q, s_ω) + ∂M/∂p − s_ω × I ω − ω × I s_ω − ω × E ω − E ω̇
//! ṡ_q  = ½ s_q ⊗ (0, ω) + ½ q ⊗ (0, s_ω)
//! ```
//!
//! from s(0) = ∂(ω₀, q₀)/∂p (ω₀'s axes; ½ q₀ ⊗ (0, v) for a turn of q₀ whose derivative is v in body axes; zero
//! for the inertia). The rigid body's part is differentiated by hand; the effects' moment, which may be a table, a law or
//! an orbit's field, is linearised at each stage by a central difference along (s_q, s_ω) (and across the
//! inertia for a moment that depends on it), with a step of ε^(1/3) of the state's size: its error, ~1e-11
//! relative, is far below what a fit's Jacobian needs.

use nalgebra::{Matrix3, Quaternion, SVector, UnitQuaternion, Vector3};

use crate::effects::{AppliedMoment, EffectMoments};
use crate::integrate::{self, Dense, OdeSystem, Schedule, Settings, StepWatch};
use crate::method::{Backend, Method};
use crate::motion::free::{FreeBody, quaternion_rate};

/// The most parameters the variational equations carry: the inertia's six, ω₀'s three, q₀'s three.
pub const MAX_COLUMNS: usize = 12;
/// The state's length for `columns` parameters: ω (3), q (4), then (s_ω, s_q) for each.
pub const fn state_len(columns: usize) -> usize {
    7 * (1 + columns)
}
/// The augmented state of `N` entries; columns beyond the model's stay zero. Two lengths are compiled, for up to
/// 6 and up to [`MAX_COLUMNS`] columns: a step's cost grows with N.
pub type State<const N: usize> = SVector<f64, N>;

/// The relative tolerance of the model's integration (dop853; the sensitivities are under the same control):
/// 1e-11, a hundred times below what a double-precision gyro reading resolves over a record of 10⁴ rows.
pub const RTOL: f64 = 1e-11;
/// The relative step of the central differences of the effects' moment, ≈ ε^(1/3).
const STEP: f64 = 6e-6;

/// How one parameter enters the equations.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Column {
    /// It moves the inertia about the moment center by `E` = ∂I/∂p (body axes).
    Inertia(Matrix3<f64>),
    /// It is ω₀'s component along body axis k.
    Omega0(usize),
    /// It turns q₀: ∂q₀/∂p = ½ q₀ ⊗ (0, v), v in body axes.
    Attitude0(Vector3<f64>),
}

/// The effects' moment at one parameter point, and at the inertia moved ± along each inertia column (only when
/// a moment depends on the inertia, e.g. the gravity gradient).
#[derive(Debug, Clone)]
pub struct Moments {
    /// M at the parameters.
    pub at: EffectMoments,
    /// (M at I + δE_j, M at I − δE_j, 2δ) for each column j that moves the inertia.
    pub across: Vec<Option<(EffectMoments, EffectMoments, f64)>>,
}

/// The free body and its start at one parameter point, with the parameters' columns.
#[derive(Debug, Clone)]
pub struct Model {
    /// The body about its moment center.
    pub body: FreeBody,
    /// The effects' moment; `None`: torque-free.
    pub moments: Option<Moments>,
    /// ω₀, body axes (rad/s).
    pub omega0_b: Vector3<f64>,
    /// q₀, body → space.
    pub q0: UnitQuaternion<f64>,
    /// One column per dynamic parameter, at most [`MAX_COLUMNS`].
    pub columns: Vec<Column>,
}

/// The model's solution at one measured time: ω, q and their sensitivities.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Point {
    /// ω (rad/s, body axes).
    pub omega_b: Vector3<f64>,
    /// q (body → space), normalised.
    pub q: UnitQuaternion<f64>,
    /// ∂ω/∂p_j per column.
    pub d_omega: [Vector3<f64>; MAX_COLUMNS],
    /// The attitude's sensitivity as a turn in body axes, δ_j = 2 vec(q̄ ⊗ ∂q/∂p_j).
    pub d_attitude: [Vector3<f64>; MAX_COLUMNS],
}

impl Model {
    /// The state at t = 0.
    fn initial_state<const N: usize>(&self) -> State<N> {
        let mut y = State::<N>::zeros();
        y.fixed_rows_mut::<3>(0).copy_from(&self.omega0_b);
        let q = self.q0.quaternion();
        y.fixed_rows_mut::<4>(3)
            .copy_from_slice(&[q.w, q.i, q.j, q.k]);
        self.seed(&mut y, 7);
        y
    }

    /// Each column's ∂(ω₀, q₀)/∂p into its block of `y` (blocks `block` long): ω₀'s axis, ½ q₀ ⊗ (0, v) for a turn,
    /// zero for the inertia (which neither ω₀, q₀ nor a wheel's spin hold).
    pub(super) fn seed<const N: usize>(&self, y: &mut State<N>, block: usize) {
        let q = self.q0.quaternion();
        for (j, column) in self.columns.iter().enumerate() {
            let at = block * (j + 1);
            match *column {
                Column::Inertia(_) => {}
                Column::Omega0(k) => y[at + k] = 1.0,
                Column::Attitude0(v) => {
                    let s = quaternion_rate(&[q.w, q.i, q.j, q.k], &v);
                    y.fixed_rows_mut::<4>(at + 3).copy_from_slice(&s);
                }
            }
        }
    }

    /// The model at `times` (increasing, ≥ 0): dop853 at [`RTOL`] over [0, last time], read at the times from its
    /// dense output. `Err` names the time and the reason a run failed.
    pub fn solve(&self, times: &[f64]) -> Result<Vec<Point>, String> {
        if self.columns.len() <= 6 {
            let y0 = self.initial_state::<{ state_len(6) }>();
            integrate_to(&mut Variational { model: self }, y0, 7, times)
        } else {
            let y0 = self.initial_state::<{ state_len(MAX_COLUMNS) }>();
            integrate_to(&mut Variational { model: self }, y0, 7, times)
        }
    }
}

/// Integrates `system` from `y0` over [0, the last time] by dop853 at [`RTOL`] and reads each time's [`Point`]
/// from the dense output; the state's first block (ω, q, …) and each parameter's block are `block` long.
pub(super) fn integrate_to<const N: usize, S: OdeSystem<N>>(
    system: &mut S,
    y0: SVector<f64, N>,
    block: usize,
    times: &[f64],
) -> Result<Vec<Point>, String> {
    let t_last = *times.last().expect("at least one time");
    let schedule = Schedule::new(t_last.max(f64::MIN_POSITIVE), t_last)
        .map_err(|e| format!("the model's schedule: {e}"))?;
    let settings = Settings {
        method: Method::Dop853,
        backend: Backend::Own,
        rtol: RTOL,
        atol: RTOL * 1e-2,
        ..Settings::default()
    };
    let mut watch = AtTimes {
        times,
        block,
        points: Vec::with_capacity(times.len()),
    };
    if times[0] == 0.0 {
        watch.points.push(point(&y0, block));
    }
    integrate::integrate_watched(
        system,
        y0,
        &schedule,
        &settings,
        |_, _| Ok::<(), std::convert::Infallible>(()),
        &mut watch,
    )
    .map_err(|e| e.to_string())?;
    if watch.points.len() != times.len() {
        return Err(format!(
            "the model reached {} of the {} measured times",
            watch.points.len(),
            times.len()
        ));
    }
    Ok(watch.points)
}

/// The model's point from the augmented state of blocks `block` long: ω and q from the first, ∂ω/∂p and ∂q/∂p
/// from the first seven entries of each parameter's.
fn point<const N: usize>(y: &State<N>, block: usize) -> Point {
    let omega_b = Vector3::new(y[0], y[1], y[2]);
    let q_raw = Quaternion::new(y[3], y[4], y[5], y[6]);
    let norm = q_raw.norm();
    let q = UnitQuaternion::new_unchecked(q_raw / norm);
    let conj = q.quaternion().conjugate();
    let mut d_omega = [Vector3::zeros(); MAX_COLUMNS];
    let mut d_attitude = [Vector3::zeros(); MAX_COLUMNS];
    for j in 0..(N / block - 1) {
        let at = block * (j + 1);
        d_omega[j] = Vector3::new(y[at], y[at + 1], y[at + 2]);
        let s_q = Quaternion::new(y[at + 3], y[at + 4], y[at + 5], y[at + 6]);
        d_attitude[j] = (conj * s_q).imag() * (2.0 / norm);
    }
    Point {
        omega_b,
        q,
        d_omega,
        d_attitude,
    }
}

/// Reads the dense output at the measured times inside each accepted step.
struct AtTimes<'a> {
    times: &'a [f64],
    block: usize,
    points: Vec<Point>,
}

impl<const N: usize> StepWatch<N> for AtTimes<'_> {
    fn step(&mut self, solution: &Dense<N>) -> Option<f64> {
        while let Some(&t) = self.times.get(self.points.len()) {
            if t > solution.t1() {
                break;
            }
            self.points.push(point(&solution.at(t), self.block));
        }
        None
    }
}

/// The state and its variational equations as one system.
struct Variational<'a> {
    model: &'a Model,
}

/// M at (t, q, ω) from `moments`, q normalised.
fn moment(
    moments: &EffectMoments,
    t: f64,
    q: &Quaternion<f64>,
    omega_b: &Vector3<f64>,
) -> Vector3<f64> {
    moments.moment_b(t, &UnitQuaternion::new_normalize(*q), omega_b)
}

impl<const N: usize> OdeSystem<N> for Variational<'_> {
    fn rhs(&mut self, t: f64, y: &State<N>) -> State<N> {
        let model = self.model;
        let inertia = model.body.inertia_b();
        let omega = Vector3::new(y[0], y[1], y[2]);
        let q_arr = [y[3], y[4], y[5], y[6]];
        let q = Quaternion::new(y[3], y[4], y[5], y[6]);
        let m_b = (model.moments.as_ref()).map(|m| moment(&m.at, t, &q, &omega));
        let omega_dot = *model.body.omega_dot_b(
            &crate::frames::Vector::new(omega),
            m_b.map(crate::frames::Vector::new).as_ref(),
        );
        let h = inertia * omega;
        let mut dy = State::<N>::zeros();
        dy.fixed_rows_mut::<3>(0).copy_from(&omega_dot);
        dy.fixed_rows_mut::<4>(3)
            .copy_from_slice(&quaternion_rate(&q_arr, &omega));
        let size = omega.norm() + 1.0;
        for (j, column) in model.columns.iter().enumerate() {
            let at = 7 * (j + 1);
            let s_omega = Vector3::new(y[at], y[at + 1], y[at + 2]);
            let s_q = Quaternion::new(y[at + 3], y[at + 4], y[at + 5], y[at + 6]);
            let mut rhs_b = -s_omega.cross(&h) - omega.cross(&(inertia * s_omega));
            if let Some(moments) = &model.moments {
                // Only along what the moment depends on: a body-axis torque of time alone costs nothing here.
                let (on_q, on_omega) = moments.at.depends_on_state();
                let s_q = if on_q { s_q } else { Quaternion::default() };
                let s_omega = if on_omega { s_omega } else { Vector3::zeros() };
                let reach = (s_omega.norm_squared() + s_q.norm_squared()).sqrt();
                if reach > 0.0 {
                    let e = STEP * size / reach;
                    let plus = moment(&moments.at, t, &(q + s_q * e), &(omega + s_omega * e));
                    let minus = moment(&moments.at, t, &(q - s_q * e), &(omega - s_omega * e));
                    rhs_b += (plus - minus) / (2.0 * e);
                }
                if let Some(Some((plus, minus, width))) = moments.across.get(j) {
                    rhs_b += (moment(plus, t, &q, &omega) - moment(minus, t, &q, &omega)) / *width;
                }
            }
            if let Column::Inertia(e) = column {
                rhs_b -= omega.cross(&(e * omega)) + e * omega_dot;
            }
            let s_omega_dot = model.body.inertia_inv_b() * rhs_b;
            dy.fixed_rows_mut::<3>(at).copy_from(&s_omega_dot);
            let s_q_arr = [s_q.w, s_q.i, s_q.j, s_q.k];
            let a = quaternion_rate(&s_q_arr, &omega);
            let b = quaternion_rate(&q_arr, &s_omega);
            for k in 0..4 {
                dy[at + 3 + k] = a[k] + b[k];
            }
        }
        dy
    }

    /// The moment's next corner (a tabulated moment's row).
    fn next_breakpoint(&self, t: f64) -> Option<f64> {
        (self.model.moments.as_ref()).and_then(|m| m.at.corner_after(t))
    }
}
