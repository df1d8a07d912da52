//! The torque-free body on an equal grid of times `t_k = k·every`, each row advanced from the previous one by
//! addition theorems instead of evaluated from scratch.
//!
//! On the grid, `τ_k = λ t_k + τ₀` advances by the constant `h = λ·every`, so (DLMF 22.8.1–22.8.3)
//!
//! ```text
//!   sn(u + h) = (sn u cn h dn h + sn h cn u dn u) / Δ
//!   cn(u + h) = (cn u cn h − sn u dn u sn h dn h) / Δ        Δ = 1 − m sn²u sn²h
//!   dn(u + h) = (dn u dn h − m sn u cn u sn h cn h) / Δ
//! ```
//!
//! and the precession angle's elliptic integral `J(u) = ∫₀ᵘ sn²v / (1 + ν sn²v) dv` (ν = −n ≥ 0, the
//! characteristic of [`TorqueFreeBody::attitude`], whose `Π(am u, n|m) = u − ν J(u)`) by its addition theorem
//!
//! ```text
//!   J(u + h) = J(u) + J(h) + atan2(ρ sn u sn h sn(u+h),  1 + ν sn²(u+h) − ν sn u sn h cn(u+h) dn(u+h)) / ρ
//!   ρ = √(ν (m + ν)(1 + ν))
//! ```
//!
//! — Jacobi's addition theorem of the integral of the third kind (the Legendre form is DLMF §19.11(i), Carlson's
//! form DLMF 19.26.9: the extra term is an `R_C`, elementary), written for the imaginary parameter `a` of
//! `n = m sn²a < 0`, where the logarithm of Jacobi's form becomes this arctangent. The second argument of the
//! arctangent is ≥ 1 (so the principal value is the continuous one); the identity is checked against the direct
//! evaluation (Carlson `R_J`) in the tests, and was checked against mpmath quadrature to 1e-30 when derived.
//! The rest of the attitude (L&L §37, see [`TorqueFreeBody::attitude`]) is algebraic in sn, cn, dn: the nutation
//! and spin half-angles follow from `H_p` by half-angle formulas (no atan2, no sine), so a row costs one arctangent,
//! one sine–cosine pair (of the precession angle) and a few square roots.
//!
//! Round-off: the recurrences are neutrally stable, so their rounding errors accumulate (measured: see
//! [`ANCHOR_ROWS`]); every [`ANCHOR_ROWS`] rows the walk restarts from a direct evaluation, which bounds the error
//! independently of the number of rows. The separatrix and stationary motions are evaluated directly at every row.
//! Nothing in a row's error grows with t: the direct evaluation carries `τ = λt + τ₀`, its reduction by 2K and the
//! precession angle's secular part in double-double ([`TorqueFreeBody::attitude`]); the walk's step h = λ·every and
//! φ's increment per row are formed the same way once, and each row follows the rounding of its own time
//! t_k = k·every to first order (so its state is at τ(t_k), as the direct evaluation's is).

use nalgebra::{Matrix3, UnitQuaternion, Vector3};

use super::double_double::{Dd, FOUR_PI};
use super::torque_free::{
    Elliptic, Regime, TorqueFreeBody, half_period_sign, precession_nutation_spin,
};
use crate::trig::small_sin_cos;

/// Rows between two direct evaluations of the walk, chosen from the measured round-off growth of the recurrences
/// (test `roundoff_growth_without_reanchoring_sets_the_anchor_interval`, docs/book/src/explanation/performance.md): for the benchmark
/// body, never re-anchored, the attitude's difference from the direct evaluation grows with the number of rows r —
/// at h = λ·every ≈ 0.004: 9.9e-15 rad after 256 rows, 2.9e-14 after 1000 and after 10⁴, 5.7e-14 after 10⁵ (ω: 8.8e-16,
/// 4.6e-15, 4.6e-15, 1.1e-14); at h ≈ 0.04, about in proportion to r: 2.5e-15, 4.9e-15, 5.0e-14, 6.3e-13.
/// 256 rows keep the walk's own error ~10× below 1e-13; the direct evaluation (~0.23 µs) then costs ~1 ns a row.
pub const ANCHOR_ROWS: u64 = 256;

