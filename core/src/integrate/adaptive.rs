//! Adaptive driver shared by the embedded Runge–Kutta pairs (DOPRI5, DOP853): Hairer's
//! initial step `hinit`, the (PI-stabilised) step-size controller, exact landing on row times.
//!
//! References: HNW I §II.4 ("Automatic step size control", "Starting step size") and the
//! Fortran codes `dopri5.f` / `dop853.f` (E. Hairer, G. Wanner), routines DOPCOR, DP86CO, HINIT.

use nalgebra::SVector;

use super::dense::{Dense, StepEnds, StepWatch};
use super::explicit_rk::{self, RkStep};
use super::tableau::ButcherTableau;
use super::{IntegrateError, OdeSystem, Schedule, Settings, Stats, all_finite, report, start};

/// Tolerances of the error norm sc_i = atol + rtol·max(|y_i|, |ŷ_i|) (HNW I eq. (4.10)).
#[derive(Debug, Clone, Copy)]
pub(crate) struct Tol {
    pub rtol: f64,
    pub atol: f64,
}

impl Tol {
    /// Scale sc_i = atol + rtol·max(|y0|, |y1|).
    #[inline]
    pub fn scale(&self, y0: f64, y1: f64) -> f64 {
        self.atol + self.rtol * y0.abs().max(y1.abs())
    }

    /// Reciprocal scales 1/sc_i of the step y → y₁: one division per component, computed while
    /// the last stage is evaluated, so the error norm multiplies instead of dividing.
    #[inline(always)]
    pub fn inverse_scales<const N: usize>(
        &self,
        y: &SVector<f64, N>,
        y_new: &SVector<f64, N>,
    ) -> SVector<f64, N> {
        let mut inv = SVector::<f64, N>::zeros();
        for (i, v) in inv.iter_mut().enumerate() {
            *v = 1.0 / self.scale(y[i], y_new[i]);
        }
        inv
    }
}

/// Σ_i (e_i·s_i)², the sum of squares of an error estimate e scaled by s = 1/sc, in four
/// interleaved partial sums (a dependency chain of ⌈N/4⌉ + 2 additions instead of N; the order
/// only changes the rounding).
#[inline(always)]
pub(crate) fn scaled_sum_sq<const N: usize>(e: &SVector<f64, N>, s: &SVector<f64, N>) -> f64 {
    let mut acc = [0.0; 4];
    for i in 0..N {
        let r = e[i] * s[i];
        acc[i % 4] += r * r;
    }
    (acc[0] + acc[1]) + (acc[2] + acc[3])
}

/// Result of one attempted step of an embedded pair.
pub(crate) struct Trial<const N: usize> {
    /// Higher-order solution at t + h (local extrapolation).
    pub y_new: SVector<f64, N>,
    /// Square of the scaled error estimate err; the step is accepted iff err² ≤ 1 (⇔ err ≤ 1).
    /// The square root is never taken: the controller works with ln err² or (err²)^(1/16).
    pub err_sq: f64,
    /// f(t + h, y_new) if the pair computes it inside the step (FSAL, DOPRI5); `None` if the
    /// driver must evaluate it after acceptance (DOP853, as in `dop853.f`).
    pub f_new: Option<SVector<f64, N>>,
}

/// Hairer's step-size controller parameters of an embedded pair.
pub(crate) trait ControllerParams {
    /// Order used by `hinit` (IORD in Hairer's codes).
    const HINIT_ORDER: f64;
    /// Exponent of the error in the controller: EXPO1 = 1/(q+1) − β·(weight), Hairer's codes.
    const EXPO1: f64;
    /// PI (Lund) stabilisation exponent β (HNW II §IV.2, as cited in `dopri5.f`).
    const BETA: f64;
    /// Lower bound of h_new/h (FAC1).
    const FAC_MIN: f64;
    /// Upper bound of h_new/h (FAC2).
    const FAC_MAX: f64;
    /// Safety factor (SAFE).
    const SAFE: f64 = 0.9;

    /// Unclamped step ratio h_new/h = SAFE·facold^β / err^EXPO1 from err² and ln(facold): the
    /// reciprocal of Hairer's FAC = FAC11/FACOLD^β/SAFE (ln facold = 0 gives SAFE/err^EXPO1, the
    /// ratio after a rejection).
    ///
    /// Default: exp(ln SAFE + β·ln facold − (EXPO1/2)·ln err²), one logarithm and one exponential
    /// on the step's critical path instead of two powers and two divisions (equal up to rounding).
    /// err = 0 gives +∞ (clamped to FAC_MAX by the controller), as Hairer's FAC = 0 does.
    #[inline]
    fn step_ratio(err_sq: f64, ln_fac_old: f64) -> f64 {
        (Self::SAFE.ln() + Self::BETA * ln_fac_old - 0.5 * Self::EXPO1 * err_sq.ln()).exp()
    }
}

