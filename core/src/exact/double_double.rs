//! Double-double arithmetic (≈ 106-bit significands) for the one-time constants of the torque-free attitude, and the
//! complete elliptic integrals K(m), Π(n|m) carried in it.
//!
//! A value is an unevaluated sum `hi + lo` with `|lo| ≤ ½ ulp(hi)`. The error-free transformations are Knuth's
//! TwoSum (TAOCP vol. 2, §4.2.2, Theorem B: `a + b = s + e` exactly) and Dekker's product (Dekker 1971, "A
//! floating-point technique for extending the available precision", Numer. Math. 18, 224–242: Veltkamp's split of
//! each factor into 26-bit halves, `a·b = p + e` exactly), so no fused multiply-add is needed; the operations built
//! on them (Dekker's add2/mul2/div2 with one extra renormalisation, and one Newton step for the square root) are
//! accurate to a few units of 2⁻¹⁰⁴ relative.
//!
//! K and Π come from the arithmetic-geometric mean (DLMF 19.8.5, 19.8.6–19.8.7), which needs only these operations
//! and converges quadratically. (Carlson's duplication for R_F and R_J, DLMF §19.36(i) / Carlson 1995, would serve
//! as well, but its R_J needs an R_C — an arctangent — at every step; `ellip` evaluates it so in binary64 for the
//! incomplete integrals, whose values stay bounded.)

use std::ops::{Add, Div, Mul, Neg, Sub};

/// `hi + lo`, the pair normalised so that `hi` is the sum rounded to binary64.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(super) struct Dd {
    pub(super) hi: f64,
    pub(super) lo: f64,
}

/// π in double-double (π = 3.14159265358979323846264338327950288…).
pub(super) const PI: Dd = Dd {
    hi: std::f64::consts::PI,
    lo: 1.224_646_799_147_353_2e-16,
};

/// 4π, the period of the quaternion of a rotation about a fixed axis as a function of its angle.
pub(super) const FOUR_PI: Dd = Dd {
    hi: 4.0 * PI.hi,
    lo: 4.0 * PI.lo,
};

/// `a + b = s + e` exactly, `s = fl(a + b)` (Knuth, TAOCP §4.2.2, Theorem B).
fn two_sum(a: f64, b: f64) -> (f64, f64) {
    let s = a + b;
    let bb = s - a;
    (s, (a - (s - bb)) + (b - bb))
}

/// `a + b = s + e` exactly for `|a| ≥ |b|` (Dekker 1971, Fast2Sum).
fn quick_two_sum(a: f64, b: f64) -> (f64, f64) {
    let s = a + b;
    (s, b - (s - a))
}

/// Veltkamp's split `a = hi + lo` into two halves of at most 26 significant bits (Dekker 1971, §5).
fn split(a: f64) -> (f64, f64) {
    const SPLITTER: f64 = 134_217_729.0; // 2²⁷ + 1
    let c = SPLITTER * a;
    let hi = c - (c - a);
    (hi, a - hi)
}

/// `a·b = p + e` exactly, `p = fl(a·b)` (Dekker 1971, mul12), for `|a·b|` well inside the binary64 range.
fn two_prod(a: f64, b: f64) -> (f64, f64) {
    let p = a * b;
    let ((ah, al), (bh, bl)) = (split(a), split(b));
    (p, ((ah * bh - p) + ah * bl + al * bh) + al * bl)
}

impl Dd {
    pub(super) const ZERO: Self = Self { hi: 0.0, lo: 0.0 };
    pub(super) const ONE: Self = Self { hi: 1.0, lo: 0.0 };

    fn renormalised(hi: f64, lo: f64) -> Self {
        let (hi, lo) = quick_two_sum(hi, lo);
        Self { hi, lo }
    }

