//! The system's mass distribution at a time t: the rest of the body (rigid) and the moving masses on their
//! paths, or an inertia history — its centre of mass C(t), inertia about C, their rates, and the moving masses'
//! moment of momentum and kinetic energy relative to the body.
//!
//! With the rest of the body (mass m_r, centre c_r, inertia I_r about c_r) and masses m_i at r_i(t), all in body
//! axes, M = m_r + Σ m_i, P(d) = |d|² E − d dᵀ (the parallel-axis term) and ρ_i = r_i − c:
//!
//! ```text
//!   c = (m_r c_r + Σ m_i r_i)/M            ċ = Σ m_i ṙ_i / M
//!   I = I_r + m_r P(c_r − c) + Σ m_i P(ρ_i)
//!   İ = m_r Q(c_r − c, −ċ) + Σ m_i Q(ρ_i, ṙ_i − ċ),      Q(d, ḋ) = 2 (d·ḋ) E − ḋ dᵀ − d ḋᵀ
//!   h = Σ m_i ρ_i × ṙ_i                    ḣ = Σ m_i (ρ_i × r̈_i − ċ × ṙ_i)
//!   T_rel = ½ Σ m_i |ṙ_i|² − ½ M |ċ|²      Ṫ_rel = Σ m_i ṙ_i·r̈_i − M ċ·c̈
//! ```
//!
//! h is the moment of momentum about C of the motion relative to the body (the rest of the body moves at −ċ
//! relative to C and Σ m ρ = 0, so it adds nothing); T_rel the kinetic energy of that motion relative to C
//! (Schaub & Junkins, *Analytical Mechanics of Space Systems*, 4th ed., §4.2: the moment of momentum of a system
//! of particles about its centre of mass; Hughes, *Spacecraft Attitude Dynamics*, §3.3).

use std::path::PathBuf;

use nalgebra::{Matrix3, Vector3};

use super::path::{MassPath, Side, interval};

/// A point mass moved inside the body.
#[derive(Debug, Clone, PartialEq)]
pub struct MovingMass {
    /// The prefix of its position columns.
    pub name: String,
    /// kg, > 0.
    pub mass: f64,
    /// Its path in body axes (m, from the reference origin).
    pub path: MassPath,
}

/// An inertia history about C in body axes (kg·m²), linear between rows and held outside.
#[derive(Debug, Clone, PartialEq)]
pub struct InertiaHistory {
    /// The file it was read from.
    pub path: PathBuf,
    /// Row times (s), strictly increasing, at least two.
    pub t: Vec<f64>,
    /// The tensor at each row (symmetric, positive definite).
    pub inertia_b: Vec<Matrix3<f64>>,
}

/// What changes the body's mass distribution.
#[derive(Debug, Clone, PartialEq)]
pub enum Distribution {
    /// The rest of the body (rigid) and masses moved inside it.
    Masses {
        /// m_r (kg).
        rest_mass: f64,
        /// c_r, the rest's centre of mass from the reference origin (m, body axes).
        rest_c_b: Vector3<f64>,
        /// I_r about c_r (kg·m², body axes).
        rest_inertia_b: Matrix3<f64>,
        /// The moving masses.
        masses: Vec<MovingMass>,
    },
    /// The inertia about C given in time; C fixed, no relative momentum.
    Table {
        /// The body's centre of mass from the reference origin (m, body axes).
        c_b: Vector3<f64>,
        /// I(t).
        history: InertiaHistory,
    },
}

/// The distribution at one time, about the system's centre of mass C(t), body axes.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct MassState {
    /// I about C (kg·m²).
    pub inertia_b: Matrix3<f64>,
    /// İ (kg·m²/s).
    pub inertia_dot_b: Matrix3<f64>,
    /// C from the reference origin (m).
    pub c_b: Vector3<f64>,
    /// h: the moment of momentum about C of the motion relative to the body (kg·m²/s).
    pub h_b: Vector3<f64>,
    /// ḣ (its finite part), N·m.
    pub h_dot_b: Vector3<f64>,
    /// T_rel: the kinetic energy of the motion relative to the body, about C (J).
    pub energy_rel: f64,
    /// Ṫ_rel (W).
    pub energy_rel_dot: f64,
}

