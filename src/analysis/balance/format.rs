//! One format for every figure `eulerdyn balance` prints: numbers to significant digits, angles in [0, 360)
//! degrees (never 360.0), masses in g.

use nalgebra::Vector3;

/// `x` to `digits` significant digits, in exponent form outside 1e-3 ≤ |x| < 1e6 ("0" for zero).
pub(crate) fn sig(x: f64, digits: usize) -> String {
    if x == 0.0 || !x.is_finite() {
        return format!("{x}");
    }
    let exponent = x.abs().log10().floor() as i32;
    if (-3..6).contains(&exponent) {
        let decimals = (digits as i32 - 1 - exponent).max(0) as usize;
        format!("{x:.decimals$}")
    } else {
        format!("{x:.*e}", digits - 1)
    }
}

/// An angle (deg) brought into [0, 360): x − 360·⌊x/360⌋, with the 360.0 that rounding can give for a tiny
/// negative angle taken as 0.
pub fn wrap_deg(deg: f64) -> f64 {
    let wrapped = deg.rem_euclid(360.0);
    if wrapped >= 360.0 { 0.0 } else { wrapped }
}

/// An angle (deg) as printed: to 0.1 deg in [0, 360), so that 359.96 prints as 0.0, never 360.0.
pub(crate) fn angle_text(deg: f64) -> String {
    format!("{:.1}", wrap_deg((wrap_deg(deg) * 10.0).round() / 10.0))
}

/// One correction as every mode prints it: "plane A at -0.1 m: correction 15.42 g at 213.8 deg, at = […] m":
/// the plane `plane` at `z` (m), the mass `mass` (kg) at `angle_deg` and its position `at_b` (m, body axes).
pub(crate) fn correction_line(
    plane: &str,
    z: f64,
    (mass, angle_deg): (f64, f64),
    at_b: &Vector3<f64>,
) -> String {
    if mass == 0.0 {
        return format!("plane {plane} at {z} m: correction 0 g (none needed)\n");
    }
    format!(
        "plane {plane} at {} m: correction {} g at {} deg, at = [{:.6}, {:.6}, {:.6}] m (body axes, from the reference origin)\n",
        z,
        sig(mass * 1e3, 4),
        angle_text(angle_deg),
        at_b.x,
        at_b.y,
        at_b.z
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn angles_print_in_0_to_360_and_never_as_360() {
        assert_eq!(angle_text(-0.01), "0.0");
        assert_eq!(angle_text(359.96), "0.0");
        assert_eq!(angle_text(-120.9), "239.1");
        assert_eq!(angle_text(720.26), "0.3");
        assert_eq!(wrap_deg(-1e-18), 0.0);
        assert_eq!(wrap_deg(-90.0), 270.0);
    }
}
