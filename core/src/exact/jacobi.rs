//! Jacobi elliptic functions sn, cn, dn and the amplitude am, written by hand.
//!
//! Method:
//!
//! * `m ≤ ½`: the descending Landen (Gauss) transformation (A&S 16.12, DLMF 22.7.1–22.7.3;
//!   the function-value form of the AGM scheme A&S 16.4 / DLMF 22.20) drives the parameter to
//!   `< 1e-12`, the functions are evaluated there by the small-m expansion A&S 16.13.1–16.13.3,
//!   and carried back up with
//!
//!   ```text
//!     k₁ = (1 − k′)/(1 + k′) = k²/(1 + k′)²,   w = z/(1 + k₁),   (s, c, d) at (w | k₁²)
//!     sn(z|k²) = (1 + k₁) s / (1 + k₁ s²)
//!     cn(z|k²) = c d / (1 + k₁ s²)
//!     dn(z|k²) = ((1 − k₁) + k₁ c²) / (1 + k₁ s²)          [= (1 − k₁s²)/(1 + k₁s²)]
//!   ```
//!
//! * `m > ½`: the ascending Landen transformation (A&S 16.14, DLMF 22.7.4–22.7.6)
//!   drives m′ to `< 1e-16`, the functions are evaluated by the small-m′ expansion
//!   A&S 16.15.1–16.15.3 (tanh/sech plus the first-order m′ term), and carried back down with
//!
//!   ```text
//!     k₂′ = (1 − k)/(1 + k) = k′²/(1 + k)²,   k₂ = 2√k/(1 + k)
//!     w = z/(1 + k₂′),   (s, c, d) at (w | k₂²)
//!     sn(z|k²) = (1 + k₂′) s c / d
//!     cn(z|k²) = (1 + k₂′)(d² − k₂′)/(k₂² d)
//!     dn(z|k²) = (1 − k₂′)(d² + k₂′)/(k₂² d)
//!   ```
//!
//!   (Repeated descending steps near m = 1 act like repeated squaring of sech and double the
//!   relative error of cn, dn per level; the ascending chain needs only ~4 levels there and
//!   its one subtraction `d² − k₂′` is bounded away from cancellation because `w ≤ K₂/4`.)
//!
//! Before the transformation the argument is reduced to `z ∈ [0, K/2]` with the half-period
//! symmetries `sn(u + 2K) = −sn u`, `cn(u + 2K) = −cn u`, `dn(u + 2K) = dn u` and the quarter
//! period shift `sn(K − z) = cd z`, `cn(K − z) = k′ sd z`, `dn(K − z) = k′ nd z`
//! (DLMF §22.4(iii)), so `cn` and `dn` keep their relative accuracy up to `u = K`.
//! `K(m)` is Carlson's `R_F(0, m′, 1)` (DLMF 19.25.1 — the form `ellip::ellipk` evaluates,
//! called here with the complementary parameter so that `m → 1` keeps full accuracy).
//!
//! Measured accuracy (against mpmath at 250 digits, 199 points on `[0, K)` for each of 17
//! parameters from `m = 1e-300` to `m′ = 1e-100`): the error never exceeds 6 ulp times
//! `max(1, κ)`, where `κ = |u f′(u)/f(u)|` is the condition number of `f ∈ {sn, cn, dn}` with
//! respect to `u`: the error is at most 6 ulp or the effect of perturbing `u` by 6 ulp,
//! whichever is larger. Where
//! `κ ≲ 1` this is a few ulp relative (sn everywhere: ≤ 4.2 ulp; dn for `m ≤ 0.99`: ≤ 4.3 ulp).
//! Larger forward errors occur only where the function itself is ill-conditioned: `cn` near
//! its zero at `u = K`, and `cn`, `dn ≈ sech u` for `m → 1` where `u` ranges up to
//! `K ≈ ½ ln(16/m′)`. For `|u| > K` the reduction `u − 2jK` uses the rounded `K`, adding an
//! absolute error of about `(|u|/K)·ulp(K)`.
//! The parameter is carried as the pair (m, m′ = 1 − m); there is no cancellation except the
//! one bounded subtraction of the ascending step.