/// P(d) = |d|² E − d dᵀ: a unit point mass at d about the origin.
fn parallel(d: &Vector3<f64>) -> Matrix3<f64> {
    Matrix3::from_diagonal_element(d.norm_squared()) - d * d.transpose()
}

/// Q(d, ḋ) = dP/dt = 2 (d·ḋ) E − ḋ dᵀ − d ḋᵀ.
fn parallel_rate(d: &Vector3<f64>, d_dot: &Vector3<f64>) -> Matrix3<f64> {
    Matrix3::from_diagonal_element(2.0 * d.dot(d_dot))
        - d_dot * d.transpose()
        - d * d_dot.transpose()
}

impl Distribution {
    /// The distribution at t (the module's equations), one-sided at a corner of a path or of the table.
    pub fn at(&self, t: f64, side: Side) -> MassState {
        match self {
            Distribution::Masses {
                rest_mass,
                rest_c_b,
                rest_inertia_b,
                masses,
            } => masses_at(*rest_mass, rest_c_b, rest_inertia_b, masses, t, side),
            Distribution::Table { c_b, history } => {
                let (inertia_b, inertia_dot_b) = history.at(t, side);
                MassState {
                    inertia_b,
                    inertia_dot_b,
                    c_b: *c_b,
                    h_b: Vector3::zeros(),
                    h_dot_b: Vector3::zeros(),
                    energy_rel: 0.0,
                    energy_rel_dot: 0.0,
                }
            }
        }
    }

    /// Every corner (a time where a rate jumps), sorted, without repeats.
    pub fn corners(&self) -> Vec<f64> {
        let mut corners: Vec<f64> = match self {
            Distribution::Masses { masses, .. } => {
                masses.iter().flat_map(|m| m.path.corners()).collect()
            }
            Distribution::Table { history, .. } => history.t.clone(),
        };
        corners.sort_by(f64::total_cmp);
        corners.dedup();
        corners
    }

    /// The system's mass (kg).
    pub fn mass(&self, body_mass: f64) -> f64 {
        match self {
            Distribution::Masses {
                rest_mass, masses, ..
            } => rest_mass + masses.iter().map(|m| m.mass).sum::<f64>(),
            Distribution::Table { .. } => body_mass,
        }
    }
}

/// The module's equations for the rest of the body and the moving masses.
fn masses_at(
    rest_mass: f64,
    rest_c_b: &Vector3<f64>,
    rest_inertia_b: &Matrix3<f64>,
    masses: &[MovingMass],
    t: f64,
    side: Side,
) -> MassState {
    // The sums over the masses in one pass (no allocation: this runs at every right-hand side), the paths
    // evaluated again in the second pass below (a few operations each).
    let kinematics = || masses.iter().map(|m| (m.mass, m.path.at(t, side)));
    let (mut moved, mut sum_r, mut sum_v, mut sum_a) =
        (0.0, Vector3::zeros(), Vector3::zeros(), Vector3::zeros());
    for (m, k) in kinematics() {
        moved += m;
        sum_r += k.r * m;
        sum_v += k.v * m;
        sum_a += k.a * m;
    }
    let total = rest_mass + moved;
    let c_b = (rest_c_b * rest_mass + sum_r) / total;
    let c_dot_b = sum_v / total;
    let c_ddot_b = sum_a / total;
    let d_rest = rest_c_b - c_b;
    let mut state = MassState {
        inertia_b: rest_inertia_b + parallel(&d_rest) * rest_mass,
        inertia_dot_b: parallel_rate(&d_rest, &-c_dot_b) * rest_mass,
        c_b,
        h_b: Vector3::zeros(),
        h_dot_b: Vector3::zeros(),
        energy_rel: -0.5 * total * c_dot_b.norm_squared(),
        energy_rel_dot: -total * c_dot_b.dot(&c_ddot_b),
    };
    for (m, k) in kinematics() {
        let rho = k.r - c_b;
        state.inertia_b += parallel(&rho) * m;
        state.inertia_dot_b += parallel_rate(&rho, &(k.v - c_dot_b)) * m;
        state.h_b += rho.cross(&k.v) * m;
        state.h_dot_b += (rho.cross(&k.a) - c_dot_b.cross(&k.v)) * m;
        state.energy_rel += 0.5 * m * k.v.norm_squared();
        state.energy_rel_dot += m * k.v.dot(&k.a);
    }
    state
}