/// An explicit embedded Runge–Kutta pair with `S` stages: its tableau, its error estimate and Hairer's controller
/// parameters.
pub(crate) trait EmbeddedPair<const S: usize>: ControllerParams {
    /// The tableau of the higher-order solution (local extrapolation).
    const TABLEAU: &'static ButcherTableau<S>;

    /// err², the square of the scaled error estimate of `step` from y with step size h, from the stages.
    fn error_sq<const N: usize>(step: &RkStep<N, S>, y: &SVector<f64, N>, h: f64, tol: Tol) -> f64;

    /// The pair's own continuous extension over an accepted step ([`super::dense`]) and the evaluations of f it
    /// took.
    fn dense<const N: usize, Sys: OdeSystem<N>>(
        sys: &mut Sys,
        ends: &StepEnds<'_, N, S>,
    ) -> (Dense<N>, u64);
}

/// Attempts one step of the pair `P` of size h from (t, y) with k1 = f(t, y): s − 1 evaluations, + 1 with FSAL.
/// With `keep_stages` (a constant where the driver calls it) the stages come back too, for the dense output.
// Always inlined into the driver (see explicit_rk::step).
#[inline(always)]
fn attempt<P, const S: usize, const N: usize, Sys>(
    sys: &mut Sys,
    (t, y, k1): (f64, &SVector<f64, N>, &SVector<f64, N>),
    h: f64,
    tol: Tol,
    keep_stages: bool,
) -> (Trial<N>, Option<[SVector<f64, N>; S]>)
where
    P: EmbeddedPair<S>,
    Sys: OdeSystem<N>,
{
    let step = explicit_rk::step(sys, P::TABLEAU, t, t + h, y, k1, h);
    let trial = Trial {
        err_sq: P::error_sq(&step, y, h, tol),
        y_new: step.y_new,
        f_new: P::TABLEAU.fsal.then_some(step.k[S - 1]),
    };
    (trial, keep_stages.then_some(step.k))
}

/// Hairer's starting step size (HNW I §II.4, "Starting step size"; function HINIT of
/// `dopri5.f`/`dop853.f`, with its unnormalised sums): h0 = 0.01·‖y0‖/‖f0‖ (or 1e-6), one
/// explicit Euler step to estimate ‖y''‖, then h = min(100·h0, (0.01/max(‖f0‖, ‖y''‖))^(1/p),
/// hmax). Costs one RHS evaluation (f0 is given).
pub(crate) fn hinit<const N: usize, S: OdeSystem<N>>(
    sys: &mut S,
    t: f64,
    y: &SVector<f64, N>,
    f0: &SVector<f64, N>,
    order: f64,
    h_max: f64,
    tol: Tol,
) -> f64 {
    let mut dnf = 0.0;
    let mut dny = 0.0;
    for i in 0..N {
        let sk = tol.atol + tol.rtol * y[i].abs();
        dnf += (f0[i] / sk).powi(2);
        dny += (y[i] / sk).powi(2);
    }
    let mut h = if dnf <= 1e-10 || dny <= 1e-10 {
        1e-6
    } else {
        (dny / dnf).sqrt() * 0.01
    };
    h = h.min(h_max);
    let y1 = y + f0 * h;
    let f1 = sys.rhs(t + h, &y1);
    let mut der2 = 0.0;
    for i in 0..N {
        let sk = tol.atol + tol.rtol * y[i].abs();
        der2 += ((f1[i] - f0[i]) / sk).powi(2);
    }
    let der2 = der2.sqrt() / h;
    let der12 = der2.abs().max(dnf.sqrt());
    let h1 = if der12 <= 1e-15 {
        (h * 1e-3).max(1e-6)
    } else {
        (0.01 / der12).powf(1.0 / order)
    };
    (100.0 * h).min(h1).min(h_max)
}

/// Lower bound of FACOLD = max(err, 1e-4) (Hairer's codes).
const FAC_OLD_MIN: f64 = 1e-4;

/// Hairer's step-size controller state (FACOLD, kept as its logarithm; REJECT).
struct Controller<P> {
    ln_fac_old: f64,
    reject: bool,
    _pair: std::marker::PhantomData<P>,
}