/// The rows `k = 0, 1, 2, …` of [`TorqueFreeBody::equal_grid`]: `(t_k, ω(t_k), q(t_k))`, `t_k = k·every` (the
/// binary64 product, as [`crate::integrate::Schedule::time`] forms it), ω in the principal axes and q principal →
/// space (or in the axes of [`EqualGrid::in_axes`]). An endless iterator.
#[derive(Debug, Clone)]
pub struct EqualGrid<'a> {
    body: &'a TorqueFreeBody,
    every: f64,
    next: u64,
    anchor_rows: u64,
    /// Rows until the next direct evaluation.
    until_anchor: u64,
    /// The axes of the rows as a rotation from them to the principal axes (identity: principal axes).
    axes_q: UnitQuaternion<f64>,
    walk: Option<Walk<'a>>,
}

impl TorqueFreeBody {
    /// The motion on the equal grid `t_k = k·every`, `k = 0, 1, 2, …`, advanced row by row by addition theorems
    /// (see [`EqualGrid`]); agrees with [`Self::omega_p`] and [`Self::attitude`] to round-off (≤ 1e-13).
    pub fn equal_grid(&self, every: f64) -> EqualGrid<'_> {
        let walk = match &self.regime {
            Regime::Elliptic(e) if !e.separatrix && e.jac.mc() > 0.0 && every.is_finite() => {
                Some(Walk::new(e, every))
            }
            _ => None,
        };
        EqualGrid {
            body: self,
            every,
            next: 0,
            anchor_rows: ANCHOR_ROWS,
            until_anchor: 0,
            axes_q: UnitQuaternion::identity(),
            walk,
        }
    }
}

impl EqualGrid<'_> {
    /// The same grid restarted from a direct evaluation every `rows` rows instead of [`ANCHOR_ROWS`] (at least 1;
    /// 1 is the direct evaluation at every row). For measuring the recurrences' round-off growth.
    ///
    /// ```
    /// use eulerdyn::exact::TorqueFreeBody;
    /// use nalgebra::{UnitQuaternion, Vector3};
    /// let body = TorqueFreeBody::new(
    ///     Vector3::new(1.0, 2.0, 3.0),
    ///     Vector3::new(0.3, 0.0, 2.0),
    ///     UnitQuaternion::identity(),
    /// )?;
    /// // Anchored at every row, each row's ω is the direct evaluation's.
    /// for (t, omega_p, _) in body.equal_grid(0.1).with_anchor_rows(1).take(1000) {
    ///     assert_eq!(omega_p, body.omega_p(t));
    /// }
    /// # Ok::<(), Box<dyn std::error::Error>>(())
    /// ```
    pub fn with_anchor_rows(mut self, rows: u64) -> Self {
        self.anchor_rows = rows.max(1);
        self
    }

    /// The same grid with ω in other axes b and the attitude b → space, `axes_q` being the rotation principal → b
    /// (`v_b = axes_q · v_p`, the principal axes' matrix in b): ω_b = axes_q · ω_p and q_b = q_p ⊗ axes_q⁻¹, folded
    /// into the constants of the walk.
    pub fn in_axes(mut self, axes_q: &UnitQuaternion<f64>) -> Self {
        self.axes_q = *axes_q;
        if let Some(walk) = &mut self.walk {
            walk.set_axes(axes_q);
        }
        self
    }

    /// Whether rows are advanced by the addition theorems (false: each row is evaluated directly — stationary
    /// motion and the separatrix).
    pub fn is_walk(&self) -> bool {
        self.walk.is_some()
    }
}

impl Iterator for EqualGrid<'_> {
    type Item = (f64, Vector3<f64>, UnitQuaternion<f64>);

    fn next(&mut self) -> Option<Self::Item> {
        let k = self.next;
        self.next += 1;
        let t = k as f64 * self.every;
        let Some(walk) = &mut self.walk else {
            let (omega_p, q_p) = (self.body.omega_p(t), self.body.attitude(t));
            return Some((t, self.axes_q * omega_p, q_p * self.axes_q.inverse()));
        };
        if self.until_anchor == 0 {
            walk.anchor(t);
            self.until_anchor = self.anchor_rows - 1;
        } else {
            walk.advance(t);
            self.until_anchor -= 1;
        }
        Some((t, walk.omega(), walk.attitude(t)))
    }
}

