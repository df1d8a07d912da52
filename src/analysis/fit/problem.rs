//! The least-squares problem: residuals and their Jacobian from the model's forward sensitivities, in the form
//! the Levenberg–Marquardt solver asks for (`levenberg_marquardt`, a port of MINPACK's `lmder`, Moré 1978).
//!
//! Per measured row: the gyro's residual (ω(t) + b − ω_meas)/σ_ω, and the attitude's as a turn in body axes,
//! φ = Log(q_meas⁻¹ ⊗ q(t))/σ_att, whose derivative along a turn δ of the model's attitude is J_r⁻¹(φ) δ (Solà,
//! Deray & Atchuthan 2018, eq. 144).

use std::cell::RefCell;

use levenberg_marquardt::LeastSquaresProblem;
use nalgebra::{DMatrix, DVector, Dyn, Owned, UnitQuaternion, Vector3};

use super::build::Builder;
use super::params::{Parameters, right_jacobian_inverse};

/// The measured rows: times, and the gyro's ω and the attitude where given.
#[derive(Debug, Clone, Default)]
pub struct Data {
    /// Times (s), increasing.
    pub times: Vec<f64>,
    /// The gyro's ω, body axes (rad/s).
    pub omega_b: Vec<Option<Vector3<f64>>>,
    /// The attitude, body → space.
    pub q: Vec<Option<UnitQuaternion<f64>>>,
}

impl Data {
    /// Each block of three residuals in order: (the data row, the channel — 0 the gyro, 1 the attitude —, the
    /// index of its first residual).
    pub fn blocks(&self) -> impl Iterator<Item = (usize, usize, usize)> + '_ {
        let given = (0..self.times.len()).flat_map(move |i| {
            [
                (i, 0, self.omega_b[i].is_some()),
                (i, 1, self.q[i].is_some()),
            ]
        });
        (given.filter(|b| b.2).enumerate()).map(|(k, (i, c, _))| (i, c, 3 * k))
    }

    /// The first `rows` rows.
    pub fn prefix(&self, rows: usize) -> Self {
        Self {
            times: self.times[..rows].to_vec(),
            omega_b: self.omega_b[..rows].to_vec(),
            q: self.q[..rows].to_vec(),
        }
    }

    /// The number of rows with a gyro reading, and with an attitude.
    pub fn counts(&self) -> (usize, usize) {
        (
            self.omega_b.iter().flatten().count(),
            self.q.iter().flatten().count(),
        )
    }
}

/// The σ each channel's residuals are divided by: the gyro's (rad/s) and the attitude's (rad).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Sigmas {
    /// The gyro's.
    pub omega: f64,
    /// The attitude's.
    pub attitude: f64,
}

impl Sigmas {
    /// The σ of channel `c` (0 the gyro, 1 the attitude).
    pub fn of(&self, c: usize) -> f64 {
        [self.omega, self.attitude][c]
    }
}

/// Residuals and Jacobian at one x.
#[derive(Debug, Clone)]
pub struct Evaluation {
    /// The weighted residuals, row by row: the gyro's three, then the attitude's three.
    pub residuals: DVector<f64>,
    /// Their derivatives in x.
    pub jacobian: DMatrix<f64>,
}

impl Evaluation {
    /// The same evaluation weighed with `to` instead of `from`: each channel's rows scaled by σ_from/σ_to.
    pub fn reweighted(&self, data: &Data, from: Sigmas, to: Sigmas) -> Self {
        let mut out = self.clone();
        for (_, c, at) in data.blocks() {
            let scale = from.of(c) / to.of(c);
            out.residuals.rows_mut(at, 3).scale_mut(scale);
            out.jacobian.rows_mut(at, 3).scale_mut(scale);
        }
        out
    }
}

/// Log(q) as a turn (rad, body axes): 2 atan2(|v|, w) v/|v| with w ≥ 0, accurate for small turns (an arccos of
/// w is not).
pub fn turn_of(q: &UnitQuaternion<f64>) -> Vector3<f64> {
    let (w, v) = if q.w < 0.0 {
        (-q.w, -q.imag())
    } else {
        (q.w, q.imag())
    };
    let s = v.norm();
    if s < 1e-300 {
        return v * 2.0;
    }
    v * (2.0 * s.atan2(w) / s)
}

