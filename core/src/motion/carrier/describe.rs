//! The carrier's lines in `eulerdyn check`: its rate and profile, and a vehicle's centre, acceleration and the
//! axis point's acceleration a_A at t = 0 with the force m a_A the support carries for it.

use super::Carrier;
use crate::motion::moving_support::MovingSupport;
use crate::text::{Description, line, vec3};

/// Appends the carrier's lines to `w` for a body of mass `mass` (kg) on the axis it holds
/// ([`MovingSupport::describe`]).
///
/// ```
/// use eulerdyn::motion::carrier::Carrier;
/// use eulerdyn::motion::moving_support::MovingSupport;
/// use eulerdyn::profile::Profile;
/// use eulerdyn::text::Description;
/// let mut w = Description::default();
/// Carrier::new(nalgebra::Vector3::new(0.0, 0.0, 0.5), Profile::Constant).describe(2.0, &mut w);
/// assert_eq!(w.lines[0].0, "carrier");
/// assert!(w.lines[0].1.contains("(0.000000, 0.000000, 0.500000) rad/s (space axes), constant"));
/// ```
pub(super) fn lines(carrier: &Carrier, mass: f64, w: &mut Description) {
    line(
        w,
        "carrier",
        &format!(
            "the axis and its bearings turn with a carrier at {} rad/s (space axes), {}: omega = Omega_c + theta' u",
            vec3(carrier.rate_s()),
            carrier.profile()
        ),
    );
    let Some(vehicle) = carrier.vehicle() else {
        return;
    };
    line(
        w,
        "vehicle",
        &format!(
            "turns about {} m from the axis point (space axes at t = 0), accelerates at {} m/s^2 (space axes), {}",
            vec3(vehicle.center_s()),
            vec3(vehicle.accel_s()),
            vehicle.profile()
        ),
    );
    let a_a_s = carrier.at(0.0).accel_a_s.unwrap_or_default();
    line(
        w,
        "",
        &format!(
            "the axis point accelerates at a_A = {} m/s^2 at t = 0: the support carries m a_A = {} N besides the weight",
            vec3(&a_a_s),
            vec3(&(a_a_s * mass))
        ),
    );
}