impl<P: ControllerParams> Controller<P> {
    fn new() -> Self {
        Self {
            ln_fac_old: FAC_OLD_MIN.ln(),
            reject: false,
            _pair: std::marker::PhantomData,
        }
    }

    /// Accepted step of size `h` with error err (given as err²); `h_prop` is the proposal the
    /// step was cut from (h < h_prop if it was shortened to land on a row). Returns the next
    /// proposal.
    ///
    /// Hairer: fac = err^EXPO1 / facold^β / SAFE, h_new = h / clamp(fac, 1/FAC_MAX, 1/FAC_MIN),
    /// computed as h·clamp(1/fac, FAC_MIN, FAC_MAX) ([`ControllerParams::step_ratio`]); after a
    /// rejection h_new ≤ h; h_new ≤ hmax. Landing on a row must not shrink the step
    /// carried forward, so for a shortened step (h < h_prop) h_new = max(h_new, h_prop): the
    /// unclamped proposal is remembered. (If the error of the shortened step says h_prop is too
    /// large, the next attempt is simply rejected and shrunk as usual.)
    fn accept(&mut self, err_sq: f64, h: f64, h_prop: f64, h_max: f64) -> f64 {
        let ratio = P::step_ratio(err_sq, self.ln_fac_old);
        let mut h_new = h * ratio.clamp(P::FAC_MIN, P::FAC_MAX);
        if h < h_prop {
            h_new = h_new.max(h_prop);
        }
        if P::BETA != 0.0 {
            // ln max(err, 1e-4) = max(½·ln err², ln 1e-4), sharing ln err² with `step_ratio`.
            self.ln_fac_old = (0.5 * err_sq.ln()).max(FAC_OLD_MIN.ln());
        }
        h_new = h_new.min(h_max);
        if self.reject {
            h_new = h_new.min(h.max(h_prop));
        }
        self.reject = false;
        h_new
    }

    /// Rejected step with error err (given as err²): h_new = h / min(1/FAC_MIN, err^EXPO1/SAFE)
    /// (Hairer), computed as h·max(FAC_MIN, SAFE/err^EXPO1); a non-finite error (non-finite
    /// trial state) shrinks by the maximal factor FAC_MIN.
    fn reject(&mut self, err_sq: f64, h: f64) -> f64 {
        self.reject = true;
        if err_sq.is_finite() {
            h * P::step_ratio(err_sq, 0.0).max(P::FAC_MIN)
        } else {
            h * P::FAC_MIN
        }
    }
}

/// Smallest admissible step at time t: a step h ≤ 16·ε·|t| cannot advance t reliably.
#[inline]
fn too_small(h: f64, t: f64) -> bool {
    // NaN compares false, so a NaN proposal is "too small" too.
    let ok = h > 16.0 * f64::EPSILON * t.abs() && h > f64::MIN_POSITIVE;
    !ok
}

