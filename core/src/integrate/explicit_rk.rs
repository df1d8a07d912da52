//! One step of an explicit Runge–Kutta method given by its [`ButcherTableau`] (HNW I §II.1, eq. (1.8)):
//!
//! ```text
//!   k_i = f(t + c_i h, y + h Σ_{j<i} a_ij k_j),   i = 1..s,      y₁ = y + h Σ_j b_j k_j
//! ```
//!
//! The tableau is constant data and the stages are unrolled, so every coefficient is a compile-time constant:
//! zero coefficients cost nothing and the combinations are straight-line code per component (see
//! docs/book/src/explanation/integrators.md for what this costs).

use nalgebra::SVector;

use super::OdeSystem;
use super::tableau::{ButcherTableau, Increment};

/// The most stages a tableau may have (the unrolled stage list of [`step`]).
const MAX_STAGES: usize = 12;

/// The result of one step.
pub(crate) struct RkStep<const N: usize, const S: usize> {
    /// The solution y₁ at t + h.
    pub y_new: SVector<f64, N>,
    /// The stages k_1..k_s (with FSAL, k_s = f(t + h, y₁)).
    pub k: [SVector<f64, N>; S],
    /// The weighted sum of the stages before y is added: Σ_j b_j k_j for [`Increment::Slope`] (the slope, not yet
    /// scaled by h/d), Σ_j (b_j h) k_j for [`Increment::FoldedStep`].
    pub weighted: SVector<f64, N>,
}

/// One step of `tab` from (t, y) with k1 = f(t, y) given; `t_end` is the end time of the step, t + h as the caller
/// computes it, used for the nodes c_i = 1. Costs s − 1 evaluations of f.
///
/// The stage arguments are y + Σ_j (a_ij h) k_j, added to y term by term; the solution is y plus the weighted sum of
/// [`Increment`] (see [`weighted_sum`]).
// Always inlined: where several systems instantiate it (the library behind the CLI), the compiler otherwise keeps it
// out of line, returning the stages through memory, and a step costs up to ~1.7 × as much (docs/book/src/explanation/integrators.md).
#[inline(always)]
pub(crate) fn step<const N: usize, const S: usize, Sys: OdeSystem<N>>(
    sys: &mut Sys,
    tab: &ButcherTableau<S>,
    t: f64,
    t_end: f64,
    y: &SVector<f64, N>,
    k1: &SVector<f64, N>,
    h: f64,
) -> RkStep<N, S> {
    const { assert!(S >= 1 && S <= MAX_STAGES) };
    let explicit = S - usize::from(tab.fsal);
    let mut k = [*k1; S];
    // Stage i with a literal index, so that row a_i and the sums over j < i unroll to constants.
    macro_rules! stages {
        ($($i:literal)*) => {$(
            if $i < explicit {
                let arg = combine_onto(y, &tab.a[$i], h, &k, $i);
                k[$i] = sys.rhs(tab.node($i, t, t_end, h), &arg);
            }
        )*};
    }
    stages!(1 2 3 4 5 6 7 8 9 10 11);
    let (weighted, y_new) = match tab.increment {
        Increment::FoldedStep => {
            let sum = weighted_sum(&tab.b, h, &k);
            (sum, y + sum)
        }
        Increment::Slope { denominator } => {
            let slope = weighted_sum(&tab.b, 1.0, &k);
            (slope, y + slope * (h / denominator))
        }
    };
    if tab.fsal {
        k[S - 1] = sys.rhs(t_end, &y_new);
    }
    RkStep { y_new, k, weighted }
}

/// Calls `$term!(j)` for every literal stage index j < [`MAX_STAGES`], so that stage indices are constants.
macro_rules! for_each_stage {
    ($term:ident) => {
        $term!(0);
        $term!(1);
        $term!(2);
        $term!(3);
        $term!(4);
        $term!(5);
        $term!(6);
        $term!(7);
        $term!(8);
        $term!(9);
        $term!(10);
        $term!(11);
    };
}

/// base + Σ_{j<terms} (w_j·scale)·k_j, the terms added to base in the order of j (the newest stage last: the older
/// terms are summed while it is evaluated), zero weights skipped; per component, each term for all components at
/// once (the same operations per component as a loop over components with the terms inside).
#[inline(always)]
pub(crate) fn combine_onto<const N: usize, const S: usize>(
    base: &SVector<f64, N>,
    w: &[f64; S],
    scale: f64,
    k: &[SVector<f64, N>; S],
    terms: usize,
) -> SVector<f64, N> {
    let mut out = *base;
    macro_rules! term {
        ($j:literal) => {
            if $j < terms && $j < S && w[$j] != 0.0 {
                let c = w[$j] * scale;
                let k_j = &k[$j];
                for (o, v) in out.iter_mut().zip(k_j.iter()) {
                    *o += c * v;
                }
            }
        };
    }
    for_each_stage!(term);
    out
}

