//! Own Dormand–Prince 5(4) pair (DOPRI5) with FSAL.
//!
//! Coefficients: HNW I, §II.5, Table 5.2 (Dormand & Prince 1980), as in Hairer's `dopri5.f`.
//! The 7th stage is f(t + h, y₁) (a7j = b_j), reused as k1 of the next step (FSAL), so a step
//! costs 6 evaluations. Error: err_i = h·Σ e_j k_j with e = b − b̂ (E1..E7 of `dopri5.f`),
//! err = sqrt(mean((err_i/sc_i)²)), sc_i = atol + rtol·max(|y_i|, |y₁_i|) (HNW I eq. (4.11)),
//! returned as err² (the controller needs no square root).

use nalgebra::SVector;

use super::OdeSystem;
use super::adaptive::{EmbeddedPair, Tol, Trial, scaled_sum_sq, stage_arg, weighted_sum};

const C2: f64 = 1.0 / 5.0;
const C3: f64 = 3.0 / 10.0;
const C4: f64 = 4.0 / 5.0;
const C5: f64 = 8.0 / 9.0;

const A21: f64 = 1.0 / 5.0;
const A31: f64 = 3.0 / 40.0;
const A32: f64 = 9.0 / 40.0;
const A41: f64 = 44.0 / 45.0;
const A42: f64 = -56.0 / 15.0;
const A43: f64 = 32.0 / 9.0;
const A51: f64 = 19372.0 / 6561.0;
const A52: f64 = -25360.0 / 2187.0;
const A53: f64 = 64448.0 / 6561.0;
const A54: f64 = -212.0 / 729.0;
const A61: f64 = 9017.0 / 3168.0;
const A62: f64 = -355.0 / 33.0;
const A63: f64 = 46732.0 / 5247.0;
const A64: f64 = 49.0 / 176.0;
const A65: f64 = -5103.0 / 18656.0;
// a7j = b_j (5th-order weights); b2 = 0.
const A71: f64 = 35.0 / 384.0;
const A73: f64 = 500.0 / 1113.0;
const A74: f64 = 125.0 / 192.0;
const A75: f64 = -2187.0 / 6784.0;
const A76: f64 = 11.0 / 84.0;

const E1: f64 = 71.0 / 57600.0;
const E3: f64 = -71.0 / 16695.0;
const E4: f64 = 71.0 / 1920.0;
const E5: f64 = -17253.0 / 339200.0;
const E6: f64 = 22.0 / 525.0;
const E7: f64 = -1.0 / 40.0;

/// DOPRI5 marker type; controller parameters of `dopri5.f` (β = 0.04, EXPO1 = 0.2 − 0.75β,
/// 0.2 ≤ h_new/h ≤ 10, safety 0.9).
pub(crate) struct Dopri5;

impl EmbeddedPair for Dopri5 {
    const HINIT_ORDER: f64 = 5.0;
    const EXPO1: f64 = 0.2 - 0.04 * 0.75;
    const BETA: f64 = 0.04;
    const FAC_MIN: f64 = 0.2;
    const FAC_MAX: f64 = 10.0;
    const STAGE_EVALS: u64 = 6;

    // Always inlined into the driver: where several systems instantiate it (the library behind the CLI), the
    // compiler otherwise keeps it out of line, returning the trial through memory, and a step costs up to ~1.2 × as
    // much (`cargo bench --bench methods`).
    #[inline(always)]
    fn attempt<const N: usize, S: OdeSystem<N>>(
        sys: &mut S,
        t: f64,
        y: &SVector<f64, N>,
        k1: &SVector<f64, N>,
        h: f64,
        tol: Tol,
    ) -> Trial<N> {
        let k2 = sys.rhs(t + C2 * h, &stage_arg(y, [(A21 * h, k1)]));
        let k3 = sys.rhs(t + C3 * h, &stage_arg(y, [(A31 * h, k1), (A32 * h, &k2)]));
        let k4 = sys.rhs(
            t + C4 * h,
            &stage_arg(y, [(A41 * h, k1), (A42 * h, &k2), (A43 * h, &k3)]),
        );
        let k5 = sys.rhs(
            t + C5 * h,
            &stage_arg(
                y,
                [
                    (A51 * h, k1),
                    (A52 * h, &k2),
                    (A53 * h, &k3),
                    (A54 * h, &k4),
                ],
            ),
        );
        let t_new = t + h;
        let k6 = sys.rhs(
            t_new,
            &stage_arg(
                y,
                [
                    (A61 * h, k1),
                    (A62 * h, &k2),
                    (A63 * h, &k3),
                    (A64 * h, &k4),
                    (A65 * h, &k5),
                ],
            ),
        );
        // y₁ = y + h·Σ b_j k_j: the increment is summed first and added to y last, as in
        // `dopri5.f`, so y₁ carries one rounding at the scale of y.
        let y_new = y + weighted_sum([
            (A71 * h, k1),
            (A73 * h, &k3),
            (A74 * h, &k4),
            (A75 * h, &k5),
            (A76 * h, &k6),
        ]);
        let k7 = sys.rhs(t_new, &y_new);
        let e = weighted_sum([
            (E1 * h, k1),
            (E3 * h, &k3),
            (E4 * h, &k4),
            (E5 * h, &k5),
            (E6 * h, &k6),
            (E7 * h, &k7),
        ]);
        let sk_inv = tol.inverse_scales(y, &y_new);
        Trial {
            y_new,
            err_sq: scaled_sum_sq(&e, &sk_inv) * (1.0 / N as f64),
            f_new: Some(k7),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    const A: [[f64; 6]; 7] = [
        [0.0; 6],
        [A21, 0.0, 0.0, 0.0, 0.0, 0.0],
        [A31, A32, 0.0, 0.0, 0.0, 0.0],
        [A41, A42, A43, 0.0, 0.0, 0.0],
        [A51, A52, A53, A54, 0.0, 0.0],
        [A61, A62, A63, A64, A65, 0.0],
        [A71, 0.0, A73, A74, A75, A76],
    ];
    const C: [f64; 7] = [0.0, C2, C3, C4, C5, 1.0, 1.0];
    const B: [f64; 7] = [A71, 0.0, A73, A74, A75, A76, 0.0];
    const E: [f64; 7] = [E1, 0.0, E3, E4, E5, E6, E7];

    #[test]
    fn row_sums_are_nodes() {
        for i in 1..7 {
            let s: f64 = A[i].iter().sum();
            assert!((s - C[i]).abs() < 1e-15, "row {i}: {s} vs {}", C[i]);
        }
    }

    #[test]
    fn quadrature_conditions_order_5() {
        // Σ b_i c_i^(q−1) = 1/q for q = 1..5 (bushy-tree order conditions).
        for q in 1..=5 {
            let s: f64 = (0..7).map(|i| B[i] * C[i].powi(q - 1)).sum();
            assert!((s - 1.0 / q as f64).abs() < 1e-15, "q = {q}: {s}");
        }
        // The embedded 4th-order weights b̂ = b − e satisfy them to q = 4 but not 5.
        for q in 1..=4 {
            let s: f64 = (0..7).map(|i| (B[i] - E[i]) * C[i].powi(q - 1)).sum();
            assert!((s - 1.0 / q as f64).abs() < 1e-15, "q = {q}: {s}");
        }
        assert!(E.iter().sum::<f64>().abs() < 1e-17);
    }
}
