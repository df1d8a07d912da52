//! Balance quality grades of rigid rotors, ISO 21940-11:2016 ("Mechanical vibration — Rotor balancing — Part 11:
//! Procedures and tolerances for rotors with rigid behaviour", formerly ISO 1940-1).
//!
//! A grade G (mm/s) bounds the product e·Ω of the specific unbalance e = U/m and the maximum service speed Ω
//! (5.3, 6.3.1). The permissible residual unbalance of the whole rotor is therefore (6.3.3)
//!
//! ```text
//!   U_per = 1000 · G · m / Ω   g·mm     (m in kg, Ω in rad/s)   = 9549 · G · m / n   (n in r/min)
//! ```
//!
//! The tolerance planes are the bearing planes (4.4): the unbalance found in the correction planes z_1, z_2 is
//! converted to the bearing planes L_A, L_B keeping its resultant and its moment ([`to_planes`]), and U_per is
//! allotted to them by the lever rule about the centre of mass z_C (7.2.1), U_per,A = U_per·|L_B − z_C|/|L_B − L_A|
//! and U_per,B = U_per·|L_A − z_C|/|L_B − L_A|, each share kept between 30 % and 70 % of U_per (7.2.2, 7.2.3:
//! a centre of mass near one bearing or outside them). With `--tolerance-planes correction` (or a scene without
//! bearings) the correction planes take the bearings' place in the same formulas. The grade a rotor meets is the
//! smallest G for which each tolerance plane's unbalance is within its share: G = max_i U_i Ω / (1000 m share_i).

use nalgebra::Complex;

/// The balance quality grades ISO 21940-11 lists (G 0.4 to G 4000), mm/s: each 2.5 times the one before.
pub const STANDARD_GRADES: [f64; 11] = [
    0.4, 1.0, 2.5, 6.3, 16.0, 40.0, 100.0, 250.0, 630.0, 1600.0, 4000.0,
];

/// Each tolerance plane's share of U_per is kept within these fractions (ISO 21940-11, 7.2.2 and 7.2.3).
pub const SHARE_LIMITS: [f64; 2] = [0.3, 0.7];

/// Ω (rad/s) of a speed `n` in revolutions per minute: Ω = 2π n / 60.
pub fn rpm_to_rad_s(n: f64) -> f64 {
    n * std::f64::consts::PI / 30.0
}

/// The permissible residual unbalance U_per = 1000·G·m/Ω (g·mm) of a rotor of mass `mass` (kg) at the maximum
/// service speed `omega` (rad/s) for the grade `grade` (mm/s), ISO 21940-11, 6.3.3.
pub fn permissible_unbalance(grade: f64, mass: f64, omega: f64) -> f64 {
    1000.0 * grade * mass / omega.abs()
}

/// The shares of U_per of the tolerance planes at `z_a` and `z_b` for the centre of mass at `z_c` (same origin),
/// the lever rule of ISO 21940-11, 7.2.1: |z_B − z_C|/|z_B − z_A| for A and |z_A − z_C|/|z_B − z_A| for B, each
/// clamped to [`SHARE_LIMITS`] (7.2.2 inboard, 7.2.3 outboard rotors).
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

/// Unbalances `u` (complex, g·mm) in the planes `from` converted to the planes `to` (axial positions, same
/// origin) with the same resultant and moment (ISO 21940-11, 4.2 and 4.4: the unbalance stated in the tolerance
/// planes), the lever rule: U_A = Σ_i (L_B − z_i) U_i/(L_B − L_A), U_B = Σ_i (z_i − L_A) U_i/(L_B − L_A).
pub fn to_planes(u: [Complex<f64>; 2], from: [f64; 2], to: [f64; 2]) -> [Complex<f64>; 2] {
    let [l_a, l_b] = to;
    let span = l_b - l_a;
    let lever = |k: usize, z: f64| {
        if k == 0 {
            (l_b - z) / span
        } else {
            (z - l_a) / span
        }
    };
    [0, 1].map(|k| u[0] * lever(k, from[0]) + u[1] * lever(k, from[1]))
}

/// Where U_per is allotted.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum TolerancePlanes {
    /// The bearing planes (ISO 21940-11, 4.4), when the scene has bearings; else the correction planes.
    #[default]
    Bearings,
    /// The correction planes (`--tolerance-planes correction`).
    Correction,
}

