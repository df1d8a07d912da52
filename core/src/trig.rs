//! Sine and cosine evaluated inline, without a call into the C library.
//!
//! A call in the middle of a Runge–Kutta stage makes the compiler spill the state to memory and puts the stage behind
//! the call's latency; inline arithmetic that depends only on t (a sine torque) overlaps with the stage's own work.
//! Measured on the sine-torque benchmark: see the README's "What accuracy costs".

// The constants are fdlibm's decimal literals, kept digit for digit.
#![allow(clippy::excessive_precision)]

/// 2/π.
const INV_PIO2: f64 = std::f64::consts::FRAC_2_PI;
/// π/2 in three parts of 33 bits each with their tails (fdlibm `e_rem_pio2.c`): PIO2_1 + PIO2_1T = π/2 to 85 bits,
/// PIO2_1 + PIO2_2 + PIO2_2T to 118 bits, PIO2_1 + PIO2_2 + PIO2_3 + PIO2_3T to 151 bits. n·PIO2_k is exact for
/// |n| < 2²⁰.
const PIO2_1: f64 = 1.570_796_326_734_125_614_17;
const PIO2_1T: f64 = 6.077_100_506_506_192_249_32e-11;
const PIO2_2: f64 = 6.077_100_506_303_965_976_60e-11;
const PIO2_2T: f64 = 2.022_266_248_795_950_631_54e-21;
const PIO2_3: f64 = 2.022_266_248_711_166_455_80e-21;
const PIO2_3T: f64 = 8.478_427_660_368_899_569_97e-32;
/// 1.5·2⁵²: adding and subtracting it rounds |x| < 2⁵¹ to the nearest integer (ties to even).
const TO_INT: f64 = 6_755_399_441_055_744.0;
/// Below this |x| (just below 2²⁰·π/2, fdlibm's bound) the three-part reduction is exact; beyond, the library's sine.
const MEDIUM_LIMIT: f64 = 1_647_099.0;

/// Minimax coefficients of sin on |x| ≤ π/4 (fdlibm `k_sin.c`, relative error < 2⁻⁵⁸).
const S1: f64 = -1.666_666_666_666_663_243_48e-01;
const S2: f64 = 8.333_333_333_322_489_461_24e-03;
const S3: f64 = -1.984_126_982_985_794_931_34e-04;
const S4: f64 = 2.755_731_370_707_006_767_89e-06;
const S5: f64 = -2.505_076_025_340_686_341_95e-08;
const S6: f64 = 1.589_690_995_211_550_102_21e-10;
/// Minimax coefficients of cos on |x| ≤ π/4 (fdlibm `k_cos.c`, error < 2⁻⁵⁸).
const C1: f64 = 4.166_666_666_666_660_190_37e-02;
const C2: f64 = -1.388_888_888_887_410_957_49e-03;
const C3: f64 = 2.480_158_728_947_672_941_78e-05;
const C4: f64 = -2.755_731_435_139_066_330_35e-07;
const C5: f64 = 2.087_572_321_298_174_827_90e-09;
const C6: f64 = -1.135_964_755_778_819_482_65e-11;

/// sin x, within one ulp of the correctly rounded value, the algorithm of FreeBSD's msun (fdlibm, Sun Microsystems
/// 1993: `s_sin.c`, `e_rem_pio2.c`, `k_sin.c`, `k_cos.c`): x = n·π/2 + (y₀ + y₁) by Cody–Waite reduction with π/2 in
/// three parts (a second and third round only where the first cancels, near a multiple of π/2), then
/// sin x = ±sin y or ±cos y by n mod 4, both kernels minimax polynomials on |y| ≤ π/4; only the kernel n mod 2 asks
/// for is evaluated (a branch that follows t, so it is predicted). For |x| ≥ 2²⁰·π/2, NaN and ±∞: `f64::sin`.
#[inline(always)]
pub fn sin(x: f64) -> f64 {
    if x.is_nan() || x.abs() >= MEDIUM_LIMIT {
        return x.sin();
    }
    let (n, y0, y1) = rem_pio2(x);
    let v = if n & 1 == 0 {
        kernel_sin(y0, y1)
    } else {
        kernel_cos(y0, y1)
    };
    if n & 2 == 0 { v } else { -v }
}

