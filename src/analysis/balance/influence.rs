//! Two-plane balancing by influence coefficients: the shop-floor method that needs no knowledge of the rotor's
//! mass distribution, only its measured 1× response (E. L. Thearle, "Dynamic balancing of rotating machinery in the
//! field", Trans. ASME 56, 1934; the least-squares form: T. P. Goodman, "A least-squares method for computing
//! balance corrections", J. Eng. Ind. 86, 1964).
//!
//! A reading is a phasor V = amp·e^{i·phase}: the 1× part of the signal, x(θ) = amp·cos(θ + phase), θ the angle
//! the rotor has turned since its reference mark passed the sensor. A trial mass m at the angle φ (in the
//! direction of rotation from the mark) is the complex mass T = m·e^{iφ}. For a linear rotor the readings of a
//! run with the trial masses T are V = V⁰ + α T, α the 2 × 2 complex matrix of influence coefficients (reading
//! per gram, row = sensor A, B; column = plane A, B). From the initial run and trial runs, V⁰ and α follow by
//! least squares over all runs, and the corrections that cancel V⁰ are W = −α⁻¹ V⁰ (grams at the trial radius,
//! angles in the trial masses' convention). A constant lag or gain of a sensor multiplies its row of V⁰ and α
//! alike and changes no correction. cond₂(α) = σ_max/σ_min measures how much measurement errors are magnified.

use nalgebra::{Complex, DMatrix, Matrix2, Vector2};

/// A complex number for a phasor, an influence coefficient or a complex mass.
pub type Phasor = Complex<f64>;

/// The phasor amp·e^{i·phase} of an amplitude and a phase in degrees.
pub fn phasor(amp: f64, phase_deg: f64) -> Phasor {
    Complex::from_polar(amp, phase_deg.to_radians())
}

/// A phasor's amplitude and phase in degrees, the phase in [0, 360).
pub fn polar_deg(v: Phasor) -> (f64, f64) {
    (v.norm(), super::format::wrap_deg(v.arg().to_degrees()))
}

/// The 1× phasor of a signal sampled at the rotation angles `theta` (rad): the single-frequency discrete Fourier
/// coefficient V = (2/N) Σ x_k e^{−iθ_k}. For samples equally spaced over whole revolutions it is exact for
/// x(θ) = c + amp·cos(θ + phase) + (harmonics below N/2): the other terms sum to zero.
pub fn phasor_1x(theta: &[f64], signal: &[f64]) -> Phasor {
    let sum: Phasor = theta
        .iter()
        .zip(signal)
        .map(|(&th, &x)| Complex::from_polar(x, -th))
        .sum();
    sum * (2.0 / theta.len() as f64)
}

/// One run of the measured table.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Run {
    /// The trial mass: its plane (0 = A, 1 = B) and its complex mass m·e^{iφ} (g); `None` for an initial run.
    pub trial: Option<(usize, Phasor)>,
    /// The readings at sensors A and B.
    pub readings: [Phasor; 2],
}

/// What the runs give: the influence coefficients and the initial readings, fitted.
#[derive(Debug, Clone, PartialEq)]
pub struct Fit {
    /// α: reading per gram at the trial radius; row = sensor (A, B), column = plane (A, B).
    pub alpha: Matrix2<Phasor>,
    /// V⁰, the initial readings as the fit gives them (the measured ones when the system is square).
    pub initial: Vector2<Phasor>,
}

/// The least-squares fit of V⁽ᵏ⁾ = V⁰ + α T⁽ᵏ⁾ over all `runs` (an initial run and trial runs in both planes):
/// for each sensor, the rows [1, T_A, T_B] of the design matrix against its readings, solved by SVD. With one
/// initial run and one trial per plane it is the textbook α_ij = (V_i⁽ʲ⁾ − V_i⁰)/T_j. `None` when the design
/// matrix has rank below 3 (a plane without a trial, no initial run).
pub fn fit(runs: &[Run]) -> Option<Fit> {
    let design = DMatrix::from_fn(runs.len(), 3, |k, j| match (j, runs[k].trial) {
        (0, _) => Complex::new(1.0, 0.0),
        (j, Some((plane, t))) if plane + 1 == j => t,
        _ => Complex::new(0.0, 0.0),
    });
    let readings = DMatrix::from_fn(runs.len(), 2, |k, i| runs[k].readings[i]);
    let svd = design.svd(true, true);
    let sigma = &svd.singular_values;
    if sigma.len() < 3 || sigma.min() <= 1e-12 * sigma.max() {
        return None;
    }
    let beta = svd.solve(&readings, 0.0).ok()?;
    Some(Fit {
        alpha: Matrix2::new(beta[(1, 0)], beta[(2, 0)], beta[(1, 1)], beta[(2, 1)]),
        initial: Vector2::new(beta[(0, 0)], beta[(0, 1)]),
    })
}