/// The walk: the step's constants and the state at the last row.
#[derive(Debug, Clone)]
struct Walk<'a> {
    e: &'a Elliptic,
    /// m and m′ = 1 − m.
    m: f64,
    mc: f64,
    /// sn h, cn h, dn h, cn h dn h, sn h dn h, m sn h cn h, m sn²h.
    step: [f64; 7],
    /// φ's increment per row for the exact step: `(M/I₁)·every + κ·3J(h)` (3J in the units of
    /// [`Elliptic::g_integral`]), in double-double, reduced modulo 4π.
    phi_step: Dd,
    /// The part of h = λ·every (double-double, reduced by 2K) that sn h, cn h, dn h do not see: added to each
    /// row's first-order correction.
    h_rest: f64,
    /// ν = −n, ρ and 3/ρ (J's addition theorem); unused when n = 0.
    nu: f64,
    rho: f64,
    three_over_rho: f64,
    /// 1/(2K(m)), for the half-period count of a row.
    inv_two_k: f64,
    /// The grid step (s), and λ.
    every: f64,
    lambda: f64,
    /// ω = omega_of · (cn τ, sn τ, dn τ): the output axes from the canonical frame, times diag(a, ε b, c).
    omega_of: Matrix3<f64>,
    /// The constant right factor of the attitude: canonical → output axes (P, then the axes' rotation).
    right: UnitQuaternion<f64>,
    /// sn, cn, dn of τ at the last row (unreduced).
    s: f64,
    c: f64,
    d: f64,
    /// The last row's time and cos, sin of half its precession angle φ.
    t: f64,
    cos_half_phi: f64,
    sin_half_phi: f64,
}

impl<'a> Walk<'a> {
    /// The step's constants: h = λ·every in double-double reduced by 2K (so that a step of many half periods is as
    /// exact as a short one), sn h, cn h, dn h at it, and φ's increment with its secular part
    /// `(M/I₁)·every + j_h·2κR_J(0, m′, 1, 1−n)` in double-double (see [`TorqueFreeBody::attitude`]).
    fn new(e: &'a Elliptic, every: f64) -> Self {
        let ((s, c, d, j), h_rest) = e.reduce_tau(e.lambda_dd * every);
        let sign = half_period_sign(j);
        let (sh, ch, dh) = (sign * s, sign * c, d);
        let m = e.jac.m();
        let nu = -e.n;
        let rho = (nu * (m + nu) * (1.0 + nu)).sqrt();
        let mut phi_step = e.phi_rate * every;
        if e.n != 0.0 {
            phi_step = phi_step + e.phi_per_half_period * j + e.kappa * e.g_integral(s, c, d, 0.0);
        }
        let mut walk = Self {
            e,
            m,
            mc: e.jac.mc(),
            step: [sh, ch, dh, ch * dh, sh * dh, m * sh * ch, m * sh * sh],
            phi_step: phi_step.reduce(FOUR_PI),
            h_rest,
            nu,
            rho,
            three_over_rho: 3.0 / rho,
            inv_two_k: 0.5 / e.jac.quarter_period(),
            every,
            lambda: e.lambda,
            omega_of: Matrix3::identity(),
            right: e.q_perm,
            s: 0.0,
            c: 1.0,
            d: 1.0,
            t: 0.0,
            cos_half_phi: 1.0,
            sin_half_phi: 0.0,
        };
        walk.set_axes(&UnitQuaternion::identity());
        walk
    }

    /// Output in the axes of [`EqualGrid::in_axes`].
    fn set_axes(&mut self, axes_q: &UnitQuaternion<f64>) {
        let e = self.e;
        let scale = Matrix3::from_diagonal(&Vector3::new(e.a, e.eps * e.b, e.c));
        self.omega_of = axes_q.to_rotation_matrix().matrix() * e.perm.transpose() * scale;
        self.right = e.q_perm * axes_q.inverse();
    }

    /// Restart from the direct evaluation at t ([`TorqueFreeBody::attitude`]'s: τ, its reduction and the precession
    /// angle's secular part in double-double, φ reduced modulo 4π).
    fn anchor(&mut self, t: f64) {
        let e = self.e;
        let (tau, (s, c, d, j)) = e.phase(t);
        let sign = half_period_sign(j);
        (self.s, self.c, self.d) = (sign * s, sign * c, d);
        let phi = e.phi(t, tau, s, c, d, j);
        (self.sin_half_phi, self.cos_half_phi) = (0.5 * phi).sin_cos();
        self.t = t;
    }

