//! The continuous solution over one accepted step ("dense output"), for locating events between the rows.
//!
//! Every interpolant here has Hairer's nested form (HNW I §II.6, eq. (6.7) and the routines CONTD5 of `dopri5.f` and
//! CONTD8 of `dop853.f`): with θ = (t − t₀)/h and θ' = 1 − θ,
//!
//! ```text
//!   u(t) = r₁ + θ(r₂ + θ'(r₃ + θ(r₄ + θ'(r₅ + θ(r₆ + θ'(r₇ + θ r₈))))))
//! ```
//!
//! where r₁ = y₀, r₂ = y₁ − y₀, r₃ = h f₀ − r₂, r₄ = r₂ − h f₁ − r₃: the first four terms alone are the cubic
//! Hermite interpolant of (y₀, f₀, y₁, f₁) (used for RK4); DOPRI5 adds r₅ (Shampine's order-4 dense output, 1986),
//! DOP853 r₅..r₈ (order 7, three more stages per step).

use nalgebra::SVector;

use super::OdeSystem;

/// The most terms r_j of an interpolant (DOP853's 8).
const MAX_TERMS: usize = 8;

/// The solution over one step [t₀, t₀ + h] as a polynomial in Hairer's nested form (module docs).
#[derive(Debug, Clone, Copy)]
pub struct Dense<const N: usize> {
    t0: f64,
    t1: f64,
    h: f64,
    r: [SVector<f64, N>; MAX_TERMS],
    terms: usize,
}

impl<const N: usize> Dense<N> {
    /// The cubic Hermite interpolant of y₀ = y(t₀), f₀ = y'(t₀), y₁ = y(t₁), f₁ = y'(t₁): exact for cubics, error
    /// O(h⁴) (HNW I §II.6, eq. (6.7) with the first four terms).
    pub fn hermite(
        t0: f64,
        t1: f64,
        y0: &SVector<f64, N>,
        f0: &SVector<f64, N>,
        y1: &SVector<f64, N>,
        f1: &SVector<f64, N>,
    ) -> Self {
        let h = t1 - t0;
        let mut r = [SVector::zeros(); MAX_TERMS];
        r[0] = *y0;
        r[1] = y1 - y0;
        r[2] = f0 * h - r[1];
        r[3] = r[1] - f1 * h - r[2];
        Self {
            t0,
            t1,
            h,
            r,
            terms: 4,
        }
    }

    /// The Hermite interpolant with `extra` higher terms r₅, r₆, … (already multiplied by h).
    fn with_terms(mut self, extra: &[SVector<f64, N>]) -> Self {
        for (slot, term) in self.r[4..].iter_mut().zip(extra) {
            *slot = *term;
        }
        self.terms = 4 + extra.len().min(MAX_TERMS - 4);
        self
    }

    /// The step's start time t₀.
    pub fn t0(&self) -> f64 {
        self.t0
    }

    /// The step's end time t₁.
    pub fn t1(&self) -> f64 {
        self.t1
    }

    /// u(t), the interpolant at t (meant for t₀ ≤ t ≤ t₁; u(t₀) = y₀ and u(t₁) = y₁ up to rounding).
    pub fn at(&self, t: f64) -> SVector<f64, N> {
        if t == self.t1 {
            return self.r[0] + self.r[1];
        }
        let theta = (t - self.t0) / self.h;
        let theta1 = 1.0 - theta;
        let mut acc = self.r[self.terms - 1];
        for j in (1..self.terms - 1).rev() {
            // Term j + 1 (from 1) is multiplied by θ when j is odd, by θ' when j is even (r₂ by θ, r₃ by θ', …).
            let factor = if j % 2 == 1 { theta1 } else { theta };
            acc = self.r[j] + acc * factor;
        }
        self.r[0] + acc * theta
    }
}

/// Sees the continuous solution of every accepted step, in time order, before the row at the step's end is
/// reported. A watch with `ACTIVE = false` ([`NoWatch`]) costs nothing: the drivers build no interpolant for it.
pub trait StepWatch<const N: usize> {
    /// Whether the drivers build interpolants for this watch.
    const ACTIVE: bool = true;
    /// Looks at one step; `Some(t_stop)` (t₀ < t_stop ≤ t₁) ends the run at t_stop, whose row (the interpolant
    /// there) is the last one reported.
    fn step(&mut self, solution: &Dense<N>) -> Option<f64>;
}

/// The watch of a run without events.
#[derive(Debug, Clone, Copy, Default)]
pub struct NoWatch;

impl<const N: usize> StepWatch<N> for NoWatch {
    const ACTIVE: bool = false;
    fn step(&mut self, _solution: &Dense<N>) -> Option<f64> {
        None
    }
}