/// Adaptive driver for the pair `P`.
///
/// Per step: if 1.01·h_prop ≥ (next row − t) the step is cut (or stretched by ≤ 1%, as in
/// Hairer's codes) to land exactly on the row (likewise on a breakpoint of f before the row,
/// [`OdeSystem::next_breakpoint`]); the trial is accepted iff err ≤ 1 and the
/// projected state and its derivative are finite; otherwise h shrinks (a rejection). The FSAL
/// derivative is reused unless `project` changed the state. Errors: `TooManySteps` when
/// accepted + rejected reaches `max_steps`, `StepSizeTooSmall` when h_prop ≤ 16·ε·|t|,
/// `NonFinite { t: 0 }` if f(0, y0) is non-finite.
///
/// An active `watch` sees every accepted step's dense output ([`EmbeddedPair::dense`], its evaluations counted)
/// before the row at its end; when it asks to stop at t_stop, the interpolant's state there is the last row.
pub(crate) fn run<P, const STAGES: usize, const N: usize, S, E, F, W>(
    sys: &mut S,
    y0: SVector<f64, N>,
    schedule: &Schedule,
    settings: &Settings,
    on_row: &mut F,
    watch: &mut W,
) -> Result<Stats, IntegrateError<E>>
where
    P: EmbeddedPair<STAGES>,
    S: OdeSystem<N>,
    F: FnMut(f64, &SVector<f64, N>) -> Result<(), E>,
    W: StepWatch<N>,
{
    let tol = Tol {
        rtol: settings.rtol,
        atol: settings.atol,
    };
    let mut stats = Stats::default();
    let mut y = start(sys, y0, on_row)?;
    if schedule.len() == 1 {
        return Ok(stats);
    }
    let mut t = 0.0;
    let mut k1 = first_rhs(sys, &y, &mut stats)?;
    let h_max = schedule.t_end();
    let mut h_prop = hinit(sys, t, &y, &k1, P::HINIT_ORDER, h_max, tol);
    stats.evals += 1;
    let mut ctl = Controller::<P>::new();

    for t_row in schedule.iter().skip(1) {
        while t < t_row {
            let attempts = stats.steps + stats.rejected;
            if attempts >= settings.max_steps {
                return Err(IntegrateError::TooManySteps { t, steps: attempts });
            }
            if too_small(h_prop, t) {
                return Err(IntegrateError::StepSizeTooSmall { t, h: h_prop });
            }
            let (h, t_new) = next_step(sys, t, t_row, h_prop);
            let (trial, stages) = attempt::<P, STAGES, N, S>(sys, (t, &y, &k1), h, tol, W::ACTIVE);
            stats.evals += STAGES as u64 - 1;

            if trial.err_sq <= 1.0 && all_finite(&trial.y_new) {
                let mut y_new = trial.y_new;
                sys.project(&mut y_new);
                let k_new = match trial.f_new {
                    Some(f) if y_new == trial.y_new => f,
                    _ => {
                        stats.evals += 1;
                        sys.rhs(t_new, &y_new)
                    }
                };
                if all_finite(&y_new) && all_finite(&k_new) {
                    if let Some(k) = stages.filter(|_| W::ACTIVE) {
                        let ends = StepEnds {
                            t,
                            h: t_new - t,
                            y: &y,
                            y_new: &y_new,
                            k: &k,
                            k_new: &k_new,
                        };
                        let (dense, evals) = P::dense(sys, &ends);
                        stats.evals += evals;
                        if let Some(t_stop) = watch.step(&dense) {
                            stats.steps += 1;
                            report(on_row, t_stop, &dense.at(t_stop))?;
                            return Ok(stats);
                        }
                    }
                    h_prop = ctl.accept(trial.err_sq, h, h_prop, h_max);
                    t = t_new;
                    y = y_new;
                    k1 = k_new;
                    stats.steps += 1;
                    continue;
                }
                h_prop = ctl.reject(f64::NAN, h);
            } else {
                h_prop = ctl.reject(trial.err_sq, h);
            }
            stats.rejected += 1;
        }
        report(on_row, t, &y)?;
    }
    Ok(stats)
}

/// The step (h, t + h) from t toward the row t_row with the proposed size `h_prop`: it ends on the row, or on an
/// earlier breakpoint of f (not reported), when the rest is within 1 % of `h_prop`.
fn next_step<const N: usize, S: OdeSystem<N>>(
    sys: &S,
    t: f64,
    t_row: f64,
    h_prop: f64,
) -> (f64, f64) {
    let t_stop = match sys.next_breakpoint(t) {
        Some(b) if b < t_row => b,
        _ => t_row,
    };
    let remaining = t_stop - t;
    if 1.01 * h_prop >= remaining {
        (remaining, t_stop)
    } else {
        (h_prop, t + h_prop)
    }
}

/// f(0, y0), counted; `NonFinite { t: 0 }` when it is not finite.
fn first_rhs<const N: usize, S: OdeSystem<N>, E>(
    sys: &mut S,
    y: &SVector<f64, N>,
    stats: &mut Stats,
) -> Result<SVector<f64, N>, IntegrateError<E>> {
    let k1 = sys.rhs(0.0, y);
    stats.evals += 1;
    if all_finite(&k1) {
        Ok(k1)
    } else {
        Err(IntegrateError::NonFinite { t: 0.0 })
    }
}

#[cfg(test)]
mod tests {
    use super::super::dopri5::Dopri5;
    use super::*;

    struct Pair;
    impl ControllerParams for Pair {
        const HINIT_ORDER: f64 = 5.0;
        const EXPO1: f64 = 0.2;
        const BETA: f64 = 0.0;
        const FAC_MIN: f64 = 0.2;
        const FAC_MAX: f64 = 10.0;
    }

