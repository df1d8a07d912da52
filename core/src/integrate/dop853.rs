//! DOP853, the Dormand–Prince 8(5,3) pair (tableau: [`super::tableau::DOP853`], HNW I §II.5, Hairer's
//! `dop853.f`). After acceptance the driver evaluates f(t + h, y₁) once more and reuses it as k1: 11 evaluations
//! per attempt plus 1 per accepted step.
//!
//! Error (DP86CO of `dop853.f`): with sc_i = atol + rtol·max(|y_i|, |y₁_i|),
//! err5 = Σ_i (Σ_j er_j k_{j,i} / sc_i)², err3 = Σ_i ((Σ_j b_j k_{j,i} − Σ_j bhh_j k_{j,i}) / sc_i)²,
//! err = |h|·err5 / sqrt(N·(err5 + 0.01·err3)), returned as err².

use nalgebra::SVector;

use super::OdeSystem;
use super::adaptive::{ControllerParams, EmbeddedPair, Tol, scaled_sum_sq};
use super::dense::{self, Dense, StepEnds};
use super::explicit_rk::{RkStep, combine_onto, weighted_sum};
use super::tableau::{ButcherTableau, DOP853, DOP853_ERROR3, DOP853_ERROR5};

/// DOP853 marker type; controller parameters of `dop853.f` (β = 0, EXPO1 = 1/8,
/// 1/3 ≤ h_new/h ≤ 6 with FAC1 = 0.333, safety 0.9).
pub(crate) struct Dop853;

impl ControllerParams for Dop853 {
    const HINIT_ORDER: f64 = 8.0;
    const EXPO1: f64 = 1.0 / 8.0;
    const BETA: f64 = 0.0;
    const FAC_MIN: f64 = 0.333;
    const FAC_MAX: f64 = 6.0;

    /// SAFE/err^(1/8) = SAFE·(1/err²)^(1/16), four square roots and one division instead of a
    /// power and two divisions (β = 0: FACOLD does not enter). err = 0 gives +∞.
    #[inline]
    fn step_ratio(err_sq: f64, _ln_fac_old: f64) -> f64 {
        Self::SAFE * (1.0 / err_sq).sqrt().sqrt().sqrt().sqrt()
    }
}

impl EmbeddedPair<12> for Dop853 {
    const TABLEAU: &'static ButcherTableau<12> = &DOP853;

    #[inline(always)]
    fn error_sq<const N: usize>(
        step: &RkStep<N, 12>,
        y: &SVector<f64, N>,
        h: f64,
        tol: Tol,
    ) -> f64 {
        let sk_inv = tol.inverse_scales(y, &step.y_new);
        // The slope Σ_j b_j k_j minus the 3rd-order one.
        let e3 = combine_onto(&step.weighted, &DOP853_ERROR3, -1.0, &step.k, 12);
        let e5 = weighted_sum(&DOP853_ERROR5, 1.0, &step.k);
        let err3 = scaled_sum_sq(&e3, &sk_inv);
        let err5 = scaled_sum_sq(&e5, &sk_inv);
        let mut deno = err5 + 0.01 * err3;
        if deno <= 0.0 {
            deno = 1.0;
        }
        // err² = h²·err5² / (N·deno).
        (h * err5) * (h * err5) / (N as f64 * deno)
    }

    fn dense<const N: usize, Sys: OdeSystem<N>>(
        sys: &mut Sys,
        ends: &StepEnds<'_, N, 12>,
    ) -> (Dense<N>, u64) {
        dense::dop853(sys, ends)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn step_ratio_is_safe_over_the_eighth_root() {
        // SAFE·(1/err²)^(1/16) = SAFE/err^(1/8) to 4 ulps (a division and four correctly
        // rounded square roots, each halving the relative error it inherits), and 0 ↦ +∞.
        for err in [1e-150, 1e-20, 3.3e-7, 0.01, 0.999, 1.0, 4.0, 1e10] {
            let fast = Dop853::step_ratio(err * err, 0.0);
            let hairer = Dop853::SAFE / err.powf(Dop853::EXPO1);
            assert!(
                (fast - hairer).abs() <= 4.0 * f64::EPSILON * hairer,
                "err {err:e}: {fast:e} vs {hairer:e}"
            );
        }
        assert_eq!(Dop853::step_ratio(0.0, 0.0), f64::INFINITY);
    }
}