/// Σ_j (w_j·scale)·k_j, summed from 0 in the order of j, zero weights skipped and runs of equal adjacent weights
/// factored: w·k_j + w·k_{j+1} as w·(k_j + k_{j+1}) (RK4's 2(k2 + k3)).
#[inline(always)]
pub(crate) fn weighted_sum<const N: usize, const S: usize>(
    w: &[f64; S],
    scale: f64,
    k: &[SVector<f64, N>; S],
) -> SVector<f64, N> {
    let mut sum = SVector::<f64, N>::zeros();
    let mut run = SVector::<f64, N>::zeros();
    macro_rules! term {
        ($j:literal) => {
            if $j < S && w[$j] != 0.0 {
                if $j > 0 && w[$j.max(1) - 1] == w[$j] {
                    run += k[$j];
                } else {
                    run = k[$j];
                }
                if $j + 1 == S || w[($j + 1).min(S - 1)] != w[$j] {
                    let c = w[$j] * scale;
                    for (s, r) in sum.iter_mut().zip(run.iter()) {
                        *s += c * r;
                    }
                }
            }
        };
    }
    for_each_stage!(term);
    sum
}

#[cfg(test)]
mod tests {
    use super::super::tableau::{DOPRI5, RK4};
    use super::*;

    /// f(t, y) = (y2, −y1, t): a rotation and a clock.
    struct Oscillator;
    impl OdeSystem<3> for Oscillator {
        fn rhs(&mut self, t: f64, y: &SVector<f64, 3>) -> SVector<f64, 3> {
            SVector::<f64, 3>::new(y[1], -y[0], t)
        }
    }

    #[test]
    fn rk4_step_is_the_classical_formula_bit_for_bit() {
        let (t, h) = (0.3, 0.07);
        let y = SVector::<f64, 3>::new(0.9, -0.4, 2.0);
        let sys = &mut Oscillator;
        let k1 = sys.rhs(t, &y);
        let got = step(sys, &RK4, t, t + h, &y, &k1, h).y_new;
        let half = 0.5 * h;
        let k2 = sys.rhs(t + half, &(y + k1 * half));
        let k3 = sys.rhs(t + half, &(y + k2 * half));
        let k4 = sys.rhs(t + h, &(y + k3 * h));
        let classical = y + (k1 + (k2 + k3) * 2.0 + k4) * (h / 6.0);
        assert_eq!(got, classical);
    }

    #[test]
    fn fsal_stage_is_f_at_the_solution() {
        let (t, h) = (1.0, 0.1);
        let y = SVector::<f64, 3>::new(0.2, 0.5, -1.0);
        let sys = &mut Oscillator;
        let k1 = sys.rhs(t, &y);
        let s = step(sys, &DOPRI5, t, t + h, &y, &k1, h);
        assert_eq!(s.k[6], sys.rhs(t + h, &s.y_new));
        assert_eq!(s.y_new, y + s.weighted);
        // y₁ is the rotation by h to order 5 (|error| ~ h⁶/6!), the clock exactly quadratic.
        let (sin, cos) = h.sin_cos();
        let exact = SVector::<f64, 3>::new(
            cos * y[0] + sin * y[1],
            cos * y[1] - sin * y[0],
            y[2] + t * h + 0.5 * h * h,
        );
        assert!((s.y_new - exact).norm() < 1e-8);
    }

    #[test]
    fn combinations_equal_the_vector_expressions() {
        // combine_onto / weighted_sum against nalgebra's y + h·Σ a_j k_j: only the rounding differs (h folded into
        // the weights, another summation order), so they agree to a few ulps of the largest magnitude involved,
        // |y| + Σ|a_j h k_j| (≤ 2M + 2 roundings of it).
        let y = SVector::<f64, 7>::from([1.0, -0.3, 2.5e-3, 0.7, -0.7, 1e-9, 0.1]);
        let k1 = SVector::<f64, 7>::from([0.3, 1.7, -2.0, 0.01, 5.0, -1e-3, 0.0]);
        let k2 = SVector::<f64, 7>::from([-0.9, 0.2, 3.0, -4.0, 1e-6, 2.0, -0.5]);
        let k3 = SVector::<f64, 7>::from([2.2, -1.1, 0.4, 0.6, -0.8, 1.0, 3.3]);
        let (a1, a2, a3, h) = (19372.0 / 6561.0, -25360.0 / 2187.0, 64448.0 / 6561.0, 0.037);
        let (w, k) = ([a1, a2, a3], [k1, k2, k3]);
        let fast = combine_onto(&y, &w, h, &k, 3);
        let vector = y + (k1 * a1 + k2 * a2 + k3 * a3) * h;
        let sum = weighted_sum(&w, h, &k);
        for i in 0..7 {
            let terms = (a1 * k1[i]).abs() + (a2 * k2[i]).abs() + (a3 * k3[i]).abs();
            let scale = y[i].abs() + h * terms;
            assert!(
                (fast[i] - vector[i]).abs() <= 8.0 * f64::EPSILON * scale,
                "{i}"
            );
            assert!(
                (y[i] + sum[i] - vector[i]).abs() <= 8.0 * f64::EPSILON * scale,
                "{i}"
            );
        }
    }
}