use ellip::elliprf;
use std::f64::consts::{FRAC_PI_2, PI};

/// Stop the Landen descent once the parameter is below this; the first-order expansion
/// A&S 16.13 then has a relative error O(m²) < 1e-24.
const BOTTOM_M: f64 = 1e-12;
/// Stop the Landen ascent once m′ is below this; the first-order expansion A&S 16.15 then has
/// a relative error O(m′^1.4) < 1e-22 on `w ≤ K/4`.
const TOP_MC: f64 = 1e-16;
/// Enough for any `m ∈ (0, 1)` representable in f64 (m′ down to the smallest subnormal
/// needs ≈ 12 levels).
const MAX_LEVELS: usize = 40;

/// The Jacobi elliptic functions of one fixed parameter `m = k²`, with the Landen chain and
/// the quarter period `K(m)` precomputed.
///
/// `sn(u|m)`, `cn(u|m)`, `dn(u|m)` are defined by `sn = sin φ`, `cn = cos φ`,
/// `dn = √(1 − m sin²φ)` with `φ = am(u|m)` the inverse of `u = F(φ|m)` (DLMF 22.2, 22.16.1).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct JacobiElliptic {
    m: f64,
    mc: f64,
    kc: f64,
    quarter_period: f64,
    /// Descending chain (m ≤ ½): `(k₁, 1 − k₁)` per level. Ascending chain (m > ½):
    /// `(k₂′, k₂²)` per level. The first `n_levels` entries are used.
    levels: [(f64, f64); MAX_LEVELS],
    n_levels: usize,
    ascending: bool,
    /// `1 / Π (1 + k₁)` (descending) or `1 / Π (1 + k₂′)` (ascending): the argument scale at
    /// the end of the chain.
    inv_scale: f64,
    /// The parameter m (descending) or m′ (ascending) at the end of the chain.
    m_end: f64,
}

/// The result of reducing `u = 2K·j + r`, `r ∈ [−K, K]`: `sn u = (−1)^j sn r`,
/// `cn u = (−1)^j cn r`, `dn u = dn r`, `am u = jπ + am r` (DLMF §22.4(iii), 22.16.2).
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct Reduced {
    /// Number of half periods 2K (an integer stored as f64; 0 for m = 1).
    pub j: f64,
    /// sn(r), cn(r) ≥ 0, dn(r) of the reduced argument.
    pub sn: f64,
    pub cn: f64,
    pub dn: f64,
}

impl Reduced {
    /// sn, cn, dn of the unreduced argument.
    pub fn values(&self) -> (f64, f64, f64) {
        let sign = if is_odd(self.j) { -1.0 } else { 1.0 };
        (sign * self.sn, sign * self.cn, self.dn)
    }
}

fn is_odd(j: f64) -> bool {
    (j % 2.0).abs() == 1.0
}

impl JacobiElliptic {
    /// Prepare sn, cn, dn for the parameter `m` (`0 ≤ m ≤ 1`). Returns `None` for `m`
    /// outside `[0, 1]` or not finite.
    pub fn new(m: f64) -> Option<Self> {
        if !(0.0..=1.0).contains(&m) {
            return None;
        }
        Self::with_complement(m, 1.0 - m)
    }