    /// `√x` by one Newton step from the binary64 root (Karp & Markstein 1997): `s + (x − s²)/(2s)`; 0 for x ≤ 0.
    pub(super) fn sqrt(self) -> Self {
        if self.hi <= 0.0 {
            return Self::ZERO;
        }
        let s = self.hi.sqrt();
        let (p, e) = two_prod(s, s);
        Self::renormalised(s, (((self.hi - p) - e) + self.lo) / (2.0 * s))
    }

    /// The value clamped to `[lower, upper]` (binary64 bounds).
    pub(super) fn clamp(self, lower: f64, upper: f64) -> Self {
        if self.hi < lower {
            Self::from(lower)
        } else if self.hi > upper {
            Self::from(upper)
        } else {
            self
        }
    }

    /// `self − q·period` with `q` the integer nearest `self/period`: the value reduced to `[−period/2, period/2]`
    /// (up to rounding). The product `q·period` is exact up to `|q|·2⁻¹⁰⁶·period`.
    pub(super) fn reduce(self, period: Self) -> Self {
        let q = nearest_integer(self.hi / period.hi);
        self - period * q
    }
}

/// 1.5·2⁵²: adding and subtracting it rounds |x| < 2⁵¹ to the nearest integer (ties to even).
const TO_INT: f64 = 6_755_399_441_055_744.0;

/// x rounded to the nearest integer (ties to even below 2⁵¹, away from zero above, where every binary64 is an
/// integer or a half): without SSE4.1 in the target `f64::round` is a call into the C library, this two additions.
pub(super) fn nearest_integer(x: f64) -> f64 {
    if x.abs() < 2_251_799_813_685_248.0 {
        (x + TO_INT) - TO_INT
    } else {
        x.round()
    }
}

impl From<f64> for Dd {
    fn from(x: f64) -> Self {
        Self { hi: x, lo: 0.0 }
    }
}

impl Neg for Dd {
    type Output = Self;
    fn neg(self) -> Self {
        Self {
            hi: -self.hi,
            lo: -self.lo,
        }
    }
}

impl Add for Dd {
    type Output = Self;
    /// Both parts summed by TwoSum, the errors folded in with two renormalisations (the "accurate" add2).
    fn add(self, b: Self) -> Self {
        let (s, e) = two_sum(self.hi, b.hi);
        let (t, f) = two_sum(self.lo, b.lo);
        let (s, e) = quick_two_sum(s, e + t);
        Self::renormalised(s, e + f)
    }
}

impl Add<f64> for Dd {
    type Output = Self;
    fn add(self, b: f64) -> Self {
        let (s, e) = two_sum(self.hi, b);
        Self::renormalised(s, e + self.lo)
    }
}

impl Sub for Dd {
    type Output = Self;
    fn sub(self, b: Self) -> Self {
        self + (-b)
    }
}

impl Mul for Dd {
    type Output = Self;
    /// Dekker's mul2: the exact product of the high parts plus the cross terms.
    fn mul(self, b: Self) -> Self {
        let (p, e) = two_prod(self.hi, b.hi);
        Self::renormalised(p, e + (self.hi * b.lo + self.lo * b.hi))
    }
}

impl Mul<f64> for Dd {
    type Output = Self;
    fn mul(self, b: f64) -> Self {
        let (p, e) = two_prod(self.hi, b);
        Self::renormalised(p, e + self.lo * b)
    }
}

impl Div for Dd {
    type Output = Self;
    /// Long division: three binary64 quotient digits, each from the remainder of the ones before.
    fn div(self, b: Self) -> Self {
        let q1 = self.hi / b.hi;
        let r = self - b * q1;
        let q2 = r.hi / b.hi;
        let r = r - b * q2;
        let q3 = r.hi / b.hi;
        Self::renormalised(q1, q2) + q3
    }
}

/// Iterations of the AGM at most: from `k′ = 2⁻⁵³⁷` (m′ at the binary64 limit) it converges in about 16.
const AGM_ITERATIONS: usize = 64;