/// x = n·π/2 + (y₀ + y₁), |y₀ + y₁| ≤ π/4 (+ rounding), y₁ the tail of y₀; for |x| < 2²⁰·π/2
/// (fdlibm `__ieee754_rem_pio2`, its "medium" case).
#[inline(always)]
fn rem_pio2(x: f64) -> (i64, f64, f64) {
    let f_n = (x * INV_PIO2 + TO_INT) - TO_INT;
    let exponent = |v: f64| ((v.to_bits() >> 52) & 0x7ff) as i64;
    let mut r = x - f_n * PIO2_1;
    let mut w = f_n * PIO2_1T;
    let mut y0 = r - w;
    // One more round: r − n·(p + p_tail), the rounding of r − n·p carried into w.
    let round = |r: f64, p: f64, p_tail: f64| {
        let w = f_n * p;
        let r_new = r - w;
        let w = f_n * p_tail - ((r - r_new) - w);
        (r_new, w, r_new - w)
    };
    if exponent(x) - exponent(y0) > 16 {
        // The first round cancelled more than 16 bits: subtract the next 33 bits of π/2 (118 bits in all).
        (r, w, y0) = round(r, PIO2_2, PIO2_2T);
        if exponent(x) - exponent(y0) > 49 {
            // And again (151 bits): covers every double below the limit.
            (r, w, y0) = round(r, PIO2_3, PIO2_3T);
        }
    }
    let y1 = (r - y0) - w;
    (f_n as i64, y0, y1)
}

/// sin(x + y) for |x| ≤ π/4, y a tail of x (fdlibm `__kernel_sin` with iy = 1).
#[inline(always)]
fn kernel_sin(x: f64, y: f64) -> f64 {
    let z = x * x;
    let w = z * z;
    let r = S2 + z * (S3 + z * S4) + z * w * (S5 + z * S6);
    let v = z * x;
    x - ((z * (0.5 * y - v * r) - y) - v * S1)
}

/// cos(x + y) for |x| ≤ π/4, y a tail of x (fdlibm `__kernel_cos`).
#[inline(always)]
fn kernel_cos(x: f64, y: f64) -> f64 {
    let z = x * x;
    let w = z * z;
    let r = z * (C1 + z * (C2 + z * C3)) + w * w * (C4 + z * (C5 + z * C6));
    let hz = 0.5 * z;
    let w = 1.0 - hz;
    w + (((1.0 - w) - hz) + (z * r - x * y))
}

/// (sin x, cos x) for the small angles of the splitting methods' sub-flows. For |x| ≤ 1/16 (|ω|·τ ≤ 1/8, which a
/// step resolving the motion keeps to) by the Taylor series to x⁹ and x⁸, evaluated inline in Estrin's scheme (a
/// short chain of dependent operations): the remainders (< x¹¹/11! and x¹⁰/10!) are below 10⁻¹⁸ relative there and
/// the terms after the first add less than x²/6 ≤ 0.001 ulp of rounding, so the results are the correctly rounded
/// ones but for ≈ 0.5 ulp — as the library's — without a call. Beyond 1/16 the library's `sin_cos`.
#[inline(always)]
pub fn small_sin_cos(x: f64) -> (f64, f64) {
    if x.abs() > 0.0625 {
        return x.sin_cos();
    }
    let z = x * x;
    let z2 = z * z;
    let sin_tail = (-1.0 / 6.0 + z * (1.0 / 120.0)) + z2 * (-1.0 / 5040.0 + z * (1.0 / 362_880.0));
    let cos_tail = (-0.5 + z * (1.0 / 24.0)) + z2 * (-1.0 / 720.0 + z * (1.0 / 40_320.0));
    (x + (x * z) * sin_tail, 1.0 + z * cos_tail)
}