    /// As [`JacobiElliptic::new`], with the complementary parameter `mc = 1 − m` supplied by
    /// the caller, who can often form it without the cancellation of `1 − m` (this matters
    /// for `m → 1`, where `K(m) ≈ ½ ln(16/mc)`). Requires `m, mc ≥ 0` and
    /// `|m + mc − 1| ≤ 1e-12`.
    ///
    /// ```
    /// use eulerdyn::exact::JacobiElliptic;
    /// // 1 − 1e-20 rounds to 1 (K = ∞); with m′ given, K = ½ ln(16/m′) + O(m′ ln m′) (DLMF 19.12.1).
    /// assert_eq!(JacobiElliptic::new(1.0 - 1e-20).unwrap().quarter_period(), f64::INFINITY);
    /// let jac = JacobiElliptic::with_complement(1.0 - 1e-20, 1e-20).unwrap();
    /// assert!((jac.quarter_period() - 0.5 * (16.0f64 / 1e-20).ln()).abs() < 1e-13);
    /// ```
    pub fn with_complement(m: f64, mc: f64) -> Option<Self> {
        if !(m.is_finite() && mc.is_finite() && m >= 0.0 && mc >= 0.0) {
            return None;
        }
        if (m + mc - 1.0).abs() > 1e-12 {
            return None;
        }
        let kc = mc.sqrt();
        let mut levels = [(0.0, 1.0); MAX_LEVELS];
        let mut n_levels = 0;
        let mut inv_scale = 1.0;
        let ascending = m > 0.5;
        let mut m_end = if ascending { mc } else { m };
        if ascending && mc > 0.0 {
            let mut k_n = m.sqrt();
            while m_end > TOP_MC && n_levels < MAX_LEVELS {
                // k₂′ = (1 − k)/(1 + k) = k′²/(1 + k)², k₂ = 2√k/(1 + k)  (A&S 16.14).
                let kc2 = m_end / ((1.0 + k_n) * (1.0 + k_n));
                let k2 = 2.0 * k_n.sqrt() / (1.0 + k_n);
                levels[n_levels] = (kc2, k2 * k2);
                n_levels += 1;
                inv_scale /= 1.0 + kc2;
                k_n = k2;
                m_end = kc2 * kc2;
            }
        } else if !ascending && m > 0.0 {
            let mut kc_n = kc;
            while m_end > BOTTOM_M && n_levels < MAX_LEVELS {
                // k₁ = (1 − k′)/(1 + k′) = k²/(1 + k′)², k₁′ = 2√k′/(1 + k′)  (A&S 16.12).
                let k1 = m_end / ((1.0 + kc_n) * (1.0 + kc_n));
                let one_minus_k1 = 2.0 * kc_n / (1.0 + kc_n);
                levels[n_levels] = (k1, one_minus_k1);
                n_levels += 1;
                inv_scale /= 1.0 + k1;
                kc_n = 2.0 * kc_n.sqrt() / (1.0 + kc_n);
                m_end = k1 * k1;
            }
        }
        let quarter_period = if mc == 0.0 {
            f64::INFINITY
        } else if m == 0.0 {
            FRAC_PI_2
        } else {
            // K(m) = R_F(0, 1 − m, 1) (DLMF 19.25.1). R_F(0, mc, 1) with 0 < mc ≤ 1 is always
            // in ellip's domain; the fallback (the arithmetic-geometric mean, DLMF §19.8(i))
            // only guards against a future change of its error reporting.
            elliprf(0.0, mc, 1.0).unwrap_or_else(|_| FRAC_PI_2 / agm(1.0, kc))
        };
        Some(Self {
            m,
            mc,
            kc,
            quarter_period,
            levels,
            n_levels,
            ascending,
            inv_scale,
            m_end,
        })
    }

    /// The parameter m.
    pub fn m(&self) -> f64 {
        self.m
    }

    /// The complementary parameter m′ = 1 − m.
    pub fn mc(&self) -> f64 {
        self.mc
    }

    /// The quarter period `K(m) = F(π/2|m)` (DLMF §19.2(ii)); `+∞` for `m = 1`.
    pub fn quarter_period(&self) -> f64 {
        self.quarter_period
    }

    /// `(sn(u|m), cn(u|m), dn(u|m))` (DLMF 22.2); NaN for non-finite `u`.
    pub fn sn_cn_dn(&self, u: f64) -> (f64, f64, f64) {
        self.reduce(u).values()
    }