impl InertiaHistory {
    /// I(t) and İ(t): linear between rows (İ the interval's slope, on the side's interval at a row), held
    /// outside (İ = 0).
    pub fn at(&self, t: f64, side: Side) -> (Matrix3<f64>, Matrix3<f64>) {
        match interval(&self.t, t, side) {
            Err(held) => (self.inertia_b[held], Matrix3::zeros()),
            Ok(i) => {
                let slope =
                    (self.inertia_b[i + 1] - self.inertia_b[i]) / (self.t[i + 1] - self.t[i]);
                (self.inertia_b[i] + slope * (t - self.t[i]), slope)
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::super::path::Profile;
    use super::*;

    /// A symmetric pair moved radially on a disk-like rest: C stays, I_zz = I_r,zz + 2 m r², h = 0.
    #[test]
    fn a_symmetric_pair_adds_its_parallel_axis_terms_and_no_relative_momentum() {
        let pair = |sign: f64| MovingMass {
            name: "m".into(),
            mass: 0.5,
            path: MassPath::Move {
                from: Vector3::new(sign * 0.1, 0.0, 0.0),
                to: Vector3::new(sign * 1.1, 0.0, 0.0),
                start: 0.0,
                duration: 2.0,
                profile: Profile::Linear,
            },
        };
        let d = Distribution::Masses {
            rest_mass: 4.0,
            rest_c_b: Vector3::zeros(),
            rest_inertia_b: Matrix3::from_diagonal(&Vector3::new(1.0, 1.0, 2.0)),
            masses: vec![pair(1.0), pair(-1.0)],
        };
        let s = d.at(1.0, Side::After);
        // r = 0.6 m, ṙ = 0.5 m/s: I_zz = 2 + 2·0.5·0.36, İ_zz = 2·m·2 r ṙ = 0.6.
        assert!((s.inertia_b[(2, 2)] - 2.36).abs() < 1e-15);
        assert!((s.inertia_b[(1, 1)] - 1.36).abs() < 1e-15);
        assert_eq!(s.inertia_b[(0, 0)], 1.0);
        assert!((s.inertia_dot_b[(2, 2)] - 0.6).abs() < 1e-15);
        assert_eq!((s.c_b, s.h_b), (Vector3::zeros(), Vector3::zeros()));
        assert!((s.energy_rel - 0.125).abs() < 1e-16);
    }

    /// İ, ḣ and Ṫ_rel are the time derivatives of I, h and T_rel (central differences, error ~h² ≈ 1e-8).
    #[test]
    fn the_rates_are_the_derivatives_of_the_distribution() {
        let d = Distribution::Masses {
            rest_mass: 3.0,
            rest_c_b: Vector3::new(0.05, -0.02, 0.1),
            rest_inertia_b: Matrix3::new(1.0, 0.1, 0.0, 0.1, 1.5, -0.05, 0.0, -0.05, 2.0),
            masses: vec![
                MovingMass {
                    name: "a".into(),
                    mass: 0.4,
                    path: MassPath::Move {
                        from: Vector3::new(0.2, 0.1, -0.3),
                        to: Vector3::new(1.0, -0.4, 0.2),
                        start: 0.0,
                        duration: 4.0,
                        profile: Profile::Smooth,
                    },
                },
                MovingMass {
                    name: "b".into(),
                    mass: 0.7,
                    path: MassPath::Move {
                        from: Vector3::new(-0.3, 0.2, 0.0),
                        to: Vector3::new(0.1, 0.9, -0.5),
                        start: 1.0,
                        duration: 2.5,
                        profile: Profile::Smooth,
                    },
                },
            ],
        };
        let h = 1e-4;
        for t in [0.5, 1.7, 2.9] {
            let (a, b, s) = (
                d.at(t - h, Side::After),
                d.at(t + h, Side::After),
                d.at(t, Side::After),
            );
            let diff = |x: f64, y: f64| (y - x) / (2.0 * h);
            assert!(((b.inertia_b - a.inertia_b) / (2.0 * h) - s.inertia_dot_b).amax() < 1e-7);
            assert!(((b.h_b - a.h_b) / (2.0 * h) - s.h_dot_b).amax() < 1e-7);
            assert!((diff(a.energy_rel, b.energy_rel) - s.energy_rel_dot).abs() < 1e-7);
        }
    }
}
