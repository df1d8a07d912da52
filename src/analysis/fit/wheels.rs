//! The model of a body with wheels (`[[body.rotor]]`): the gyrostat's own right-hand side in body axes — its
//! wheels' drives, friction, limits and law as in `run` —, state y = (ω_b, q, Ω_k, φ_k), beside its variational
//! equations ṡ = ∂f/∂y s + ∂f/∂p. There ∂f/∂y s is the central difference of f along s, each entry of y moved by
//! at most ε^(1/3) of its size, and ∂f/∂p for the inertia the central difference of the right-hand sides of the
//! scene built at I ± δE (the internal differentiation of Bock, 1981): the wheels' equations are differentiated
//! through the code that runs them, to ~1e-10, which a fit's Jacobian does not notice. Wheels whose Coulomb
//! friction sticks them make f not smooth there; the sensitivities are then those of one side.

use nalgebra::SVector;

use super::model::{MAX_COLUMNS, Model, Point, integrate_to};
use crate::effects::EffectMoments;
use crate::frames::{Form, Vector};
use crate::integrate::OdeSystem;
use crate::wheels::gyrostat::{self, Gyrostat, GyrostatForm};

/// The gyrostat's state length.
const BLOCK: usize = 15;
/// The relative step of the central differences.
const STEP: f64 = 6e-6;

/// A body with wheels and the moments on it, at one parameter point.
#[derive(Debug, Clone)]
pub struct GyrostatSystem {
    /// The body and its wheels.
    pub gyrostat: Gyrostat,
    /// The effects' moment.
    pub moments: EffectMoments,
}

/// The wheels' model at a parameter point, and across the inertia for each column that moves it.
#[derive(Debug, Clone)]
pub struct GyrostatModel {
    /// At the parameters.
    pub at: GyrostatSystem,
    /// (at I + δE_j, at I − δE_j, 2δ) for each column j that moves the inertia.
    pub across: Vec<Option<(GyrostatSystem, GyrostatSystem, f64)>>,
}

/// The body form of `system`'s equations.
fn form(system: &GyrostatSystem) -> GyrostatForm<'_, EffectMoments> {
    GyrostatForm {
        gyrostat: &system.gyrostat,
        moment: system.moments.clone(),
        form: Form::Body,
    }
}

impl GyrostatModel {
    /// The model at `times` with the start and columns of `model`.
    pub fn solve(&self, model: &Model, times: &[f64]) -> Result<Vec<Point>, String> {
        let mut system = Variational {
            at: form(&self.at),
            across: (self.across.iter())
                .map(|a| a.as_ref().map(|(p, m, w)| (form(p), form(m), *w)))
                .collect(),
            columns: model.columns.len(),
        };
        let base =
            (self.at.gyrostat).initial_state(Form::Body, &Vector::new(model.omega0_b), &model.q0);
        if model.columns.len() <= 6 {
            let y0 = initial::<{ BLOCK * 7 }>(&base, model);
            integrate_to(&mut system, y0, BLOCK, times)
        } else {
            let y0 = initial::<{ BLOCK * (1 + MAX_COLUMNS) }>(&base, model);
            integrate_to(&mut system, y0, BLOCK, times)
        }
    }
}

/// The augmented state at t = 0: the gyrostat's, then each column's ∂y₀/∂p ([`Model::seed`]).
fn initial<const N: usize>(base: &gyrostat::State, model: &Model) -> SVector<f64, N> {
    let mut y = SVector::<f64, N>::zeros();
    y.fixed_rows_mut::<BLOCK>(0).copy_from(base);
    model.seed(&mut y, BLOCK);
    y
}

/// A body form of the gyrostat's equations.
type Form15<'a> = GyrostatForm<'a, EffectMoments>;

/// The gyrostat's equations and their variational equations as one system.
struct Variational<'a> {
    at: Form15<'a>,
    /// (at I + δE_j, at I − δE_j, 2δ) per column.
    across: Vec<Option<(Form15<'a>, Form15<'a>, f64)>>,
    columns: usize,
}

impl<const N: usize> OdeSystem<N> for Variational<'_> {
    fn rhs(&mut self, t: f64, y: &SVector<f64, N>) -> SVector<f64, N> {
        let y0: gyrostat::State = y.fixed_rows::<BLOCK>(0).into_owned();
        let mut dy = SVector::<f64, N>::zeros();
        dy.fixed_rows_mut::<BLOCK>(0)
            .copy_from(&self.at.rhs(t, &y0));
        for j in 0..self.columns {
            let at = BLOCK * (j + 1);
            let s: gyrostat::State = y.fixed_rows::<BLOCK>(at).into_owned();
            let reach = (0..BLOCK)
                .map(|i| s[i].abs() / (y0[i].abs() + 1.0))
                .fold(0.0, f64::max);
            let mut ds = gyrostat::State::zeros();
            if reach > 0.0 {
                let e = STEP / reach;
                ds += (self.at.rhs(t, &(y0 + s * e)) - self.at.rhs(t, &(y0 - s * e))) / (2.0 * e);
            }
            if let Some(Some((plus, minus, width))) = self.across.get_mut(j) {
                ds += (plus.rhs(t, &y0) - minus.rhs(t, &y0)) / *width;
            }
            dy.fixed_rows_mut::<BLOCK>(at).copy_from(&ds);
        }
        dy
    }

    /// The wheels' tables' and the moment's next corner.
    fn next_breakpoint(&self, t: f64) -> Option<f64> {
        OdeSystem::<BLOCK>::next_breakpoint(&self.at, t)
    }
}

/// The inertia's ±δE step across which the wheels' right-hand side is differenced: δ = ε^(1/3) ‖I‖/‖E‖.
pub fn inertia_step(inertia: &nalgebra::Matrix3<f64>, e: &nalgebra::Matrix3<f64>) -> f64 {
    STEP * inertia.norm() / e.norm()
}