#[cfg(test)]
mod tests {
    use std::f64::consts::FRAC_PI_2;

    use super::*;

    /// One unit in the last place of x.
    fn ulp(x: f64) -> f64 {
        let a = x.abs();
        if a == 0.0 {
            f64::from_bits(1)
        } else {
            f64::from_bits(a.to_bits() + 1) - a
        }
    }

    /// Both are within 1 ulp of the exact value (fdlibm's bound; glibc's sine is correctly rounded but for rare
    /// cases, within 0.5 ulp + ε), so they may differ by 1 ulp, never more.
    fn assert_within_one_ulp(x: f64) {
        let (ours, lib) = (sin(x), x.sin());
        assert!(
            (ours - lib).abs() <= ulp(lib),
            "sin({x:e}): {ours:e} vs library {lib:e}"
        );
    }

    #[test]
    fn sine_matches_the_library_to_an_ulp() {
        // Log-spaced magnitudes from 1e-300 to the medium limit, both signs.
        let mut x = 1e-300;
        while x < MEDIUM_LIMIT {
            assert_within_one_ulp(x);
            assert_within_one_ulp(-x);
            x *= 1.000_5;
        }
        // A dense uniform sweep over the arguments of a long sine-torque run: ωt up to 2π·1e4.
        for k in 0..2_000_000 {
            assert_within_one_ulp(k as f64 * 0.031_415_926_5 + 1e-3);
        }
    }

    #[test]
    fn sine_near_multiples_of_half_pi_uses_the_extra_rounds() {
        // Arguments within a few ulp of n·π/2, where the first reduction round cancels, for n up to 2^20 − 1.
        for n in (1..1_048_576i64)
            .step_by(997)
            .chain([1, 2, 3, 4, 1_048_575])
        {
            let x = n as f64 * FRAC_PI_2;
            for k in -4..=4 {
                let xk = f64::from_bits((x.to_bits() as i64 + k) as u64);
                assert_within_one_ulp(xk);
                assert_within_one_ulp(-xk);
            }
        }
    }

    #[test]
    fn sine_beyond_the_limit_and_non_finite_is_the_library_one() {
        for x in [MEDIUM_LIMIT, 2e6, -1e9, 1e300] {
            assert_eq!(sin(x), x.sin());
        }
        assert!(sin(f64::NAN).is_nan());
        assert!(sin(f64::INFINITY).is_nan());
        assert_eq!(sin(0.0).to_bits(), 0.0f64.to_bits());
        assert_eq!(sin(-0.0).to_bits(), (-0.0f64).to_bits());
    }

    #[test]
    fn small_sin_cos_is_the_library_one_to_an_ulp() {
        // The series are truncated where their remainders are below 1e-18 relative (|x| <= 1/16): the results are
        // the correctly rounded values but for about 0.5 ulp, like the library's, so they differ from it by at
        // most one ulp; beyond 1/16 they are the library's.
        let mut x = 1e-300;
        let mut xs = vec![0.0, 0.0625, -0.0625, 0.0625f64.next_down(), 1e-8, 2.5e-4];
        while x < 0.0625 {
            xs.push(x);
            xs.push(-x);
            x *= 1.003_7;
        }
        for x in xs {
            let (s, c) = small_sin_cos(x);
            let (s_lib, c_lib) = x.sin_cos();
            assert!((s - s_lib).abs() <= ulp(s_lib), "sin({x:e})");
            assert!((c - c_lib).abs() <= ulp(c_lib), "cos({x:e})");
        }
        for x in [0.0626, -0.3, 1.0, 3.0, 100.0] {
            assert_eq!(small_sin_cos(x), x.sin_cos());
        }
    }
}
