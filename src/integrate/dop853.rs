//! Own Dormand–Prince 8(5,3) pair (DOP853).
//!
//! Coefficients and error estimator copied from Hairer's `dop853.f` (HNW I, §II.5;
//! Prince & Dormand 1981). Twelve stages; stage 12 is evaluated at the
//! node c12 = 1, i.e. at t + h (`XPH` in `dop853.f`; ode_solvers 0.6.2 wrongly tabulates
//! c12 = c13 = 0, which is invisible for autonomous systems only). After acceptance the
//! derivative at the new point is evaluated once more and reused as k1 (FSAL): 11 evaluations
//! per attempt plus 1 per accepted step.
//!
//! Error (DP86CO): with ŷ − y = h·Σ b_j k_j and sc_i = atol + rtol·max(|y_i|, |ŷ_i|),
//! err5 = Σ_i (Σ_j er_j k_{j,i} / sc_i)², err3 = Σ_i ((Σ_j b_j k_{j,i} − bhh1 k1 − bhh2 k9 −
//! bhh3 k12)_i / sc_i)², err = |h|·err5 / sqrt(N·(err5 + 0.01·err3)), returned as err².

#![allow(clippy::excessive_precision)]

use nalgebra::SVector;

use super::OdeSystem;
use super::adaptive::{EmbeddedPair, Tol, Trial, scaled_sum_sq, stage_arg, weighted_sum};

const C2: f64 = 0.526001519587677318785587544488E-01;
const C3: f64 = 0.789002279381515978178381316732E-01;
const C4: f64 = 0.118350341907227396726757197510E+00;
const C5: f64 = 0.281649658092772603273242802490E+00;
const C6: f64 = 0.333333333333333333333333333333E+00;
const C7: f64 = 0.25E+00;
const C8: f64 = 0.307692307692307692307692307692E+00;
const C9: f64 = 0.651282051282051282051282051282E+00;
const C10: f64 = 0.6E+00;
const C11: f64 = 0.857142857142857142857142857142E+00;
/// Node of stage 12: t + h (`XPH` in `dop853.f`).
pub(crate) const C12: f64 = 1.0;

const B1: f64 = 5.42937341165687622380535766363E-2;
const B6: f64 = 4.45031289275240888144113950566E0;
const B7: f64 = 1.89151789931450038304281599044E0;
const B8: f64 = -5.8012039600105847814672114227E0;
const B9: f64 = 3.1116436695781989440891606237E-1;
const B10: f64 = -1.52160949662516078556178806805E-1;
const B11: f64 = 2.01365400804030348374776537501E-1;
const B12: f64 = 4.47106157277725905176885569043E-2;

const BHH1: f64 = 0.244094488188976377952755905512E+00;
const BHH2: f64 = 0.733846688281611857341361741547E+00;
const BHH3: f64 = 0.220588235294117647058823529412E-01;

const ER1: f64 = 0.1312004499419488073250102996E-01;
const ER6: f64 = -0.1225156446376204440720569753E+01;
const ER7: f64 = -0.4957589496572501915214079952E+00;
const ER8: f64 = 0.1664377182454986536961530415E+01;
const ER9: f64 = -0.3503288487499736816886487290E+00;
const ER10: f64 = 0.3341791187130174790297318841E+00;
const ER11: f64 = 0.8192320648511571246570742613E-01;
const ER12: f64 = -0.2235530786388629525884427845E-01;