    /// One row on, to t: DLMF 22.8.1–22.8.3 by the step h = λ·every, then by the rest of the row's own step,
    /// `δ = λ(t − t_prev) − h` (the rounding of t_k = k·every, a few ulp(t)·λ; the difference of two rows' times is
    /// exact) to first order (DLMF 22.13.1–22.13.3: sn′ = cn dn, cn′ = −sn dn, dn′ = −m sn cn; the second order is
    /// ~1e-27), so that the state is at τ(t_k) and not at λ·k·every + τ₀, which differ by up to λ·ulp(t). φ turns
    /// by [`Self::phi_increment`]. (No `mul_add`: without the FMA instruction in the target it is a call.)
    fn advance(&mut self, t: f64) {
        let [sh, ch, dh, ch_dh, sh_dh, m_sh_ch, m_sh2] = self.step;
        let (s, c, d) = (self.s, self.c, self.d);
        let inv = 1.0 / (1.0 - m_sh2 * s * s);
        let s1 = (s * ch_dh + sh * c * d) * inv;
        let c1 = (c * ch - s * d * sh_dh) * inv;
        let d1 = (d * dh - m_sh_ch * s * c) * inv;
        let dt = t - self.t;
        let delta = self.lambda * (dt - self.every) + self.h_rest;
        let d_phi = self.phi_increment(s * sh, (s1, c1, d1), dt, delta);
        let (s1, c1, d1) = (
            s1 + delta * c1 * d1,
            c1 - delta * s1 * d1,
            d1 - delta * self.m * s1 * c1,
        );
        // Back onto the curve sn² + cn² = 1, dn² = m′ + m cn² (DLMF 22.6.1), one Newton step each: off the curve
        // the addition theorems are not a translation, and the deviation would grow from row to row.
        let scale = 0.5 * (3.0 - (s1 * s1 + c1 * c1));
        let (s1, c1) = (s1 * scale, c1 * scale);
        let d1 = 0.5 * (d1 + (self.mc + self.m * c1 * c1) / d1);
        let (sin_d, cos_d) = small_sin_cos(0.5 * d_phi);
        let (cos_f, sin_f) = (self.cos_half_phi, self.sin_half_phi);
        self.cos_half_phi = cos_f * cos_d - sin_f * sin_d;
        self.sin_half_phi = sin_f * cos_d + cos_f * sin_d;
        (self.s, self.c, self.d, self.t) = (s1, c1, d1, t);
    }

    /// φ's increment over a row (modulo 4π): the constant [`Walk::phi_step`] for the step h (in double-double, its
    /// low part added here), plus the rest of the time part `(M/I₁)(dt − every)`, plus κ times 3× the increment
    /// of J beyond J(h) — the arctangent of J's addition theorem (module docs), from `ss = sn u sn h` and sn, cn, dn
    /// of `u + h` — and `J′(u + h)·δ`, `J′ = sn²/(1 + ν sn²)`, for the rest δ of the row's τ-step.
    fn phi_increment(&self, ss: f64, (s1, c1, d1): (f64, f64, f64), dt: f64, delta: f64) -> f64 {
        let e = self.e;
        let mut rest = self.phi_step.lo + e.phi_rate.hi * (dt - self.every);
        if self.nu != 0.0 {
            let s1_2 = s1 * s1;
            let y = 1.0 + self.nu * (s1_2 - ss * c1 * d1);
            let j_delta = 3.0 * delta * s1_2 / (1.0 + self.nu * s1_2);
            rest += e.kappa * (j_delta + self.three_over_rho * (self.rho * ss * s1).atan2(y));
        }
        self.phi_step.hi + rest
    }

    /// ω in the output axes (L&L §37: ω₁ = a cn τ, ω₂ = ε b sn τ, ω₃ = c dn τ canonically).
    fn omega(&self) -> Vector3<f64> {
        self.omega_of * Vector3::new(self.c, self.s, self.d)
    }

    /// The attitude at t from the walk's state: [`TorqueFreeBody::attitude`]'s `q_fixed ⊗ R_z(φ) R_x(θ) R_z(ψ) ⊗ P`
    /// (then the output axes) with the half-angles of θ and ψ from `H_p` by half-angle formulas.
    fn attitude(&self, t: f64) -> UnitQuaternion<f64> {
        let e = self.e;
        // The half-period count j of τ = 2jK + r and the reduced sn r, cn r ≥ 0 (as Elliptic::q_h uses them).
        // j = ⌊τ/2K + ½⌋ (τ ≥ τ₀ ≥ −K, so τ/2K + 3/2 > 0 and the conversion truncates to the floor; no call to
        // `round`, which is one without SSE4.1; which side a tie goes to does not matter: q is continuous there).
        let j = ((e.lambda * t + e.tau0) * self.inv_two_k + 1.5) as i64 - 1;
        let sign = if j & 1 == 1 { -1.0 } else { 1.0 };
        let half = e.half_angles(sign * self.c, sign * self.s, self.d, j);
        let q_h = precession_nutation_spin(self.cos_half_phi, self.sin_half_phi, half);
        e.q_fixed * UnitQuaternion::new_unchecked(q_h) * self.right
    }
}
