//! Brent's method for a root of a continuous function in a bracket (R. P. Brent, *Algorithms for Minimization
//! without Derivatives*, Prentice-Hall 1973, ch. 4, procedure `zero`): inverse quadratic interpolation or the
//! secant, falling back to bisection whenever they would not shrink the bracket fast enough; it never leaves the
//! bracket and converges superlinearly for a simple root.

/// A root of g in [a, b], where g(a) and g(b) have opposite signs (or one is zero), to within
/// 4ε·|t| + `tol` (s). Without a sign change it returns the end where |g| is smaller.
pub fn brent(mut g: impl FnMut(f64) -> f64, a: f64, b: f64, tol: f64) -> f64 {
    let (mut a, mut b) = (a, b);
    let (mut fa, mut fb) = (g(a), g(b));
    if fa == 0.0 {
        return a;
    }
    if fb == 0.0 {
        return b;
    }
    if (fa > 0.0) == (fb > 0.0) {
        return if fa.abs() < fb.abs() { a } else { b };
    }
    let (mut c, mut fc) = (a, fa);
    let mut d = b - a;
    let mut e = d;
    for _ in 0..200 {
        if (fb > 0.0) == (fc > 0.0) {
            (c, fc) = (a, fa);
            d = b - a;
            e = d;
        }
        if fc.abs() < fb.abs() {
            (a, fa) = (b, fb);
            (b, fb) = (c, fc);
            (c, fc) = (a, fa);
        }
        let tol1 = 2.0 * f64::EPSILON * b.abs() + 0.5 * tol;
        let m = 0.5 * (c - b);
        if m.abs() <= tol1 || fb == 0.0 {
            return b;
        }
        if e.abs() >= tol1 && fa.abs() > fb.abs() {
            let s = fb / fa;
            let (mut p, mut q) = if a == c {
                (2.0 * m * s, 1.0 - s)
            } else {
                let (q, r) = (fa / fc, fb / fc);
                (
                    s * (2.0 * m * q * (q - r) - (b - a) * (r - 1.0)),
                    (q - 1.0) * (r - 1.0) * (s - 1.0),
                )
            };
            if p > 0.0 {
                q = -q;
            } else {
                p = -p;
            }
            if 2.0 * p < (3.0 * m * q - (tol1 * q).abs()).min((e * q).abs()) {
                e = d;
                d = p / q;
            } else {
                d = m;
                e = m;
            }
        } else {
            d = m;
            e = m;
        }
        (a, fa) = (b, fb);
        b += if d.abs() > tol1 { d } else { tol1.copysign(m) };
        fb = g(b);
    }
    b
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn finds_simple_roots_to_the_tolerance() {
        // cos t = 0 at π/2; t³ − 2t − 5 = 0 at 2.0945514815423265 (Wallis's cubic, Brent 1973 ch. 4).
        let r = brent(f64::cos, 1.0, 2.0, 1e-14);
        assert!((r - std::f64::consts::FRAC_PI_2).abs() < 1e-14);
        let r = brent(|t| t * t * t - 2.0 * t - 5.0, 2.0, 3.0, 1e-14);
        assert!((r - 2.094_551_481_542_326_5).abs() < 1e-14);
        // A zero at an end is that end; no sign change gives the smaller end.
        assert_eq!(brent(|t| t - 1.0, 1.0, 2.0, 1e-14), 1.0);
        assert_eq!(brent(|t| t * t + 1.0, -1.0, 0.5, 1e-14), 0.5);
    }
}