const A21: f64 = 5.26001519587677318785587544488E-2;
const A31: f64 = 1.97250569845378994544595329183E-2;
const A32: f64 = 5.91751709536136983633785987549E-2;
const A41: f64 = 2.95875854768068491816892993775E-2;
const A43: f64 = 8.87627564304205475450678981324E-2;
const A51: f64 = 2.41365134159266685502369798665E-1;
const A53: f64 = -8.84549479328286085344864962717E-1;
const A54: f64 = 9.24834003261792003115737966543E-1;
const A61: f64 = 3.7037037037037037037037037037E-2;
const A64: f64 = 1.70828608729473871279604482173E-1;
const A65: f64 = 1.25467687566822425016691814123E-1;
const A71: f64 = 3.7109375E-2;
const A74: f64 = 1.70252211019544039314978060272E-1;
const A75: f64 = 6.02165389804559606850219397283E-2;
const A76: f64 = -1.7578125E-2;
const A81: f64 = 3.70920001185047927108779319836E-2;
const A84: f64 = 1.70383925712239993810214054705E-1;
const A85: f64 = 1.07262030446373284651809199168E-1;
const A86: f64 = -1.53194377486244017527936158236E-2;
const A87: f64 = 8.27378916381402288758473766002E-3;
const A91: f64 = 6.24110958716075717114429577812E-1;
const A94: f64 = -3.36089262944694129406857109825E0;
const A95: f64 = -8.68219346841726006818189891453E-1;
const A96: f64 = 2.75920996994467083049415600797E1;
const A97: f64 = 2.01540675504778934086186788979E1;
const A98: f64 = -4.34898841810699588477366255144E1;
const A101: f64 = 4.77662536438264365890433908527E-1;
const A104: f64 = -2.48811461997166764192642586468E0;
const A105: f64 = -5.90290826836842996371446475743E-1;
const A106: f64 = 2.12300514481811942347288949897E1;
const A107: f64 = 1.52792336328824235832596922938E1;
const A108: f64 = -3.32882109689848629194453265587E1;
const A109: f64 = -2.03312017085086261358222928593E-2;
const A111: f64 = -9.3714243008598732571704021658E-1;
const A114: f64 = 5.18637242884406370830023853209E0;
const A115: f64 = 1.09143734899672957818500254654E0;
const A116: f64 = -8.14978701074692612513997267357E0;
const A117: f64 = -1.85200656599969598641566180701E1;
const A118: f64 = 2.27394870993505042818970056734E1;
const A119: f64 = 2.49360555267965238987089396762E0;
const A1110: f64 = -3.0467644718982195003823669022E0;
const A121: f64 = 2.27331014751653820792359768449E0;
const A124: f64 = -1.05344954667372501984066689879E1;
const A125: f64 = -2.00087205822486249909675718444E0;
const A126: f64 = -1.79589318631187989172765950534E1;
const A127: f64 = 2.79488845294199600508499808837E1;
const A128: f64 = -2.85899827713502369474065508674E0;
const A129: f64 = -8.87285693353062954433549289258E0;
const A1210: f64 = 1.23605671757943030647266201528E1;
const A1211: f64 = 6.43392746015763530355970484046E-1;

/// DOP853 marker type; controller parameters of `dop853.f` (β = 0, EXPO1 = 1/8,
/// 1/3 ≤ h_new/h ≤ 6 with FAC1 = 0.333, safety 0.9).
pub(crate) struct Dop853;

impl EmbeddedPair for Dop853 {
    const HINIT_ORDER: f64 = 8.0;
    const EXPO1: f64 = 1.0 / 8.0;
    const BETA: f64 = 0.0;
    const FAC_MIN: f64 = 0.333;
    const FAC_MAX: f64 = 6.0;
    const STAGE_EVALS: u64 = 11;

    /// SAFE/err^(1/8) = SAFE·(1/err²)^(1/16), four square roots and one division instead of a
    /// power and two divisions (β = 0: FACOLD does not enter). err = 0 gives +∞.
    #[inline]
    fn step_ratio(err_sq: f64, _ln_fac_old: f64) -> f64 {
        Self::SAFE * (1.0 / err_sq).sqrt().sqrt().sqrt().sqrt()
    }

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
        let k4 = sys.rhs(t + C4 * h, &stage_arg(y, [(A41 * h, k1), (A43 * h, &k3)]));
        let k5 = sys.rhs(
            t + C5 * h,
            &stage_arg(y, [(A51 * h, k1), (A53 * h, &k3), (A54 * h, &k4)]),
        );
        let k6 = sys.rhs(
            t + C6 * h,
            &stage_arg(y, [(A61 * h, k1), (A64 * h, &k4), (A65 * h, &k5)]),
        );
        let k7 = sys.rhs(
            t + C7 * h,
            &stage_arg(
                y,
                [
                    (A71 * h, k1),
                    (A74 * h, &k4),
                    (A75 * h, &k5),
                    (A76 * h, &k6),
                ],
            ),
        );
        let k8 = sys.rhs(
            t + C8 * h,
            &stage_arg(
                y,
                [
                    (A81 * h, k1),
                    (A84 * h, &k4),
                    (A85 * h, &k5),
                    (A86 * h, &k6),
                    (A87 * h, &k7),
                ],
            ),
        );
        let k9 = sys.rhs(
            t + C9 * h,
            &stage_arg(
                y,
                [
                    (A91 * h, k1),
                    (A94 * h, &k4),
                    (A95 * h, &k5),
                    (A96 * h, &k6),
                    (A97 * h, &k7),
                    (A98 * h, &k8),
                ],
            ),
        );
        let k10 = sys.rhs(
            t + C10 * h,
            &stage_arg(
                y,
                [
                    (A101 * h, k1),
                    (A104 * h, &k4),
                    (A105 * h, &k5),
                    (A106 * h, &k6),
                    (A107 * h, &k7),
                    (A108 * h, &k8),
                    (A109 * h, &k9),
                ],
            ),
        );
        let k11 = sys.rhs(
            t + C11 * h,
            &stage_arg(
                y,
                [
                    (A111 * h, k1),
                    (A114 * h, &k4),
                    (A115 * h, &k5),
                    (A116 * h, &k6),
                    (A117 * h, &k7),
                    (A118 * h, &k8),
                    (A119 * h, &k9),
                    (A1110 * h, &k10),
                ],
            ),
        );
        let k12 = sys.rhs(
            t + C12 * h,
            &stage_arg(
                y,
                [
                    (A121 * h, k1),
                    (A124 * h, &k4),
                    (A125 * h, &k5),
                    (A126 * h, &k6),
                    (A127 * h, &k7),
                    (A128 * h, &k8),
                    (A129 * h, &k9),
                    (A1210 * h, &k10),
                    (A1211 * h, &k11),
                ],
            ),
        );
        // Σ b_j k_j (unscaled: the error estimators below use it), then y₁ = y + h·Σ b_j k_j
        // with y added last, as in `dop853.f`.
        let slope = weighted_sum([
            (B1, k1),
            (B6, &k6),
            (B7, &k7),
            (B8, &k8),
            (B9, &k9),
            (B10, &k10),
            (B11, &k11),
            (B12, &k12),
        ]);
        let y_new = y + slope * h;

