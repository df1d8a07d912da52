//! A PD attitude controller slewing a body to a target attitude through a direct torque:
//! M = −k_p θ_err·axis − k_d ω, with θ_err·axis the rotation vector that remains from the attitude q to the target
//! (body axes). Run: `cargo run --release --example pd_slew`.
//!
//! For a single axis and a small angle the loop is I θ̈ + k_d θ̇ + k_p θ = k_p θ_t, the second-order system with
//! ω_n = √(k_p/I) and ζ = k_d/(2√(k_p I)) (Ogata, Modern Control Engineering, 5th ed., §5-3). About one principal
//! axis the remaining rotation vector is exactly (θ_t − θ)·z, so the loop is that linear system at any angle below
//! π; the example prints the slew angle beside its underdamped step response (Ogata eq. 5-10)
//! θ(t) = θ_t [1 − e^{−ζ ω_n t} (cos ω_d t + ζ/√(1 − ζ²) sin ω_d t)], ω_d = ω_n √(1 − ζ²).

use eulerdyn::frames::Axes;
use eulerdyn::scene::{BodySpec, SceneSpec};
use nalgebra::{UnitQuaternion, Vector3};

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let (i_z, k_p, k_d, theta_t) = (2.0, 8.0, 4.0, 0.5);
    let target = UnitQuaternion::from_axis_angle(&Vector3::z_axis(), theta_t);
    let pd = move |_t: f64, q: &UnitQuaternion<f64>, omega_b: &Vector3<f64>| {
        let error_b = q.inverse_transform_vector(&q.rotation_to(&target).scaled_axis());
        error_b * k_p - omega_b * k_d
    };
    let scene = SceneSpec::new(BodySpec::principal(1.0, [1.0, 1.5, i_z]), 8.0, 0.5)
        .build()?
        .with_moment("pd_slew", Axes::Body, pd)?;
    let (samples, report) = eulerdyn::simulate::samples(&scene)?;
    let omega_n = (k_p / i_z).sqrt();
    let zeta = k_d / (2.0 * (k_p * i_z).sqrt());
    println!("omega_n = {omega_n:.4} rad/s, zeta = {zeta:.4}");
    let omega_d = omega_n * (1.0 - zeta * zeta).sqrt();
    let closed_form = |t: f64| {
        let decay = (-zeta * omega_n * t).exp();
        let sine = zeta / (1.0 - zeta * zeta).sqrt() * (omega_d * t).sin();
        theta_t * (1.0 - decay * ((omega_d * t).cos() + sine))
    };
    println!(
        "{:>6} {:>12} {:>12} {:>10}",
        "t (s)", "theta (rad)", "Ogata 5-10", "diff"
    );
    for s in &samples {
        let theta = 2.0 * s.q.k.atan2(s.q.w);
        let expected = closed_form(s.t);
        println!(
            "{:6.2} {theta:12.8} {expected:12.8} {:10.1e}",
            s.t,
            theta - expected
        );
    }
    println!(
        "{} steps, {} evaluations of the law",
        report.stats.steps, report.stats.evals
    );
    Ok(())
}