/// The complete elliptic integrals `(K(m), Π(n|m))` for `0 < m′ = 1 − m ≤ 1` and `n < 1`, in double-double, by the
/// arithmetic-geometric mean of `a₀ = 1`, `g₀ = k′ = √m′` (`a_{j+1} = (a_j + g_j)/2`, `g_{j+1} = √(a_j g_j)`,
/// common limit M):
///
/// ```text
///   K(m)   = π / (2M)                                                  (DLMF 19.8.5)
///   Π(n|m) = π / (4M) · (2 + n/(1 − n) Σ Q_j)                           (DLMF 19.8.6)
///   p₀ = √(1 − n), Q₀ = 1,  p_{j+1} = (p_j² + a_j g_j)/(2p_j),
///   Q_{j+1} = ½ Q_j (p_j² − a_j g_j)/(p_j² + a_j g_j)                   (DLMF 19.8.7)
/// ```
///
/// (A&S 17.2.15's sign of n: `Π(n|m) = ∫₀^{π/2} dθ / ((1 − n sin²θ) √(1 − m sin²θ))`.) Iterates until `a − g` and
/// `Q_j` are below 1e-31 relative.
pub(super) fn complete_k_pi(mc: Dd, n: Dd) -> (Dd, Dd) {
    let (mut a, mut g) = (Dd::ONE, mc.sqrt());
    let mut p = (Dd::ONE - n).sqrt();
    let (mut q, mut sum) = (Dd::ONE, Dd::ZERO);
    for _ in 0..AGM_ITERATIONS {
        sum = sum + q;
        let ag = a * g;
        let p2 = p * p;
        q = q * 0.5 * (p2 - ag) / (p2 + ag);
        p = (p2 + ag) / (p * 2.0);
        let converged = (a - g).hi.abs() <= 1e-31 * a.hi && q.hi.abs() <= 1e-31 * sum.hi.abs();
        (a, g) = ((a + g) * 0.5, ag.sqrt());
        if converged {
            break;
        }
    }
    let k = PI / (a * 2.0);
    let pi_n = PI / (a * 4.0) * (n / (Dd::ONE - n) * sum + 2.0);
    (k, pi_n)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// |x − y| in units of 2⁻¹⁰⁰ relative to |y|.
    fn rel(x: Dd, y: Dd) -> f64 {
        ((x - y).hi / y.hi).abs() * 2f64.powi(100)
    }

    #[test]
    fn error_free_transformations_are_exact() {
        // TwoSum and Dekker's product: the pair's sum equals the exact result (checked where it is known exactly).
        let (s, e) = two_sum(1.0, 1e-20);
        assert_eq!((s, e), (1.0, 1e-20));
        let x = 1.0 + f64::EPSILON;
        // (1 + ε)² = 1 + 2ε + ε²: p = 1 + 2ε, e = ε².
        assert_eq!(
            two_prod(x, x),
            (1.0 + 2.0 * f64::EPSILON, f64::EPSILON * f64::EPSILON)
        );
        let (h, l) = split(0.1);
        assert_eq!(h + l, 0.1);
        assert!(h.to_bits().trailing_zeros() >= 26);
    }

    #[test]
    fn arithmetic_reaches_double_double_precision() {
        // 1/3 · 3 = 1, √2² = 2, (1/7)·7 = 1: each to half a unit of 2⁻¹⁰⁰ (a few units of 2⁻¹⁰⁴).
        let three = Dd::from(3.0);
        let third = Dd::ONE / three;
        assert!(rel(third * three, Dd::ONE) <= 0.5, "{:?}", third * three);
        let root2 = Dd::from(2.0).sqrt();
        assert!(rel(root2 * root2, Dd::from(2.0)) <= 0.5);
        // √2 = 1.41421356237309504880168872420969807856967…: hi is the binary64 rounding, lo the rest
        // (−9.667293313452913e-17 from mpmath, to 16 digits) to 2⁻¹⁰² relative.
        assert_eq!(root2.hi, std::f64::consts::SQRT_2);
        assert!(
            (root2.lo - (-9.667_293_313_452_913e-17)).abs() <= 2e-31,
            "{root2:?}"
        );
        let seventh = Dd::ONE / Dd::from(7.0);
        assert!(rel(seventh * 7.0, Dd::ONE) <= 0.5);
        // 4π reduces 4π + 1 to 1 exactly, and 1e3·4π + 0.25 to 0.25 within 1e3 · 2⁻¹⁰⁶ · 4π.
        assert_eq!((FOUR_PI + 1.0).reduce(FOUR_PI), Dd::ONE);
        let r = (FOUR_PI * 1000.0 + 0.25).reduce(FOUR_PI);
        assert!((r - Dd::from(0.25)).hi.abs() <= 1e-27);
    }

    #[test]
    fn nearest_integer_rounds_to_the_nearest() {
        // Ties go to even below 2⁵¹ (IEEE 754 roundTiesToEven of the sum with 1.5·2⁵²); either neighbour is a valid
        // half-period count at a tie, so only the non-ties must agree with `f64::round`.
        for (x, want) in [
            (0.4, 0.0),
            (-0.6, -1.0),
            (2.5, 2.0),
            (3.5, 4.0),
            (-7.49, -7.0),
            (1e15 + 0.75, 1e15 + 1.0),
        ] {
            assert_eq!(nearest_integer(x), want, "{x}");
        }
        assert_eq!(nearest_integer(3e15 + 0.5), 3e15 + 1.0);
        assert_eq!(nearest_integer(-1e300), -1e300);
    }

    #[test]
    fn agm_gives_the_complete_integrals() {
        // Against mpmath 1.3.0 (`ellipk`, `ellippi` at 50 digits, from the binary64 arguments), each to 2⁻¹⁰⁰:
        // K(1/2) = Γ(1/4)²/(4√π) = 1.85407467730137191843385034719526… (the lemniscatic case),
        // Π(−3 | 0.0075) = 0.78638361097393506586130561508324…, Π(0.3 | 0.5) = 2.25037682194394666535561434659001…;
        // and Π(0|m) = K(m).
        let (k, pi0) = complete_k_pi(Dd::from(0.5), Dd::ZERO);
        let k_ref = Dd {
            hi: 1.854_074_677_301_371_9,
            lo: 4.220_810_632_962_078_7e-17,
        };
        assert!(rel(k, k_ref) <= 1.0, "K(1/2) = {k:?}");
        assert!(rel(pi0, k) <= 1.0);
        let (_, pi_n) = complete_k_pi(Dd::ONE - Dd::from(0.0075), Dd::from(-3.0));
        let pi_ref = Dd {
            hi: 0.786_383_610_973_935,
            lo: 1.147_228_877_406_886_6e-17,
        };
        assert!(rel(pi_n, pi_ref) <= 1.0, "{pi_n:?}");
        let (_, pi_n) = complete_k_pi(Dd::from(0.5), Dd::from(0.3));
        let pi_ref = Dd {
            hi: 2.250_376_821_943_947,
            lo: -1.714_125_767_865_701_4e-16,
        };
        assert!(rel(pi_n, pi_ref) <= 1.0, "{pi_n:?}");
        // Carlson's form, DLMF 19.25.2: Π(n|m) − K(m) = (n/3) R_J(0, m′, 1, 1 − n), in binary64 by `ellip`; and
        // m′ = 1e-300 (K ≈ ½ ln(16/m′), DLMF 19.12.1) converges.
        let (k, pi_n) = complete_k_pi(Dd::from(0.25), Dd::from(-10.0));
        let rj = ellip::elliprj(0.0, 0.25, 1.0, 11.0).unwrap();
        let want = (-10.0 / 3.0) * rj;
        assert!(((pi_n - k).hi - want).abs() <= 8.0 * f64::EPSILON * want.abs());
        let (k, _) = complete_k_pi(Dd::from(1e-300), Dd::from(-1.0));
        assert!((k.hi - 0.5 * (16e300f64).ln()).abs() <= 1e-13 * k.hi);
    }
}