        let sk_inv = tol.inverse_scales(y, &y_new);
        let e3 = weighted_sum([(1.0, &slope), (-BHH1, k1), (-BHH2, &k9), (-BHH3, &k12)]);
        let e5 = weighted_sum([
            (ER1, k1),
            (ER6, &k6),
            (ER7, &k7),
            (ER8, &k8),
            (ER9, &k9),
            (ER10, &k10),
            (ER11, &k11),
            (ER12, &k12),
        ]);
        let err3 = scaled_sum_sq(&e3, &sk_inv);
        let err5 = scaled_sum_sq(&e5, &sk_inv);
        let mut deno = err5 + 0.01 * err3;
        if deno <= 0.0 {
            deno = 1.0;
        }
        // err² = h²·err5² / (N·deno).
        let err_sq = (h * err5) * (h * err5) / (N as f64 * deno);
        Trial {
            y_new,
            err_sq,
            f_new: None,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Rows of A (stage i uses k1..k_{i−1}) with the nodes c_i.
    fn tableau() -> Vec<(f64, Vec<f64>)> {
        vec![
            (0.0, vec![]),
            (C2, vec![A21]),
            (C3, vec![A31, A32]),
            (C4, vec![A41, 0.0, A43]),
            (C5, vec![A51, 0.0, A53, A54]),
            (C6, vec![A61, 0.0, 0.0, A64, A65]),
            (C7, vec![A71, 0.0, 0.0, A74, A75, A76]),
            (C8, vec![A81, 0.0, 0.0, A84, A85, A86, A87]),
            (C9, vec![A91, 0.0, 0.0, A94, A95, A96, A97, A98]),
            (
                C10,
                vec![A101, 0.0, 0.0, A104, A105, A106, A107, A108, A109],
            ),
            (
                C11,
                vec![A111, 0.0, 0.0, A114, A115, A116, A117, A118, A119, A1110],
            ),
            (
                C12,
                vec![
                    A121, 0.0, 0.0, A124, A125, A126, A127, A128, A129, A1210, A1211,
                ],
            ),
        ]
    }

    const B: [f64; 12] = [B1, 0.0, 0.0, 0.0, 0.0, B6, B7, B8, B9, B10, B11, B12];

    #[test]
    fn row_sums_are_nodes_and_c12_is_one() {
        // c_i = Σ_j a_ij; in particular the last row sums to 1, so stage 12 sits at t + h.
        for (i, (c, row)) in tableau().iter().enumerate() {
            let s: f64 = row.iter().sum();
            assert!((s - c).abs() < 1e-13, "stage {}: Σa = {s}, c = {c}", i + 1);
        }
        let last: f64 = tableau()[11].1.iter().sum();
        assert!((last - 1.0).abs() < 1e-13);
    }

    #[test]
    fn quadrature_conditions_order_8() {
        let t = tableau();
        for q in 1..=8 {
            let s: f64 = (0..12).map(|i| B[i] * t[i].0.powi(q - 1)).sum();
            assert!((s - 1.0 / q as f64).abs() < 1e-13, "q = {q}: {s}");
        }
    }

    #[test]
    fn stage_order_condition() {
        // Σ_i b_i Σ_j a_ij c_j = 1/6 (the tree [[τ]]) — catches a misplaced A entry.
        let t = tableau();
        let s: f64 = (0..12)
            .map(|i| {
                let inner: f64 = t[i].1.iter().enumerate().map(|(j, a)| a * t[j].0).sum();
                B[i] * inner
            })
            .sum();
        assert!((s - 1.0 / 6.0).abs() < 1e-13, "{s}");
    }

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

    #[test]
    fn error_weights_annihilate_constants() {
        let er = [ER1, ER6, ER7, ER8, ER9, ER10, ER11, ER12];
        assert!(er.iter().sum::<f64>().abs() < 1e-13);
        assert!((BHH1 + BHH2 + BHH3 - 1.0).abs() < 1e-15);
    }
}