    /// The amplitude `am(u|m)` (DLMF 22.16.1), continuous in `u`:
    /// `am(u + 2K) = am(u) + π` (DLMF 22.16.2), so it is not wrapped to `(−π, π]`.
    /// For `m = 1`, `am(u|1) = gd(u) = atan(sinh u)` (the Gudermannian function).
    pub fn amplitude(&self, u: f64) -> f64 {
        if self.m == 0.0 {
            return u;
        }
        if self.mc == 0.0 {
            return u.sinh().atan();
        }
        let red = self.reduce(u);
        red.j * PI + red.sn.atan2(red.cn)
    }

    /// Reduce `u = 2K·j + r` with `|r| ≤ K` and evaluate sn, cn, dn at `r`.
    pub(crate) fn reduce(&self, u: f64) -> Reduced {
        if !u.is_finite() {
            return Reduced {
                j: 0.0,
                sn: f64::NAN,
                cn: f64::NAN,
                dn: f64::NAN,
            };
        }
        if self.m == 0.0 {
            // Circular limit: keep libm's exact argument reduction by π.
            let j = (u / PI).round();
            let (s, c) = u.sin_cos();
            let sign = if is_odd(j) { -1.0 } else { 1.0 };
            // sign·(s, c) = (sin r, cos r), r = u − jπ, with cos r ≥ 0 (up to rounding).
            let cn = (sign * c).max(0.0);
            return Reduced {
                j,
                sn: sign * s,
                cn,
                dn: 1.0,
            };
        }
        if self.mc == 0.0 {
            return self.at_reduced(0.0, u);
        }
        let k = self.quarter_period;
        let two_k = 2.0 * k;
        let j = if u.abs() <= k {
            0.0
        } else {
            (u / two_k).round()
        };
        let r = if j == 0.0 { u } else { (-j).mul_add(two_k, u) };
        self.at_reduced(j, r)
    }

    /// sn, cn, dn at `r`, the reduced argument of `u = 2K·j + r` (`|r| ≤ K` up to rounding) that the caller formed,
    /// e.g. in higher precision than binary64 so that `r` carries no error growing with `|u|`
    /// ([`crate::exact::TorqueFreeBody`] reduces `τ = λt + τ₀` in double-double). `m = 1` (no reduction) takes
    /// `j = 0`, `r = u`.
    pub(crate) fn at_reduced(&self, j: f64, r: f64) -> Reduced {
        if self.m == 0.0 {
            // Circular limit: sin, cos of r (K = π/2).
            let (sn, cn) = r.sin_cos();
            return Reduced {
                j,
                sn,
                cn: cn.max(0.0),
                dn: 1.0,
            };
        }
        if self.mc == 0.0 {
            // Hyperbolic limit (DLMF §22.5(iv)): sn = tanh, cn = dn = sech.
            let sech = 1.0 / r.cosh();
            return Reduced {
                j: 0.0,
                sn: r.tanh(),
                cn: sech,
                dn: sech,
            };
        }
        let k = self.quarter_period;
        let z = r.abs();
        let (s, c, d) = if z <= 0.5 * k {
            self.landen(z)
        } else {
            // Quarter-period shift (DLMF §22.4(iii)), w = K − z ∈ [−ulp, K/2].
            let (s, c, d) = self.landen(k - z);
            (c / d, self.kc * s / d, self.kc / d)
        };
        Reduced {
            j,
            sn: if r < 0.0 { -s } else { s },
            cn: c,
            dn: d,
        }
    }