    #[test]
    fn shortened_step_keeps_proposal() {
        // A tiny step cut to land on a row with a negligible error keeps the proposal.
        let mut c = Controller::<Pair>::new();
        assert_eq!(c.accept(1e-20, 1e-9, 0.5, 10.0), 0.5);
        // An unshortened step with the same error grows by at most FAC_MAX.
        let mut c = Controller::<Pair>::new();
        assert_eq!(c.accept(1e-20, 0.5, 0.5, 10.0), 5.0);
        // A moderately shortened step may still grow beyond the proposal.
        let mut c = Controller::<Pair>::new();
        assert!(c.accept(1e-8, 0.45, 0.5, 10.0) > 0.5);
        // An unshortened step with a large error is reduced.
        let mut c = Controller::<Pair>::new();
        assert!(c.accept(0.99, 0.5, 0.5, 10.0) < 0.5);
    }

    #[test]
    fn rejection_shrinks_and_blocks_growth() {
        let mut c = Controller::<Pair>::new();
        let h = c.reject(4.0, 1.0);
        assert!((Pair::FAC_MIN..1.0).contains(&h));
        assert_eq!(c.reject(f64::NAN, 1.0), Pair::FAC_MIN);
        // After a rejection the next accepted step may not grow.
        assert_eq!(c.accept(1e-10, 0.2, 0.2, 10.0), 0.2);
    }

    #[test]
    fn step_ratio_is_hairers_factor() {
        // exp(ln SAFE + β·ln facold − (EXPO1/2)·ln err²) = 1/fac with Hairer's
        // fac = err^EXPO1/facold^β/SAFE, to a few ulps over the range the controller sees
        // (err ≤ 1 accepted, > 1 rejected; facold ∈ [1e-4, 1]).
        for err in [1e-150, 1e-30, 1e-12, 3.7e-5, 1e-4, 0.5, 1.0, 2.0, 1e6] {
            for fac_old in [1e-4, 2.5e-3, 0.3, 1.0] {
                let fast = Dopri5::step_ratio(err * err, f64::ln(fac_old));
                let fac = err.powf(Dopri5::EXPO1) / fac_old.powf(Dopri5::BETA) / Dopri5::SAFE;
                assert!(
                    (fast - 1.0 / fac).abs() <= 1e-14 / fac,
                    "err {err:e}, facold {fac_old:e}: {fast:e} vs {:e}",
                    1.0 / fac
                );
            }
        }
        assert_eq!(Dopri5::step_ratio(0.0, 0.0), f64::INFINITY);
        // The controller's floor of facold, kept as a logarithm: ln max(err, 1e-4).
        let mut c = Controller::<Dopri5>::new();
        assert_eq!(c.ln_fac_old, f64::ln(1e-4));
        c.accept(1e-18, 0.1, 0.1, 10.0);
        assert_eq!(c.ln_fac_old, f64::ln(1e-4));
        c.accept(0.25 * 0.25, 0.1, 0.1, 10.0);
        assert!((c.ln_fac_old - f64::ln(0.25)).abs() <= 1e-15);
    }

    #[test]
    fn scaled_sum_sq_is_the_error_norms_sum() {
        // Σ (e_i·(1/sc_i))² in four partial sums vs Σ (e_i/sc_i)² in one: every term is
        // positive with a relative rounding ≤ 3ε apart (reciprocal, product, square), and both
        // sums add ≤ N roundings, so they agree to (N + 6)·ε relative.
        let tol = Tol {
            rtol: 1e-7,
            atol: 1e-9,
        };
        let y = SVector::<f64, 7>::from([1.0, -0.3, 2.5e-3, 0.7, -0.7, 1e-12, 0.1]);
        let y_new = SVector::<f64, 7>::from([1.1, -0.2, 2.4e-3, 0.71, -0.69, 0.0, -0.1]);
        let e = SVector::<f64, 7>::from([3e-8, -1e-9, 4e-11, 2e-7, -5e-8, 1e-10, 7e-9]);
        let fast = scaled_sum_sq(&e, &tol.inverse_scales(&y, &y_new));
        let plain: f64 = (0..7)
            .map(|i| (e[i] / tol.scale(y[i], y_new[i])).powi(2))
            .sum();
        assert!(
            (fast - plain).abs() <= 13.0 * f64::EPSILON * plain,
            "{fast} vs {plain}"
        );
    }

    #[test]
    fn too_small_threshold() {
        assert!(too_small(1e-16, 1.0));
        assert!(!too_small(1e-14, 1.0));
        assert!(too_small(0.0, 0.0));
        assert!(too_small(f64::NAN, 0.0));
        assert!(!too_small(1e-300, 0.0));
    }
}
