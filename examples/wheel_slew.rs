//! A three-axis slew flown by three reaction wheels under a PD law, with the wheels' torque and speed limits and
//! friction (scenarios/slew_three_wheels.toml). Run: `cargo run --release --example wheel_slew [OUT.csv]`; the
//! run is written to OUT.csv (default `slew_three_wheels.csv`) with its sidecar, so that `eulerdyn plot OUT.csv`
//! draws it, and the wheels' speeds are printed every 10 s.
//!
//! The law (`eulerdyn::wheels::AttitudePd`) asks the body for the control moment u_b = k_p e_b − k_d ω_b (e_b
//! the rotation vector that remains to the target, body axes; Wie, *Space Vehicle Dynamics and Control*, 2nd ed., §7.3, the quaternion-feedback
//! regulator in its small-angle form) and commands each wheel τ_k = −u_b·a_k, since the body feels −τ_k a_k
//! (Rigid-body dynamics, lecture notes, the gyrostat). The 0.05 N·m limit caps the body's acceleration, so the
//! slew starts at a constant rate of turn set by saturation, then settles as the PD law's second-order response.

use eulerdyn::output::write_run;
use eulerdyn::scene::{Overrides, load};
use eulerdyn::wheels::AttitudePd;
use nalgebra::{UnitQuaternion, Vector3};

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let out = std::env::args()
        .nth(1)
        .unwrap_or("slew_three_wheels.csv".into());
    let target = UnitQuaternion::from_euler_angles(0.6, -0.4, 0.9);
    let pd = AttitudePd::new(
        target,
        0.6,
        3.0,
        vec![Vector3::x(), Vector3::y(), Vector3::z()],
    );
    let scene = load(
        std::path::Path::new("scenarios/slew_three_wheels.toml"),
        &Overrides::default(),
    )?
    .with_wheel_law("pd_slew", pd)?;
    let report = write_run(&scene, std::path::Path::new(&out))?;
    println!("wrote {out} ({} rows)", report.rows);
    let text = std::fs::read_to_string(&out)?;
    let mut lines = text.lines();
    let header: Vec<&str> = lines.next().unwrap_or_default().split(',').collect();
    let at = |name: &str| header.iter().position(|c| *c == name);
    let columns = ["t", "wheel_x_spin", "wheel_y_spin", "wheel_z_spin"].map(at);
    println!(
        "{:>6} {:>14} {:>14} {:>14}",
        "t (s)", "wheel_x (rpm)", "wheel_y (rpm)", "wheel_z (rpm)"
    );
    for line in lines {
        let values: Vec<f64> = line.split(',').filter_map(|v| v.parse().ok()).collect();
        let get = |i: Option<usize>| i.and_then(|i| values.get(i).copied()).unwrap_or(f64::NAN);
        let t = get(columns[0]);
        if t % 10.0 == 0.0 {
            let rpm = |i| get(i) * 30.0 / std::f64::consts::PI;
            println!(
                "{t:6.1} {:14.2} {:14.2} {:14.2}",
                rpm(columns[1]),
                rpm(columns[2]),
                rpm(columns[3])
            );
        }
    }
    let end = q_end_error(&text, &target);
    println!("attitude error at the end: {end:.2e} rad");
    Ok(())
}

/// The angle between the run's last attitude and the target (rad).
fn q_end_error(text: &str, target: &UnitQuaternion<f64>) -> f64 {
    let last: Vec<f64> = (text.lines().last().unwrap_or_default().split(','))
        .filter_map(|v| v.parse().ok())
        .collect();
    let q = UnitQuaternion::from_quaternion(nalgebra::Quaternion::new(
        last[1], last[2], last[3], last[4],
    ));
    q.angle_to(target)
}