    /// sn, cn, dn for `|z| ≤ K/2` (plus rounding) by the descending or ascending Landen chain.
    fn landen(&self, z: f64) -> (f64, f64, f64) {
        let w = z * self.inv_scale;
        let levels = &self.levels[..self.n_levels];
        if self.ascending {
            // A&S 16.15.1–16.15.3 with m₁ = m′ at the top of the chain.
            let m1 = self.m_end;
            let (sh, ch) = (w.sinh(), w.cosh());
            let (th, sech) = (sh / ch, 1.0 / ch);
            let a = 0.25 * m1 * (sh * ch - w);
            let b = 0.25 * m1 * (sh * ch + w);
            let mut sn = th + a * sech * sech;
            let mut cn = sech - a * th * sech;
            let mut dn = sech + b * th * sech;
            for &(kc2, m2) in levels.iter().rev() {
                let d2 = dn * dn;
                let sn_dn = (1.0 + kc2) * sn * cn / dn;
                let cn_dn = (1.0 + kc2) * (d2 - kc2) / (m2 * dn);
                let dn_dn = (1.0 - kc2) * (d2 + kc2) / (m2 * dn);
                sn = sn_dn;
                cn = cn_dn;
                dn = dn_dn;
            }
            (sn, cn, dn)
        } else {
            // A&S 16.13.1–16.13.3 with the parameter at the bottom of the chain.
            let mb = self.m_end;
            let (sw, cw) = w.sin_cos();
            let corr = 0.25 * mb * (w - sw * cw);
            let mut sn = sw - corr * cw;
            let mut cn = cw + corr * sw;
            let mut dn = 1.0 - 0.5 * mb * sw * sw;
            for &(k1, one_minus_k1) in levels.iter().rev() {
                let den = 1.0 + k1 * sn * sn;
                let sn_up = (1.0 + k1) * sn / den;
                let cn_up = cn * dn / den;
                let dn_up = (one_minus_k1 + k1 * cn * cn) / den;
                sn = sn_up;
                cn = cn_up;
                dn = dn_up;
            }
            (sn, cn, dn)
        }
    }
}

/// Arithmetic-geometric mean (DLMF §19.8(i)), used only as a fallback for K.
fn agm(mut a: f64, mut b: f64) -> f64 {
    for _ in 0..64 {
        if (a - b).abs() <= 4.0 * f64::EPSILON * a {
            break;
        }
        let a1 = 0.5 * (a + b);
        b = (a * b).sqrt();
        a = a1;
    }
    0.5 * (a + b)
}

/// Jacobi elliptic functions `(sn(u|m), cn(u|m), dn(u|m))` for the parameter `0 ≤ m ≤ 1`
/// (`m = k²`).
///
/// Definition DLMF 22.2 / A&S 16.1; computed by the descending Landen transformation for
/// `m ≤ ½` (A&S 16.12, DLMF 22.7.1–22.7.3, the function-value form of the AGM scheme A&S 16.4,
/// DLMF 22.20) and the ascending one for `m > ½` (A&S 16.14, DLMF 22.7.4–22.7.6), after
/// reducing `u` by the half period `2K(m)` and the quarter-period shift
/// (DLMF §22.4(iii)). Limits: `m = 0` gives `(sin u, cos u, 1)`, `m = 1` gives
/// `(tanh u, sech u, sech u)` (DLMF §22.5(iv)); both limits are approached continuously.
///
/// Returns NaNs if `m ∉ [0, 1]` or either argument is not finite. For repeated evaluation at
/// one `m`, build a [`JacobiElliptic`] once.
pub fn sn_cn_dn(u: f64, m: f64) -> (f64, f64, f64) {
    match JacobiElliptic::new(m) {
        Some(j) => j.sn_cn_dn(u),
        None => (f64::NAN, f64::NAN, f64::NAN),
    }
}