impl TolerancePlanes {
    /// The word of `--tolerance-planes` and of the JSON.
    pub fn name(self) -> &'static str {
        match self {
            Self::Bearings => "bearings",
            Self::Correction => "correction",
        }
    }
}

impl crate::named::Named for TolerancePlanes {
    const ALL: &'static [Self] = &[Self::Bearings, Self::Correction];

    fn name(&self) -> &'static str {
        TolerancePlanes::name(*self)
    }
}

/// A verdict against the grade asked for.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Verdict {
    /// Within the permissible residual unbalance.
    Pass,
    /// Beyond it.
    Fail,
    /// A warning about the input (a likely unit slip) stands: no verdict is given.
    Unverified,
}

impl Verdict {
    /// "pass", "fail" or "unverified".
    pub fn word(self) -> &'static str {
        match self {
            Self::Pass => "pass",
            Self::Fail => "fail",
            Self::Unverified => "unverified",
        }
    }
}

/// The rotor and the planes a grade is judged in: its mass (kg), its centre of mass along the axis (m), the
/// tolerance planes used and their axial positions (m).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Judged {
    /// The rotor's mass (kg).
    pub mass: f64,
    /// Its centre of mass along the axis (m, from the axis point).
    pub z_c: f64,
    /// The tolerance planes used.
    pub planes: TolerancePlanes,
    /// Their axial positions (m).
    pub z: [f64; 2],
}

/// A rotor's unbalance judged against ISO 21940-11 at its service speed.
#[derive(Debug, Clone, PartialEq)]
pub struct Assessment {
    /// The maximum service speed (rad/s).
    pub omega: f64,
    /// Whether it is `--service-rpm`'s rather than the scene's rate.
    pub from_service_rpm: bool,
    /// The rotor's mass (kg) and its centre of mass along the axis (m, from the axis point).
    pub mass: f64,
    /// Its centre of mass along the axis (m, from the axis point).
    pub z_c: f64,
    /// The tolerance planes and their axial positions (m).
    pub planes: TolerancePlanes,
    /// Their axial positions (m).
    pub z: [f64; 2],
    /// The unbalance in the tolerance planes (g·mm), `[before, after]`.
    pub unbalance: [[f64; 2]; 2],
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
    /// U_per (g·mm) and its allotment to the tolerance planes A and B.
    pub u_per: f64,
    /// U_per's shares in planes A and B (g·mm).
    pub u_per_planes: [f64; 2],
    /// Whether the unbalance is within U_per's shares before and after balancing.
    pub pass: [bool; 2],
    /// The verdicts printed: `pass`/`fail`, or `unverified` when a warning about the input stands.
    pub verdict: [Verdict; 2],
}

/// Judges the tolerance-plane unbalances `unbalance` (g·mm, `[before, after]`) of the rotor `judged` at the service
/// speed `omega` (rad/s; `from_service_rpm`: given by `--service-rpm`) against `grade` when given.
pub fn assess(
    unbalance: [[f64; 2]; 2],
    judged: Judged,
    (omega, from_service_rpm): (f64, bool),
    grade: Option<f64>,
) -> Assessment {
    let Judged {
        mass,
        z_c,
        planes,
        z,
    } = judged;
    let shares = plane_shares(z[0], z[1], z_c);
    let met = unbalance.map(|u| grade_met(u, shares, mass, omega));
    let target = grade.map(|g| {
        let u_per = permissible_unbalance(g, mass, omega);
        let pass = met.map(|m| m <= g);
        Target {
            grade: g,
            u_per,
            u_per_planes: shares.map(|s| s * u_per),
            pass,
            verdict: pass.map(|p| if p { Verdict::Pass } else { Verdict::Fail }),
        }
    });
    Assessment {
        omega: omega.abs(),
        from_service_rpm,
        mass,
        z_c,
        planes,
        z,
        unbalance,
        shares,
        met,
        target,
    }
}

impl Assessment {
    /// After a warning about the input every verdict reads `unverified`.
    pub fn unverify(&mut self) {
        if let Some(t) = &mut self.target {
            t.verdict = [Verdict::Unverified; 2];
        }
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