/// The shared inputs of an embedded pair's dense output: the step, its end points and its stages.
pub(crate) struct StepEnds<'a, const N: usize, const S: usize> {
    pub t: f64,
    pub h: f64,
    pub y: &'a SVector<f64, N>,
    pub y_new: &'a SVector<f64, N>,
    /// The stages k_1..k_s of the step.
    pub k: &'a [SVector<f64, N>; S],
    /// f(t + h, y_new), the next step's k1.
    pub k_new: &'a SVector<f64, N>,
}

impl<const N: usize, const S: usize> StepEnds<'_, N, S> {
    /// The Hermite part r₁..r₄ of the step.
    fn hermite(&self) -> Dense<N> {
        Dense::hermite(
            self.t,
            self.t + self.h,
            self.y,
            &self.k[0],
            self.y_new,
            self.k_new,
        )
    }
}

/// DOPRI5's dense output (`dopri5.f`, CONTD5; Shampine 1986): r₅ = h Σ_j d_j k_j, continuous of order 4. No
/// extra evaluation.
pub(crate) fn dopri5<const N: usize>(ends: &StepEnds<'_, N, 7>) -> Dense<N> {
    const D: [f64; 7] = [
        -12715105075.0 / 11282082432.0,
        0.0,
        87487479700.0 / 32700410799.0,
        -10690763975.0 / 1880347072.0,
        701980252875.0 / 199316789632.0,
        -1453857185.0 / 822651844.0,
        69997945.0 / 29380423.0,
    ];
    // The last stage of DOPRI5 is f at the unprojected y₁; d₇ weighs f(t + h, y_new) as the driver has it.
    let mut k = *ends.k;
    k[6] = *ends.k_new;
    let r5 = combination(&SVector::zeros(), &D, ends.h, &k);
    ends.hermite().with_terms(&[r5])
}

/// DOP853's dense output (`dop853.f`, CONTD8 and the three extra stages k₁₄..k₁₆ at c = 0.1, 0.2, 7/9), continuous
/// of order 7: 3 more evaluations of f per step. Returns the interpolant and the evaluations it took.
pub(crate) fn dop853<const N: usize, Sys: OdeSystem<N>>(
    sys: &mut Sys,
    ends: &StepEnds<'_, N, 12>,
) -> (Dense<N>, u64) {
    use dop853_dense::{A14, A15, A16, C14, C15, C16, D4, D5, D6, D7};
    // Stages 1..16 of dop853.f: k₁..k₁₂ of the step, k₁₃ = f(t + h, y₁), then k₁₄..k₁₆.
    let mut k = [SVector::<f64, N>::zeros(); 16];
    k[..12].copy_from_slice(ends.k);
    k[12] = *ends.k_new;
    let (t, h, y) = (ends.t, ends.h, ends.y);
    for (i, (c, a)) in [(C14, &A14), (C15, &A15), (C16, &A16)]
        .into_iter()
        .enumerate()
    {
        let arg = combination(y, &a[..13 + i], h, &k);
        k[13 + i] = sys.rhs(t + c * h, &arg);
    }
    let zero = SVector::zeros();
    let r = [
        combination(&zero, &D4, h, &k),
        combination(&zero, &D5, h, &k),
        combination(&zero, &D6, h, &k),
        combination(&zero, &D7, h, &k),
    ];
    (ends.hermite().with_terms(&r), 3)
}

/// base + h Σ_j w_j k_j over the given weights (zero weights skipped).
fn combination<const N: usize>(
    base: &SVector<f64, N>,
    w: &[f64],
    h: f64,
    k: &[SVector<f64, N>],
) -> SVector<f64, N> {
    let mut out = *base;
    for (wj, kj) in w.iter().zip(k).filter(|(wj, _)| **wj != 0.0) {
        out += kj * (wj * h);
    }
    out
}

/// The coefficients of DOP853's dense output, from Hairer's `dop853.f` (nodes C14..C16, rows A14..A16 of the
/// extra stages, D4..D7 of CONTD8), indexed by stage 1..16 from 0.
#[allow(clippy::excessive_precision)]
mod dop853_dense {
    pub const C14: f64 = 0.1;
    pub const C15: f64 = 0.2;
    pub const C16: f64 = 7.0 / 9.0;