/// The Jacobi amplitude `am(u|m)`, the inverse of `u = F(φ|m)` (DLMF 22.16.1),
/// continued continuously in `u` (`am(u + 2K) = am(u) + π`, DLMF 22.16.2), not wrapped.
/// `am(u|0) = u`, `am(u|1) = gd(u)`. NaN if `m ∉ [0, 1]` or `u` is not finite.
pub fn amplitude(u: f64, m: f64) -> f64 {
    match JacobiElliptic::new(m) {
        Some(j) if u.is_finite() => j.amplitude(u),
        _ => f64::NAN,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    const PARAMS: [f64; 14] = [
        0.0,
        1e-300,
        1e-12,
        1e-6,
        0.01,
        0.1,
        0.36,
        0.5,
        0.7,
        0.9,
        0.99,
        0.999999,
        1.0 - 1e-12,
        1.0,
    ];

    fn rel(a: f64, b: f64) -> f64 {
        if b == 0.0 {
            a.abs()
        } else {
            ((a - b) / b).abs()
        }
    }

    #[test]
    fn pythagorean_identities() {
        // DLMF 22.6.1: sn² + cn² = 1, dn² + m sn² = 1.
        for &m in &PARAMS {
            for i in -200..=200 {
                let u = 0.0731 * f64::from(i);
                let (s, c, d) = sn_cn_dn(u, m);
                assert!(
                    (s * s + c * c - 1.0).abs() <= 8.0 * f64::EPSILON,
                    "m={m} u={u}"
                );
                assert!(
                    (d * d + m * s * s - 1.0).abs() <= 8.0 * f64::EPSILON,
                    "m={m} u={u}"
                );
            }
        }
    }

    #[test]
    fn quarter_period_values() {
        // DLMF §22.5(i) special values: sn K = 1, cn K = 0, dn K = k′, and
        // sn(K/2) = (1 + k′)^(-1/2), cn(K/2) = (k′/(1 + k′))^(1/2), dn(K/2) = k′^(1/2).
        for &m in &PARAMS[..PARAMS.len() - 1] {
            let j = JacobiElliptic::new(m).expect("valid m");
            let k = j.quarter_period();
            let kc = (1.0 - m).sqrt();
            let (s, c, d) = j.sn_cn_dn(k);
            assert!((s - 1.0).abs() <= f64::EPSILON, "m={m}");
            assert!(c.abs() <= f64::EPSILON, "m={m} cn={c}");
            assert!(rel(d, kc) <= 2.0 * f64::EPSILON, "m={m}");
            let (s, c, d) = j.sn_cn_dn(0.5 * k);
            assert!(
                rel(s, 1.0 / (1.0 + kc).sqrt()) <= 8.0 * f64::EPSILON,
                "m={m}"
            );
            assert!(
                rel(c, (kc / (1.0 + kc)).sqrt()) <= 16.0 * f64::EPSILON,
                "m={m}"
            );
            assert!(rel(d, kc.sqrt()) <= 16.0 * f64::EPSILON, "m={m}");
            // sn(2K) = 0, cn(2K) = −1, sn(3K) = −1, cn(4K) = 1.
            let (s, c, _) = j.sn_cn_dn(2.0 * k);
            assert!(s.abs() <= 4.0 * f64::EPSILON && (c + 1.0).abs() <= 4.0 * f64::EPSILON);
            let (s, _, _) = j.sn_cn_dn(3.0 * k);
            assert!((s + 1.0).abs() <= 4.0 * f64::EPSILON);
            let (_, c, _) = j.sn_cn_dn(4.0 * k);
            assert!((c - 1.0).abs() <= 4.0 * f64::EPSILON);
        }
        // K(1/2) = Γ(1/4)²/(4√π) (the lemniscatic case).
        let j = JacobiElliptic::new(0.5).expect("valid m");
        assert!(rel(j.quarter_period(), 1.854_074_677_301_371_9) <= 2.0 * f64::EPSILON);
    }

    /// (u, m, sn, cn, dn): computed with mpmath 1.3.0 `ellipfun` at 40 significant digits
    /// (arguments are the exact binary64 values shown).
    const REFERENCE: [(f64, f64, f64, f64, f64); 10] = [
        (
            0.2,
            0.36,
            0.198_202_950_103_046_12,
            0.980_161_002_371_778_4,
            0.992_903_627_048_145,
        ),
        (
            0.75342,
            0.7,
            0.651_373_512_613_176,
            0.758_757_238_559_193_3,
            0.838_450_226_874_667_2,
        ),
        (
            1.0,
            0.5,
            0.803_001_824_895_643_9,
            0.595_976_567_672_140_7,
            0.823_161_001_631_596_3,
        ),
        (
            2.5,
            0.9,
            0.999_694_538_450_586_1,
            0.024_714_971_010_898_663,
            0.317_095_800_686_263_6,
        ),
        (
            3.0,
            0.99,
            0.997_170_312_900_001_8,
            0.075_175_574_962_300_39,
            0.124_879_355_380_316_28,
        ),
        (
            0.5,
            1e-9,
            0.479_425_538_586_812_7,
            0.877_582_561_899_873,
            0.999_999_999_885_075_6,
        ),
        (
            10.0,
            0.3,
            0.278_487_316_264_899_4,
            -0.960_439_906_854_965,
            0.988_298_256_805_035_6,
        ),
        (
            4.0,
            1.0 - 1.0 / 1_099_511_627_776.0,
            0.999_329_299_739_293,
            0.036_618_993_467_518_97,
            0.036_618_993_479_920_66,
        ),
        (
            1.5,
            0.1,
            0.994_313_629_062_764_7,
            0.106_491_347_348_199_43,
            0.949_280_801_821_043_6,
        ),
        (
            7.0,
            0.999999,
            0.999_998_577_542_555_3,
            0.001_686_686_949_620_104_6,
            0.001_960_844_211_337_214_6,
        ),
    ];

    #[test]
    fn reference_values() {
        for &(u, m, s_ref, c_ref, d_ref) in &REFERENCE {
            let (s, c, d) = sn_cn_dn(u, m);
            // Relative accuracy is limited by the condition number |u f′/f| times ε; these
            // points have condition numbers ≤ 60 (the last one ≈ 7·tanh-like growth).
            let tol = 64.0 * f64::EPSILON * u.max(1.0);
            assert!(rel(s, s_ref) <= tol, "sn({u}|{m}) = {s}, want {s_ref}");
            assert!(rel(c, c_ref) <= tol, "cn({u}|{m}) = {c}, want {c_ref}");
            assert!(rel(d, d_ref) <= tol, "dn({u}|{m}) = {d}, want {d_ref}");
        }
    }

    #[test]
    fn small_u_accuracy() {
        // For |u| ≤ K/2 (the first three reference points) the result must be within a few ulp (no reduction
        // involved).
        for &(u, m, s_ref, c_ref, d_ref) in &REFERENCE[..3] {
            let (s, c, d) = sn_cn_dn(u, m);
            assert!(rel(s, s_ref) <= 4.0 * f64::EPSILON);
            assert!(rel(c, c_ref) <= 4.0 * f64::EPSILON);
            assert!(rel(d, d_ref) <= 4.0 * f64::EPSILON);
        }
    }

    #[test]
    fn limits_m0_and_m1() {
        for i in -100..=100 {
            let u = 0.37 * f64::from(i);
            let (s, c, d) = sn_cn_dn(u, 0.0);
            assert_eq!((s, c, d), (u.sin(), u.cos(), 1.0));
            let (s, c, d) = sn_cn_dn(u, 1.0);
            assert_eq!((s, c, d), (u.tanh(), 1.0 / u.cosh(), 1.0 / u.cosh()));
            // Continuity: m = 1e-300 and m′ = 1e-300 agree with the limits.
            let (s, c, d) = sn_cn_dn(u, 1e-300);
            assert!((s - u.sin()).abs() <= 1e-15 * u.abs().max(1.0));
            assert!((c - u.cos()).abs() <= 1e-15 * u.abs().max(1.0));
            assert_eq!(d, 1.0);
            let j = JacobiElliptic::with_complement(1.0, 1e-300).expect("valid");
            let (s, c, d) = j.sn_cn_dn(u);
            let sech = 1.0 / u.cosh();
            assert!(rel(s, u.tanh()) <= 4.0 * f64::EPSILON, "u={u}");
            assert!(rel(c, sech) <= 1e-14, "u={u} cn={c} sech={sech}");
            assert!(rel(d, sech) <= 1e-14, "u={u}");
        }
        // m → 0: sn(u|m) = sin u − ¼ m (u − sin u cos u) cos u + O(m²) (A&S 16.13.1).
        let (m, u) = (1e-7, 0.9_f64);
        let (s, _, _) = sn_cn_dn(u, m);
        let approx = u.sin() - 0.25 * m * (u - u.sin() * u.cos()) * u.cos();
        assert!((s - approx).abs() <= 1e-15);
    }

    #[test]
    fn derivative_identities() {
        // DLMF 22.13.1–22.13.3: d sn/du = cn dn, d cn/du = −sn dn, d dn/du = −m sn cn.
        let h = 1e-5;
        for &m in &[0.0, 1e-8, 0.3, 0.8, 0.9999, 1.0] {
            for i in -30..=30 {
                let u = 0.41 * f64::from(i) + 0.013;
                let (sp, cp, dp) = sn_cn_dn(u + h, m);
                let (sm, cm, dm) = sn_cn_dn(u - h, m);
                let (s, c, d) = sn_cn_dn(u, m);
                let ds = (sp - sm) / (2.0 * h);
                let dc = (cp - cm) / (2.0 * h);
                let dd = (dp - dm) / (2.0 * h);
                assert!((ds - c * d).abs() <= 1e-9, "m={m} u={u}");
                assert!((dc + s * d).abs() <= 1e-9, "m={m} u={u}");
                assert!((dd + m * s * c).abs() <= 1e-9, "m={m} u={u}");
            }
        }
    }

    #[test]
    fn periodicity_and_large_arguments() {
        for &m in &[0.2, 0.7, 0.99] {
            let j = JacobiElliptic::new(m).expect("valid m");
            let p = 4.0 * j.quarter_period();
            for i in 0..20 {
                let u = 0.29 * f64::from(i);
                let (s0, c0, d0) = j.sn_cn_dn(u);
                let (s1, c1, d1) = j.sn_cn_dn(u + 1000.0 * p);
                // u + 1000·4K ≈ 1.5e4 is itself rounded to ≈ 2e-12; the reduction adds
                // ≈ (|u|/K)·ulp(K) of the same size.
                assert!((s0 - s1).abs() <= 1e-11 && (c0 - c1).abs() <= 1e-11);
                assert!((d0 - d1).abs() <= 1e-11);
                let (s2, c2, d2) = j.sn_cn_dn(-u);
                assert_eq!((s2, c2, d2), (-s0, c0, d0));
            }
        }
    }

    #[test]
    fn amplitude_is_continuous_and_consistent() {
        for &m in &[0.0, 0.25, 0.9, 0.999_999, 1.0] {
            let j = JacobiElliptic::new(m).expect("valid m");
            let mut prev = j.amplitude(-20.0);
            for i in -1999..=2000 {
                let u = 0.01 * f64::from(i);
                let a = amplitude(u, m);
                assert!(a >= prev && a - prev <= 0.0101, "m={m} u={u}");
                prev = a;
                let (s, c, _) = j.sn_cn_dn(u);
                assert!((a.sin() - s).abs() <= 1e-14 && (a.cos() - c).abs() <= 1e-14);
            }
            if m < 1.0 {
                let k = j.quarter_period();
                assert!((j.amplitude(k) - FRAC_PI_2).abs() <= 4.0 * f64::EPSILON);
                assert!((j.amplitude(7.0 * k) - 3.5 * PI).abs() <= 1e-14);
                // am is the inverse of F (DLMF 22.16.1): am(F(φ|m)|m) = φ.
                for &phi in &[0.1, 1.0, 1.5, 3.0, 10.0] {
                    let f = ellip::ellipf(phi, m).expect("in domain");
                    assert!((j.amplitude(f) - phi).abs() <= 1e-14 * phi.max(1.0));
                }
            }
        }
    }

    #[test]
    fn invalid_parameter_gives_nan() {
        assert!(sn_cn_dn(0.3, -0.1).0.is_nan());
        assert!(sn_cn_dn(0.3, 1.1).1.is_nan());
        assert!(sn_cn_dn(f64::NAN, 0.5).2.is_nan());
        assert!(amplitude(f64::INFINITY, 0.5).is_nan());
        assert!(JacobiElliptic::new(f64::NAN).is_none());
        assert!(JacobiElliptic::with_complement(0.5, 0.6).is_none());
    }
}
