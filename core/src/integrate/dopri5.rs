//! DOPRI5, the Dormand–Prince 5(4) pair with FSAL (tableau: [`super::tableau::DOPRI5`], HNW I §II.5, Table 5.2,
//! Hairer's `dopri5.f`).
//!
//! Error (HNW I eq. (4.11)): err_i = h·Σ_j e_j k_j with e = b − b̂, sc_i = atol + rtol·max(|y_i|, |y₁_i|),
//! err = sqrt(mean((err_i/sc_i)²)), returned as err² (the controller needs no square root).

use nalgebra::SVector;

use super::OdeSystem;
use super::adaptive::{ControllerParams, EmbeddedPair, Tol, scaled_sum_sq};
use super::dense::{self, Dense, StepEnds};
use super::explicit_rk::{RkStep, weighted_sum};
use super::tableau::{ButcherTableau, DOPRI5, DOPRI5_ERROR};

/// DOPRI5 marker type; controller parameters of `dopri5.f` (β = 0.04, EXPO1 = 0.2 − 0.75β,
/// 0.2 ≤ h_new/h ≤ 10, safety 0.9).
pub(crate) struct Dopri5;

impl ControllerParams for Dopri5 {
    const HINIT_ORDER: f64 = 5.0;
    const EXPO1: f64 = 0.2 - 0.04 * 0.75;
    const BETA: f64 = 0.04;
    const FAC_MIN: f64 = 0.2;
    const FAC_MAX: f64 = 10.0;
}

impl EmbeddedPair<7> for Dopri5 {
    const TABLEAU: &'static ButcherTableau<7> = &DOPRI5;

    #[inline(always)]
    fn error_sq<const N: usize>(step: &RkStep<N, 7>, y: &SVector<f64, N>, h: f64, tol: Tol) -> f64 {
        let e = weighted_sum(&DOPRI5_ERROR, h, &step.k);
        let sk_inv = tol.inverse_scales(y, &step.y_new);
        scaled_sum_sq(&e, &sk_inv) * (1.0 / N as f64)
    }

    fn dense<const N: usize, Sys: OdeSystem<N>>(
        _sys: &mut Sys,
        ends: &StepEnds<'_, N, 7>,
    ) -> (Dense<N>, u64) {
        (dense::dopri5(ends), 0)
    }
}