/// The residuals and Jacobian of `params` at x against `data` with `sigmas`; `Err`: x is not a body, or the
/// model's run failed (the reason).
pub fn evaluate(
    builder: &Builder,
    params: &Parameters,
    data: &Data,
    sigmas: Sigmas,
    x: &DVector<f64>,
) -> Result<Evaluation, String> {
    let model = builder.model(params, x)?;
    let points = model.solve(&data.times)?;
    let (_, column_of) = params.columns(x);
    let bias = params.bias(x);
    let bias_at: Vec<Option<usize>> = (0..3).map(|k| params.bias_index(k)).collect();
    let (gyro, attitude) = data.counts();
    let m = 3 * (gyro + attitude);
    let mut residuals = DVector::zeros(m);
    let mut jacobian = DMatrix::zeros(m, params.len());
    let mut row = 0;
    for (i, point) in points.iter().enumerate() {
        if let Some(measured) = data.omega_b[i] {
            let r = (point.omega_b + bias - measured) / sigmas.omega;
            residuals.fixed_rows_mut::<3>(row).copy_from(&r);
            for (c, column) in column_of.iter().enumerate() {
                if let Some(j) = column {
                    let d = point.d_omega[*j] / sigmas.omega;
                    jacobian.fixed_view_mut::<3, 1>(row, c).copy_from(&d);
                }
            }
            for (k, at) in bias_at.iter().enumerate() {
                if let Some(c) = at {
                    jacobian[(row + k, *c)] = 1.0 / sigmas.omega;
                }
            }
            row += 3;
        }
        if let Some(measured) = data.q[i] {
            let phi = turn_of(&(measured.inverse() * point.q));
            residuals
                .fixed_rows_mut::<3>(row)
                .copy_from(&(phi / sigmas.attitude));
            let j_inv = right_jacobian_inverse(&phi);
            for (c, column) in column_of.iter().enumerate() {
                if let Some(j) = column {
                    let d = j_inv * point.d_attitude[*j] / sigmas.attitude;
                    jacobian.fixed_view_mut::<3, 1>(row, c).copy_from(&d);
                }
            }
            row += 3;
        }
    }
    Ok(Evaluation {
        residuals,
        jacobian,
    })
}

/// An evaluation and the x it was made at.
type Cached = (DVector<f64>, Result<Evaluation, String>);

/// The problem as the solver sees it. A trial x that is not a body (or whose run fails) gets residuals of
/// `penalty` each, far above the start's, so that the solver rejects the step and shortens it.
pub struct Problem<'a> {
    builder: &'a Builder,
    params: &'a Parameters,
    data: &'a Data,
    sigmas: Sigmas,
    x: DVector<f64>,
    penalty: f64,
    /// The last evaluation, at its x: the solver asks for the residuals, then for the Jacobian at the same x.
    cache: RefCell<Option<Cached>>,
    /// Jacobians asked for: the solver's iterations.
    jacobians: std::cell::Cell<usize>,
}

impl<'a> Problem<'a> {
    /// The problem from `x0`, whose evaluation `start` is.
    pub fn new(
        builder: &'a Builder,
        params: &'a Parameters,
        data: &'a Data,
        sigmas: Sigmas,
        x0: DVector<f64>,
        start: &Evaluation,
    ) -> Self {
        let m = start.residuals.len().max(1) as f64;
        Self {
            builder,
            params,
            data,
            sigmas,
            penalty: 1e3 * (start.residuals.norm() + 1.0) / m.sqrt(),
            cache: RefCell::new(Some((x0.clone(), Ok(start.clone())))),
            x: x0,
            jacobians: std::cell::Cell::new(0),
        }
    }

    /// The evaluation at the current x.
    pub fn evaluation(&self) -> Result<Evaluation, String> {
        let mut cache = self.cache.borrow_mut();
        match &*cache {
            Some((x, e)) if *x == self.x => e.clone(),
            _ => {
                let e = evaluate(self.builder, self.params, self.data, self.sigmas, &self.x);
                *cache = Some((self.x.clone(), e.clone()));
                e
            }
        }
    }

    /// The current x.
    pub fn x(&self) -> &DVector<f64> {
        &self.x
    }

    /// The Jacobians the solver asked for: its iterations.
    pub fn jacobians(&self) -> usize {
        self.jacobians.get()
    }
}

impl LeastSquaresProblem<f64, Dyn, Dyn> for Problem<'_> {
    type ResidualStorage = Owned<f64, Dyn>;
    type JacobianStorage = Owned<f64, Dyn, Dyn>;
    type ParameterStorage = Owned<f64, Dyn>;

    fn set_params(&mut self, x: &DVector<f64>) {
        self.x.copy_from(x);
    }

    fn params(&self) -> DVector<f64> {
        self.x.clone()
    }

    fn residuals(&self) -> Option<DVector<f64>> {
        let (gyro, attitude) = self.data.counts();
        Some(match self.evaluation() {
            Ok(e) => e.residuals,
            Err(_) => DVector::from_element(3 * (gyro + attitude), self.penalty),
        })
    }

    fn jacobian(&self) -> Option<DMatrix<f64>> {
        self.jacobians.set(self.jacobians.get() + 1);
        self.evaluation().ok().map(|e| e.jacobian)
    }
}
