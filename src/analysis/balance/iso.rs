//! Balance quality grades of rigid rotors, ISO 21940-11:2016 ("Mechanical vibration — Rotor balancing — Part 11:
//! Procedures and tolerances for rotors with rigid behaviour", formerly ISO 1940-1).
//!
//! A grade G (mm/s) bounds the product e·Ω of the specific unbalance e = U/m and the service speed Ω. The
//! permissible residual unbalance of the whole rotor is therefore (ISO 21940-11, balance tolerances)
//!
//! ```text
//!   U_per = 1000 · G · m / Ω   g·mm     (m in kg, Ω in rad/s)   = 9549 · G · m / n   (n in r/min)
//! ```
//!
//! and it is allotted to the two correction planes in inverse proportion to their distance from the centre of
//! mass, U_per,A = U_per·|z_B − z_C|/|z_B − z_A| and U_per,B = U_per·|z_A − z_C|/|z_B − z_A| (ISO 21940-11,
//! allocation to the tolerance planes), each share kept between 30 % and 70 % of U_per. The grade a rotor meets is the smallest G for which each
//! plane's unbalance is within its share: G = max_i U_i Ω / (1000 m share_i).

/// The balance quality grades ISO 21940-11 lists (G 0.4 to G 4000), mm/s: each 2.5 times the one before.
pub const STANDARD_GRADES: [f64; 11] = [
    0.4, 1.0, 2.5, 6.3, 16.0, 40.0, 100.0, 250.0, 630.0, 1600.0, 4000.0,
];

/// Each plane's share of U_per is kept within these fractions (ISO 21940-11).
pub const SHARE_LIMITS: [f64; 2] = [0.3, 0.7];

/// Ω (rad/s) of a speed `n` in revolutions per minute: Ω = 2π n / 60.
pub fn rpm_to_rad_s(n: f64) -> f64 {
    n * std::f64::consts::PI / 30.0
}

/// The permissible residual unbalance U_per = 1000·G·m/Ω (g·mm) of a rotor of mass `mass` (kg) at the speed
/// `omega` (rad/s) for the grade `grade` (mm/s), ISO 21940-11.
pub fn permissible_unbalance(grade: f64, mass: f64, omega: f64) -> f64 {
    1000.0 * grade * mass / omega.abs()
}

/// The shares of U_per of the planes at `z_a` and `z_b` for the centre of mass at `z_c` (same origin):
/// |z_B − z_C|/|z_B − z_A| for A and |z_A − z_C|/|z_B − z_A| for B, each clamped to [`SHARE_LIMITS`].
pub fn plane_shares(z_a: f64, z_b: f64, z_c: f64) -> [f64; 2] {
    let span = (z_b - z_a).abs();
    let [low, high] = SHARE_LIMITS;
    [(z_b - z_c).abs() / span, (z_a - z_c).abs() / span].map(|s| s.clamp(low, high))
}

/// The smallest grade G (mm/s) for which the plane unbalances `unbalance` (g·mm) are within their shares
/// `shares` of U_per = 1000·G·m/Ω: G = max_i U_i Ω / (1000 m share_i).
pub fn grade_met(unbalance: [f64; 2], shares: [f64; 2], mass: f64, omega: f64) -> f64 {
    (0..2)
        .map(|i| unbalance[i] * omega.abs() / (1000.0 * mass * shares[i]))
        .fold(0.0, f64::max)
}

/// The finest grade of [`STANDARD_GRADES`] that a rotor meeting `grade` meets too (the smallest listed G ≥
/// `grade`); `None` above G 4000.
pub fn standard_grade_met(grade: f64) -> Option<f64> {
    STANDARD_GRADES.iter().copied().find(|&g| g >= grade)
}

/// A rotor's unbalance judged against ISO 21940-11 at one speed.
#[derive(Debug, Clone, PartialEq)]
pub struct Assessment {
    /// The speed (rad/s) and where it came from (`--rpm` or the scene's rate).
    pub omega: f64,
    /// Whether the speed is `--rpm`'s rather than the scene's.
    pub from_rpm: bool,
    /// The rotor's mass (kg) and its centre of mass along the axis (m, from the axis point).
    pub mass: f64,
    pub z_c: f64,
    /// The planes' shares of U_per.
    pub shares: [f64; 2],
    /// The grade met before and after balancing (mm/s).
    pub met: [f64; 2],
    /// The grade asked for, when one is.
    pub target: Option<Target>,
}

/// The permissible unbalance of a requested grade and the verdicts.
#[derive(Debug, Clone, PartialEq)]
pub struct Target {
    /// The grade G (mm/s).
    pub grade: f64,
    /// U_per (g·mm) and its allotment to planes A and B.
    pub u_per: f64,
    pub u_per_planes: [f64; 2],
    /// Whether the rotor meets the grade before and after balancing.
    pub pass: [bool; 2],
}

/// Judges the plane unbalances `before` and `after` (g·mm) of a rotor of mass `mass` with its centre of mass at
/// `z_c` between the planes `z_a`, `z_b`, at `omega` (rad/s), against `grade` when given.
pub fn assess(
    before: [f64; 2],
    after: [f64; 2],
    (z_a, z_b, z_c): (f64, f64, f64),
    (mass, omega, from_rpm): (f64, f64, bool),
    grade: Option<f64>,
) -> Assessment {
    let shares = plane_shares(z_a, z_b, z_c);
    let met = [before, after].map(|u| grade_met(u, shares, mass, omega));
    let target = grade.map(|g| {
        let u_per = permissible_unbalance(g, mass, omega);
        Target {
            grade: g,
            u_per,
            u_per_planes: shares.map(|s| s * u_per),
            pass: met.map(|m| m <= g),
        }
    });
    Assessment {
        omega: omega.abs(),
        from_rpm,
        mass,
        z_c,
        shares,
        met,
        target,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_grade_met_puts_the_worse_plane_exactly_at_its_share() {
        let (mass, omega) = (3.0, 200.0);
        let shares = plane_shares(0.0, 1.0, 0.25);
        assert_eq!(shares, [0.7, 0.3]);
        let g = grade_met([100.0, 90.0], shares, mass, omega);
        // Plane B is the worse: 90 / 0.3 > 100 / 0.7, and at that grade it uses its share exactly.
        let u_per = permissible_unbalance(g, mass, omega);
        assert!((u_per * shares[1] - 90.0).abs() < 1e-12);
        assert!(u_per * shares[0] > 100.0);
    }

    #[test]
    fn standard_grades_step_by_two_and_a_half() {
        for pair in STANDARD_GRADES.windows(2) {
            let ratio = pair[1] / pair[0];
            assert!((2.5..=2.55).contains(&ratio), "{pair:?}");
        }
        assert_eq!(standard_grade_met(6.3), Some(6.3));
        assert_eq!(standard_grade_met(6.31), Some(16.0));
        assert_eq!(standard_grade_met(0.01), Some(0.4));
        assert_eq!(standard_grade_met(5000.0), None);
    }
}