/// The initial readings for known coefficients (one-shot balancing): the mean of the initial runs' readings,
/// the least-squares V⁰ when α is not fitted. `None` without an initial run.
pub fn initial_readings(runs: &[Run]) -> Option<Vector2<Phasor>> {
    let initial: Vec<_> = runs.iter().filter(|r| r.trial.is_none()).collect();
    if initial.is_empty() {
        return None;
    }
    let sum = initial
        .iter()
        .fold(Vector2::zeros(), |s, r| s + Vector2::from(r.readings));
    Some(sum / Complex::new(initial.len() as f64, 0.0))
}

/// cond₂(α) = σ_max / σ_min (∞ for a singular α).
pub fn condition_number(alpha: &Matrix2<Phasor>) -> f64 {
    let sigma = alpha.singular_values();
    let (max, min) = (sigma.max(), sigma.min());
    if min > 0.0 { max / min } else { f64::INFINITY }
}

/// The corrections W = −α⁻¹ V⁰ (g, complex: m·e^{iφ}) that cancel the initial readings; `None` when α is
/// singular (cond₂ above 1e12).
pub fn corrections(alpha: &Matrix2<Phasor>, initial: &Vector2<Phasor>) -> Option<Vector2<Phasor>> {
    if condition_number(alpha) > 1e12 {
        return None;
    }
    alpha.try_inverse().map(|inv| -(inv * initial))
}

/// The influence coefficients a rigid rotor in rigid bearings has for the force the rotor applies to each
/// bearing, N per gram at the radius `radius` (m), at the speed `omega` (rad/s). A mass m at radius R in the
/// plane z_p at the angle φ turns with the rotor and needs the centripetal force m R Ω² towards the axis; the
/// rotor pushes the bearings with its reaction m R Ω² e^{iφ}, shared by the lever rule (statics of the shaft,
/// moments about each bearing): α_{A,p} = R Ω² (z_B − z_p)/(z_B − z_A) and α_{B,p} = R Ω² (z_p − z_A)/(z_B − z_A),
/// real (in phase with the mass) and per gram (× 10⁻³ kg). `bearings` and `planes` are axial positions.
pub fn rigid_rotor_coefficients(
    bearings: [f64; 2],
    planes: [f64; 2],
    radius: f64,
    omega: f64,
) -> Matrix2<Phasor> {
    let [z_a, z_b] = bearings;
    let per_gram = 1e-3 * radius * omega * omega / (z_b - z_a);
    Matrix2::from_fn(|sensor, plane| {
        let z_p = planes[plane];
        let lever = if sensor == 0 { z_b - z_p } else { z_p - z_a };
        Complex::new(per_gram * lever, 0.0)
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_1x_phasor_of_a_sampled_cosine_over_whole_revolutions_is_exact() {
        let n = 48;
        let theta: Vec<f64> = (0..3 * n)
            .map(|k| k as f64 * std::f64::consts::TAU / n as f64)
            .collect();
        let signal: Vec<f64> = theta
            .iter()
            .map(|th| 4.0 + 2.5 * (th + 0.7).cos() + 0.3 * (2.0 * th).sin())
            .collect();
        let v = phasor_1x(&theta, &signal);
        assert!((v - phasor(2.5, 0.7f64.to_degrees())).norm() < 1e-13);
    }

    #[test]
    fn a_square_fit_is_the_textbook_difference_quotient() {
        let v0 = [phasor(3.0, 10.0), phasor(2.0, 200.0)];
        let (t_a, t_b) = (phasor(5.0, 30.0), phasor(4.0, 90.0));
        let va = [phasor(4.0, 40.0), phasor(1.0, 120.0)];
        let vb = [phasor(2.5, 300.0), phasor(3.5, 170.0)];
        let runs = [
            Run {
                trial: None,
                readings: v0,
            },
            Run {
                trial: Some((0, t_a)),
                readings: va,
            },
            Run {
                trial: Some((1, t_b)),
                readings: vb,
            },
        ];
        let fit = fit(&runs).unwrap();
        for i in 0..2 {
            assert!((fit.alpha[(i, 0)] - (va[i] - v0[i]) / t_a).norm() < 1e-12);
            assert!((fit.alpha[(i, 1)] - (vb[i] - v0[i]) / t_b).norm() < 1e-12);
            assert!((fit.initial[i] - v0[i]).norm() < 1e-12);
        }
    }

    #[test]
    fn a_plane_without_a_trial_has_no_fit() {
        let runs = [
            Run {
                trial: None,
                readings: [phasor(1.0, 0.0); 2],
            },
            Run {
                trial: Some((0, phasor(1.0, 0.0))),
                readings: [phasor(2.0, 0.0); 2],
            },
        ];
        assert!(fit(&runs).is_none());
    }
}