    pub const A14: [f64; 16] = [
        5.61675022830479523392909219681e-2,
        0.0,
        0.0,
        0.0,
        0.0,
        0.0,
        2.53500210216624811088794765333e-1,
        -2.46239037470802489917441475441e-1,
        -1.24191423263816360469010140626e-1,
        1.5329179827876569731206322685e-1,
        8.20105229563468988491666602057e-3,
        7.56789766054569976138603589584e-3,
        -8.298e-3,
        0.0,
        0.0,
        0.0,
    ];
    pub const A15: [f64; 16] = [
        3.18346481635021405060768473261e-2,
        0.0,
        0.0,
        0.0,
        0.0,
        2.83009096723667755288322961402e-2,
        5.35419883074385676223797384372e-2,
        -5.49237485713909884646569340306e-2,
        0.0,
        0.0,
        -1.08347328697249322858509316994e-4,
        3.82571090835658412954920192323e-4,
        -3.40465008687404560802977114492e-4,
        1.41312443674632500278074618366e-1,
        0.0,
        0.0,
    ];
    pub const A16: [f64; 16] = [
        -4.28896301583791923408573538692e-1,
        0.0,
        0.0,
        0.0,
        0.0,
        -4.69762141536116384314449447206e0,
        7.68342119606259904184240953878e0,
        4.06898981839711007970213554331e0,
        3.56727187455281109270669543021e-1,
        0.0,
        0.0,
        0.0,
        -1.39902416515901462129418009734e-3,
        2.9475147891527723389556272149e0,
        -9.15095847217987001081870187138e0,
        0.0,
    ];
    pub const D4: [f64; 16] = [
        -0.84289382761090128651353491142e+01,
        0.0,
        0.0,
        0.0,
        0.0,
        0.56671495351937776962531783590e+00,
        -0.30689499459498916912797304727e+01,
        0.23846676565120698287728149680e+01,
        0.21170345824450282767155149946e+01,
        -0.87139158377797299206789907490e+00,
        0.22404374302607882758541771650e+01,
        0.63157877876946881815570249290e+00,
        -0.88990336451333310820698117400e-01,
        0.18148505520854727256656404962e+02,
        -0.91946323924783554000451984436e+01,
        -0.44360363875948939664310572000e+01,
    ];
    pub const D5: [f64; 16] = [
        0.10427508642579134603413151009e+02,
        0.0,
        0.0,
        0.0,
        0.0,
        0.24228349177525818288430175319e+03,
        0.16520045171727028198505394887e+03,
        -0.37454675472269020279518312152e+03,
        -0.22113666853125306036270938578e+02,
        0.77334326684722638389603898808e+01,
        -0.30674084731089398182061213626e+02,
        -0.93321305264302278729567221706e+01,
        0.15697238121770843886131091075e+02,
        -0.31139403219565177677282850411e+02,
        -0.93529243588444783865713862664e+01,
        0.35816841486394083752465898540e+02,
    ];
    pub const D6: [f64; 16] = [
        0.19985053242002433820987653617e+02,
        0.0,
        0.0,
        0.0,
        0.0,
        -0.38703730874935176555105901742e+03,
        -0.18917813819516756882830838328e+03,
        0.52780815920542364900561016686e+03,
        -0.11573902539959630126141871134e+02,
        0.68812326946963000169666922661e+01,
        -0.10006050966910838403183860980e+01,
        0.77771377980534432092869265740e+00,
        -0.27782057523535084065932004339e+01,
        -0.60196695231264120758267380846e+02,
        0.84320405506677161018159903784e+02,
        0.11992291136182789328035130030e+02,
    ];
    pub const D7: [f64; 16] = [
        -0.25693933462703749003312586129e+02,
        0.0,
        0.0,
        0.0,
        0.0,
        -0.15418974869023643374053993627e+03,
        -0.23152937917604549567536039109e+03,
        0.35763911791061412378285349910e+03,
        0.93405324183624310003907691704e+02,
        -0.37458323136451633156875139351e+02,
        0.10409964950896230045147246184e+03,
        0.29840293426660503123344363579e+02,
        -0.43533456590011143754432175058e+02,
        0.96324553959188282948394950600e+02,
        -0.39177261675615439165231486172e+02,
        -0.14972683625798562581422125276e+03,
    ];
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn hermite_is_exact_for_cubics() {
        // y = t³ − 2t + 1, y' = 3t² − 2 on [0.5, 1.25]: the cubic Hermite interpolant reproduces it.
        let y = |t: f64| SVector::<f64, 1>::new(t * t * t - 2.0 * t + 1.0);
        let f = |t: f64| SVector::<f64, 1>::new(3.0 * t * t - 2.0);
        let d = Dense::hermite(0.5, 1.25, &y(0.5), &f(0.5), &y(1.25), &f(1.25));
        for t in [0.5, 0.6, 0.9, 1.1, 1.25] {
            assert!((d.at(t) - y(t)).norm() < 1e-14, "t = {t}");
        }
    }
}
